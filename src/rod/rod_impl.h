/* rod_impl.h: what the files of the rod share inside src/rod/ (not public): the stencil sizes,
 * the tangent's pattern and slot maps, the mass matrix and the parallel transport of frames. */
#ifndef GALLOP_ROD_IMPL_H
#define GALLOP_ROD_IMPL_H

#include "gallop/rod/rod.h"

#define NL 11   /* node stencil: x_{i-1}, x_i, x_{i+1} (9), theta_{i-1}, theta_i */
#define EL 6    /* edge: x_j, x_{j+1} */

/* Configuration indices of the node stencil at interior node i (-1 for absent twists). */
void gal_rod_node_q(const gal_rod *rod, int i, int *qi);
/* The tangent's pattern (rod->K) and the slot maps of the node and edge stencils. */
int gal_rod_pattern_build(gal_rod *rod);
/* The mass matrix rod->M and its diagonal rod->mdiag from the current rest lengths. */
void gal_rod_mass_build(gal_rod *rod);
/* Parallel transport of a (normal to tb) from unit tangent tb to unit tangent t. */
void gal_rod_transport(const double *tb, const double *a, const double *t, double *r);

#endif
