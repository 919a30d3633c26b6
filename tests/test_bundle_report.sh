#!/usr/bin/env bash
# test_bundle_report.sh: notebooks-free-reports/bundle_report.sh (the quad bundle beside its single
# sub-conductor, `make report`) on short runs: it exits 0, report.md holds the three rows with a
# measured onset speed and amplitude each, measured.csv the same figures as the runs' summary.json,
# and the figure is drawn when gnuplot is there.
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
scratch bundle_report
BUNDLE_DURATION=30 BUNDLE_SET="model.elements=24 stability.speed_min=2 stability.speed_max=5 stability.speed_step=0.25" \
    bash "$here/../notebooks-free-reports/bundle_report.sh" "$GALLOP" "$tmp" > "$tmp/log" 2>&1
rc=$?
[ $rc -eq 0 ] && ok "bundle_report.sh exits 0" || bad "bundle_report.sh: exit $rc: $(tail -5 "$tmp/log")"
r=$tmp/bundle/report.md
for label in "single Drake" "quad bundle, equivalent" "quad bundle, explicit"; do
    grep -E "^\| $label[^|]*\| [0-9.]+ m/s \| [0-9.]+ m \|" "$r" > /dev/null 2>&1 && ok "row: $label" ||
        bad "row '$label': $(grep "$label" "$r" 2>/dev/null)"
done
grep -q 'n H R^2 = 16[0-9][0-9][0-9] N m^2' "$r" && ok "the bundle's torsional stiffness" || bad "stiffness: $(grep -o 'Torsional.*' "$r")"
# measured.csv against the explicit run's own summary.json
v=$(awk -F, '$1 == "explicit" { print $3 }' "$tmp/bundle/measured.csv" 2>/dev/null)
w=$(grep -m1 '"vertical_peak_to_peak_m"' "$tmp/bundle/explicit/full/summary.json" 2>/dev/null | sed 's/.*: *//; s/,$//')
[ -n "$v" ] && [ "$v" = "$w" ] && ok "explicit vertical p-p $v m as summary.json" || bad "measured '$v' against '$w'"
if command -v gnuplot > /dev/null; then
    [ -s "$tmp/bundle/fig/growth.png" ] && ok "fig/growth.png" || bad "no fig/growth.png: $(cat "$tmp/bundle/fig/gnuplot.log" 2>/dev/null)"
fi
finish
