#!/usr/bin/env bash
# fixture.sh OUTDIR: writes a made-up scene output directory (modes/, full/, reduced/, compare/,
# accuracy/, torsion/) in the formats that gallop writes, so that plot_scene.sh can be tried and
# tested without the solver. The numbers are synthetic (a catenary, sine mode shapes, a growing
# limit cycle); they are not results of gallop.
set -eu
out=${1:?usage: fixture.sh OUTDIR}
mkdir -p "$out"/modes "$out"/full "$out"/reduced "$out"/compare "$out"/accuracy "$out"/torsion

# ---- modes: a level 300 m span, H = 30 kN, m = 1.6 kg/m, 20 elements ----
awk -v L=300 -v H=30000 -v m=1.6 -v n=20 -v dir="$out/modes" 'BEGIN {
    g = 9.81; a = H / (m * g); pi = atan2(0, -1)
    f = dir "/equilibrium.csv"
    print "node,s_m,x_m,y_m,z_m,twist_rad,tension_n" > f
    s = 0; xp = 0; zp = 0
    for (i = 0; i <= n; i++) {
        x = L * i / n; u = (x - L / 2) / a
        z = a * (cosh(u) - cosh(L / (2 * a)))
        if (i > 0) s += sqrt((x - xp) ^ 2 + (z - zp) ^ 2)
        printf "%d,%.9g,%.9g,0,%.9g,0,%.9g\n", i, s, x, z, H * cosh(u) > f
        xp = x; zp = z; Z[i] = z
    }
    sag = -Z[n / 2]
    f = dir "/modes.csv"
    print "index,family,symmetry,frequency_hz,period_s,share_vertical,share_horizontal,share_torsional,share_axial,selected" > f
    nm = split("horizontal vertical vertical horizontal vertical torsional torsional axial", fam, " ")
    split("symmetric antisymmetric symmetric antisymmetric symmetric symmetric antisymmetric symmetric", sym, " ")
    split("0.2258 0.4516 0.4812 0.4516 0.6774 0.95 1.9 6.2", fr, " ")
    split("1 2 1 2 3 1 2 1", order, " ")
    for (k = 1; k <= nm; k++) {
        sv = fam[k] == "vertical"; sh = fam[k] == "horizontal"; st = fam[k] == "torsional"; sa = fam[k] == "axial"
        printf "%d,%s,%s,%.9g,%.9g,%.6f,%.6f,%.6f,%.6f,%d\n", k, fam[k], sym[k], fr[k], 1 / fr[k],
               sv * 0.98 + 0.01, sh * 0.98 + 0.01, st * 0.97 + 0.005, sa * 0.98 + 0.005, !sa > f
    }
    f = dir "/shapes.csv"
    print "mode,family,frequency_hz,node,x_m,z_m,ux,uy,uz,twist" > f
    for (k = 1; k <= nm; k++) {
        if (fam[k] == "axial") continue
        for (i = 0; i <= n; i++) {
            x = L * i / n; v = 0.0645 * sin(order[k] * pi * x / L)
            ux = 0; uy = 0; uz = 0; tw = 0
            if (fam[k] == "vertical") uz = v; else if (fam[k] == "horizontal") uy = v; else tw = 4 * v
            printf "%d,%s,%.9g,%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", k, fam[k], fr[k], i, x, Z[i], ux, uy, uz, tw > f
        }
        printf "\n\n" > f
    }
    f = dir "/summary.json"
    printf "{\n  \"command\": \"modes\",\n  \"scene\": \"fixture.ini\",\n  \"sag_m\": %.10g,\n", sag > f
    printf "  \"horizontal_tension_n\": %.10g,\n  \"unstretched_length_m\": %.10g,\n", H, s - 0.4 > f
    printf "  \"elements\": %d,\n  \"dofs\": %d,\n  \"newton_iterations\": 5,\n  \"wall_time_s\": 0.012,\n", n, 4 * n - 4 > f
    printf "  \"frequencies\": [\n" > f
    first = 1
    for (k = 1; k <= nm; k++) if (fam[k] != "axial") { printf "%s    %g", first ? "" : ",\n", fr[k] > f; first = 0 }
    printf "\n  ],\n  \"modes\": [\n" > f
    first = 1
    for (k = 1; k <= nm; k++) {
        if (fam[k] == "axial") continue
        printf "%s    {\n      \"index\": %d,\n      \"family\": \"%s\",\n      \"symmetry\": \"%s\",\n      \"frequency_hz\": %g\n    }",
               first ? "" : ",\n", k, fam[k], sym[k], fr[k] > f
        first = 0
    }
    printf "\n  ]\n}\n" > f
}
function cosh(u) { return (exp(u) + exp(-u)) / 2 }'

