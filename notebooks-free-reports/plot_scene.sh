#!/usr/bin/env bash
# plot_scene.sh OUTDIR [TITLE]: turns the output directory of one scene (modes/, full/, reduced/,
# compare/, accuracy/, torsion/ as written by gallop and make_report.sh) into OUTDIR/report.md
# with PNG figures in OUTDIR/fig/. It only reads files: every figure and table is made when its
# input exists and left out (with a line saying so) when it does not. gnuplot makes the figures
# (pngcairo if it has it, else png); without gnuplot the report has the tables only.
# Exit status: 0 report written, 1 a figure failed (report still written), 2 bad usage.
set -u
here=$(cd "$(dirname "$0")" && pwd)
. "$here/lib.sh"

dir=${1:-}
if [ -z "$dir" ] || [ ! -d "$dir" ]; then
    echo "usage: plot_scene.sh OUTDIR [TITLE]  (OUTDIR: a scene's report directory)" >&2
    exit 2
fi
title=${2:-$(basename "$dir")}
fig=$dir/fig
dat=$fig/data
mkdir -p "$dat"
md=$dir/report.md.part
: > "$md"
: > "$fig/gnuplot.log"
failed=0
psd_fmax=${REPORT_PSD_FMAX:-5}   # Hz, upper end of the PSD plots

# ---- gnuplot terminal ----
gp=
if command -v gnuplot >/dev/null 2>&1; then
    gp=gnuplot
    if [ "${REPORT_TERMINAL:-}" != png ] && gnuplot -e 'set terminal' 2>&1 | grep -qw pngcairo; then
        term="pngcairo enhanced size 1000,640 font 'Sans,10' linewidth 1.2"
    else
        term="png enhanced size 1000,640"
    fi
fi

out() { printf '%s\n' "$@" >> "$md"; }

# esc TEXT: TEXT for a gnuplot enhanced-text string ("_" would start a subscript).
esc() { printf '%s' "$1" | sed 's/[_^@&~{}]/\\\\&/g'; }
gtitle=$(esc "$title")

# orbit_view FILE T0 T1 XCOL YCOL [XCOL YCOL]: an orbit panel of the rows with T0 <= time <= T1,
# both axes to the same scale (gnuplot `set size ratio -1`: the galloping ellipse's shape as it
# is, never stretched); the narrower extent is widened to half the larger so that a thin orbit
# still gets a readable panel.
orbit_view() {
    awk -v t0="$2" -v t1="$3" -v xs="$4 ${6:-}" -v ys="$5 ${7:-}" '
        BEGIN { nx = split(xs, xc, " "); split(ys, yc, " ") }
        NF && $1 >= t0 && $1 <= t1 {
            for (i = 1; i <= nx; i++) {
                x = $(xc[i]); y = $(yc[i])
                if (!n++) { x0 = x1 = x; y0 = y1 = y }
                if (x < x0) x0 = x; if (x > x1) x1 = x; if (y < y0) y0 = y; if (y > y1) y1 = y
            }
        }
        END {
            print "set size ratio -1"
            print "scale = \", same scale on both axes\""
            if (!n) { print "set autoscale xy"; exit }
            hx = (x1 - x0) / 2; hy = (y1 - y0) / 2
            if (hx < hy / 2) hx = hy / 2; if (hy < hx / 2) hy = hx / 2
            if (hx <= 0) hx = hy = 1e-3
            printf "set xrange [%.9g:%.9g]\nset yrange [%.9g:%.9g]\n", (x0 + x1) / 2 - 1.1 * hx, (x0 + x1) / 2 + 1.1 * hx, (y0 + y1) / 2 - 1.1 * hy, (y0 + y1) / 2 + 1.1 * hy
        }' "$1"
}

# plot NAME CAPTION [WIDTHxHEIGHT]: runs the gnuplot commands on stdin into fig/NAME.png and puts
# the figure in the report, or a line saying why not.
plot() {
    local name=$1 caption=$2 size=${3:-} png=$fig/$1.png t=$term
    if [ -z "$gp" ]; then
        cat > /dev/null
        out "_Figure ${name} not made: gnuplot is not installed._" ""
        return 0
    fi
    [ -n "$size" ] && t=$(printf '%s' "$term" | sed "s/size [0-9]*,[0-9]*/size ${size/x/,}/")
    rm -f "$png"
    {
        printf 'set terminal %s\nset output "%s"\n' "$t" "$png"
        printf 'set grid lc rgb "#d0d0d0"\nset key box opaque samplen 2\nset datafile missing "nan"\n'
        printf 'set style data lines\nset colorsequence default\n'
        cat
        printf 'unset output\n'
    } | { echo "== $name" >> "$fig/gnuplot.log"; gnuplot >> "$fig/gnuplot.log" 2>&1; }
    if [ -s "$png" ]; then
        out "![${caption}](fig/${name}.png)" "" "*${caption}*" ""
    else
        out "_Figure ${name} failed (see fig/gnuplot.log)._" ""
        failed=1
    fi
}

# md_table FILE COLUMN...: a Markdown table of the named CSV columns.
md_table() {
    local file=$1; shift
    local names="$*"
    out "| ${names// / | } |"
    out "|$(printf '%s\n' "$@" | sed 's/.*/---|/' | tr -d '\n')"
    # tab-separated: a cell may hold spaces ("simulate full"); a "|" in a cell is escaped
    CSV_PICK_SEP=$'\t' csv_pick "$file" "$@" | awk -F'\t' 'NF { line = "|"; for (i = 1; i <= NF; i++) { c = $i; gsub(/\|/, "\\|", c); line = line " " c " |" }; print line }' >> "$md"
    out ""
}

