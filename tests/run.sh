#!/usr/bin/env bash
# Runs every test program given on the command line (and the shell tests), adds up the
# "#summary P F" lines and ends with "N passed, N failed"; exits non-zero on any failure.
# TEST_JOBS programs run at once (default: the number of cores); each one's output is kept in
# a file and printed whole, in the order given, so the log reads the same as a serial run.
# FAIL_FAST=1 (make mutate) runs one at a time and stops at the first failing program.
set -u
# One BLAS thread, as the command line runs (src/cli/blas.c): the test programs then see the same
# round-off as `gallop` on any machine, whatever its core count (reduced runs whose growth round-off
# decides read differently with 2 threads: BENCHMARKS.md "The fine-mesh twist depends on the instant
# of a late growth"), and two programs at once do not oversubscribe the cores.
export OPENBLAS_NUM_THREADS=1
passed=0; failed=0
jobs=${TEST_JOBS:-$(nproc 2>/dev/null || echo 1)}
[ -n "${FAIL_FAST:-}" ] && jobs=1
case "$jobs" in ''|*[!0-9]*|0) jobs=1 ;; esac
dir=$(mktemp -d /tmp/gallop_run_XXXXXX) || exit 1
trap 'rm -rf "$dir"' EXIT

# one program, its output to $dir/i.out; $dir/i.rc appears (by rename) only when it is done
run_one() {
  local i=$1 t=$2 t0=$SECONDS rc
  case "$t" in
    *.sh) bash "$t" > "$dir/$i.out" 2>&1; rc=$? ;;
    *)    "$t" > "$dir/$i.out" 2>&1; rc=$? ;;
  esac
  echo "$rc $((SECONDS - t0))" > "$dir/$i.tmp" && mv "$dir/$i.tmp" "$dir/$i.rc"
}

# prints program i's output and adds its summary to the totals
report() {
  local i=$1 name rc secs sum p f
  name=$(basename "${progs[$i]}")
  read -r rc secs < "$dir/$i.rc"
  echo "== $name"
  grep -v '^#summary' "$dir/$i.out"
  sum=$(grep '^#summary' "$dir/$i.out" | tail -n 1)
  if [ -n "$sum" ]; then
    read -r _ p f <<<"$sum"
    passed=$((passed + p)); failed=$((failed + f))
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
      echo "  FAIL $name exited with status $rc"; failed=$((failed + 1))
    fi
  else
    echo "  FAIL $name: no summary (exit status $rc, crashed?)"; failed=$((failed + 1))
  fi
  echo "  [$name: $secs s]"
}

progs=("$@")
next=0   # the first program not yet reported
stop=0
flush() {
  while [ "$next" -lt "${#progs[@]}" ] && [ -e "$dir/$next.rc" ]; do
    report "$next"; next=$((next + 1))
    if [ -n "${FAIL_FAST:-}" ] && [ "$failed" -gt 0 ]; then stop=1; return; fi
  done
}
for i in "${!progs[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n; flush; done
  flush
  [ "$stop" -eq 1 ] && break
  run_one "$i" "${progs[$i]}" &
done
wait
[ "$stop" -eq 1 ] || flush
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
