/* test_damping.c: the structural damping as a property of the structure (issue 15): the stated
 * ratio at every mode of the band to round-off, none above it, the same matrix whatever modes a
 * scene selects; the Rayleigh kind gives its ratio at its two fitting frequencies; the modal kind's
 * projection and its product C v bit for bit as one dot at a time. */
#include "check.h"
#include "gallop.h"
#include "gallop/model/damping.h"
#include "gallop/model/model.h"
#include "gallop/modes/modes.h"
#include "gallop/scene/scene.h"
#include "gallop/statics/statics.h"

static int equilibrium(const char *const *ov, int n, gal_equilibrium *eq)
{
    gal_scene sc;
    int st = gal_scene_load(&sc, "data/scenes/iced_gallop.ini", ov, n, NULL);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (st) return st;
    gal_model *m = gal_model_alloc(&sc, &st);
    if (m) st = gal_statics_solve(&m->rod[0].p, m->rod[0].spec, m->rod[0].spec_value, NULL, eq);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    gal_model_free(m);
    return st;
}

/* Every mode of the band gets zeta (and the pairs none), modes above the band get nothing. */
static void test_modal_ratio_in_band(void)
{
    const char *ov[] = {"model.elements=30"};
    gal_equilibrium eq;
    if (equilibrium(ov, 1, &eq)) return;
    double zeta = 0.003;
    gal_damping *c = gal_damping_modal_alloc(eq.rod, eq.q, zeta, 2.0);
    CHECK(c && c->kind == GAL_DAMPING_MODAL, "%s", gal_error_message());
    if (!c) { gal_equilibrium_clear(&eq); return; }
    gal_modes md;
    CHECK(gal_modes_solve(eq.rod, eq.q, c->nb + 4, &md) == GAL_OK, "%s", gal_error_message());
    printf("    (%d modes below %.3g Hz; next %.4g Hz)\n", c->nb, c->band_hz, md.mode[c->nb].frequency_hz);
    CHECK(c->nb >= 6, "band holds %d modes", c->nb);
    int n = eq.rod->ndof, nt = c->nb + 4;
    double worst = 0, off = 0;
    for (int k = 0; k < nt; k++) {
        double r = gal_damping_ratio(c, md.shape + (size_t)k * n, md.mode[k].omega);
        if (k < c->nb) worst = fmax(worst, fabs(r - zeta) / zeta);
        else CHECK(fabs(r) < 1e-9 * zeta, "mode %d above the band (%.4g Hz) gets %.3g", k + 1, md.mode[k].frequency_hz, r);
    }
    CHECK(worst < 1e-9, "relative error of the band ratios %.3g", worst);
    double *P = malloc((size_t)nt * nt * sizeof(double));
    CHECK(gal_damping_project(c, md.shape, nt, P) == GAL_OK, "project");
    for (int a = 0; a < nt; a++)
        for (int b = 0; b < nt; b++) {
            double want = (a == b && a < c->nb) ? 2 * zeta * md.mode[a].omega : 0;
            off = fmax(off, fabs(P[(size_t)b * nt + a] - want));
        }
    CHECK(off < 1e-9 * 2 * zeta * md.mode[0].omega, "Phi^T C Phi off diag(2 zeta w) by %.3g", off);
    free(P);
    gal_modes_clear(&md);
    gal_damping_free(c);
    gal_equilibrium_clear(&eq);
}

/* The modal kind's projection, its dots taken several at a time, equals one dot at a time summed in
 * order, bit for bit, for every count of basis columns (odd and even) against the band's. */
static void project_bitwise(const gal_equilibrium *eq, double band_hz)
{
    gal_damping *c = gal_damping_modal_alloc(eq->rod, eq->q, 0.003, band_hz);
    gal_modes md;
    CHECK(c && gal_modes_solve(eq->rod, eq->q, c->nb + 5, &md) == GAL_OK, "%s", gal_error_message());
    if (!c) return;
    int n = eq->rod->ndof, nt = c->nb + 5, same = 1;
    double *P = malloc((size_t)nt * nt * sizeof(double)), *B = malloc((size_t)nt * c->nb * sizeof(double));
    for (int nbasis = 1; nbasis <= nt; nbasis += nbasis < 4 ? 1 : nt - 4) {
        CHECK(gal_damping_project(c, md.shape, nbasis, P) == GAL_OK, "project %d", nbasis);
        for (int a = 0; a < nbasis; a++)
            for (int k = 0; k < c->nb; k++) {
                double s = 0;
                for (int j = 0; j < n; j++) s += c->mphi[(size_t)k * n + j] * md.shape[(size_t)a * n + j];
                B[a * c->nb + k] = s;
            }
        for (int a = 0; a < nbasis; a++)
            for (int b = 0; b < nbasis; b++) {
                double s = 0;
                for (int k = 0; k < c->nb; k++) s += 2 * c->zeta * c->omega[k] * B[a * c->nb + k] * B[b * c->nb + k];
                same &= P[(size_t)b * nbasis + a] == s;
            }
    }
    printf("    (%d band modes; 1, 2, 3, 4 and %d basis columns)\n", c->nb, nt);
    CHECK(same, "%d band modes: the projection differs from one dot at a time", c->nb);
    free(P), free(B);
    gal_modes_clear(&md);
    gal_damping_free(c);
}

static void test_project_bitwise(void)
{
    const char *ov[] = {"model.elements=30"};
    gal_equilibrium eq;
    if (equilibrium(ov, 1, &eq)) return;
    project_bitwise(&eq, 2.0);
    project_bitwise(&eq, 1.75);
    project_bitwise(&eq, 1.5);
    gal_equilibrium_clear(&eq);
}

