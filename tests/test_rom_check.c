/* test_rom_check.c: the reduced model's self-check on a still span (rom_check.c): the scale of each
 * translational family has a floor with a physical meaning, the response K0^-1 W to a load of
 * GAL_ROM_CHECK_LOAD times the span's weight along the family (horizontally: the span swung by
 * that fraction of its sag, checked against the pendulum's swing), so that a span at rest gives a
 * residual of round-off, not an alarm; and a model on a copied set-up starts from the equilibrium
 * (its start's acceleration is the one of the model computed alone, not heap garbage). */
#include "check.h"
#include "gallop.h"
#include "gallop/modes/modes.h"
#include "gallop/reduced/rom_adapt.h"
#include "gallop/statics/statics.h"
#include "rom_sagged.h"


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
    gal_modes_clear(&md);
    gal_equilibrium_clear(&eq);
}

int main(void)
{
    RUN(test_still);
    return CHECK_SUMMARY();
}
