/* test_sim.c: galloping runs of scenes (issues 5 and 6): the dynamic blow-out settles on the
 * static solution; a Den Hartog stable section decays, an unstable one grows and settles on a
 * limit cycle; the reduced model against the full one on a galloping span; the paper's finding
 * that a larger torsional stiffness GJ delays steady galloping and lowers its vertical amplitude. */
#include "check.h"
#include "gallop.h"
#include "gallop/loads/loads.h"
#include "gallop/scene/scene.h"
#include "gallop/run/sim.h"
#include "gallop/output/simreport.h"

static int load(gal_scene *sc, const char *path, const char *const *ov, int n)
{
    int st = gal_scene_load(sc, path, ov, n, NULL);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    return st;
}

/* Drag only, heavy damping: the full model comes to rest on the static blow-out. */
static void test_dynamic_blowout_matches_statics(void)
{
    gal_scene sc;
    const char *ov[] = {"model.elements=20", "effects.aero_lift=off", "effects.aero_moment=off",
                        "conductor.damping_ratio=0.3", "wind.speed=15", "simulation.duration=60",
                        "simulation.wind_ramp=5"};
    if (load(&sc, "data/scenes/iced_gallop.ini", ov, 7)) return;
    gal_sim_setup s;
    CHECK(gal_sim_setup_init(&s, &sc, 1) == GAL_OK, "%s", gal_error_message());
    gal_sim_result r;
    CHECK(gal_sim_run(&s, GAL_MODEL_FULL, &r) == GAL_OK, "%s", gal_error_message());
    /* static solution under the same mean drag */
    int nq = s.data->eq.rod->nq, it = 0;
    double *q = malloc(nq * sizeof(double));
    memcpy(q, s.data->eq.q, nq * sizeof(double));
    CHECK(gal_loads_static(s.data->eq.rod, q, &s.data->loads, 1e-6, 50, &it) == GAL_OK, "%s", gal_error_message());
    int mid = s.data->eq.rod->nn / 2, k = gal_sim_mid_probe(&r);
    double ys = q[3 * mid + 1] - s.data->eq.q[3 * mid + 1], zs = q[3 * mid + 2] - s.data->eq.q[3 * mid + 2];
    const double *last = r.trace + (size_t)(r.nsamples - 1) * 4 * r.nprobe + 4 * k;
    printf("    (mid-span blow-out: dynamic %.5f m across, %.5f m up; static %.5f, %.5f)\n", last[0], last[1], ys, zs);
    CHECK_REL(last[0], ys, 1e-2);
    CHECK_NEAR(last[1], zs, 1e-2 * fabs(ys));
    free(q);
    gal_sim_result_clear(&r);
    gal_sim_setup_clear(&s);
}

/* simulation.start = mean_wind: the run starts on the equilibrium under the mean wind, so it starts
 * at rest there: no blow-out transient (the rest start swings by centimetres). */
static void test_start_from_mean_wind(void)
{
    double swing[2], y0[2];
    for (int k = 0; k < 2; k++) {
        gal_scene sc;
        const char *ov[] = {"model.elements=20", "simulation.duration=20", "effects.aero_lift=off",
                            k ? "simulation.start=mean_wind" : "simulation.start=rest"};
        if (load(&sc, "data/scenes/iced_gallop.ini", ov, 4)) return;
        gal_sim_setup s;
        CHECK(gal_sim_setup_init(&s, &sc, 1) == GAL_OK, "%s", gal_error_message());
        gal_sim_result r;
        CHECK(gal_sim_run(&s, GAL_MODEL_FULL, &r) == GAL_OK, "%s", gal_error_message());
        int kp = gal_sim_mid_probe(&r);
        double lo = INFINITY, hi = -INFINITY;
        for (long i = r.nsamples / 2; i < r.nsamples; i++) {
            double y = r.trace[(size_t)i * 4 * r.nprobe + 4 * kp];
            lo = fmin(lo, y), hi = fmax(hi, y);
        }
        swing[k] = hi - lo, y0[k] = r.trace[4 * kp];
        gal_sim_result_clear(&r);
        gal_sim_setup_clear(&s);
    }
    printf("    (horizontal swing over 10-20 s: %.3g m from rest, %.3g m from the mean-wind equilibrium, "
           "which starts %.4g m across)\n", swing[0], swing[1], y0[1]);
    CHECK(y0[1] > 0.1 && y0[0] == 0, "the mean-wind start is blown out: %g", y0[1]);
    CHECK(swing[1] < 0.01 * swing[0], "no transient from the mean-wind equilibrium: %g vs %g", swing[1], swing[0]);
}

