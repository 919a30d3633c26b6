#!/usr/bin/env bash
# test_bundle_input.sh: [bundle] keys through the real binary: hostile values exit 2 naming the file,
# the line, the key and the allowed range (separation not above a sub-conductor's diameter, spacers
# and spacer_positions together, positions at a support, unsorted, repeated or too close), nothing
# crashes; spacer_positions at the evenly spaced places give the spacers' modes digit for digit,
# uneven ones are placed on the nearest node within 1e-3 of the span (summary.json says where); an
# 8-bundle on the largest separation runs; `simulate` and `sweep` warn below 6 elements a sub-span;
# spacer_stiffness out of range or below 100 N/m (but 0) exits 2 naming it.
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
scratch bundle_input

# a twin on 24 elements; line 12 is the [bundle] line under test
scene() {
    cat <<EOF2
; test_bundle_input.sh
[span]
length = 200
horizontal_tension = 40000
[conductor]
name = Drake
[model]
elements = 24
[bundle]
subconductors = ${2:-2}
separation = ${3:-0.457}
$1
model = explicit
EOF2
}
refuse() { # line key pattern-of-allowed scene-args...
    local line=$1 key=$2 pat=$3; shift 3
    scene "$@" > "$tmp/s.ini"
    "$GALLOP" modes "$tmp/s.ini" -o "$tmp/o" > "$tmp/out" 2>&1
    local rc=$?
    if [ $rc -eq 2 ] && grep -q "s.ini:$line: \[bundle\] $key = " "$tmp/out" && grep -q "allowed: .*$pat" "$tmp/out" &&
       [ ! -e "$tmp/o" ]; then ok "refused: $key ($*)"; else bad "$key ($*): exit $rc: $(cat "$tmp/out")"; fi
    rm -rf "$tmp/o"
}
refuse 11 separation '0.02814 < separation <= 2' "spacers = 4" 2 0.02
refuse 11 separation '0.02814 < separation <= 2' "spacers = 4" 8 0.0281
refuse 12 spacer_positions 'one of the two' "spacer_positions = 0.5
spacers = 3"
refuse 12 spacer_positions '0 < p < 1' "spacer_positions = 0, 0.5"
refuse 12 spacer_positions '0 < p < 1' "spacer_positions = 0.5, 1"
refuse 12 spacer_positions 'increasing' "spacer_positions = 0.6, 0.4"
refuse 12 spacer_positions 'increasing' "spacer_positions = 0.4, 0.4"
refuse 12 spacer_positions 'at least 0.005 of the span' "spacer_positions = 0.4, 0.402"
refuse 12 spacer_positions 'at least 0.005 of the span' "spacer_positions = 0.999"
refuse 12 spacer_positions 'not a number\|fractions' "spacer_positions = 0.4,,0.6"

# the evenly spaced places by position: the same modes as by count
scene "spacers = 3" > "$tmp/even.ini"
scene "spacer_positions = 0.25, 0.5, 0.75" > "$tmp/pos.ini"
"$GALLOP" modes "$tmp/even.ini" -o "$tmp/even" > /dev/null 2>&1 && "$GALLOP" modes "$tmp/pos.ini" -o "$tmp/pos" > /dev/null 2>&1 &&
    cmp -s "$tmp/even/modes.csv" "$tmp/pos/modes.csv" && ok "positions 0.25, 0.5, 0.75 = spacers 3 (modes.csv)" ||
    bad "positions against count: $(diff "$tmp/even/modes.csv" "$tmp/pos/modes.csv" 2>&1 | head -4)"
# uneven: each on a node within 1e-3 of the span, the mesh refined to at least 2 elements a sub-span
scene "spacer_positions = 0.13, 0.31, 0.62" > "$tmp/uneven.ini"
if "$GALLOP" modes "$tmp/uneven.ini" -o "$tmp/un" > "$tmp/un.txt" 2>&1; then
    py=$(python3 - "$tmp/un/summary.json" <<'PY'
import json, sys
b = json.load(open(sys.argv[1]))["bundle"]
want = [0.13, 0.31, 0.62]
got = b["spacer_positions"]
print("ok" if len(got) == 3 and max(abs(a - w) for a, w in zip(got, want)) <= 1e-3 else "bad %s" % got)
PY
)
    [ "$py" = ok ] && ok "uneven positions within 1e-3 of the span" || bad "uneven positions: $py"
    grep -q 'explicit bundle of 2 sub-conductors, 3 spacers' "$tmp/un.txt" && ok "uneven: 3 spacers" || bad "uneven: $(head -1 "$tmp/un.txt")"
