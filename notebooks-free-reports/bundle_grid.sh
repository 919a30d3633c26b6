#!/usr/bin/env bash
# bundle_grid.sh GALLOP OUTDIR: the equivalent bundle against the explicit one over a grid (README
# "Bundles", "When the equivalent model is good enough"; issue 19): data/scenes/quad_bundle_gallop.ini
# strung as a twin, a triple and a quad (BUNDLE_GRID_N) with 4, 8, 16 and 40 spacers
# (BUNDLE_GRID_SPACERS), each model's `gallop stability` (the coupled onset speed) and
# `gallop simulate --model full` (the mid-span amplitudes over the steady window), into
# OUTDIR/bundle_grid/; then OUTDIR/bundle_grid/grid.csv (one row a case, both models),
# report.md (the table, with the first sub-span's taut-string frequency over the galloping one,
# f_ss / f_g, f_ss = sqrt(H / m) / (2 L / (spacers + 1)), H and m one sub-conductor's, and the
# detuning d_t = |f_t / f_v - 1| of the torsional partner f_t of the vertical mode f_v nearest the
# galloping, from the equivalent model's `gallop modes`: gal_bundle_equivalent_outside's criterion)
# and fig/grid.png, fig/detuning.png (each measure's equivalent/explicit - 1 against f_ss / f_g and
# against d_t; gnuplot).
# BUNDLE_GRID_TOTALS="KG KGM2": the spacers' total mass and inertia held (each spacer 1/spacers of
# them), so that the spacing alone varies (default: each spacer the scene's, the totals growing).
# BUNDLE_GRID_REUSE=1: a case whose two summary.json files are there is not run again (a grid
# resumed, or its report made again).
# BUNDLE_DURATION: simulated s of each run (the scene's 500); BUNDLE_SET: "section.key=value ..."
# given to every run (a quick look: "model.elements=24 simulation.duration=60").
# Long (48 runs, about 15 min on one free core): `make report-bundle-grid`, not `make check`.
# Exit status: 0 written, 1 a run or the figure failed, 2 bad usage.
set -u
bin=${1:-}; out=${2:-}
here=$(cd "$(dirname "$0")" && pwd)
. "$here/lib.sh"   # jget
root=$(cd "$here/.." && pwd)
if [ ! -x "$bin" ] || [ -z "$out" ]; then
    echo "usage: bundle_grid.sh GALLOP OUTDIR" >&2
    exit 2
