#!/usr/bin/env bash
# make bench: builds the benchmark programs of tests/bench/ against the library and runs them on
# one core (taskset when available). Figures are medians of repeats.
set -eu
build=${1:-build}
mkdir -p "$build/bench"
CPU=""
command -v taskset >/dev/null 2>&1 && CPU="taskset -c 0"
echo "machine: $(uname -m), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo 2>/dev/null | cut -d: -f2 | sed 's/^ *//')"
for src in tests/bench/bench_*.c; do
  exe="$build/bench/$(basename "$src" .c)"
  ${CC:-cc} -std=c11 -O2 -Iinclude -Isrc -I/usr/include/suitesparse -D_POSIX_C_SOURCE=200809L \
    "$src" "$build/libgallop.a" -lumfpack -lcholmod -lamd -lcolamd -lsuitesparseconfig -larpack \
    -lgsl -lgslcblas -lfftw3 -linih -llapack -lblas -lm -o "$exe"
  echo "== $(basename "$exe")"
  $CPU "$exe"
done
