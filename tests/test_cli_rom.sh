#!/usr/bin/env bash
# test_cli_rom.sh: the recomputed reduced model (model.reduced = recomputed) through `gallop
# simulate` and `gallop compare` on the short span of tests/rom/: summary.json gets residual_max and
# valid; a run past model.residual_tolerance stops with exit 1 naming what grew and the key, or with
# model.on_invalid = warn finishes with valid: false and says so on stderr; compare writes the full
# model's results when the reduced model fails, and says so.
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
scratch cli_rom
scene=tests/rom/condor_150_taut_dshape.ini
rom=(--set model.reduced=recomputed --set simulation.duration=30)

if "$GALLOP" simulate "$scene" "${rom[@]}" -o "$tmp/a" >/dev/null 2>"$tmp/err" &&
   grep -q '"residual_max": ' "$tmp/a/summary.json" && grep -q '"valid": true' "$tmp/a/summary.json"; then
  ok "simulate: residual_max and valid: true in summary.json"
else
  bad "simulate: $(cat "$tmp/err")"
fi
"$GALLOP" simulate "$scene" "${rom[@]}" --set model.residual_tolerance=1e-6 -o "$tmp/b" >/dev/null 2>"$tmp/err"
rc=$?
if [ $rc -eq 1 ] && grep -q 'residual grew to' "$tmp/err" && grep -q 'model.residual_tolerance' "$tmp/err" &&
   grep -q 'model.modes_' "$tmp/err"; then
  ok "past the tolerance: exit 1 naming what grew and the keys"
else
  bad "past the tolerance: exit $rc: $(cat "$tmp/err")"
fi
"$GALLOP" simulate "$scene" "${rom[@]}" --set model.residual_tolerance=1e-6 --set model.on_invalid=warn \
  -o "$tmp/c" >/dev/null 2>"$tmp/err"
rc=$?
if [ $rc -eq 0 ] && grep -q '"valid": false' "$tmp/c/summary.json" && grep -q 'valid: false' "$tmp/err"; then
  ok "on_invalid = warn: exit 0, valid: false, said on stderr"
else
  bad "on_invalid = warn: exit $rc: $(cat "$tmp/err")"
fi
# the adaptation tried first: the growths logged in summary.json, the basis larger than at the start
b0=$(grep -o '"basis_start": [0-9]*' "$tmp/c/summary.json" | grep -o '[0-9]*$')
b1=$(grep -o '"basis": [0-9]*' "$tmp/c/summary.json" | grep -o '[0-9]*$')
if [ -n "$b0" ] && [ -n "$b1" ] && [ "$b1" -gt "$b0" ] && grep -q '"basis_after": ' "$tmp/c/summary.json" &&
   grep -q '"corrections_added": 1' "$tmp/c/summary.json"; then
  ok "the basis grew before the run was marked invalid ($b0 -> $b1), logged in summary.json"
else
  bad "no growth logged in summary.json (basis $b0 -> $b1)"
fi
"$GALLOP" compare "$scene" "${rom[@]}" --set model.residual_tolerance=1e-6 -o "$tmp/d" >/dev/null 2>"$tmp/err"
rc=$?
if [ $rc -eq 1 ] && [ -s "$tmp/d/trace.csv" ] && grep -q '"model": "full"' "$tmp/d/summary.json" &&
   grep -q 'full model.s results are written' "$tmp/err"; then
  ok "compare: the reduced model fails, the full model's results are written and said"
else
  bad "compare with a failing reduced model: exit $rc: $(cat "$tmp/err")"
fi
"$GALLOP" compare "$scene" "${rom[@]}" -o "$tmp/e" >/dev/null 2>"$tmp/err"
rc=$?
if [ $rc -eq 0 ] && grep -q '"residual_max": ' "$tmp/e/summary.json"; then
  ok "compare: the reduced object has residual_max"
else
  bad "compare: exit $rc: $(cat "$tmp/err")"
fi
"$GALLOP" check "$scene" --set model.reduced=recomputed --set model.on_invalid=sometimes >/dev/null 2>"$tmp/err"
rc=$?
if [ $rc -eq 2 ] && grep -q 'stop | warn' "$tmp/err"; then ok "model.on_invalid: unknown value refused"; else bad "on_invalid: exit $rc"; fi

finish
