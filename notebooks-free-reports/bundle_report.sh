#!/usr/bin/env bash
# bundle_report.sh GALLOP OUTDIR: the quad bundle beside its single sub-conductor under the same
# ice and wind (README "Bundles", issue 19): `gallop stability` and `gallop simulate --model full`
# of data/scenes/iced_gallop.ini (one iced Drake) and data/scenes/quad_bundle_gallop.ini (four of
# them on a 0.457 m square), the bundle both as the equivalent rod and as the explicit model, into
# OUTDIR/bundle/; then OUTDIR/bundle/report.md: a table of the measured onset speed, amplitudes,
# time to steady and support tension of each, the torsional stiffness each has (GJ against the
# tension's n H R^2 + n GJ), and fig/growth.png, the mid-span vertical motion of the three runs
# against time (gnuplot). BUNDLE_DURATION: simulated s of each run (the scenes' own: 500);
# BUNDLE_SET: "section.key=value ..." given to every run (a quick look: model.elements=24).
# Exit status: 0 written, 1 a run or the figure failed, 2 bad usage.
set -u
bin=${1:-}; out=${2:-}
here=$(cd "$(dirname "$0")" && pwd)
. "$here/lib.sh"   # jget
root=$(cd "$here/.." && pwd)
if [ ! -x "$bin" ] || [ -z "$out" ]; then
    echo "usage: bundle_report.sh GALLOP OUTDIR" >&2
    exit 2
fi
d=$out/bundle
fig=$d/fig
mkdir -p "$fig" "$d/logs"
single=$root/data/scenes/iced_gallop.ini
quad=$root/data/scenes/quad_bundle_gallop.ini
dur=()
[ -n "${BUNDLE_DURATION:-}" ] && dur=(--set "simulation.duration=$BUNDLE_DURATION")
for kv in ${BUNDLE_SET:-}; do dur+=(--set "$kv"); done
status=0
names=(single equivalent explicit)
scenes=("$single" "$quad" "$quad")
extra=("" "" "bundle.model=explicit")
for i in 0 1 2; do
    n=${names[$i]} s=${scenes[$i]} set=()
    [ -n "${extra[$i]}" ] && set=(--set "${extra[$i]}")
    echo "  bundle report: $n" >&2
    "$bin" stability "$s" "${set[@]}" "${dur[@]}" -o "$d/$n/stability" > "$d/logs/stability_$n.log" 2>&1 || status=1
    "$bin" simulate "$s" --model full "${set[@]}" "${dur[@]}" -o "$d/$n/full" > "$d/logs/full_$n.log" 2>&1 || status=1
done

