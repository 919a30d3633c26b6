# tests/lib.sh: what the shell tests share, sourced as `. "$(dirname "$0")/lib.sh"`: the pass and
# fail counters with their printers ok and bad, `finish` (the "#summary P F" line tests/run.sh adds
# up, and the status), `scratch NAME` (a temporary directory in $tmp, removed on exit) and
# `openmpi_sanitizers` (the suppressions that let Open MPI's start-up run under SAN=1).
pass=0; fail=0
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ok()  { pass=$((pass + 1)); echo "  ok   $1"; }
bad() { fail=$((fail + 1)); echo "  FAIL $1"; }
finish() { echo "#summary $pass $fail"; [ "$fail" -eq 0 ]; }
scratch() { tmp=$(mktemp -d "/tmp/gallop_$1_XXXXXX") || exit 1; trap 'rm -rf "$tmp"' EXIT; }
openmpi_sanitizers() {
  export LSAN_OPTIONS="suppressions=$here/lsan-openmpi.supp:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
  export ASAN_OPTIONS="fast_unwind_on_malloc=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
}