# ---- a mid-span trace that grows into a limit cycle: TRACE DIR F AMP TSTEADY WALL ----
trace() {
    awk -v dir="$1" -v f0="$2" -v A="$3" -v ts="$4" -v wall="$5" 'BEGIN {
        pi = atan2(0, -1); dt = 0.05; T = 60
        f = dir "/trace.csv"
        print "time_s,p0.5_horizontal_m,p0.5_vertical_m,p0.5_along_m,p0.5_twist_deg,p0.25_horizontal_m,p0.25_vertical_m,p0.25_along_m,p0.25_twist_deg,tension_left_n,tension_right_n" > f
        for (i = 0; i <= T / dt; i++) {
            t = i * dt; a = A / (1 + exp(-(t - ts / 2) / (ts / 10))); w = 2 * pi * f0 * t
            v = a * sin(w); h = 0.25 * a * sin(w + 1.1) + 0.3 * (1 - exp(-t / 3)); tw = 6 * a * sin(w + 0.6)
            printf "%.4f,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", t, h, v, 0.01 * a * sin(2 * w), tw,
                   0.7 * h, 0.7 * v, 0, 0.7 * tw, 30500 + 3000 * a * sin(2 * w), 30500 + 2900 * a * sin(2 * w + 0.1) > f
        }
        f = dir "/psd.csv"
        print "frequency_hz,p0.5_horizontal_m2_per_hz,p0.5_vertical_m2_per_hz,p0.5_twist_deg2_per_hz" > f
        for (i = 0; i <= 200; i++) {
            x = i * 0.025; L = 1 / (1 + ((x - f0) / 0.02) ^ 2) + 1e-4 / (1 + x * x)
            printf "%.4f,%.6g,%.6g,%.6g\n", x, 0.06 * A * A * L, A * A * L, 36 * A * A * L > f
        }
        f = dir "/summary.json"
        printf "{\n  \"command\": \"simulate\",\n  \"wall_time_s\": %g,\n  \"frequency_hz\": %g,\n", wall, f0 > f
        printf "  \"amplitude_m\": %g,\n  \"time_to_steady_s\": %g,\n  \"steps\": 1200,\n", 2 * A, ts > f
        printf "  \"p0.5_vertical_m\": {\n    \"peak_frequency_hz\": %g,\n    \"peak_to_peak\": %g,\n    \"rms\": %g\n  },\n", f0, 2 * A, A / sqrt(2) > f
        # the CIGRE TB 322 members of gallop simulate (output/cigrereport.h), made up
        printf "  \"probes\": [{\"position\": 0.25, \"ellipse\": {\"major_peak_to_peak_m\": %g, \"minor_peak_to_peak_m\": %g, \"tilt_deg\": 85, \"centre_horizontal_m\": 0.2, \"centre_vertical_m\": 0.1, \"from_s\": %g},\n    \"clearances\": [{\"neighbour_horizontal_m\": 0, \"neighbour_vertical_m\": 4, \"clearance_m\": 1.5}]}],\n", 2 * A, 0.1 * A, ts > f
        printf "  \"support_tensions\": {\"min_n\": 20000, \"max_n\": 69390, \"static_n\": 30000, \"max_over_static\": 2.313, \"rated_strength_n\": 138780, \"max_over_rated_strength\": 0.5, \"over\": \"both supports\"},\n" > f
        printf "  \"cigre_envelope\": {\"formula\": \"A/D = 80 ln(L/(500 D))\", \"source\": \"made up\", \"span_over_diameter\": 10661, \"envelope_peak_to_peak_m\": 6.92, \"simulated_peak_to_peak_m\": %g, \"simulated_over_envelope\": %g}\n}\n", 2 * A, 2 * A / 6.92 > f
    }'
}
trace "$out/full" 0.4812 1.50 30 42.0
trace "$out/reduced" 0.4850 1.44 28 0.9

# ---- compare: the two traces side by side ----
paste -d, "$out/full/trace.csv" "$out/reduced/trace.csv" | awk -F, 'NR == 1 {
        print "time_s,full_vertical_m,reduced_vertical_m,full_horizontal_m,reduced_horizontal_m,full_twist_deg,reduced_twist_deg"; next }
    { printf "%s,%s,%s,%s,%s,%s,%s\n", $1, $3, $14, $2, $13, $5, $16 }' > "$out/compare/compare.csv"
cat > "$out/compare/summary.json" <<'JSON'
{
  "command": "compare",
  "full": {
    "frequency_hz": 0.4812,
    "amplitude_m": 3.0,
    "wall_time_s": 42.0
  },
  "reduced": {
    "frequency_hz": 0.485,
    "amplitude_m": 2.88,
    "wall_time_s": 0.9
  },
  "frequency_error": 0.0079,
  "amplitude_error": -0.04,
  "speedup": 46.7
}
JSON

# ---- accuracy: four studies, the cheapest setting under 2 % marked ----
cat > "$out/accuracy/accuracy.csv" <<'CSV'
study,setting,value,error,wall_time_s,chosen
elements,20,2.71,0.097,0.4,0
elements,50,2.86,0.047,1.1,0
elements,100,2.95,0.017,2.3,1
elements,200,2.99,0.004,5.0,0
modes,3,2.60,0.13,0.3,0
modes,5,2.91,0.03,0.6,0
modes,7,2.97,0.011,0.9,1
modes,9,2.99,0.004,1.4,0
time_step,0.05,2.80,0.066,0.5,0
time_step,0.02,2.95,0.017,1.2,1
time_step,0.01,2.99,0.005,2.4,0
time_step,0.005,3.00,0.001,4.9,0
effects,all,3.00,0.0,2.3,0
effects,no_bending,2.98,0.006,2.1,1
effects,no_torsion,2.10,0.30,1.5,0
CSV

# ---- torsional stiffness study ----
printf 'factor,torsional_stiffness_n_m2_per_rad,directory,status\n' > "$out/torsion/study.csv"
for fac in 0.5 1 2 4; do
    d="$out/torsion/gj_$fac"; mkdir -p "$d"
    read -r f0 A ts <<<"$(awk -v k="$fac" 'BEGIN { printf "%g %g %g", 0.48 + 0.003 * k, 1.8 / (1 + 0.25 * k), 20 + 8 * k }')"
    trace "$d" "$f0" "$A" "$ts" 0.9
    printf '%s,%s,gj_%s,ok\n' "$fac" "$(awk -v k="$fac" 'BEGIN { printf "%g", 150 * k }')" "$fac" >> "$out/torsion/study.csv"
done