# the resolved scene's value of section.key (gallop check)
cget() {
    "$bin" check "$1" ${3:+--set "$3"} 2>/dev/null | awk -v want="$2" '
        /^\[/ { sec = substr($0, 2, index($0, "]") - 2); next }
        { k = $1 } sec "." k == want { print $3; exit }'
}
fmt() { [ -n "$1" ] && awk -v x="$1" -v f="$2" 'BEGIN { printf f, x }' || printf 'n/a'; }

row() { # name label
    local n=$1 st=$d/$1/stability/summary.json sm=$d/$1/full/summary.json onset v h t ts tm
    onset=$(jget "$st" onset_speed_m_s)
    if [ "$n" != explicit ]; then   # one rod (the equivalent bundle too): its probes
        v=$(jget "$sm" probes vertical peak_to_peak_m); h=$(jget "$sm" probes horizontal peak_to_peak_m)
        t=$(jget "$sm" probes twist peak_to_peak_deg); ts=$(jget "$sm" probes time_to_steady_s)
        tm=$(jget "$sm" tension_max_n)
    else
        v=$(jget "$sm" probes centroid vertical_peak_to_peak_m); h=$(jget "$sm" probes centroid horizontal_peak_to_peak_m)
        t=$(jget "$sm" probes centroid twist_peak_to_peak_deg); ts=$(jget "$sm" probes centroid time_to_steady_s)
        tm=$(jget "$sm" probes centroid tension_max_n)
    fi
    printf '| %s | %s m/s | %s m | %s m | %s deg | %s s | %s kN |\n' "$2" "$(fmt "$onset" %.2f)" "$(fmt "$v" %.2f)" \
        "$(fmt "$h" %.2f)" "$(fmt "$t" %.2f)" "$(fmt "$ts" %.0f)" "$(fmt "${tm:+$(awk -v x="$tm" 'BEGIN { print x / 1000 }')}" %.1f)"
    printf '%s,%s,%s,%s,%s,%s,%s\n' "$n" "$onset" "$v" "$h" "$t" "$ts" "$tm" >> "$d/measured.csv"
}

H=$(cget "$quad" span.horizontal_tension); GJ=$(cget "$quad" conductor.torsional_stiffness)
nb=$(cget "$quad" bundle.subconductors); sep=$(cget "$quad" bundle.separation)
stiff=$(awk -v H="$H" -v G="$GJ" -v n="$nb" -v s="$sep" 'BEGIN { R = s / (2 * sin(3.14159265358979 / n));
    printf "one sub-conductor GJ = %g N m^2; the bundle n H R^2 = %.0f N m^2 (R = %.4f m) beside n GJ = %g N m^2", G, n * H * R * R, R, n * G }')
printf 'run,onset_speed_m_s,vertical_pp_m,horizontal_pp_m,twist_pp_deg,time_to_steady_s,tension_max_n\n' > "$d/measured.csv"
{
    echo "# A quad bundle beside its single sub-conductor"
    echo
    echo "Made by \`notebooks-free-reports/bundle_report.sh\`: \`gallop stability\` and \`gallop simulate --model full\`"
    echo "of \`iced_gallop.ini\` and \`quad_bundle_gallop.ini\` (the same iced Drake, the same D-shaped ice and"
    echo "10 m/s wind; the quad as the equivalent rod and as the explicit model). Amplitudes at mid-span over"
    echo "the steady window (the bundle's centroid; twist: the bundle's rotation); tension: the largest support"
    echo "tension (the bundle's, summed over its sub-conductors). Torsional stiffness: $stiff."
    echo
    echo "| | coupled onset | vertical p-p | horizontal p-p | twist p-p | time to steady | support tension max |"
    echo "|---|---|---|---|---|---|---|"
    row single "single Drake (iced_gallop)"
    row equivalent "quad bundle, equivalent"
    row explicit "quad bundle, explicit"
    echo
    echo "The figures are in measured.csv; the runs' files in single/, equivalent/, explicit/."
} > "$d/report.md"
if ! command -v gnuplot > /dev/null; then
    echo "No gnuplot: no figure." >> "$d/report.md"
    exit $status
fi
# fig/growth.png: p0.5_vertical_m of each run against time
plots=()
for n in "${names[@]}"; do
    tr=$d/$n/full/trace.csv
    [ -s "$tr" ] || continue
    c=$(head -1 "$tr" | tr ',' '\n' | grep -n -x 'p0.5_vertical_m' | cut -d: -f1)
    [ -n "$c" ] && plots+=("'$tr' using 1:$c with lines title '$n'")
done
if [ ${#plots[@]} -gt 0 ]; then
    p=$(IFS=,; echo "${plots[*]}")
    gnuplot -e "set terminal pngcairo size 1000,560; set output '$fig/growth.png'; set datafile separator ',';
        set key autotitle columnhead; set xlabel 'time (s)'; set ylabel 'mid-span vertical displacement (m)';
        set key top left; plot $p" 2>> "$fig/gnuplot.log" &&
        echo "![mid-span vertical motion: single conductor, quad equivalent, quad explicit](fig/growth.png)" >> "$d/report.md" ||
        status=1
fi
exit $status
