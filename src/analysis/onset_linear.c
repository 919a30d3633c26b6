/* onset_linear.c: the linearization of the aeroelastic equations about a mean-wind equilibrium:
 * aerodynamic stiffness and damping on a modal basis, the state matrix's eigenvalues, the
 * kinetic-energy shares of a complex mode. */
#include "onset_internal.h"
#include "gallop/base/core.h"
#include "gallop/base/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The generalized loads of element j (gal_loads_full's distribution, its element function: an
 * equivalent bundle's summed over its sub-conductors): g[0..2] on node j, g[3..5] on node j+1,
 * g[6] on the element's twist. */
int gal_onset_elem_load(const gal_loads *L, const gal_rod *rod, const double *q, const double *v, int j, double g[7])
{
    gal_loads Lr = *L;
    Lr.rod = rod;
    return gal_loads_element(&Lr, 0.0, q, v, j, g);
}

/* Central difference of element j's loads with respect to entry x[idx] (step h): column col of J. */
int gal_onset_elem_column(const gal_loads *L, const gal_rod *rod, double *q, double *v, int j, double *x, int idx,
                       double h, double *col)
{
    double x0 = x[idx], gp[7], gm[7];
    x[idx] = x0 + h;
    int st = gal_onset_elem_load(L, rod, q, v, j, gp);
    x[idx] = x0 - h;
    if (!st) st = gal_onset_elem_load(L, rod, q, v, j, gm);
    x[idx] = x0;
    if (st) return st;
    for (int r = 0; r < 7; r++) col[r] = (gp[r] - gm[r]) / (2 * h);
    return GAL_OK;
}

/* M_ab += -sum_rc P[r][a] J[r][c] P[c][b] over the element's local entries (P: 7 x n rows of Phi,
 * J: 7 x nc, columns mapped to rows of P by cmap) */
static void project_add(int n, const double *P, const double *J, int nc, const int *cmap, double *Mout, double *T)
{
    /* T (7 x n) = J P(cmap, :) */
    for (int r = 0; r < 7; r++)
        for (int b = 0; b < n; b++) {
            double s = 0;
            for (int c = 0; c < nc; c++) s += J[c * 7 + r] * P[cmap[c] * n + b];
            T[r * n + b] = s;
        }
    for (int b = 0; b < n; b++)
        for (int a = 0; a < n; a++) {
            double s = 0;
            for (int r = 0; r < 7; r++) s += P[r * n + a] * T[r * n + b];
            Mout[(size_t)b * n + a] -= s;
        }
}

int gal_onset_aero_matrices(const gal_rod *rod, const double *q0, const gal_loads *L, const double *phi, int n,
                            double *Ka, double *Ca)
{
    int nq = rod->nq, nn = rod->nn, nel = rod->p.elements, st = GAL_OK;
    double *q = malloc((size_t)nq * sizeof(double)), *v = calloc((size_t)nq, sizeof(double));
    double *P = calloc((size_t)7 * n, sizeof(double)), *T = malloc((size_t)7 * n * sizeof(double));
    if (!q || !v || !P || !T) { free(q); free(v); free(P); free(T); return gal_error(GAL_ENOMEM, "onset: out of memory"); }
    memcpy(q, q0, (size_t)nq * sizeof(double));
    if (Ka) memset(Ka, 0, (size_t)n * n * sizeof(double));
    if (Ca) memset(Ca, 0, (size_t)n * n * sizeof(double));
    double U = fmax(fabs(L->speed), 1.0), hx = 1e-5 * fmax(rod->p.length / nel, 1e-3), ht = 1e-6, hv = 1e-6 * U;
    int cmap[7] = {0, 1, 2, 3, 4, 5, 6};
    for (int j = 0; j < nel && !st; j++) {
        int qi[7], nc = rod->p.torsion ? 7 : 6;
        for (int k = 0; k < 3; k++) qi[k] = 3 * j + k, qi[3 + k] = 3 * (j + 1) + k;
        qi[6] = 3 * nn + j;
        int any = 0;
        for (int r = 0; r < 7; r++) {
            int d = (r < nc) ? rod->dof[qi[r]] : -1;
            for (int a = 0; a < n; a++) P[r * n + a] = d >= 0 ? phi[(size_t)a * rod->ndof + d] : 0;
            any |= d >= 0;
        }
        if (!any) continue;
        double J[49];
        if (Ka) {
            for (int c = 0; c < nc && !st; c++)
                st = gal_onset_elem_column(L, rod, q, v, j, q, qi[c], c < 6 ? hx : ht, J + 7 * c);
            if (!st) project_add(n, P, J, nc, cmap, Ka, T);
        }
        if (Ca && L->aero_damping && !st) {
            /* an equivalent bundle's loads depend on the twist rate too (its sub-conductors move) */
            int ncv = L->bundle.n > 1 ? nc : 6;
            for (int c = 0; c < ncv && !st; c++) st = gal_onset_elem_column(L, rod, q, v, j, v, qi[c], hv, J + 7 * c);
            if (!st) project_add(n, P, J, ncv, cmap, Ca, T);
        }
    }
    free(q); free(v); free(P); free(T);
    return st;
}

