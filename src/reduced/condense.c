/* condense.c: static condensation of the full rod at prescribed modal coordinates (Hollkamp &
 * Gordon 2008's implicit condensation; reduced.h): Newton on the KKT system by its Schur complement
 * on the multipliers, which are the reduced restoring force. */
#include "gallop/reduced/reduced.h"
#include "gallop/base/core.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "reduced/internal.h"

int gal_kkt_alloc(gal_kkt_ws *w, const gal_rod *rod, const gal_reduced *rm)
{
    int n = rod->ndof, nq = rod->nq, r = rm->r;
    w->K = gal_csc_clone(rod->K);
    w->chol = w->K ? gal_chol_alloc(w->K) : NULL;
    w->g = malloc((size_t)nq * sizeof(double));
    w->r1 = malloc((size_t)n * sizeof(double)), w->x = malloc((size_t)n * sizeof(double));
    w->r2 = malloc((size_t)r * sizeof(double)), w->dl = malloc((size_t)r * sizeof(double));
    w->S = malloc((size_t)r * r * sizeof(double));
    w->Y = malloc((size_t)n * r * sizeof(double)), w->MPhi = malloc((size_t)n * r * sizeof(double));
    if (!w->K || !w->chol || !w->g || !w->r1 || !w->x || !w->r2 || !w->dl || !w->S || !w->Y || !w->MPhi) return GAL_ENOMEM;
    for (int i = 0; i < r; i++) gal_rod_mass_mult(rod, rm->phi + (size_t)i * n, w->MPhi + (size_t)i * n);
    return GAL_OK;
}

void gal_kkt_free(gal_kkt_ws *w)
{
    gal_chol_free(w->chol);
    gal_csc_free(w->K);
    free(w->g); free(w->r1); free(w->x); free(w->r2); free(w->dl); free(w->S); free(w->Y); free(w->MPhi);
}

static int solve_small(double *A, double *b, int r)
{
    /* Gaussian elimination with partial pivoting (r <= 40), A destroyed, b := A^-1 b */
    for (int c = 0; c < r; c++) {
        int p = c;
        for (int a = c + 1; a < r; a++) if (fabs(A[a * r + c]) > fabs(A[p * r + c])) p = a;
        if (!(fabs(A[p * r + c]) > 0)) return GAL_EFAIL;
        if (p != c) {
            for (int k = 0; k < r; k++) { double t = A[c * r + k]; A[c * r + k] = A[p * r + k]; A[p * r + k] = t; }
            double t = b[c]; b[c] = b[p]; b[p] = t;
        }
        for (int a = c + 1; a < r; a++) {
            double f = A[a * r + c] / A[c * r + c];
            for (int k = c; k < r; k++) A[a * r + k] -= f * A[c * r + k];
            b[a] -= f * b[c];
        }
    }
    for (int a = r - 1; a >= 0; a--) {
        double s = b[a];
        for (int k = a + 1; k < r; k++) s -= A[a * r + k] * b[k];
        b[a] = s / A[a * r + a];
    }
    return GAL_OK;
}

int gal_kkt_condense(const gal_rod *rod, const double *q_eq, const gal_reduced *rm, gal_kkt_ws *w, const double *eta,
                    double *q, double *lam, double ftol, long *iters)
{
    int n = rod->ndof, nq = rod->nq, r = rm->r, st;
    for (int it = 0; it < 60; it++) {
        if ((st = gal_rod_eval(rod, q, NULL, w->g, w->K))) return st;
        double rn1 = 0, rn2 = 0;
        for (int j = 0; j < n; j++) {
            double s = w->g[rod->free_q[j]];
            for (int i = 0; i < r; i++) s -= w->MPhi[(size_t)i * n + j] * lam[i];
            w->r1[j] = s;
            rn1 = fmax(rn1, fabs(s));
        }
        for (int i = 0; i < r; i++) {
            double s = -eta[i];
            for (int j = 0; j < n; j++) s += w->MPhi[(size_t)i * n + j] * (q[rod->free_q[j]] - q_eq[rod->free_q[j]]);
            w->r2[i] = s;
            rn2 = fmax(rn2, fabs(s) / rm->eta_ref[i]);
        }
        if (!isfinite(rn1) || !isfinite(rn2)) return gal_error(GAL_EFAIL, "reduced: condensation diverged");
        if (rn1 <= ftol && rn2 <= 1e-10) return GAL_OK;
        (*iters)++;
        if ((st = gal_chol_factor(w->chol, w->K, 0, NULL)))
            return gal_error(GAL_EFAIL, "reduced: the stiffness is not positive definite at a prescribed modal "
                             "amplitude (the span buckles or goes slack there): %s", gal_error_message());
        /* Y = K^-1 M Phi, S = (M Phi)^T Y, x = K^-1 r1 */
        for (int i = 0; i < r; i++)
            if ((st = gal_chol_solve(w->chol, w->MPhi + (size_t)i * n, w->Y + (size_t)i * n))) return st;
        if ((st = gal_chol_solve(w->chol, w->r1, w->x))) return st;
        for (int a = 0; a < r; a++) {
            double s = 0;
            for (int j = 0; j < n; j++) s += w->MPhi[(size_t)a * n + j] * w->x[j];
            w->dl[a] = s - w->r2[a]; /* S dlam = (M Phi)^T K^-1 r1 - r2 */
            for (int b = 0; b < r; b++) {
                double t = 0;
                for (int j = 0; j < n; j++) t += w->MPhi[(size_t)a * n + j] * w->Y[(size_t)b * n + j];
                w->S[a * r + b] = t;
            }
        }
        if ((st = solve_small(w->S, w->dl, r))) return gal_error(GAL_EFAIL, "reduced: singular modal constraint");
        /* dq = -x + Y dlam */
        for (int j = 0; j < n; j++) {
            double s = -w->x[j];
            for (int i = 0; i < r; i++) s += w->Y[(size_t)i * n + j] * w->dl[i];
            q[rod->free_q[j]] += s;
        }
        for (int i = 0; i < r; i++) lam[i] += w->dl[i];
    }
    (void)nq;
    return gal_error(GAL_EFAIL, "reduced: the condensation did not converge in 60 Newton iterations");
}

int gal_reduced_condensed_force(const gal_reduced *rm, const gal_rod *rod, const double *q_eq, const double *eta, double *f)
{
    int n = rod->ndof, nq = rod->nq, r = rm->r, st;
    gal_kkt_ws w = {0};
    double *q = malloc((size_t)nq * sizeof(double));
    if (gal_kkt_alloc(&w, rod, rm) != GAL_OK || !q) {
        st = gal_error(GAL_ENOMEM, "reduced: out of memory");
    } else {
        memcpy(q, q_eq, (size_t)nq * sizeof(double));
        for (int j = 0; j < n; j++) {
            double u = 0;
            for (int i = 0; i < r; i++) u += rm->phi[(size_t)i * n + j] * eta[i];
            q[rod->free_q[j]] += u;
        }
        for (int i = 0; i < r; i++) f[i] = rm->omega2[i] * eta[i];
        double tol = 20 * DBL_EPSILON * rod->p.length * rod->p.EA / rod->l0[0];
        long it = 0;
        st = gal_kkt_condense(rod, q_eq, rm, &w, eta, q, f, fmax(tol, 1e-9), &it);
    }
    gal_kkt_free(&w); free(q);
    return st;
}