# json_details FILE LABEL: every scalar of a summary.json, folded.
json_details() {
    [ -s "$1" ] || return 0
    out "<details><summary>All figures of ${2}</summary>" "" "| key | value |" "|---|---|"
    jflat "$1" | awk -F'\t' '{ gsub(/\|/, "\\|", $2); printf "| %s | %s |\n", $1, $2 }' >> "$md"
    out "" "</details>" ""
}

# span FILE COLUMN: "tmin tmax" of the first column of a picked data file.
span() { awk 'NF { if (n++ == 0) a = $1; b = $1 } END { print a + 0, b + 0 }' "$1"; }

# probe_col FILE WHAT: the mid-span probe column for WHAT (vertical, horizontal, twist, along),
# falling back to the first probe that has it.
probe_col() {
    local c
    c=$(csv_find_col "$1" "^p0?\\.50*_$2_")
    [ -n "$c" ] || c=$(csv_find_col "$1" "^p[0-9.]*_$2_")
    [ -n "$c" ] || c=$(csv_find_col "$1" "$2")
    printf '%s' "$c"
}

# psd_floor FILE "COL...": the largest value of those columns over 1e8 (the lower end of a PSD
# panel: 8 decades, below which a spectrum is the numerical floor).
psd_floor() {
    awk -v cols="$2" 'BEGIN { n = split(cols, c, " ") }
        NF { for (k = 1; k <= n; k++) if ($(c[k]) > m) m = $(c[k]) }
        END { printf "%.6g\n", (m > 0) ? m / 1e8 : 1e-12 }' "$1"
}

# cigre_tables SUMMARY: the CIGRE TB 322 outputs of a run (gallop simulate's summary.json): the
# galloping ellipse of each probe, the clearances to the neighbouring phases, the dynamic support
# tensions with the maximum over the static tension and over the rated strength, the span's
# amplitude beside the brochure's empirical envelope with its source.
cigre_tables() {
    local s=$1
    [ -s "$s" ] && jq -e '.support_tensions' "$s" >/dev/null 2>&1 || return 0
    out "#### CIGRE TB 322 outputs" ""
    out "Galloping ellipse of each probe over its steady window (peak-to-peak extents along the principal axes of the orbit; tilt of the major axis from the horizontal; centre from the equilibrium, horizontal downwind and up)." ""
    out "| probe (fraction of span) | from (s) | major axis p-p (m) | minor axis p-p (m) | tilt (deg) | centre horizontal (m) | centre vertical (m) |" "|---|---|---|---|---|---|---|"
    jq -r '.probes[]? | select(.ellipse) | [.position, .ellipse.from_s, .ellipse.major_peak_to_peak_m, .ellipse.minor_peak_to_peak_m, .ellipse.tilt_deg, .ellipse.centre_horizontal_m, .ellipse.centre_vertical_m] | @tsv' "$s" |
        while IFS=$'\t' read -r p f a b t cy cz; do
            out "| $p | $(num %.1f "$f") | $(num %.4g "$a") | $(num %.4g "$b") | $(num %.3g "$t") | $(num %.4g "$cy") | $(num %.4g "$cz") |"
        done
    out ""
    if jq -e '[.probes[]?.clearances[]?] | length > 0' "$s" >/dev/null 2>&1; then
        out "Clearance the ellipse leaves to each neighbouring phase at rest (output.neighbour_phases; negative: the phase lies inside the ellipse)." ""
        out "| probe | neighbour horizontal (m) | neighbour vertical (m) | clearance (m) |" "|---|---|---|---|"
        jq -r '.probes[]? | .position as $p | .clearances[]? | [$p, .neighbour_horizontal_m, .neighbour_vertical_m, .clearance_m] | @tsv' "$s" |
            while IFS=$'\t' read -r p y z c; do out "| $p | $(num %.4g "$y") | $(num %.4g "$z") | $(num %.4g "$c") |"; done
        out ""
    fi
    local rts ratio
    rts=$(jq -r '.support_tensions.rated_strength_n // empty' "$s")
    ratio=$(jq -r '.support_tensions.max_over_rated_strength // empty' "$s")
    out "Dynamic support tensions (both supports, the whole run; static: the start state)." ""
    out "| min (N) | max (N) | static (N) | max / static | rated strength RTS (N) | max / RTS |" "|---|---|---|---|---|---|"
    if [ -n "$rts" ]; then rts=$(num %.6g "$rts"); ratio=$(num %.4g "$ratio"); else rts="unknown (no rated_strength)"; ratio="n/a"; fi
    out "| $(num %.6g "$(jq -r .support_tensions.min_n "$s")") | $(num %.6g "$(jq -r .support_tensions.max_n "$s")") | $(num %.6g "$(jq -r .support_tensions.static_n "$s")") | $(num %.4g "$(jq -r .support_tensions.max_over_static "$s")") | $rts | $ratio |"
    out ""
    if jq -e '.cigre_envelope' "$s" >/dev/null 2>&1; then
        out "The span's largest galloping amplitude (the largest major axis of the probes' ellipses) beside the brochure's empirical envelope for single conductors." ""
        out "| formula | L / D | envelope p-p (m) | simulated p-p (m) | simulated / envelope |" "|---|---|---|---|---|"
        out "| $(jq -r .cigre_envelope.formula "$s" | sed 's/|/\\|/g') | $(num %.5g "$(jq -r .cigre_envelope.span_over_diameter "$s")") | $(num %.4g "$(jq -r .cigre_envelope.envelope_peak_to_peak_m "$s")") | $(num %.4g "$(jq -r .cigre_envelope.simulated_peak_to_peak_m "$s")") | $(num %.3g "$(jq -r '.cigre_envelope.simulated_over_envelope // empty' "$s")") |"
        out "" "Source of the envelope: $(jq -r .cigre_envelope.source "$s")" ""
    fi
}

