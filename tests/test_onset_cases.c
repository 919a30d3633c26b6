/* test_onset_cases.c: the coupled onset analysis (issue 15) on the cases Den Hartog's criterion at
 * rest cannot see, each against the full model or a closed form:
 *   - data/scenes/crescent_condor.ini: Den Hartog stable at every angle; the coupled analysis
 *     predicts an onset, and the full model decays just below it and grows just above it;
 *   - data/scenes/condor_twisted.ini: Den Hartog unstable at rest (1.9 m/s); the mean wind twists
 *     the span past 60 deg to an angle the criterion calls stable; the coupled analysis says the
 *     span is stable again above some speed, and the full model gallops just below that speed and
 *     decays just above it;
 *   - torsional divergence on a table with dC_M/dalpha = -1 and no mean load: the speed where the
 *     aerodynamic torsional stiffness cancels GJ (pi/L0)^2 of the torsional string;
 *   - a fold of the twist path on a table whose moment grows faster than the twist: the speed
 *     against the one-term Galerkin solution of the twist equation. */
#include "check.h"
#include "gallop.h"
#include "gallop/analysis/onset.h"
#include "gallop/analysis/stability.h"
#include "gallop/run/sim.h"

static int setup(const char *scene, const char *const *ov, int n, gal_scene *sc, gal_sim_setup *s)
{
    int st = gal_scene_load(sc, scene, ov, n, NULL);
    if (!st) st = gal_sim_setup_init(s, sc, 1);
    CHECK(st == GAL_OK, "%s: %s", scene, gal_error_message());
    return st;
}

static int analyse(const char *scene, const char *const *ov, int n, double umin, double umax, double step, gal_onset *r)
{
    gal_scene sc;
    gal_sim_setup s;
    if (setup(scene, ov, n, &sc, &s)) return GAL_EFAIL;
    gal_onset_opts o;
    gal_onset_default_opts(&o);
    o.speed_min = umin, o.speed_max = umax, o.speed_step = step;
    double mass = sc.conductor.mass_per_length + sc.ice.mass_per_length;
    int st = gal_onset_analyse(s.data->eq.rod, s.data->eq.q, &s.data->loads, s.data->damping, mass, &o, r);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    gal_sim_setup_clear(&s);
    return st;
}

/* A full-model run of the scene at wind speed U: growth rate (1/s, slope of the log of 10-s
 * window maxima of the quarter-span vertical motion over the last two thirds) and the vertical
 * peak-to-peak (m) of its last 50 s. */
static int full_run(const char *scene, double U, double duration, double *growth, double *pp)
{
    char sp[64], du[64];
    snprintf(sp, sizeof sp, "wind.speed=%.6g", U);
    snprintf(du, sizeof du, "simulation.duration=%.6g", duration);
    const char *ov[] = {sp, du};
    gal_scene sc;
    gal_sim_setup s;
    gal_sim_result r;
    *growth = *pp = NAN;
    if (setup(scene, ov, 2, &sc, &s)) return GAL_EFAIL;
    int st = gal_sim_run(&s, GAL_MODEL_FULL, &r);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (!st && r.nsamples) {
        int np = r.nprobe, k = 1;
        long win = (long)(10.0 / r.dt_out), tail = (long)(50.0 / r.dt_out);
        double sx = 0, sy = 0, sxx = 0, sxy = 0, lo = INFINITY, hi = -INFINITY;
        int m = 0;
        for (long a = r.nsamples / 3; a + win <= r.nsamples; a += win, m++) {
            double mx = 0, mean = 0;
            for (long i = a; i < a + win; i++) mean += r.trace[(size_t)i * 4 * np + 4 * k + 1] / win;
            for (long i = a; i < a + win; i++) mx = fmax(mx, fabs(r.trace[(size_t)i * 4 * np + 4 * k + 1] - mean));
            double t = r.time[a + win / 2], y = log(mx);
            sx += t, sy += y, sxx += t * t, sxy += t * y;
        }
        for (long i = r.nsamples - tail; i < r.nsamples; i++) {
            double z = r.trace[(size_t)i * 4 * np + 4 * k + 1];
            lo = fmin(lo, z), hi = fmax(hi, z);
        }
        *growth = (m * sxy - sx * sy) / (m * sxx - sx * sx);
        *pp = hi - lo;
        gal_sim_result_clear(&r);
    }
    gal_sim_setup_clear(&s);
    return st;
}

