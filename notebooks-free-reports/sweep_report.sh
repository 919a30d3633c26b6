#!/usr/bin/env bash
# sweep_report.sh GALLOP SCENE OUTDIR: a small sweep of SCENE (issue 18) and its figures:
# `gallop sweep` over wind.speed (with --continuation: up and down, the galloping branch and its
# hysteresis) and over wind.speed x conductor.damping_ratio (a map), into OUTDIR/sweep/, then
# OUTDIR/sweep/report.md with fig/amplitude.png (vertical peak-to-peak against the first key)
# and fig/map.png (the same over the two keys). Grids: SWEEP_SPEEDS (2:16:1), SWEEP_DAMPING
# (0.002,0.004,0.006,0.008), SWEEP_DURATION (simulated s per case, 200), SWEEP_MODEL (full).
# Exit status: 0 written, 1 a run or a figure failed, 2 bad usage.
set -u
bin=${1:-}; scene=${2:-}; out=${3:-}
if [ ! -x "$bin" ] || [ ! -r "$scene" ] || [ -z "$out" ]; then
    echo "usage: sweep_report.sh GALLOP SCENE OUTDIR" >&2
    exit 2
fi
d=$out/sweep
fig=$d/fig
mkdir -p "$fig"
speeds=${SWEEP_SPEEDS:-2:16:1}
damping=${SWEEP_DAMPING:-0.002,0.004,0.006,0.008}
common=(--model "${SWEEP_MODEL:-full}" --set "simulation.duration=${SWEEP_DURATION:-200}")
status=0
"$bin" sweep "$scene" --vary "wind.speed=$speeds" --continuation "${common[@]}" -o "$d/branch" \
    > "$d/branch.log" 2>&1 || status=1
"$bin" sweep "$scene" --vary "wind.speed=$speeds" --vary "conductor.damping_ratio=$damping" "${common[@]}" \
    -o "$d/map" > "$d/map.log" 2>&1 || status=1
{
    echo "# Sweep of $(basename "$scene" .ini)"
    echo
    echo "Made by \`notebooks-free-reports/sweep_report.sh\`: \`gallop sweep\` over wind.speed = $speeds"
    echo "(--continuation, up then down) and over wind.speed x conductor.damping_ratio = $damping."
    echo
} > "$d/report.md"
if ! command -v gnuplot > /dev/null; then
    echo "No gnuplot: no figures (the CSV files are in branch/ and map/)." >> "$d/report.md"
    exit $status
fi
# the branches: columns 1 key, 2 branch, 3 vertical_pp_m
if [ -s "$d/branch/sweep.csv" ]; then
    awk -F, 'NR > 1 && $2 == "up"' "$d/branch/sweep.csv" > "$fig/up.dat"
    awk -F, 'NR > 1 && $2 == "down"' "$d/branch/sweep.csv" > "$fig/down.dat"
    gnuplot -e "set terminal pngcairo size 900,560; set output '$fig/amplitude.png'; set datafile separator ',';
        set xlabel 'wind speed (m/s)'; set ylabel 'vertical peak-to-peak at the first probe (m)'; set key top left;
        plot '$fig/up.dat' using 1:3 with linespoints title 'up', '$fig/down.dat' using 1:3 with linespoints title 'down'" \
        2>> "$fig/gnuplot.log" && echo "![amplitude against wind speed](fig/amplitude.png)" >> "$d/report.md" || status=1
fi
# the map: columns 1 speed, 2 damping, 4 vertical_pp_m; a block per damping value
if [ -s "$d/map/sweep.csv" ]; then
    awk -F, 'NR > 1 { if (NR > 2 && $2 != last) print ""; last = $2; print $1, $2, $4 }' "$d/map/sweep.csv" > "$fig/map.dat"
    gnuplot -e "set terminal pngcairo size 900,560; set output '$fig/map.png'; set view map;
        set xlabel 'wind speed (m/s)'; set ylabel 'damping ratio'; set cblabel 'vertical peak-to-peak (m)';
        splot '$fig/map.dat' using 1:2:3 with pm3d notitle" \
        2>> "$fig/gnuplot.log" && echo "![amplitude over wind speed and damping](fig/map.png)" >> "$d/report.md" || status=1
fi
exit $status
