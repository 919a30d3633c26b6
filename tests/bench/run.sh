#!/usr/bin/env bash
# make bench: builds the benchmark programs of tests/bench/ against the library, runs them on one
# core (taskset when available), prints one table of the figures (medians of repeats) and records
# it in notebooks-free-reports/BENCHMARKS.md with the machine it ran on. bench_ccx compares with
# CalculiX: calculix-ccx is installed here when missing (apt-get, as root; otherwise it says so and
# that comparison is skipped).
set -eu
build=${1:-build}
mkdir -p "$build/bench"
if ! command -v ccx >/dev/null 2>&1; then
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "installing calculix-ccx for the CalculiX comparison ..." >&2
    { apt-get install -y calculix-ccx || { apt-get update && apt-get install -y calculix-ccx; }; } >/dev/null 2>&1 ||
      echo "make bench: could not install calculix-ccx: the CalculiX comparison is skipped" >&2
  else
    echo "make bench: ccx (Debian calculix-ccx) is missing and this is not root: the CalculiX comparison is skipped" >&2
  fi
fi
CPU=""
command -v taskset >/dev/null 2>&1 && CPU="taskset -c 0"
machine="$(uname -m), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo 2>/dev/null | cut -d: -f2 | sed 's/^ *//'), $(free -g | awk '/Mem:/{print $2}') GiB"
rows=$(mktemp)
trap 'rm -f "$rows"' EXIT
for src in tests/bench/bench_*.c; do
  exe="$build/bench/$(basename "$src" .c)"
  ${CC:-cc} -std=c11 -O2 -Iinclude -Isrc -I/usr/include/suitesparse -D_POSIX_C_SOURCE=200809L \
    "$src" "$build/libgallop.a" -lumfpack -lcholmod -lamd -lcolamd -lsuitesparseconfig -larpack \
    -lgsl -lgslcblas -lfftw3 -linih -llapack -lblas -lm -o "$exe"
  echo "running $(basename "$exe") ..." >&2
  args=()
  [ "$(basename "$exe")" = bench_ccx ] && args=("$build/bench/ccx")
  $CPU "$exe" ${args[@]+"${args[@]}"} | grep '^BENCH|' >>"$rows"
done
bash tests/bench/sweep.sh "$build" >>"$rows"   # 2 MPI ranks against 1 (issue 18)
kept=$(sed -n '/^## /,$p' notebooks-free-reports/BENCHMARKS.md 2>/dev/null || true)
table=$( {
  echo "| figure | value | unit | how |"
  echo "|---|---:|---|---|"
  awk -F'|' '{printf "| %s | %s | %s | %s |\n", $2, $3, $4, $5}' "$rows"
} )
echo "machine: $machine"
echo "$table"
{
  echo "# Benchmarks"
  echo
  echo "The latest \`make bench\` (tests/bench/), $(date -u +%Y-%m-%d), on one core of: $machine."
  echo "Targets: the modes stage within 4x and a full-model step within 3x of their arithmetic floors; statics +"
  echo "30 modes at 1000 elements 1000x faster than CalculiX (issue 16); the reduced model (issue 13) per simulated"
  echo "second at least 30x the full model at 100-125 elements and 100x at 400, a whole 300-s run at least 10x"
  echo "(medians over tests/rom/: make report-spanset), its cost per step flat in the mesh, its own set-up at 1000"
  echo "elements at most 3x that at 100. Times marked CPU are the process's CPU time (the machine is shared);"
  echo "peak memory is each case's own process's."
  echo
  echo "$table"
  # the sections written by hand (every "## " section after the table) are kept
  if [ -n "$kept" ]; then echo; printf '%s\n' "$kept"; fi
} >notebooks-free-reports/BENCHMARKS.md
echo "recorded in notebooks-free-reports/BENCHMARKS.md"
