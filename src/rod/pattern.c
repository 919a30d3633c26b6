/* pattern.c: the sparsity pattern of the rod's tangent stiffness (node and edge stencils, every
 * diagonal) and the slot maps that place each stencil's local pairs in its value array. */
#include "gallop/base/core.h"
#include "rod_impl.h"
#include "gallop/base/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- sparse pattern ---- */

static int cmp_pair(const void *a, const void *b)
{
    const long *x = a, *y = b;
    return (*x > *y) - (*x < *y);
}

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

int gal_rod_pattern_build(gal_rod *rod)
{
    int nel = rod->p.elements, nn = rod->nn;
    size_t cap = (size_t)(nn - 2) * NL * NL + (size_t)nel * EL * EL + 16;
    long *pairs = malloc(cap * sizeof(long));
    if (!pairs) return GAL_ENOMEM;
    size_t np = 0;
    int qi[NL];
    long n = rod->ndof;
    for (int i = 1; i <= nn - 2; i++) {
        gal_rod_node_q(rod, i, qi);
        for (int a = 0; a < NL; a++)
            for (int b = 0; b < NL; b++) {
                int da = qi[a] < 0 ? -1 : rod->dof[qi[a]], db = qi[b] < 0 ? -1 : rod->dof[qi[b]];
                if (da >= 0 && db >= 0 && da <= db) pairs[np++] = (long)db * n + da;
            }
    }
    for (int j = 0; j < nel; j++) {
        edge_q(j, qi);
        for (int a = 0; a < EL; a++)
            for (int b = 0; b < EL; b++) {
                int da = rod->dof[qi[a]], db = rod->dof[qi[b]];
                if (da >= 0 && db >= 0 && da <= db) pairs[np++] = (long)db * n + da;
            }
    }
    for (int d = 0; d < n; d++) pairs[np++] = (long)d * n + d; /* every diagonal */
    qsort(pairs, np, sizeof(long), cmp_pair);
    size_t nu = 0;
    for (size_t k = 0; k < np; k++)
        if (nu == 0 || pairs[k] != pairs[nu - 1]) pairs[nu++] = pairs[k];

    gal_csc *A = calloc(1, sizeof *A);
    if (!A) { free(pairs); return GAL_ENOMEM; }
    A->n = (int)n;
    A->nnz = (int)nu;
    A->colptr = calloc((size_t)n + 1, sizeof(int));
    A->rowind = malloc(nu * sizeof(int));
    A->val = calloc(nu, sizeof(double));
    A->diag = malloc((size_t)n * sizeof(int));
    if (!A->colptr || !A->rowind || !A->val || !A->diag) {
        free(pairs);
        gal_csc_free(A);
        return GAL_ENOMEM;
    }
    for (size_t k = 0; k < nu; k++) {
        int col = (int)(pairs[k] / n), row = (int)(pairs[k] % n);
        A->rowind[k] = row;
        A->colptr[col + 1]++;
    }
    for (int j = 0; j < n; j++) A->colptr[j + 1] += A->colptr[j];
    for (int j = 0; j < n; j++) A->diag[j] = gal_csc_find(A, j, j);
    free(pairs);
    rod->K = A;

    return slot_maps(rod);
}
