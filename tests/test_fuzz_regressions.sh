#!/usr/bin/env bash
# test_fuzz_regressions.sh: the inputs kept in tests/fuzz/regressions/ (issue 8: crashes and
# near-misses found by `make fuzz`, and hand-made nasty inputs) fed to the real binary: scenes
# (*.ini) to `gallop check`, aerodynamic tables (*.csv) as the [ice] aero_table of a valid scene
# to `gallop check`. Each must give exit 0 or 2 with a message, never a crash or a hang.
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
scratch fuzzreg
printf '[span]\nlength = 200\nhorizontal_tension = 25000\n[conductor]\nname = Drake\n[ice]\nmass_per_length = 0.6\n' \
    >"$tmp/base.ini"
n=0
for f in tests/fuzz/regressions/*; do
    [ -f "$f" ] || continue
    n=$((n + 1))
    case "$f" in
        *.ini) timeout 20 "$GALLOP" check "$f" >/dev/null 2>"$tmp/err" ;;
        *.csv) timeout 20 "$GALLOP" check "$tmp/base.ini" --set "ice.aero_table=$PWD/$f" >/dev/null 2>"$tmp/err" ;;
        *) continue ;;
    esac
    rc=$?
    if [ $rc -eq 0 ] || { [ $rc -eq 2 ] && [ -s "$tmp/err" ]; }; then
        ok "$(basename "$f"): exit $rc $(head -n 1 "$tmp/err" | cut -c1-100)"
    else
        bad "$(basename "$f"): exit $rc: $(head -n 3 "$tmp/err")"
    fi
done
[ $n -gt 0 ] && ok "$n regression inputs" || bad "no inputs in tests/fuzz/regressions"
finish
