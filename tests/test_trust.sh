#!/usr/bin/env bash
# test_trust.sh: the promises of issue 14 through the real binary: the tension measures agree
# with the tensions printed beside them; duplicate probes are refused; trace time stamps never
# repeat; the output directory is checked before any computation (`-o` a regular file, `-o ""`);
# `compare` leaves no directory behind when it fails. Ends with "#summary P F" (tests/run.sh).
set -u
GALLOP=${GALLOP:-build/gallop}
dir=$(mktemp -d /tmp/gallop_trust_XXXXXX)
trap 'rm -rf "$dir"' EXIT
passed=0; failed=0
ok()   { echo "  ok   $1"; passed=$((passed + 1)); }
fail() { echo "  FAIL $1"; failed=$((failed + 1)); }
S=data/scenes
# jnum FILE KEY: the first number under "KEY" in a summary.json
jnum() { grep -m1 "\"$2\":" "$1" | sed 's/.*: *//; s/,$//'; }

# ---- tension measures (issue 14): the largest tension is not below the support tensions ----
"$GALLOP" modes $S/drake_300m.ini -o "$dir/modes" >/dev/null 2>"$dir/err"
m=$dir/modes/summary.json
if [ -s "$m" ] && awk -v T="$(jnum "$m" tension_max_n)" -v l="$(jnum "$m" tension_left_n)" \
        -v r="$(jnum "$m" tension_right_n)" -v e="$(jnum "$m" element_tension_max_n)" \
        'BEGIN { exit !(T >= l && T >= r && T >= e && T == (l > r ? (l > e ? l : e) : (r > e ? r : e))) }'; then
    ok "modes: tension_max_n is the largest of the support and element tensions"
else
    fail "modes: tension_max_n $(jnum "$m" tension_max_n) vs support $(jnum "$m" tension_left_n) $(cat "$dir/err")"
fi
"$GALLOP" simulate $S/iced_gallop.ini --set simulation.duration=20 -o "$dir/sim" >/dev/null 2>"$dir/err"
s=$dir/sim/summary.json
if [ -s "$s" ]; then
    # the trace's support tension columns (the last two): their min and max over the run, and
    # over the steady window from steady_from_s (of the mid-span probe)
    from=$(awk '/"probes"/ { p = 1 } p && /"position": 0.5/ { q = 1 } q && /steady_from_s/ { sub(/.*: */, ""); sub(/,$/, ""); print; exit }' "$s")
    read -r tmin tmax smin smax < <(awk -F, -v from="$from" '/^[0-9]/ { for (c = NF - 1; c <= NF; c++) {
            if (mn == "" || $c < mn) mn = $c; if (mx == "" || $c > mx) mx = $c
            if ($1 >= from - 1e-9) { if (sn == "" || $c < sn) sn = $c; if (sx == "" || $c > sx) sx = $c } } }
            END { print mn, mx, sn, sx }' "$dir/sim/trace.csv")
    rel() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 1e-7 * (b < 0 ? -b : b)) }'; }
    if rel "$(jnum "$s" tension_max_n)" "$tmax" && rel "$(jnum "$s" tension_max_run_n)" "$tmax" &&
       rel "$(jnum "$s" tension_min_run_n)" "$tmin" && rel "$(jnum "$s" tension_max_steady_n)" "$smax" &&
       rel "$(jnum "$s" tension_min_steady_n)" "$smin"; then
        ok "simulate: tension_{min,max}_{run,steady}_n agree with trace.csv's support tensions"
    else
        fail "simulate: tensions run $tmin..$tmax steady $smin..$smax (from $from) vs $(grep tension "$s" | tr -d '\n ')"
    fi
else
    fail "simulate: no summary: $(cat "$dir/err")"
fi

# ---- the output directory, checked before any computation ----
: >"$dir/afile"
t0=$(date +%s)
"$GALLOP" compare $S/iced_gallop.ini -o "$dir/afile" >/dev/null 2>"$dir/err"; rc=$?
if [ $rc -eq 2 ] && grep -q "not a directory" "$dir/err" && [ $(( $(date +%s) - t0 )) -lt 5 ]; then
    ok "compare -o a regular file: exit 2 before the computation"
else
    fail "compare -o a regular file: exit $rc, $(cat "$dir/err")"
fi
"$GALLOP" modes $S/drake_300m.ini -o "$dir/afile/sub" >/dev/null 2>"$dir/err"; rc=$?
[ $rc -eq 2 ] && grep -q "afile" "$dir/err" && ok "modes -o below a regular file: exit 2" \
    || fail "modes -o below a regular file: exit $rc, $(cat "$dir/err")"
"$GALLOP" spectrum "$dir/sim/trace.csv" -o "" >/dev/null 2>"$dir/err"; rc=$?
[ $rc -eq 2 ] && grep -q "empty" "$dir/err" && ok "spectrum -o '': exit 2, empty name" \
    || fail "spectrum -o '': exit $rc, $(cat "$dir/err")"
"$GALLOP" spectrum "$dir/sim/trace.csv" -o "$dir/afile" >/dev/null 2>"$dir/err"; rc=$?
[ $rc -eq 2 ] && grep -q "not a directory" "$dir/err" && ok "spectrum -o a regular file: exit 2" \
    || fail "spectrum -o a regular file: exit $rc, $(cat "$dir/err")"
# ---- a duration too short to measure: refused before the run, naming the key, no directory ----
"$GALLOP" compare $S/iced_gallop.ini --set simulation.duration=1 -o "$dir/new/cmp" >/dev/null 2>"$dir/err"; rc=$?
if [ $rc -eq 2 ] && grep -q "\[simulation\] duration = 1 s: too short to measure" "$dir/err" && [ ! -e "$dir/new" ]; then
    ok "compare with a 1 s duration: exit 2 naming [simulation] duration, no directory made"
else
    fail "compare with a 1 s duration: exit $rc, $(cat "$dir/err"), $(ls -d "$dir/new" 2>&1)"
fi

echo "#summary $passed $failed"
[ $failed -eq 0 ]
