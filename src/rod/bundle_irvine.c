/* bundle_irvine.c: the sub-conductors' differential stretch in a bundle carried as one rod (the
 * equivalent model's Irvine effect, README "Bundles"). Sub-conductor k sits at the offset p_k (m,
 * horizontal and vertical across the span) from the bundle's axis. A twist psi of the bundle moves
 * it by psi (x x p_k); on a span whose tangent t has a vertical (and, blown out, a horizontal) part,
 * that changes its strain by (x x p_k) . t psi' = p_k . (t_z, -t_y) psi': the sub-conductor at a
 * horizontal offset y_k goes up or down, changes its sag and so stretches, and the tension change
 * stiffens the symmetric torsional modes. The spacers let the sub-conductors slide axially against
 * each other by turning about axes across the span: a field F(s) (rad, a vector across the span)
 * moves sub-conductor k axially by p_k . F, so its strain grows by p_k . (F' + (t_z, -t_y) psi'),
 * and the sub-conductors' energy sum_k EA_sub/2 (p_k . (...))^2 is, with S = sum_k p_k p_k^T,
 * EA_sub/2 (...)^T S (...): S = (n R^2 / 2) I for 3 to 8 sub-conductors on the circle (two fields,
 * u_f the horizontal and vertical), and 2 p_1 p_1^T for a twin (one field along u = p_1 / R). Per
 * field f the energy density is k/2 (a_f' + c_f psi')^2, k = EA_sub lambda_f, lambda_f = sum_k
 * (u_f . p_k)^2, c_f = u_f . (t_z, -t_y). The yokes hold every sub-conductor: a_f = 0 and psi = 0 at
 * both supports, so a_f cannot take up the whole of c_f psi': minimizing over a_f leaves
 * k / (2 L) (int c_f psi' ds)^2, the stretch of Irvine's cable (int z' psi' = -int z'' psi, which
 * vanishes for antisymmetric twists), here kept as a local energy of the field. The field carries
 * the sub-conductors' axial inertia, m_sub lambda_f, and the spacers' about the axes across.
 * Discretized as the twist is (src/rod/torsion.c): a_f one angle per edge, at each interior node
 * U = k (a_{f,i} - a_{f,i-1} + c_f m_i)^2 / lbar_i (m_i the twist strain, c_f at the mean of the
 * two edges' tangents) and at each end edge k (a_f + c_f theta)^2 / l0 (the half edge from the
 * yoke). Gradient and Hessian in closed form. The first order in the twist: the offsets p_k do not
 * turn with the twist (sums over the circle that do not change as it turns for 3 to 8
 * sub-conductors; a twin's changes by the square of the twist angle). */
#include "gallop/base/core.h"
#include "rod_impl.h"
#include "gallop/base/vec3.h"

#include <math.h>
#include <string.h>

#define NE 10 /* the node's variables: e0, e1, theta_{i-1}, theta_i, a_{i-1}, a_i */

/* v = x x (0, u_y, u_z) = (0, -u_z, u_y): c = v . t */
static void field_v(const gal_rod *rod, int f, double v[3])
{
    v[0] = 0, v[1] = -rod->p.bundle_field_dir[f][1], v[2] = rod->p.bundle_field_dir[f][0];
}

/* d(v . t)/de = P v / n and d2(v . t)/de2 = -(t v^T + v t^T + (v . t)(I - 3 t t^T)) / n^2, scaled
 * by s, added to dc (3) and D (3 x 3 with stride ld). */
static void vt_derivs(const double *t, double n, const double *v, double s, double *dc, double *D, int ld)
{
    double vt = gal_dot3(v, t);
    for (int a = 0; a < 3; a++) {
        dc[a] += s * (v[a] - vt * t[a]) / n;
        for (int b = 0; b < 3; b++)
            D[a * ld + b] -= s * (t[a] * v[b] + v[a] * t[b] + vt * ((a == b) - 3 * t[a] * t[b])) / (n * n);
    }
}

/* Add the local gradient g and Hessian H (nl x nl, row-major) over the configuration entries qi
 * (-1 absent) to grad and K. */
