/* rod.c: the discrete Cosserat rod (paper Eqs. 1-5, DESIGN.md "The rod"): energy, forces and the
 * sparse tangent stiffness of extension, isotropic bending, torsion and gravity. The node stencil
 * (bending and torsion) and extension are differentiated in closed form. */
#include "gallop/base/core.h"
#include "gallop/rod/rod.h"
#include "gallop/base/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>


#define NL 11   /* node stencil: x_{i-1}, x_i, x_{i+1} (9), theta_{i-1}, theta_i */
#define EL 6    /* edge: x_j, x_{j+1} */

static void transport(const double *tb, const double *a, const double *t, double *r);
static void build_mass(gal_rod *rod);

/* ---- sparse pattern ---- */

static int cmp_pair(const void *a, const void *b)
{
    const long *x = a, *y = b;
    return (*x > *y) - (*x < *y);
}

/* Configuration indices of the node stencil at interior node i and of edge j. */
static void node_stencil_q(const gal_rod *rod, int i, int *qi)
{
    for (int k = 0; k < 9; k++) qi[k] = 3 * (i - 1) + k;
    if (rod->p.torsion) {
        qi[9] = 3 * rod->nn + i - 1;
        qi[10] = 3 * rod->nn + i;
    } else {
        qi[9] = qi[10] = -1;
    }
}

static void edge_q(int j, int *qi)
{
    for (int k = 0; k < 6; k++) qi[k] = 3 * j + k;
}

static int build_pattern(gal_rod *rod)
{
    int nel = rod->p.elements, nn = rod->nn;
    size_t cap = (size_t)(nn - 2) * NL * NL + (size_t)nel * EL * EL + 16;
    long *pairs = malloc(cap * sizeof(long));
    if (!pairs) return GAL_ENOMEM;
    size_t np = 0;
    int qi[NL];
    long n = rod->ndof;
    for (int i = 1; i <= nn - 2; i++) {
        node_stencil_q(rod, i, qi);
        for (int a = 0; a < NL; a++)
            for (int b = 0; b < NL; b++) {
                int da = qi[a] < 0 ? -1 : rod->dof[qi[a]], db = qi[b] < 0 ? -1 : rod->dof[qi[b]];
                if (da >= 0 && db >= 0 && da <= db) pairs[np++] = (long)db * n + da;
            }
    }
    for (int j = 0; j < nel; j++) {
        edge_q(j, qi);
        for (int a = 0; a < EL; a++)
            for (int b = 0; b < EL; b++) {
                int da = rod->dof[qi[a]], db = rod->dof[qi[b]];
                if (da >= 0 && db >= 0 && da <= db) pairs[np++] = (long)db * n + da;
            }
    }
    for (int d = 0; d < n; d++) pairs[np++] = (long)d * n + d; /* every diagonal */
    qsort(pairs, np, sizeof(long), cmp_pair);
    size_t nu = 0;
    for (size_t k = 0; k < np; k++)
        if (nu == 0 || pairs[k] != pairs[nu - 1]) pairs[nu++] = pairs[k];

    gal_csc *A = calloc(1, sizeof *A);
    if (!A) { free(pairs); return GAL_ENOMEM; }
    A->n = (int)n;
    A->nnz = (int)nu;
    A->colptr = calloc((size_t)n + 1, sizeof(int));
    A->rowind = malloc(nu * sizeof(int));
    A->val = calloc(nu, sizeof(double));
    A->diag = malloc((size_t)n * sizeof(int));
    if (!A->colptr || !A->rowind || !A->val || !A->diag) {
        free(pairs);
        gal_csc_free(A);
        return GAL_ENOMEM;
    }
    for (size_t k = 0; k < nu; k++) {
        int col = (int)(pairs[k] / n), row = (int)(pairs[k] % n);
        A->rowind[k] = row;
        A->colptr[col + 1]++;
    }
    for (int j = 0; j < n; j++) A->colptr[j + 1] += A->colptr[j];
    for (int j = 0; j < n; j++) A->diag[j] = gal_csc_find(A, j, j);
    free(pairs);
    rod->K = A;

    /* slot maps: where each local pair of a stencil lands in the value array */
    rod->slot_node = malloc((size_t)(nn > 2 ? nn - 2 : 1) * NL * NL * sizeof(int));
    rod->slot_edge = malloc((size_t)nel * EL * EL * sizeof(int));
    if (!rod->slot_node || !rod->slot_edge) return GAL_ENOMEM;
    for (int i = 1; i <= nn - 2; i++) {
        int *s = rod->slot_node + (size_t)(i - 1) * NL * NL;
        node_stencil_q(rod, i, qi);
        for (int a = 0; a < NL; a++)
            for (int b = 0; b < NL; b++) {
                int da = qi[a] < 0 ? -1 : rod->dof[qi[a]], db = qi[b] < 0 ? -1 : rod->dof[qi[b]];
                s[a * NL + b] = (da >= 0 && db >= 0 && da <= db) ? gal_csc_find(A, da, db) : -1;
            }
    }
    for (int j = 0; j < nel; j++) {
        int *s = rod->slot_edge + (size_t)j * EL * EL;
        edge_q(j, qi);
        for (int a = 0; a < EL; a++)
            for (int b = 0; b < EL; b++) {
                int da = rod->dof[qi[a]], db = rod->dof[qi[b]];
                s[a * EL + b] = (da >= 0 && db >= 0 && da <= db) ? gal_csc_find(A, da, db) : -1;
            }
    }
    return GAL_OK;
}

