/* test_sweep.c: the sweep's library parts (run/sweep.h, output/sweepreport.h): LIST parsing (lists,
 * ranges, the refused forms), the cases of a unit (a chain up and down, the rows), the overrides of
 * a case, the fingerprint (what changes it), a case record written and read back exactly, and the
 * continuation hook: a full or reduced run continued from its final state (gal_data_start_from,
 * gal_run_to_state) ends where one longer run ends. */
#include <unistd.h>

#include "check.h"
#include "gallop.h"

static void test_lists_and_ranges(void)
{
    gal_sweep_grid g;
    memset(&g, 0, sizeof g);
    CHECK(gal_sweep_axis_parse(&g.axis[0], "wind.speed=2:10:0.5") == GAL_OK, "%s", gal_error_message());
    CHECK(g.axis[0].n == 17 && !strcmp(g.axis[0].key, "wind.speed"), "17 values of wind.speed, got %d", g.axis[0].n);
    CHECK(!strcmp(g.axis[0].value[3], "3.5") && g.axis[0].num[16] == 10, "3.5 and 10 exactly");
    CHECK(gal_sweep_axis_parse(&g.axis[1], "wind.turbulence= none, kaimal") == GAL_OK, "%s", gal_error_message());
    CHECK(g.axis[1].n == 2 && !strcmp(g.axis[1].value[1], "kaimal") && isnan(g.axis[1].num[1]), "a list of names");
    CHECK(gal_sweep_axis_parse(&g.axis[2], "ice.attack_angle=10:-10:-10") == GAL_OK, "a descending range");
    CHECK(g.axis[2].n == 3 && !strcmp(g.axis[2].value[1], "0"), "0, not -0 or 1e-16: '%s'", g.axis[2].value[1]);
    g.naxes = 3;
    CHECK(gal_sweep_grid_init(&g, 0) == GAL_OK && g.npoints == 102 && g.ncases == 102 && g.unit_cases == 1,
          "the product grid: %ld", g.npoints);
    gal_sweep_grid_clear(&g);
    static const char *const bad[] = {"wind.speed", "speed=1,2", "wind.speed=", "wind.speed=1,,2", "wind.speed=1:5:0",
                                      "wind.speed=5:1:1", "wind.speed=1:x:1", "wind.speed=0:1e9:1"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        gal_sweep_axis a;
        CHECK(gal_sweep_axis_parse(&a, bad[i]) == GAL_EINPUT && strstr(gal_error_message(), "--vary"),
              "'%s' refused naming --vary: %s", bad[i], gal_error_message());
        free(a.value), free(a.num);
    }
}

/* A chain: axis 0 up and back down, one unit per point of the other axes. */
static void test_chains(void)
{
    gal_sweep_grid g;
    memset(&g, 0, sizeof g);
    CHECK(gal_sweep_axis_parse(&g.axis[0], "wind.speed=1,2,3") == GAL_OK, "%s", gal_error_message());
    CHECK(gal_sweep_axis_parse(&g.axis[1], "conductor.damping_ratio=0.01,0.02") == GAL_OK, "%s", gal_error_message());
    g.naxes = 2;
    CHECK(gal_sweep_grid_init(&g, 1) == GAL_OK && g.nunits == 2 && g.unit_cases == 5 && g.ncases == 10, "2 chains of 5");
    static const int idx0[5] = {0, 1, 2, 1, 0};
    for (long u = 0; u < g.nunits; u++)
        for (int p = 0; p < 5; p++) {
            gal_sweep_case c;
            gal_sweep_case_of(&g, u, p, &c);
            CHECK(c.row == u * 5 + p && c.idx[0] == idx0[p] && c.idx[1] == u, "unit %ld case %d", u, p);
            CHECK(c.branch == (p < 3 ? GAL_SWEEP_UP : GAL_SWEEP_DOWN), "branch of case %d", p);
        }
    char buf[GAL_SWEEP_MAX_AXES][GAL_SWEEP_KEY_MAX + GAL_SWEEP_VALUE_MAX];
    const char *sets[4], *user[1] = {"model.elements=20"};
    gal_sweep_case c;
    gal_sweep_case_of(&g, 1, 3, &c);
    int n = gal_sweep_case_sets(&g, &c, user, 1, buf, sets);
    CHECK(n == 3 && !strcmp(sets[0], user[0]) && !strcmp(sets[1], "wind.speed=2") &&
          !strcmp(sets[2], "conductor.damping_ratio=0.02"), "the overrides after the user's");
    CHECK(gal_sweep_grid_check(&g, "data/scenes/iced_gallop.ini", user, 1) == GAL_OK, "%s", gal_error_message());
    gal_sweep_grid_clear(&g);
    CHECK(gal_sweep_axis_parse(&g.axis[0], "wind.speed=3,-1") == GAL_OK, "parsed");
    g.naxes = 1;
    CHECK(gal_sweep_grid_init(&g, 0) == GAL_OK, "init");
    CHECK(gal_sweep_grid_check(&g, "data/scenes/iced_gallop.ini", NULL, 0) == GAL_EINPUT &&
              strstr(gal_error_message(), "--vary wind.speed=-1") && strstr(gal_error_message(), "allowed"),
          "the bad value named with the range: %s", gal_error_message());
    gal_sweep_grid_clear(&g);
}

