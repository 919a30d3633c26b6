/* eval.c: energy, forces and the sparse tangent stiffness of the rod (paper Eqs. 1-5): extension,
 * isotropic bending, torsion and gravity. The node stencil (bending and torsion) and extension
 * are differentiated in closed form. */
#include "gallop/base/core.h"
#include "rod_impl.h"
#include "gallop/base/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- the node stencil: bending and torsion at interior node i ----
 * Variables: e0 = x_i - x_{i-1}, e1 = x_{i+1} - x_i (6), theta0, theta1 (2). Gradient g[8] and
 * Hessian H[8][8] of the stencil energy, in closed form. */

typedef double m33[3][3];

/* [a]_x b = a x b */
static void skew(const double *a, m33 S)
{
    S[0][0] = 0, S[0][1] = -a[2], S[0][2] = a[1];
    S[1][0] = a[2], S[1][1] = 0, S[1][2] = -a[0];
    S[2][0] = -a[1], S[2][1] = a[0], S[2][2] = 0;
}

/* C = A B */
static void mul33(m33 A, m33 B, m33 C)
{
    m33 T;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) T[i][j] = A[i][0] * B[0][j] + A[i][1] * B[1][j] + A[i][2] * B[2][j];
    memcpy(C, T, sizeof T);
}

/* Half-angle rotation vector between unit vectors: g(u, v) = u x v / (1 + u . v), and its
 * derivatives dg/du = -s [v]_x - s^2 (u x v) v^T, dg/dv = s [u]_x - s^2 (u x v) u^T, s = 1/(1+u.v). */
static void halfrot(const double *u, const double *v, double *g, m33 Du, m33 Dv)
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

/* Energy, gradient (8) and, when H != NULL, Hessian (8 x 8) of the stencil at node i. */
static double stencil(const gal_rod *rod, int i, const double *q, double *g, double (*H)[8])
{
    const gal_rod_params *p = &rod->p;
    double lbar = rod->l0[i - 1] + rod->l0[i];
    double e0[3], e1[3], t0[3], t1[3];
    for (int k = 0; k < 3; k++) {
        e0[k] = q[3 * i + k] - q[3 * (i - 1) + k];
        e1[k] = q[3 * (i + 1) + k] - q[3 * i + k];
    }
    double n0 = gal_norm3(e0), n1 = gal_norm3(e1);
    for (int k = 0; k < 3; k++) t0[k] = e0[k] / n0, t1[k] = e1[k] / n1;
    double c = gal_dot3(t0, t1);
    m33 P0, P1;
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) {
            P0[a][b] = (a == b) - t0[a] * t0[b];
            P1[a][b] = (a == b) - t1[a] * t1[b];
        }
    double E = 0;
    memset(g, 0, 8 * sizeof(double));
    if (H) memset(H, 0, 64 * sizeof(double));

    if (p->EI > 0) {
        /* E = k f(c), f = (1 - c)/(1 + c) = |kb|^2 / 4, k = 4 EI / lbar */
        double k = 4.0 * p->EI / lbar, f = (1 - c) / (1 + c);
        double f1 = -2.0 / ((1 + c) * (1 + c)), f2 = 4.0 / ((1 + c) * (1 + c) * (1 + c));
        double a0[3], a1[3]; /* dc/de0 = (t1 - c t0)/n0, dc/de1 = (t0 - c t1)/n1 */
        for (int d = 0; d < 3; d++) a0[d] = (t1[d] - c * t0[d]) / n0, a1[d] = (t0[d] - c * t1[d]) / n1;
        E += k * f;
        for (int d = 0; d < 3; d++) g[d] += k * f1 * a0[d], g[3 + d] += k * f1 * a1[d];
        if (H) {
            double gc[6] = {a0[0], a0[1], a0[2], a1[0], a1[1], a1[2]};
            for (int a = 0; a < 3; a++)
                for (int b = 0; b < 3; b++) {
                    /* d2c/de0^2 = -(t0 a0^T + a0 t0^T + c P0/n0)/n0, d2c/de0 de1 = (P1/n1 - t0 a1^T)/n0 */
                    double c00 = -(t0[a] * a0[b] + a0[a] * t0[b] + c * P0[a][b] / n0) / n0;
                    double c11 = -(t1[a] * a1[b] + a1[a] * t1[b] + c * P1[a][b] / n1) / n1;
                    double c01 = (P1[a][b] / n1 - t0[a] * a1[b]) / n0;
                    H[a][b] += k * (f2 * gc[a] * gc[b] + f1 * c00);
                    H[3 + a][3 + b] += k * (f2 * gc[3 + a] * gc[3 + b] + f1 * c11);
                    H[a][3 + b] += k * (f2 * gc[a] * gc[3 + b] + f1 * c01);
                    H[3 + b][a] = H[a][3 + b];
                }
        }
    }

    if (p->torsion) {
        const double *tb0 = rod->tbar + 3 * (i - 1), *tb1 = rod->tbar + 3 * i;
        double A0[3], A1[3], u[3], w[3];
        gal_rod_transport(tb0, rod->abar + 3 * (i - 1), t0, A0); /* reference director of edge i-1 */
        gal_rod_transport(tb1, rod->abar + 3 * i, t1, A1);        /* and of edge i */
        gal_rod_transport(t0, A0, t1, u);                         /* edge i-1's carried across node i */
        gal_cross3(u, A1, w);
        double mref = atan2(gal_dot3(w, t1), gal_dot3(u, A1));    /* signed angle u -> A1 about t1 */
        double th0 = q[3 * rod->nn + i - 1], th1 = q[3 * rod->nn + i];
        double m = th1 - th0 + mref, kt = p->GJ / lbar;
        /* d mref/de0 = [g(t0,t1) + g(tb0,t0)]/n0, d mref/de1 = [g(t0,t1) - g(tb1,t1)]/n1: the
         * curvature binormal's share (Bergou et al. 2010) plus the turn of each reference frame
         * about its own tangent as it is carried from the reference tangent */
        double gA[3], gB0[3], gB1[3];
        m33 DAu, DAv, DB0, DB1;
        halfrot(t0, t1, gA, H ? DAu : NULL, H ? DAv : NULL);
        halfrot(tb0, t0, gB0, NULL, H ? DB0 : NULL);
        halfrot(tb1, t1, gB1, NULL, H ? DB1 : NULL);
        double gm[8];
        for (int d = 0; d < 3; d++) gm[d] = (gA[d] + gB0[d]) / n0, gm[3 + d] = (gA[d] - gB1[d]) / n1;
        gm[6] = -1, gm[7] = 1;
        E += kt * m * m;
        for (int a = 0; a < 8; a++) g[a] += 2 * kt * m * gm[a];
        if (H) {
            m33 X0, X1, Y0, Y1;
            mul33(DAu, P0, X0); /* dA/de0 * n0 */
            mul33(DAv, P1, X1); /* dA/de1 * n1 */
            mul33(DB0, P0, Y0); /* dB0/de0 * n0 */
            mul33(DB1, P1, Y1); /* dB1/de1 * n1 */
            double Hm[6][6];
            for (int a = 0; a < 3; a++)
                for (int b = 0; b < 3; b++) {
                    Hm[a][b] = (X0[a][b] + Y0[a][b]) / (n0 * n0) - (gA[a] + gB0[a]) * t0[b] / (n0 * n0);
                    Hm[a][3 + b] = X1[a][b] / (n0 * n1);
                    Hm[3 + a][b] = X0[a][b] / (n0 * n1);
                    Hm[3 + a][3 + b] = (X1[a][b] - Y1[a][b]) / (n1 * n1) - (gA[a] - gB1[a]) * t1[b] / (n1 * n1);
                }
            for (int a = 0; a < 8; a++)
                for (int b = 0; b < 8; b++) {
                    double hm = (a < 6 && b < 6) ? 0.5 * (Hm[a][b] + Hm[b][a]) : 0.0;
                    H[a][b] += 2 * kt * (gm[a] * gm[b] + m * hm);
                }
        }
    }
    return E;
}

