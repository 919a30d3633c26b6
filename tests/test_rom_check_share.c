/* test_rom_check_share.c: what the reduced model's checks share and keep (rom_check.c, ecsw.c) is
 * what they would compute afresh, bit for bit: the sample check's whole-rod gradient and loads from
 * one reconstruction of q and v (gal_rom_hyper_check) against the rod and the loads evaluated by
 * the test at its own reconstruction, and its error against the exact forces of
 * gal_rom_exact_force and gal_rom_eval_external; the self-check (gal_rom_residual_dir) right after
 * it, which takes that gradient and those loads and skips its own reconstruction, against the same
 * self-check with nothing held and the model's configuration scratch spoiled; the kept node
 * directions against gal_rod_node_directions at the equilibrium. On data/scenes/iced_gallop.ini at
 * 40 elements, galloping (issue 13: the checks' cost, the same numbers). */
#include "check.h"
#include "gallop.h"
#include "gallop/reduced/ecsw.h"
#include "reduced/hyper.h"
#include "sim_fixture.h"

#include <math.h>

#define SCENE "data/scenes/iced_gallop.ini"

static int same(const double *a, const double *b, int n)
{
    return !memcmp(a, b, (size_t)n * sizeof(double));
}

static int same_check(const gal_rom_check *a, const gal_rom_check *b)
{
    int ok = 1;
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) {
        ok &= a->err[f] == b->err[f] && a->disp[f] == b->disp[f] && a->scale[f] == b->scale[f] && a->rel[f] == b->rel[f];
        for (int k = 0; k < 3; k++) ok &= a->power[k][f] == b->power[k][f];
    }
    return ok && a->max == b->max;
}

/* |rw .* a| (ecsw.c's norm of the sample check) */
static double wnorm(const double *rw, const double *a, int r)
{
    double s = 0;
    for (int k = 0; k < r; k++) s += rw[k] * rw[k] * a[k] * a[k];
    return sqrt(s);
}

/* The sample check's error from the exact forces evaluated apart: the internal force by
 * gal_rom_exact_force, the loads by the whole rod's (gal_rom_eval_external on a model not sampled
 * there is not at hand: the loads at the test's own reconstruction, projected in the dofs' order). */
static double sample_error(gal_rom *m, const gal_sim_setup *s)
{
    const gal_rom_hyper *h = m->hyper;
    int r = m->r, n = m->ndof;
    double fa[64], fb[64], fl[64], e = 0;
    if (gal_rom_exact_force(m, m->x, fa) || gal_rom_hyper_internal(m, m->x, fb, NULL)) return NAN;
    for (int k = 0; k < r; k++) fb[k] -= fa[k], fa[k] -= h->F0[k];
    double den = wnorm(h->set[0].rw, fa, r);
    if (den > 0) e = wnorm(h->set[0].rw, fb, r) / den;
    gal_rom_reconstruct_at(m, m->x, m->v);
    memset(m->fq, 0, (size_t)m->nq * sizeof(double));
    if (gal_loads_full((void *)&s->data->loads, m->t, m->q, m->vq, m->fq)) return NAN;
    for (int k = 0; k < r; k++) {
        double sl = 0;
        for (int d = 0; d < n; d++) sl += m->V[(size_t)k * n + d] * m->fq[m->rod->free_q[d]];
        fl[k] = sl;
    }
    if (gal_rom_hyper_external(m, m->t, m->x, m->v, fb)) return NAN;
    for (int k = 0; k < r; k++) fb[k] -= fl[k];
    den = wnorm(h->set[1].rw, fl, r);
    if (den > 0) e = fmax(e, wnorm(h->set[1].rw, fb, r) / den);
    return e;
}

/* sampled: the loads sampled (the default) or evaluated over the whole rod at every step (then the
 * sample check holds the gradient alone and the self-check evaluates the loads itself) */
