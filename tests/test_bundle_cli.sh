#!/usr/bin/env bash
# test_bundle_cli.sh: an explicit bundle ([bundle] model = explicit) through the real binary:
# `gallop modes` writes the single rod's files with the sub-conductor named (equilibrium.csv and
# shapes.csv column sub, modes.csv share_subspan); `simulate` (reduced, the default, and --model full)
# and `stability` run it, trace.csv with the centroid's columns and each sub-conductor's (suffix
# _s<k>), the reduced run self-checked (exit 1 past the tolerance, valid: false with warn); `compare`
# writes compare.csv with both runs per sub-conductor (measured as the centroid, at its headline
# probes over its window), or the full run alone (exit 1) when the reduced
# fails; `sweep` runs it (test_sweep_bundle.sh); accuracy refuses it with exit 2, naming the file, the line and [bundle] model, and
# saying equivalent is what runs.
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
# `gallop sweep` starts Open MPI: its own leaks under SAN=1 are suppressed as in test_sweep.sh
# (tests/lsan-openmpi.supp, with the full unwinding that reaches libmpi's frames)
openmpi_sanitizers
scratch bundle_cli

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

for cmd in accuracy; do
    "$GALLOP" $cmd "$tmp/quad.ini" -o "$tmp/$cmd" > "$tmp/$cmd.txt" 2>&1
    rc=$?
    if [ $rc -eq 2 ] && grep -q "quad.ini:$line: \[bundle\] model = explicit" "$tmp/$cmd.txt" &&
       grep -q 'allowed: model = equivalent' "$tmp/$cmd.txt" && [ ! -e "$tmp/$cmd" ]; then
        ok "$cmd refuses the explicit model (exit 2, line $line)"
    else
        bad "$cmd: exit $rc: $(cat "$tmp/$cmd.txt")"
    fi
done
"$GALLOP" accuracy data/scenes/quad_bundle_gallop.ini --set bundle.model=explicit -o "$tmp/s2" > "$tmp/s2.txt" 2>&1
rc=$?
[ $rc -eq 2 ] && grep -q -- '--set: \[bundle\] model = explicit' "$tmp/s2.txt" && ok "--set explicit refused" || bad "--set: exit $rc: $(cat "$tmp/s2.txt")"

# the reduced model's run (the default model) and compare (short: 20 s): the sub-conductors' columns
if "$GALLOP" simulate "$tmp/quad.ini" --set simulation.duration=20 -o "$tmp/red" > "$tmp/red.txt" 2>&1; then
    ok "simulate (reduced) runs"
else
    bad "simulate (reduced): $(cat "$tmp/red.txt")"
fi
hdr=$(head -1 "$tmp/red/trace.csv" 2>/dev/null)
for col in p0.5_vertical_m p0.5_vertical_m_s1 p0.25_twist_deg_s4 tension_left_n_s2 tension_right_n_s4; do
    echo ",$hdr," | grep -q ",$col," && ok "reduced trace.csv column $col" || bad "reduced trace.csv column $col: $hdr"
done
tr -d ' \n' < "$tmp/red/summary.json" 2>/dev/null | grep -q '"model":"reduced"' &&
    tr -d ' \n' < "$tmp/red/summary.json" | grep -q '"valid":true' && grep -q '"residual_max"' "$tmp/red/summary.json" &&
    ok "reduced summary.json: model, residual_max, valid" || bad "reduced summary.json: $(head -c 600 "$tmp/red/summary.json")"
# a tolerance the reduced model cannot meet: exit 1 and no output; with on_invalid = warn it finishes marked invalid
"$GALLOP" simulate "$tmp/quad.ini" --set simulation.duration=20 --set model.residual_tolerance=1e-9 -o "$tmp/inv" > "$tmp/inv.txt" 2>&1
rc=$?
[ $rc -eq 1 ] && grep -q 'residual grew to' "$tmp/inv.txt" && [ ! -e "$tmp/inv" ] && ok "invalid reduced run: exit 1" ||
    bad "invalid reduced run: exit $rc: $(cat "$tmp/inv.txt")"