/* Crescent ice: stable at every angle for Den Hartog, an onset for the coupled analysis, and the
 * full model on each side of it as predicted. */
static void test_crescent(void)
{
    const char *scene = "data/scenes/crescent_condor.ini";
    gal_aero_table *t = gal_aero_table_load("data/aero/iced_crescent.csv");
    CHECK(t != NULL, "%s", gal_error_message());
    if (!t) return;
    gal_stability_params p = {2.122, 0.003, 1.225, 0.02776, 15 * GAL_PI / 180, 0, NULL};
    gal_stability *S = gal_stability_sweep(t, &p);
    CHECK(S && S->nranges == 0, "Den Hartog: %d unstable ranges", S ? S->nranges : -1);
    gal_stability_free(S);
    gal_aero_table_free(t);
    gal_onset r;
    if (analyse(scene, NULL, 0, 0.5, 16, 0.5, &r)) return;
    double uc = r.onset_speed;
    printf("    (coupled onset %.4g m/s, %.4f Hz, shares %.2f/%.2f/%.2f)\n", uc, r.onset_frequency_hz, r.onset_share[0],
           r.onset_share[1], r.onset_share[2]);
    gal_onset_clear(&r);
    CHECK(uc > 5 && uc < 15, "onset %.4g m/s", uc);
    if (!isfinite(uc)) return;
    double g[2], pp[2];
    for (int k = 0; k < 2; k++) full_run(scene, uc * (k ? 1.1 : 0.9), 200, g + k, pp + k);
    printf("    (full model: growth rate %.3g 1/s at %.4g m/s, %.3g 1/s at %.4g m/s)\n", g[0], 0.9 * uc, g[1], 1.1 * uc);
    CHECK(g[0] < 0 && g[1] > 0, "growth rates %.3g below and %.3g above the onset", g[0], g[1]);
}

/* Condor, D-shape: Den Hartog at rest says 1.9 m/s and unstable above; the mean wind twists the
 * span to where the criterion says the opposite; stable again above restable_speed, as the full
 * model confirms on each side of it. */
static void test_condor_twisted(void)
{
    const char *scene = "data/scenes/condor_twisted.ini";
    gal_onset r;
    if (analyse(scene, NULL, 0, 0.5, 20, 0.5, &r)) return;
    const gal_onset_speed *lo = r.sp, *hi = r.sp + r.nspeed - 1;
    double ur = r.restable_speed;
    printf("    (Den Hartog at rest %.4g m/s; coupled onset %.4g m/s; stable again above %.4g m/s; at %.4g m/s twist "
           "%.1f deg, alpha %.1f deg, H %.3f)\n", lo->den_hartog_onset, r.onset_speed, ur, hi->speed, hi->twist_deg,
           hi->alpha_deg, hi->den_hartog);
    CHECK_NEAR(lo->den_hartog_onset, 1.9, 0.05);
    /* little twist at that speed: Den Hartog's, to 0.3% (1.8% high when the basis lacked the
     * antisymmetric torsional mode, the 34th natural mode of this span) */
    CHECK_REL(r.onset_speed, lo->den_hartog_onset, 3e-3);
    CHECK(hi->twist_deg > 60 && hi->den_hartog > 0, "twist %.1f deg, H %.3f", hi->twist_deg, hi->den_hartog);
    CHECK(ur > 10 && ur < 18, "stable again above %.4g m/s", ur);
    gal_onset_clear(&r);
    if (!isfinite(ur)) return;
    double g[2], pp[2];
    for (int k = 0; k < 2; k++) full_run(scene, ur * (k ? 1.1 : 0.9), 200, g + k, pp + k);
    printf("    (full model: vertical p-p %.3g m at %.4g m/s; growth rate %.3g 1/s, p-p %.3g m at %.4g m/s)\n", pp[0],
           0.9 * ur, g[1], pp[1], 1.1 * ur);
    CHECK(pp[0] > 1, "gallops below: vertical p-p %.3g m", pp[0]);
    CHECK(g[1] < 0 && pp[1] < 0.01 * pp[0], "decays above: growth rate %.3g, p-p %.3g m", g[1], pp[1]);
}