# ======================================================================================
out "# Galloping report: ${title}" ""
out "Made by \`notebooks-free-reports/plot_scene.sh\` on $(date -u '+%Y-%m-%d %H:%M UTC') from the files in \`${dir}\`." ""
if [ -s "$dir/runs.csv" ]; then
    out "## Runs" ""
    md_table "$dir/runs.csv" step status seconds
fi
if [ -s "$dir/notes.md" ]; then
    out "## Notes" ""
    cat "$dir/notes.md" >> "$md"
    out ""
fi
if [ -s "$dir/scene.ini" ]; then
    out "<details><summary>Resolved scene (gallop check)</summary>" "" '```ini'
    cat "$dir/scene.ini" >> "$md"
    out '```' "" "</details>" ""
fi

# ======================================================================================
# Equilibrium and modes
m=$dir/modes
out "## Static equilibrium" ""
if [ -s "$m/summary.json" ]; then
    s=$m/summary.json
    out "| quantity | value |" "|---|---|"
    out "| mid-span sag | $(num %.4g "$(jfind "$s" sag_m)") m |"
    out "| horizontal tension | $(num %.6g "$(jfind "$s" horizontal_tension_n)") N |"
    out "| unstretched length | $(num %.8g "$(jfind "$s" unstretched_length_m)") m |"
    tl=$(jfind "$s" tension_left_n); tright=$(jfind "$s" tension_right_n)
    [ -n "$tl$tright" ] && out "| support tensions (left / right) | $(num %.6g "$tl") / $(num %.6g "$tright") N |"
    out "| elements / degrees of freedom | $(num %d "$(jfind "$s" elements)") / $(num %d "$(jfind "$s" dofs)") |"
    out "| Newton iterations | $(num %d "$(jfind "$s" newton_iterations)") |"
    out "| wall time (statics + modes) | $(num %.3g "$(jfind "$s" wall_time_s)") s |" ""
fi
if has_rows "$m/equilibrium.csv" && csv_pick "$m/equilibrium.csv" x_m z_m tension_n > "$dat/equilibrium.dat"; then
    sag=$(jfind "$m/summary.json" sag_m 2>/dev/null)
    plot equilibrium "Sagged static equilibrium: shape (z against x) and tension along the span" 1000x700 <<EOF
set multiplot layout 2,1 title "Static equilibrium: $gtitle$( [ -n "$sag" ] && printf ', mid-span sag %.3g m' "$sag")"
set xlabel "x, along the span (m)"
set ylabel "z, height (m)"
set key bottom right
plot "$dat/equilibrium.dat" using 1:2 with linespoints pt 7 ps 0.5 lw 2 title "conductor", \
     "" using 1:2 every ::0::0 with points pt 5 ps 1.5 lc rgb "black" title "supports", \
     "" using 1:2 every ::$(( $(wc -l < "$dat/equilibrium.dat") - 1 )) with points pt 5 ps 1.5 lc rgb "black" notitle
set ylabel "tension (kN)"
set key top center
plot "$dat/equilibrium.dat" using 1:(\$3/1000) with linespoints pt 7 ps 0.5 lw 2 lc 2 title "axial tension"
unset multiplot
EOF
else
    out "_No equilibrium (modes/equilibrium.csv missing)._" ""
fi

out "## Natural modes" ""
if has_rows "$m/modes.csv"; then
    out "Selected modes (the basis of the reduced model); shares are of the modal kinetic energy." ""
    csv_pick "$m/modes.csv" index family symmetry frequency_hz period_s share_vertical share_horizontal share_torsional share_axial selected |
        awk 'BEGIN { print "| mode | family | symmetry | frequency (Hz) | period (s) | vertical | horizontal | torsional | axial |"
                     print "|---|---|---|---|---|---|---|---|---|" }
             $10 == 1 { printf "| %s | %s | %s | %.5g | %.4g | %.3f | %.3f | %.3f | %.3f |\n", $1, $2, $3, $4, $5, $6, $7, $8, $9 }' >> "$md"
    out ""
    nsel=$(csv_pick "$m/modes.csv" selected | awk '$1 != 1 { n++ } END { print n + 0 }')
    [ "$nsel" -gt 0 ] && out "${nsel} more computed mode(s) not selected (see modes/modes.csv)." ""
else
    out "_No modes (modes/modes.csv missing)._" ""
