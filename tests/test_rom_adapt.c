/* test_rom_adapt.c: the reduced model's adaptation (rom_adapt.h): a growth keeps the state (the
 * new model starts from the old one's reconstructed rod, unchanged), logs what it added and when
 * (a family's first growth the correction alone, the next the mode too), the twist's norm,
 * carries the counters; the stiff new directions start quasi-static (their reduced force balanced);
 * a basis that cannot grow says what reached its bound and leaves the model as it was; the
 * residual's power along the reconstructed velocity vanishes without hyper-reduction. */
#include "check.h"
#include "base/chol.h"
#include "gallop.h"
#include "gallop/modes/modes.h"
#include "gallop/reduced/rom_adapt.h"
#include "gallop/statics/statics.h"
#include "rom_sagged.h"


static double maxdiff(const double *a, const double *b, int n, double *scale)
{
    double e = 0;
    *scale = 0;
    for (int k = 0; k < n; k++) e = fmax(e, fabs(a[k] - b[k])), *scale = fmax(*scale, fabs(b[k]));
    return e;
}

/* The residual's power along the full velocity, split per family (gal_rom_check.power): the
 * reduced equations are the full ones projected on the basis, so without hyper-reduction the
 * residual does no work along the reconstructed velocity (its families' powers cancel), while each
 * family's alone does not vanish. */
static void residual_power(const gal_rod *rod, const double *q_eq, const gal_modes *md, const int *sel, int ns)
{
    gal_rom_opts o;
    gal_rom_default_opts(&o);
    o.h = 0.02, o.hyper = 0;
    gal_rom *m = gal_rom_alloc(rod, q_eq, md, sel, ns, &o, NULL);
    CHECK(m != NULL, "%s", gal_error_message());
    if (!m) return;
    double *q = malloc((size_t)m->nq * sizeof(double));
    m->x[0] = 0.5 * sqrt(sagged.mass * sagged.length), m->x[2] = 0.3 * sqrt(sagged.mass * sagged.length);
    gal_rom_reconstruct(m, q, NULL);
    CHECK(gal_rom_start(m, 0, q, NULL) == GAL_OK && gal_rom_advance(m, 0.7) == GAL_OK, "%s", gal_error_message());
    gal_rom_check chk;
    CHECK(gal_rom_residual(m, &chk) == GAL_OK, "%s", gal_error_message());
    double sum = 0, mag = 0;
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) sum += chk.power[0][f], mag = fmax(mag, fabs(chk.power[0][f]));
    CHECK(mag > 0, "the families' residual powers vanish");
    CHECK(fabs(sum) <= 1e-8 * mag, "the residual's power %g along the reduced velocity (families up to %g)", sum, mag);
    CHECK(chk.power[1][0] == 0 && chk.power[2][0] == 0, "no load, no damping: %g %g", chk.power[1][0], chk.power[2][0]);
    free(q);
    gal_rom_free(m);
}