else
    bad "uneven positions: $(cat "$tmp/un.txt")"
fi
# `gallop check` prints spacer_positions (and reads its own print back)
"$GALLOP" check "$tmp/uneven.ini" > "$tmp/chk.ini" 2>&1 && grep -q '^spacer_positions = 0.13, 0.31, 0.62 ' "$tmp/chk.ini" &&
    ! grep -q '^spacers = ' "$tmp/chk.ini" && "$GALLOP" check "$tmp/chk.ini" > /dev/null 2>&1 &&
    ok "check prints spacer_positions and reads it back" || bad "check: $(grep -A3 '^\[bundle' "$tmp/chk.ini")"
# an 8-bundle on the largest separation (2 m, a 2.6 m circle) runs
scene "spacers = 3" 8 2 > "$tmp/eight.ini"
"$GALLOP" modes "$tmp/eight.ini" -o "$tmp/eight" > "$tmp/eight.txt" 2>&1 &&
    grep -q 'explicit bundle of 8 sub-conductors' "$tmp/eight.txt" && ok "8 on 2 m separation" || bad "8 on 2 m: $(tail -3 "$tmp/eight.txt")"

# simulate and compare warn when a sub-span has fewer than 6 elements (the galloping runs' mesh rule)
scene "spacers = 3" > "$tmp/coarse.ini"
"$GALLOP" simulate "$tmp/coarse.ini" --model full --set model.elements=12 --set simulation.duration=4 -o "$tmp/c12" > /dev/null 2> "$tmp/c12.err"
grep -q 'warning: the explicit bundle.s mesh has 3 elements in its shortest sub-span.*model.elements >= 24' "$tmp/c12.err" &&
    ok "3 elements a sub-span: warned" || bad "no mesh warning: $(cat "$tmp/c12.err")"
"$GALLOP" simulate "$tmp/coarse.ini" --model full --set simulation.duration=4 -o "$tmp/c24" > /dev/null 2> "$tmp/c24.err"
! grep -q 'mesh has' "$tmp/c24.err" && [ -s "$tmp/c24/trace.csv" ] && ok "6 elements a sub-span: no warning" ||
    bad "24 elements: $(cat "$tmp/c24.err")"

# sweep warns as well (its cases run the explicit bundle's full model)
"$GALLOP" sweep "$tmp/coarse.ini" --vary wind.speed=4 --set model.elements=12 --set simulation.duration=4 -o "$tmp/sw12" > /dev/null 2> "$tmp/sw12.err"
grep -q 'gallop sweep: warning: the explicit bundle.s mesh has 3 elements in its shortest sub-span.*model.elements >= 24' "$tmp/sw12.err" &&
    ok "sweep, 3 elements a sub-span: warned" || bad "sweep: no mesh warning: $(cat "$tmp/sw12.err")"
"$GALLOP" sweep "$tmp/coarse.ini" --vary wind.speed=4 --set simulation.duration=4 -o "$tmp/sw24" > /dev/null 2> "$tmp/sw24.err"
! grep -q 'mesh has' "$tmp/sw24.err" && [ -s "$tmp/sw24/sweep.csv" ] && ok "sweep, 6 elements a sub-span: no warning" ||
    bad "sweep, 24 elements: $(cat "$tmp/sw24.err")"

# flexible spacers ([bundle] spacer_stiffness): out of range or below the softest, exit 2 naming it
refuse 12 spacer_stiffness '0 (rigid spacers) or 100 to 1e+09 N/m' "spacer_stiffness = 50"
refuse 12 spacer_stiffness '0 <= spacer_stiffness <= 1000000000 N/m' "spacer_stiffness = 2e9"
refuse 12 spacer_stiffness '0 <= spacer_stiffness' "spacer_stiffness = -3"
refuse 12 spacer_stiffness 'not a number\|0 <= spacer_stiffness' "spacer_stiffness = stiff"
# `gallop check` prints it (and reads its own print back); rigid scenes do not print it
scene "spacers = 3
spacer_stiffness = 2.5e5" > "$tmp/flex.ini"
"$GALLOP" check "$tmp/flex.ini" > "$tmp/flex_chk.ini" 2>&1 && grep -q '^spacer_stiffness = 250000 ' "$tmp/flex_chk.ini" &&
    "$GALLOP" check "$tmp/flex_chk.ini" > /dev/null 2>&1 && ! grep -q spacer_stiffness "$tmp/chk.ini" &&
    ok "check prints spacer_stiffness and reads it back" || bad "check: $(grep -A9 '^\[bundle' "$tmp/flex_chk.ini")"

finish
