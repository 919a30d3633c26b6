/* dense.h: LU factorization with partial pivoting of a small dense row-major matrix and its solve,
 * for the reduced models' iteration matrices (r x r, r up to a few hundred). The factorization
 * swaps whole rows, multipliers included (LAPACK's convention, P A = L U with P the swaps in their
 * order), so the solve permutes the right-hand side first, then runs the two triangular solves. */
#ifndef GALLOP_DENSE_H
#define GALLOP_DENSE_H

/* A (r x r, row-major) into its L\U factors in place, piv[k] the row swapped with k at step k.
 * 0, or -1 when a pivot column is exactly zero (A singular). */
int gal_dense_lu_factor(double *A, int r, int *piv);

/* b = A^-1 b with gal_dense_lu_factor's A and piv. */
void gal_dense_lu_solve(const double *A, int r, const int *piv, double *b);

#endif
