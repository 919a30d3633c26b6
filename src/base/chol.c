/* chol.c: CHOLMOD wrapper: analyse once, factorize and solve many times without allocating; the
 * tangent (values and analysis) one stage hands to the next. */
#include "base/chol.h"

#include <stdlib.h>
#include <string.h>

#include "gallop/base/core.h"

gal_chol *gal_chol_free(gal_chol *f)
{
    if (f) {
        cholmod_free_sparse(&f->A, &f->c);
        cholmod_free_factor(&f->L, &f->c);
        cholmod_free_dense(&f->B, &f->c);
        cholmod_free_dense(&f->X, &f->c);
        cholmod_free_dense(&f->Y, &f->c);
        cholmod_free_dense(&f->E, &f->c);
        cholmod_finish(&f->c);
        free(f->perm);
        free(f->map);
        free(f);
    }
    return NULL;
}

/* The permuted pattern A = triu(K(perm, perm)) with sorted columns, and map: K's entry k -> A's,
 * in O(nnz): the entries bucketed by their row in A (a counting sort), then placed into their
 * columns row by row, so that every column comes out sorted and each entry's place is known. */
static int permuted_pattern(gal_chol *f, const gal_csc *K)
{
    int n = K->n, nnz = K->nnz, st = GAL_ENOMEM;
    int *pinv = malloc((size_t)n * sizeof(int)), *next = calloc((size_t)n + 1, sizeof(int));
    int *byrow = malloc((size_t)nnz * sizeof(int)), *colof = malloc((size_t)nnz * sizeof(int));
    f->A = cholmod_allocate_sparse(n, n, nnz, 1, 1, 1, CHOLMOD_REAL, &f->c);
    f->map = malloc((size_t)nnz * sizeof(int));
    if (!pinv || !next || !byrow || !colof || !f->A || !f->map) goto done;
    int *Ap = f->A->p, *Ai = f->A->i;
    for (int k = 0; k < n; k++) pinv[f->perm[k]] = k;
    memset(Ap, 0, (size_t)(n + 1) * sizeof(int));
    for (int j = 0; j < n; j++)
        for (int p = K->colptr[j]; p < K->colptr[j + 1]; p++) {
            int a = pinv[K->rowind[p]], b = pinv[j];
            colof[p] = a > b ? a : b;
            next[(a > b ? b : a) + 1]++;
            Ap[colof[p] + 1]++;
        }
    for (int j = 0; j < n; j++) next[j + 1] += next[j], Ap[j + 1] += Ap[j];
    for (int j = 0; j < n; j++) /* bucket by row: next[r] runs from row r's start to its end */
        for (int p = K->colptr[j]; p < K->colptr[j + 1]; p++) {
            int a = pinv[K->rowind[p]], b = pinv[j];
            byrow[next[a > b ? b : a]++] = p;
        }
    memcpy(pinv, Ap, (size_t)n * sizeof(int)); /* pinv is done with: now each column's fill point */
    int q = 0;
    for (int r = 0; r < n; r++)
        for (; q < next[r]; q++) {
            int p = byrow[q], s = pinv[colof[p]]++;
            Ai[s] = r;
            f->map[p] = s;
        }
    st = GAL_OK;
done:
    free(pinv); free(next); free(byrow); free(colof);
    return st;
}

