/* node.c: the node stencil that bending and torsion share: the geometry of the two edges at an
 * interior node (with the fold-back check), and one pass over the nodes that sums the node terms'
 * energies, gradients and Hessians, given over the edge variables e0 = x_i - x_{i-1},
 * e1 = x_{i+1} - x_i, theta_{i-1}, theta_i, and assembles them into the configuration's gradient
 * and the tangent's values. */
#include "gallop/base/core.h"
#include "rod_impl.h"
#include "gallop/base/vec3.h"

#include <math.h>
#include <string.h>

/* Side `side` of nd (0: edge i-1, e0 = x_i - x_{i-1}; 1: edge i, e1 = x_{i+1} - x_i) at node i:
 * the edge vector, its length, unit tangent and projection; with tw > 0 also the edge's
 * reference director carried to its tangent and the half-angle vector g(tbar, t), with tw == 2
 * its derivative along t times P (gal_rod_node). */
static void edge(const gal_rod *rod, int i, int side, const double *q, int tw, gal_rod_node *nd)
{
    int j = i - 1 + side; /* the edge: x_j -> x_{j+1} */
    double *e = side ? nd->e1 : nd->e0, *t = side ? nd->t1 : nd->t0, *n = side ? &nd->n1 : &nd->n0;
    double(*P)[3] = side ? nd->P1 : nd->P0;
    for (int k = 0; k < 3; k++) e[k] = q[3 * (j + 1) + k] - q[3 * j + k];
    *n = gal_norm3(e);
    for (int k = 0; k < 3; k++) t[k] = e[k] / *n;
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) P[a][b] = (a == b) - t[a] * t[b];
    if (!tw) return;
    const double *tb = rod->tbar + 3 * j;
    gal_rod_transport(tb, rod->abar + 3 * j, t, side ? nd->A1 : nd->A0);
    gal_m33 DB;
    gal_rod_halfrot(tb, t, side ? nd->gB1 : nd->gB0, NULL, tw == 2 ? DB : NULL);
    if (tw == 2) gal_rod_mul33(DB, P, side ? nd->Y1 : nd->Y0);
}

/* What nd holds of the node itself (both sides filled): the fold-back check, lbar and c. */
static int node_of_edges(const gal_rod *rod, int i, gal_rod_node *nd)
{
    double cf = gal_dot3(nd->e0, nd->e1) / (nd->n0 * nd->n1);
    if (!(cf > -0.999))
        return gal_error(GAL_EFAIL, "rod: the rod folds back on itself at node %d", i);
    nd->lbar = rod->l0[i - 1] + rod->l0[i];
    nd->c = gal_dot3(nd->t0, nd->t1);
    return GAL_OK;
}

/* Fill nd; GAL_EFAIL with a message when the rod folds back on itself at node i. */
int gal_rod_node_geometry(const gal_rod *rod, int i, const double *q, gal_rod_node *nd)
{
    nd->tw = 0;
    edge(rod, i, 0, q, 0, nd), edge(rod, i, 1, q, 0, nd);
    return node_of_edges(rod, i, nd);
}

/* Node i + 1's side 0 is node i's side 1 (the same edge): moved over, not computed again. */
static void shift(gal_rod_node *nd)
{
    memcpy(nd->e0, nd->e1, sizeof nd->e0), memcpy(nd->t0, nd->t1, sizeof nd->t0), nd->n0 = nd->n1;
    memcpy(nd->P0, nd->P1, sizeof nd->P0);
    if (!nd->tw) return;
    memcpy(nd->A0, nd->A1, sizeof nd->A0), memcpy(nd->gB0, nd->gB1, sizeof nd->gB0);
    if (nd->tw == 2) memcpy(nd->Y0, nd->Y1, sizeof nd->Y0);
}

/* Node-space incidence of the stencil variables: local node variable a (0..10) is the sum of
 * coef * (edge variable idx). */
static const int inc_n[NL] = {1, 1, 1, 2, 2, 2, 1, 1, 1, 1, 1};
static const int inc_v[NL][2] = {{0, 0}, {1, 0}, {2, 0}, {0, 3}, {1, 4}, {2, 5},
                                 {3, 0}, {4, 0}, {5, 0}, {6, 0}, {7, 0}};
static const double inc_c[NL][2] = {{-1, 0}, {-1, 0}, {-1, 0}, {1, -1}, {1, -1}, {1, -1},
                                    {1, 0},  {1, 0},  {1, 0},  {1, 0},  {1, 0}};

/* The Hessian's incidence unrolled: node-space entry (a, b) = sum over its n terms of
 * c[t] * H[i[t]] (H flat, 8 x 8), the terms in the order of the loops over inc_v[a], then inc_v[b]
 * (the coefficients' products are +-1: each term exact, the same sums as those loops). */
typedef struct hess_plan {
    int n, i[4];
    double c[4];
} hess_plan;