/* C v, its band modes taken four at a time, equals one mode at a time in order bit for bit (y
 * added to, not overwritten), for bands of every count modulo 4. */
static void test_apply_bitwise(void)
{
    const char *ov[] = {"model.elements=30"};
    gal_equilibrium eq;
    if (equilibrium(ov, 1, &eq)) return;
    int n = eq.rod->ndof, seen = 0, same = 1;
    double *v = malloc((size_t)3 * n * sizeof(double)), *y = v + n, *z = v + 2 * n;
    for (double band = 0.5; band <= 3.0 && v; band += 0.125) {
        gal_damping *c = gal_damping_modal_alloc(eq.rod, eq.q, 0.004, band);
        CHECK(c && c->kind == GAL_DAMPING_MODAL, "%s", gal_error_message());
        if (!c) break;
        seen |= 1 << (c->nb % 4);
        for (int j = 0; j < n; j++) v[j] = sin(0.37 * j + band), y[j] = z[j] = cos(0.11 * j);
        gal_damping_apply(c, v, y);
        for (int k = 0; k < c->nb; k++) {
            const double *m = c->mphi + (size_t)k * n;
            double s = 0;
            for (int j = 0; j < n; j++) s += m[j] * v[j];
            s *= 2 * c->zeta * c->omega[k];
            for (int j = 0; j < n; j++) z[j] += s * m[j];
        }
        for (int j = 0; j < n; j++) same &= y[j] == z[j];
        gal_damping_free(c);
    }
    printf("    (band counts modulo 4 seen: mask %#x)\n", seen);
    CHECK(seen == 0xf, "the bands tried cover only the counts mod 4 of mask %#x", seen);
    CHECK(same, "C v four modes at a time differs from one mode at a time");
    free(v);
    gal_equilibrium_clear(&eq);
}

/* The damping does not depend on the modes a scene selects: C v the same to round-off. */
static void test_selection_independent(void)
{
    const char *ova[] = {"model.elements=30", "model.modes_vertical=1", "model.modes_horizontal=0", "model.modes_torsional=0"};
    const char *ovb[] = {"model.elements=30", "model.modes_vertical=6", "model.modes_horizontal=4", "model.modes_torsional=3"};
    gal_equilibrium ea, eb;
    if (equilibrium(ova, 4, &ea)) return;
    if (equilibrium(ovb, 4, &eb)) { gal_equilibrium_clear(&ea); return; }
    gal_damping *ca = gal_damping_modal_alloc(ea.rod, ea.q, 0.01, 0);
    gal_damping *cb = gal_damping_modal_alloc(eb.rod, eb.q, 0.01, 0);
    CHECK(ca && cb, "%s", gal_error_message());
    if (ca && cb) {
        CHECK(ca->nb == cb->nb, "%d vs %d band modes", ca->nb, cb->nb);
        CHECK(ca->band_hz == GAL_DAMPING_BAND_HZ, "default band %g Hz", ca->band_hz);
        int n = ea.rod->ndof;
        double *v = malloc((size_t)3 * n * sizeof(double)), *ya = v + n, *yb = v + 2 * n, d = 0, s = 0;
        for (int j = 0; j < n; j++) v[j] = sin(0.37 * j + 1), ya[j] = yb[j] = 0;
        gal_damping_apply(ca, v, ya);
        gal_damping_apply(cb, v, yb);
        for (int j = 0; j < n; j++) d = fmax(d, fabs(ya[j] - yb[j])), s = fmax(s, fabs(ya[j]));
        CHECK(d <= 1e-10 * s, "C v differs by %.3g of %.3g", d, s);
        free(v);
    }
    gal_damping_free(ca);
    gal_damping_free(cb);
    gal_equilibrium_clear(&ea);
    gal_equilibrium_clear(&eb);
}

/* Rayleigh: zeta at the two fitting frequencies, less between them. */
static void test_rayleigh(void)
{
    const char *ov[] = {"model.elements=30"};
    gal_equilibrium eq;
    if (equilibrium(ov, 1, &eq)) return;
    gal_modes md;
    CHECK(gal_modes_solve(eq.rod, eq.q, 6, &md) == GAL_OK, "%s", gal_error_message());
    double a, b, zeta = 0.02, w1 = md.mode[0].omega, w2 = md.mode[5].omega;
    gal_damping_rayleigh_fit(zeta, w1, w2, &a, &b);
    gal_damping *c = gal_damping_rayleigh_alloc(eq.rod, eq.q, a, b);
    CHECK(c && c->kind == GAL_DAMPING_RAYLEIGH, "%s", gal_error_message());
    if (c) {
        int n = eq.rod->ndof;
        CHECK_REL(gal_damping_ratio(c, md.shape, w1), zeta, 1e-9);
        CHECK_REL(gal_damping_ratio(c, md.shape + (size_t)5 * n, w2), zeta, 1e-9);
        CHECK(gal_damping_ratio(c, md.shape + (size_t)2 * n, md.mode[2].omega) < zeta, "between the fitting frequencies");
    }
    gal_damping *z = gal_damping_modal_alloc(eq.rod, eq.q, 0, 0);
    CHECK(z && z->kind == GAL_DAMPING_NONE, "zeta 0: no damping");
    gal_damping_free(z);
    gal_damping_free(c);
    gal_modes_clear(&md);
    gal_equilibrium_clear(&eq);
}

int main(void)
{
    RUN(test_modal_ratio_in_band);
    RUN(test_project_bitwise);
    RUN(test_apply_bitwise);
    RUN(test_selection_independent);
    RUN(test_rayleigh);
    return CHECK_SUMMARY();
}