gal_chol *gal_chol_alloc(const gal_csc *K)
{
    gal_chol *f = calloc(1, sizeof *f);
    if (!f) return NULL;
    cholmod_start(&f->c);
    f->c.print = 0;
    f->c.error_handler = NULL;
    f->n = K->n;
    f->A = cholmod_allocate_sparse(K->n, K->n, K->nnz, 1, 1, 1, CHOLMOD_REAL, &f->c);
    f->B = cholmod_zeros(K->n, 1, CHOLMOD_REAL, &f->c);
    f->perm = malloc((size_t)K->n * sizeof(int));
    if (!f->A || !f->B || !f->perm) {
        gal_error(GAL_ENOMEM, "CHOLMOD: out of memory for a %d x %d matrix", K->n, K->n);
        return gal_chol_free(f);
    }
    memcpy(f->A->p, K->colptr, (size_t)(K->n + 1) * sizeof(int));
    memcpy(f->A->i, K->rowind, (size_t)K->nnz * sizeof(int));
    /* the fill-reducing ordering (CHOLMOD's choice, postordered); the matrix is then handed over
     * permuted, so the analysis is that of the permuted matrix in its natural order: a simplicial
     * factor's column counts are the same, only its Perm becomes the identity (what a second
     * analysis in the natural order gives, at 0.2 ms of 1 at 1000 elements); a supernodal one is
     * analysed again */
    f->L = cholmod_analyze(f->A, &f->c);
    if (f->L && f->c.status >= 0) {
        memcpy(f->perm, f->L->Perm, (size_t)K->n * sizeof(int));
        cholmod_free_sparse(&f->A, &f->c);
        if (permuted_pattern(f, K) != GAL_OK) {
            gal_error(GAL_ENOMEM, "CHOLMOD: out of memory for a %d x %d matrix", K->n, K->n);
            return gal_chol_free(f);
        }
        f->c.nmethods = 1;
        f->c.method[0].ordering = CHOLMOD_NATURAL;
        f->c.postorder = 0;
        if (!f->L->is_super) {
            int *P = f->L->Perm;
            for (int k = 0; k < K->n; k++) P[k] = k;
            f->L->ordering = CHOLMOD_NATURAL;
        } else {
            cholmod_free_factor(&f->L, &f->c);
            f->L = cholmod_analyze(f->A, &f->c);
        }
    }
    if (f->c.status == CHOLMOD_OUT_OF_MEMORY) {
        gal_error(GAL_ENOMEM, "CHOLMOD: out of memory in the symbolic analysis of a %d x %d matrix "
                  "(%d entries)", K->n, K->n, K->nnz);
        return gal_chol_free(f);
    }
    if (!f->L || f->c.status < 0) {
        gal_error(GAL_EFAIL, "CHOLMOD: symbolic analysis failed (status %d)", f->c.status);
        return gal_chol_free(f);
    }
    return f;
}

/* The numeric factorization of f->A as it was filled. */
static int factor_filled(gal_chol *f)
{
    f->factorizations++;
    int ok = cholmod_factorize(f->A, f->L, &f->c);
    /* out of memory is reported as memory, never as a matrix that is not positive definite (a
     * physical statement: lost stability) */
    if (f->c.status == CHOLMOD_OUT_OF_MEMORY)
        return gal_error(GAL_ENOMEM, "CHOLMOD: out of memory factorizing a %d x %d matrix", f->n, f->n);
    if (!ok || f->c.status == CHOLMOD_NOT_POSDEF || f->L->minor < (size_t)f->n)
        return gal_error(GAL_EFAIL, "the stiffness matrix is not positive definite (pivot %ld of %d)",
                         (long)f->L->minor, f->n);
    if (f->c.status < 0) return gal_error(GAL_EFAIL, "CHOLMOD: factorization failed (status %d)", f->c.status);
    f->negative_pivots = 0;
    if (!f->L->is_super && !f->L->is_ll) { /* LDL': D on the diagonal of L's columns */
        const int *Lp = f->L->p;
        const double *Lx = f->L->x;
        for (int j = 0; j < f->n; j++) f->negative_pivots += Lx[Lp[j]] < 0;
    }
    return GAL_OK;
}

int gal_chol_factor(gal_chol *f, const gal_csc *K, double shift, const double *d)
{
    double *Ax = f->A->x;
    const int *map = f->map;
    for (int k = 0; k < K->nnz; k++) Ax[map[k]] = K->val[k];
    if (shift != 0)
        for (int j = 0; j < K->n; j++) Ax[map[K->diag[j]]] += shift * (d ? d[j] : 1.0);
    return factor_filled(f);
}

