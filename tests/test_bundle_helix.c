/* test_bundle_helix.c: the equivalent bundle's torsional stiffness from its sub-conductors' tension
 * (src/rod/bundle.c) at large twist: each node's energy is the helix's, (lbar/2) EA/2 ((eps +
 * R^2 tau^2/2)^2 - eps^2) with tau = 2 m / lbar, quartic term included (without it the energy had
 * no lower bound: a large twist rate compressed the element, quad_bundle_gallop.ini run to 1200 s
 * folded back at the yoke); the gradient and tangent of the node and clamp terms against finite
 * differences where the quartic term outweighs the tension's. */
#include "check.h"
#include "gallop.h"
#include "rod_fd.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int term_index(const gal_rod *rod, const gal_rod_term *t)
{
    for (int k = 0; k < rod->nterm; k++)
        if (rod->term[k] == t) return k;
    return -1;
}

/* A straight rod of 10 elements stretched by eps, twists theta_j (edges) alternating so that every
 * interior node has the same twist difference m; R^2 = 0.1 m^2. */
static gal_rod *straight(double eps, double m, double **qout)
{
    int nel = 10;
    gal_rod_params p = {.length = 100, .elements = nel, .unstretched_length = 100 / (1 + eps), .EA = 1e8, .EI = 50,
                        .GJ = 300, .mass = 1.5, .polar_inertia = 2e-4, .torsion = 1, .twist_clamped = 1,
                        .bundle_radius2 = 0.1};
    int nq = gal_rod_nq(&p);
    double *q = calloc((size_t)nq, sizeof(double));
    for (int i = 0; i <= nel; i++) q[3 * i] = 10.0 * i;
    gal_rod *rod = gal_rod_alloc(&p, q);
    CHECK(rod != NULL, "%s", gal_error_message());
    for (int j = 0; j < nel; j++) q[3 * (nel + 1) + j] = (j % 2 ? 0.5 : -0.5) * m;
    *qout = q;
    return rod;
}

static void test_helix_energy(void)
{
    double eps = 1e-3, m = 0.4; /* tau = 2 m / lbar = 0.04 1/m: R^2 tau^2 / (4 eps) = 0.04 */
    for (int big = 0; big < 2; big++) {
        if (big) m = 2.0;   /* tau = 0.2 1/m: the quartic term 100 times the tension's */
        double *q;
        gal_rod *rod = straight(eps, m, &q);
        if (!rod) return;
        int k = term_index(rod, &gal_rod_term_bundle_torsion);
        CHECK(k >= 0, "bundle_torsion on");
        double U = 0;
        CHECK(gal_rod_eval_term(rod, k, q, &U, NULL, NULL) == GAL_OK, "%s", gal_error_message());
        double lbar = 2 * rod->l0[0], tau = 2 * m / lbar, R2 = 0.1, e = 10.0 / rod->l0[0] - 1;
        double helix = 9 * (lbar / 2) * 0.5 * 1e8 * ((e + R2 * tau * tau / 2) * (e + R2 * tau * tau / 2) - e * e);
        printf("  twist %.1f rad per node: energy %.9g J, the helix's %.9g J\n", m, U, helix);
        CHECK_REL(U, helix, 1e-12);
        double err[4];
        const gal_rod_term *t[2] = {&gal_rod_term_bundle_torsion, &gal_rod_term_bundle_clamps};
        for (int i = 0; i < 2; i++) {
            int kt = term_index(rod, t[i]);
            if (kt < 0) continue;
            for (int j = 0; j < rod->nq; j++) q[j] += 0.02 * sin(1.7 * j + big); /* off the straight line */
            rod_fd_errors(rod, kt, q, err);
            printf("    (%s: force error %.2g of %.2g, tangent error %.2g of %.2g)\n", t[i]->name, err[0], err[1],
                   err[2], err[3]);
            CHECK(err[0] <= 1e-6 * err[1], "%s: gradient vs FD: %g of %g", t[i]->name, err[0], err[1]);
            CHECK(err[2] <= 1e-5 * err[3], "%s: tangent vs FD: %g of %g", t[i]->name, err[2], err[3]);
        }
        free(q);
        gal_rod_free(rod);
    }
}

int main(void)
{
    RUN(test_helix_energy);
    return CHECK_SUMMARY();
}
