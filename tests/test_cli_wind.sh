#!/usr/bin/env bash
# test_cli_wind.sh: `gallop wind` end to end on a copy of the iced scene with Kaimal turbulence over
# a 600 s record: exit 0, wind.csv and summary.json, the header, mean speed within 5% of U and
# standard deviation within 15% of I U at every written point, same seed same file, another seed
# another field, --points, the other spectra; turbulence = none and bad --points: exit 2.
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
scratch cli_wind
cp data/scenes/iced_gallop.ini "$tmp/iced.ini"
set -- --set ice.aero_table="$PWD/data/aero/iced_d_shape.csv" --set wind.turbulence=kaimal \
       --set wind.intensity=0.15 --set wind.speed=12 --set simulation.duration=599

if "$GALLOP" wind "$tmp/iced.ini" "$@" -o "$tmp/w" >"$tmp/out" 2>"$tmp/err"; then
  ok "wind on the iced scene with kaimal turbulence exits 0"
else
  bad "wind: exit $?: $(cat "$tmp/err")"
fi
for f in wind.csv summary.json; do
  [ -s "$tmp/w/$f" ] && ok "writes $f" || bad "no $f"
done
ls "$tmp/w" | grep -q tmp && bad "temporary files left behind" || ok "no temporary files left"
csv="$tmp/w/wind.csv"; js="$tmp/w/summary.json"
[ "$(head -n 1 "$csv")" = "time_s,u_x0m,u_x50m,u_x100m,u_x150m,u_x200m" ] && ok "wind.csv header: 5 points" \
  || bad "header: $(head -n 1 "$csv")"
n=$(($(wc -l <"$csv") - 1))
[ "$n" -eq 12000 ] && ok "12000 samples at 20 Hz (duration + 1 s)" || bad "$n samples"
for k in command scene spectrum target_sigma_m_s coherence_decay points mean_m_s std_m_s generation_wall_time_s; do
  grep -q "\"$k\"" "$js" || missing="${missing:-} $k"
done
[ -z "${missing:-}" ] && ok "summary.json has the keys" || bad "summary.json lacks$missing"
grep -q '"spectrum": "kaimal"' "$js" && grep -q '"target_sigma_m_s": 1.8,' "$js" && ok "kaimal, target sigma I U = 1.8 m/s" \
  || bad "spectrum / target sigma: $(grep -E 'spectrum|target' "$js")"
# every written point: mean within 5% of U = 12, std within 15% of I U = 1.8
if awk -F, 'NR > 1 { for (c = 2; c <= NF; c++) { s[c] += $c; s2[c] += $c * $c } n++; nc = NF }
     END { for (c = 2; c <= nc; c++) { m = s[c] / n; sd = sqrt(s2[c] / n - m * m);
             printf "    x%d: mean %.4f std %.4f\n", c - 2, m, sd;
             if (m < 12 * 0.95 || m > 12 * 1.05 || sd < 1.8 * 0.85 || sd > 1.8 * 1.15) bad++ }
           exit bad > 0 }' "$csv" >"$tmp/mom"; then
  ok "mean within 5% of U and std within 15% of I U at every point"
else
  bad "moments: $(cat "$tmp/mom")"
fi
# the summary's moments are those of the file
m1=$(awk -F, 'NR > 1 {s += $4; n++} END {printf "%.4f", s / n}' "$csv")
m2=$(grep '"mean_m_s"' "$js" | sed -n 3p | sed 's/.*: *//; s/,//' | awk '{printf "%.4f", $1}')
[ "$m1" = "$m2" ] && ok "summary mean at mid-span = the file's ($m1 m/s)" || bad "mid-span mean: $m1 vs $m2"
# reproducible, seeded
"$GALLOP" wind "$tmp/iced.ini" "$@" -o "$tmp/w2" >/dev/null 2>&1
cmp -s "$csv" "$tmp/w2/wind.csv" && ok "same seed: identical wind.csv" || bad "same seed gives a different wind.csv"
"$GALLOP" wind "$tmp/iced.ini" "$@" --set wind.seed=2 -o "$tmp/w3" >/dev/null 2>&1
[ -s "$tmp/w3/wind.csv" ] && ! cmp -s "$csv" "$tmp/w3/wind.csv" && ok "seed 2: another field" || bad "seed 2 gives the same field"
# --points
"$GALLOP" wind "$tmp/iced.ini" "$@" --points 3 -o "$tmp/p3" >/dev/null 2>&1
[ "$(head -n 1 "$tmp/p3/wind.csv")" = "time_s,u_x0m,u_x100m,u_x200m" ] && ok "--points 3" || bad "--points 3: $(head -n 1 "$tmp/p3/wind.csv")"
"$GALLOP" wind "$tmp/iced.ini" "$@" --points 65 -o "$tmp/p65" >/dev/null 2>&1
[ "$(head -n 1 "$tmp/p65/wind.csv" | awk -F, '{print NF, $3}')" = "66 u_x3.125m" ] && ok "--points 65: every point" \
  || bad "--points 65: $(head -n 1 "$tmp/p65/wind.csv" | cut -c1-60)"
