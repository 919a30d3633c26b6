#!/usr/bin/env bash
# test_blas_threads.sh: gallop's BLAS threads (src/cli/blas.c, README "BLAS threads"). Under an
# address-space limit a gallop run must end, never hang in the BLAS: with OpenBLAS's default
# thread pool `ulimit -v 400000; gallop modes drake_300m --set model.elements=20000` hung at exit
# in blas_memory_alloc, and with one thread a tighter limit hung inside dgemv_ (measured). Each
# run below must finish within 60 s: the 20000-element case with exit 0, a case too large for the
# limit with exit 1 and "out of memory", a limit too small for the BLAS buffer with exit 1 and a
# message about memory. Skipped in the sanitizer build (ASan reserves terabytes of address space).
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
scratch blas
if nm -an "$GALLOP" 2>/dev/null | grep -q __asan_init || ldd "$GALLOP" 2>/dev/null | grep -q libasan; then
  echo "  skip: sanitizer build (ulimit -v does not apply)"
  echo "#summary 0 0"; exit 0
fi

# limited KB ELEMENTS WANT_RC WANT_MESSAGE NAME
limited() {
  local t0 t1 rc
  t0=$(date +%s)
  ( ulimit -v "$1"; exec timeout 60 "$GALLOP" modes data/scenes/drake_300m.ini \
      --set model.elements="$2" -o "$tmp/out_$5" ) >/dev/null 2>"$tmp/err_$5"
  rc=$?; t1=$(date +%s)
  if [ $rc -eq 124 ]; then bad "$5: still running after 60 s (ulimit -v $1, $2 elements): a hang"; return; fi
  if [ $rc -eq "$3" ] && { [ -z "$4" ] || grep -q "$4" "$tmp/err_$5"; }; then
    ok "$5: exit $rc in $((t1 - t0)) s$( [ -n "$4" ] && printf ': %s' "$(head -c 120 "$tmp/err_$5")")"
  else
    bad "$5: exit $rc (want $3), stderr: $(cat "$tmp/err_$5")"
  fi
}
limited 400000 20000 0 "" "the case that hung with a thread pool"
limited 400000 50000 1 "out of memory" "too large for the limit"
limited 400000 60000 1 "out of memory" "out of memory in the statics' factorization: memory, not an indefinite tangent"
limited 300000 80000 1 "out of memory" "out of memory building the rod: exit 1, not 2"
limited 200000 20000 1 "memory" "no room for the BLAS buffer"

# GALLOP_BLAS_THREADS is read (a bad value falls back to 1) and the run still works
for v in 2 nonsense; do
  if GALLOP_BLAS_THREADS=$v "$GALLOP" modes data/scenes/drake_300m.ini -o "$tmp/t$v" >/dev/null 2>"$tmp/e$v"; then
    ok "GALLOP_BLAS_THREADS=$v: exit 0"
  else
    bad "GALLOP_BLAS_THREADS=$v: exit $?: $(cat "$tmp/e$v")"
  fi
done
# one BLAS thread by default: the process has no OpenBLAS worker threads
"$GALLOP" modes data/scenes/drake_300m.ini --set model.elements=40000 -o "$tmp/thr" >/dev/null 2>&1 &
pid=$!
sleep 0.5
n=$(awk '/^Threads:/ {print $2}' "/proc/$pid/status" 2>/dev/null)
wait $pid
[ -z "$n" ] || [ "$n" -eq 1 ] && ok "one thread by default (${n:-ended before sampling})" \
  || bad "$n threads by default"
finish
