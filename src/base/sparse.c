/* sparse.c: compressed sparse column matrices stored as their upper triangle: clone, free, the
 * symmetric product and the look-up of an entry. */
#include "gallop/base/sparse.h"

#include <stdlib.h>
#include <string.h>

gal_csc *gal_csc_free(gal_csc *A)
{
    if (A) {
        free(A->colptr);
        free(A->rowind);
        free(A->val);
        free(A->diag);
        free(A);
    }
    return NULL;
}

gal_csc *gal_csc_clone(const gal_csc *A)
{
    gal_csc *B = calloc(1, sizeof *B);
    if (!B) return NULL;
    B->n = A->n;
    B->nnz = A->nnz;
    B->colptr = malloc((size_t)(A->n + 1) * sizeof(int));
    B->rowind = malloc((size_t)A->nnz * sizeof(int));
    B->val = calloc((size_t)A->nnz, sizeof(double));
    B->diag = malloc((size_t)A->n * sizeof(int));
    if (!B->colptr || !B->rowind || !B->val || !B->diag) return gal_csc_free(B);
    memcpy(B->colptr, A->colptr, (size_t)(A->n + 1) * sizeof(int));
    memcpy(B->rowind, A->rowind, (size_t)A->nnz * sizeof(int));
    memcpy(B->diag, A->diag, (size_t)A->n * sizeof(int));
    return B;
}

void gal_csc_symv(const gal_csc *A, const double *x, double *y)
{
    memset(y, 0, (size_t)A->n * sizeof(double));
    for (int j = 0; j < A->n; j++)
        for (int p = A->colptr[j]; p < A->colptr[j + 1]; p++) {
            int i = A->rowind[p];
            y[i] += A->val[p] * x[j];            /* upper part A(i,j) */
            if (i != j) y[j] += A->val[p] * x[i]; /* its mirror A(j,i) */
        }
}

/* Index of entry (i, j), i <= j, in the pattern, or -1. */
int gal_csc_find(const gal_csc *A, int i, int j)
{
    int lo = A->colptr[j], hi = A->colptr[j + 1] - 1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        if (A->rowind[mid] == i) return mid;
        if (A->rowind[mid] < i) lo = mid + 1;
        else hi = mid - 1;
    }
    return -1;
}
