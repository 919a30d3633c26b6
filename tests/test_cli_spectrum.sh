#!/usr/bin/env bash
# test_cli_spectrum.sh: `gallop spectrum` on small CSV traces: exit status 0 on a good trace with
# summary.json and psd.csv written and the known frequency found; exit status 2, a message on
# stderr and no output files on bad input. Ends with "#summary P F" (tests/run.sh).
set -u
GALLOP=${GALLOP:-build/gallop}
dir=$(mktemp -d /tmp/gallop_cli_spectrum_XXXXXX)
trap 'rm -rf "$dir"' EXIT
passed=0; failed=0
ok()   { echo "  ok   $1"; passed=$((passed + 1)); }
fail() { echo "  FAIL $1"; failed=$((failed + 1)); }

# A probe orbiting at 0.8 Hz (y amplitude 0.5, z amplitude 1.5, growing to steady) and a tension
# at 1.6 Hz: 6000 samples at 0.01 s.
awk 'BEGIN {
  print "# synthetic galloping trace"; print "time,mid_y,mid_z,tension";
  pi = 3.14159265358979; w = 2 * pi * 0.8;
  for (k = 0; k < 6000; k++) { t = k * 0.01; a = 1 / (1 + exp(-(t - 15) / 2));
    printf "%.2f,%.8f,%.8f,%.5f\n", t, a * 0.5 * cos(w * t), -3 + a * 1.5 * sin(w * t + 0.3),
           20000 + 300 * a * cos(2 * w * t) } }' > "$dir/good.csv"

# 1. good trace, default output directory next to the trace
out=$("$GALLOP" spectrum "$dir/good.csv" 2>"$dir/err"); rc=$?
if [ $rc -eq 0 ] && [ -s "$dir/spectrum/summary.json" ] && [ -s "$dir/spectrum/psd.csv" ]; then
  ok "good trace: exit 0, summary.json and psd.csv in TRACE_DIR/spectrum"
else
  fail "good trace: exit $rc, $(cat "$dir/err")"
fi
if head -n 1 "$dir/spectrum/psd.csv" 2>/dev/null | grep -qx 'frequency_hz,mid_y_psd,mid_z_psd,tension_psd'; then
  ok "psd.csv header"
else
  fail "psd.csv header: $(head -n 1 "$dir/spectrum/psd.csv" 2>/dev/null)"
fi
# the dominant frequency of mid_z is 0.8 Hz to 1e-4, the orbit is found from the *_y/*_z names
f=$(awk '/"mid_z"/ {on = 1} on && /"frequency_hz"/ {gsub(/[ ,]/, "", $2); print $2; exit}' \
    "$dir/spectrum/summary.json")
if awk -v f="$f" 'BEGIN { exit !(f != "" && f - 0.8 < 1e-4 && 0.8 - f < 1e-4) }'; then
  ok "mid_z frequency $f Hz"
else
  fail "mid_z frequency '$f', want 0.8"
fi
if grep -q '"major_semi_axis"' "$dir/spectrum/summary.json" && grep -q '"tilt_deg"' "$dir/spectrum/summary.json"; then
  ok "orbit of the mid_y/mid_z pair in summary.json"
else
  fail "no orbit in summary.json"
fi
if printf '%s\n' "$out" | grep -q '^mid_z'; then ok "table on stdout"; else fail "no table: $out"; fi

# 2. options: one column, explicit pair, --from, --segment, -o
"$GALLOP" spectrum "$dir/good.csv" --column tension --pair mid_y,mid_z --from 30 --segment 1024 \
  -o "$dir/out2" >/dev/null 2>"$dir/err"; rc=$?
if [ $rc -eq 0 ] && grep -q '"segment": 1024' "$dir/out2/summary.json" \
   && grep -q '"steady_from_s": 30' "$dir/out2/summary.json" \
   && head -n 1 "$dir/out2/psd.csv" | grep -qx 'frequency_hz,tension_psd'; then
  ok "options --column --pair --from --segment -o"
else
  fail "options: exit $rc, $(cat "$dir/err")"
fi

# 3. bad inputs: exit 2, a message on stderr, nothing written
bad() {  # name, expected message fragment, then the arguments after "spectrum"
  local name=$1 want=$2; shift 2
  rm -rf "$dir/outbad"
  "$GALLOP" spectrum "$@" -o "$dir/outbad" >/dev/null 2>"$dir/err"; local rc=$?
  if [ $rc -eq 2 ] && grep -q -- "$want" "$dir/err" && [ ! -e "$dir/outbad/summary.json" ]; then
    ok "$name: exit 2"
  else
    fail "$name: exit $rc, stderr: $(cat "$dir/err")"
  fi
}
bad "missing file" "cannot open" "$dir/nope.csv"
printf 'time,x\n' > "$dir/short.csv"
for k in 1 2 3 4 5; do printf '%d,%d\n' "$k" "$k" >> "$dir/short.csv"; done
bad "short trace" "at least 16" "$dir/short.csv"
sed '40s/.*/0.38,nan,1,2/' "$dir/good.csv" > "$dir/nan.csv"
bad "NaN in the trace" ":40:" "$dir/nan.csv"
sed '50s/,/;/g' "$dir/good.csv" > "$dir/fields.csv"
bad "wrong number of fields" ":50:" "$dir/fields.csv"
sed '100d' "$dir/good.csv" > "$dir/gap.csv"
bad "non-uniform sampling" "not uniform" "$dir/gap.csv"
tail -n +3 "$dir/good.csv" > "$dir/nohead.csv"
bad "no header" "no header" "$dir/nohead.csv"
bad "unknown column" "no column 'nope'" "$dir/good.csv" --column nope
bad "bad pair" "--pair" "$dir/good.csv" --pair mid_y
bad "bad --from" "outside the trace" "$dir/good.csv" --from 1000
bad "bad --segment" "--segment" "$dir/good.csv" --segment 3
bad "segment longer than the record" "longer than the steady part" "$dir/good.csv" --segment 100000
bad "unknown option" "unknown option" "$dir/good.csv" --frobnicate
bad "no trace" "no trace" --from 3

# 4. a constant column: exit 0, no frequency (null), no crash
awk 'BEGIN { print "t,c,s"; for (k = 0; k < 300; k++) printf "%g,1.5,%.8f\n", k * 0.1, sin(k * 0.7) }' \
  > "$dir/const.csv"
"$GALLOP" spectrum "$dir/const.csv" -o "$dir/outc" >/dev/null 2>"$dir/err"; rc=$?
if [ $rc -eq 0 ] && grep -A1 '"c": {' "$dir/outc/summary.json" | grep -q '"frequency_hz": null'; then
  ok "constant column: exit 0, frequency null"
else
  fail "constant column: exit $rc, $(cat "$dir/err")"
fi

echo "#summary $passed $failed"
[ "$failed" -eq 0 ]
