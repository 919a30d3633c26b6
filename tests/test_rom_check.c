/* test_rom_check.c: the reduced model's self-check on a still span (rom_check.c): the scale of each
 * translational family has a floor with a physical meaning, the response K0^-1 W to a load of
 * GAL_ROM_CHECK_LOAD times the span's weight along the family (horizontally: the span swung by
 * that fraction of its sag, checked against the pendulum's swing), so that a span at rest gives a
 * residual of round-off, not an alarm; and a model on a copied set-up starts from the equilibrium
 * (its start's acceleration is the one of the model computed alone, not heap garbage); the cubic
 * indicator (gal_rom_cubic) against the same term built by another route. */
#include "check.h"
#include "gallop.h"
#include "gallop/modes/modes.h"
#include "gallop/reduced/rom_adapt.h"
#include "gallop/statics/statics.h"
#include "rom_sagged.h"
#include "base/chol.h"


/* The mass norm of the swing of the whole span by the angle eps about its chord: eps times each
 * node's sag below the chord (the span swings as a pendulum under a uniform horizontal load of eps
 * times its weight). */
static double pendulum_swing(const gal_rod *rod, const double *q_eq, double eps)
{
    double s = 0, L = rod->p.length, hd = rod->p.height_difference;
    for (int i = 0; i < rod->nn; i++) {
        int d = rod->dof[3 * i];
        if (d < 0) continue;
        double sag = hd * q_eq[3 * i] / L - q_eq[3 * i + 2];
        s += rod->mdiag[d] * (eps * sag) * (eps * sag);
    }
    return sqrt(s);
}

static void still_span(const gal_rod *rod, const double *q_eq, const gal_modes *md, const int *sel, int ns)
{
    gal_rom_opts o;
    gal_rom_default_opts(&o);
    o.h = 0.02;
    gal_rom *m = gal_rom_alloc(rod, q_eq, md, sel, ns, &o, NULL);
    CHECK(m != NULL, "%s", gal_error_message());
    if (!m) return;
    gal_rom_check chk;
    CHECK(gal_rom_advance(m, 5.0) == GAL_OK, "%s", gal_error_message());
    CHECK(gal_rom_residual(m, &chk) == GAL_OK, "%s", gal_error_message());
    /* nothing drives it: its motion and residual are round-off, far under the floors: ten times under the default tolerance at least */
    CHECK(chk.max < 0.01, "a span at rest: residual %g (the default tolerance: 0.1)", chk.max);
    double swing = pendulum_swing(rod, q_eq, GAL_ROM_CHECK_LOAD);
    CHECK_REL(chk.scale[GAL_FAMILY_HORIZONTAL], swing, 0.05);
    /* the stretching stiffens the in-plane response; the axial one is the stiffest */
    CHECK(chk.scale[GAL_FAMILY_VERTICAL] > 0 && chk.scale[GAL_FAMILY_VERTICAL] < swing, "vertical floor %g, swing %g",
          chk.scale[GAL_FAMILY_VERTICAL], swing);
    CHECK(chk.scale[GAL_FAMILY_AXIAL] > 0 && chk.scale[GAL_FAMILY_AXIAL] < chk.scale[GAL_FAMILY_VERTICAL],
          "axial floor %g", chk.scale[GAL_FAMILY_AXIAL]);
    gal_rom_free(m);
}

/* A model on a copied set-up (gal_rom_setup_alloc, o.setup) starts at rest with the acceleration
 * of the model computed alone: the sampled evaluations read the whole element, clamped ends
 * included, from m->q. */
static void copied_setup(const gal_rod *rod, const double *q_eq, const gal_modes *md, const int *sel, int ns)
{
    gal_rom_opts o;
    gal_rom_default_opts(&o);
    o.h = 0.02;
    gal_rom *alone = gal_rom_alloc(rod, q_eq, md, sel, ns, &o, NULL);
    gal_rom *setup = gal_rom_setup_alloc(rod, q_eq, md, sel, ns, &o);
    o.setup = setup;
    gal_rom *copy = setup ? gal_rom_alloc(rod, q_eq, md, sel, ns, &o, NULL) : NULL;
    CHECK(alone && setup && copy, "%s", gal_error_message());
    if (alone && copy) {
        CHECK(copy->setup_reused && copy->r == alone->r, "reused %d, basis %d and %d", copy->setup_reused, copy->r,
              alone->r);
        double e = 0, s = 0;
        for (int k = 0; k < copy->r && k < alone->r; k++)
            e = fmax(e, fabs(copy->a[k] - alone->a[k])), s = fmax(s, fabs(copy->fi[k]));
        CHECK(e <= 1e-9 && s <= 1e-6, "start: acceleration off by %g, internal force %g at rest", e, s);
    }
    gal_rom_free(copy);
    gal_rom_free(alone);
    gal_rom_free(setup);
}