fi
case $bin in /*) ;; *) bin=$PWD/$bin ;; esac
d=$out/bundle_grid
mkdir -p "$d/fig" "$d/logs"
scene=$root/data/scenes/quad_bundle_gallop.ini
ns_list=${BUNDLE_GRID_N:-2 3 4}
sp_list=${BUNDLE_GRID_SPACERS:-4 8 16 40}
common=()
[ -n "${BUNDLE_DURATION:-}" ] && common=(--set "simulation.duration=$BUNDLE_DURATION")
for kv in ${BUNDLE_SET:-}; do common+=(--set "$kv"); done
status=0

# the resolved scene's value of section.key (gallop check)
cget() {
    "$bin" check "$scene" "${common[@]}" 2>/dev/null | awk -v want="$1" '
        /^\[/ { sec = substr($0, 2, index($0, "]") - 2); next }
        { k = $1 } sec "." k == want { print $3; exit }'
}
H=$(cget span.horizontal_tension); L=$(cget span.length)
m=$(awk -v a="$(cget conductor.mass_per_length)" -v b="$(cget ice.mass_per_length)" 'BEGIN { print a + b }')

echo "n,spacers,f_subspan_hz,model,onset_m_s,vertical_pp_m,horizontal_pp_m,twist_pp_deg,frequency_hz" > "$d/runs.csv"
for n in $ns_list; do
    for s in $sp_list; do
        for model in explicit equivalent; do
            c=n${n}_s${s}_$model
            set=(--set "bundle.subconductors=$n" --set "bundle.spacers=$s" --set "bundle.model=$model" "${common[@]}")
            if [ -n "${BUNDLE_GRID_TOTALS:-}" ]; then
                read -r tm ti <<< "$BUNDLE_GRID_TOTALS"
                set+=(--set "bundle.spacer_mass=$(awk -v t="$tm" -v s="$s" 'BEGIN { printf "%.9g", t / s }')"
                      --set "bundle.spacer_inertia=$(awk -v t="$ti" -v s="$s" 'BEGIN { printf "%.9g", t / s }')")
            fi
            st=$d/$c/stability/summary.json sm=$d/$c/full/summary.json
            if [ -z "${BUNDLE_GRID_REUSE:-}" ] || [ ! -s "$st" ] || [ ! -s "$sm" ]; then
                echo "  bundle grid: $c" >&2
                "$bin" stability "$scene" "${set[@]}" -o "$d/$c/stability" > "$d/logs/stability_$c.log" 2>&1 || status=1
                "$bin" simulate "$scene" --model full "${set[@]}" -o "$d/$c/full" > "$d/logs/full_$c.log" 2>&1 || status=1
            fi
            if [ $model = explicit ]; then
                v=$(jget "$sm" probes centroid vertical_peak_to_peak_m); h=$(jget "$sm" probes centroid horizontal_peak_to_peak_m)
                t=$(jget "$sm" probes centroid twist_peak_to_peak_deg); f=$(jget "$sm" probes centroid vertical_frequency_hz)
            else
                v=$(jget "$sm" probes vertical peak_to_peak_m); h=$(jget "$sm" probes horizontal peak_to_peak_m)
                t=$(jget "$sm" probes twist peak_to_peak_deg); f=$(jget "$sm" frequency_hz)
            fi
            if [ $model = equivalent ]; then
                "$bin" modes "$scene" "${set[@]}" -o "$d/$c/modes" > "$d/logs/modes_$c.log" 2>&1 || status=1
            fi
            fss=$(awk -v H="$H" -v m="$m" -v L="$L" -v s="$s" 'BEGIN { printf "%.6g", sqrt(H / m) / (2 * L / (s + 1)) }')
            echo "$n,$s,$fss,$model,$(jget "$st" onset_speed_m_s),$v,$h,$t,$f" >> "$d/runs.csv"
        done
    done
done

# detuning CASE FG: |f_t / f_v - 1|, f_v the selected vertical mode of the equivalent model nearest FG,
# f_t the torsional mode of its symmetry nearest it
detuning() {
    awk -F, -v fg="$2" 'NR == 1 { next } { f[NR] = $4; fam[NR] = $2; sym[NR] = $3; sel[NR] = $10; n = NR }
        END { v = 0; for (i = 2; i <= n; i++) if (fam[i] == "vertical" && sel[i] == 1 && (!v || (f[i] - fg) ^ 2 < (f[v] - fg) ^ 2)) v = i
              t = 0; for (i = 2; i <= n; i++) if (v && fam[i] == "torsional" && sym[i] == sym[v] && (!t || (f[i] - f[v]) ^ 2 < (f[t] - f[v]) ^ 2)) t = i
              if (t) { x = f[t] / f[v] - 1; printf "%.4f", x < 0 ? -x : x } }' "$d/$1/modes/modes.csv" 2>/dev/null
}

# grid.csv: one row a case, the explicit and the equivalent side by side, f_ss / f_g (f_g the
# explicit model's galloping frequency) and each measure's equivalent / explicit - 1
awk -F, 'NR == 1 { next }
    { k = $1 "," $2; if ($4 == "explicit") { X[k] = $0; order[++no] = k } else E[k] = $0 }
    function rel(a, b) { return (a != "" && b != "" && b + 0 != 0) ? sprintf("%.4f", a / b - 1) : "" }
    END {
        print "n,spacers,f_subspan_hz,f_gallop_hz,fss_over_fg,onset_x,onset_e,vertical_x,vertical_e,horizontal_x," \
              "horizontal_e,twist_x,twist_e,d_onset,d_vertical,d_horizontal,d_twist"
        for (i = 1; i <= no; i++) {
            k = order[i]; split(X[k], x, ","); split(E[k], e, ",")
            r = (x[9] + 0 > 0) ? sprintf("%.3f", x[3] / x[9]) : ""
            print k "," x[3] "," x[9] "," r "," x[5] "," e[5] "," x[6] "," e[6] "," x[7] "," e[7] "," x[8] "," e[8] "," \
                  rel(e[5], x[5]) "," rel(e[6], x[6]) "," rel(e[7], x[7]) "," rel(e[8], x[8])
        }
    }' "$d/runs.csv" > "$d/grid.tmp"
{
    head -1 "$d/grid.tmp" | sed 's/$/,partner_detuning/'
    tail -n +2 "$d/grid.tmp" | while IFS=, read -r n s rest; do
        fg=$(echo "$rest" | cut -d, -f2)
        echo "$n,$s,$rest,$(detuning "n${n}_s${s}_equivalent" "$fg")"
    done
} > "$d/grid.csv"
rm -f "$d/grid.tmp"

pct() { [ -n "$1" ] && awk -v x="$1" 'BEGIN { printf "%+.1f%%", 100 * x }' || printf 'n/a'; }
f2() { [ -n "$1" ] && awk -v x="$1" 'BEGIN { printf "%.3g", x }' || printf 'n/a'; }
{
    echo "# The equivalent bundle against the explicit one"
    echo
    echo "Made by \`notebooks-free-reports/bundle_grid.sh\`: \`quad_bundle_gallop.ini\` (200 m, $H N and $m kg/m per"
    echo "sub-conductor, D-shaped ice, 10 m/s) with \`bundle.subconductors\` and \`bundle.spacers\` set, each case in"
    echo "both models: \`gallop stability\` (coupled onset) and \`gallop simulate --model full\` (mid-span peak-to-peak"
    echo "over the steady window; twist: the bundle's rotation). f_ss: the first sub-span's taut-string frequency,"
    echo "f_g: the explicit model's galloping frequency; d_t: the detuning |f_t / f_v - 1| of the torsional partner"
    echo "f_t of the vertical mode f_v nearest f_g (the equivalent model's modes). Each pair: explicit / equivalent"
    echo "(difference)."
    echo
    echo "| n | spacers | f_ss / f_g | d_t | onset m/s | vertical p-p m | horizontal p-p m | rotation p-p deg |"
    echo "|---|---|---|---|---|---|---|---|"
    awk -F, 'NR > 1' "$d/grid.csv" | while IFS=, read -r n s fss fg r ox oe vx ve hx he tx te dox dv dh dt pd; do
        echo "| $n | $s | $(f2 "$r") | $(pct "$pd") | $(f2 "$ox") / $(f2 "$oe") ($(pct "$dox")) | $(f2 "$vx") / $(f2 "$ve") ($(pct "$dv")) |" \
             "$(f2 "$hx") / $(f2 "$he") ($(pct "$dh")) | $(f2 "$tx") / $(f2 "$te") ($(pct "$dt")) |"
    done
    echo
    echo "The runs' figures are in runs.csv, the pairs in grid.csv, the runs' files in n<N>_s<S>_<model>/."
} > "$d/report.md"
if ! command -v gnuplot > /dev/null; then
    echo "No gnuplot: no figure." >> "$d/report.md"
    exit $status
fi
gnuplot -e "set terminal pngcairo size 1100,620; set output '$d/fig/grid.png'; set datafile separator ',';
    set logscale x; set xlabel 'f_{ss} / f_g (first sub-span over galloping frequency)';
    set ylabel 'equivalent / explicit - 1 (%)'; set key outside right; set grid;
    plot for [n in '$ns_list'] '$d/grid.csv' using (\$1 == n + 0 ? \$5 : NaN):(100 * \$15) with linespoints title 'vertical, n = '.n,
         for [n in '$ns_list'] '$d/grid.csv' using (\$1 == n + 0 ? \$5 : NaN):(100 * \$14) with points pt 6 title 'onset, n = '.n,
         for [n in '$ns_list'] '$d/grid.csv' using (\$1 == n + 0 ? \$5 : NaN):(100 * \$17) with points pt 4 title 'rotation, n = '.n" \
    2>> "$d/fig/gnuplot.log" && echo "![equivalent against explicit over f_ss / f_g](fig/grid.png)" >> "$d/report.md" || status=1
gnuplot -e "set terminal pngcairo size 1100,620; set output '$d/fig/detuning.png'; set datafile separator ',';
    set xlabel 'd_t = |f_t / f_v - 1| (torsional partner of the galloping vertical mode)'; set format x '%.0f%%';
    set ylabel 'equivalent / explicit - 1 (%)'; set key outside right; set grid; set arrow from 5, graph 0 to 5, graph 1 nohead dt 2;
    plot for [n in '$ns_list'] '$d/grid.csv' using (\$1 == n + 0 ? 100 * \$18 : NaN):(100 * \$15) with points pt 7 title 'vertical, n = '.n,
         for [n in '$ns_list'] '$d/grid.csv' using (\$1 == n + 0 ? 100 * \$18 : NaN):(100 * \$14) with points pt 6 title 'onset, n = '.n,
         for [n in '$ns_list'] '$d/grid.csv' using (\$1 == n + 0 ? 100 * \$18 : NaN):(100 * \$17) with points pt 4 title 'rotation, n = '.n" \
    2>> "$d/fig/gnuplot.log" && echo "![equivalent against explicit over d_t](fig/detuning.png)" >> "$d/report.md" || status=1
exit $status
