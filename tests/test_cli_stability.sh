#!/usr/bin/env bash
# test_cli_stability.sh: `gallop stability` end to end on a copy of the iced scene: exit 0 and the
# two files, H = dC_L/dalpha + C_D on every row, the onset speed -4 m zeta w / (rho d H) recomputed
# from the scene's numbers and the mode's frequency, the unstable ranges against the H column, the
# zero-damping case, the attack angle; the coupled onset (vg.csv, issue 15); a scene without an aero table: exit 2, nothing written.
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
scratch cli_stability
cp data/scenes/iced_gallop.ini "$tmp/iced.ini"
tab="--set ice.aero_table=$PWD/data/aero/iced_d_shape.csv"

if "$GALLOP" stability "$tmp/iced.ini" $tab --set conductor.damping_ratio=0.005 -o "$tmp/s" >"$tmp/out" 2>"$tmp/err"; then
  ok "stability on the iced scene exits 0"
else
  bad "stability on the iced scene: exit $?: $(cat "$tmp/err")"
fi
for f in stability.csv summary.json; do
  [ -s "$tmp/s/$f" ] && ok "writes $f" || bad "no $f"
done
ls "$tmp/s" | grep -q tmp && bad "temporary files left behind" || ok "no temporary files left"
csv="$tmp/s/stability.csv"; js="$tmp/s/summary.json"
hdr="alpha_deg,cd,cl,cm,dcl_dalpha,den_hartog,onset_speed_mode1_m_s,onset_speed_mode2_m_s,onset_speed_mode3_m_s"
[ "$(head -n 1 "$csv")" = "$hdr" ] && ok "stability.csv header" || bad "stability.csv header: $(head -n 1 "$csv")"
n=$(awk -F, 'NR > 1' "$csv" | wc -l)
[ "$n" -eq 361 ] && awk -F, 'NR == 2 && $1 == -180 {a = 1} END {exit !(a && $1 == 180)}' "$csv" \
  && ok "361 angles from -180 to 180 deg" || bad "rows: $n"
for k in command scene table table_source attack_angle_deg den_hartog_at_rest unstable_ranges_deg \
         min_den_hartog modes index frequency_hz onset_speed_at_rest_m_s lowest_onset_speed_m_s at_alpha_deg wall_time_s; do
  grep -q "\"$k\"" "$js" || missing="${missing:-} $k"
done
[ -z "${missing:-}" ] && ok "summary.json has the keys of issue 4" || bad "summary.json lacks$missing"
awk -F, 'NR > 1 { d = $6 - ($5 + $2); if (d < 0) d = -d; if (d > 1e-8) bad++ } END {exit bad > 0}' "$csv" \
  && ok "den_hartog = dcl_dalpha + cd on every row" || bad "den_hartog differs from dcl_dalpha + cd"
awk -F, 'NR > 1 { if (($6 < 0) != ($7 != "")) bad++ } END {exit bad > 0}' "$csv" \
  && ok "an onset speed exactly where H < 0 (empty where H >= 0)" || bad "onset column vs the sign of H"

# the onset at alpha = 10 deg recomputed: m = Drake + 0.6 kg/m ice, zeta 0.005, rho 1.225, d of Drake
m=$(awk -F, '$1=="Drake"{print $3 + 0.6}' data/conductors.csv)
d=$(awk -F, '$1=="Drake"{print $2}' data/conductors.csv)
f1=$(grep -m 1 '"frequency_hz"' "$js" | sed 's/.*: *//; s/,//')
f3=$(grep '"frequency_hz"' "$js" | sed -n 3p | sed 's/.*: *//; s/,//')
for col in 7:$f1 9:$f3; do
  c=${col%%:*}; f=${col#*:}
  if awk -F, -v m="$m" -v d="$d" -v f="$f" -v c="$c" '$1 == 10 {
        pi = 3.14159265358979; u = -4 * m * 0.005 * 2 * pi * f / (1.225 * d * $6);
        e = ($c - u) / u; if (e < 0) e = -e; found = 1; exit !(e < 0.005) }
      END { if (!found) exit 1 }' "$csv"; then
    ok "onset speed (column $c) at 10 deg = -4 m zeta w / (rho d H) within 0.5%"
  else
    bad "onset speed (column $c) at 10 deg: $(awk -F, '$1 == 10' "$csv"), m $m d $d f $f"
  fi
