#!/usr/bin/env bash
# test_cli_accuracy_newton.sh: simulation.newton_tolerance, the Newton tolerance of both models'
# implicit step (the integrator tolerance the accuracy study sweeps): its range (exit 2 naming
# FILE:LINE, the key and the allowed range); the default and the same value written out give the
# same outputs bit for bit; a looser value does less Newton work in both models (counters of
# summary.json) and changes the trace. A tighter one: the full model does at least as much Newton
# work; the reduced model's trace moves, and far less than under the looser value (Newton's
# converged state is off by about the tolerance). The reduced model runs without growths
# (model.residual_tolerance = 10: it checks itself, it does not grow): a growth is a discrete decision
# on a residual read at one instant, so the grown bases of two tolerances may differ, and since a
# growth's replay rewrites the record before it (rom_adapt.h) the whole traces would part by a
# finite amount (its iteration count over the whole run followed them: 1339 at 1e-8 against 1377 at
# 1e-12 on main, and any last-bit change of the basis reversed the order).
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
scratch cli_accnewton
# the taut string of tests/cli/taut_string.ini, 10 s
sed 's/^duration = 30$/duration = 10/' "$here/cli/taut_string.ini" >"$tmp/s.ini"
# ---- the range ----
for v in 0 1e-15 0.1 -1 abc; do
  cp "$tmp/s.ini" "$tmp/b.ini"
  echo "newton_tolerance = $v" >>"$tmp/b.ini"
  line=$(wc -l <"$tmp/b.ini")
  "$GALLOP" simulate "$tmp/b.ini" -o "$tmp/bad" >/dev/null 2>"$tmp/err"
  rc=$?
  if [ $rc -eq 2 ] && grep -q "$tmp/b.ini:$line: \[simulation\] newton_tolerance" "$tmp/err" &&
     { [ "$v" = abc ] || grep -q "1e-14 <= newton_tolerance <= 0.01" "$tmp/err"; }; then
    ok "newton_tolerance = $v: exit 2 naming file, line, key and range"
  else bad "newton_tolerance = $v: exit $rc: $(cat "$tmp/err")"; fi
done
[ -e "$tmp/bad" ] && bad "bad input wrote output" || ok "bad input writes nothing"
# ---- the default, and the same value written out: the same outputs ----
# the time of the reduced run's first basis growth (summary.json basis_growths), else 1e30
growth1() { awk -F': ' '/"basis_growths"/ { g = 1 } g && /"time_s"/ { gsub(/[, ]/, "", $2); print $2; f = 1; exit }
  END { if (!f) print 1e30 }' "$1/summary.json"; }
# the largest difference between two traces before time $3, each column over its largest magnitude
tdiff() { paste -d, "$1" "$2" | awk -F, -v tmax="$3" 'NR == 1 { n = NF / 2; next } $1 + 0 >= tmax + 0 { next }
  { for (j = 2; j <= n; j++) { d = $j - $(j + n); s = $j < 0 ? -$j : $j; if (d < 0) d = -d
      if (d > dm[j]) dm[j] = d; if (s > sc[j]) sc[j] = s } }
  END { r = 0; for (j = 2; j <= n; j++) if (sc[j] > 0 && dm[j] / sc[j] > r) r = dm[j] / sc[j]; printf "%.3e", r }'; }
counter() { awk -F': ' -v k="\"$2\"" '$1 ~ k { gsub(/[, ]/, "", $2); print $2; exit }' "$1/summary.json"; }
for model in full reduced; do
  for t in default 1e-8 1e-3 1e-12; do
    set=(); [ $t = default ] || set=(--set simulation.newton_tolerance=$t)
    [ $model = reduced ] && set+=(--set model.residual_tolerance=10)
    "$GALLOP" simulate "$tmp/s.ini" --model $model "${set[@]}" -o "$tmp/$model-$t" >/dev/null 2>"$tmp/err" \
      || bad "$model, tolerance $t: exit $?: $(cat "$tmp/err")"
  done
  cmp -s "$tmp/$model-default/trace.csv" "$tmp/$model-1e-8/trace.csv" \
    && ok "$model: newton_tolerance = 1e-8 (the default) gives the default's trace bit for bit" \
    || bad "$model: 1e-8 and the default differ"
  nd=$(counter "$tmp/$model-default" newton_iterations); nl=$(counter "$tmp/$model-1e-3" newton_iterations)
  nt=$(counter "$tmp/$model-1e-12" newton_iterations)
  [ -n "$nl" ] && [ -n "$nd" ] && [ "$nl" -lt "$nd" ] \
    && ok "$model: Newton iterations $nl at 1e-3 < $nd at 1e-8" || bad "$model: Newton iterations '$nl' at 1e-3, '$nd' at 1e-8"
  if [ $model = full ]; then
    [ -n "$nt" ] && [ -n "$nd" ] && [ "$nt" -ge "$nd" ] \
      && ok "full: Newton iterations $nd at 1e-8 <= $nt at 1e-12" || bad "full: Newton iterations '$nd' at 1e-8, '$nt' at 1e-12"
  else
    tg=$(for t in default 1e-3 1e-12; do growth1 "$tmp/reduced-$t"; done | sort -g | head -n 1)
    awk -v t="$tg" 'BEGIN { exit !(t + 0 >= 1e30) }' && ok "reduced: no growth at residual_tolerance 10" || bad "reduced: a growth at $tg s"
    dt=$(tdiff "$tmp/reduced-default/trace.csv" "$tmp/reduced-1e-12/trace.csv" "$tg")
    dl=$(tdiff "$tmp/reduced-default/trace.csv" "$tmp/reduced-1e-3/trace.csv" "$tg")
    awk -v t="$dt" -v l="$dl" 'BEGIN { exit !(t > 0 && 20 * t < l) }' \
      && ok "reduced: 1e-12 moves the trace by $dt, 1e-3 by $dl (> 20x)" \
      || bad "reduced: 1e-12 moves the trace by '$dt', 1e-3 by '$dl' (want 0 < 20 x the first < the second)"
  fi
  cmp -s "$tmp/$model-default/trace.csv" "$tmp/$model-1e-3/trace.csv" \
    && bad "$model: 1e-3 gives the default's trace: the key is not read" || ok "$model: 1e-3 changes the trace"
done
finish
