/* test_dense.c: the dense LU of the reduced models (base/dense.h) on matrices that pivot. */
#include "check.h"
#include "base/dense.h"

#include <math.h>
#include <stdlib.h>

/* A x = b solved for a matrix whose every step pivots (small diagonal, larger entries below it),
 * against the product A x computed from the original A. */
static void test_pivoting_solve(void)
{
    enum { R = 7 };
    double A[R * R], LU[R * R], b[R], x[R];
    int piv[R], swaps = 0;
    for (int i = 0; i < R; i++)
        for (int j = 0; j < R; j++) A[i * R + j] = i == j ? 1e-3 * (i + 1) : sin(1.0 + 3 * i + 7 * j) * (1 + i);
    for (int k = 0; k < R * R; k++) LU[k] = A[k];
    CHECK(gal_dense_lu_factor(LU, R, piv) == 0, "factorization");
    for (int k = 0; k < R; k++) swaps += piv[k] != k;
    CHECK(swaps >= 3, "%d swaps", swaps); /* the case must pivot, more than once */
    for (int i = 0; i < R; i++) x[i] = b[i] = cos(0.3 + i);
    gal_dense_lu_solve(LU, R, piv, x);
    double err = 0, scale = 0;
    for (int i = 0; i < R; i++) {
        double s = 0;
        for (int j = 0; j < R; j++) s += A[i * R + j] * x[j];
        err = fmax(err, fabs(s - b[i])), scale = fmax(scale, fabs(b[i]));
    }
    CHECK(err < 1e-12 * scale, "residual %.3g of A x = b with pivoting", err);
}

/* A singular matrix (a zero column) is refused. */
static void test_singular(void)
{
    double A[9] = {1, 0, 2, 3, 0, 4, 5, 0, 6};
    int piv[3];
    CHECK(gal_dense_lu_factor(A, 3, piv) != 0, "a zero column is singular");
}

int main(void)
{
    RUN(test_pivoting_solve);
    RUN(test_singular);
    return CHECK_SUMMARY();
}
