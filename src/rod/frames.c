/* frames.c: the rod's material frames: reference directors carried to the current tangents by
 * parallel transport (the minimal rotation), turned by the twist. */
#include "gallop/base/core.h"
#include "rod_impl.h"
#include "gallop/base/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Parallel transport of a (normal to tb) from unit tangent tb to unit tangent t. */
void gal_rod_transport(const double *tb, const double *a, const double *t, double *r)
{
    double f = gal_dot3(t, a) / (1.0 + gal_dot3(tb, t));
    for (int k = 0; k < 3; k++) r[k] = a[k] - f * (tb[k] + t[k]);
}

void gal_rod_material_frame(const gal_rod *rod, const double *q, int j, double t[3], double d1[3])
{
    double e[3], a[3];
    for (int k = 0; k < 3; k++) e[k] = q[3 * (j + 1) + k] - q[3 * j + k];
    double le = gal_norm3(e);
    for (int k = 0; k < 3; k++) t[k] = e[k] / le;
    gal_rod_transport(rod->tbar + 3 * j, rod->abar + 3 * j, t, a);
    double th = rod->p.torsion ? q[3 * rod->nn + j] : 0.0, b[3];
    gal_cross3(t, a, b);
    for (int k = 0; k < 3; k++) d1[k] = cos(th) * a[k] + sin(th) * b[k];
}
