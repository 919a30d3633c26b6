# gallop: build, test, demo, bench, report. `make demo` and `make check` install the Debian
# packages that are missing when run as root (apt-get), or say what to install otherwise.

CC      ?= cc
CSTD    := -std=c11
WARN    := -Wall -Wextra
OPT     ?= -O2
CFLAGS  ?=
CPPFLAGS += -Iinclude -Isrc -I/usr/include/suitesparse -D_POSIX_C_SOURCE=200809L
LIBS    := -lumfpack -lcholmod -lamd -lcolamd -lsuitesparseconfig -larpack -lgsl -lgslcblas -lfftw3 \
           -linih -llapack -lblas -lm

ifeq ($(SAN),1)
  OPT := -O1 -g
  SANFLAGS := -fsanitize=address,undefined,float-cast-overflow -fno-omit-frame-pointer -fno-sanitize-recover=undefined,float-cast-overflow
  BUILD := build/san
else
  SANFLAGS :=
  BUILD := build
endif

ALL_CFLAGS := $(CSTD) $(WARN) $(OPT) $(SANFLAGS) $(CFLAGS)

# the library: every stage folder of src/ but the command line (src/cli/)
LIB_SRC  := $(filter-out src/cli/%,$(wildcard src/*/*.c))
CLI_OBJ  := $(patsubst src/%.c,$(BUILD)/obj/%.o,$(wildcard src/cli/*.c))
LIB_OBJ  := $(patsubst src/%.c,$(BUILD)/obj/%.o,$(LIB_SRC))
TEST_SRC := $(wildcard tests/test_*.c)
TEST_BIN := $(patsubst tests/%.c,$(BUILD)/tests/%,$(TEST_SRC))
TEST_SH  := $(wildcard tests/test_*.sh)

DEB_PKGS := libarpack2-dev libsuitesparse-dev libgsl-dev libfftw3-dev libinih-dev \
            liblapack-dev libblas-dev libopenblas-dev pkg-config gnuplot-nox jq libopenmpi-dev openmpi-bin
STAMP    := build/.deps-ok

.PHONY: all deps demo check bench diag report report-bundle-grid report-bundle-partner report-spanset clean fuzz mutate install
all: $(BUILD)/gallop $(BUILD)/libgallop.a

# ---- Debian packages ----
$(STAMP):
	@sh tests/deps.sh $(DEB_PKGS)
	@mkdir -p build && touch $@
deps: $(STAMP)

$(BUILD)/obj/%.o: src/%.c $(wildcard include/*.h include/gallop/*/*.h src/*/*.h) | $(STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CFLAGS) $(CPPFLAGS) -MMD -c $< -o $@

$(BUILD)/libgallop.a: $(LIB_OBJ)
	@rm -f $@ # a fresh archive: no member left over from a source moved or removed
	ar rcs $@ $^

$(BUILD)/gallop: $(CLI_OBJ) $(BUILD)/libgallop.a
	$(CC) $(ALL_CFLAGS) -pthread $^ $(LIBS) $(MPI_LIBS) -o $@

# ---- MPI (issue 18): `gallop sweep` over the ranks of mpirun when Open MPI is there (pkg-config
# ompi, else mpicc); MPI=0 builds the serial sweep. Evaluated when used, after the packages are in;
# $(BUILD)/.mpi changes only when the choice does, and then sweep_par.o is rebuilt. ----
MPI ?= auto
MPI_ON = $(if $(filter 0,$(MPI)),0,$(shell pkg-config --exists ompi 2>/dev/null && echo 1 || { command -v mpicc >/dev/null 2>&1 && echo 1; } || echo 0))
MPI_CFLAGS = $(if $(filter 1,$(MPI_ON)),-DGAL_MPI $(shell pkg-config --cflags ompi 2>/dev/null || mpicc --showme:compile))
MPI_LIBS = $(if $(filter 1,$(MPI_ON)),$(shell pkg-config --libs ompi 2>/dev/null || mpicc --showme:link))
$(BUILD)/.mpi: FORCE | $(STAMP)
	@mkdir -p $(dir $@); v="$(MPI_ON)"; [ "$$(cat $@ 2>/dev/null)" = "$$v" ] || echo "$$v" > $@
$(BUILD)/obj/cli/sweep_par.o: CPPFLAGS += $(MPI_CFLAGS)
$(BUILD)/obj/cli/sweep_par.o: $(BUILD)/.mpi
.PHONY: FORCE
FORCE:

$(BUILD)/tests/%: tests/%.c tests/check.h $(BUILD)/libgallop.a
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CFLAGS) -pthread $(CPPFLAGS) $< $(BUILD)/libgallop.a $(LIBS) -o $@

-include $(LIB_OBJ:.o=.d) $(CLI_OBJ:.o=.d)

# the git commit every summary.json records (output/record.c); "unknown" outside a git checkout.
# build/.commit changes only when the commit does, so that record.o is rebuilt then and only then.
GAL_COMMIT := $(shell git rev-parse --short HEAD 2>/dev/null || echo unknown)
COMMIT_STAMP := build/.commit
$(shell mkdir -p build; [ "$$(cat $(COMMIT_STAMP) 2>/dev/null)" = "$(GAL_COMMIT)" ] || echo "$(GAL_COMMIT)" > $(COMMIT_STAMP))
$(BUILD)/obj/output/record.o: CPPFLAGS += -DGAL_COMMIT='"$(GAL_COMMIT)"'
$(BUILD)/obj/output/record.o: $(COMMIT_STAMP)

# the data directory an installed gallop searches (src/base/datadir.c): empty in a build tree;
# `make install` builds in build/install with $(PREFIX)/share/gallop baked in
GAL_DATADIR ?=
DATADIR_STAMP := $(BUILD)/.datadir
$(shell mkdir -p $(BUILD); [ -f $(DATADIR_STAMP) ] && [ "$$(cat $(DATADIR_STAMP))" = "$(GAL_DATADIR)" ] || echo "$(GAL_DATADIR)" > $(DATADIR_STAMP))
$(BUILD)/obj/base/datadir.o: CPPFLAGS += -DGAL_DATADIR='"$(GAL_DATADIR)"'
$(BUILD)/obj/base/datadir.o: $(DATADIR_STAMP)

# ---- install: make install PREFIX=... [DESTDIR=...] ----
PREFIX  ?= /usr/local
GAL_VERSION := $(shell sed -n 's/^\#define GAL_VERSION "\(.*\)"/\1/p' include/gallop/output/record.h)
INST    := $(DESTDIR)$(PREFIX)
INST_BUILD := build/install
install: | $(STAMP)
	$(MAKE) --no-print-directory BUILD=$(INST_BUILD) SAN=0 GAL_DATADIR=$(PREFIX)/share/gallop \
	    $(INST_BUILD)/gallop $(INST_BUILD)/libgallop.a
	install -d $(INST)/bin $(INST)/lib/pkgconfig $(INST)/include/gallop $(INST)/share/man/man1 \
	    $(INST)/share/gallop/aero $(INST)/share/gallop/scenes
	install -m 755 $(INST_BUILD)/gallop $(INST)/bin/gallop
	install -m 644 $(INST_BUILD)/libgallop.a $(INST)/lib/libgallop.a
	install -m 644 include/gallop.h $(INST)/include/gallop.h
	cd include && for d in gallop/*/; do install -d $(INST)/include/$$d && install -m 644 $$d*.h $(INST)/include/$$d; done
	install -m 644 doc/gallop.1 $(INST)/share/man/man1/gallop.1
	install -m 644 data/conductors.csv $(INST)/share/gallop/conductors.csv
	install -m 644 data/aero/*.csv $(INST)/share/gallop/aero/
	install -m 644 data/scenes/*.ini $(INST)/share/gallop/scenes/
	sed -e 's|@PREFIX@|$(PREFIX)|; s|@VERSION@|$(GAL_VERSION)|; s|@LIBS@|$(LIBS)|' gallop.pc.in > $(INST)/lib/pkgconfig/gallop.pc
	@echo "installed gallop $(GAL_VERSION) in $(INST)"

# ---- the library example of the README (examples/first_frequencies.c) ----
EXAMPLES := $(BUILD)/examples/first_frequencies
$(BUILD)/examples/%: examples/%.c $(BUILD)/libgallop.a
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CFLAGS) $(CPPFLAGS) $< $(BUILD)/libgallop.a $(LIBS) -o $@

# ---- fuzzing (issue 8): libFuzzer harnesses of the scene and table parsers, built with clang ----
FUZZ_TIME ?= 60
FUZZ_CC   ?= clang
FUZZ_PKGS := clang libclang-rt-14-dev
FUZZ_STAMP := build/.fuzz-deps-ok
FUZZ_DIR  := build/fuzz
FUZZ_SAN  := -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer
FUZZ_CFLAGS := $(CSTD) -g -O1 $(FUZZ_SAN)
FUZZ_OBJ  := $(patsubst src/%.c,$(FUZZ_DIR)/obj/%.o,$(LIB_SRC))

$(FUZZ_STAMP): | $(STAMP)
	@sh tests/deps.sh $(FUZZ_PKGS)
	@touch $@

$(FUZZ_DIR)/obj/%.o: src/%.c $(wildcard include/*.h include/gallop/*/*.h src/*/*.h) | $(FUZZ_STAMP)
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer-no-link $(CPPFLAGS) -c $< -o $@

$(FUZZ_DIR)/fuzz_%: tests/fuzz/fuzz_%.c $(FUZZ_OBJ) | $(FUZZ_STAMP)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer $(CPPFLAGS) $< $(FUZZ_OBJ) $(LIBS) -o $@

.SECONDARY: $(FUZZ_OBJ)
fuzz: $(FUZZ_DIR)/fuzz_scene $(FUZZ_DIR)/fuzz_aero
	@bash tests/fuzz/run.sh $(FUZZ_DIR) $(FUZZ_TIME)

# ---- the main job and the tests ----
DEMO_SCENE ?= data/scenes/drake_300m.ini
demo: $(BUILD)/gallop
	./$(BUILD)/gallop modes $(DEMO_SCENE) -o out/demo

check: $(BUILD)/gallop $(TEST_BIN) $(EXAMPLES)
	@GALLOP=$(abspath $(BUILD)/gallop) GALLOP_EXAMPLES=$(abspath $(BUILD)/examples) CC="$(CC)" GALLOP_CPPFLAGS="$(CPPFLAGS)" \
	    bash tests/run.sh $(TEST_BIN) $(TEST_SH)

# the suite's power: the mutants of tests/mutate/mutants.txt, each applied to a copy of the sources
mutate: | $(STAMP)
	@bash tests/mutate/run.sh $(MUTANTS)

bench: $(BUILD)/gallop $(BUILD)/libgallop.a
	@bash tests/bench/run.sh $(BUILD)

# the diagnostic programs tests/bench/diag_*.c, built (not run: each file says its usage and the
# BENCHMARKS.md section it measured), e.g. build/bench/diag_line
DIAG_BIN := $(patsubst tests/bench/%.c,$(BUILD)/bench/%,$(wildcard tests/bench/diag_*.c))
diag: $(DIAG_BIN)
$(BUILD)/bench/diag_%: tests/bench/diag_%.c $(BUILD)/libgallop.a
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CFLAGS) -pthread $(CPPFLAGS) $< $(BUILD)/libgallop.a $(LIBS) -o $@

report: $(BUILD)/gallop
	@bash notebooks-free-reports/make_report.sh $(BUILD)/gallop

# the equivalent bundle against the explicit one over a grid (long: 48 runs, README "Bundles")
report-bundle-grid: $(BUILD)/gallop
	@bash notebooks-free-reports/bundle_grid.sh $(BUILD)/gallop out/report

# the twin's reduced model against its full model, 300 s (BEFORE=path of an older gallop to compare)
report-bundle-partner: $(BUILD)/gallop
	@bash notebooks-free-reports/bundle_partner.sh $(BUILD)/gallop out/report $(BEFORE)

# issue 13's figures over tests/rom/ (accuracy at the own mesh, 100 and 125 elements; CPU speed at 100,
# 125, 400), 20-60 min; JOBS=2 runs two processes at a time (BENCHMARKS.md "span set, re-measured")
report-spanset: $(BUILD)/gallop
	@bash tests/bench/spanset.sh $(BUILD)/gallop out/spanset

clean:
	rm -rf build out
