/* chol.c: CHOLMOD wrapper: analyse once, factorize and solve many times without allocating. */
#include "base/chol.h"

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
        free(f);
    }
    return NULL;
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
    if (!f->A || !f->B) {
        gal_error(GAL_ENOMEM, "CHOLMOD: out of memory for a %d x %d matrix", K->n, K->n);
        return gal_chol_free(f);
    }
    int *Ap = f->A->p, *Ai = f->A->i;
    memcpy(Ap, K->colptr, (size_t)(K->n + 1) * sizeof(int));
    memcpy(Ai, K->rowind, (size_t)K->nnz * sizeof(int));
    f->L = cholmod_analyze(f->A, &f->c); /* fill-reducing ordering and symbolic factorization */
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

int gal_chol_factor(gal_chol *f, const gal_csc *K, double shift, const double *d)
{
    double *Ax = f->A->x;
    memcpy(Ax, K->val, (size_t)K->nnz * sizeof(double));
    if (shift != 0)
        for (int j = 0; j < K->n; j++) Ax[K->diag[j]] += shift * (d ? d[j] : 1.0);
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

int gal_chol_solve(gal_chol *f, const double *b, double *x)
{
    memcpy(f->B->x, b, (size_t)f->n * sizeof(double));
    if (!cholmod_solve2(CHOLMOD_A, f->L, f->B, NULL, &f->X, NULL, &f->Y, &f->E, &f->c))
        return gal_error(f->c.status == CHOLMOD_OUT_OF_MEMORY ? GAL_ENOMEM : GAL_EFAIL,
                         "CHOLMOD: solve failed (%s)", f->c.status == CHOLMOD_OUT_OF_MEMORY
                                                           ? "out of memory" : "numerical failure");
    memcpy(x, f->X->x, (size_t)f->n * sizeof(double));
    f->solves++;
    return GAL_OK;
}