static int load(gal_scene *sc, const char *extra)
{
    const char *ov[4] = {"model.elements=16", "simulation.duration=30", "model.modes_vertical=2", extra};
    int st = gal_scene_load(sc, "data/scenes/iced_gallop.ini", ov, extra ? 4 : 3, NULL);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    return st;
}

static void test_fingerprint_and_record(void)
{
    gal_scene a, b;
    if (load(&a, NULL) || load(&b, "wind.speed=11")) return;
    uint64_t fa, fa2, fb, fup, fprev;
    CHECK(gal_sweep_fingerprint(&a, GAL_MODEL_FULL, GAL_SWEEP_NONE, 0, &fa) == GAL_OK, "%s", gal_error_message());
    gal_sweep_fingerprint(&a, GAL_MODEL_FULL, GAL_SWEEP_NONE, 0, &fa2);
    gal_sweep_fingerprint(&b, GAL_MODEL_FULL, GAL_SWEEP_NONE, 0, &fb);
    gal_sweep_fingerprint(&a, GAL_MODEL_FULL, GAL_SWEEP_UP, 0, &fup);
    gal_sweep_fingerprint(&a, GAL_MODEL_FULL, GAL_SWEEP_UP, 7, &fprev);
    CHECK(fa == fa2 && fa != fb && fa != fup && fup != fprev, "the scene, the branch and the predecessor count");
    strcpy(b.output.directory, "elsewhere");
    gal_sweep_fingerprint(&a, GAL_MODEL_REDUCED, GAL_SWEEP_NONE, 0, &fb);
    CHECK(fb != fa, "the model counts");
    char dir[] = "/tmp/gallop_test_sweep_XXXXXX";
    CHECK(mkdtemp(dir) != NULL, "temporary directory");
    CHECK(gal_sweep_cases_dir(dir) == GAL_OK, "%s", gal_error_message());
    gal_sweep_result r = {0}, back;
    r.vertical_pp_m = 0.1 / 3, r.horizontal_pp_m = 1e-300, r.twist_pp_deg = NAN, r.frequency_hz = 0.4617;
    r.tension_max_n = 40123.456789012345, r.onset_speed_m_s = NAN, r.valid = 1, r.residual_max = 0.02;
    r.wall_time_s = 1.5, r.has_onset = 1;
    strcpy(r.message, "two\nlines");
    double q[3] = {1.0 / 7, -2e-17, 3}, v[3] = {0, 1e10, -0.5}, *q2 = NULL, *v2 = NULL;
    int nq = 0;
    CHECK(gal_sweep_record_read(dir, fa, &back, NULL, NULL, NULL) == 0, "no record yet");
    CHECK(gal_sweep_record_write(dir, fa, &r, q, v, 3) == GAL_OK, "%s", gal_error_message());
    CHECK(gal_sweep_record_read(dir, fa, &back, &q2, &v2, &nq) == 1 && nq == 3 && q2 && v2, "read back");
    CHECK(back.vertical_pp_m == r.vertical_pp_m && back.horizontal_pp_m == r.horizontal_pp_m &&
              isnan(back.twist_pp_deg) && back.tension_max_n == r.tension_max_n && back.valid == 1 &&
              back.has_onset == 1 && isnan(back.onset_speed_m_s) && !strcmp(back.message, "two lines"),
          "every figure to the last digit");
    CHECK(q2 && v2 && !memcmp(q, q2, sizeof q) && !memcmp(v, v2, sizeof v), "the state, bit for bit");
    free(q2), free(v2);
    CHECK(gal_sweep_record_read(dir, fup, &back, NULL, NULL, NULL) == 0, "another fingerprint: not found");
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    CHECK(system(cmd) == 0, "clean up");
}

