/* chol.h: sparse Cholesky factorization of a symmetric matrix given as its upper triangle in a
 * gal_csc pattern, by CHOLMOD: symbolic analysis once, numeric factorization many times, with an
 * optional diagonal shift (K + s D). The matrix is handed to CHOLMOD already permuted to its
 * fill-reducing order (an upper triangle in the natural order is what its simplicial LDL' takes
 * without a copy: otherwise every factorization transposes it twice). */
#ifndef GALLOP_CHOL_H
#define GALLOP_CHOL_H

#include <cholmod.h>

#include "gallop/base/sparse.h"

typedef struct gal_chol {
    cholmod_common c;
    cholmod_sparse *A;
    cholmod_factor *L;
    cholmod_dense *B, *X, *Y, *E;
    int n;
    int *perm;             /* n: the fill-reducing order, A's column k is K's column perm[k] */
    int *map;              /* K->nnz: where each entry of K lands in A = triu(K(perm, perm)) */
    long factorizations;   /* counter */
    long solves;           /* counter */
    int negative_pivots;   /* of the last factorization: the negative entries of D (the number of
                            * negative eigenvalues, Sylvester's law of inertia) */
} gal_chol;

gal_chol *gal_chol_alloc(const gal_csc *pattern);
gal_chol *gal_chol_free(gal_chol *f);
/* Factor K + shift * diag(d) (d NULL: the identity; shift 0: K alone). GAL_EFAIL when a pivot
 * is zero or, in a supernodal LL' factorization, not positive (the message says at which column);
 * the simplicial LDL' factorization CHOLMOD chooses for a banded rod factors an indefinite matrix:
 * f->negative_pivots then counts its negative eigenvalues (callers that need a positive definite
 * matrix check it). GAL_ENOMEM when CHOLMOD ran out of memory (callers pass that on: it is not a
 * statement about the matrix). */
int gal_chol_factor(gal_chol *f, const gal_csc *K, double shift, const double *d);
/* Factor K - sigma M, M on K's pattern (the same as gal_chol_factor of that matrix, without
 * forming it). */
int gal_chol_factor_pencil(gal_chol *f, const gal_csc *K, double sigma, const gal_csc *M);
/* A copy of f: its analysis, its last numeric factorization and counters at 0; solves with it give
 * the same numbers as with f. NULL when out of memory (with the message). */
gal_chol *gal_chol_clone(const gal_chol *f);
/* x = (K + shift D)^-1 b; x and b may be the same array. */
int gal_chol_solve(gal_chol *f, const double *b, double *x);

/* A tangent stiffness at a configuration with the symbolic analysis of its pattern, handed by the
 * stage that made them (the statics, whose stability check evaluates and factorizes the tangent at
 * the equilibrium) to the next (the modes, which would otherwise evaluate and analyse the same again:
 * a fifth of their time, issue 16). */
typedef struct gal_tangent {
    gal_csc *K;      /* the rod's pattern (a copy), the tangent's values at q */
    gal_chol *chol;  /* analysed on that pattern; its numeric factor is whatever was factorized last */
    double *q;       /* nq: the configuration (a copy: the taker checks that it is still the one) */
    int nq;
    double L0;       /* the rod's unstretched length when it was evaluated */
} gal_tangent;

/* Takes over K and chol (NULL in the callers' hands afterwards) and copies q; NULL when out of
 * memory (K and chol are then left where they were). */
gal_tangent *gal_tangent_alloc(gal_csc **K, gal_chol **chol, const double *q, int nq, double L0);
/* The same from copies of K and chol (gal_chol_clone: the numeric factor kept too); NULL when out
 * of memory. */
gal_tangent *gal_tangent_copy(const gal_csc *K, const gal_chol *chol, const double *q, int nq, double L0);
gal_tangent *gal_tangent_free(gal_tangent *t);

#endif