static void add_local(const gal_rod *rod, int nl, const int *qi, const double *g, const double *H, double *grad,
                      gal_csc *K)
{
    for (int a = 0; a < nl; a++) {
        if (qi[a] < 0) continue;
        if (grad) grad[qi[a]] += g[a];
        int da = rod->dof[qi[a]];
        if (!K || da < 0) continue;
        for (int b = 0; b < nl; b++) {
            int db = qi[b] < 0 ? -1 : rod->dof[qi[b]];
            if (db < da) continue;
            int sl = gal_csc_find(K, da, db);
            if (sl >= 0) K->val[sl] += H[a * nl + b];
        }
    }
}

/* Field f at interior node i: energy, and the gradient g (NE) and Hessian H (NE x NE) over
 * (e0, e1, theta_{i-1}, theta_i, a_{i-1}, a_i). */
static double node_field(const gal_rod *rod, int f, const gal_rod_node *nd, const gal_rod_twist *s,
                         const double *D2m, const double *q, int i, double *g, double *H)
{
    int nel = rod->p.elements, k0 = 3 * rod->nn + (1 + f) * nel + i - 1;
    double v[3], dc[8] = {0}, D2c[8 * 8] = {0}, tb[3];
    field_v(rod, f, v);
    for (int a = 0; a < 3; a++) tb[a] = 0.5 * (nd->t0[a] + nd->t1[a]);
    double c = gal_dot3(v, tb), m = s->m, kk = rod->p.bundle_field_k / nd->lbar;
    double w = q[k0 + 1] - q[k0] + c * m;
    vt_derivs(nd->t0, nd->n0, v, 0.5, dc, D2c, 8);
    vt_derivs(nd->t1, nd->n1, v, 0.5, dc + 3, D2c + 3 * 8 + 3, 8);
    double gw[NE];
    for (int a = 0; a < 8; a++) gw[a] = c * s->gm[a] + m * dc[a];
    gw[8] = -1, gw[9] = 1;
    for (int a = 0; a < NE; a++) g[a] = 2 * kk * w * gw[a];
    if (H) {
        memset(H, 0, NE * NE * sizeof(double));
        for (int a = 0; a < NE; a++)
            for (int b = 0; b < NE; b++) {
                double hw = 0;
                if (a < 8 && b < 8)
                    hw = c * D2m[a * 8 + b] + dc[a] * s->gm[b] + s->gm[a] * dc[b] + m * D2c[a * 8 + b];
                H[a * NE + b] = 2 * kk * (gw[a] * gw[b] + w * hw);
            }
    }
    return kk * w * w;
}

/* Map the node's NE variables to its stencil (x_{i-1}, x_i, x_{i+1}, theta_{i-1}, theta_i, a_{i-1},
 * a_i; 13): x_{i-1} = -e0, x_i = e0 - e1, x_{i+1} = e1. */
static void to_stencil(const double *gE, const double *HE, double *g, double *H)
{
    double B[13][NE];
    memset(B, 0, sizeof B);
    for (int k = 0; k < 3; k++) B[k][k] = -1, B[3 + k][k] = 1, B[3 + k][3 + k] = -1, B[6 + k][3 + k] = 1;
    for (int k = 0; k < 4; k++) B[9 + k][6 + k] = 1;
    for (int a = 0; a < 13; a++) {
        g[a] = 0;
        for (int r = 0; r < NE; r++) g[a] += B[a][r] * gE[r];
    }
    if (!HE) return;
    double T[13][NE];
    for (int a = 0; a < 13; a++)
        for (int r = 0; r < NE; r++) {
            T[a][r] = 0;
            for (int p = 0; p < NE; p++) T[a][r] += B[a][p] * HE[p * NE + r];
        }
    for (int a = 0; a < 13; a++)
        for (int b = 0; b < 13; b++) {
            double h = 0;
            for (int r = 0; r < NE; r++) h += T[a][r] * B[b][r];
            H[a * 13 + b] = h;
        }
}