done
# the vertical frequencies are those of `gallop modes`
"$GALLOP" modes "$tmp/iced.ini" $tab -o "$tmp/m" >/dev/null 2>&1
fm=$(awk -F, '$2=="vertical"{print $4; exit}' "$tmp/m/modes.csv")
awk -v a="$f1" -v b="$fm" 'BEGIN {e = (a - b) / b; if (e < 0) e = -e; exit !(e < 1e-6)}' \
  && ok "mode 1 frequency $f1 Hz = the first vertical mode of gallop modes" || bad "mode 1: $f1 vs $fm"

# unstable ranges: runs of H < 0 in the CSV
want=$(awk -F, 'NR > 1 { if ($6 < 0) { if (!in_) { s = $1; in_ = 1 } e = $1 } else if (in_) { printf "%s,%s;", s, e; in_ = 0 } }
                END { if (in_) printf "%s,%s;", s, e }' "$csv")
got=$(sed -n '/"unstable_ranges_deg"/,/"min_den_hartog"/p' "$js" | grep -E '^ *-?[0-9.]+,?$' | tr -d ' ,' |
      paste -sd' ' | awk '{for (i = 1; i < NF; i += 2) printf "%s,%s;", $i, $(i + 1)}')
[ -n "$want" ] && [ "$want" = "$got" ] && ok "unstable_ranges_deg = the runs of H < 0: $got" || bad "ranges: $got vs $want"
hmin=$(awk -F, 'NR > 1 && (NR == 2 || $6 < h) {h = $6; a = $1} END {print a}' "$csv")
grep -q "\"min_den_hartog_alpha_deg\": $hmin," "$js" && ok "lowest H at $hmin deg" || bad "lowest H at $hmin deg: $(grep min_den "$js")"
grep -q '"at_alpha_deg": '"$hmin" "$js" && ok "lowest onset where H is lowest" || bad "at_alpha_deg"
grep -q "onset at rest" "$tmp/out" && grep -q "unstable (H < 0)" "$tmp/out" && ok "table on stdout" || bad "stdout: $(cat "$tmp/out")"

# the attack angle: H at rest is the table's H at that angle
"$GALLOP" stability "$tmp/iced.ini" $tab --set ice.attack_angle=19 -o "$tmp/a" >/dev/null 2>&1
h19=$(awk -F, '$1 == 19 {print $6}' "$tmp/a/stability.csv")
hr=$(grep '"den_hartog_at_rest"' "$tmp/a/summary.json" | sed 's/.*: *//; s/,//')
awk -v a="$h19" -v b="$hr" 'BEGIN {e = a - b; if (e < 0) e = -e; exit !(e < 1e-8)}' && grep -q '"attack_angle_deg": 19,' "$tmp/a/summary.json" \
  && ok "attack angle 19 deg: den_hartog_at_rest = H(19 deg)" || bad "attack angle: $hr vs $h19"

# the coupled onset (issue 15): vg.csv over [stability] speeds, the onset where the onset mode's
# damping ratio changes sign, the structural ratio at zero wind, null when stable over the range
vg="$tmp/s/vg.csv"
[ -s "$vg" ] && ok "writes vg.csv" || bad "no vg.csv"
for k in onset_speed_m_s onset_mode share_vertical share_horizontal share_torsional onset_frequency_hz \
         divergence_speed_m_s fold_speed_m_s speed_max_m_s vg; do
  grep -q "\"$k\"" "$js" || missing2="${missing2:-} $k"
done
[ -z "${missing2:-}" ] && ok "summary.json has the keys of issue 15" || bad "summary.json lacks$missing2"
n=$(grep -v '^#' "$vg" | awk 'NR > 1' | wc -l)
[ "$n" -eq 79 ] && ok "79 speeds from 0.5 to 20 m/s by 0.25" || bad "vg.csv rows: $n"
uc=$(grep -m 1 '"onset_speed_m_s"' "$js" | sed 's/.*: *//; s/,//')
idx=$(grep -A 1 '"onset_mode"' "$js" | grep '"index"' | sed 's/.*: *//; s/,//')
if [ -n "$idx" ] && grep -v '^#' "$vg" | awk -F, -v u="$uc" -v k="$idx" '
     NR == 1 { for (i = 1; i <= NF; i++) if ($i == "zeta" k) c = i; next }
     $1 < u { below = $c } $1 > u && !done { above = $c; done = 1 }
     END { exit !(c && below > 0 && above < 0) }'; then
  ok "onset $uc m/s: the damping ratio of mode $idx changes sign there"
else
  bad "onset $uc m/s, mode $idx: no sign change in vg.csv"
fi
"$GALLOP" stability "$tmp/iced.ini" $tab --set conductor.damping_ratio=0.005 --set stability.speed_min=0 \
  --set stability.speed_max=2 --set stability.speed_step=1 -o "$tmp/v" >/dev/null 2>&1
grep -v '^#' "$tmp/v/vg.csv" | awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i ~ /^zeta[0-9]/) c[i] = 1; next }
  $1 == 0 { for (i in c) { e = ($i - 0.005) / 0.005; if (e < 0) e = -e; if (e > 1e-6) bad++; n++ } }
  END { exit !(n == 8 && bad == 0) }' \
  && ok "zero wind: every followed mode has the scene's damping ratio" || bad "zero wind ratios: $(grep -v '^#' "$tmp/v/vg.csv" | sed -n 2p)"