static void checks_share(int sampled)
{
    const char *ov[] = {"model.elements=40"};
    gal_scene sc;
    gal_sim_setup s;
    if (sim_fixture(&sc, &s, SCENE, ov, 1)) return;
    gal_rom_opts ro;
    gal_rom_default_opts(&ro);
    ro.h = 0.01, ro.rho_inf = sc.simulation.rho_inf, ro.hyper_check_interval = 0; /* the test's checks alone */
    ro.hyper_loads = sampled;
    gal_rom *m = rom_fixture(&s, &ro);
    if (!m) {
        gal_sim_setup_clear(&s);
        return;
    }
    CHECK(m->hyper && m->hyper->loads == sampled && m->r <= 64, "a sampled model, loads sampled %d, basis %d", sampled, m->r);
    CHECK(gal_rom_advance(m, 40.0) == GAL_OK, "%s", gal_error_message());
    int n = m->ndof, nq = m->nq, r = m->r;
    double *g = malloc((size_t)nq * sizeof(double)), *f = calloc((size_t)nq, sizeof(double));
    double *du1 = malloc((size_t)n * sizeof(double)), *du2 = malloc((size_t)n * sizeof(double));
    double xs[128];
    memcpy(xs, m->x, (size_t)r * sizeof(double)), memcpy(xs + r, m->v, (size_t)r * sizeof(double));

    /* the sample check: its kept gradient and loads are the rod's and the loads' at q_eq + V x, v = V x' */
    double err = -1;
    m->o.hyper_check_tol = 1e30; /* no re-sampling: the same sample before and after */
    CHECK(gal_rom_hyper_check(m, &err) == GAL_OK, "%s", gal_error_message());
    const double *wg, *wf;
    CHECK(gal_rom_hyper_whole(m, &wg, &wf) && wg && !wf == !sampled, "the sample check keeps the gradient (and the sampled loads)");
    gal_rom_reconstruct_at(m, m->x, m->v);
    CHECK(gal_rod_eval(m->rod, m->q, NULL, g, NULL) == GAL_OK, "%s", gal_error_message());
    CHECK(gal_loads_full((void *)&s.data->loads, m->t, m->q, m->vq, f) == GAL_OK, "%s", gal_error_message());
    CHECK(wg && same(wg, g, nq), "kept gradient = the rod's at the reconstruction, bit for bit");
    CHECK(!sampled || (wf && same(wf, f, nq)), "kept loads = the loads at the reconstruction (q and v), bit for bit");
    double e2 = sampled ? sample_error(m, &s) : err;
    CHECK(err == e2 && err > 0 && err < 1, "sample check error %.17g, from the exact forces apart %.17g", err, e2);

    /* the self-check right after the sample check (shared evaluation, no reconstruction), then with
     * nothing held and the configuration scratch spoiled: the same check */
    CHECK(gal_rom_hyper_check(m, NULL) == GAL_OK, "%s", gal_error_message());
    gal_rom_check c1, c2;
    CHECK(gal_rom_residual_dir(m, &c1, du1) == GAL_OK, "%s", gal_error_message());
    m->hyper->whole_has = 0;
    for (int d = 0; d < n; d++) m->q[m->rod->free_q[d]] = m->vq[m->rod->free_q[d]] = NAN;
    CHECK(gal_rom_residual_dir(m, &c2, du2) == GAL_OK, "%s", gal_error_message());
    CHECK(same_check(&c1, &c2) && same(du1, du2, n), "self-check shared = afresh: max %.17g and %.17g", c1.max, c2.max);
    CHECK(c1.max > 0 && isfinite(c1.max), "a residual to compare: %g", c1.max);
    CHECK(same(xs, m->x, r) && same(xs + r, m->v, r), "the checks leave the state as it was");

    /* the kept directions: gal_rod_node_directions at the equilibrium */
    CHECK(m->node_dir != NULL, "directions kept after a check");
    int bad = 0;
    for (int i = 0; m->node_dir && i < m->rod->nn; i++) {
        double e[9];
        gal_rod_node_directions(m->rod, m->q_eq, i, e, e + 3, e + 6);
        bad += !same(e, m->node_dir + 9 * i, 9);
    }
    CHECK(bad == 0, "%d of %d nodes' kept directions differ from the equilibrium's", bad, m->rod->nn);
    printf("    loads sampled %d, 40 elements at t = %.2f s: basis %d, sample check %.3g, self-check %.3g\n", sampled, m->t, r, err, c1.max);

    free(g), free(f), free(du1), free(du2);
    gal_rom_free(m);
    gal_sim_setup_clear(&s);
}

static void test_checks_share(void)
{
    checks_share(1);
}

static void test_checks_share_loads_whole(void)
{
    checks_share(0);
}

int main(void)
{
    RUN(test_checks_share);
    RUN(test_checks_share_loads_whole);
    return CHECK_SUMMARY();
}
