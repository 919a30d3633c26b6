#!/usr/bin/env bash
# test_sweep_bundle.sh: `gallop sweep` on an explicit bundle ([bundle] model = explicit; README
# "Bundles"): every case runs the explicit bundle's full model (said on stderr), its figures are
# the centroid's as `gallop simulate --model full` measures them, per sub-conductor columns
# (suffix _s<k>) hold each sub-conductor's, the onset is `gallop stability`'s coupled one, a rerun
# resumes with the same sweep.csv, --continuation is refused (exit 2), and a single conductor's
# sweep.csv has no sub-conductor columns.
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
openmpi_sanitizers
scratch sweep_bundle
scene=$here/../data/scenes/quad_bundle_gallop.ini
set_=(--set bundle.model=explicit --set model.elements=42 --set simulation.duration=30
      --set stability.speed_max=6 --set stability.speed_step=0.5)
col() { head -1 "$1" | tr ',' '\n' | grep -n -x "$2" | cut -d: -f1; }
val() { local c; c=$(col "$1" "$2"); [ -n "$c" ] && sed -n "$3p" "$1" | cut -d, -f"$c"; }

"$GALLOP" sweep "$scene" "${set_[@]}" --vary wind.speed=2,8 -o "$tmp/sw" > "$tmp/out" 2> "$tmp/err"
rc=$?
[ $rc -eq 0 ] && ok "sweep runs the explicit bundle" || bad "sweep: exit $rc: $(cat "$tmp/err")"
grep -q "every case runs the explicit bundle's full model" "$tmp/err" && ok "says: the full model" ||
    bad "no word of the full model: $(cat "$tmp/err")"
grep -q '"model": "full"' "$tmp/sw/summary.json" 2>/dev/null && ok "summary.json: model full" || bad "summary.json model"
csv=$tmp/sw/sweep.csv
for c in vertical_pp_m_s1 horizontal_pp_m_s2 twist_pp_deg_s3 tension_max_n_s4; do
    [ -n "$(col "$csv" $c)" ] && ok "sweep.csv column $c" || bad "sweep.csv column $c: $(head -1 "$csv")"
done
[ -z "$(col "$csv" vertical_pp_m_s5)" ] && ok "four sub-conductors" || bad "a fifth sub-conductor column"
# the 8 m/s case against `gallop simulate --model full` of the same scene (the same run, digit for digit)
"$GALLOP" simulate "$scene" --model full "${set_[@]}" --set wind.speed=8 -o "$tmp/sim" > /dev/null 2>&1 ||
    bad "simulate --model full"
py=$(python3 - "$csv" "$tmp/sim/summary.json" <<'PY'
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1])))
p = json.load(open(sys.argv[2]))["probes"][0]
r = rows[1]
def close(a, b, rel=1e-6): return abs(a - b) <= rel * max(abs(a), abs(b), 1e-12)
out = []
out.append("centroid" if close(float(r["vertical_pp_m"]), p["centroid"]["vertical_peak_to_peak_m"]) else "CENTROID")
for k, s in enumerate(p["subconductors"]):
    ok = close(float(r["vertical_pp_m_s%d" % (k + 1)]), s["vertical_peak_to_peak_m"]) and \
         close(float(r["horizontal_pp_m_s%d" % (k + 1)]), s["horizontal_peak_to_peak_m"])
    out.append("sub" if ok else "SUB%d" % (k + 1))
mean = sum(float(r["vertical_pp_m_s%d" % k]) for k in range(1, 5)) / 4
out.append("mean" if close(mean, float(r["vertical_pp_m"]), 0.05) else "MEAN")
out.append("grows" if float(r["vertical_pp_m"]) > 10 * float(rows[0]["vertical_pp_m"]) else "GROWS")
ten = sum(float(r["tension_max_n_s%d" % k]) for k in range(1, 5))
out.append("tension" if close(ten, float(r["tension_max_n"]), 0.01) else "TENSION")
print(" ".join(out))
PY
)
[ "$py" = "centroid sub sub sub sub mean grows tension" ] && ok "figures as simulate's: $py" || bad "figures: $py"
# the onset: gallop stability's coupled onset of the explicit bundle
"$GALLOP" stability "$scene" "${set_[@]}" -o "$tmp/st" > "$tmp/st.txt" 2>&1 || bad "stability"
want=$(sed -n 's/^ *onset \([0-9.]*\) m\/s.*/\1/p' "$tmp/st.txt" | head -1)
got=$(val "$csv" onset_speed_m_s 2)
python3 -c "import sys; sys.exit(0 if abs($got - $want) < 1e-3 else 1)" 2>/dev/null &&
    ok "onset $got m/s = stability's $want" || bad "onset '$got' against stability's '$want'"
# a rerun resumes both cases: the same sweep.csv but wall_time_s
cut -d, -f1-9,11- "$csv" > "$tmp/a.csv"
"$GALLOP" sweep "$scene" "${set_[@]}" --vary wind.speed=2,8 -o "$tmp/sw" > "$tmp/out2" 2>&1
grep -q '2 cases (0 computed, 2 resumed' "$tmp/out2" && ok "rerun resumes" || bad "rerun: $(cat "$tmp/out2")"
cut -d, -f1-9,11- "$csv" > "$tmp/b.csv"
cmp -s "$tmp/a.csv" "$tmp/b.csv" && ok "resumed sweep.csv the same, sub-conductors too" || bad "resumed sweep.csv differs"
# --continuation: refused before anything runs
"$GALLOP" sweep "$scene" "${set_[@]}" --vary wind.speed=2,8 --continuation -o "$tmp/cont" > "$tmp/c.txt" 2>&1
rc=$?
[ $rc -eq 2 ] && grep -q 'continuation with \[bundle\] model = explicit' "$tmp/c.txt" && [ ! -e "$tmp/cont/sweep.csv" ] &&
    ok "--continuation refused (exit 2)" || bad "--continuation: exit $rc: $(cat "$tmp/c.txt")"
# a single conductor: no sub-conductor columns
"$GALLOP" sweep "$here/../data/scenes/iced_gallop.ini" --model full --set model.elements=16 \
    --set simulation.duration=20 --vary wind.speed=8 -o "$tmp/one" > /dev/null 2>&1
head -1 "$tmp/one/sweep.csv" 2>/dev/null | grep -q ',valid,wall_time_s$' && ok "single conductor: no _s columns" ||
    bad "single conductor header: $(head -1 "$tmp/one/sweep.csv" 2>/dev/null)"

finish