grep -q '"onset_speed_m_s": null' "$tmp/v/summary.json" && grep -q '"speed_max_m_s": 2' "$tmp/v/summary.json" \
  && ok "stable over 0 to 2 m/s: onset null, speed_max_m_s 2" || bad "stable range: $(grep -E 'onset_speed|speed_max' "$tmp/v/summary.json")"
"$GALLOP" stability "$tmp/iced.ini" $tab --set stability.speed_min=5 --set stability.speed_max=4 -o "$tmp/r" >/dev/null 2>"$tmp/err"
rc=$?
[ $rc -eq 2 ] && [ ! -e "$tmp/r" ] && ok "speed_max below speed_min: exit 2" || bad "speed range: exit $rc: $(cat "$tmp/err")"

# no structural damping: onset 0 wherever H < 0
"$GALLOP" stability "$tmp/iced.ini" $tab --set conductor.damping_ratio=0 -o "$tmp/z" >"$tmp/zout" 2>&1
awk -F, 'NR > 1 && $6 < 0 { if ($7 != 0) bad++ } END {exit bad > 0}' "$tmp/z/stability.csv" && grep -q "any wind gallops" "$tmp/zout" \
  && ok "zero damping: onset 0 where H < 0, and said so" || bad "zero damping: $(tail -n 3 "$tmp/zout")"

# a heavily iced, slack-strung span (Lark, 320 m, 22 kN, 0.7 kg/m of ice): under the wind its third
# torsional mode moves above the modes the coupled onset asked for at rest (it stopped with exit 1,
# "32 of the 33 basis modes ... among 81 modes", until session 12); it asks for more
cat > "$tmp/lark.ini" <<EOF
[span]
length = 320
horizontal_tension = 22000
[conductor]
name = Lark
damping_ratio = 0.003
[ice]
mass_per_length = 0.7
aero_table = $PWD/data/aero/iced_d_shape.csv
attack_angle = 30
[wind]
speed = 9
[model]
elements = 100
EOF
if "$GALLOP" stability "$tmp/lark.ini" --set stability.speed_step=1 -o "$tmp/lark" >"$tmp/lout" 2>"$tmp/err"; then
  on=$(jq -c '[.onset_basis_modes, .onset_speed_m_s]' "$tmp/lark/summary.json")
  jq -e '.onset_basis_modes == 33 and .onset_speed_m_s > 2 and .onset_speed_m_s < 5' "$tmp/lark/summary.json" >/dev/null \
    && ok "Lark 320 m: the coupled onset on its 33 modes (basis, m/s: $on)" || bad "Lark 320 m: basis, onset $on"
else
  bad "Lark 320 m: stability exit $?: $(cat "$tmp/err")"
fi

# a scene without an aero table: exit 2, nothing written
"$GALLOP" stability data/scenes/drake_300m.ini -o "$tmp/bare" >/dev/null 2>"$tmp/err"
rc=$?
[ $rc -eq 2 ] && grep -q "needs \[ice\] aero_table" "$tmp/err" && ok "no aero table: exit 2 with the reason" || bad "no aero table: exit $rc: $(cat "$tmp/err")"
[ -e "$tmp/bare" ] && bad "no aero table wrote output" || ok "no aero table writes nothing"
"$GALLOP" stability "$tmp/iced.ini" --set ice.aero_table=$tmp/none.csv -o "$tmp/bad" >/dev/null 2>"$tmp/err"
rc=$?
[ $rc -eq 2 ] && [ ! -e "$tmp/bad" ] && ok "missing table file: exit 2" || bad "missing table file: exit $rc: $(cat "$tmp/err")"
finish