fi
if has_rows "$m/shapes.csv"; then
    # symmetry of each mode, for the keys
    if has_rows "$m/modes.csv"; then csv_pick "$m/modes.csv" index symmetry > "$dat/symmetry.dat"; else : > "$dat/symmetry.dat"; fi
    for family in vertical horizontal torsional axial; do
        case $family in
            vertical) comp=uz; what="vertical displacement u_z" ;;
            horizontal) comp=uy; what="horizontal displacement u_y" ;;
            torsional) comp=twist; what="twist" ;;
            axial) comp=ux; what="axial displacement u_x" ;;
        esac
        # one block per mode, each scaled to a largest value of +1; the plot command with the keys
        csv_pick "$m/shapes.csv" mode family frequency_hz x_m "$comp" | awk -v fam="$family" -v dat="$dat/shapes_$family.dat" \
            -v symf="$dat/symmetry.dat" '
            BEGIN { while ((getline l < symf) > 0) { split(l, a, " "); sym[a[1]] = a[2] } }
            NF && $2 == fam {
                if (!($1 in seen)) { seen[$1] = 1; order[++nm] = $1; freq[$1] = $3 }
                k = $1; n[k]++; x[k, n[k]] = $4; v[k, n[k]] = $5
                if ($5 * $5 > big[k] * big[k]) big[k] = $5
            }
            END {
                if (nm == 0) exit 1
                cmd = "plot "
                for (b = 1; b <= nm; b++) {
                    k = order[b]; s = big[k] != 0 ? 1 / big[k] : 1
                    for (i = 1; i <= n[k]; i++) print x[k, i], v[k, i] * s > dat
                    printf "\n\n" > dat
                    t = sprintf("mode %s: %.4g Hz%s", k, freq[k], (k in sym) ? ", " sym[k] : "")
                    cmd = cmd sprintf("%s\"%s\" index %d using 1:2 with linespoints pt 7 ps 0.5 lw 2 title \"%s\"", b > 1 ? ", " : "", dat, b - 1, t)
                }
                print cmd
            }' > "$dat/shapes_$family.gp" || continue
        plot "modes_$family" "${family^} mode shapes (${what}, each scaled to a largest value of 1), with their frequencies" <<EOF
set title "${family^} modes of $gtitle: ${what} along the span"
set xlabel "x, along the span (m)"
set ylabel "${what} (scaled, largest = 1)"
set key outside right top
set yrange [-1.15:1.15]
$(cat "$dat/shapes_$family.gp")
EOF
    done
else
    out "_No mode shapes (modes/shapes.csv missing)._" ""
fi
json_details "$m/summary.json" "modes/summary.json"

# ======================================================================================
# Simulations: one section per model
sim_table_done=0
for model in full reduced; do
    d=$dir/$model
    [ -e "$d/trace.csv" ] || [ -e "$d/summary.json" ] || continue
    if [ $sim_table_done = 0 ]; then
        out "## Galloping simulations" ""
        out "| model | wall time (s) | frequency (Hz) | vertical peak to peak (m) | horizontal peak to peak (m) | time to steady (s) |" "|---|---|---|---|---|---|"
        for mm in full reduced; do
            s=$dir/$mm/summary.json
            [ -s "$s" ] || continue
            out "| $mm | $(num %.4g "$(jfind "$s" wall_time_s)") | $(num %.5g "$(jfind "$s" frequency_hz)") | $(num %.4g "$(jfind "$s" amplitude_m.vertical)") | $(num %.4g "$(jfind "$s" amplitude_m.horizontal)") | $(num %.4g "$(jfind "$s" time_to_steady_s)") |"
        done
        out ""
        sim_table_done=1
    fi
    out "### ${model^} model" ""
    tr=$d/trace.csv
    if has_rows "$tr"; then
        cv=$(probe_col "$tr" vertical); ch=$(probe_col "$tr" horizontal); ct=$(probe_col "$tr" twist)
        if [ -n "$cv" ] && [ -n "$ch" ]; then
            cols="time_s $ch $cv"; [ -n "$ct" ] && cols="$cols $ct"
            csv_pick "$tr" $cols > "$dat/trace_$model.dat"
            probe=${cv%%_*}
            np=2; tw=""; tens=""
            if [ -n "$ct" ]; then np=$((np + 1)); tw="set ylabel \"twist (deg)\"
plot \"$dat/trace_$model.dat\" using 1:4 lc 3 title \"twist\""; fi
            if [ -n "$(csv_col "$tr" tension_left_n)" ] && [ -n "$(csv_col "$tr" tension_right_n)" ]; then
                csv_pick "$tr" time_s tension_left_n tension_right_n > "$dat/tension_$model.dat"
                np=$((np + 1)); tens="set ylabel \"support tension (kN)\"
plot \"$dat/tension_$model.dat\" using 1:(\$2/1000) lc 4 title \"left\", \"\" using 1:(\$3/1000) lc 7 title \"right\""
            fi
            plot "trace_$model" "${model^} model: mid-span probe (${probe}) against time$( [ -n "$tens" ] && printf ', and support tensions')" 1000x$((220 * np + 60)) <<EOF
