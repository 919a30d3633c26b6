/* bundle.c: the torsional stiffness that the sub-conductors' tension gives a bundle carried as one
 * rod (the equivalent bundle model, [bundle] model = equivalent). A sub-conductor at radius R from
 * the bundle axis follows a helix when the bundle twists at the rate tau: its strain grows from
 * eps to eps + R^2 tau^2 / 2, so the bundle's axial energy EA/2 (eps + R^2 tau^2 / 2)^2 per length
 * (EA the bundle's, the sum over its sub-conductors) holds the cross term EA eps R^2 tau^2 / 2 =
 * T R^2 tau^2 / 2, T the bundle's tension: a torsional stiffness T R^2 that moves with the tension,
 * and the quartic term EA R^4 tau^4 / 8. The quartic term is small beside the other (by
 * R^2 tau^2 / (4 eps), below 1e-3 for a conductor in tension at small twist) but it bounds the energy
 * from below: without it, minimizing over eps at a fixed tau gives -EA R^4 tau^4 / 8, so that a large
 * enough twist rate (3/2 EA R^2 tau^2 > T) lowered the energy by compressing the element, a spurious
 * local collapse (`quad_bundle_gallop.ini` run to 1200 s folded back at the yoke; README "Bundles").
 * Discretized as the twist energy of torsion.c with GJ replaced by EA eps_bar R^2: at each interior
 * node U = EA R^2 eps_bar m^2 / lbar + EA R^4 m^4 / lbar^3 (tau = 2 m / lbar over lbar / 2), eps_bar
 * the mean strain of the node's two edges; with the twist clamped at the supports (the yokes hold
 * the sub-conductors), EA R^2 eps theta^2 / l0 + EA R^4 theta^4 / l0^3 for each end edge (tau =
 * 2 theta / l0 over l0 / 2). Gradient and Hessian in closed form. */
#include "gallop/base/core.h"
#include "rod_impl.h"
#include "gallop/base/vec3.h"

#include <math.h>
#include <string.h>

/* The node term: c eps_bar m^2, c = EA R^2 / lbar. */
static double node(const gal_rod *rod, int i, const double *q, const gal_rod_node *nd, double *g,
                   double (*H)[8])
{
    gal_rod_twist s;
    gal_rod_twist_strain(rod, i, q, nd, H != NULL, &s);
    double la = rod->l0[i - 1], lb = rod->l0[i];
    double c = rod->p.EA * rod->p.bundle_radius2 / nd->lbar;
    double eb = 0.5 * (nd->n0 / la + nd->n1 / lb) - 1.0;
    double ge[8] = {0}; /* d eps_bar over (e0, e1, theta0, theta1) */
    for (int k = 0; k < 3; k++) ge[k] = nd->t0[k] / (2 * la), ge[3 + k] = nd->t1[k] / (2 * lb);
    double m = s.m, c4 = c * rod->p.bundle_radius2 / (nd->lbar * nd->lbar); /* EA R^4 / lbar^3 */
    for (int a = 0; a < 8; a++) g[a] += c * (m * m * ge[a] + 2 * eb * m * s.gm[a]) + 4 * c4 * m * m * m * s.gm[a];
    if (H) {
        /* 2 (c eps_bar + 2 c4 m^2) (gm gm^T + m d2m), then the rest of 12 c4 m^2 gm gm^T */
        gal_rod_twist_hessian(nd, &s, c * eb + 2 * c4 * m * m, H);
        for (int a = 0; a < 8; a++)
            for (int b = 0; b < 8; b++) H[a][b] += 8 * c4 * m * m * s.gm[a] * s.gm[b];
        for (int a = 0; a < 8; a++)
            for (int b = 0; b < 8; b++) H[a][b] += 2 * c * m * (ge[a] * s.gm[b] + s.gm[a] * ge[b]);
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                H[a][b] += c * m * m * nd->P0[a][b] / (2 * la * nd->n0);
                H[3 + a][3 + b] += c * m * m * nd->P1[a][b] / (2 * lb * nd->n1);
            }
    }
    return c * eb * m * m + c4 * m * m * m * m;
}

/* Add the local Hessian Hl over node i's stencil (x_{i-1}, x_i, x_{i+1}, theta_{i-1}, theta_i)
 * to K on the stencil's slots. */
static void add_node_block(const gal_rod *rod, int i, double (*Hl)[NL], gal_csc *K)
{
    const int *sm = rod->slot_node + (size_t)(i - 1) * NL * NL;
    for (int a = 0; a < NL; a++)
        for (int b = 0; b < NL; b++)
            if (sm[a * NL + b] >= 0) K->val[sm[a * NL + b]] += Hl[a][b];
}

