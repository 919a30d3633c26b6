/* mass.c: the rod's mass matrix: lumped node masses and edge polar inertias, plus the eccentric
 * ice's twist-translation coupling. */
#include "gallop/base/core.h"
#include "rod_impl.h"
#include "gallop/base/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* M on the pattern of K: the lumped masses on the diagonal and, for eccentric ice, the coupling
 * of twist and translation (src/rod/ice.c). */
void gal_rod_mass_build(gal_rod *rod)
{
    gal_csc *M = rod->M;
    if (!M) return;
    memset(M->val, 0, (size_t)M->nnz * sizeof(double));
    if (!rod->mdiag && !(rod->mdiag = malloc((size_t)rod->ndof * sizeof(double)))) return;
    gal_rod_mass_diag(rod, rod->mdiag);
    for (int d = 0; d < rod->ndof; d++) M->val[M->diag[d]] = rod->mdiag[d];
    gal_rod_ice_mass(rod); /* the eccentric ice's coupling, if any */
}

void gal_rod_mass_mult(const gal_rod *rod, const double *x, double *y)
{
    if (rod->ecc_c) { /* eccentric ice: M couples twist and translation */
        gal_csc_symv(rod->M, x, y);
        return;
    }
    for (int d = 0; d < rod->ndof; d++) y[d] = rod->mdiag[d] * x[d]; /* lumped: diagonal */
}

void gal_rod_mass_diag(const gal_rod *rod, double *mdiag)
{
    for (int d = 0; d < rod->ndof; d++) {
        int q = rod->free_q[d];
        mdiag[d] = q < 3 * rod->nn ? rod->node_mass[q / 3] : rod->edge_inertia[q - 3 * rod->nn];
    }
}
