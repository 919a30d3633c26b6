#!/usr/bin/env bash
# test_cli_rom_cubic.sh: the soft-torsion span of tests/rom/ (grosbeak_300_soft_gj, its own 100
# elements), whose basis lacks the modes' third-order coupling: the reduced run held an orbit 46% off
# in twist with the instantaneous residual at 0.098, under the tolerance, then was refused by the
# check's cubic indicator (rom_adapt.h). Now the check tripped by the cubic part grows the basis by
# the third-order modal derivatives of the selected modes (on the initial basis) and runs it again
# from the start (236.65 s here), and the run's record before the growth is the grown model's run
# from the start, not the refused model's (within issue 13's figures on 300-400 s at 100 and 125
# elements: BENCHMARKS.md, helper soft; a full-model comparison takes ~25 s, not run here).
#  - 240 s: exit 0, valid, one growth adding the 56 third-order derivatives, said on stderr with its cost;
#  - the record up to 230 s differs from the same run stopped at 230 s (before the growth: the model
#    that the check later refuses), so it was rewritten by the replay.
# The spans within the issue's figures never trip the cubic part (test_cli_rom.sh, test_rom_spans);
# the mechanism to the bit: test_rom_third.
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
scratch cli_rom_cubic
scene=tests/rom/grosbeak_300_soft_gj.ini

"$GALLOP" simulate "$scene" --model reduced --set simulation.duration=240 -o "$tmp/a" >/dev/null 2>"$tmp/err"
rc=$?
if [ $rc -eq 0 ] && grep -q '"valid": true' "$tmp/a/summary.json" && grep -q '"corrections_added": 56' "$tmp/a/summary.json"; then
  ok "grosbeak at 100 elements, 240 s: valid, grown by the 56 third-order modal derivatives"
else
  bad "grosbeak at 100 elements, 240 s: exit $rc: $(cat "$tmp/err"; grep -o '"valid": [a-z]*' "$tmp/a/summary.json" 2>/dev/null)"
fi
# the growth said on stderr: from 27 to 79 vectors, and what a basis that large costs
grep -q "note: the reduced basis grew from 27 to 79 vectors in [0-9]* growths" "$tmp/err" && grep -q "costs several times" "$tmp/err" \
  && ok "the growth to 79 vectors said on stderr, with its cost" || bad "no growth note: $(cat "$tmp/err")"
"$GALLOP" simulate "$scene" --model reduced --set simulation.duration=230 -o "$tmp/b" >/dev/null 2>"$tmp/err"
rc=$?
# before the third-order set: grown, but not to twice the start (no cost line)
grep -q "note: the reduced basis grew from 27 to" "$tmp/err" && ! grep -q "costs several times" "$tmp/err" \
  && ok "230 s: the growths said, no cost line under twice the start" || bad "230 s: $(cat "$tmp/err")"
# largest |difference| of the mid-span vertical and twist over the rows of t <= 230 s
diff=$(awk -F, 'NR == FNR { if (FNR > 1) { v[$1] = $3; w[$1] = $5 }; next }
  FNR > 1 && ($1 in v) && $1 + 0 <= 230 { d = $3 - v[$1]; if (d < 0) d = -d; if (d > dv) dv = d;
    e = $5 - w[$1]; if (e < 0) e = -e; if (e > dw) dw = e; n++ }
  END { printf "%d %.6g %.6g", n, dv, dw }' "$tmp/b/trace.csv" "$tmp/a/trace.csv" 2>/dev/null)
read -r n dv dw <<<"$diff"
if [ $rc -eq 0 ] && [ "${n:-0}" -gt 4000 ] && awk -v a="${dv:-0}" -v b="${dw:-0}" 'BEGIN { exit !(a > 0.01 && b > 1) }'; then
  ok "the record before the growth is the grown model's ($n rows; vertical up to $dv m, twist up to $dw deg from the refused model's)"
else
  bad "the record before the growth: exit $rc, rows $n, vertical $dv m, twist $dw deg apart (the refused model's kept?)"
fi
finish
