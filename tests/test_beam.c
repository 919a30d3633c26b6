/* test_beam.c: bending against beam theory, an analytic reference the cable tests cannot give
 * (a sagged conductor's frequencies hardly feel EI). A straight span without gravity under
 * tension H is a pinned-pinned beam-string (the discrete rod's curvature lives at interior nodes,
 * the supports fix positions only):
 *   w_n = (n pi / L)^2 sqrt(EI / m) sqrt(1 + H L^2 / (n^2 pi^2 EI))
 * (e.g. Blevins, Formulas for Natural Frequency and Mode Shape, beam with axial load). Also the
 * direction labels of a straight span: "vertical" is z, "horizontal" is y. */
#include "check.h"
#include "gallop.h"
#include "gallop/modes/modes.h"
#include "gallop/statics/statics.h"

#define L 10.0
#define B_EI 2.0e4
#define B_MASS 1.6
#define B_H 1000.0

static double beam_hz(int n)
{
    double k = n * GAL_PI / L;
    return k * k * sqrt(B_EI / B_MASS) * sqrt(1 + B_H / (k * k * B_EI)) / (2 * GAL_PI);
}

static int solve(int nel, gal_equilibrium *eq, gal_modes *md)
{
    gal_rod_params p = {.length = L, .elements = nel, .EA = 3e7, .EI = B_EI, .GJ = 100, .mass = B_MASS,
                        .polar_inertia = 1e-4, .gravity = 0, .torsion = 0, .twist_clamped = 1};
    int st = gal_statics_solve(&p, GAL_BY_TENSION, B_H, NULL, eq);
    CHECK(st == GAL_OK, "statics: %s", gal_error_message());
    if (st) return st;
    int want[GAL_FAMILY_COUNT] = {3, 3, 0, 0};
    st = gal_modes_find(eq->rod, eq->q, want, 200, md);
    CHECK(st == GAL_OK, "modes: %s", gal_error_message());
    if (st) gal_equilibrium_clear(eq);
    return st;
}

/* n-th (1-based) frequency of family f */
static double family_hz(const gal_modes *md, gal_family f, int n)
{
    for (int i = 0; i < md->n; i++)
        if (md->mode[i].family == f && --n == 0) return md->mode[i].frequency_hz;
    return NAN;
}

/* The first three frequencies of both families against the beam-string; the error of a central
 * difference of the curvature falls as h^2: about (n pi / N)^2 / 12 at N elements (x1.5 here). */
static void test_beam_string_frequencies(void)
{
    gal_equilibrium eq;
    gal_modes md;
    if (solve(100, &eq, &md)) return;
    for (int n = 1; n <= 3; n++) {
        double ref = beam_hz(n), tol = 1.5 * pow(n * GAL_PI / 100, 2) / 12 + 1e-5; /* achieved 4e-5, 2.8e-4, 6.9e-4 */
        CHECK_REL(family_hz(&md, GAL_FAMILY_VERTICAL, n), ref, tol);
        CHECK_REL(family_hz(&md, GAL_FAMILY_HORIZONTAL, n), ref, tol);
        printf("    (n = %d: vertical %.6f Hz, horizontal %.6f Hz, beam-string %.6f Hz, string alone %.6f Hz)\n",
               n, family_hz(&md, GAL_FAMILY_VERTICAL, n), family_hz(&md, GAL_FAMILY_HORIZONTAL, n), ref,
               n * sqrt(B_H / B_MASS) / (2 * L));
    }
    gal_modes_clear(&md);
    gal_equilibrium_clear(&eq);
}

/* Refining the mesh, the error of the first mode falls at second order. */
static void test_beam_convergence(void)
{
    double err[2];
    int nels[2] = {25, 50};
    for (int k = 0; k < 2; k++) {
        gal_equilibrium eq;
        gal_modes md;
        if (solve(nels[k], &eq, &md)) return;
        err[k] = fabs(family_hz(&md, GAL_FAMILY_VERTICAL, 2) / beam_hz(2) - 1);
        gal_modes_clear(&md);
        gal_equilibrium_clear(&eq);
    }
    double order = log2(err[0] / err[1]);
    printf("    (2nd mode errors %.2e at 25, %.2e at 50 elements: order %.2f)\n", err[0], err[1], order);
    CHECK(order > 1.8 && order < 2.2, "order %g", order);
}

/* On a straight span the families are directions: a mode called vertical moves in z, one called
 * horizontal in y (no sag to tell them apart by the plane). */
static void test_straight_span_directions(void)
{
    gal_equilibrium eq;
    gal_modes md;
    if (solve(40, &eq, &md)) return;
    const gal_rod *rod = eq.rod;
    double *full = calloc((size_t)rod->nq, sizeof(double));
    for (int i = 0; i < md.n; i++) {
        if (md.mode[i].family != GAL_FAMILY_VERTICAL && md.mode[i].family != GAL_FAMILY_HORIZONTAL) continue;
        memset(full, 0, (size_t)rod->nq * sizeof(double));
        gal_rod_scatter(rod, md.shape + (size_t)i * md.ndof, full);
        double y2 = 0, z2 = 0;
        for (int k = 0; k < rod->nn; k++) y2 += full[3 * k + 1] * full[3 * k + 1], z2 += full[3 * k + 2] * full[3 * k + 2];
        double zshare = z2 / (y2 + z2);
        if (md.mode[i].family == GAL_FAMILY_VERTICAL)
            CHECK(zshare > 0.999, "mode %d called vertical has z share %g", i, zshare);
        else
            CHECK(zshare < 1e-3, "mode %d called horizontal has z share %g", i, zshare);
    }
    free(full);
    gal_modes_clear(&md);
    gal_equilibrium_clear(&eq);
}

int main(void)
{
    RUN(test_beam_string_frequencies);
    RUN(test_beam_convergence);
    RUN(test_straight_span_directions);
    return CHECK_SUMMARY();
}