/* Node-space incidence of the stencil variables: local node variable a (0..10) is the sum of
 * coef * (edge variable idx). */
static const int inc_n[NL] = {1, 1, 1, 2, 2, 2, 1, 1, 1, 1, 1};
static const int inc_v[NL][2] = {{0, 0}, {1, 0}, {2, 0}, {0, 3}, {1, 4}, {2, 5},
                                 {3, 0}, {4, 0}, {5, 0}, {6, 0}, {7, 0}};
static const double inc_c[NL][2] = {{-1, 0}, {-1, 0}, {-1, 0}, {1, -1}, {1, -1}, {1, -1},
                                    {1, 0},  {1, 0},  {1, 0},  {1, 0},  {1, 0}};

int gal_rod_eval(const gal_rod *rod, const double *q, double *energy, double *grad, gal_csc *K)
{
    const gal_rod_params *p = &rod->p;
    int nn = rod->nn, nel = p->elements;
    gal_csc *KK = K;
    double U = 0.0;
    if (grad) memset(grad, 0, (size_t)rod->nq * sizeof(double));
    if (KK) memset(KK->val, 0, (size_t)KK->nnz * sizeof(double));

    /* extension, per edge: U = EA/2 (|e|/l0 - 1)^2 l0 */
    for (int j = 0; j < nel; j++) {
        double e[3], l0 = rod->l0[j];
        for (int k = 0; k < 3; k++) e[k] = q[3 * (j + 1) + k] - q[3 * j + k];
        double le = gal_norm3(e);
        if (!(le > 1e-12 * l0)) return gal_error(GAL_EFAIL, "rod: element %d has collapsed (length %g m)", j, le);
        double eps = le / l0 - 1.0, t[3] = {e[0] / le, e[1] / le, e[2] / le};
        U += 0.5 * p->EA * eps * eps * l0;
        if (grad)
            for (int k = 0; k < 3; k++) {
                double g = p->EA * eps * t[k];   /* dU/de = EA eps t */
                grad[3 * j + k] -= g;
                grad[3 * (j + 1) + k] += g;
            }
        if (KK) {
            /* d2U/de2 = EA/l0 t t^T + EA eps/|e| (I - t t^T) */
            double H[3][3];
            for (int a = 0; a < 3; a++)
                for (int b = 0; b < 3; b++)
                    H[a][b] = p->EA / l0 * t[a] * t[b] + p->EA * eps / le * ((a == b) - t[a] * t[b]);
            const int *s = rod->slot_edge + (size_t)j * EL * EL;
            for (int a = 0; a < EL; a++)
                for (int b = 0; b < EL; b++) {
                    int sl = s[a * EL + b];
                    if (sl < 0) continue;
                    double sg = ((a < 3) == (b < 3)) ? 1.0 : -1.0;
                    KK->val[sl] += sg * H[a % 3][b % 3];
                }
        }
    }

    /* bending and torsion, per interior node */
    if (p->EI > 0 || p->torsion) {
        for (int i = 1; i <= nn - 2; i++) {
            double c = 0;
            {
                double e0[3], e1[3];
                for (int k = 0; k < 3; k++) {
                    e0[k] = q[3 * i + k] - q[3 * (i - 1) + k];
                    e1[k] = q[3 * (i + 1) + k] - q[3 * i + k];
                }
                c = gal_dot3(e0, e1) / (gal_norm3(e0) * gal_norm3(e1));
            }
            if (!(c > -0.999))
                return gal_error(GAL_EFAIL, "rod: the rod folds back on itself at node %d", i);
            double Eg[8], EH[8][8];
            U += stencil(rod, i, q, Eg, KK ? EH : NULL);
            int qi[NL];
            gal_rod_node_q(rod, i, qi);
            if (grad)
                for (int a = 0; a < NL; a++) {
                    if (qi[a] < 0) continue;
                    double g = 0;
                    for (int r = 0; r < inc_n[a]; r++) g += inc_c[a][r] * Eg[inc_v[a][r]];
                    grad[qi[a]] += g;
                }
            if (KK) {
                const int *s = rod->slot_node + (size_t)(i - 1) * NL * NL;
                for (int a = 0; a < NL; a++)
                    for (int b = 0; b < NL; b++) {
                        int sl = s[a * NL + b];
                        if (sl < 0) continue;
                        double h = 0;
                        for (int r = 0; r < inc_n[a]; r++)
                            for (int t = 0; t < inc_n[b]; t++)
                                h += inc_c[a][r] * inc_c[b][t] * EH[inc_v[a][r]][inc_v[b][t]];
                        KK->val[sl] += h;
                    }
            }
        }
    }

    /* clamped twist at the supports: the end edges' frames against the clamps' (their reference
     * frames, carried by the same minimal rotation), over the half edge between support and edge
     * centre: U = GJ theta^2 / l0 at each end */
    if (p->torsion && p->twist_clamped)
        for (int e = 0; e < 2; e++) {
            int j = e ? nel - 1 : 0, k = 3 * nn + j;
            double kt = p->GJ / rod->l0[j], th = q[k];
            U += kt * th * th;
            if (grad) grad[k] += 2 * kt * th;
            if (KK && rod->dof[k] >= 0) KK->val[KK->diag[rod->dof[k]]] += 2 * kt;
        }

    /* weight of the eccentric ice: U = m_i g e l0 c_z(theta), c turned by the twist about the
     * reference tangent (the tangent's own turn is left out: it is second order here) */
    if (rod->ecc_c && p->gravity != 0)
        for (int j = 0; j < nel; j++) {
            int k = 3 * nn + j;
            double *c = rod->ecc_c + 3 * j, *t = rod->tbar + 3 * j, tc[3];
            gal_cross3(t, c, tc);
            double th = q[k], w = p->ecc_mass * p->gravity * p->ecc * rod->l0[j];
            double cz = cos(th) * c[2] + sin(th) * tc[2], dcz = -sin(th) * c[2] + cos(th) * tc[2];
            U += w * cz;
            if (grad) grad[k] += w * dcz;
            if (KK && rod->dof[k] >= 0) KK->val[KK->diag[rod->dof[k]]] -= w * cz;
        }

    /* gravity: U = sum m_i g z_i */
    if (p->gravity != 0)
        for (int i = 0; i < nn; i++) {
            U += rod->node_mass[i] * p->gravity * q[3 * i + 2];
            if (grad) grad[3 * i + 2] += rod->node_mass[i] * p->gravity;
        }
    if (energy) *energy = U;
    if (!isfinite(U)) return gal_error(GAL_EFAIL, "rod: the energy is not finite");
    return GAL_OK;
}
