/* nnls.c: non-negative least squares, min |A x - b| subject to x >= 0, by the active-set method of
 * Lawson & Hanson (1974, "Solving least squares problems", ch. 23), stopped early once the
 * residual falls below a share of |b| (the sparse weights of ECSW: Farhat, Avery, Chapman &
 * Cortial 2014). The unconstrained subproblems on the passive set are solved by Householder QR
 * from scratch (the passive set stays small: it is the sample). */
#include "gallop/reduced/ecsw.h"
#include "gallop/base/core.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* column j of [Q c] (Q m x p column-major, c the column p) */
static double *column(double *Q, int m, int p, double *c, int j)
{
    return j < p ? Q + (size_t)j * m : c;
}

/* min |A_P z - b| over the p columns P of A (m x n, column-major) by Householder QR; Q (m x p) and
 * c (m) are scratch. Returns 0, or -1 when A_P is rank deficient. */
static int ls_solve(int m, const double *A, const double *b, const int *P, int p, double *z, double *Q, double *c)
{
    for (int k = 0; k < p; k++) memcpy(Q + (size_t)k * m, A + (size_t)P[k] * m, (size_t)m * sizeof(double));
    memcpy(c, b, (size_t)m * sizeof(double));
    for (int k = 0; k < p; k++) {
        double *qk = Q + (size_t)k * m, s = 0;
        for (int i = k; i < m; i++) s += qk[i] * qk[i];
        double nrm = sqrt(s);
        if (!(nrm > 0)) return -1;
        double alpha = qk[k] > 0 ? -nrm : nrm;    /* v = x - alpha e_k, H x = alpha e_k */
        qk[k] -= alpha;
        double vv = 0; /* |v|^2 */
        for (int i = k; i < m; i++) vv += qk[i] * qk[i];
        int j = k + 1; /* apply H = I - 2 v v^T / |v|^2 to the columns j > k and to c */
        for (; j + 4 <= p + 1; j += 4) { /* four columns a pass: four independent sums over i */
            double *y0 = column(Q, m, p, c, j), *y1 = column(Q, m, p, c, j + 1);
            double *y2 = column(Q, m, p, c, j + 2), *y3 = column(Q, m, p, c, j + 3);
            double d0 = 0, d1 = 0, d2 = 0, d3 = 0;
            for (int i = k; i < m; i++) d0 += qk[i] * y0[i], d1 += qk[i] * y1[i], d2 += qk[i] * y2[i], d3 += qk[i] * y3[i];
            d0 *= 2 / vv, d1 *= 2 / vv, d2 *= 2 / vv, d3 *= 2 / vv;
            for (int i = k; i < m; i++) y0[i] -= d0 * qk[i], y1[i] -= d1 * qk[i], y2[i] -= d2 * qk[i], y3[i] -= d3 * qk[i];
        }
        for (; j <= p; j++) {
            double *y = column(Q, m, p, c, j), d = 0;
            for (int i = k; i < m; i++) d += qk[i] * y[i];
            d *= 2 / vv;
            for (int i = k; i < m; i++) y[i] -= d * qk[i];
        }
        qk[k] = alpha; /* R(k,k); R(k, j > k) is Q[j * m + k] */
    }
    double rmax = 0;
    for (int k = 0; k < p; k++) rmax = fmax(rmax, fabs(Q[(size_t)k * m + k]));
    for (int k = p - 1; k >= 0; k--) {
        double r = Q[(size_t)k * m + k];
        if (!(fabs(r) > 1e-13 * rmax)) return -1;
        double s = c[k];
        for (int j = k + 1; j < p; j++) s -= Q[(size_t)j * m + k] * z[j];
        z[k] = s / r;
    }
    return 0;
}