set multiplot layout $np,1 title "${model^} model, $gtitle: probe $(esc "$probe")"
set xlabel "time (s)"
set key top left
set ylabel "vertical (m)"
plot "$dat/trace_$model.dat" using 1:3 lc 1 title "vertical"
set ylabel "horizontal (m)"
plot "$dat/trace_$model.dat" using 1:2 lc 2 title "horizontal"
$tw
$tens
unset multiplot
EOF
            read -r t0 t1 <<<"$(span "$dat/trace_$model.dat")"
            w=$(awk -v a="$t0" -v b="$t1" 'BEGIN { print (b - a) / 4 }')
            e1=$(awk -v a="$t0" -v w="$w" 'BEGIN { print a + w }'); l0=$(awk -v b="$t1" -v w="$w" 'BEGIN { print b - w }')
            tss=$(jfind "$d/summary.json" time_to_steady_s)
            late="last quarter of the run"
            [ -n "$tss" ] && awk -v a="$tss" -v b="$l0" 'BEGIN { exit !(a + 0 <= b + 0) }' && late="last quarter of the run, after the time to steady ($(num %.0f "$tss") s)"
            # the CIGRE galloping ellipse of this probe (summary.json) over the late orbit
            pos=${probe#p}
            ell=$(jq -r --argjson p "$pos" '.probes[]? | select(.position == $p) | .ellipse
                | "\(.centre_horizontal_m) \(.centre_vertical_m) \(.major_peak_to_peak_m / 2) \(.minor_peak_to_peak_m / 2) \(.tilt_deg) \(.from_s)"' \
                "$d/summary.json" 2>/dev/null | head -n 1)
            ellplot=""; ellcap=""
            if [ -n "$ell" ]; then
                read -r ecy ecz ea eb eth efrom <<<"$ell"
                awk -v cy="$ecy" -v cz="$ecz" -v a="$ea" -v b="$eb" -v th="$eth" 'BEGIN {
                    c = cos(th * 3.14159265358979 / 180); s = sin(th * 3.14159265358979 / 180)
                    for (k = 0; k <= 360; k++) { t = k * 3.14159265358979 / 180; u = a * cos(t); v = b * sin(t)
                        printf "%.9g %.9g\n", cy + c * u - s * v, cz + s * u + c * v } }' > "$dat/ellipse_$model.dat"
                ellplot=", \"$dat/ellipse_$model.dat\" using 1:2 with lines lc rgb \"black\" dt 2 lw 1.5 title \"galloping ellipse (from $(num %.0f "$efrom") s)\""
                ellcap="; dashed, the galloping ellipse (CIGRE TB 322: peak-to-peak axes, tilt and centre over the steady window, from $(num %.0f "$efrom") s)"
            fi
            plot "orbit_$model" "${model^} model: orbit of the mid-span probe, first quarter of the run (left) and ${late} (right), axes to the same scale${ellcap}" 1100x560 <<EOF
set multiplot layout 1,2 title "${model^} model, $gtitle: orbit of probe $(esc "$probe") (seen along the span)"
set xlabel "horizontal (m)"
set ylabel "vertical (m)"
set key below
$(orbit_view "$dat/trace_$model.dat" "$t0" "$e1" 2 3)
set title sprintf("early: %.1f to %.1f s", $t0, $e1) . scale
plot "$dat/trace_$model.dat" using (\$1 <= $e1 ? \$2 : NaN):3 lc 1 title "orbit"
$(orbit_view "$dat/trace_$model.dat" "$l0" "$t1" 2 3)
set title sprintf("late: %.1f to %.1f s", $l0, $t1) . scale
plot "$dat/trace_$model.dat" using (\$1 >= $l0 ? \$2 : NaN):3 lc 2 title "orbit"$ellplot
unset multiplot
EOF
        else
            out "_trace.csv has no vertical and horizontal probe columns._" ""
        fi
    else
        out "_No trace (${model}/trace.csv missing or empty)._" ""
    fi
    psd=$d/spectrum/psd.csv   # gallop spectrum on this run's trace.csv
    [ -e "$psd" ] || psd=$d/psd.csv
    if has_rows "$psd" && [ -n "$(csv_col "$psd" frequency_hz)" ]; then
        # the mid-span probe's signals (all columns of a trace without probes)
        pcols=$(csv_header "$psd" | tr ',' '\n' | grep -v '^frequency_hz$' | grep -E '^p0?\.50*_(vertical|horizontal|twist)' | tr '\n' ' ')
        [ -n "$pcols" ] || pcols=$(csv_header "$psd" | tr ',' '\n' | grep -v '^frequency_hz$' | tr '\n' ' ')
        csv_pick "$psd" frequency_hz $pcols > "$dat/psd_$model.dat"
        # one panel per unit: translations (m^2/Hz) and twist (deg^2/Hz); the legend names the
        # motion; each panel shows 8 decades below its peak (below is the numerical floor)
        pt=""; pr=""; tcols=""; rcols=""; i=2
        for c in $pcols; do
            what=${c#*_}; what=${what%%_*}
            line="\"$dat/psd_$model.dat\" using 1:(\$$i > 0 ? \$$i : NaN) lw 1.5 title \"$what\""
            case $c in
                *_deg2_per_hz) pr="$pr$( [ -n "$pr" ] && printf ', ')$line"; rcols="$rcols $i" ;;
                *) pt="$pt$( [ -n "$pt" ] && printf ', ')$line"; tcols="$tcols $i" ;;
            esac
            i=$((i + 1))
        done
        xmax=$(awk -v m="$psd_fmax" 'NF { if ($1 > x) x = $1 } END { print (x > 0 && x < m) ? x : m }' "$dat/psd_$model.dat")
        np=0; [ -n "$pt" ] && np=$((np + 1)); [ -n "$pr" ] && np=$((np + 1))
        plot "psd_$model" "${model^} model: power spectral density of the mid-span probe's motion over the steady part of this run (gallop spectrum on trace.csv, Welch; log scale): translations (m^2/Hz), twist (deg^2/Hz)" 1000x$((300 * np + 60)) <<EOF
set multiplot layout $np,1 title "${model^} model, $gtitle: power spectral density, mid-span probe"
set xlabel "frequency (Hz)"
set logscale y
set format y "10^{%L}"
set key top right
set xrange [0:$xmax]
$( [ -n "$pt" ] && printf 'set ylabel "PSD (m^2/Hz)"\nset yrange [%s:*]\nplot %s\n' "$(psd_floor "$dat/psd_$model.dat" "$tcols")" "$pt")
$( [ -n "$pr" ] && printf 'set ylabel "PSD (deg^2/Hz)"\nset yrange [%s:*]\nplot %s\n' "$(psd_floor "$dat/psd_$model.dat" "$rcols")" "$pr")
unset multiplot
EOF
    fi
    cigre_tables "$d/summary.json"
    json_details "$d/summary.json" "${model}/summary.json"
