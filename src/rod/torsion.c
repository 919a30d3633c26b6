/* torsion.c: the twist energy of the discrete rod (paper Eqs. 3-5; Bergou et al. 2010): at each
 * interior node U = GJ (theta_i - theta_{i-1} + mref_i)^2 / lbar_i, mref the reference twist of
 * the reference frames carried to the current tangents; and, with the twist clamped at the
 * supports, GJ theta^2 / l0 for each end edge. Gradient and Hessian in closed form. */
#include "gallop/base/core.h"
#include "rod_impl.h"
#include "gallop/base/vec3.h"

#include <math.h>
#include <string.h>


/* [a]_x b = a x b */
static void skew(const double *a, gal_m33 S)
{
    S[0][0] = 0, S[0][1] = -a[2], S[0][2] = a[1];
    S[1][0] = a[2], S[1][1] = 0, S[1][2] = -a[0];
    S[2][0] = -a[1], S[2][1] = a[0], S[2][2] = 0;
}

void gal_rod_mul33(gal_m33 A, gal_m33 B, gal_m33 C)
{
    gal_m33 T;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) T[i][j] = A[i][0] * B[0][j] + A[i][1] * B[1][j] + A[i][2] * B[2][j];
    memcpy(C, T, sizeof T);
}

/* Half-angle rotation vector between unit vectors: g(u, v) = u x v / (1 + u . v), and its
 * derivatives dg/du = -s [v]_x - s^2 (u x v) v^T, dg/dv = s [u]_x - s^2 (u x v) u^T, s = 1/(1+u.v). */
void gal_rod_halfrot(const double *u, const double *v, double *g, gal_m33 Du, gal_m33 Dv)
{
    double s = 1.0 / (1.0 + gal_dot3(u, v)), w[3];
    gal_cross3(u, v, w);
    for (int k = 0; k < 3; k++) g[k] = s * w[k];
    if (Du) {
        skew(v, Du);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) Du[i][j] = -s * Du[i][j] - s * s * w[i] * v[j];
    }
    if (Dv) {
        skew(u, Dv);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) Dv[i][j] = s * Dv[i][j] - s * s * w[i] * u[j];
    }
}

void gal_rod_twist_strain(const gal_rod *rod, int i, const double *q, const gal_rod_node *nd,
                          int hess, gal_rod_twist *s)
{
    const double *t0 = nd->t0, *t1 = nd->t1;
    const double *tb0 = rod->tbar + 3 * (i - 1), *tb1 = rod->tbar + 3 * i;
    double Aw[2][3], u[3], w[3];
    const double *A0 = nd->A0, *A1 = nd->A1; /* the pass's, per edge (tw > 0) */
    if (!nd->tw) {
        gal_rod_transport(tb0, rod->abar + 3 * (i - 1), t0, Aw[0]); /* reference director of edge i-1 */
        gal_rod_transport(tb1, rod->abar + 3 * i, t1, Aw[1]);        /* and of edge i */
        A0 = Aw[0], A1 = Aw[1];
    }
    gal_rod_transport(t0, A0, t1, u);                         /* edge i-1's carried across node i */
    gal_cross3(u, A1, w);
    double mref = atan2(gal_dot3(w, t1), gal_dot3(u, A1));    /* signed angle u -> A1 about t1 */
    double th0 = q[3 * rod->nn + i - 1], th1 = q[3 * rod->nn + i];
    s->m = th1 - th0 + mref;
    /* d mref/de0 = [g(t0,t1) + g(tb0,t0)]/n0, d mref/de1 = [g(t0,t1) - g(tb1,t1)]/n1: the
     * curvature binormal's share (Bergou et al. 2010) plus the turn of each reference frame
     * about its own tangent as it is carried from the reference tangent */
    gal_rod_halfrot(t0, t1, s->gA, hess ? s->DAu : NULL, hess ? s->DAv : NULL);
    if (nd->tw == 2 || (nd->tw && !hess)) /* the pass's, per edge (the Hessian reads Y0, Y1) */
        memcpy(s->gB0, nd->gB0, sizeof s->gB0), memcpy(s->gB1, nd->gB1, sizeof s->gB1);
    else {
        gal_rod_halfrot(tb0, t0, s->gB0, NULL, hess ? s->DB0 : NULL);
        gal_rod_halfrot(tb1, t1, s->gB1, NULL, hess ? s->DB1 : NULL);
    }
    for (int d = 0; d < 3; d++)
        s->gm[d] = (s->gA[d] + s->gB0[d]) / nd->n0, s->gm[3 + d] = (s->gA[d] - s->gB1[d]) / nd->n1;
    s->gm[6] = -1, s->gm[7] = 1;
}