for v in 0 66 x; do
  "$GALLOP" wind "$tmp/iced.ini" "$@" --points $v -o "$tmp/pbad" >/dev/null 2>"$tmp/err"
  rc=$?
  [ $rc -eq 2 ] && [ ! -e "$tmp/pbad" ] && ok "--points $v: exit 2" || bad "--points $v: exit $rc"
done
for s in davenport von_karman; do
  "$GALLOP" wind "$tmp/iced.ini" "$@" --set wind.turbulence=$s -o "$tmp/$s" >/dev/null 2>&1 \
    && grep -q "\"spectrum\": \"$s\"" "$tmp/$s/summary.json" && ok "$s spectrum" || bad "$s spectrum"
done
# no turbulence: exit 2 with the reason, nothing written
"$GALLOP" wind "$tmp/iced.ini" --set ice.aero_table="$PWD/data/aero/iced_d_shape.csv" -o "$tmp/none" >/dev/null 2>"$tmp/err"
rc=$?
[ $rc -eq 2 ] && grep -q "needs \[wind\] turbulence" "$tmp/err" && ok "turbulence none: exit 2 with the reason" \
  || bad "turbulence none: exit $rc: $(cat "$tmp/err")"
[ -e "$tmp/none" ] && bad "turbulence none wrote output" || ok "turbulence none writes nothing"
# the vertical component: w columns, its statistics in summary.json and on stdout; the turbulence
# effect off removes both components from the simulations, and `gallop wind` says so on stderr
"$GALLOP" wind "$tmp/iced.ini" "$@" --set wind.vertical_turbulence=on --points 3 -o "$tmp/v" >"$tmp/vout" 2>"$tmp/verr"
[ "$(head -n 1 "$tmp/v/wind.csv")" = "time_s,u_x0m,u_x100m,u_x200m,w_x0m,w_x100m,w_x200m" ] && ok "vertical: w columns" \
  || bad "vertical header: $(head -n 1 "$tmp/v/wind.csv")"
grep -q '"vertical_turbulence": "on"' "$tmp/v/summary.json" && grep -q '"vertical": {' "$tmp/v/summary.json" \
  && grep -q "vertical w: I_w = 0.075" "$tmp/vout" && ok "vertical: statistics in summary.json and on stdout" \
  || bad "vertical statistics: $(grep -c vertical "$tmp/v/summary.json") $(cat "$tmp/vout")"
# sd of w at x = 0, a point of the field, within 15% of the sigma its discrete spectrum carries (the
# Kaimal w spectrum, L_w = 4.62 m, has a fifth of its variance above the 10 Hz Nyquist frequency;
# 600 s); between the field's points the linear interpolation lowers the point variance of the
# high frequencies, whose coherence over 2.4 m is low (windfield.h)
sw=$(grep -A4 '"vertical": {' "$tmp/v/summary.json" | grep discrete_sigma | sed 's/.*: *//; s/,//')
awk -F, -v sw="${sw:-0}" 'NR > 1 { s += $5; s2 += $5 * $5; n++ } END { m = s / n; sd = sqrt(s2 / n - m * m);
  printf "%.4f %.4f of %.4f", m, sd, sw; exit (m < -0.1 || m > 0.1 || sd < sw * 0.85 || sd > sw * 1.15) }' "$tmp/v/wind.csv" >"$tmp/wm" \
  && ok "w at x = 0: mean ~0, sd within 15% of the discrete sigma ($(cat "$tmp/wm"))" || bad "w moments: $(cat "$tmp/wm")"
[ -s "$tmp/verr" ] && bad "a note with the effect on: $(cat "$tmp/verr")" || ok "effect on: nothing on stderr"
"$GALLOP" wind "$tmp/iced.ini" "$@" --set wind.vertical_turbulence=on --set effects.turbulence=off -o "$tmp/voff" >/dev/null 2>"$tmp/verr"
grep -q "turbulence = off: simulations use neither the along-wind field nor the vertical one" "$tmp/verr" \
  && ok "effect off: the note on stderr" || bad "effect off: $(cat "$tmp/verr")"
finish
