/* rom_impl.h: what rom.c shares with romcheck.c (the explicit bundle's reduced model, bundle_rom.h). */
#ifndef GALLOP_BUNDLE_ROM_IMPL_H
#define GALLOP_BUNDLE_ROM_IMPL_H

#include "gallop/bundle/bundle_rom.h"

/* y = V x (ndof) */
void gal_bundle_rom_expand(const gal_bundle_rom *m, const double *x, double *y);
/* The state s at x, the gradient in b->grad (the tangent in b->K when asked), the loads in m->f at
 * time t and rate xd, and the net force's projection fi = V^T (grad U - F) (r; fe set to zero: the
 * equations take fi - fe, and fe only carries the linear steps' load corrections). */
int gal_bundle_rom_forces(gal_bundle_rom *m, const double *x, const double *xd, double t, int tangent, double *s,
                          double *fi, double *fe);
/* The reduced equations' own acceleration a = (V^T M(s) V)^-1 (fe - Cr v - fi) at the state of the
 * last evaluation (s). */
int gal_bundle_rom_acceleration(gal_bundle_rom *m, const double *s, const double *v, const double *fi,
                                const double *fe, double *a);

/* y = V^T M(s) V x at the state of the last evaluation (the map's values at s). */
void gal_bundle_rom_mass_mult(gal_bundle_rom *m, const double *s, const double *x, double *y);
/* The mass dofs S of the product above (m->sidx, m->VS; none with an eccentric ice), after the basis. */
int gal_bundle_rom_mass_dofs(gal_bundle_rom *m);

/* The arrays of a basis of at most rmax vectors (rom.c). */
int gal_bundle_rom_alloc_state(gal_bundle_rom *m, int rmax);
/* Kr = V^T A V (r x r, row-major) for a symmetric A on the system's pattern; uses m->z, m->g. */
void gal_bundle_rom_project_matrix(gal_bundle_rom *m, const gal_csc *A, double *Kr);
/* The basis, the damping and the mean loads' Jacobians (rombasis.c); K0, M0, chol0 set. */
int gal_bundle_rom_basis(gal_bundle_rom *m, const gal_modes *md);

#endif