int gal_chol_factor_pencil(gal_chol *f, const gal_csc *K, double sigma, const gal_csc *M)
{
    double *Ax = f->A->x;
    const int *map = f->map;
    for (int k = 0; k < K->nnz; k++) Ax[map[k]] = K->val[k] - sigma * M->val[k];
    return factor_filled(f);
}

gal_chol *gal_chol_clone(const gal_chol *f)
{
    gal_chol *g = calloc(1, sizeof *g);
    if (!g) {
        gal_error(GAL_ENOMEM, "CHOLMOD: out of memory copying a factorization");
        return NULL;
    }
    cholmod_start(&g->c);
    g->c.print = 0;
    g->c.error_handler = NULL;
    g->c.nmethods = 1; /* as gal_chol_alloc leaves it: A is handed over already permuted */
    g->c.method[0].ordering = CHOLMOD_NATURAL;
    g->c.postorder = 0;
    g->n = f->n, g->negative_pivots = f->negative_pivots;
    size_t nnz = (size_t)f->A->nzmax;
    g->A = cholmod_copy_sparse(f->A, &g->c);
    g->L = cholmod_copy_factor(f->L, &g->c);
    g->B = cholmod_zeros(f->n, 1, CHOLMOD_REAL, &g->c);
    g->perm = malloc((size_t)f->n * sizeof(int)), g->map = malloc(nnz * sizeof(int));
    if (!g->A || !g->L || !g->B || !g->perm || !g->map) {
        gal_error(GAL_ENOMEM, "CHOLMOD: out of memory copying the factorization of a %d x %d matrix", f->n, f->n);
        return gal_chol_free(g);
    }
    memcpy(g->perm, f->perm, (size_t)f->n * sizeof(int)), memcpy(g->map, f->map, nnz * sizeof(int));
    return g;
}

int gal_chol_solve(gal_chol *f, const double *b, double *x)
{
    double *B = f->B->x;
    for (int k = 0; k < f->n; k++) B[k] = b[f->perm[k]];
    if (!cholmod_solve2(CHOLMOD_A, f->L, f->B, NULL, &f->X, NULL, &f->Y, &f->E, &f->c))
        return gal_error(f->c.status == CHOLMOD_OUT_OF_MEMORY ? GAL_ENOMEM : GAL_EFAIL,
                         "CHOLMOD: solve failed (%s)", f->c.status == CHOLMOD_OUT_OF_MEMORY
                                                           ? "out of memory" : "numerical failure");
    const double *X = f->X->x;
    for (int k = 0; k < f->n; k++) x[f->perm[k]] = X[k];
    f->solves++;
    return GAL_OK;
}

gal_tangent *gal_tangent_alloc(gal_csc **K, gal_chol **chol, const double *q, int nq, double L0)
{
    gal_tangent *t = malloc(sizeof *t);
    double *qc = malloc((size_t)nq * sizeof(double));
    if (!t || !qc) {
        free(t); free(qc);
        return NULL;
    }
    memcpy(qc, q, (size_t)nq * sizeof(double));
    t->K = *K, t->chol = *chol, t->q = qc, t->nq = nq, t->L0 = L0;
    *K = NULL, *chol = NULL;
    return t;
}

gal_tangent *gal_tangent_copy(const gal_csc *K, const gal_chol *chol, const double *q, int nq, double L0)
{
    gal_csc *Kc = gal_csc_clone(K); /* the pattern */
    if (Kc) memcpy(Kc->val, K->val, (size_t)K->nnz * sizeof(double));
    gal_chol *c = Kc ? gal_chol_clone(chol) : NULL;
    gal_tangent *t = c ? gal_tangent_alloc(&Kc, &c, q, nq, L0) : NULL;
    if (!t) gal_csc_free(Kc), gal_chol_free(c);
    return t;
}

gal_tangent *gal_tangent_free(gal_tangent *t)
{
    if (t) {
        gal_csc_free(t->K);
        gal_chol_free(t->chol);
        free(t->q);
        free(t);
    }
    return NULL;
}