/* peak-to-peak of the vertical displacement at the mid probe over [t0, t1] */
static double pp(const gal_sim_result *r, double t0, double t1)
{
    int k = gal_sim_mid_probe(r);
    double lo = INFINITY, hi = -INFINITY;
    for (long i = 0; i < r->nsamples; i++)
        if (r->time[i] >= t0 && r->time[i] <= t1) {
            double z = r->trace[(size_t)i * 4 * r->nprobe + 4 * k + 1];
            lo = fmin(lo, z), hi = fmax(hi, z);
        }
    return hi - lo;
}

/* At 90 deg the D-section is Den Hartog stable: the motion the wind's onset leaves decays. */
static void test_stable_section_decays(void)
{
    gal_scene sc;
    const char *ov[] = {"model.elements=30", "ice.attack_angle=90", "simulation.duration=120",
                        "simulation.wind_ramp=1"};
    if (load(&sc, "data/scenes/iced_gallop.ini", ov, 4)) return;
    gal_sim_setup s;
    CHECK(gal_sim_setup_init(&s, &sc, 1) == GAL_OK, "%s", gal_error_message());
    for (int m = 0; m < 2; m++) {
        gal_sim_result r;
        CHECK(gal_sim_run(&s, m ? GAL_MODEL_REDUCED : GAL_MODEL_FULL, &r) == GAL_OK, "%s", gal_error_message());
        double early = pp(&r, 5, 20), late = pp(&r, 100, 120);
        printf("    (%s, stable section: vertical p-p %.3g m early, %.3g m late)\n", m ? "reduced" : "full", early, late);
        CHECK(late < 0.5 * early, "the motion must decay: %g then %g", early, late);
        gal_sim_result_clear(&r);
    }
    gal_sim_setup_clear(&s);
}

/* The data scene: the unstable section grows to a steady orbit; full and reduced agree (issue 6:
 * frequency within 1%, vertical peak-to-peak within 5%, horizontal and twist within 10%). The
 * reduced basis takes the two lowest torsional modes (the scene selects one): with one, the
 * mid-span twist came out 26.8 deg against the full model's 19.1 (23.2 without the hyper-reduction)
 * while the self-check's residual stayed at 0.092, below model.residual_tolerance = 0.1 (issue 13:
 * the check misses that error); with two, 20.0 deg, residual 0.033. */
