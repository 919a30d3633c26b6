/* test_rom_irk.c: the reduced model's two-stage Gauss-Legendre step (rom_irk.c, opt-in through
 * gal_rom_opts.scheme / gal_run_opts.rom_scheme): fourth order in time on the growth of
 * condor_150_taut_dshape's galloping (its 40 elements, [5, 20] s, the RMS trajectory difference at
 * mid-span from the run at dt_out/16, tests/trace_rms.h), more accurate at 10 steps a period of the
 * highest mode than generalized-alpha at 40; and, undamped and unloaded, the energy of a free
 * vibration of the sagged span of tests/rom_sagged.h (0.2 m at mid-span, as test_rom's) within
 * 1e-3 over 1000 periods at 10 steps a period of the highest selected mode (issue 13's figure). */
#include "check.h"
#include "sim_fixture.h"
#include "gallop.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"
#include "rom_sagged.h"
#include "trace_rms.h"

#define SCENE "tests/rom/condor_150_taut_dshape.ini"

static int run(const gal_sim_setup *s, const gal_run_opts *o, int scheme, double h, gal_sim_result *r)
{
    gal_run_opts ok = *o;
    ok.rom_scheme = scheme, ok.time_step = h;
    int st = gal_run(s->model, s->data, &gal_integrator_reduced, &ok, r);
    CHECK(st == GAL_OK, "reduced run (scheme %d) at %g s: %s", scheme, h, gal_error_message());
    return st;
}

static void test_order(void)
{
    const char *ov[] = {"simulation.duration=20"};
    gal_scene sc;
    gal_sim_setup s;
    if (sim_fixture(&sc, &s, SCENE, ov, 1)) return;
    gal_run_opts o;
    gal_run_opts_from_scene(&sc, &o);
    gal_sim_result r[5] = {{0}}; /* Gauss at dt_out/1, /2, /4, /16; generalized-alpha at its default */
    int st = gal_run_check_measurable(s.model, s.data, &o);
    if (!st) st = run(&s, &o, GAL_ROM_SCHEME_GALPHA, 0, &r[4]);
    double dt = st ? 0 : r[4].dt_out;
    const int sub[4] = {1, 2, 4, 16};
    for (int k = 0; k < 4 && !st; k++) st = run(&s, &o, GAL_ROM_SCHEME_GAUSS2, dt / sub[k], &r[k]);
    if (!st) {
        const int col[3] = {0, 1, 3};
        const char *name[3] = {"horizontal", "vertical", "twist"};
        for (int c = 0; c < 3; c++) {
            double e[3], ga = rms_error(&r[4], &r[3], col[c], 5, 20);
            for (int k = 0; k < 3; k++) e[k] = rms_error(&r[k], &r[3], col[c], 5, 20);
            double p = log2(e[1] / e[2]);
            printf("    %-10s Gauss at dt_out/1, /2, /4: %.3e %.3e %.3e (order %.2f, %.2f); generalized-alpha at "
                   "dt_out/4: %.3e\n", name[c], e[0], e[1], e[2], log2(e[0] / e[1]), p, ga);
            CHECK(p >= (c == 2 ? 3.0 : 3.5), "%s: observed order %.2f from dt_out/2 to /4; expected 4", name[c], p);
            CHECK(e[0] < 0.2 * ga, "%s: Gauss at 10 steps a period %g, not within a fifth of generalized-alpha's %g at 40",
                  name[c], e[0], ga);
        }
    }
    for (int k = 0; k < 5; k++) gal_sim_result_clear(&r[k]);
    gal_sim_setup_clear(&s);
}

static void test_energy(void)
{
    gal_equilibrium eq;
    gal_modes md;
    int sel[8], ns, k1 = -1;
    memset(&eq, 0, sizeof eq), memset(&md, 0, sizeof md);
    int st = sagged_setup(&eq, &md, sel, &ns);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    double fhi = 0;
    for (int k = 0; !st && k < ns; k++) {
        const gal_mode *mo = &md.mode[sel[k]];
        fhi = fmax(fhi, mo->frequency_hz);
        if (k1 < 0 && mo->family == GAL_FAMILY_VERTICAL && mo->symmetry == GAL_SYM_SYMMETRIC) k1 = k;
    }
    CHECK(st || k1 >= 0, "a symmetric vertical mode");
    gal_rom *m = NULL;
    if (!st && k1 >= 0) {
        gal_rom_opts o;
        gal_rom_default_opts(&o);
        o.scheme = GAL_ROM_SCHEME_GAUSS2, o.h = 0.1 / fhi;
        m = gal_rom_alloc(eq.rod, eq.q, &md, sel, ns, &o, NULL);
        CHECK(m != NULL, "%s", gal_error_message());
    }
    if (m) {
        double w1 = md.mode[sel[k1]].omega, U0 = gal_rom_energy(m);
        /* about 0.2 m at mid-span, test_rom's (measured: 4.7e-5; at 0.7 m 9.1e-3 at 10 steps a period,
         * 8.8e-4 at 20: the Newton tolerance's error, which a symplectic step does not bound) */
        m->x[k1] = 0.15 * sqrt(sagged.mass * sagged.length);
        double *q = malloc(m->nq * sizeof(double));
        gal_rom_reconstruct(m, q, NULL);
        CHECK(gal_rom_start(m, 0, q, NULL) == GAL_OK, "%s", gal_error_message());
        double E0 = gal_rom_energy(m), dev = 0;
        for (int per = 0; per < 1000; per++) {
            if (gal_rom_advance(m, (per + 1) * 2 * GAL_PI / w1)) { CHECK(0, "%s", gal_error_message()); break; }
            if (per % 10 == 9) dev = fmax(dev, fabs(gal_rom_energy(m) - E0));
        }
        printf("    (1000 periods, %ld steps of %.4g s, %.1f a period of the highest mode: energy %.2e of the motion's)\n",
               m->steps, m->o.h, 1 / (fhi * m->o.h), dev / (E0 - U0));
        CHECK(dev < 1e-3 * (E0 - U0), "energy moved %g of %g", dev, E0 - U0);
        free(q);
        gal_rom_free(m);
    }
    gal_modes_clear(&md);
    gal_equilibrium_clear(&eq);
}

int main(void)
{
    RUN(test_order);
    RUN(test_energy);
    return CHECK_SUMMARY();
}