"$GALLOP" simulate "$tmp/quad.ini" --set simulation.duration=20 --set model.residual_tolerance=1e-9 \
    --set model.on_invalid=warn -o "$tmp/warn" > "$tmp/warn.txt" 2>&1
rc=$?
[ $rc -eq 0 ] && grep -q 'warning' "$tmp/warn.txt" && tr -d ' \n' < "$tmp/warn/summary.json" | grep -q '"valid":false' &&
    ok "on_invalid = warn: exit 0, valid false" || bad "warn: exit $rc: $(cat "$tmp/warn.txt")"
if "$GALLOP" compare "$tmp/quad.ini" --set simulation.duration=20 -o "$tmp/cmp" > "$tmp/cmp.txt" 2>&1; then
    ok "compare runs"
else
    bad "compare: $(cat "$tmp/cmp.txt")"
fi
hdr=$(head -1 "$tmp/cmp/compare.csv" 2>/dev/null)
for col in full_vertical_m reduced_vertical_m full_twist_deg reduced_vertical_m_s1 full_twist_deg_s3 \
           reduced_tension_left_n_s2 full_tension_right_n_s4; do
    echo ",$hdr," | grep -q ",$col," && ok "compare.csv column $col" || bad "compare.csv column $col: $hdr"
done
subs=$(tr -d ' \n' < "$tmp/cmp/summary.json" 2>/dev/null | grep -o '"sub":[0-9]' | tr '\n' ' ')
[ "$subs" = '"sub":1 "sub":2 "sub":3 "sub":4 ' ] && ok "compare summary.json per sub-conductor" ||
    bad "compare summary.json: '$subs'"
# the centroid's and every sub-conductor's figures are measured alike (gal_compare_measure): over the
# window, each family at the centroid's headline probe, the columns of compare.csv
py=$(python3 - "$tmp/cmp/summary.json" "$tmp/cmp/compare.csv" <<'PY'
import csv, json, sys
s = json.load(open(sys.argv[1])); rows = list(csv.DictReader(open(sys.argv[2])))
t0 = s["steady_from_s"]; bad = []
def pp(col):
    z = [float(r[col]) for r in rows if float(r["time_s"]) >= t0 - 1e-9]
    return max(z) - min(z)
fam = (("vertical_m", "vertical_peak_to_peak_m"), ("horizontal_m", "horizontal_peak_to_peak_m"), ("twist_deg", "twist_peak_to_peak_deg"))
for run in ("full", "reduced"):
    for c, key in fam:
        if abs(pp("%s_%s" % (run, c)) - s[run][key]) > 1e-6 * abs(s[run][key]) + 1e-12: bad.append("centroid %s %s" % (run, c))
        for sub in s["subconductors"]:
            got, want = sub[run][key], pp("%s_%s_s%d" % (run, c, sub["sub"]))
            if abs(got - want) > 1e-6 * abs(want) + 1e-12: bad.append("sub %d %s %s %g %g" % (sub["sub"], run, c, got, want))
print("ok" if not bad else "bad " + "; ".join(bad[:4]))
PY
)
[ "$py" = ok ] && ok "compare: centroid and sub-conductors measured over the window at the headline probes" || bad "compare measures: $py"
# the reduced model failing in compare: the full model's results alone, exit 1
"$GALLOP" compare "$tmp/quad.ini" --set simulation.duration=20 --set model.residual_tolerance=1e-9 -o "$tmp/cf" > "$tmp/cf.txt" 2>&1
rc=$?
[ $rc -eq 1 ] && [ -e "$tmp/cf/trace.csv" ] && [ ! -e "$tmp/cf/compare.csv" ] && grep -q 'written alone' "$tmp/cf.txt" &&
    ok "compare: full results alone when the reduced fails (exit 1)" || bad "compare, reduced failing: exit $rc: $(cat "$tmp/cf.txt")"

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

finish
