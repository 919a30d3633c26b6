#!/usr/bin/env bash
# test_bundle_cli.sh: an explicit bundle ([bundle] model = explicit) through the real binary:
# `gallop modes` writes the single rod's files with the sub-conductor named (equilibrium.csv and
# shapes.csv column sub, modes.csv share_subspan); `simulate --model full` and `stability` run it (sweep: test_sweep_bundle.sh), trace.csv with
# the centroid's columns and each sub-conductor's (suffix _s<k>); simulate (reduced) and compare
# refuse it with exit 2, naming the file, the line and [bundle] model, and saying
# equivalent is what runs.
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
pass=0; fail=0
ok()  { pass=$((pass + 1)); echo "  ok   $1"; }
bad() { fail=$((fail + 1)); echo "  FAIL $1"; }
# `gallop sweep` starts Open MPI: its own leaks under SAN=1 are suppressed as in test_sweep.sh
# (tests/lsan-openmpi.supp, with the full unwinding that reaches libmpi's frames)
export LSAN_OPTIONS="suppressions=$(cd "$(dirname "$0")" && pwd)/lsan-openmpi.supp:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
export ASAN_OPTIONS="fast_unwind_on_malloc=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
tmp=$(mktemp -d /tmp/gallop_bundle_cli_XXXXXX)
trap 'rm -rf "$tmp"' EXIT

sed 's/^model = equivalent/model = explicit/' data/scenes/quad_bundle_gallop.ini > "$tmp/quad.ini"
sed -i 's#\.\./aero/#'"$PWD"'/data/aero/#' "$tmp/quad.ini"
line=$(grep -n '^model = explicit' "$tmp/quad.ini" | cut -d: -f1)

if "$GALLOP" modes "$tmp/quad.ini" -o "$tmp/modes" > "$tmp/modes.txt" 2>&1; then ok "modes runs"; else bad "modes runs: $(cat "$tmp/modes.txt")"; fi
grep -q 'explicit bundle of 4 sub-conductors, 6 spacers' "$tmp/modes.txt" && ok "table names the bundle" || bad "table names the bundle"
head -1 "$tmp/modes/modes.csv" 2>/dev/null | grep -q 'share_subspan' && ok "modes.csv share_subspan" || bad "modes.csv share_subspan"
head -1 "$tmp/modes/shapes.csv" 2>/dev/null | grep -q '^mode,family,frequency_hz,sub,node' && ok "shapes.csv sub" || bad "shapes.csv sub"
subs=$(tail -n +2 "$tmp/modes/equilibrium.csv" 2>/dev/null | cut -d, -f1 | sort -u | tr '\n' ' ')
[ "$subs" = "1 2 3 4 " ] && ok "equilibrium.csv: 4 sub-conductors" || bad "equilibrium.csv: sub-conductors '$subs'"
grep -q '"model": "explicit"' "$tmp/modes/summary.json" 2>/dev/null && ok "summary.json bundle" || bad "summary.json bundle"

for cmd in simulate compare; do
    "$GALLOP" $cmd "$tmp/quad.ini" -o "$tmp/$cmd" > "$tmp/$cmd.txt" 2>&1
    rc=$?
    if [ $rc -eq 2 ] && grep -q "quad.ini:$line: \[bundle\] model = explicit" "$tmp/$cmd.txt" &&
       grep -q 'allowed: model = equivalent' "$tmp/$cmd.txt" && [ ! -e "$tmp/$cmd" ]; then
        ok "$cmd refuses the explicit model (exit 2, line $line)"
    else
        bad "$cmd: exit $rc: $(cat "$tmp/$cmd.txt")"
    fi
done
"$GALLOP" simulate data/scenes/quad_bundle_gallop.ini --set bundle.model=explicit -o "$tmp/s2" > "$tmp/s2.txt" 2>&1
rc=$?
[ $rc -eq 2 ] && grep -q -- '--set: \[bundle\] model = explicit' "$tmp/s2.txt" && ok "--set explicit refused" || bad "--set: exit $rc: $(cat "$tmp/s2.txt")"

# the full model's run of the explicit bundle (short: 20 s)
if "$GALLOP" simulate "$tmp/quad.ini" --model full --set simulation.duration=20 -o "$tmp/full" > "$tmp/full.txt" 2>&1; then
    ok "simulate --model full runs"
else
    bad "simulate --model full: $(cat "$tmp/full.txt")"
fi
hdr=$(head -1 "$tmp/full/trace.csv" 2>/dev/null)
for col in p0.5_vertical_m p0.5_twist_deg tension_left_n p0.5_vertical_m_s1 p0.25_twist_deg_s4 tension_left_n_s2 tension_right_n_s4; do
    echo ",$hdr," | grep -q ",$col," && ok "trace.csv column $col" || bad "trace.csv column $col: $hdr"
done
rows=$(tail -n +2 "$tmp/full/trace.csv" 2>/dev/null | wc -l)
[ "$rows" -ge 64 ] && ok "trace.csv: $rows samples" || bad "trace.csv: $rows samples"
grep -q '"model": "explicit"' "$tmp/full/summary.json" 2>/dev/null && grep -q '"subconductors": \[' "$tmp/full/summary.json" &&
    ok "summary.json: explicit, per sub-conductor measures" || bad "summary.json: $(head -c 400 "$tmp/full/summary.json" 2>/dev/null)"
# the leeward sub-conductor of the quad at orientation 0 (a diamond) in a wind across the span: 1, behind 3
grep -A3 '"leeward"' "$tmp/full/summary.json" | tr -d ' \n' | grep -q '"leeward":\[1\]' && ok "leeward 1" ||
    bad "leeward: $(grep -A3 '"leeward"' "$tmp/full/summary.json")"

echo "#summary $pass $fail"
[ "$fail" -eq 0 ]
