#!/usr/bin/env bash
# make_report.sh BUILD_DIR|GALLOP_BINARY [SCENE.ini...]: runs gallop on each scene (default: every
# data/scenes/*.ini) and writes a Markdown report with PNG figures per scene in
# $REPORT_OUT/NAME/report.md (plot_scene.sh makes the figures and tables from the output files).
# Commands that this build of gallop does not have (see `gallop help`) are skipped with a note.
#
# Environment:
#   REPORT_OUT         output directory                                   (out/report)
#   REPORT_SET         extra settings "section.key=value ..." given to every command as --set
#   REPORT_DURATION    simulated time (s) of every run, --set simulation.duration=...;
#                      "scene" keeps each scene's own duration (the galloping scenes need
#                      their full build-up)                            (scene)
#   REPORT_GJ_FACTORS  factors on the scene's torsional stiffness GJ  ("0.5 1 2 4")
#   REPORT_ACCURACY_DURATION  simulated time (s) of the accuracy study's runs (300)
#   REPORT_STEPS       steps to run, of: modes stability full reduced compare accuracy torsion
#                      sweep bundle (all; sweep: sweep_report.sh on iced_gallop, once; bundle:
#                      bundle_report.sh, the quad bundle beside its single sub-conductor, once)
#   REPORT_TIMEOUT     seconds allowed to each gallop run              (900)
#   REPORT_PSD_FMAX, REPORT_TERMINAL: see plot_scene.sh and README.md
# Exit status: 0 every report written and every run succeeded, 1 a run or a figure failed (the
# reports are still written), 2 bad usage.
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
. "$here/lib.sh"

usage() {
    echo "usage: make_report.sh BUILD_DIR|GALLOP_BINARY [SCENE.ini...]" >&2
    echo "  env: REPORT_OUT REPORT_SET REPORT_DURATION REPORT_GJ_FACTORS REPORT_STEPS REPORT_TIMEOUT" >&2
}

arg=${1:-}
if [ -d "$arg" ]; then bin=$arg/gallop; else bin=$arg; fi
if [ -z "$arg" ] || [ ! -x "$bin" ] || [ -d "$bin" ]; then
    [ -n "$arg" ] && echo "make_report.sh: no gallop binary at '$bin' (build it first: make)" >&2
    usage
    exit 2
