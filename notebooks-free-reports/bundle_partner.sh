#!/usr/bin/env bash
# bundle_partner.sh GALLOP OUTDIR [GALLOP_BEFORE]: the explicit Drake twin with 40 spacers under the
# quad's ice and wind (tests/bundle/drake_twin.ini, its modes 2/2/1; README "Bundles", "Which modes
# are selected"), `gallop compare` (the explicit full model against its reduced model, 300 s) into
# OUTDIR/bundle_partner/after/ (and, given a second binary, e.g. a build of a commit before the
# torsional partners, into before/); report.md: the amplitude errors, checked against the stated
# tolerances (vertical 2%, rotation 15%; measured 0.42% and 9.2%, with the first torsional mode
# alone 18.7% and 71.5%), and fig/twin.png: the mid-span vertical displacement and bundle rotation,
# full against reduced (and before). About 1 min per binary on a free core: `make report-bundle-partner`.
# BUNDLE_SET: "section.key=value ..." given to every run; BUNDLE_PARTNER_REUSE=1: a run whose
# summary.json and log are there is not made again (the report and figure made again).
# Exit status: 0 within the tolerances, 1 a run failed or an error past its tolerance, 2 bad usage.
set -u
bin=${1:-}; out=${2:-}; before=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
if [ ! -x "$bin" ] || [ -z "$out" ] || { [ -n "$before" ] && [ ! -x "$before" ]; }; then
    echo "usage: bundle_partner.sh GALLOP OUTDIR [GALLOP_BEFORE]" >&2
    exit 2
fi
mkdir -p "$out/bundle_partner/fig" || exit 2
d=$(cd "$out/bundle_partner" && pwd)
case $bin in /*) ;; *) bin=$PWD/$bin ;; esac
case $before in /*|"") ;; *) before=$PWD/$before ;; esac
set_=()
for kv in bundle.model=explicit bundle.spacers=40 bundle.spacer_mass=6 bundle.spacer_inertia=0.4 \
    ice.mass_per_length=0.6 ice.aero_table=data/aero/iced_d_shape.csv ice.attack_angle=20 wind.speed=10 \
    wind.yaw=90 conductor.damping_ratio=0.003 simulation.wind_ramp=2 simulation.duration=300 \
    model.elements=120 model.on_invalid=warn ${BUNDLE_SET:-}; do set_+=(--set "$kv"); done
status=0
runs=(after); bins=("$bin")
[ -n "$before" ] && runs+=(before) bins+=("$before")
for i in "${!runs[@]}"; do
    [ -n "${BUNDLE_PARTNER_REUSE:-}" ] && [ -s "$d/${runs[$i]}/summary.json" ] && [ -s "$d/${runs[$i]}.log" ] && continue
    (cd "$root" && "${bins[$i]}" compare tests/bundle/drake_twin.ini "${set_[@]}" -o "$d/${runs[$i]}") \
        > "$d/${runs[$i]}.log" 2>&1 || status=1
done
# err RUN KEY: amplitude_errors.KEY of a run's summary.json
err() { awk -v k="\"$2\"" 'index($0, "\"amplitude_errors\"") { on = 1 } on && index($0, k) {
            v = $0; sub(/^[^:]*:[[:space:]]*/, "", v); sub(/,$/, "", v); print v; exit }' "$d/$1/summary.json" 2>/dev/null; }
{
    echo "# The twin's reduced model against its full model"
    echo
    echo "Made by \`notebooks-free-reports/bundle_partner.sh\`: \`gallop compare\` of \`tests/bundle/drake_twin.ini\`"
    echo "(explicit, 40 spacers, the quad's ice and 10 m/s wind, modes 2/2/1, 300 s). after: this build (the"
    echo "torsional partner of each selected vertical mode selected); before: the binary given second."
    echo
    echo "| run | basis | vertical error | horizontal error | rotation error |"
    echo "|---|---|---|---|---|"
    for r in "${runs[@]}"; do
        b=$(sed -n 's/.*reduced basis \([0-9]*\).*/\1/p' "$d/$r.log")
        echo "| $r | $b | $(err "$r" vertical) | $(err "$r" horizontal) | $(err "$r" twist) |"
    done
    echo
} > "$d/report.md"
v=$(err after vertical); t=$(err after twist)
if awk -v v="$v" -v t="$t" 'BEGIN { exit !(v != "" && t != "" && v < 0.02 && t < 0.15) }'; then
    echo "after: vertical $v, rotation $t: within 0.02 and 0.15." >> "$d/report.md"
else
    echo "after: vertical '$v', rotation '$t': NOT within 0.02 and 0.15." >> "$d/report.md"
    status=1
fi
command -v gnuplot > /dev/null || { echo "No gnuplot: no figure." >> "$d/report.md"; exit $status; }
col() { head -1 "$1" | tr ',' '\n' | grep -n -x "$2" | cut -d: -f1; }
plots_v=() plots_r=()
for r in "${runs[@]}"; do
    c=$d/$r/compare.csv
    [ -s "$c" ] || continue
    fv=$(col "$c" full_vertical_m) rv=$(col "$c" reduced_vertical_m)
    ft=$(col "$c" full_twist_deg) rt=$(col "$c" reduced_twist_deg)
    [ "$r" = after ] && plots_v+=("'$c' using 1:$fv with lines lw 2 title 'full'") &&
        plots_r+=("'$c' using 1:$ft with lines lw 2 title 'full'")
    plots_v+=("'$c' using 1:$rv with lines title 'reduced, $r'")
    plots_r+=("'$c' using 1:$rt with lines title 'reduced, $r'")
done
pv=$(IFS=,; echo "${plots_v[*]}"); pr=$(IFS=,; echo "${plots_r[*]}")
gnuplot -e "set terminal pngcairo size 1100,800; set output '$d/fig/twin.png'; set datafile separator ',';
    set multiplot layout 2,1; set xrange [200:300]; set key top left; set grid;
    set ylabel 'mid-span vertical (m)'; plot $pv;
    set xlabel 'time (s)'; set ylabel 'bundle rotation (deg)'; plot $pr; unset multiplot" 2>> "$d/fig/gnuplot.log" &&
    echo "![the twin: full against reduced, vertical and rotation at mid-span](fig/twin.png)" >> "$d/report.md" ||
    status=1
exit $status
