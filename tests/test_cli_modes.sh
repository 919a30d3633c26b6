#!/usr/bin/env bash
# test_cli_modes.sh: `gallop modes` end to end: the demo scene (exit 0, the four files, the keys
# of summary.json, the first out-of-plane frequency against string theory), bad input (exit 2,
# no output written) and a span with no equilibrium (exit 1 with the reason).
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
scratch cli_modes

if "$GALLOP" modes data/scenes/drake_300m.ini -o "$tmp/demo" >"$tmp/out" 2>"$tmp/err"; then
  ok "modes on the demo scene exits 0"
else
  bad "modes on the demo scene: exit $?: $(cat "$tmp/err")"
fi
for f in summary.json modes.csv shapes.csv equilibrium.csv; do
  [ -s "$tmp/demo/$f" ] && ok "writes $f" || bad "no $f"
done
ls "$tmp/demo" | grep -q tmp && bad "temporary files left behind" || ok "no temporary files left"
for k in sag_m horizontal_tension_n unstretched_length_m elements dofs newton_iterations wall_time_s \
         modes index family symmetry frequency_hz share_vertical share_horizontal share_torsional share_axial; do
  grep -q "\"$k\"" "$tmp/demo/summary.json" || { bad "summary.json lacks $k"; continue; }
done
ok "summary.json has the keys of the design"
# the first horizontal mode: n/(2L) sqrt(H/m) with Drake's mass from the conductor table
m=$(awk -F, '$1=="Drake"{print $3}' data/conductors.csv)
f=$(awk -F, '$2=="horizontal"{print $4; exit}' "$tmp/demo/modes.csv")
if awk -v f="$f" -v m="$m" 'BEGIN{g=sqrt(28000/m)/600; e=(f-g)/g; if(e<0)e=-e; exit !(e<0.005)}'; then
  ok "first horizontal frequency $f Hz within 0.5% of string theory"
else
  bad "first horizontal frequency $f Hz vs string theory with m = $m"
fi
# bad input: exit 2, message names the key, nothing written
"$GALLOP" modes data/scenes/drake_300m.ini --set span.length=-3 -o "$tmp/bad" >/dev/null 2>"$tmp/err"
rc=$?
[ $rc -eq 2 ] && grep -q "length" "$tmp/err" && ok "bad value: exit 2 naming the key" || bad "bad value: exit $rc: $(cat "$tmp/err")"
[ -e "$tmp/bad" ] && bad "bad input wrote output" || ok "bad input writes nothing"
# no equilibrium: a sag without gravity
"$GALLOP" modes data/scenes/drake_300m.ini --set effects.gravity=off --set span.sag=3 -o "$tmp/nogr" >/dev/null 2>"$tmp/err"
rc=$?
[ $rc -eq 2 ] && grep -q "gravity" "$tmp/err" && ok "sag without gravity: exit 2 with the reason" || bad "sag without gravity: exit $rc: $(cat "$tmp/err")"
# torsion off: no twist unknowns (dofs = 3 (elements - 1))
"$GALLOP" modes data/scenes/drake_300m.ini --set effects.torsion=off --set model.elements=40 -o "$tmp/nt" >/dev/null 2>"$tmp/err"
grep -q '"dofs": 117,' "$tmp/nt/summary.json" && ok "torsion off: 117 dofs for 40 elements" || bad "torsion off dofs: $(grep dofs "$tmp/nt/summary.json")"
finish
