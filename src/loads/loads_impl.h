/* loads_impl.h: what loads.c and bundle_section.c share inside src/loads/ (not public): the
 * section load of an equivalent bundle, summed over its sub-conductors. */
#ifndef GALLOP_LOADS_IMPL_H
#define GALLOP_LOADS_IMPL_H

#include "gallop/loads/loads.h"

/* The load per unit length on an equivalent bundle's section (L->bundle.n > 1): w the wind at the
 * centroid (before the relative terms of ls), rdot the centroid's velocity, spin the section's
 * twist rate (rad/s, about tan), tan and d1 its material frame, da the reference direction of
 * the angle of attack (d1 turned by the attack angle). Each sub-conductor k at
 * p_k = off[k][0] e1 + off[k][1] e2 (e1: d1's unit part normal to tan, e2 = tan x e1) moves at
 * rdot + spin tan x p_k, sees the relative wind that ls's terms make of w and that velocity, and
 * carries the section terms at its rho; out f = sum f_k (N/m), m = sum (m_k + (p_k x f_k) . tan)
 * (N m/m, about +tan). A status (the section load's). */
int gal_loads_bundle_section(const gal_loads *L, const gal_loads_list *ls, const double w[3],
                             const double rdot[3], double spin, const double tan[3], const double d1[3],
                             const double da[3], double f[3], double *m);

#endif