static void plan_build(hess_plan *P)
{
    for (int a = 0; a < NL; a++)
        for (int b = 0; b < NL; b++) {
            hess_plan *p = P + a * NL + b;
            p->n = 0;
            for (int r = 0; r < inc_n[a]; r++)
                for (int t = 0; t < inc_n[b]; t++, p->n++)
                    p->i[p->n] = 8 * inc_v[a][r] + inc_v[b][t], p->c[p->n] = inc_c[a][r] * inc_c[b][t];
        }
}

/* Assemble the stencil gradient g (8) and Hessian H (8 x 8, when K; P its plan) of node i. */
static void assemble(const gal_rod *rod, int i, const double *g, double (*H)[8], const hess_plan *P,
                     double *grad, gal_csc *K)
{
    int qi[NL];
    gal_rod_node_q(rod, i, qi);
    if (grad)
        for (int a = 0; a < NL; a++) {
            if (qi[a] < 0) continue;
            double s = 0;
            for (int r = 0; r < inc_n[a]; r++) s += inc_c[a][r] * g[inc_v[a][r]];
            grad[qi[a]] += s;
        }
    if (K) {
        const int *sm = rod->slot_node + (size_t)(i - 1) * NL * NL;
        const double *Hf = H[0];
        for (int ab = 0; ab < NL * NL; ab++) {
            int sl = sm[ab];
            if (sl < 0) continue;
            const hess_plan *p = P + ab;
            double h = 0 + p->c[0] * Hf[p->i[0]];
            if (p->n > 1) {
                h += p->c[1] * Hf[p->i[1]];
                if (p->n > 2) h += p->c[2] * Hf[p->i[2]], h += p->c[3] * Hf[p->i[3]];
            }
            K->val[sl] += h;
        }
    }
}

/* Side `side` of nd's edge frame (its tangent, then A) into frames + 6 j, j the edge. */
static void keep_frame(const gal_rod_node *nd, int i, int side, double *frames)
{
    double *f = frames + 6 * (i - 1 + side);
    memcpy(f, side ? nd->t1 : nd->t0, 3 * sizeof(double)), memcpy(f + 3, side ? nd->A1 : nd->A0, 3 * sizeof(double));
}

int gal_rod_node_pass(const gal_rod *rod, const gal_rod_term *const *t, int nt, const double *q,
                      double *U, double *grad, gal_csc *K, double *frames, int *framed)
{
    hess_plan P[NL * NL];
    if (K) plan_build(P);
    gal_rod_node nd;
    nd.tw = 0; /* the twist's terms read each edge's frame data, filled once for both its nodes */
    for (int k = 0; k < nt; k++)
        if (t[k] == &gal_rod_term_torsion || t[k] == &gal_rod_term_bundle_torsion) nd.tw = K ? 2 : 1;
    for (int i = 1; i <= rod->nn - 2; i++) {
        if (i == 1) edge(rod, i, 0, q, nd.tw, &nd);
        else shift(&nd);
        edge(rod, i, 1, q, nd.tw, &nd);
        if (frames && nd.tw) {
            if (i == 1) keep_frame(&nd, i, 0, frames);
            keep_frame(&nd, i, 1, frames);
        }
        int st = node_of_edges(rod, i, &nd);
        if (st) return st;
        double g[8], H[8][8], E = 0;
        memset(g, 0, sizeof g);
        if (K) memset(H, 0, sizeof H);
        for (int k = 0; k < nt; k++) E += t[k]->node(rod, i, q, &nd, g, K ? H : NULL);
        *U += E;
        assemble(rod, i, g, H, P, grad, K);
    }
    if (frames && nd.tw && rod->nn > 2) *framed = 1;
    return GAL_OK;
}

int gal_rod_node_local(const gal_rod *rod, const gal_rod_term *const *t, int nt, int i, const double *q,
                       double *U, double *g11, double *H11)
{
    gal_rod_node nd;
    int st = gal_rod_node_geometry(rod, i, q, &nd);
    if (st) return st;
    double g[8], H[8][8];
    memset(g, 0, sizeof g);
    if (H11) memset(H, 0, sizeof H);
    for (int k = 0; k < nt; k++) *U += t[k]->node(rod, i, q, &nd, g, H11 ? H : NULL);
    /* node variable a = sum_r inc_c[a][r] * edge variable inc_v[a][r] */
    for (int a = 0; a < NL; a++) {
        double s = 0;
        for (int r = 0; r < inc_n[a]; r++) s += inc_c[a][r] * g[inc_v[a][r]];
        g11[a] += s;
    }
    if (H11)
        for (int a = 0; a < NL; a++)
            for (int b = 0; b < NL; b++) {
                double h = 0;
                for (int r = 0; r < inc_n[a]; r++)
                    for (int c = 0; c < inc_n[b]; c++) h += inc_c[a][r] * inc_c[b][c] * H[inc_v[a][r]][inc_v[b][c]];
                H11[a * NL + b] += h;
            }
    return GAL_OK;
}