done

# ======================================================================================
# Full against reduced
c=$dir/compare
if [ -e "$c/compare.csv" ] || [ -e "$c/summary.json" ]; then
    out "## Full against reduced model" ""
    s=$c/summary.json
    if [ -s "$s" ]; then
        out "| figure | full | reduced |" "|---|---|---|"
        jflat "$s" | awk -F'\t' '
            $1 ~ /^full\./ { k = substr($1, 6); if (!(k in f)) order[++n] = k; f[k] = $2 }
            $1 ~ /^reduced\./ { k = substr($1, 9); if (!(k in f) && !(k in r)) order[++n] = k; r[k] = $2 }
            END { for (i = 1; i <= n; i++) { k = order[i]; printf "| %s | %s | %s |\n", k, (k in f) ? f[k] : "", (k in r) ? r[k] : "" } }' >> "$md"
        out ""
        out "| measure | value |" "|---|---|"
        for k in frequency_error amplitude_error speedup; do
            v=$(jfind "$s" "$k")
            [ -n "$v" ] && out "| $k | $(num %.4g "$v") |"
        done
        out ""
    fi
    cc=$c/compare.csv
    if has_rows "$cc" && csv_pick "$cc" time_s full_vertical_m reduced_vertical_m full_horizontal_m reduced_horizontal_m > "$dat/compare.dat"; then
        np=2; tw=""
        if csv_pick "$cc" full_twist_deg reduced_twist_deg > "$dat/compare_twist.dat" 2>/dev/null; then
            paste -d' ' "$dat/compare.dat" "$dat/compare_twist.dat" > "$dat/compare_all.dat"
            mv "$dat/compare_all.dat" "$dat/compare.dat"
            np=3; tw="set ylabel \"twist (deg)\"
plot \"$dat/compare.dat\" using 1:6 lc 1 title \"full\", \"\" using 1:7 lc 2 dt 2 lw 1.5 title \"reduced\""
        fi
        plot compare_traces "Mid-span probe, full (solid) against reduced (dashed) model" 1000x$((230 * np + 60)) <<EOF
set multiplot layout $np,1 title "Full against reduced model, $gtitle: mid-span"
set xlabel "time (s)"
set key top left
set ylabel "vertical (m)"
plot "$dat/compare.dat" using 1:2 lc 1 title "full", "" using 1:3 lc 2 dt 2 lw 1.5 title "reduced"
set ylabel "horizontal (m)"
plot "$dat/compare.dat" using 1:4 lc 1 title "full", "" using 1:5 lc 2 dt 2 lw 1.5 title "reduced"
$tw
unset multiplot
EOF
        read -r t0 t1 <<<"$(span "$dat/compare.dat")"
        w=$(awk -v a="$t0" -v b="$t1" 'BEGIN { print (b - a) / 4 }')
        e1=$(awk -v a="$t0" -v w="$w" 'BEGIN { print a + w }'); l0=$(awk -v b="$t1" -v w="$w" 'BEGIN { print b - w }')
        plot compare_orbits "Mid-span orbit, full against reduced model: first quarter of the run (left) and last quarter (right)" 1100x560 <<EOF
set multiplot layout 1,2 title "Full against reduced model, $gtitle: mid-span orbit"
set xlabel "horizontal (m)"
set ylabel "vertical (m)"
set key below
$(orbit_view "$dat/compare.dat" "$t0" "$e1" 4 2 5 3)
set title sprintf("early: %.1f to %.1f s", $t0, $e1) . scale
plot "$dat/compare.dat" using (\$1 <= $e1 ? \$4 : NaN):2 lc 1 title "full", "" using (\$1 <= $e1 ? \$5 : NaN):3 lc 2 dt 2 lw 1.5 title "reduced"
$(orbit_view "$dat/compare.dat" "$l0" "$t1" 4 2 5 3)
set title sprintf("late: %.1f to %.1f s", $l0, $t1) . scale
plot "$dat/compare.dat" using (\$1 >= $l0 ? \$4 : NaN):2 lc 1 title "full", "" using (\$1 >= $l0 ? \$5 : NaN):3 lc 2 dt 2 lw 1.5 title "reduced"
unset multiplot
EOF
    else
        out "_No comparison traces (compare/compare.csv missing or without the expected columns)._" ""
    fi
    json_details "$s" "compare/summary.json"
fi

