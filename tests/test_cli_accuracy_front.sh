#!/usr/bin/env bash
# test_cli_accuracy_front.sh: the front study of `gallop accuracy` on a scene with a known answer:
# a taut string (gravity off, a small step of drag, no damping, no aerodynamic damping) swings
# freely in its first horizontal mode, f = 1/(2L) sqrt(H/m). The lumped-mass string of N
# elements has w_N = (2N c / L) sin(pi / 2N), c = sqrt(H/m), and the generalized-alpha step with
# rho_inf = 1 (the trapezoidal rule) turns w into (2/h) atan(w h / 2): the true frequency error of
# every (N, h) is known in closed form. The study's reported errors (against its own converged,
# extrapolated reference) must match the true ones within a factor of 2; the configuration it
# recommends must meet its tolerance, by the closed form and by its check run; the reference must
# report its own estimated error; --budget must stop the study early and say so.
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
scratch cli_accfront
cp "$here/cli/taut_string.ini" "$tmp/string.ini"
E=0.02
if "$GALLOP" accuracy "$tmp/string.ini" --tolerance $E -o "$tmp/a" >"$tmp/out" 2>"$tmp/err"; then
  ok "accuracy (front) exits 0"
else
  bad "accuracy (front): exit $?: $(cat "$tmp/err")"
fi
c=$tmp/a/front.csv
hdr='label,group,model,elements,modes,time_step_s,effect_off,error_frequency,error_vertical,error_horizontal,error_twist,error_tension,error_time_to_steady,error,wall_time_s,on_front,chosen,newton_tolerance,newton_iterations'
[ "$(head -n 1 "$c" 2>/dev/null)" = "$hdr" ] && ok "front.csv header" || bad "front.csv header: $(head -n 1 "$c" 2>/dev/null)"
# the reported frequency error of every full-model configuration against the closed form (not of
# a reduced one: it halves its step where its Newton fails; tests/test_accuracy.c holds those to
# string theory); counted: the deterministic stages (the combined ones depend on wall times)
awk -F, -v L=100 -v H=20000 -v m=1 'function atan(x) { return atan2(x, 1) }
  NR > 1 && $7 == "" && $3 == "full" && $8 != "nan" && $8 != "inf" {
    pi = atan2(0, -1); c = sqrt(H / m); w = pi * c / L; N = $4; h = $6
    wN = 2 * N * c / L * sin(pi / (2 * N)); wb = 2 / h * atan(wN * h / 2); t = 1 - wb / w
    if (t < 0) t = -t
    if (t < 1e-3) next                    # below what a 30 s spectrum resolves
    n += ($2 != "combined"); r = $8 / t
    if (r < 0.5 || r > 2) { bad++; printf "    %s: reported %.4g, true %.4g\n", $1, $8, t }
  }
  END { printf "%d %d\n", n, bad; exit !(n >= 7 && bad == 0) }' "$c" >"$tmp/fq" \
  && ok "reported frequency errors within a factor 2 of the closed form ($(tail -n 1 "$tmp/fq" | cut -d' ' -f1) configurations)" \
  || bad "frequency errors against the closed form: $(cat "$tmp/fq")"
# the element order is 2 and the time step's order is 2: halving both divides the error by ~4
awk -F, 'NR > 1 && $2 == "refine" { e[++n] = $8 } END { exit !(n >= 1) }' "$c" && ok "reference refinement levels listed" \
  || bad "no refinement rows"
j=$tmp/a/summary.json
python3 - "$j" "$E" <<'PY' && ok "reference converged with its estimated error; the chosen configuration meets the tolerance (closed form and check run)" || bad "summary: see above"
import json, math, sys
d = json.load(open(sys.argv[1])); E = float(sys.argv[2]); f = d["front"]; r = f["reference"]
def fail(msg): print("    " + msg); sys.exit(1)
if not r["converged"]: fail("reference not converged: %s" % r)
ee = r["estimated_error"]["frequency"]
if not (ee is not None and 0 <= ee < E / 10): fail("reference frequency error estimate %s" % ee)
fs = math.sqrt(20000 / 1.0) / 200
fr = r["values"]["frequency"]
if abs(fr - fs) / fs > E / 10: fail("reference frequency %g against string theory %g" % (fr, fs))
ch, chk = f["chosen"], f["check"]
if not ch or not chk: fail("no chosen configuration or no check")
if not (chk["error"] <= E): fail("check run error %s > %g" % (chk["error"], E))
if chk["label"] != ch["label"]: fail("check ran %s, chose %s" % (chk["label"], ch["label"]))
# the chosen configuration's true frequency error: its frequency against string theory, and for
# the full model the closed form of its mesh and step
t = abs(ch["values"]["frequency"] / fs - 1)
if t > E: fail("chosen %s: frequency %g Hz, %g off string theory > %g" % (ch["label"], ch["values"]["frequency"], t, E))
lab = ch["label"].split(); N = int(lab[-2][2:]); h = float(lab[-1][2:])
w = math.pi * math.sqrt(20000) / 100; wN = 2 * N * math.sqrt(20000) / 100 * math.sin(math.pi / (2 * N))
t = abs(1 - 2 / h * math.atan(wN * h / 2) / w)
if lab[0] == "full" and t > E: fail("chosen %s: true frequency error %g > %g" % (ch["label"], t, E))
# the cheapest within E: no point within E is cheaper
for p in f["points"]:
    if p["group"] != "effect" and p["error"] is not None and p["error"] <= E and p["wall_time_s"] < ch["wall_time_s"]:
        fail("%s is within E and cheaper than the chosen one" % p["label"])