/* The mass norm of c less its part in the basis V (M-orthonormal columns). */
static double norm_outside(const gal_rom *m, double *c, double *Mc)
{
    int n = m->ndof;
    gal_rod_mass_mult(m->rod, c, Mc);
    for (int k = 0; k < m->r; k++) {
        double p = 0;
        for (int d = 0; d < n; d++) p += m->V[(size_t)k * n + d] * Mc[d];
        for (int d = 0; d < n; d++) c[d] -= p * m->V[(size_t)k * n + d];
    }
    gal_rod_mass_mult(m->rod, c, Mc);
    double s = 0;
    for (int d = 0; d < n; d++) s += c[d] * Mc[d];
    return sqrt(s);
}

/* The cubic indicator (gal_rom_cubic) against the test's own construction of the same term by
 * another route: the third derivative of the rod's gradient along w = Phi eta by a five-point
 * difference of gradients (not of tangents), c = -(1/6) K0^-1 d3/ds3 grad U(q_eq + s w); the
 * indicator is the mass norm of c outside the basis (within 2%), it grows as the cube of the
 * amplitude, and with c itself in the basis it reads nothing. */
static void cubic_indicator(const gal_rod *rod, const double *q_eq, const gal_modes *md, const int *sel, int ns)
{
    gal_rom_opts o;
    gal_rom_default_opts(&o);
    o.h = 0.02;
    gal_rom *m = gal_rom_alloc(rod, q_eq, md, sel, ns, &o, NULL);
    CHECK(m != NULL, "%s", gal_error_message());
    if (!m) return;
    int n = m->ndof, nq = m->nq;
    double *w = calloc(n, sizeof(double)), *c = calloc(n, sizeof(double)), *Mc = calloc(n, sizeof(double));
    double *q = malloc(nq * sizeof(double)), *g = malloc(nq * sizeof(double)), *gf = malloc(n * sizeof(double));
    static const double eta[4] = {6, -4, 5, 3}, cf[4] = {-1, 2, -2, 1}, sf[4] = {-2, -1, 1, 2};
    memset(m->x, 0, m->r * sizeof(double));
    for (int k = 0; k < m->nmodes && k < 4; k++) {
        m->x[k] = eta[k];
        for (int d = 0; d < n; d++) w[d] += eta[k] * m->V[(size_t)k * n + d];
    }
    double hs = 0.05; /* a fraction of w: w moves the span by metres */
    for (int p = 0; p < 4; p++) {
        memcpy(q, q_eq, nq * sizeof(double));
        for (int d = 0; d < n; d++) q[rod->free_q[d]] += sf[p] * hs * w[d];
        CHECK(gal_rod_eval(rod, q, NULL, g, NULL) == GAL_OK, "%s", gal_error_message());
        gal_rod_gather(rod, g, gf);
        for (int d = 0; d < n; d++) c[d] += -cf[p] * gf[d] / (2 * hs * hs * hs) / 6;
    }
    CHECK(gal_chol_solve(m->chol0, c, c) == GAL_OK, "%s", gal_error_message());
    double ref = norm_outside(m, c, Mc), e1[GAL_FAMILY_COUNT], e2[GAL_FAMILY_COUNT], t1 = 0, t2 = 0;
    CHECK(gal_rom_cubic(m, m->x, e1) == GAL_OK, "%s", gal_error_message());
    for (int k = 0; k < m->nmodes && k < 4; k++) m->x[k] = 2 * eta[k];
    CHECK(gal_rom_cubic(m, m->x, e2) == GAL_OK, "%s", gal_error_message());
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) t1 += e1[f] * e1[f], t2 += e2[f] * e2[f];
    t1 = sqrt(t1), t2 = sqrt(t2);
    CHECK(ref > 0 && t1 > 0, "indicator %g, reference %g", t1, ref);
    CHECK_REL(t1, ref, 0.02);
    CHECK_REL(t2, 8 * t1, 1e-6);
    /* with c (outside V already) as an extra basis vector the indicator at the same state reads nothing */
    o.extra = c, o.nextra = 1;
    gal_rom *m2 = gal_rom_alloc(rod, q_eq, md, sel, ns, &o, NULL);
    CHECK(m2 != NULL, "%s", gal_error_message());
    if (m2) {
        for (int k = 0; k < m2->nmodes && k < 4; k++) m2->x[k] = eta[k];
        CHECK(gal_rom_cubic(m2, m2->x, e2) == GAL_OK, "%s", gal_error_message());
        t2 = 0;
        for (int f = 0; f < GAL_FAMILY_COUNT; f++) t2 += e2[f] * e2[f];
        CHECK(sqrt(t2) < 0.02 * t1, "with the term in the basis: %g, without %g", sqrt(t2), t1);
    }
    gal_rom_free(m2);
    gal_rom_free(m);
    free(w), free(c), free(Mc), free(q), free(g), free(gf);
}

static void test_still(void)
{
    gal_equilibrium eq = {0};
    gal_modes md = {0};
    int sel[8], ns;
    if (sagged_setup(&eq, &md, sel, &ns)) {
        CHECK(0, "%s", gal_error_message());
        return;
    }
    still_span(eq.rod, eq.q, &md, sel, ns);
    copied_setup(eq.rod, eq.q, &md, sel, ns);
    cubic_indicator(eq.rod, eq.q, &md, sel, ns);
    gal_modes_clear(&md);
    gal_equilibrium_clear(&eq);
}

int main(void)
{
    RUN(test_still);
    return CHECK_SUMMARY();
}
