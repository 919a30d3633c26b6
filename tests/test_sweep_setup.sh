#!/usr/bin/env bash
# test_sweep_setup.sh: `gallop sweep` finds a span's equilibrium and modes once (issue 13; run/sweep.h
# gal_sweep_setup_cache, forward.h gal_data_share): over the wind the set-up is computed by the first
# case and reused by the others (summary.json setups_computed, setups_reused, damping_computed), and
# every case's record is the one the case alone computes (its own process, its own set-up), to all
# 17 digits; a varied key that the set-up reads (span.length) computes it again, and a varied damping
# ratio keeps the equilibrium and modes but builds the damping anew; the rows are `gallop simulate`'s
# figures, reduced and full model. The reduced model's own wind-independent set-up (its basis and
# the internal force's sample: gal_data.rom_setup) is computed once per span too (summary.json
# reduced_setups_computed, reduced_setups_reused), its records still those of the cases alone.
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
scratch sweep_setup
scene=$here/../data/scenes/iced_gallop.ini
openmpi_sanitizers
small=(--set model.elements=40 --set simulation.duration=20 --set stability.speed_max=12)
counts() { jq -r '[.computed, .setups_computed, .setups_reused, .damping_computed] | map(tostring) | join(" ")' \
             "$1/summary.json" 2>/dev/null; }
romcounts() { jq -r '[.reduced_setups_computed, .reduced_setups_reused] | map(tostring) | join(" ")' \
                "$1/summary.json" 2>/dev/null; }
# a case's record less its wall time
rec() { grep -v '^wall_time_s ' "$1"; }
# every record of sweep $1 against the one-case sweeps of $2 (their own processes): digit for digit
same_records() {
  local n=0 d=0 f
  for f in "$1"/cases/*.case; do
    n=$((n + 1))
    local g; g=$(ls "$2"/*/cases/"$(basename "$f")" 2>/dev/null | head -1)
    if [ -z "$g" ] || ! cmp -s <(rec "$f") <(rec "$g"); then d=$((d + 1)); fi
  done
  [ $n -gt 0 ] && [ $d -eq 0 ]
}

for model in reduced full; do
  # ---- over the wind: one set-up ----
  "$GALLOP" sweep "$scene" --model $model --vary wind.speed=4,8,12 "${small[@]}" -o "$tmp/w$model" \
    > /dev/null 2> "$tmp/err"; rc=$?
  [ $rc -eq 0 ] && [ "$(counts "$tmp/w$model")" = "3 1 2 1" ] \
    && ok "$model, 3 wind speeds: the set-up computed once, reused twice" \
    || bad "$model, wind: exit $rc, computed/setups/reused/damping $(counts "$tmp/w$model"): $(tail -2 "$tmp/err")"
  want="1 2"; [ $model = full ] && want="0 0"
  [ "$(romcounts "$tmp/w$model")" = "$want" ] && ok "$model, 3 wind speeds: reduced set-ups computed/reused $want" \
    || bad "$model, wind: reduced set-ups computed/reused $(romcounts "$tmp/w$model"), want $want"
  for v in 4 8 12; do
    "$GALLOP" sweep "$scene" --model $model --vary wind.speed=$v "${small[@]}" -o "$tmp/s$model/$v" > /dev/null 2>&1
  done
  want="1 1 0 1 1 0"; [ $model = full ] && want="1 1 0 1 0 0"
  [ "$(counts "$tmp/s$model/8") $(romcounts "$tmp/s$model/8")" = "$want" ] \
    && ok "$model, a one-case sweep computes its own set-up" \
    || bad "$model, one-case sweep: $(counts "$tmp/s$model/8") $(romcounts "$tmp/s$model/8")"
  same_records "$tmp/w$model" "$tmp/s$model" \
    && ok "$model: every case as computed alone, to 17 digits" || bad "$model: a case differs from its run alone"
  # the row at 8 m/s is `gallop simulate`'s
  "$GALLOP" simulate "$scene" --model $model --set wind.speed=8 "${small[@]}" -o "$tmp/sim$model" > /dev/null 2>&1
  py=$(python3 - "$tmp/w$model/sweep.csv" "$tmp/sim$model/summary.json" <<'PY'
import csv, json, sys
r = [x for x in csv.DictReader(open(sys.argv[1])) if float(x["wind.speed"]) == 8][0]
p = json.load(open(sys.argv[2]))["probes"][0]
def close(a, b): return abs(a - b) <= 1e-7 * max(abs(a), abs(b), 1e-12)
ok = close(float(r["vertical_pp_m"]), p["vertical"]["peak_to_peak_m"]) and \
     close(float(r["horizontal_pp_m"]), p["horizontal"]["peak_to_peak_m"]) and \
     close(float(r["twist_pp_deg"]), p["twist"]["peak_to_peak_deg"]) and \
     close(float(r["frequency_hz"]), p["vertical"]["frequency_hz"])
print("same" if ok else "differ: %s %s" % (dict(r), p["vertical"]))
PY
)
  [ "$py" = same ] && ok "$model: the 8 m/s row is gallop simulate's" || bad "$model: row against simulate: $py"
done

# ---- a key the set-up reads: computed again per span ----
"$GALLOP" sweep "$scene" --vary wind.speed=4,8 --vary span.length=200,220 "${small[@]}" -o "$tmp/span" \
  > /dev/null 2> "$tmp/err"; rc=$?
[ $rc -eq 0 ] && [ "$(counts "$tmp/span") $(romcounts "$tmp/span")" = "4 2 2 2 2 2" ] && ok "2 spans x 2 speeds: two set-ups, each reused once" \
  || bad "span: exit $rc, $(counts "$tmp/span") $(romcounts "$tmp/span"): $(tail -2 "$tmp/err")"
for L in 200 220; do for v in 4 8; do
  "$GALLOP" sweep "$scene" --vary wind.speed=$v --set span.length=$L "${small[@]}" -o "$tmp/sspan/$L-$v" \
    > /dev/null 2>&1
done; done
same_records "$tmp/span" "$tmp/sspan" && ok "spans: every case as computed alone" || bad "spans: a case differs"

# ---- the damping ratio: the equilibrium and modes kept, the damping built anew ----
"$GALLOP" sweep "$scene" --vary wind.speed=4,8 --vary conductor.damping_ratio=0.002,0.01 "${small[@]}" \
  -o "$tmp/damp" > /dev/null 2> "$tmp/err"; rc=$?
[ $rc -eq 0 ] && [ "$(counts "$tmp/damp") $(romcounts "$tmp/damp")" = "4 1 3 3 1 3" ] \
  && ok "2 dampings x 2 speeds: one set-up (the reduced one too), the damping built for the other ratio" \
  || bad "damping: exit $rc, $(counts "$tmp/damp") $(romcounts "$tmp/damp"): $(tail -2 "$tmp/err")"
for z in 0.002 0.01; do for v in 4 8; do
  "$GALLOP" sweep "$scene" --vary wind.speed=$v --set conductor.damping_ratio=$z "${small[@]}" \
    -o "$tmp/sdamp/$z-$v" > /dev/null 2>&1
done; done
same_records "$tmp/damp" "$tmp/sdamp" && ok "dampings: every case as computed alone" || bad "dampings: a case differs"
# the damping is the case's own: more damping, less motion at 8 m/s
awk -F, '$1 == 8 && $2 == 0.002 { a = $4 } $1 == 8 && $2 == 0.01 { b = $4 } END { exit !(b < a) }' \
  "$tmp/damp/sweep.csv" && ok "the higher ratio damps more" || bad "damping rows: $(cat "$tmp/damp/sweep.csv")"

finish