static int nodes(const gal_rod *rod, const double *q, double *U, double *grad, gal_csc *K)
{
    for (int i = 1; i <= rod->nn - 2; i++) {
        gal_rod_node nd;
        int st = gal_rod_node_geometry(rod, i, q, &nd);
        if (st) return st;
        gal_rod_twist s, s1;
        gal_rod_twist_strain(rod, i, q, &nd, K != NULL, &s);
        double D2m[8][8];
        if (K) { /* the second derivative of the twist strain alone */
            memset(D2m, 0, sizeof D2m);
            s1 = s, s1.m = 1;
            memset(s1.gm, 0, sizeof s1.gm);
            gal_rod_twist_hessian(&nd, &s1, 0.5, D2m);
        }
        int qa[GAL_ROD_AUX_NL];
        gal_rod_aux_q(rod, i, qa);
        for (int f = 0; f < rod->p.bundle_fields; f++) {
            double gE[NE], HE[NE * NE], gl[13], Hl[13 * 13];
            *U += node_field(rod, f, &nd, &s, &D2m[0][0], q, i, gE, K ? HE : NULL);
            to_stencil(gE, K ? HE : NULL, gl, Hl);
            int ql[13];
            memcpy(ql, qa, NL * sizeof(int));
            ql[11] = qa[NL + 2 * f], ql[12] = qa[NL + 2 * f + 1];
            add_local(rod, 13, ql, gl, Hl, grad, K);
        }
    }
    return GAL_OK;
}

/* The end edges: k (a_f + c_f theta)^2 / l0, c_f = v . t of the edge, over (x_j, x_{j+1}, theta_j,
 * a_{f,j}). */
static int clamps(const gal_rod *rod, const double *q, double *U, double *grad, gal_csc *K)
{
    int nel = rod->p.elements, nn = rod->nn;
    for (int side = 0; side < 2; side++) {
        int j = side ? nel - 1 : 0;
        double e[3], t[3], l0 = rod->l0[j], kk = rod->p.bundle_field_k / l0;
        for (int d = 0; d < 3; d++) e[d] = q[3 * (j + 1) + d] - q[3 * j + d];
        double le = gal_norm3(e), th = q[3 * nn + j];
        if (!(le > 1e-12 * l0)) return gal_error(GAL_EFAIL, "rod: element %d has collapsed (length %g m)", j, le);
        for (int d = 0; d < 3; d++) t[d] = e[d] / le;
        for (int f = 0; f < rod->p.bundle_fields; f++) {
            int ka = 3 * nn + (1 + f) * nel + j;
            double v[3], dc[3] = {0}, D[9] = {0}, gl[8], Hl[64];
            field_v(rod, f, v);
            double c = gal_dot3(v, t), w = q[ka] + c * th;
            vt_derivs(t, le, v, 1.0, dc, D, 3);
            *U += kk * w * w;
            double gw[8]; /* over x_j, x_{j+1}, theta_j, a_j */
            for (int d = 0; d < 3; d++) gw[d] = -th * dc[d], gw[3 + d] = th * dc[d];
            gw[6] = c, gw[7] = 1;
            for (int a = 0; a < 8; a++) gl[a] = 2 * kk * w * gw[a];
            double dcx[6]; /* d c / d(x_j, x_{j+1}) */
            for (int d = 0; d < 3; d++) dcx[d] = -dc[d], dcx[3 + d] = dc[d];
            for (int a = 0; a < 8; a++)
                for (int b = 0; b < 8; b++) {
                    double hw = 0; /* d2 w: theta d2c over x, dc over x and theta */
                    if (a < 6 && b < 6) hw = ((a < 3) == (b < 3) ? 1 : -1) * th * D[(a % 3) * 3 + b % 3];
                    else if (a < 6 && b == 6) hw = dcx[a];
                    else if (b < 6 && a == 6) hw = dcx[b];
                    Hl[a * 8 + b] = 2 * kk * (gw[a] * gw[b] + w * hw);
                }
            int ql[8] = {3 * j, 3 * j + 1, 3 * j + 2, 3 * j + 3, 3 * j + 4, 3 * j + 5, 3 * nn + j, ka};
            add_local(rod, 8, ql, gl, Hl, grad, K);
        }
    }
    return GAL_OK;
}

static int eval(const gal_rod *rod, const double *q, double *U, double *grad, gal_csc *K)
{
    int st = nodes(rod, q, U, grad, K);
    return st ? st : clamps(rod, q, U, grad, K);
}

const gal_rod_term gal_rod_term_bundle_irvine = {"bundle_irvine", eval, NULL, NULL};