/* A run of 30 s continued for 20 s from its final state ends where a run of 50 s does: the full
 * model, and the reduced one (its state reconstructed, the basis rebuilt about the equilibrium). */
static void continued_run(const gal_integrator_type *T)
{
    gal_scene sc;
    if (load(&sc, "wind.speed=12")) return;
    int st;
    gal_model *m = gal_model_alloc(&sc, &st);
    gal_data *d1 = m ? gal_data_alloc(m) : NULL, *d2 = m ? gal_data_alloc(m) : NULL, *d3 = m ? gal_data_alloc(m) : NULL;
    if (!d1 || !d2 || !d3) return;
    gal_run_opts o;
    gal_run_opts_from_scene(&sc, &o);
    gal_sim_result r1, r2, r3;
    gal_forward(m, d1, GAL_STAGE_START);
    int nq = d1->eq.rod->nq;
    double *q = malloc((size_t)nq * sizeof *q), *v = malloc((size_t)nq * sizeof *v);
    CHECK(gal_run_to_state(m, d1, T, &o, &r1, q, v) == GAL_OK, "%s", gal_error_message());
    CHECK(gal_data_start_from(m, d2, q, v) == GAL_OK && d2->v_start && d2->loads.ramp_time == 0, "start from it");
    gal_run_opts o2 = o, o3 = o;
    o2.duration = 20, o3.duration = 50;
    o2.output_interval = o3.output_interval = r1.dt_out;
    CHECK(gal_run(m, d2, T, &o2, &r2) == GAL_OK, "%s", gal_error_message());
    CHECK(gal_run(m, d3, T, &o3, &r3) == GAL_OK, "%s", gal_error_message());
    /* the vertical displacement at the first probe at the end, against the motion's size */
    double a2 = r2.trace[(r2.nsamples - 1) * 4 * r2.nprobe + 1], a3 = r3.trace[(r3.nsamples - 1) * 4 * r3.nprobe + 1];
    double size = 0;
    for (long i = 0; i < r3.nsamples; i++) size = fmax(size, fabs(r3.trace[i * 4 * r3.nprobe + 1]));
    printf("    (%s: continued %.5g m, one run %.5g m at the end; motion %.3g m)\n", T->name, a2, a3, size);
    CHECK(size > 0.01, "the span moves: %g m", size);
    CHECK_NEAR(a2, a3, 0.01 * size);
    /* and not a start from rest: that one is still far from it */
    gal_sim_result r4;
    gal_data *d4 = gal_data_alloc(m);
    gal_run(m, d4, T, &o2, &r4);
    double a4 = r4.trace[(r4.nsamples - 1) * 4 * r4.nprobe + 1];
    CHECK(fabs(a4 - a3) > 0.05 * size, "from rest: %g against %g", a4, a3);
    gal_sim_result_clear(&r1), gal_sim_result_clear(&r2), gal_sim_result_clear(&r3), gal_sim_result_clear(&r4);
    free(q), free(v);
    gal_data_free(d1), gal_data_free(d2), gal_data_free(d3), gal_data_free(d4);
    gal_model_free(m);
}

static void test_continued_run(void)
{
    continued_run(&gal_integrator_full);
    continued_run(&gal_integrator_reduced);
}

int main(void)
{
    RUN(test_lists_and_ranges);
    RUN(test_chains);
    RUN(test_fingerprint_and_record);
    RUN(test_continued_run);
    return CHECK_SUMMARY();
}
