#!/usr/bin/env bash
# plot_onset.sh DIR [TITLE]: appends to DIR/report.md the classic criteria beside the coupled onset
# of `gallop stability` (DIR/stability/vg.csv, summary.json; issue 15): per mean wind speed, Den
# Hartog's onset under the applied damping and Nigol's torsional onset at the angle of attack of
# the mean-wind equilibrium, and the linear divergence speed about it, against the wind speed
# itself (a criterion calls the span unstable where its curve lies below the diagonal), with the
# coupled onset, the restabilization and the fold marked. Called by make_report.sh after
# plot_scene.sh; does nothing without vg.csv. Needs gnuplot (else a note), awk, jq (lib.sh).
set -u
here=$(cd "$(dirname "$0")" && pwd)
. "$here/lib.sh"
dir=$1
title=${2:-$(basename "$dir")}
g=$dir/stability
vg=$g/vg.csv
[ -s "$vg" ] && [ -s "$dir/report.md" ] || exit 0
fig=$dir/fig
dat=$fig/data
mkdir -p "$dat"
md=$dir/report.md
s=$g/summary.json
num() { if [ -n "$2" ]; then printf "$1 m/s" "$2"; else printf 'none'; fi; }
{
    echo "## Classic criteria about the mean-wind equilibrium"
    echo
    echo "Den Hartog (with the applied damping of the lowest vertical mode) and Nigol (Nigol & Buchan 1981, the lowest torsional mode, lever arm d/2) evaluated at the angle of attack the mean wind produces at mid-span, and the linear divergence speed about that equilibrium, beside the coupled analysis (README: *gallop stability*)."
    echo
    echo "| quantity | value |"
    echo "|---|---|"
    echo "| coupled onset | $(num %.4g "$(jfind "$s" onset_speed_m_s)") |"
    echo "| stable again above | $(num %.4g "$(jfind "$s" restable_speed_m_s)") |"
    echo "| torsional divergence | $(num %.4g "$(jfind "$s" divergence_speed_m_s)") |"
    echo "| fold of the mean-wind equilibrium | $(num %.4g "$(jfind "$s" fold_speed_m_s)") |"
    echo
} >> "$md"
c_u=$(csv_col "$vg" speed_m_s) c_dh=$(csv_col "$vg" den_hartog_onset_m_s)
c_ni=$(csv_col "$vg" nigol_onset_m_s) c_dv=$(csv_col "$vg" divergence_linear_m_s)
[ -n "$c_u" ] && [ -n "$c_dh" ] && [ -n "$c_ni" ] && [ -n "$c_dv" ] || exit 0
awk -F, -v a="$c_u" -v b="$c_dh" -v c="$c_ni" -v d="$c_dv" '/^#/ || !h++ { next }
    function v(x) { return (x == "" || x == "inf") ? "nan" : x }
    { print $a, v($b), v($c), v($d) }' "$vg" > "$dat/classic.dat"
if ! command -v gnuplot >/dev/null 2>&1; then
    printf '_Figure classic_criteria not made: gnuplot is not installed._\n\n' >> "$md"
    exit 0
fi
marks=""
for key in onset_speed_m_s restable_speed_m_s fold_speed_m_s; do
    u=$(jfind "$s" "$key")
    [ -n "$u" ] && marks="$marks
set arrow from $u, graph 0 to $u, graph 1 nohead dt 2 lw 2 lc rgb \"red\"
set label \"${key%%_*} $(printf %.3g "$u")\" at $u, graph 0.95 left offset 0.5,0 tc rgb \"red\""
done
esc_title=$(printf '%s' "$title" | sed 's/[_^@&~{}]/\\\\&/g')
png=$fig/classic_criteria.png
rm -f "$png"
{
    printf 'set terminal pngcairo enhanced size 1000,600 font "Sans,10"\nset output "%s"\n' "$png"
    printf 'set grid lc rgb "#d0d0d0"\nset key top left box opaque\nset datafile missing "nan"\nset logscale y\n'
    printf 'set title "Classic criteria about the mean-wind equilibrium, %s"\n' "$esc_title"
    printf 'set xlabel "mean wind speed (m/s)"\nset ylabel "criterion speed (m/s)"\n%s\n' "$marks"
    printf 'plot "%s" using 1:2 with linespoints pt 7 ps 0.5 lw 2 title "Den Hartog onset", ' "$dat/classic.dat"
    printf '"" using 1:3 with linespoints pt 7 ps 0.5 lw 2 title "Nigol onset", '
    printf '"" using 1:4 with linespoints pt 7 ps 0.5 lw 2 title "linear divergence", '
    printf 'x with lines lw 1 lc rgb "black" title "criterion = wind speed"\n'
} | gnuplot >> "$fig/gnuplot.log" 2>&1
if [ -s "$png" ]; then
    cap="Classic criteria at the mean-wind equilibrium against the wind speed (below the diagonal: the criterion calls the span unstable there)"
    printf '![%s](fig/classic_criteria.png)\n\n*%s*\n\n' "$cap" "$cap" >> "$md"
else
    printf '_Figure classic_criteria failed (see fig/gnuplot.log)._\n\n' >> "$md"
    exit 1
fi
