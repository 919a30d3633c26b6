/* terrain.h: the wind of the line standards: EN 1991-1-4 (Eurocode 1, wind actions), which
 * EN 50341-1 (overhead lines > 1 kV) uses for the wind on conductors.
 *   terrain categories (Table 4.1):  0: z0 = 0.003 m, z_min = 1 m;  I: 0.01, 1;  II: 0.05, 2;
 *                                    III: 0.3, 5;  IV: 1.0, 10;  z_max = 200 m
 *   terrain factor (Eq. 4.5):        k_r = 0.19 (z0 / 0.05)^0.07
 *   roughness factor (Eq. 4.4):      c_r(z) = k_r ln(z / z0),  z = max(z, z_min)
 *   mean wind (Eq. 4.3, c_0 = 1):    v_m(z) = c_r(z) v_b
 *   turbulence intensity (Eq. 4.7, k_I = 1, c_0 = 1):  I_v(z) = 1 / ln(z / z0)
 *   length scale (Annex B, Eq. B.1): L(z) = 300 m (z / 200 m)^alpha, alpha = 0.67 + 0.05 ln(z0),
 *                                    z0 in m
 *   spectrum (Annex B, Eq. B.2):     f S_v(f) / sigma_v^2 = 6.8 f_L / (1 + 10.2 f_L)^(5/3),
 *                                    f_L = f L(z) / v_m(z)   (gallop/loads/wind.h: en1991) */
#ifndef GALLOP_TERRAIN_H
#define GALLOP_TERRAIN_H

#include "gallop/scene/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* z0 (m) and z_min (m) of a category (Table 4.1); GAL_EINPUT for GAL_TERRAIN_NONE. */
int gal_terrain_category(gal_terrain t, double *z0, double *zmin);

/* At height z (m) over terrain of roughness length z0 (m) with minimum height zmin (m, 0: none):
 * the roughness factor c_r, the turbulence intensity I_v and the length scale L (m); any output
 * pointer may be NULL. GAL_EINPUT unless z0 > 0 and max(z, zmin) > z0. */
int gal_terrain_profile(double z0, double zmin, double z, double *cr, double *iv, double *L);

#ifdef __cplusplus
}
#endif

#endif
