/* terrain.c: the mean-wind profile, turbulence intensity and length scale of EN 1991-1-4
 * (Table 4.1, Eqs. 4.3-4.7, Annex B Eq. B.1), the formulas stated in gallop/scene/terrain.h. */
#include "gallop/scene/terrain.h"
#include "gallop/base/core.h"

#include <math.h>

int gal_terrain_category(gal_terrain t, double *z0, double *zmin)
{
    static const double Z0[5] = {0.003, 0.01, 0.05, 0.3, 1.0}; /* m, Table 4.1 */
    static const double ZMIN[5] = {1, 1, 2, 5, 10};            /* m, Table 4.1 */
    if (t < GAL_TERRAIN_0 || t > GAL_TERRAIN_IV)
        return gal_error(GAL_EINPUT, "terrain category %d: allowed 0, I, II, III, IV", (int)t);
    *z0 = Z0[t];
    *zmin = ZMIN[t];
    return GAL_OK;
}

int gal_terrain_profile(double z0, double zmin, double z, double *cr, double *iv, double *L)
{
    double ze = fmax(z, zmin);                           /* below z_min: the value at z_min */
    if (!(z0 > 0 && ze > z0 && isfinite(ze)))
        return gal_error(GAL_EINPUT, "wind profile: height %g m over roughness length %g m: "
                         "allowed z0 > 0 and height > z0", z, z0);
    double kr = 0.19 * pow(z0 / 0.05, 0.07);             /* Eq. 4.5, z0,II = 0.05 m */
    double lz = log(ze / z0);
    if (cr) *cr = kr * lz;                               /* Eq. 4.4 */
    if (iv) *iv = 1.0 / lz;                              /* Eq. 4.7, k_I = c_0 = 1 */
    if (L) *L = 300.0 * pow(ze / 200.0, 0.67 + 0.05 * log(z0)); /* Eq. B.1 */
    return GAL_OK;
}