# ======================================================================================
# Accuracy against time
a=$dir/accuracy/accuracy.csv
if [ -e "$a" ]; then
    out "## Accuracy against time" ""
    if has_rows "$a" && csv_pick "$a" study setting value error wall_time_s chosen > "$dat/accuracy_rows.dat"; then
        out "Each study varies one setting; the **bold** row is the cheapest setting that meets the tolerance (chosen)." ""
        out "| study | setting | value | error | wall time (s) | chosen |" "|---|---|---|---|---|---|"
        awk '{ b = $6 == 1 ? "**" : ""; printf "| %s%s%s | %s%s%s | %s | %s | %s | %s |\n", b, $1, b, b, $2, b, $3, $4, $5, $6 == 1 ? "yes" : "" }' \
            "$dat/accuracy_rows.dat" >> "$md"
        out ""
        # one block per study, in order of first appearance; chosen points apart
        awk -v dat="$dat/accuracy.dat" -v ch="$dat/accuracy_chosen.dat" '
            { if (!($1 in seen)) { seen[$1] = 1; order[++n] = $1 } k = $1; m[k]++
              lab = $3                            # the effects study: which effect, not just "off"
              if ($1 == "effects") { e = $2; sub(/^effects\.?/, "", e); lab = "\"" (e == "" ? "all on" : e " " $3) "\"" }
              row[k, m[k]] = $5 " " $4 " " lab
              if ($6 == 1) print $5, $4, $3 > ch }
            END { printf "" > ch
                  for (i = 1; i <= n; i++) { k = order[i]; for (j = 1; j <= m[k]; j++) print row[k, j] > dat; printf "\n\n" > dat; print k } }' \
            "$dat/accuracy_rows.dat" > "$dat/accuracy_studies.txt"
        ac="plot "; i=0
        while read -r st; do
            # a sweep is a line; the effects study (each effect off in turn) is points alone
            sty="linespoints"; [ "$st" = effects ] && sty="points"
            ac="$ac\"$dat/accuracy.dat\" index $i using 1:(\$2 > 0 ? \$2 : NaN) with $sty pt 7 ps 1 lw 2 lc $((i + 1)) title \"${st//_/ }\", "
            ac="$ac\"$dat/accuracy.dat\" index $i using 1:(\$2 > 0 ? \$2 : NaN):3 with labels offset char 0.8,0.8 left font \",8\" tc lt $((i + 1)) noenhanced notitle, "
            i=$((i + 1))
        done < "$dat/accuracy_studies.txt"
        ac="$ac\"$dat/accuracy_chosen.dat\" using 1:(\$2 > 0 ? \$2 : NaN) with points pt 6 ps 3 lw 2 lc rgb \"black\" title \"chosen\""
        plot accuracy "Accuracy against time: error against wall time for each study (log-log), each point labelled by its setting's value; circled, the setting chosen in each study" <<EOF
set title "Accuracy against time, $gtitle"
set xlabel "wall time (s)"
set ylabel "error (relative, against the finest setting)"
set logscale xy
set format y "10^{%L}"
set key outside right top
$ac
EOF
        nz=$(awk '$4 <= 0 { n++ } END { print n + 0 }' "$dat/accuracy_rows.dat")
        [ "$nz" -gt 0 ] && out "${nz} row(s) with zero error (the reference settings) cannot be shown on the log scale." ""
    else
        out "_accuracy/accuracy.csv is empty or lacks the columns study,setting,value,error,wall_time_s,chosen._" ""
    fi
fi

# ======================================================================================
# Torsional stiffness study
ts=$dir/torsion/study.csv
if [ -e "$ts" ]; then
    out "## Torsional stiffness study" ""
    out "Reduced-model runs with the conductor's torsional stiffness GJ scaled; mid-span vertical motion." ""
    out "| GJ factor | GJ (N m^2/rad) | time to steady (s) | vertical peak-to-peak, summary (m) | vertical peak-to-peak, last quarter of trace (m) | frequency (Hz) | wall time (s) |"
    out "|---|---|---|---|---|---|---|"
    ec="plot "; i=0
    while IFS=, read -r fac gj sub status; do
        [ "$fac" = factor ] && continue
        d=$dir/torsion/$sub
        if [ "$status" != ok ]; then
            out "| $fac | $(num %.4g "$gj") | run ${status} | | | | |"
            continue
        fi
        s=$d/summary.json
        tts=$(jfind "$s" time_to_steady_s vertical)
        pp=$(jfind "$s" peak_to_peak_m vertical); [ -n "$pp" ] || pp=$(jfind "$s" peak_to_peak vertical)
        [ -n "$pp" ] || pp=$(jfind "$s" amplitude_m)
        fr=$(jfind "$s" frequency_hz vertical)
        wt=$(jfind "$s" wall_time_s)
        tp=""
        if has_rows "$d/trace.csv"; then
            cv=$(probe_col "$d/trace.csv" vertical)
            if [ -n "$cv" ] && csv_pick "$d/trace.csv" time_s "$cv" > "$dat/torsion_$i.dat"; then
                read -r t0 t1 <<<"$(span "$dat/torsion_$i.dat")"
                tp=$(awk -v l0="$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - (b - a) / 4 }')" \
                    'NF && $1 >= l0 { if (!n++) { lo = hi = $2 } if ($2 < lo) lo = $2; if ($2 > hi) hi = $2 } END { if (n) print hi - lo }' "$dat/torsion_$i.dat")
                # envelope: min and max over windows of 1.5 periods (or 1/100 of the run)
                win=$(awk -v f="$fr" -v a="$t0" -v b="$t1" 'BEGIN { print (f + 0 > 0) ? 1.5 / f : (b - a) / 100 }')
                awk -v w="$win" -v a="$t0" 'NF { k = int(($1 - a) / w); if (!(k in lo) || $2 < lo[k]) lo[k] = $2; if (!(k in hi) || $2 > hi[k]) hi[k] = $2; if (k > m) m = k }
                    END { if (m > 0) m--; for (k = 0; k <= m; k++) if (k in lo) print a + (k + 0.5) * w, lo[k], hi[k] }' "$dat/torsion_$i.dat" > "$dat/envelope_$i.dat"
                ec="$ec\"$dat/envelope_$i.dat\" using 1:3 lw 2 lc $((i + 1)) title \"GJ x $fac ($(num %.3g "$gj") N m^2/rad)\", \"\" using 1:2 lw 2 lc $((i + 1)) notitle, "
                i=$((i + 1))
            fi
        fi
        out "| $fac | $(num %.4g "$gj") | $(num %.4g "$tts") | $(num %.4g "$pp") | $(num %.4g "$tp") | $(num %.5g "$fr") | $(num %.3g "$wt") |"
    done < "$ts"
    out ""
    if [ $i -gt 0 ]; then
        plot torsion_envelope "Torsional stiffness study: envelope (upper and lower) of the mid-span vertical motion for each GJ" <<EOF
