/* sparse.h: the sparse matrix of the whole library: compressed sparse column storage of a
 * symmetric matrix by its upper triangle (row <= col), as CHOLMOD takes it (stype = 1). */
#ifndef GALLOP_BASE_SPARSE_H
#define GALLOP_BASE_SPARSE_H

#ifdef __cplusplus
extern "C" {
#endif

/* Compressed sparse column, upper triangle (row <= col), for the free degrees of freedom. */
typedef struct gal_csc {
    int n;        /* rows = columns */
    int nnz;
    int *colptr;  /* n + 1 */
    int *rowind;  /* nnz */
    double *val;  /* nnz */
    int *diag;    /* n: index of the diagonal entry of each column */
} gal_csc;

/* A copy of the pattern (values zeroed) for callers that keep their own matrix. */
gal_csc *gal_csc_clone(const gal_csc *A);
gal_csc *gal_csc_free(gal_csc *A);
/* y = A x for the symmetric matrix stored as its upper triangle. */
void gal_csc_symv(const gal_csc *A, const double *x, double *y);

/* Index of entry (i, j), i <= j, in the pattern, or -1. */
int gal_csc_find(const gal_csc *A, int i, int j);

#ifdef __cplusplus
}
#endif

#endif
