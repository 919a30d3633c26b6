/* test_rom_carry.c: Newton's last correction taken unconfirmed (gal_rom_opts.newton_carry, issue 13's
 * cost per step): on tests/rom/drake_200_level_dshape.ini the reduced model with and without it,
 * from the same start: fewer evaluations of the sampled energy, and the same trajectory to within
 * what Newton's tolerance moves; never at rho_inf = 1. */
#include "check.h"
#include "gallop.h"
#include "gallop/run/forward.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"
#include "sim_fixture.h"

#define SPAN "tests/rom/drake_200_level_dshape.ini"
#define SECONDS 150

typedef struct {
    double x[64], v[64];      /* the final reduced state */
    int r;
    long steps, carried, element_evaluations, newton_iterations;
} outcome;

/* The reduced model of `scene` over `seconds` (step h, rho_inf) with o.newton_carry = carry; its
 * final state and counters into *o. */
static int run(const char *scene, double h, int carry, double rho_inf, double seconds, outcome *o)
{
    gal_scene sc;
    gal_sim_setup s;
    if (sim_fixture(&sc, &s, scene, NULL, 0)) return 1;
    gal_rom_opts ro;
    gal_rom_default_opts(&ro);
    ro.h = h, ro.rho_inf = rho_inf, ro.newton_carry = carry;
    gal_rom *m = rom_fixture(&s, &ro);
    int st = GAL_OK;
    if (m) {
        st = gal_rom_advance(m, seconds);
        CHECK(st == GAL_OK, "%s", gal_error_message());
        o->r = m->r < 64 ? m->r : 64;
        memcpy(o->x, m->x, (size_t)o->r * sizeof(double));
        memcpy(o->v, m->v, (size_t)o->r * sizeof(double));
        o->steps = m->steps, o->carried = m->carried;
        o->element_evaluations = m->element_evaluations, o->newton_iterations = m->newton_iterations;
        printf("    carry %d, rho_inf %g: %ld steps, %ld corrections carried, %.2f energy passes a step (%.1f "
               "elements)\n", carry, rho_inf, m->steps, m->carried,
               (double)(m->newton_iterations + m->steps - m->carried) / (double)m->steps,
               (double)m->element_evaluations / (double)m->steps);
    }
    gal_rom_free(m);
    gal_sim_setup_clear(&s);
    return st || !m;
}

/* |a - b| / |b| over the state (x and v each) */
static double state_diff(const outcome *a, const outcome *b, int vel)
{
    double d = 0, n = 0;
    for (int k = 0; k < b->r; k++) {
        double p = vel ? a->v[k] : a->x[k], q = vel ? b->v[k] : b->x[k];
        d += (p - q) * (p - q), n += q * q;
    }
    return sqrt(d / n);
}

/* 150 s of drake_200 (80 elements, h = 0.0118 s: Newton takes three passes or more on most steps
 * of the cycle): with the carry a fifth or more of the steps end on a carried correction, the
 * sampled energy is evaluated at least 5% less (measured: 3327 of 12712 steps, 7.6% less), and the
 * state is Newton's confirming every correction to 5e-5 relative (measured: 1.1e-5 in x, 1.7e-5 in
 * v; with the carried correction left out, the state its residual was measured at: 5.8e-5 and
 * 3.6e-4) */
static void test_carry_same_trajectory(void)
{
    outcome a, b;
    if (run(SPAN, 0.0118, 0, 0.9, SECONDS, &a) || run(SPAN, 0.0118, 1, 0.9, SECONDS, &b)) return;
    CHECK(a.carried == 0, "%ld carried without o.newton_carry", a.carried);
    CHECK(b.steps == a.steps && b.r == a.r, "%ld/%ld steps, basis %d/%d", b.steps, a.steps, b.r, a.r);
    CHECK(b.carried >= a.steps / 5, "%ld of %ld steps carried", b.carried, b.steps);
    CHECK(b.element_evaluations <= 0.95 * (double)a.element_evaluations, "energy element evaluations %ld against %ld",
          b.element_evaluations, a.element_evaluations);
    double dx = state_diff(&b, &a, 0), dv = state_diff(&b, &a, 1);
    printf("    state against Newton confirming every correction: x %.2e, v %.2e\n", dx, dv);
    CHECK(dx <= 5e-5 && dv <= 5e-5, "x %g, v %g relative", dx, dv);
}

/* rho_inf = 1: the discrete gradient reads the energy at the step's end: never carried */
static void test_no_carry_at_rho1(void)
{
    outcome a;
    if (run(SPAN, 0.0118, 1, 1.0, 2, &a)) return;
    CHECK(a.carried == 0, "%ld carried at rho_inf = 1", a.carried);
}

int main(void)
{
    RUN(test_carry_same_trajectory);
    RUN(test_no_carry_at_rho1);
    return CHECK_SUMMARY();
}