/* r = b - A x over the passive set; returns |r|. */
static double resid(int m, const double *A, const double *b, const double *x, const int *P, int p, double *r)
{
    memcpy(r, b, (size_t)m * sizeof(double));
    for (int k = 0; k < p; k++) {
        const double *a = A + (size_t)P[k] * m;
        for (int i = 0; i < m; i++) r[i] -= a[i] * x[P[k]];
    }
    double s = 0;
    for (int i = 0; i < m; i++) s += r[i] * r[i];
    return sqrt(s);
}

int gal_nnls(int m, int n, const double *A, const double *b, double tol, int pmax, double *x, int *iterations)
{
    int p = 0, it = 0, st = GAL_OK;
    if (pmax <= 0 || pmax > n) pmax = n;
    if (pmax > m) pmax = m;
    int *P = malloc((size_t)n * sizeof(int)), *inP = calloc((size_t)n, sizeof(int));
    double *Q = malloc((size_t)m * pmax * sizeof(double)), *c = malloc((size_t)m * sizeof(double));
    double *r = malloc((size_t)m * sizeof(double)), *z = malloc((size_t)pmax * sizeof(double));
    if (!P || !inP || !Q || !c || !r || !z) { st = gal_error(GAL_ENOMEM, "nnls: out of memory (%d x %d)", m, n); goto done; }
    memset(x, 0, (size_t)n * sizeof(double));
    double nb = 0;
    for (int i = 0; i < m; i++) nb += b[i] * b[i];
    nb = sqrt(nb);
    double rn = nb;
    memcpy(r, b, (size_t)m * sizeof(double));
    while (rn > tol * nb && p < pmax && it < 3 * n) {
        /* the column most aligned with the residual, w_j = a_j^T r, among the active (x_j = 0) */
        int jb = -1;
        double wb = 0;
        for (int j0 = 0; j0 < n; j0 += 4) { /* four columns' sums at a time, compared in order */
            double w[4] = {0, 0, 0, 0};
            int nj = n - j0 < 4 ? n - j0 : 4;
            if (nj == 4) {
                const double *a0 = A + (size_t)j0 * m, *a1 = a0 + m, *a2 = a1 + m, *a3 = a2 + m;
                double w0 = 0, w1 = 0, w2 = 0, w3 = 0;
                for (int i = 0; i < m; i++) w0 += a0[i] * r[i], w1 += a1[i] * r[i], w2 += a2[i] * r[i], w3 += a3[i] * r[i];
                w[0] = w0, w[1] = w1, w[2] = w2, w[3] = w3;
            } else
                for (int t = 0; t < nj; t++) {
                    const double *a = A + (size_t)(j0 + t) * m;
                    for (int i = 0; i < m; i++) w[t] += a[i] * r[i];
                }
            for (int t = 0; t < nj; t++)
                if (!inP[j0 + t] && w[t] > wb) wb = w[t], jb = j0 + t;
        }
        if (jb < 0) break; /* Kuhn-Tucker: no descent direction left */
        P[p++] = jb, inP[jb] = 1;
        for (;;) { /* the inner loop: back along x -> z until z is feasible */
            it++;
            if (ls_solve(m, A, b, P, p, z, Q, c)) { /* the new column adds nothing: drop it */
                inP[P[--p]] = 2, x[jb] = 0; /* and never again */
                break;
            }
            double alpha = 1;
            for (int k = 0; k < p; k++)
                if (z[k] <= 0) alpha = fmin(alpha, x[P[k]] / (x[P[k]] - z[k]));
            for (int k = 0; k < p; k++) x[P[k]] += alpha * (z[k] - x[P[k]]);
            if (alpha >= 1) break;
            int q = 0; /* leave the passive set where x fell to zero */
            for (int k = 0; k < p; k++) {
                if (x[P[k]] <= 1e-15 * fabs(z[k])) { inP[P[k]] = 0, x[P[k]] = 0; continue; }
                P[q++] = P[k];
            }
            p = q;
            if (!p) break;
        }
        rn = resid(m, A, b, x, P, p, r);
    }
    if (iterations) *iterations = it;
done:
    free(P); free(inP); free(Q); free(c); free(r); free(z);
    return st;
}