void gal_rod_twist_hessian(const gal_rod_node *nd, gal_rod_twist *s, double kt,
                           double (*H)[8])
{
    const double n0 = nd->n0, n1 = nd->n1, *t0 = nd->t0, *t1 = nd->t1;
    gal_m33 X0, X1, Yw[2];
    gal_m33 P0, P1;
    memcpy(P0, nd->P0, sizeof P0), memcpy(P1, nd->P1, sizeof P1);
    gal_rod_mul33(s->DAu, P0, X0); /* dA/de0 * n0 */
    gal_rod_mul33(s->DAv, P1, X1); /* dA/de1 * n1 */
    const double(*Y0)[3] = nd->Y0, (*Y1)[3] = nd->Y1; /* the pass's, per edge (tw == 2) */
    if (nd->tw != 2) {
        gal_rod_mul33(s->DB0, P0, Yw[0]); /* dB0/de0 * n0 */
        gal_rod_mul33(s->DB1, P1, Yw[1]); /* dB1/de1 * n1 */
        Y0 = Yw[0], Y1 = Yw[1];
    }
    double Hm[6][6];
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) {
            Hm[a][b] = (X0[a][b] + Y0[a][b]) / (n0 * n0) - (s->gA[a] + s->gB0[a]) * t0[b] / (n0 * n0);
            Hm[a][3 + b] = X1[a][b] / (n0 * n1);
            Hm[3 + a][b] = X0[a][b] / (n0 * n1);
            Hm[3 + a][3 + b] = (X1[a][b] - Y1[a][b]) / (n1 * n1) - (s->gA[a] - s->gB1[a]) * t1[b] / (n1 * n1);
        }
    /* the term is symmetric in a, b bit for bit (each product and sum commutes): computed once
     * for b >= a, added to both entries */
    for (int a = 0; a < 8; a++)
        for (int b = a; b < 8; b++) {
            double hm = (a < 6 && b < 6) ? 0.5 * (Hm[a][b] + Hm[b][a]) : 0.0;
            double h = 2 * kt * (s->gm[a] * s->gm[b] + s->m * hm);
            H[a][b] += h;
            if (b != a) H[b][a] += h;
        }
}

/* clamped twist at the supports: the end edges' frames against the clamps' (their reference
 * frames, carried by the same minimal rotation), over the half edge between support and edge
 * centre: U = GJ theta^2 / l0 at each end */
static int clamps(const gal_rod *rod, const double *q, double *U, double *grad, gal_csc *K)
{
    int nel = rod->p.elements;
    for (int e = 0; e < 2; e++) {
        int j = e ? nel - 1 : 0, k = 3 * rod->nn + j;
        double kt = rod->p.GJ / rod->l0[j], th = q[k];
        *U += kt * th * th;
        if (grad) grad[k] += 2 * kt * th;
        if (K && rod->dof[k] >= 0) K->val[K->diag[rod->dof[k]]] += 2 * kt;
    }
    return GAL_OK;
}

/* The node term: energy kt m^2 at node i, kt = GJ / lbar; adds 2 kt m gm to g and its Hessian to H. */
static double node(const gal_rod *rod, int i, const double *q, const gal_rod_node *nd, double *g,
                   double (*H)[8])
{
    gal_rod_twist s;
    gal_rod_twist_strain(rod, i, q, nd, H != NULL, &s);
    double kt = rod->p.GJ / nd->lbar;
    for (int a = 0; a < 8; a++) g[a] += 2 * kt * s.m * s.gm[a];
    if (H) gal_rod_twist_hessian(nd, &s, kt, H);
    return kt * s.m * s.m;
}

const gal_rod_term gal_rod_term_torsion = {"torsion", NULL, node, NULL};
/* Edge j alone: the clamp's share when j is an end edge, over theta_j (local 6). */
static int clamp_edge(const gal_rod *rod, int j, const double *q, double *U, double *g, double (*H)[7])
{
    int nel = rod->p.elements;
    for (int e = 0; e < 2; e++) {
        if (j != (e ? nel - 1 : 0)) continue;
        double kt = rod->p.GJ / rod->l0[j], th = q[3 * rod->nn + j];
        *U += kt * th * th;
        g[6] += 2 * kt * th;
        if (H) H[6][6] += 2 * kt;
    }
    return GAL_OK;
}

const gal_rod_term gal_rod_term_torsion_clamps = {"torsion_clamps", clamps, NULL, clamp_edge};
