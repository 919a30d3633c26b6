#!/usr/bin/env bash
# test_report.sh: smoke test of notebooks-free-reports/ (make_report.sh, plot_scene.sh, the JSON
# reader). Runs by tests/run.sh with GALLOP = the built binary; ends with "#summary P F".
#  1. plot_scene.sh on a made-up output directory (fixture.sh): report.md and every figure.
#  2. jflat (jq) / jfind: nested keys, preferences, arrays.
#  3. make_report.sh with a stand-in gallop that has only some commands: the missing ones are
#     noted, not errors; REPORT_SET, REPORT_DURATION and the GJ factors reach the command lines.
#  4. make_report.sh with the real binary: if it has `gallop modes` and data/scenes has a scene,
#     on that scene with 20 elements (equilibrium and mode-shape figures); else on a made-up scene
#     (everything skipped with notes, exit status 0).
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
rep=$root/notebooks-free-reports
tmp=$(mktemp -d "${TMPDIR:-/tmp}/test_report.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
passed=0; failed=0
t_start=$(date +%s)

ok() { passed=$((passed + 1)); echo "  ok   $1"; }
fail() { failed=$((failed + 1)); echo "  FAIL $1"; [ $# -gt 1 ] && printf '    %s\n' "${@:2}"; }
# check NAME COMMAND...: passes if the command succeeds
check() { local n=$1; shift; if "$@" > "$tmp/check.out" 2>&1; then ok "$n"; else fail "$n" "$(tail -n 5 "$tmp/check.out")"; fi; }
# png FILE: exists, non-empty, PNG signature
png() { [ -s "$1" ] && [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ]; }
has_gnuplot=0; command -v gnuplot >/dev/null 2>&1 && has_gnuplot=1

# ---- 1. plot_scene.sh on fixtures ----
fx=$tmp/fixture/demo
bash "$rep/fixture.sh" "$fx"
check "plot_scene.sh on the fixture exits 0" bash "$rep/plot_scene.sh" "$fx" demo
check "report.md written" test -s "$fx/report.md"
for sec in "Static equilibrium" "Natural modes" "Full model" "Reduced model" "Full against reduced" \
           "Accuracy against time" "Torsional stiffness study"; do
    check "report.md has section: $sec" grep -q "^##.*$sec" "$fx/report.md"
done
check "mode table lists the 7 selected modes and no unselected one" \
    test "$(grep -cE '^\| [0-9]+ \| (vertical|horizontal|torsional|axial) \|' "$fx/report.md")" -eq 7
check "torsion table has 4 rows" test "$(grep -cE '^\| (0\.5|1|2|4) \| [0-9]' "$fx/report.md")" -eq 4
check "compare table shows the speedup" grep -q '^| speedup | 46.7 |' "$fx/report.md"
check "report.md has the CIGRE TB 322 outputs of each run" test "$(grep -c '^#### CIGRE TB 322 outputs' "$fx/report.md")" -eq 2
check "CIGRE: support tensions with the rated strength and max / RTS" grep -q '^| 20000 | 69390 | 30000 | 2.313 | 138780 | 0.5 |$' "$fx/report.md"
check "CIGRE: the clearance to the neighbouring phase" grep -q '^| 0.25 | 0 | 4 | 1.5 |$' "$fx/report.md"
# md_tables FILE: every Markdown table row has as many cells as its header (escaped \| aside)
md_tables() {
    awk '{ l = $0; gsub(/\\\|/, "", l) }
         /^\|/ { n = gsub(/\|/, "|", l) - 1; if (!intable) { intable = 1; h = n } else if (n != h) { print FILENAME ":" NR ": " n " cells, header " h; bad = 1 } next }
         { intable = 0 }
         END { exit bad }' "$1"
}
check "every Markdown table of the fixture's report is well formed" md_tables "$fx/report.md"
if [ $has_gnuplot = 1 ]; then
    for f in equilibrium modes_vertical modes_horizontal modes_torsional trace_full orbit_full psd_full \
             trace_reduced orbit_reduced psd_reduced compare_traces compare_orbits accuracy torsion_envelope; do
        check "figure $f.png made and linked" sh -c "$(declare -f png); png '$fx/fig/$f.png' && grep -q 'fig/$f.png' '$fx/report.md'"
    done
    check "no gnuplot warnings" sh -c "! grep -qi 'warning\|error' '$fx/fig/gnuplot.log'"
else
    echo "  (gnuplot not installed: figures not checked)"
fi
# a directory with modes only: other sections left out, no failure
mo=$tmp/modes_only/x
mkdir -p "$mo" && cp -r "$fx/modes" "$mo/"
check "plot_scene.sh on modes only exits 0" bash "$rep/plot_scene.sh" "$mo"
check "modes only: no simulation section" sh -c "! grep -q 'Galloping simulations' '$mo/report.md'"
check "plot_scene.sh without a directory: exit 2" sh -c "bash '$rep/plot_scene.sh' '$tmp/none' 2>/dev/null; test \$? -eq 2"

# ---- 2. the JSON reader ----
. "$rep/lib.sh"
cat > "$tmp/s.json" <<'EOF'
{
  "wall_time_s": 1.5,
  "frequencies": [
    0.25,
    0.5
  ],
  "p0.25_vertical_m": {
    "peak_to_peak": 1.1,
    "time_to_steady_s": null
  },
  "p0.5_vertical_m": {"peak_to_peak": 2.2, "time_to_steady_s": 31.5},
  "name": "a \"quoted\" b"
}
EOF
check "jfind top level" test "$(jfind "$tmp/s.json" wall_time_s)" = 1.5
check "jfind nested, first match" test "$(jfind "$tmp/s.json" peak_to_peak)" = 1.1
check "jfind nested, preferred path" test "$(jfind "$tmp/s.json" peak_to_peak p0.5_)" = 2.2
check "jfind skips null" test "$(jfind "$tmp/s.json" time_to_steady_s)" = 31.5
check "jfind array element" test "$(jfind "$tmp/s.json" frequencies.1)" = 0.5
check "jfind string with quotes" test "$(jfind "$tmp/s.json" name)" = 'a "quoted" b'
check "jfind missing key is empty" test -z "$(jfind "$tmp/s.json" nothing)"
check "csv_col by name" test "$(csv_col "$fx/modes/modes.csv" frequency_hz)" = 4

# ---- 3. make_report.sh with a stand-in gallop (modes, simulate, check; no compare, accuracy) ----
stub=$tmp/stub
mkdir -p "$stub"
cat > "$stub/gallop" <<EOF
#!/usr/bin/env bash
# stand-in for gallop: copies fixture outputs, logs its command lines
echo "\$*" >> "$stub/calls.log"
case \$1 in
  help) printf 'usage: gallop COMMAND [ARGS]\n\ncommands:\n  gallop version   v\n  gallop modes SCENE [-o DIR]   m\n  gallop simulate SCENE [--model reduced|full] [-o DIR]  s\n  gallop check SCENE   c\n'; exit 0 ;;
  check) printf '[span]\nlength = 300\n\n[conductor]\ndiameter = 0.028 ; m\ntorsional_stiffness = 150\n'; exit 0 ;;
esac
o=; m=
while [ \$# -gt 0 ]; do case \$1 in -o) o=\$2; shift ;; --model) m=\$2 ;; esac; shift; done
mkdir -p "\$o"
if [ -z "\$m" ]; then cp "$fx"/modes/* "\$o"/; else cp "$fx/\$m"/* "\$o"/; fi
EOF
chmod +x "$stub/gallop"
printf '[span]\nlength = 300\n' > "$tmp/tiny.ini"
REPORT_OUT=$tmp/out REPORT_SET="model.elements=20 wind.speed=12" REPORT_DURATION=7 \
    bash "$rep/make_report.sh" "$stub" "$tmp/tiny.ini" > "$tmp/stub.out" 2>&1
rc=$?
r=$tmp/out/tiny/report.md
check "stand-in: make_report.sh exits 0 (status $rc)" test $rc -eq 0
check "stand-in: report.md written" test -s "$r"
check "stand-in: index.md links the scene" grep -q 'tiny/report.md' "$tmp/out/index.md"
check "stand-in: missing compare noted" grep -q 'gallop compare` is not in this build' "$r"
check "stand-in: missing accuracy noted" grep -q 'gallop accuracy` is not in this build' "$r"
check "stand-in: REPORT_SET reaches modes" grep -q '^modes .*--set model.elements=20 --set wind.speed=12 -o ' "$stub/calls.log"
check "stand-in: REPORT_DURATION reaches simulate" grep -q '^simulate .*--model full .*--set simulation.duration=7 ' "$stub/calls.log"
check "stand-in: GJ x 0.5 from gallop check" grep -q 'conductor.torsional_stiffness=75 -o .*/torsion/gj_0.5' "$stub/calls.log"
check "stand-in: GJ x 4 from gallop check" grep -q 'conductor.torsional_stiffness=600 -o .*/torsion/gj_4' "$stub/calls.log"
check "stand-in: resolved scene in the report" grep -q 'torsional_stiffness = 150' "$r"
if [ $has_gnuplot = 1 ]; then
    for f in equilibrium modes_vertical trace_full trace_reduced torsion_envelope; do
        check "stand-in: figure $f.png" sh -c "$(declare -f png); png '$tmp/out/tiny/fig/$f.png'"
    done
fi
check "make_report.sh without a binary: exit 2" sh -c "bash '$rep/make_report.sh' '$tmp/nothing' 2>/dev/null; test \$? -eq 2"

# ---- 4. the real binary ----
if [ -n "${GALLOP:-}" ] && [ -x "$GALLOP" ]; then
    scene=
    for s in "$root/data/scenes/drake_300m.ini" "$root"/data/scenes/*.ini; do [ -e "$s" ] && { scene=$s; break; }; done
    if "$GALLOP" help 2>&1 | grep -Eq '^[[:space:]]+(gallop[[:space:]]+)?modes([[:space:]]|$)' && [ -n "$scene" ]; then
        name=$(basename "$scene" .ini)
        REPORT_OUT=$tmp/real REPORT_STEPS=modes REPORT_SET="model.elements=20" REPORT_TIMEOUT=25 \
            bash "$rep/make_report.sh" "$GALLOP" "$scene" > "$tmp/real.out" 2>&1
        rc=$?
        check "real gallop ($name, 20 elements): make_report.sh exits 0 (status $rc)" test $rc -eq 0
        check "real gallop: report.md" test -s "$tmp/real/$name/report.md"
        check "real gallop: modes/summary.json" test -s "$tmp/real/$name/modes/summary.json"
        if [ $has_gnuplot = 1 ]; then
            for f in equilibrium modes_vertical; do
                check "real gallop: figure $f.png" sh -c "$(declare -f png); png '$tmp/real/$name/fig/$f.png'"
            done
        fi
        [ $rc -eq 0 ] || sed 's/^/    /' "$tmp/real.out" | tail -n 20
    else
        REPORT_OUT=$tmp/real bash "$rep/make_report.sh" "$GALLOP" "$tmp/tiny.ini" > "$tmp/real.out" 2>&1
        rc=$?
        check "real gallop without modes (or no scene): make_report.sh exits 0 (status $rc)" test $rc -eq 0
        check "real gallop without modes: report.md says modes is missing" \
            grep -q 'gallop modes` is not in this build' "$tmp/real/tiny/report.md"
    fi
else
    echo "  (GALLOP not set: the real binary is not tried)"
fi

echo "  ($(( $(date +%s) - t_start )) s)"
echo "#summary $passed $failed"
[ $failed -eq 0 ]