int gal_onset_state_eig(int n, const double *Kt, const double *Ct, double *A, double *wr, double *wi, double *VR,
                        double *work, int lwork)
{
    int N = 2 * n, info = 0, one = 1;
    memset(A, 0, (size_t)N * N * sizeof(double));
    for (int i = 0; i < n; i++) A[i + (size_t)(n + i) * N] = 1;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            A[(n + i) + (size_t)j * N] = -Kt[i + (size_t)j * n];
            A[(n + i) + (size_t)(n + j) * N] = -Ct[i + (size_t)j * n];
        }
    double dummy;
    dgeev_("N", VR ? "V" : "N", &N, A, &N, wr, wi, &dummy, &one, VR ? VR : &dummy, VR ? &N : &one, work, &lwork, &info);
    if (info) return gal_error(GAL_EFAIL, "onset: LAPACK dgeev failed (info %d) on the %d x %d state matrix", info, N, N);
    return GAL_OK;
}

void gal_onset_shares(const gal_rod *rod, const double *q, const double *ure, const double *uim, double *full,
                      double share[3])
{
    int nn = rod->nn, nel = rod->p.elements, nq = rod->nq;
    double *fr = full, *fi = full + nq;
    memset(full, 0, (size_t)2 * nq * sizeof(double));
    gal_rod_scatter(rod, ure, fr);
    gal_rod_scatter(rod, uim, fi);
    double chord[3], off[3];
    int mid = nn / 2;
    for (int k = 0; k < 3; k++) {
        chord[k] = q[3 * nel + k] - q[k];
        off[k] = q[3 * mid + k] - 0.5 * (q[k] + q[3 * nel + k]);
    }
    double b[3];
    gal_cross3(chord, off, b);
    double nb = sqrt(gal_dot3(b, b));
    if (nb < 1e-9 * gal_dot3(chord, chord)) b[0] = 0, b[1] = 1, b[2] = 0;
    else for (int k = 0; k < 3; k++) b[k] /= nb;
    double ke[4] = {0, 0, 0, 0};
    for (int i = 0; i < nn; i++) {
        int a = i > 0 ? i - 1 : 0, c = i < nel ? i : nel - 1;
        double t[3], nrm[3];
        for (int k = 0; k < 3; k++) t[k] = q[3 * (c + 1) + k] - q[3 * a + k];
        double nt = sqrt(gal_dot3(t, t));
        for (int k = 0; k < 3; k++) t[k] /= nt;
        gal_cross3(t, b, nrm);
        const double *u[2] = {fr + 3 * i, fi + 3 * i};
        for (int p = 0; p < 2; p++) {
            double uv = gal_dot3(u[p], nrm), uh = gal_dot3(u[p], b), ua = gal_dot3(u[p], t), m = rod->node_mass[i];
            ke[0] += m * uv * uv, ke[1] += m * uh * uh, ke[3] += m * ua * ua;
        }
    }
    if (rod->p.torsion)
        for (int j = 0; j < nel; j++)
            ke[2] += rod->edge_inertia[j] * (fr[3 * nn + j] * fr[3 * nn + j] + fi[3 * nn + j] * fi[3 * nn + j]);
    double tot = ke[0] + ke[1] + ke[2] + ke[3];
    for (int f = 0; f < 3; f++) share[f] = tot > 0 ? ke[f] / tot : 0;
}