/* ---- construction ---- */

gal_rod *gal_rod_free(gal_rod *rod)
{
    if (rod) {
        free(rod->dof);
        free(rod->free_q);
        free(rod->l0);
        free(rod->tbar);
        free(rod->abar);
        free(rod->node_mass);
        free(rod->edge_inertia);
        free(rod->q0);
        gal_csc_free(rod->K);
        gal_csc_free(rod->M);
        free(rod->ecc_c);
        free(rod->mdiag);
        free(rod->slot_node);
        free(rod->slot_edge);
        free(rod);
    }
    return NULL;
}

gal_rod *gal_rod_alloc(const gal_rod_params *p, const double *q0)
{
    if (p->elements < 2 || !(p->length > 0) || !(p->unstretched_length > 0) || !(p->EA > 0) ||
        !(p->EI >= 0) || !(p->mass > 0) || (p->torsion && (!(p->GJ > 0) || !(p->polar_inertia > 0)))) {
        gal_error(GAL_EINPUT, "rod: invalid parameters (elements %d, length %g, L0 %g, EA %g, EI %g, "
                  "GJ %g, mass %g, polar inertia %g)", p->elements, p->length, p->unstretched_length,
                  p->EA, p->EI, p->GJ, p->mass, p->polar_inertia);
        return NULL;
    }
    gal_rod *rod = calloc(1, sizeof *rod);
    if (!rod) return NULL;
    rod->p = *p;
    int nel = p->elements, nn = nel + 1;
    rod->nn = nn;
    rod->nq = 3 * nn + (p->torsion ? nel : 0);
    rod->dof = malloc((size_t)rod->nq * sizeof(int));
    rod->free_q = malloc((size_t)rod->nq * sizeof(int));
    rod->l0 = malloc((size_t)nel * sizeof(double));
    rod->tbar = malloc((size_t)3 * nel * sizeof(double));
    rod->abar = malloc((size_t)3 * nel * sizeof(double));
    rod->node_mass = calloc((size_t)nn, sizeof(double));
    rod->edge_inertia = calloc((size_t)nel, sizeof(double));
    rod->q0 = malloc((size_t)rod->nq * sizeof(double));
    if (!rod->dof || !rod->free_q || !rod->l0 || !rod->tbar || !rod->abar || !rod->node_mass ||
        !rod->edge_inertia || !rod->q0) {
        gal_error(GAL_ENOMEM, "rod: out of memory for %d elements", nel);
        return gal_rod_free(rod);
    }
    memcpy(rod->q0, q0, (size_t)rod->nq * sizeof(double));

    /* Free dofs numbered node by node (positions, then the twist of the edge that follows), so
     * that the tangent is banded before any reordering. */
    for (int k = 0; k < rod->nq; k++) rod->dof[k] = -1;
    int nd = 0;
    for (int i = 0; i < nn; i++) {
        if (i > 0 && i < nn - 1)
            for (int k = 0; k < 3; k++) rod->free_q[nd] = 3 * i + k, rod->dof[3 * i + k] = nd++;
        if (p->torsion && i < nel) rod->free_q[nd] = 3 * nn + i, rod->dof[3 * nn + i] = nd++;
    }
    rod->ndof = nd;

    gal_rod_set_unstretched_length(rod, p->unstretched_length);
    for (int j = 0; j < nel; j++) {
        /* reference frame: unit tangent of q0 and a first director normal to it, chosen as the
         * horizontal normal y carried into the plane normal to the tangent */
        double *t = rod->tbar + 3 * j, *a = rod->abar + 3 * j;
        for (int k = 0; k < 3; k++) t[k] = q0[3 * (j + 1) + k] - q0[3 * j + k];
        double le = gal_norm3(t);
        if (!(le > 0)) {
            gal_error(GAL_EINPUT, "rod: element %d of the reference geometry has zero length", j);
            return gal_rod_free(rod);
        }
        for (int k = 0; k < 3; k++) t[k] /= le;
        double y[3] = {0, 1, 0}, ty = gal_dot3(t, y);
        for (int k = 0; k < 3; k++) a[k] = y[k] - ty * t[k];
        double na = gal_norm3(a);
        if (na < 1e-6) { /* tangent along y: fall back to z */
            double z[3] = {0, 0, 1}, tz = gal_dot3(t, z);
            for (int k = 0; k < 3; k++) a[k] = z[k] - tz * t[k];
            na = gal_norm3(a);
        }
        for (int k = 0; k < 3; k++) a[k] /= na;
    }
    if (build_pattern(rod) != GAL_OK || !(rod->M = gal_csc_clone(rod->K))) {
        gal_error(GAL_ENOMEM, "rod: out of memory building the stiffness pattern");
        return gal_rod_free(rod);
    }
    if (p->ecc_mass > 0 && p->ecc != 0 && p->torsion) {
        rod->ecc_c = malloc((size_t)3 * nel * sizeof(double));
        if (!rod->ecc_c) { gal_error(GAL_ENOMEM, "rod: out of memory"); return gal_rod_free(rod); }
        for (int j = 0; j < nel; j++) {
            double *t = rod->tbar + 3 * j, *a = rod->abar + 3 * j, b[3];
            gal_cross3(t, a, b);
            for (int k = 0; k < 3; k++) rod->ecc_c[3 * j + k] = cos(p->ecc_angle) * a[k] + sin(p->ecc_angle) * b[k];
        }
    }
    build_mass(rod);
    return rod;
}

