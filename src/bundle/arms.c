/* arms.c: flexible spacers ([bundle] spacer_stiffness > 0; README "Flexible spacers"): each
 * sub-conductor's node at a spacer is a free node of its rod, tied to its clamp point on the
 * spacer frame, a = u + R off_r, by the arm: a spring of stiffness k (N/m, the same in every
 * direction) on x - a, and a spring of stiffness k r^2 (N m/rad, r the bundle's radius) on the
 * node's twist (the mean of its two edges') less the frame's accumulated rotation psi_r about the
 * sub-conductor's tangent: the arm as a lever of length r hinged on the frame, whose clamp turns
 * with it. As k grows the two springs become the rigid spacers' constraints (system.c). */
#include "gallop/bundle/bundle.h"
#include "gallop/base/core.h"
#include "gallop/base/vec3.h"
#include "bundle_impl.h"

#include <string.h>

#define COLS (6 + 3) /* x (3), u (3), the frame's rotation (up to 3) */

/* The system's dof of rod r's configuration entry q (free: the node of a flexible spacer is). */
static int sys_dof(const gal_bundle *b, int r, int q)
{
    int d = b->rod[r]->dof[q];
    return d < 0 ? -1 : b->tidx[r][4 * d];
}

/* Adds c_a c_b w over the pairs of columns to the tangent (the pattern when k->pairs). */
static void outer(gal_bundle_sink *k, const int *idx, const double *c, int nc, double w)
{
    for (int a = 0; a < nc; a++)
        for (int e = a; e < nc; e++)
            if (idx[a] >= 0 && idx[e] >= 0) gal_bundle_put(k, idx[a], idx[e], w * c[a] * c[e]);
}

/* The translation spring of sub-conductor r at spacer sp: energy, gradient, tangent. */
static double arm_translation(const gal_bundle *b, const double *s, int sp, int r, double *grad, gal_bundle_sink *k)
{
    const double *R = SP_R(b, s, sp), *u = SP_U(b, s, sp);
    const double *x = gal_bundle_q(b, (double *)s, r) + 3 * b->spnode[sp];
    double ks = b->bp.spacer_stiffness, E[3][3], p[3], d[3], B[3][COLS];
    int nr = gal_bundle_basis(b, s, sp, E), u0 = b->sp0 + (3 + b->nrot) * sp, idx[COLS], nc = 6 + nr;
    for (int c = 0; c < 3; c++) {
        p[c] = R[3 * c] * b->off[r][0] + R[3 * c + 1] * b->off[r][1] + R[3 * c + 2] * b->off[r][2];
        d[c] = x[c] - u[c] - p[c];
        idx[c] = sys_dof(b, r, 3 * b->spnode[sp] + c), idx[3 + c] = u0 + c;
    }
    memset(B, 0, sizeof B);
    for (int c = 0; c < 3; c++) B[c][c] = 1.0, B[c][3 + c] = -1.0;
    for (int j = 0; j < nr; j++) {
        double ep[3];
        gal_cross3(E[j], p, ep);
        idx[6 + j] = u0 + 3 + j;
        for (int c = 0; c < 3; c++) B[c][6 + j] = -ep[c];
    }
    for (int col = 0; grad && col < nc; col++)
        for (int c = 0; c < 3 && idx[col] >= 0; c++) grad[idx[col]] += ks * B[c][col] * d[c];
    if (k) {
        for (int c = 0; c < 3; c++) outer(k, idx, B[c], nc, ks);
        double f[3] = {-ks * d[0], -ks * d[1], -ks * d[2]}; /* the energy's gradient on the clamp point */
        gal_bundle_geometric(b, s, sp, r, f, k);
    }
    return 0.5 * ks * gal_dot3(d, d);
}

/* The twist spring of sub-conductor r at spacer sp (psi's own second derivative neglected, as the
 * rigid spacers' map does). */
static double arm_twist(const gal_bundle *b, const double *s, int sp, int r, double *grad, gal_bundle_sink *k)
{
    int i = b->spnode[sp], nn = b->nn, u0 = b->sp0 + (3 + b->nrot) * sp, idx[5];
    const double *q = gal_bundle_q(b, (double *)s, r);
    double kt = b->bp.spacer_stiffness * b->bp.radius * b->bp.radius, E[3][3], t[3], c[5];
    int nr = gal_bundle_basis(b, s, sp, E), nc = 2 + nr;
    gal_bundle_tangent(b, q, i, t);
    double e = 0.5 * (q[3 * nn + i - 1] + q[3 * nn + i]) - SP_PSI(b, s, sp)[r];
    idx[0] = sys_dof(b, r, 3 * nn + i - 1), idx[1] = sys_dof(b, r, 3 * nn + i), c[0] = c[1] = 0.5;
    for (int j = 0; j < nr; j++) idx[2 + j] = u0 + 3 + j, c[2 + j] = -gal_dot3(t, E[j]);
    for (int a = 0; grad && a < nc; a++)
        if (idx[a] >= 0) grad[idx[a]] += kt * e * c[a];
    if (k) outer(k, idx, c, nc, kt);
    return 0.5 * kt * e * e;
}

double gal_bundle_arms(const gal_bundle *b, const double *s, double *grad, gal_bundle_sink *k)
{
    double U = 0;
    for (int sp = 0; sp < b->ns; sp++)
        for (int r = 0; r < b->n; r++)
            U += arm_translation(b, s, sp, r, grad, k) + arm_twist(b, s, sp, r, grad, k);
    return U;
}
