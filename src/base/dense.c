/* dense.c: LU with partial pivoting of a small dense matrix, and its solve (dense.h). */
#include "base/dense.h"

#include <math.h>

int gal_dense_lu_factor(double *A, int r, int *piv)
{
    for (int k = 0; k < r; k++) {
        int p = k;
        for (int i = k + 1; i < r; i++)
            if (fabs(A[i * r + k]) > fabs(A[p * r + k])) p = i;
        piv[k] = p;
        if (!(fabs(A[p * r + k]) > 0)) return -1;
        if (p != k)
            for (int j = 0; j < r; j++) {
                double t = A[k * r + j];
                A[k * r + j] = A[p * r + j], A[p * r + j] = t;
            }
        for (int i = k + 1; i < r; i++) {
            double l = A[i * r + k] /= A[k * r + k];
            for (int j = k + 1; j < r; j++) A[i * r + j] -= l * A[k * r + j];
        }
    }
    return 0;
}

void gal_dense_lu_solve(const double *A, int r, const int *piv, double *b)
{
    for (int k = 0; k < r; k++) { /* P b: every swap, in order, before L */
        double t = b[piv[k]];
        b[piv[k]] = b[k], b[k] = t;
    }
    for (int k = 0; k < r; k++)
        for (int i = k + 1; i < r; i++) b[i] -= A[i * r + k] * b[k];
    for (int k = r - 1; k >= 0; k--) {
        for (int j = k + 1; j < r; j++) b[k] -= A[k * r + j] * b[j];
        b[k] /= A[k * r + k];
    }
}