static void test_grow(void)
{
    gal_equilibrium eq = {0};
    gal_modes md = {0};
    int sel[8], ns;
    if (sagged_setup(&eq, &md, sel, &ns)) {
        CHECK(0, "%s", gal_error_message());
        return;
    }
    residual_power(eq.rod, eq.q, &md, sel, ns);
    gal_rom_opts o;
    gal_rom_default_opts(&o);
    o.h = 0.02;
    gal_rom_adapt a;
    gal_rom *m;
    CHECK(gal_rom_adapt_init(&a, &m, eq.rod, eq.q, &md, sel, ns, &o, NULL) == GAL_OK, "%s", gal_error_message());
    if (!m) { gal_rom_adapt_clear(&a); gal_modes_clear(&md); gal_equilibrium_clear(&eq); return; }
    a.orbit_vectors = 0; /* the failing instant's direction (the orbit's: tests/test_rom_orbit.c) */
    int nq = m->nq, n = m->ndof, r0 = m->r;
    double *q = malloc(2 * (size_t)nq * sizeof(double)), *q1 = q + nq, *du = malloc((size_t)n * sizeof(double));
    /* a large symmetric vertical motion, some steps on */
    m->x[0] = 0.5 * sqrt(sagged.mass * sagged.length), m->x[1] = 0.3 * sqrt(sagged.mass * sagged.length);
    gal_rom_reconstruct(m, q, NULL);
    CHECK(gal_rom_start(m, 0, q, NULL) == GAL_OK, "%s", gal_error_message());
    CHECK(gal_rom_advance(m, 0.5) == GAL_OK, "%s", gal_error_message());
    gal_rom_check chk;
    CHECK(gal_rom_residual_dir(m, &chk, du) == GAL_OK, "%s", gal_error_message());
    CHECK(chk.max > 0, "a residual");
    gal_rom_reconstruct(m, q, NULL);
    double t = m->t, sc;
    long steps = m->steps;
    /* growth without the relaxation: the same rod, a larger basis, the event logged; a family's
     * first growth is the correction alone, its second adds the mode */
    a.relax = 0;
    CHECK(gal_rom_adapt_grow(&a, &m, &chk, du) == GAL_OK, "%s", gal_error_message());
    gal_rom_reconstruct(m, q1, NULL);
    double e = maxdiff(q1, q, nq, &sc);
    CHECK(e <= 1e-10 * sc, "the state moved by %g of %g at the growth", e, sc);
    CHECK(m->r == r0 + 1 && m->t == t && m->steps == steps, "basis %d -> %d, t %g, steps %ld", r0, m->r, m->t, m->steps);
    CHECK(a.nevents == 1 && a.ev[0].basis_before == r0 && a.ev[0].basis_after == m->r && a.ev[0].t_s == t &&
              a.ev[0].corrections == 1 && a.ev[0].mode_added == -1,
          "event: %d, %d -> %d at %g s, mode %d", a.nevents, a.ev[0].basis_before, a.ev[0].basis_after, a.ev[0].t_s,
          a.ev[0].mode_added);
    /* with the relaxation: the new stiff direction's reduced force balanced, the old coordinates'
     * projection of the rod kept to the relaxation's size */
    CHECK(gal_rom_residual_dir(m, &chk, du) == GAL_OK, "%s", gal_error_message());
    int r1 = m->r;
    /* a stiff correction (a growth adds the tripping family's alone, rom.h gal_rom_residual_family):
     * the static response to an axial load alternating from node to node, stretching */
    memset(q1, 0, (size_t)n * sizeof(double));
    for (int i = 0; i < m->rod->nn; i++) {
        int d0 = m->rod->dof[3 * i];
        double tn[3], ey[3], nv[3];
        if (d0 < 0) continue;
        gal_rod_node_directions(m->rod, m->q_eq, i, tn, ey, nv);
        for (int c = 0; c < 3; c++) q1[d0 + c] = (i % 2 ? 1 : -1) * tn[c];
    }
    CHECK(gal_chol_solve(m->chol0, q1, du) == GAL_OK, "%s", gal_error_message());
    chk.rel[GAL_FAMILY_AXIAL] = chk.max = 2 * chk.max;
    a.relax = 1, a.policy = GAL_ROM_ADD_CORRECTION;
    CHECK(gal_rom_adapt_grow(&a, &m, &chk, du) == GAL_OK, "%s", gal_error_message());
    CHECK(m->r == r1 + 1 && a.nevents == 2 && a.ev[1].mode_added == -1, "basis %d -> %d", r1, m->r);
    double an = 0, amax = 0;
    for (int k = 0; k < m->r; k++) amax = fmax(amax, fabs(m->a[k]));
    an = fabs(m->a[m->r - 1]);
    CHECK(an <= 1e-6 * amax, "the relaxed direction's acceleration %g of %g", an, amax);
    int r05 = m->r;
    CHECK(gal_rom_advance(m, 0.6) == GAL_OK, "%s", gal_error_message());
    CHECK(gal_rom_residual_dir(m, &chk, du) == GAL_OK, "%s", gal_error_message());
    chk.rel[a.ev[0].family] = chk.max = 1; /* the same family fails again */
    a.policy = GAL_ROM_ADD_CORRECTION | GAL_ROM_ADD_MODE, a.relax = 0;
    CHECK(gal_rom_adapt_grow(&a, &m, &chk, du) == GAL_OK, "%s", gal_error_message());
    CHECK(a.nevents == 3 && a.ev[2].mode_added >= 0 && a.ev[2].corrections == 1 && m->r > r05 + 1,
          "second growth: mode %d, basis %d -> %d", a.ev[2].mode_added, r05, m->r);
    CHECK(a.md->mode[a.ev[2].mode_added].family == (a.ev[2].family == GAL_FAMILY_AXIAL ? GAL_FAMILY_VERTICAL : a.ev[2].family),
          "the mode added is of the family of the largest residual");
    /* nothing to add: the model unchanged, the bound named */
    gal_rom *before = m;
    a.policy = 0;
    CHECK(gal_rom_adapt_grow(&a, &m, &chk, du) == GAL_ROM_ELIMIT, "cannot grow");
    CHECK(m == before && a.nevents == 3, "unchanged");
    /* the norm: the twist against 1.5 times its running amplitude (at least a 1-deg half-sine) */
    gal_rom_check c2;
    double amp = a.amp[GAL_FAMILY_TORSIONAL];
    CHECK(gal_rom_adapt_residual(&a, m, &c2, du) == GAL_OK, "%s", gal_error_message());
    double expect = c2.err[GAL_FAMILY_TORSIONAL] / (GAL_ROM_TWIST_WEIGHT * fmax(fmax(amp, c2.disp[GAL_FAMILY_TORSIONAL]),
                                                                              a.twist_floor));
    CHECK_REL(c2.rel[GAL_FAMILY_TORSIONAL], expect, 1e-12);
    CHECK(a.twist_floor > 0 && a.amp[GAL_FAMILY_TORSIONAL] >= amp, "floor %g, amplitude %g", a.twist_floor, amp);
    double mx = 0;
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) mx = fmax(mx, c2.rel[f]);
    CHECK(c2.max == mx, "max %g of %g", c2.max, mx);
    CHECK(strstr(gal_error_message(), "basis grew to") != NULL, "%s", gal_error_message());
    free(q);
    free(du);
    gal_rom_free(m);
    gal_rom_adapt_clear(&a);
    gal_modes_clear(&md);
    gal_equilibrium_clear(&eq);
}

int main(void)
{
    RUN(test_grow);
    return CHECK_SUMMARY();
}
