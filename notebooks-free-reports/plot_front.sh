#!/usr/bin/env bash
# plot_front.sh DIR [REPORT.md]: the Pareto front of `gallop accuracy` (DIR/front.csv, DIR/summary.json):
# DIR/front.png, log-log, the worst relative error of every configuration against its wall time,
# the front joined, the configuration chosen for the tolerance circled; and a section appended to
# REPORT.md (the front's table, the reference and its estimated error, the check of the chosen
# configuration, the effects). Needs awk; gnuplot for the figure (without it: the table only).
set -u
dir=${1:?usage: plot_front.sh DIR [REPORT.md]}
md=${2:-$dir/front.md}
csv=$dir/front.csv
[ -s "$csv" ] || { echo "plot_front.sh: no $csv" >&2; exit 1; }
# label,group,model,elements,modes,time_step_s,effect_off,err x6,error,wall_time_s,on_front,chosen,
# newton_tolerance,newton_iterations; kind: 0 configuration, 1 one effect off, 2 a Newton tolerance
awk -F, 'NR > 1 && $14 > 0 && $14 != "inf" && $14 != "nan" {
         print $15, $14, ($7 != "" ? 1 : $2 == "newton_tolerance" ? 2 : 0), $16, $17, $1 }' "$csv" \
    > "$dir/front_points.dat"
sort -g -k1,1 "$dir/front_points.dat" | awk '$4 == 1' > "$dir/front_line.dat"
awk '$5 == 1' "$dir/front_points.dat" > "$dir/front_chosen.dat"
zero=$(awk -F, 'NR > 1 && $14 == 0' "$csv" | wc -l)
fig=""
if command -v gnuplot >/dev/null 2>&1; then
    term=png; gnuplot -e 'set terminal pngcairo' >/dev/null 2>&1 && term=pngcairo
    if gnuplot <<GP 2>"$dir/front_gnuplot.log"; then fig=front.png; fi
set terminal $term size 900,600
set output "$dir/front.png"
set logscale xy
set xlabel "wall time (s)"
set ylabel "worst relative error (frequency, amplitudes, tension, time to steady)"
set title "What accuracy costs in time: error against a converged reference"
set key top right
set grid
plot "$dir/front_points.dat" using 1:(\$3 == 0 ? \$2 : 1/0) with points pt 7 ps 1 title "configurations", \
     "$dir/front_points.dat" using 1:(\$3 == 1 ? \$2 : 1/0) with points pt 6 ps 1 title "one effect off", \
     "$dir/front_points.dat" using 1:(\$3 == 2 ? \$2 : 1/0) with points pt 9 ps 1.3 title "Newton tolerance (one model, one value)", \
     "$dir/front_line.dat" using 1:2 with linespoints lw 2 pt 5 title "Pareto front", \
     "$dir/front_chosen.dat" using 1:2 with points pt 6 ps 3 lw 2 title "chosen for the tolerance"
GP
fi
{
    echo
    echo "## What accuracy costs in time: the Pareto front"
    echo
    [ -n "$fig" ] && echo "![error against wall time]($(basename "$dir")/front.png)" && echo
    [ "$zero" -gt 0 ] && echo "($zero configurations with zero error are not on the log axes.)" && echo
    echo "| configuration | worst error % | wall time s |"
    echo "|---|---|---|"
    awk -F, 'NR > 1 && $16 == 1 { printf "| %s%s | %.3g | %.3g |\n", $1, ($17 == 1 ? " (chosen)" : ""), 100 * $14, $15 }' "$csv"
    if command -v jq >/dev/null 2>&1 && [ -s "$dir/summary.json" ]; then
        echo
        jq -r '.front | "Reference: \(.reference.levels) levels to \(.reference.elements) elements and a step of \(.reference.time_step_s) s, converged: \(.reference.converged == 1); its worst estimated error \(.reference.worst_estimated_error)." ,
            (if .check != null then "Tolerance \(.tolerance): \(.chosen.label), checked by a second run: error \(.check.error), \(.check.wall_time_s) s." else "Tolerance \(.tolerance): no configuration meets it." end),
            "Effects: \(.effects)"' "$dir/summary.json"
    fi
} >> "$md"
exit 0