/* No mean load, dC_M/dalpha = -1: divergence where 1/2 rho U^2 d^2 = GJ (pi/L0)^2. */
static void test_divergence(void)
{
    const char *ov[] = {"ice.aero_table=tests/onset/divergence.csv", "ice.attack_angle=0"};
    gal_scene sc;
    gal_sim_setup s;
    if (setup("data/scenes/condor_twisted.ini", ov, 2, &sc, &s)) return;
    double L0 = 0;
    const gal_rod *rod = s.data->eq.rod;
    for (int j = 0; j < rod->p.elements; j++) L0 += rod->l0[j];
    double d = sc.conductor.diameter, GJ = sc.conductor.torsional_stiffness, rho = sc.wind.air_density;
    double ud = sqrt(GJ * GAL_PI * GAL_PI / (L0 * L0) / (0.5 * rho * d * d));
    gal_sim_setup_clear(&s);
    gal_onset r;
    if (analyse("data/scenes/condor_twisted.ini", ov, 2, 3, 6, 0.25, &r)) return;
    printf("    (divergence %.5g m/s, closed form %.5g m/s; fold %.4g)\n", r.divergence_speed, ud, r.fold_speed);
    CHECK_REL(r.divergence_speed, ud, 5e-3);
    CHECK(isnan(r.fold_speed), "a fold at %.4g m/s", r.fold_speed);
    CHECK(r.sp[r.nspeed - 1].kt_min < 0, "K_t still definite at %.3g m/s", r.sp[r.nspeed - 1].speed);
    gal_onset_clear(&r);
}

/* C_M = 0.05 - sin^3(alpha), alpha = -twist: the twist path folds. One-term Galerkin of
 * GJ th'' + q d^2 g(th) = 0, th = T sin(pi s/L0): q(T) = GJ (pi/L0)^2 T / (2 d^2 I(T)),
 * I(T) = (1/pi) int_0^pi g(T sin x) sin x dx; the fold at the first maximum of q(T). */
static void test_fold(void)
{
    const char *ov[] = {"ice.aero_table=tests/onset/fold.csv", "ice.attack_angle=0"};
    gal_scene sc;
    gal_sim_setup s;
    if (setup("data/scenes/condor_twisted.ini", ov, 2, &sc, &s)) return;
    double L0 = 0;
    const gal_rod *rod = s.data->eq.rod;
    for (int j = 0; j < rod->p.elements; j++) L0 += rod->l0[j];
    double d = sc.conductor.diameter, GJ = sc.conductor.torsional_stiffness, rho = sc.wind.air_density;
    gal_sim_setup_clear(&s);
    double qmax = 0;
    for (double T = 0.001; T < 1.5; T += 0.001) {
        double I = 0;
        for (int i = 0; i < 400; i++) {
            double x = (i + 0.5) * GAL_PI / 400, th = T * sin(x);
            I += (0.05 + pow(sin(th), 3)) * sin(x) / 400;
        }
        double q = GJ * GAL_PI * GAL_PI / (L0 * L0) * T / (2 * d * d * I);
        if (q < qmax) break;
        qmax = q;
    }
    double uf = sqrt(2 * qmax / rho);
    gal_onset r;
    if (analyse("data/scenes/condor_twisted.ini", ov, 2, 0.5, 12, 0.5, &r)) return;
    int i = 0;
    while (i < r.nspeed && !r.sp[i].fold) i++;
    printf("    (fold %.5g m/s, Galerkin %.5g m/s; twist %.1f -> %.1f deg across it)\n", r.fold_speed, uf,
           i > 0 && i < r.nspeed ? r.sp[i - 1].twist_deg : NAN, i < r.nspeed ? r.sp[i].twist_deg : NAN);
    CHECK_REL(r.fold_speed, uf, 1e-2);
    CHECK(i > 0 && i < r.nspeed && r.sp[i - 1].speed < r.fold_speed && r.sp[i].speed > r.fold_speed,
          "the fold flag at row %d", i);
    if (i > 0 && i < r.nspeed)
        CHECK(r.sp[i].twist_deg - r.sp[i - 1].twist_deg > 45, "the twist jumps %.3g deg", r.sp[i].twist_deg - r.sp[i - 1].twist_deg);
    CHECK(isnan(r.divergence_speed), "divergence at %.4g m/s", r.divergence_speed);
    gal_onset_clear(&r);
}

int main(void)
{
    RUN(test_divergence);
    RUN(test_fold);
    RUN(test_crescent);
    RUN(test_condor_twisted);
    return CHECK_SUMMARY();
}