/* The clamps: end edge j (nodes j, j + 1, twist theta_j), U = c eps theta^2, c = EA R^2 / l0. */
static int clamps(const gal_rod *rod, const double *q, double *U, double *grad, gal_csc *K)
{
    int nel = rod->p.elements, nn = rod->nn;
    for (int side = 0; side < 2; side++) {
        int j = side ? nel - 1 : 0, k = 3 * nn + j;
        double l0 = rod->l0[j], c = rod->p.EA * rod->p.bundle_radius2 / l0, e[3], t[3];
        for (int d = 0; d < 3; d++) e[d] = q[3 * (j + 1) + d] - q[3 * j + d];
        double le = gal_norm3(e), eps = le / l0 - 1.0, th = q[k], c4 = c * rod->p.bundle_radius2 / (l0 * l0);
        if (!(le > 1e-12 * l0)) return gal_error(GAL_EFAIL, "rod: element %d has collapsed (length %g m)", j, le);
        for (int d = 0; d < 3; d++) t[d] = e[d] / le;
        *U += c * eps * th * th + c4 * th * th * th * th;
        if (grad) {
            for (int d = 0; d < 3; d++) {
                double gd = c * th * th * t[d] / l0; /* dU/de */
                grad[3 * j + d] -= gd;
                grad[3 * (j + 1) + d] += gd;
            }
            grad[k] += 2 * c * eps * th + 4 * c4 * th * th * th;
        }
        if (K && nel >= 2) {
            /* node i's stencil holds edge j: edge 0 is (x_0, x_1, theta_0) of node 1's, locals 0-5
             * and 9; edge nel-1 is (x_{nel-1}, x_nel, theta_{nel-1}) of node nel-1's, 3-8 and 10 */
            int i = side ? nel - 1 : 1, x0 = side ? 3 : 0, x1 = x0 + 3, tl = side ? 10 : 9;
            double Hl[NL][NL];
            memset(Hl, 0, sizeof Hl);
            for (int a = 0; a < 3; a++) {
                for (int b = 0; b < 3; b++) {
                    double h = c * th * th * ((a == b) - t[a] * t[b]) / (l0 * le);
                    Hl[x0 + a][x0 + b] += h, Hl[x1 + a][x1 + b] += h;
                    Hl[x0 + a][x1 + b] -= h, Hl[x1 + a][x0 + b] -= h;
                }
                double hx = 2 * c * th * t[a] / l0;
                Hl[x1 + a][tl] += hx, Hl[tl][x1 + a] += hx;
                Hl[x0 + a][tl] -= hx, Hl[tl][x0 + a] -= hx;
            }
            Hl[tl][tl] += 2 * c * eps + 12 * c4 * th * th;
            add_node_block(rod, i, Hl, K);
        }
    }
    return GAL_OK;
}

/* The clamp's share on edge j alone (an end edge), over (x_j, x_{j+1}, theta_j): the same energy. */
static int clamp_edge(const gal_rod *rod, int j, const double *q, double *U, double *g, double (*H)[7])
{
    int nel = rod->p.elements;
    for (int side = 0; side < 2; side++) {
        if (j != (side ? nel - 1 : 0)) continue;
        double l0 = rod->l0[j], c = rod->p.EA * rod->p.bundle_radius2 / l0, e[3], t[3];
        for (int d = 0; d < 3; d++) e[d] = q[3 * (j + 1) + d] - q[3 * j + d];
        double le = gal_norm3(e), eps = le / l0 - 1.0, th = q[3 * rod->nn + j], c4 = c * rod->p.bundle_radius2 / (l0 * l0);
        if (!(le > 1e-12 * l0)) return gal_error(GAL_EFAIL, "rod: element %d has collapsed (length %g m)", j, le);
        for (int d = 0; d < 3; d++) t[d] = e[d] / le;
        *U += c * eps * th * th + c4 * th * th * th * th;
        for (int d = 0; d < 3; d++) g[d] -= c * th * th * t[d] / l0, g[3 + d] += c * th * th * t[d] / l0;
        g[6] += 2 * c * eps * th + 4 * c4 * th * th * th;
        if (!H) continue;
        for (int a = 0; a < 3; a++) {
            for (int b = 0; b < 3; b++) {
                double h = c * th * th * ((a == b) - t[a] * t[b]) / (l0 * le);
                H[a][b] += h, H[3 + a][3 + b] += h, H[a][3 + b] -= h, H[3 + a][b] -= h;
            }
            double hx = 2 * c * th * t[a] / l0;
            H[3 + a][6] += hx, H[6][3 + a] += hx, H[a][6] -= hx, H[6][a] -= hx;
        }
        H[6][6] += 2 * c * eps + 12 * c4 * th * th;
    }
    return GAL_OK;
}

const gal_rod_term gal_rod_term_bundle_torsion = {"bundle_torsion", NULL, node, NULL};
const gal_rod_term gal_rod_term_bundle_clamps = {"bundle_clamps", clamps, NULL, clamp_edge};
