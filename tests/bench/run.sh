#!/usr/bin/env bash
# make bench: builds the benchmark programs of tests/bench/ against the library, runs them on one
# core (taskset when available), prints one table of the figures (medians of repeats) and records
# it in notebooks-free-reports/BENCHMARKS.md with the machine it ran on.
set -eu
build=${1:-build}
mkdir -p "$build/bench"
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
  $CPU "$exe" | grep '^BENCH|' >>"$rows"
done
kept=$(sed -n '/^## Reduced model (recomputed/,$p' notebooks-free-reports/BENCHMARKS.md 2>/dev/null || true)
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
  echo "Targets: statics + 20 modes at 1000 elements under 50 ms; reduced model at 100 and 1000"
  echo "elements within 20% of each other; speedup of reduced over full at 200 elements at least 100x."
  echo
  echo "$table"
  # the measured sections written by hand (from "## Reduced model (recomputed") are kept
  if [ -n "$kept" ]; then echo; printf '%s\n' "$kept"; fi
} >notebooks-free-reports/BENCHMARKS.md
echo "recorded in notebooks-free-reports/BENCHMARKS.md"
