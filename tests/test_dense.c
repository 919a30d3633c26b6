/* test_dense.c: the dense LU of the reduced models (base/dense.h) on matrices that pivot. */
#include "check.h"
#include "base/dense.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The plain right-looking elimination (the factorization before Crout's ordering): at step k,
 * pivot, swap whole rows, then A(i,j) -= L(i,k) U(k,j) for every i, j > k. The reference that
 * gal_dense_lu_factor must reproduce bit for bit. */
static int lu_right_looking(double *A, int r, int *piv)
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

/* The plain solve by columns: P b, then b_i -= L(i,k) b_k for k = 0, 1, .. (each b_i's
 * subtractions in increasing k), then b_k = (b_k - U(k,j) b_j, j increasing) / U(k,k). */
static void solve_by_columns(const double *A, int r, const int *piv, double *b)
{
    for (int k = 0; k < r; k++) {
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

/* The factors and pivots are the right-looking elimination's bit for bit (memcmp), and the solve
 * the solve by columns', on random
 * matrices of every order 1..97 (every remainder of the four- and eight-wide passes) that pivot,
 * some with entries spanning twenty decades, ties between candidate pivots, or a NaN (refused at
 * the same step, the pivots up to it the same). */
static void test_same_bits_as_right_looking(void)
{
    enum { RMAX = 97 };
    static double A[RMAX * RMAX], B[RMAX * RMAX];
    double xa[RMAX], xb[RMAX];
    int pa[RMAX], pb[RMAX], differ = 0, sdiffer = 0, swaps = 0;
    unsigned s = 12345;
    for (int r = 1; r <= RMAX; r++)
        for (int kind = 0; kind < 3; kind++) {
            for (int k = 0; k < r * r; k++) {
                s = s * 1103515245u + 12345u;
                double u = (double)(s >> 8) / 16777216.0 - 0.5; /* [-0.5, 0.5) */
                if (kind == 1) u *= pow(10, 20 * ((double)(k % 7) / 6 - 0.5));
                if (kind == 2) u = (double)((int)(8 * u)); /* small integers: ties and exact zeros */
                A[k] = B[k] = u;
            }
            if (kind == 2)
                for (int i = 0; i < r; i++) A[i * r + i] += 17 * (i % 3), B[i * r + i] = A[i * r + i];
            if (kind == 2 && r % 5 == 0) A[(r / 2) * (r + 1)] = B[(r / 2) * (r + 1)] = NAN; /* refused alike */
            for (int k = 0; k < r; k++) pa[k] = pb[k] = -7;
            int sa = gal_dense_lu_factor(A, r, pa), sb = lu_right_looking(B, r, pb);
            for (int k = 0; k < r; k++) swaps += pb[k] != k;
            if (sa != sb || memcmp(pa, pb, (size_t)r * sizeof(int)) ||
                (sb == 0 && memcmp(A, B, (size_t)r * r * sizeof(double))))
                differ++;
            if (sb) continue;
            for (int i = 0; i < r; i++) xa[i] = xb[i] = sin(0.7 + 1.3 * i);
            gal_dense_lu_solve(B, r, pb, xa);
            solve_by_columns(B, r, pb, xb);
            sdiffer += memcmp(xa, xb, (size_t)r * sizeof(double)) != 0;
        }
    CHECK(differ == 0, "%d of %d factorizations differ from the right-looking one", differ, 3 * RMAX);
    CHECK(sdiffer == 0, "%d solves differ from the solve by columns", sdiffer);
    CHECK(swaps > 1000, "%d swaps (the cases must pivot)", swaps);
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
    RUN(test_same_bits_as_right_looking);
    RUN(test_singular);
    return CHECK_SUMMARY();
}
