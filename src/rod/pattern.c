/* pattern.c: the sparsity pattern of the rod's tangent stiffness (node and edge stencils, every
 * diagonal) and the slot maps that place each stencil's local pairs in its value array. */
#include "gallop/base/core.h"
#include "rod_impl.h"
#include "gallop/base/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- sparse pattern ---- */

/* Configuration indices of the node stencil at interior node i and of edge j. */
void gal_rod_node_q(const gal_rod *rod, int i, int *qi)
{
    for (int k = 0; k < 9; k++) qi[k] = 3 * (i - 1) + k;
    if (rod->p.torsion) {
        qi[9] = 3 * rod->nn + i - 1;
        qi[10] = 3 * rod->nn + i;
    } else {
        qi[9] = qi[10] = -1;
    }
}

static void edge_q(int j, int *qi)
{
    for (int k = 0; k < 6; k++) qi[k] = 3 * j + k;
}

/* The slot maps: where each local pair of a node or edge stencil lands in the value array of K. */
static int slot_maps(gal_rod *rod)
{
    int nel = rod->p.elements, nn = rod->nn, qi[NL];
    const gal_csc *A = rod->K;
    rod->slot_node = malloc((size_t)(nn > 2 ? nn - 2 : 1) * NL * NL * sizeof(int));
    rod->slot_edge = malloc((size_t)nel * EL * EL * sizeof(int));
    if (!rod->slot_node || !rod->slot_edge) return GAL_ENOMEM;
    for (int i = 1; i <= nn - 2; i++) {
        int *s = rod->slot_node + (size_t)(i - 1) * NL * NL;
        gal_rod_node_q(rod, i, qi);
        for (int a = 0; a < NL; a++)
            for (int b = 0; b < NL; b++) {
                int da = qi[a] < 0 ? -1 : rod->dof[qi[a]], db = qi[b] < 0 ? -1 : rod->dof[qi[b]];
                s[a * NL + b] = (da >= 0 && db >= 0 && da <= db) ? gal_csc_find(A, da, db) : -1;
            }
    }
    for (int j = 0; j < nel; j++) {
        int *s = rod->slot_edge + (size_t)j * EL * EL;
        edge_q(j, qi);
        for (int a = 0; a < EL; a++)
            for (int b = 0; b < EL; b++) {
                int da = rod->dof[qi[a]], db = rod->dof[qi[b]];
                s[a * EL + b] = (da >= 0 && db >= 0 && da <= db) ? gal_csc_find(A, da, db) : -1;
            }
    }
    return GAL_OK;
}

/* The stencils' pairs (row da <= column db, every diagonal too) into pairs, as row * n + column. */
static size_t stencil_pairs(const gal_rod *rod, long *pairs)
{
    int nel = rod->p.elements, nn = rod->nn, qi[NL];
    long n = rod->ndof;
    size_t np = 0;
    for (int i = 1; i <= nn - 2; i++) {
        gal_rod_node_q(rod, i, qi);
        for (int a = 0; a < NL; a++)
            for (int b = 0; b < NL; b++) {
                int da = qi[a] < 0 ? -1 : rod->dof[qi[a]], db = qi[b] < 0 ? -1 : rod->dof[qi[b]];
                if (da >= 0 && db >= 0 && da <= db) pairs[np++] = (long)da * n + db;
            }
    }
    for (int j = 0; j < nel; j++) {
        edge_q(j, qi);
        for (int a = 0; a < EL; a++)
            for (int b = 0; b < EL; b++) {
                int da = rod->dof[qi[a]], db = rod->dof[qi[b]];
                if (da >= 0 && db >= 0 && da <= db) pairs[np++] = (long)da * n + db;
            }
    }
    for (int i = 1; i <= nn - 2 && rod->p.torsion && rod->p.bundle_fields; i++) {
        int qa[GAL_ROD_AUX_NL], na = gal_rod_aux_q(rod, i, qa);
        for (int a = 0; a < na; a++)
            for (int b = 0; b < na; b++) {
                int da = qa[a] < 0 ? -1 : rod->dof[qa[a]], db = qa[b] < 0 ? -1 : rod->dof[qa[b]];
                if (da >= 0 && db >= 0 && da <= db && (a >= NL || b >= NL)) pairs[np++] = (long)da * n + db;
            }
    }
    for (long d = 0; d < n; d++) pairs[np++] = d * n + d;
    return np;
}