fi
shift
case $bin in /*) ;; *) bin=$PWD/$bin ;; esac

if [ $# -gt 0 ]; then
    scenes=("$@")
else
    scenes=()
    for s in "$root"/data/scenes/*.ini; do [ -e "$s" ] && scenes+=("$s"); done
fi
for s in "${scenes[@]}"; do
    [ -r "$s" ] || { echo "make_report.sh: cannot read scene '$s'" >&2; exit 2; }
done

outroot=${REPORT_OUT:-out/report}
duration=${REPORT_DURATION-scene}
factors=${REPORT_GJ_FACTORS:-0.5 1 2 4}
steps=" ${REPORT_STEPS:-modes stability full reduced compare accuracy torsion sweep bundle} "
tmo=${REPORT_TIMEOUT:-900}
sets=()
for kv in ${REPORT_SET:-}; do sets+=(--set "$kv"); done
dur=()
[ -n "$duration" ] && [ "$duration" != scene ] && dur=(--set "simulation.duration=$duration")

# the commands this build has: `gallop help` lists them one a line ("  modes SCENE ..." or
# "  gallop modes SCENE ...")
help=$("$bin" help 2>&1)
has() { printf '%s\n' "$help" | grep -Eq "^[[:space:]]+(gallop[[:space:]]+)?$1([[:space:]]|\$)"; }
want() { case $steps in *" $1 "*) return 0 ;; *) return 1 ;; esac; }

mkdir -p "$outroot" || exit 2
status=0
index=$outroot/index.md
{
    echo "# Galloping reports"
    echo
    echo "Made by \`notebooks-free-reports/make_report.sh\` with \`$bin\`$( [ -n "${REPORT_SET:-}" ] && printf ', settings `%s`' "$REPORT_SET")$( [ ${#dur[@]} -gt 0 ] && printf ', duration %s s' "$duration")."
    echo
} > "$index"
if [ ${#scenes[@]} -eq 0 ]; then
    echo "make_report.sh: no scenes given and none in $root/data/scenes; nothing to report" >&2
    echo "No scenes: data/scenes/*.ini is empty and none were given." >> "$index"
    exit 0
fi

for scene in "${scenes[@]}"; do
    name=$(basename "$scene" .ini)
    d=$outroot/$name
    rm -rf "$d"   # no stale outputs from an earlier run in the report
    mkdir -p "$d/logs"
    notes=$d/notes.md
    : > "$notes"
    printf 'step,status,seconds\n' > "$d/runs.csv"
    note() { printf -- '- %s\n' "$*" >> "$notes"; }
    echo "report: scene $name ($scene) -> $d" >&2

    # run STEP LOG CMD...: one gallop run, timed, its output in logs/LOG.log; status 0 if it succeeded
    run() {
        local step=$1 log=$2 t0 t1 rc st; shift 2
        t0=$(date +%s.%N)
        timeout "$tmo" "$@" > "$d/logs/$log.log" 2>&1
        rc=$?
        t1=$(date +%s.%N)
        case $rc in
            0) st=ok ;;
            124) st="timed out after ${tmo} s" ;;
            *) st="failed (exit $rc)" ;;
        esac
        local secs; secs=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }')
        printf '%s,%s,%s\n' "$step" "$st" "$secs" >> "$d/runs.csv"
        echo "  $step: $st (${secs} s)" >&2
        if [ $rc -ne 0 ]; then
            note "\`$step\` $st; the last lines of logs/$log.log:"
            { printf '\n  ```\n'; tail -n 5 "$d/logs/$log.log" | sed 's/^/  /'; printf '  ```\n\n'; } >> "$notes"
            status=1
        fi
        return $rc
    }
    skip() { note "\`gallop $1\` is not in this build of gallop (\`gallop help\` does not list it): $2 left out."; }

    # the resolved scene, for the report and for GJ
    if has check; then
        if timeout "$tmo" "$bin" check "$scene" "${sets[@]}" > "$d/scene.ini" 2> "$d/logs/check.log"; then :; else
            note "\`gallop check\` failed (exit $?): see logs/check.log."
            : > "$d/scene.ini"
        fi
    else
        skip check "the resolved scene"
    fi

    # a scene without wind has no galloping: the simulations, the comparison and the torsion
    # study are left out (said in the notes), not shown as flat lines
    wind=$(awk '/^\[wind\]/ { w = 1; next } /^\[/ { w = 0 } w && $1 == "speed" { print $3 }' "$d/scene.ini" 2>/dev/null)
    windy=1   # unknown (no resolved scene): as if windy
    [ -n "$wind" ] && ! awk -v u="$wind" 'BEGIN { exit !(u > 0) }' && windy=0
    if [ $windy = 0 ]; then
        note "No wind in this scene (wind.speed = ${wind:-0}): no galloping simulations, comparison or torsion study."
        steps_scene=" $(for s in $steps; do case $s in full|reduced|compare|torsion) ;; *) printf '%s ' "$s" ;; esac; done)"
    else
        steps_scene=$steps
    fi
    want() { case $steps_scene in *" $1 "*) return 0 ;; *) return 1 ;; esac; }

    if want modes; then
        if has modes; then run modes modes "$bin" modes "$scene" "${sets[@]}" -o "$d/modes"
        else skip modes "equilibrium and modes"; fi
    fi
    # the galloping onset of the coupled system: scenes with an iced section's aerodynamic table
    if want stability; then
        if ! has stability; then skip stability "the galloping onset"
        elif grep -q '^aero_table = ' "$d/scene.ini"; then run stability stability "$bin" stability "$scene" "${sets[@]}" -o "$d/stability"
        else note "No [ice] aero_table in this scene: no galloping onset to analyse (\`gallop stability\` left out)."; fi
    fi
    for model in full reduced; do
        want "$model" || continue
        if has simulate; then
            if run "simulate $model" "$model" "$bin" simulate "$scene" --model "$model" "${sets[@]}" "${dur[@]}" -o "$d/$model" \
                && has spectrum; then
                # the spectra of the real run, by gallop spectrum on its trace
                run "spectrum $model" "spectrum_$model" "$bin" spectrum "$d/$model/trace.csv" -o "$d/$model/spectrum"
            fi
        else skip simulate "the $model-model simulation"; fi
    done
    if want compare; then
        if has compare; then run compare compare "$bin" compare "$scene" "${sets[@]}" "${dur[@]}" -o "$d/compare"
        else skip compare "the full against reduced comparison"; fi
    fi
    if want accuracy; then
        if has accuracy; then
            # a scene without wind has no galloping to measure: only the mesh study applies; the
            # dynamic studies run over REPORT_ACCURACY_DURATION s (default 300) to keep `make
            # report` to minutes
            if [ $windy = 1 ]; then
                run accuracy accuracy "$bin" accuracy "$scene" "${sets[@]}" \
                    --set "simulation.duration=${REPORT_ACCURACY_DURATION:-300}" -o "$d/accuracy"
            else
                note "No wind in this scene: the accuracy study is the mesh study alone."
                run accuracy accuracy "$bin" accuracy "$scene" "${sets[@]}" --study elements -o "$d/accuracy"
            fi
        else skip accuracy "the accuracy against time study"; fi
    fi

    # torsional stiffness study: reduced runs with GJ scaled, GJ read from `gallop check`
    if want torsion; then
        if ! has simulate; then
            skip simulate "the torsional stiffness study"
        else
            gj=$(awk '
                { sub(/[;#].*/, "") }
                /^[[:space:]]*\[/ { gsub(/[][[:space:]]/, ""); sec = $0; next }
                sec == "conductor" && /=/ {
                    k = $0; sub(/=.*/, "", k); gsub(/[[:space:]]/, "", k)
                    v = $0; sub(/^[^=]*=/, "", v); gsub(/[[:space:]]/, "", v)
                    if (k == "torsional_stiffness") { print v; exit }
                }' "$d/scene.ini" 2>/dev/null)
            if [ -z "$gj" ]; then
                note "Torsional stiffness study left out: no \`torsional_stiffness\` in the [conductor] section of \`gallop check\` output."
            else
                mkdir -p "$d/torsion"
                printf 'factor,torsional_stiffness_n_m2_per_rad,directory,status\n' > "$d/torsion/study.csv"
                for f in $factors; do
                    x=$(awk -v g="$gj" -v f="$f" 'BEGIN { printf "%.6g", g * f }')
                    if run "torsion GJ x $f" "torsion_gj_$f" "$bin" simulate "$scene" --model reduced "${sets[@]}" "${dur[@]}" \
                        --set "conductor.torsional_stiffness=$x" -o "$d/torsion/gj_$f"; then st=ok; else st=failed; fi
                    printf '%s,%s,gj_%s,%s\n' "$f" "$x" "$f" "$st" >> "$d/torsion/study.csv"
                done
            fi
        fi
    fi

    [ -s "$notes" ] || rm -f "$notes"
    if bash "$here/plot_scene.sh" "$d" "$name"; then :; else status=1; fi
    if [ -s "$d/accuracy/front.csv" ]; then bash "$here/plot_front.sh" "$d/accuracy" "$d/report.md" || status=1; fi
    bash "$here/plot_onset.sh" "$d" "$name" || status=1 # the classic criteria beside the coupled onset
    echo "  report: $d/report.md" >&2
    echo "- [$name]($name/report.md)" >> "$index"
done
case $steps in *" bundle "*) has stability && has simulate && [ -r "$root/data/scenes/quad_bundle_gallop.ini" ] && { bash "$here/bundle_report.sh" "$bin" "$outroot" && echo "- [quad bundle beside a single conductor](bundle/report.md)" >> "$index" || status=1; } ;; esac
case $steps in *" sweep "*) has sweep && [ -r "$root/data/scenes/iced_gallop.ini" ] && { bash "$here/sweep_report.sh" "$bin" "$root/data/scenes/iced_gallop.ini" "$outroot" >&2 && echo "- [sweep](sweep/report.md)" >> "$index" || status=1; } ;; esac
exit $status
