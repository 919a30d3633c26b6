/* dense.c: LU with partial pivoting of a small dense matrix, and its solve (dense.h).
 *
 * The factorization is Crout's ordering of the plain right-looking elimination: at step k the
 * column k below the diagonal and then the row k right of it are brought up to date from the
 * finished L and U, each entry in a register, A(i,j) -= L(i,m) U(m,j) for m = 0, 1, .., k-1 in
 * that order, one product and one subtraction at a time. These are the right-looking
 * elimination's operations on every entry in its order, so the factors and the pivots are the
 * same bit for bit (tests/test_dense.c compares them); what changes is that an entry is stored
 * once, not once per step, and the row update runs over contiguous rows. */
#include "base/dense.h"

#include <math.h>
#include <stddef.h>

/* A(i,k) -= sum_m L(i,m) U(m,k), m < k in order, for the rows i = k .. r-1: four rows a pass
 * (each its own sum, sharing the loads of U's column k). Returns the pivot row: the first i with
 * the largest |A(i,k)| (compared in increasing i, as the entries come). */
static int column_update(double *A, int r, int k)
{
    const double *uk = A + k; /* U(m,k) = uk[m r] */
    int i = k, p = k;
    double best = 0; /* |A(k,k)| once brought up to date */
    for (; i + 4 <= r; i += 4) {
        double *a0 = A + (size_t)i * r, *a1 = a0 + r, *a2 = a1 + r, *a3 = a2 + r;
        double s0 = a0[k], s1 = a1[k], s2 = a2[k], s3 = a3[k];
        for (int m = 0; m < k; m++) {
            double u = uk[(size_t)m * r];
            s0 -= a0[m] * u, s1 -= a1[m] * u, s2 -= a2[m] * u, s3 -= a3[m] * u;
        }
        a0[k] = s0, a1[k] = s1, a2[k] = s2, a3[k] = s3;
        if (i == k) best = fabs(s0);
        if (fabs(s0) > best) best = fabs(s0), p = i;
        if (fabs(s1) > best) best = fabs(s1), p = i + 1;
        if (fabs(s2) > best) best = fabs(s2), p = i + 2;
        if (fabs(s3) > best) best = fabs(s3), p = i + 3;
    }
    for (; i < r; i++) {
        double *ai = A + (size_t)i * r, s = ai[k];
        for (int m = 0; m < k; m++) s -= ai[m] * uk[(size_t)m * r];
        ai[k] = s;
        if (i == k) best = fabs(s);
        if (fabs(s) > best) best = fabs(s), p = i;
    }
    return p;
}

/* A(k,j) -= sum_m L(k,m) U(m,j), m < k in order, for the columns j = k+1 .. r-1: eight columns a
 * pass (each its own sum, over U's rows, contiguous) */
static void row_update(double *A, int r, int k)
{
    double *ak = A + (size_t)k * r;
    int j = k + 1;
    for (; j + 8 <= r; j += 8) {
        double s0 = ak[j], s1 = ak[j + 1], s2 = ak[j + 2], s3 = ak[j + 3];
        double s4 = ak[j + 4], s5 = ak[j + 5], s6 = ak[j + 6], s7 = ak[j + 7];
        for (int m = 0; m < k; m++) {
            const double *um = A + (size_t)m * r + j;
            double l = ak[m];
            s0 -= l * um[0], s1 -= l * um[1], s2 -= l * um[2], s3 -= l * um[3];
            s4 -= l * um[4], s5 -= l * um[5], s6 -= l * um[6], s7 -= l * um[7];
        }
        ak[j] = s0, ak[j + 1] = s1, ak[j + 2] = s2, ak[j + 3] = s3;
        ak[j + 4] = s4, ak[j + 5] = s5, ak[j + 6] = s6, ak[j + 7] = s7;
    }
    if (j + 4 <= r) {
        double s0 = ak[j], s1 = ak[j + 1], s2 = ak[j + 2], s3 = ak[j + 3];
        for (int m = 0; m < k; m++) {
            const double *um = A + (size_t)m * r + j;
            double l = ak[m];
            s0 -= l * um[0], s1 -= l * um[1], s2 -= l * um[2], s3 -= l * um[3];
        }
        ak[j] = s0, ak[j + 1] = s1, ak[j + 2] = s2, ak[j + 3] = s3;
        j += 4;
    }
    if (j < r) { /* the last one to three: their sums side by side, m outside */
        double s[3] = {0, 0, 0};
        int t = r - j;
        for (int c = 0; c < t; c++) s[c] = ak[j + c];
        for (int m = 0; m < k; m++) {
            const double *um = A + (size_t)m * r + j;
            double l = ak[m];
            for (int c = 0; c < t; c++) s[c] -= l * um[c];
        }
        for (int c = 0; c < t; c++) ak[j + c] = s[c];
    }
}