/* M on the pattern of K: the lumped masses on the diagonal and, for eccentric ice, the coupling
 * of each edge's twist with the translation of its two nodes, 1/2 l0 m_i e (t x c) each (the
 * kinetic energy of the ice centre x + e c(theta): m_i e xdot . (t x c) thetadot). */
static void build_mass(gal_rod *rod)
{
    gal_csc *M = rod->M;
    if (!M) return;
    memset(M->val, 0, (size_t)M->nnz * sizeof(double));
    if (!rod->mdiag && !(rod->mdiag = malloc((size_t)rod->ndof * sizeof(double)))) return;
    gal_rod_mass_diag(rod, rod->mdiag);
    for (int d = 0; d < rod->ndof; d++) M->val[M->diag[d]] = rod->mdiag[d];
    if (!rod->ecc_c || !rod->p.torsion) return;
    int nn = rod->nn;
    for (int j = 0; j < rod->p.elements; j++) {
        int dt = rod->dof[3 * nn + j];
        if (dt < 0) continue;
        double g[3], *c = rod->ecc_c + 3 * j, *t = rod->tbar + 3 * j;
        gal_cross3(t, c, g);
        double f = 0.5 * rod->l0[j] * rod->p.ecc_mass * rod->p.ecc;
        for (int node = j; node <= j + 1; node++)
            for (int k = 0; k < 3; k++) {
                int dx = rod->dof[3 * node + k];
                if (dx < 0) continue;
                int a = dx < dt ? dx : dt, b = dx < dt ? dt : dx;
                int sl = gal_csc_find(M, a, b);
                if (sl >= 0) M->val[sl] += f * g[k];
            }
    }
}