/* The node stencil at interior node i widened by the bundle fields of its two edges:
 * gal_rod_node_q's 11 entries, then per field f a_{f,i-1}, a_{f,i}. Returns the count. */
int gal_rod_aux_q(const gal_rod *rod, int i, int *qi)
{
    int nel = rod->p.elements, nf = rod->p.torsion ? rod->p.bundle_fields : 0;
    gal_rod_node_q(rod, i, qi);
    for (int f = 0; f < nf; f++) {
        qi[NL + 2 * f] = 3 * rod->nn + (1 + f) * nel + i - 1;
        qi[NL + 2 * f + 1] = 3 * rod->nn + (1 + f) * nel + i;
    }
    return NL + 2 * nf;
}

/* The upper triangle's pattern from the stencils' pairs, without sorting: the pairs bucketed by
 * row (a counting sort), then each row's columns, duplicates dropped by a marker, appended to
 * their columns in increasing row order, so every column comes out sorted. O(pairs + n). */
int gal_rod_pattern_build(gal_rod *rod)
{
    int n = rod->ndof;
    size_t cap = (size_t)(rod->nn > 2 ? rod->nn - 2 : 0) * GAL_ROD_AUX_NL * GAL_ROD_AUX_NL * 2 +
                 (size_t)rod->p.elements * EL * EL + (size_t)n;
    long *pairs = malloc(cap * sizeof(long));
    int *rowptr = calloc((size_t)n + 1, sizeof(int)), *cols = malloc(cap * sizeof(int));
    int *mark = malloc((size_t)n * sizeof(int));
    gal_csc *A = calloc(1, sizeof *A);
    if (A) A->colptr = calloc((size_t)n + 1, sizeof(int)), A->diag = malloc((size_t)n * sizeof(int));
    if (!pairs || !rowptr || !cols || !mark || !A || !A->colptr || !A->diag) goto fail;
    size_t np = stencil_pairs(rod, pairs);
    for (size_t k = 0; k < np; k++) rowptr[pairs[k] / n + 1]++;
    for (int r = 0; r < n; r++) rowptr[r + 1] += rowptr[r];
    for (size_t k = 0; k < np; k++) cols[rowptr[pairs[k] / n]++] = (int)(pairs[k] % n);
    for (int r = n; r > 0; r--) rowptr[r] = rowptr[r - 1]; /* the fill moved each start to the next */
    rowptr[0] = 0;
    /* count the distinct entries per column, then place them */
    for (int pass = 0; pass < 2; pass++) {
        for (int j = 0; j < n; j++) mark[j] = -1;
        for (int r = 0; r < n; r++)
            for (int p = rowptr[r]; p < rowptr[r + 1]; p++) {
                int c = cols[p];
                if (mark[c] == r) continue;
                mark[c] = r;
                if (pass == 0) A->colptr[c + 1]++;
                else A->rowind[A->diag[c]++] = r; /* diag: the fill position while placing */
            }
        if (pass == 1) break;
        for (int j = 0; j < n; j++) A->colptr[j + 1] += A->colptr[j];
        A->n = n, A->nnz = A->colptr[n];
        A->rowind = malloc((size_t)A->nnz * sizeof(int));
        A->val = calloc((size_t)A->nnz, sizeof(double));
        if (!A->rowind || !A->val) goto fail;
        memcpy(A->diag, A->colptr, (size_t)n * sizeof(int));
    }
    for (int j = 0; j < n; j++) A->diag[j] = A->colptr[j + 1] - 1; /* the diagonal is last in its column */
    free(pairs); free(rowptr); free(cols); free(mark);
    rod->K = A;
    return slot_maps(rod);
fail:
    free(pairs); free(rowptr); free(cols); free(mark);
    gal_csc_free(A);
    return GAL_ENOMEM;
}