int gal_dense_lu_factor(double *A, int r, int *piv)
{
    for (int k = 0; k < r; k++) {
        int p = column_update(A, r, k); /* the first largest |A(i,k)|, i >= k */
        piv[k] = p;
        if (!(fabs(A[(size_t)p * r + k]) > 0)) return -1;
        if (p != k) /* whole rows: L's finished part and the part not yet brought up to date */
            for (int j = 0; j < r; j++) {
                double t = A[(size_t)k * r + j];
                A[(size_t)k * r + j] = A[(size_t)p * r + j], A[(size_t)p * r + j] = t;
            }
        row_update(A, r, k);
        double d = A[(size_t)k * r + k];
        for (int i = k + 1; i < r; i++) A[(size_t)i * r + k] /= d; /* L(i,k) = A(i,k) / U(k,k) */
    }
    return 0;
}

/* P b, then the forward substitution by rows (contiguous), four rows a pass, then the backward
 * one; each entry's sum in a register, its subtractions in increasing k (forward) or j (backward):
 * the operations of the solve by columns in their order (tests/test_dense.c) */
void gal_dense_lu_solve(const double *A, int r, const int *piv, double *b)
{
    for (int k = 0; k < r; k++) { /* P b: every swap, in order, before L */
        double t = b[piv[k]];
        b[piv[k]] = b[k], b[k] = t;
    }
    int i = 1;
    for (; i + 4 <= r; i += 4) { /* b_i -= L_ik b_k, k = 0 .. i-1 in order */
        const double *l0 = A + (size_t)i * r, *l1 = l0 + r, *l2 = l1 + r, *l3 = l2 + r;
        double s0 = b[i], s1 = b[i + 1], s2 = b[i + 2], s3 = b[i + 3];
        for (int k = 0; k < i; k++) s0 -= l0[k] * b[k], s1 -= l1[k] * b[k], s2 -= l2[k] * b[k], s3 -= l3[k] * b[k];
        b[i] = s0;
        s1 -= l1[i] * b[i], b[i + 1] = s1;
        s2 -= l2[i] * b[i], s2 -= l2[i + 1] * b[i + 1], b[i + 2] = s2;
        s3 -= l3[i] * b[i], s3 -= l3[i + 1] * b[i + 1], s3 -= l3[i + 2] * b[i + 2], b[i + 3] = s3;
    }
    for (; i < r; i++) {
        const double *li = A + (size_t)i * r;
        double s = b[i];
        for (int k = 0; k < i; k++) s -= li[k] * b[k];
        b[i] = s;
    }
    for (int k = r - 1; k >= 0; k--) { /* b_k = (b_k - U_kj b_j, j = k+1 .. r-1 in order) / U_kk */
        const double *uk = A + (size_t)k * r;
        double s = b[k];
        for (int j = k + 1; j < r; j++) s -= uk[j] * b[j];
        b[k] = s / uk[k];
    }
}
