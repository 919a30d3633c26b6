/* mass.c: the rod's mass matrix: lumped node masses and edge polar inertias, plus the eccentric
 * ice's twist-translation coupling. */
#include "gallop/base/core.h"
#include "rod_impl.h"
#include "gallop/base/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* M on the pattern of K: the lumped masses on the diagonal and, for eccentric ice, the coupling
 * of each edge's twist with the translation of its two nodes, 1/2 l0 m_i e (t x c) each (the
 * kinetic energy of the ice centre x + e c(theta): m_i e xdot . (t x c) thetadot). */
void gal_rod_mass_build(gal_rod *rod)
{
    gal_csc *M = rod->M;
    if (!M) return;
    memset(M->val, 0, (size_t)M->nnz * sizeof(double));
    if (!rod->mdiag && !(rod->mdiag = malloc((size_t)rod->ndof * sizeof(double)))) return;
    gal_rod_mass_diag(rod, rod->mdiag);
    for (int d = 0; d < rod->ndof; d++) M->val[M->diag[d]] = rod->mdiag[d];
    if (!rod->ecc_c || !rod->p.torsion) return;
    int nn = rod->nn;
    for (int j = 0; j < rod->p.elements; j++) {
        int dt = rod->dof[3 * nn + j];
        if (dt < 0) continue;
        double g[3], *c = rod->ecc_c + 3 * j, *t = rod->tbar + 3 * j;
        gal_cross3(t, c, g);
        double f = 0.5 * rod->l0[j] * rod->p.ecc_mass * rod->p.ecc;
        for (int node = j; node <= j + 1; node++)
            for (int k = 0; k < 3; k++) {
                int dx = rod->dof[3 * node + k];
                if (dx < 0) continue;
                int a = dx < dt ? dx : dt, b = dx < dt ? dt : dx;
                int sl = gal_csc_find(M, a, b);
                if (sl >= 0) M->val[sl] += f * g[k];
            }
    }
}

void gal_rod_mass_mult(const gal_rod *rod, const double *x, double *y)
{
    if (rod->ecc_c && rod->p.torsion) {
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