static void test_galloping_full_vs_reduced(void)
{
    gal_scene sc, scr;
    /* 600 s: steady from ~300 s with the stated ratio at every mode (issue 15); at 500 s and 700 s
     * the steady-part rule (issue 14: its envelope's last 2%) puts steady at 490 s and 686 s */
    const char *ov[] = {"model.elements=40", "simulation.duration=600", "model.modes_torsional=2"};
    if (load(&sc, "data/scenes/iced_gallop.ini", ov, 2) || load(&scr, "data/scenes/iced_gallop.ini", ov, 3)) return;
    gal_sim_setup s, sr;
    CHECK(gal_sim_setup_init(&s, &sc, 1) == GAL_OK, "%s", gal_error_message());
    CHECK(gal_sim_setup_init(&sr, &scr, 1) == GAL_OK, "%s", gal_error_message());
    gal_sim_result f, r;
    CHECK(gal_sim_run(&s, GAL_MODEL_FULL, &f) == GAL_OK, "%s", gal_error_message());
    CHECK(gal_sim_run(&sr, GAL_MODEL_REDUCED, &r) == GAL_OK, "%s", gal_error_message());
    gal_sim_measures mf, mr;
    gal_compare_ref h; /* measured as `gallop compare` measures */
    CHECK(gal_compare_reference(&f, -1, &h) == GAL_OK && gal_compare_measure(&f, &h, &mf) == GAL_OK, "%s",
          gal_error_message());
    CHECK(gal_compare_measure(&r, &h, &mr) == GAL_OK, "%s", gal_error_message());
    printf("    (full: vertical p-p %.4g m at %.5g Hz, horizontal %.4g m, twist %.4g deg, steady after %.0f s;"
           " reduced: %.4g m at %.5g Hz, %.4g m, %.4g deg; wall %.2f s vs %.3f s)\n",
           mf.peak_to_peak[1], mf.frequency_hz[1], mf.peak_to_peak[0], mf.peak_to_peak[3], mf.time_to_steady_s,
           mr.peak_to_peak[1], mr.frequency_hz[1], mr.peak_to_peak[0], mr.peak_to_peak[3], f.wall_time_s, r.wall_time_s);
    /* it gallops: grows from centimetres to metres and becomes steady before the end */
    CHECK(mf.peak_to_peak[1] > 2.0, "galloping amplitude %g m", mf.peak_to_peak[1]);
    CHECK(pp(&f, 10, 30) < 0.05 * mf.peak_to_peak[1], "it grows from a small motion");
    CHECK(isfinite(mf.time_to_steady_s) && mf.time_to_steady_s < 0.9 * f.time[f.nsamples - 1],
          "steady galloping before the end: %g s", mf.time_to_steady_s);
    CHECK_REL(mr.frequency_hz[1], mf.frequency_hz[1], 0.01);
    CHECK_REL(mr.peak_to_peak[1], mf.peak_to_peak[1], 0.05);
    CHECK_REL(mr.peak_to_peak[0], mf.peak_to_peak[0], 0.10);
    CHECK_REL(mr.peak_to_peak[3], mf.peak_to_peak[3], 0.10);
    gal_sim_result_clear(&f);
    gal_sim_result_clear(&r);
    gal_sim_setup_clear(&s);
    gal_sim_setup_clear(&sr);
}

/* The paper's finding: a larger GJ makes steady galloping take longer and the vertical amplitude
 * smaller (reduced model, the data scene). */
static void test_torsional_stiffness_delays_and_lowers_galloping(void)
{
    double ts[2], amp[2];
    const char *gj[2] = {"conductor.torsional_stiffness=200", "conductor.torsional_stiffness=800"};
    for (int k = 0; k < 2; k++) {
        gal_scene sc;
        const char *ov[] = {"model.elements=40", gj[k], "simulation.duration=600"};
        if (load(&sc, "data/scenes/iced_gallop.ini", ov, 3)) return;
        gal_sim_setup s;
        CHECK(gal_sim_setup_init(&s, &sc, 1) == GAL_OK, "%s", gal_error_message());
        gal_sim_result r;
        CHECK(gal_sim_run(&s, GAL_MODEL_REDUCED, &r) == GAL_OK, "%s", gal_error_message());
        gal_sim_measures m;
        gal_sim_measure(&r, gal_sim_mid_probe(&r), -1, &m);
        ts[k] = m.rise_time_s, amp[k] = m.peak_to_peak[1];
        gal_sim_result_clear(&r);
        gal_sim_setup_clear(&s);
    }
    printf("    (GJ 200: envelope at 90%% of its final level after %.0f s, vertical p-p %.3f m; GJ 800: %.0f s, %.3f m)\n", ts[0], amp[0], ts[1], amp[1]);
    CHECK(ts[1] > ts[0] * 1.2, "larger GJ: later steady galloping (%g vs %g s)", ts[1], ts[0]);
    CHECK(amp[1] < amp[0] * 0.97, "larger GJ: smaller vertical amplitude (%g vs %g m)", amp[1], amp[0]);
}

int main(void)
{
    RUN(test_dynamic_blowout_matches_statics);
    RUN(test_start_from_mean_wind);
    RUN(test_stable_section_decays);
    RUN(test_galloping_full_vs_reduced);
    RUN(test_torsional_stiffness_delays_and_lowers_galloping);
    return CHECK_SUMMARY();
}