void gal_rod_mass_mult(const gal_rod *rod, const double *x, double *y)
{
    if (rod->ecc_c && rod->p.torsion) {
        gal_csc_symv(rod->M, x, y);
        return;
    }
    for (int d = 0; d < rod->ndof; d++) y[d] = rod->mdiag[d] * x[d]; /* lumped: diagonal */
}

void gal_rod_set_unstretched_length(gal_rod *rod, double L0)
{
    int nel = rod->p.elements;
    double l0 = L0 / nel;
    rod->p.unstretched_length = L0;
    for (int i = 0; i < rod->nn; i++) rod->node_mass[i] = 0;
    for (int j = 0; j < nel; j++) {
        rod->l0[j] = l0;
        rod->node_mass[j] += 0.5 * rod->p.mass * l0;
        rod->node_mass[j + 1] += 0.5 * rod->p.mass * l0;
        rod->edge_inertia[j] = rod->p.polar_inertia * l0;
    }
    build_mass(rod);
}

void gal_rod_material_frame(const gal_rod *rod, const double *q, int j, double t[3], double d1[3])
{
    double e[3], a[3];
    for (int k = 0; k < 3; k++) e[k] = q[3 * (j + 1) + k] - q[3 * j + k];
    double le = gal_norm3(e);
    for (int k = 0; k < 3; k++) t[k] = e[k] / le;
    transport(rod->tbar + 3 * j, rod->abar + 3 * j, t, a);
    double th = rod->p.torsion ? q[3 * rod->nn + j] : 0.0, b[3];
    gal_cross3(t, a, b);
    for (int k = 0; k < 3; k++) d1[k] = cos(th) * a[k] + sin(th) * b[k];
}

void gal_rod_gather(const gal_rod *rod, const double *full, double *free_part)
{
    for (int d = 0; d < rod->ndof; d++) free_part[d] = full[rod->free_q[d]];
}

void gal_rod_scatter(const gal_rod *rod, const double *free_part, double *full)
{
    for (int d = 0; d < rod->ndof; d++) full[rod->free_q[d]] = free_part[d];
}

void gal_rod_mass_diag(const gal_rod *rod, double *mdiag)
{
    for (int d = 0; d < rod->ndof; d++) {
        int q = rod->free_q[d];
        mdiag[d] = q < 3 * rod->nn ? rod->node_mass[q / 3] : rod->edge_inertia[q - 3 * rod->nn];
    }
}

void gal_rod_tensions(const gal_rod *rod, const double *q, double *tension)
{
    for (int j = 0; j < rod->p.elements; j++) {
        double e[3];
        for (int k = 0; k < 3; k++) e[k] = q[3 * (j + 1) + k] - q[3 * j + k];
        tension[j] = rod->p.EA * (gal_norm3(e) / rod->l0[j] - 1.0);
    }
}

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

/* Parallel transport of a (normal to tb) from unit tangent tb to unit tangent t. */
static void transport(const double *tb, const double *a, const double *t, double *r)
{
    double f = gal_dot3(t, a) / (1.0 + gal_dot3(tb, t));
    for (int k = 0; k < 3; k++) r[k] = a[k] - f * (tb[k] + t[k]);
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
        transport(tb0, rod->abar + 3 * (i - 1), t0, A0); /* reference director of edge i-1 */
        transport(tb1, rod->abar + 3 * i, t1, A1);        /* and of edge i */
        transport(t0, A0, t1, u);                         /* edge i-1's carried across node i */
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
            node_stencil_q(rod, i, qi);
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