set title "Torsional stiffness study, $gtitle: envelope of the mid-span vertical motion (reduced model)"
set xlabel "time (s)"
set ylabel "vertical displacement, envelope (m)"
set autoscale xfix
set key outside right top
${ec%, }
EOF
    else
        out "_No traces in the torsional stiffness study._" ""
    fi
fi

# ======================================================================================
# Galloping onset of the coupled aeroelastic system (gallop stability, issue 15)
g=$dir/stability
if has_rows "$g/vg.csv"; then
    s=$g/summary.json
    out "## Galloping onset: the coupled aeroelastic system" ""
    out "About the equilibrium under each mean wind speed, with the structural damping the dynamic models apply (\`gallop stability\`, files in \`stability/\`)." ""
    out "| quantity | value |" "|---|---|"
    out "| onset wind speed | $(num %.4g "$(jfind "$s" onset_speed_m_s)") m/s (range studied up to $(num %.4g "$(jfind "$s" speed_max_m_s)") m/s) |"
    out "| mode losing stability | $(num %d "$(jfind "$s" index onset_mode)"), $(num %.4g "$(jfind "$s" onset_frequency_hz)") Hz; shares vertical $(num %.3f "$(jfind "$s" share_vertical onset_mode)"), horizontal $(num %.3f "$(jfind "$s" share_horizontal onset_mode)"), torsional $(num %.3f "$(jfind "$s" share_torsional onset_mode)") |"
    out "| torsional divergence | $(num %.4g "$(jfind "$s" divergence_speed_m_s)") m/s |"
    out "| fold of the mean-wind equilibrium | $(num %.4g "$(jfind "$s" fold_speed_m_s)") m/s |"
    out "| Den Hartog, first vertical mode, at rest | $(num %.4g "$(jfind "$s" onset_speed_at_rest_m_s)") m/s |" ""
    # speed, f_k and zeta_k of each followed mode, swing, twist; "nan" where empty
    awk -F, '/^#/ { next } !h++ { for (i = 1; i <= NF; i++) { if ($i ~ /^f[0-9]+_hz$/) fc[++nf] = i; if ($i ~ /^zeta[0-9]+$/) zc[++nz] = i; if ($i == "swing_deg") sw = i; if ($i == "twist_deg") tw = i } next }
        { line = $1; for (k = 1; k <= nf; k++) line = line " " ($fc[k] == "" ? "nan" : $fc[k]);
          for (k = 1; k <= nz; k++) line = line " " ($zc[k] == "" ? "nan" : $zc[k]);
          print line, ($sw == "" ? "nan" : $sw), ($tw == "" ? "nan" : $tw) }
        END { print nf > "/dev/stderr" }' "$g/vg.csv" > "$dat/vg.dat" 2> "$dat/vg.n"
    nm=$(cat "$dat/vg.n")
    uc=$(jfind "$s" onset_speed_m_s)
    mark=""
    [ -n "$uc" ] && mark="set arrow from $uc, graph 0 to $uc, graph 1 nohead dt 2 lw 2 lc rgb \"red\"
set label \"onset $(num %.3g "$uc") m/s\" at $uc, graph 0.05 left offset 0.5,0 tc rgb \"red\""
    vg="" vf=""
    for k in $(seq 1 "$nm"); do
        vg="$vg\"$dat/vg.dat\" using 1:(100*\$$((1 + nm + k))) with linespoints pt 7 ps 0.5 lw 2 title \"mode $k\", "
        vf="$vf\"$dat/vg.dat\" using 1:$((1 + k)) with linespoints pt 7 ps 0.5 lw 2 title \"mode $k\", "
    done
    plot vg_diagram "V-g diagram: damping ratio of each followed aeroelastic mode against the mean wind speed (below 0: galloping)" 1000x600 <<EOF
set title "V-g diagram, $gtitle"
set xlabel "mean wind speed (m/s)"
set ylabel "damping ratio (%)"
set key outside right top
$mark
set arrow from graph 0, first 0 to graph 1, first 0 nohead lw 1 lc rgb "black"
plot ${vg%, }
EOF
    plot vf_diagram "V-f diagram: frequency of each followed aeroelastic mode against the mean wind speed" 1000x600 <<EOF
set title "V-f diagram, $gtitle"
set xlabel "mean wind speed (m/s)"
set ylabel "frequency (Hz)"
set key outside right top
$mark
plot ${vf%, }
EOF
    plot mean_wind_equilibrium "Mean-wind equilibrium at mid-span: swing angle and twist against the wind speed" 1000x500 <<EOF
set title "Mean-wind equilibrium at mid-span, $gtitle"
set xlabel "mean wind speed (m/s)"
set ylabel "angle (deg)"
set key top left
plot "$dat/vg.dat" using 1:$((2 + 2 * nm)) with linespoints pt 7 ps 0.5 lw 2 title "swing", \
     "" using 1:$((3 + 2 * nm)) with linespoints pt 7 ps 0.5 lw 2 title "twist"
EOF
fi

mv "$md" "$dir/report.md"
[ $failed = 0 ] || echo "plot_scene.sh: some figures failed, see $fig/gnuplot.log" >&2
exit $failed
