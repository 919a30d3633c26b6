/* test_rom_order.c: the reduced model's step (rom_step.c, generalized-alpha as the full model's) is
 * second order in time: on condor_150_taut_dshape at its 40 elements, the growth of the galloping
 * over [5, 20] s (before the limit cycle, where trajectories at different steps stay close), the
 * RMS difference of each family's trace at mid-span from the run at an eighth of the default step
 * h, over that trace's RMS about its mean, at 2h, h and h/2: the observed orders log2(e(2h)/e(h))
 * and log2(e(h)/e(h/2)) at least 1.8 in the horizontal and vertical (measured 1.93-2.06; the full
 * model's 2.0-2.1). The twist's is checked at 1.5 only: measured 1.65 and 1.85, because Newton
 * stops at its round-off floor ffloor (rom_basis.c), which weighs the twist entries of the
 * M-normalized basis (~1/sqrt(polar inertia)) by the axial stiffness's round-off and so sits ~1000x
 * above newton_tol's test, and the loads are held from its first correction (o.loads_once); with
 * the floor weighted per family, or the loads at every pass, the twist's order is 2.0-2.1
 * (BENCHMARKS.md, issue 13, helper order: not shipped, the self-check's basis growth moves with it). */
#include "check.h"
#include "sim_fixture.h"
#include "gallop.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"
#include "trace_rms.h"

#define SCENE "tests/rom/condor_150_taut_dshape.ini"

static void test_order(void)
{
    const char *ov[] = {"simulation.duration=20"};
    gal_scene sc;
    gal_sim_setup s;
    if (sim_fixture(&sc, &s, SCENE, ov, 1)) return;
    gal_run_opts o;
    gal_run_opts_from_scene(&sc, &o);
    gal_sim_result r[4] = {{0}}; /* 2h, h, h/2, h/8 */
    int st = gal_run_check_measurable(s.model, s.data, &o);
    if (!st) st = gal_run(s.model, s.data, &gal_integrator_reduced, &o, &r[1]);
    CHECK(st == GAL_OK, "reduced run: %s", gal_error_message());
    double h = st ? 0 : r[1].time_step_s, f[4] = {2, 1, 0.5, 0.125};
    for (int k = 0; k < 4 && !st; k++) {
        if (k == 1) continue;
        gal_run_opts ok = o;
        ok.time_step = f[k] * h;
        st = gal_run(s.model, s.data, &gal_integrator_reduced, &ok, &r[k]);
        CHECK(st == GAL_OK, "reduced run at %g s: %s", ok.time_step, gal_error_message());
        CHECK(st || fabs(r[k].time_step_s - f[k] * h) <= 1e-9 * h, "step %g s, asked %g s", r[k].time_step_s, f[k] * h);
    }
    if (!st) {
        const int col[3] = {0, 1, 3};
        const char *name[3] = {"horizontal", "vertical", "twist"};
        for (int c = 0; c < 3; c++) {
            double e[3];
            for (int k = 0; k < 3; k++) e[k] = rms_error(&r[k], &r[3], col[c], 5, 20);
            double p1 = log2(e[0] / e[1]), p2 = log2(e[1] / e[2]);
            printf("    %-10s error at 2h, h, h/2 (h = %.5g s): %.3e %.3e %.3e, order %.2f %.2f\n", name[c], h, e[0], e[1],
                   e[2], p1, p2);
            CHECK(e[1] > 0 && e[1] < 2e-2, "%s: error %g at the default step", name[c], e[1]);
            double least = c == 2 ? 1.5 : 1.8;
            CHECK(p1 >= least && p2 >= least, "%s: observed order %.2f (2h to h), %.2f (h to h/2); expected 2", name[c], p1,
                  p2);
        }
    }
    for (int k = 0; k < 4; k++) gal_sim_result_clear(&r[k]);
    gal_sim_setup_clear(&s);
}

int main(void)
{
    RUN(test_order);
    return CHECK_SUMMARY();
}