if not f["front"]: fail("empty front")
PY
# the integrator tolerance (simulation.newton_tolerance) is a choice of the study, for both models:
# listed with its error and its Newton work; in the full model the loosest does less Newton work than
# the tightest (not asserted of the reduced model: there the tolerance also moves when its basis grows,
# and a different basis changes the run's length in iterations more than the tolerance does)
python3 - "$j" <<'PY' && ok "newton_tolerance rows of both models: errors listed; full model: 1e-3 does less Newton work than 1e-10" || bad "newton_tolerance rows: see above"
import json, math, sys
f = json.load(open(sys.argv[1]))["front"]
def fail(msg): print("    " + msg); sys.exit(1)
if f.get("base_newton_tolerance") != 1e-8: fail("base_newton_tolerance %s" % f.get("base_newton_tolerance"))
for model in ("full", "reduced"):
    pts = {p["newton_tolerance"]: p for p in f["points"] if p["group"] == "newton_tolerance" and p["label"].startswith(model)}
    if sorted(pts) != [1e-10, 1e-6, 1e-4, 1e-3]: fail("%s: tolerances %s" % (model, sorted(pts)))
    for t, p in pts.items():
        if "failed" in p or p["error"] is None or not math.isfinite(p["error"]): fail("%s tol %g: error %s" % (model, t, p.get("error")))
        if not ("tol=%.3g" % t) in p["label"]: fail("label %s" % p["label"])
    if model == "full" and not (0 < pts[1e-3]["newton_iterations"] < pts[1e-10]["newton_iterations"]):
        fail("%s: Newton iterations %d at 1e-3, %d at 1e-10" % (model, pts[1e-3]["newton_iterations"], pts[1e-10]["newton_iterations"]))
PY
awk -F, 'NR > 1 && $2 == "newton_tolerance" && $18 == 0.001 && $19 > 0' "$c" | grep -q . \
  && ok "front.csv: newton_tolerance and newton_iterations columns" || bad "front.csv newton columns"
grep -q "tol=0.001 N=" "$tmp/out" && ok "the table lists the tolerance rows" || bad "no tolerance rows in the table"
grep -q "tolerance 2%: [a-z]* .*N=" "$tmp/out" && grep -q "check run reached an error of" "$tmp/out" \
  && ok "stdout states the chosen configuration, its error and time" || bad "stdout: $(tail -n 5 "$tmp/out")"
# drag off: the string does not move, every measure is lost: never recommended off
grep -q "aero_drag: keep on" "$tmp/out" && ok "drag is kept on" || bad "effects: $(grep effects: "$tmp/out")"
# a budget too small for the study stops it early and says so
"$GALLOP" accuracy "$tmp/string.ini" --tolerance $E --budget 0.001 -o "$tmp/b" >"$tmp/out2" 2>"$tmp/err2"
rc=$?
n1=$(($(wc -l <"$c") - 1)); n2=$(($(wc -l <"$tmp/b/front.csv" 2>/dev/null || echo 1) - 1))
[ $rc -eq 0 ] && [ "$n2" -lt "$n1" ] && grep -q "budget" "$tmp/b/summary.json" \
  && ok "--budget 0.001: $n2 of $n1 configurations, the summary says the budget stopped it" || bad "--budget: exit $rc, $n2 of $n1: $(cat "$tmp/err2")"
grep -q "accuracy: front" "$tmp/err2" && ok "--budget: progress on stderr" || bad "--budget: no progress on stderr"
for args in "--budget -1" "--seeds 0" "--levels 9" "--seeds 1.5"; do
  # shellcheck disable=SC2086
  "$GALLOP" accuracy "$tmp/string.ini" $args -o "$tmp/bad" >/dev/null 2>"$tmp/err"
  rc=$?
  [ $rc -eq 2 ] && [ -s "$tmp/err" ] && ok "bad input '$args': exit 2" || bad "'$args': exit $rc"
done
finish
