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

/* Edge j's unit tangent ta[0..2] and its reference director carried to it, ta[3..5]. */
void gal_rod_edge_frame(const gal_rod *rod, const double *q, int j, double ta[6])
{
    double e[3];
    for (int k = 0; k < 3; k++) e[k] = q[3 * (j + 1) + k] - q[3 * j + k];
    double le = gal_norm3(e);
    for (int k = 0; k < 3; k++) ta[k] = e[k] / le;
    gal_rod_transport(rod->tbar + 3 * j, rod->abar + 3 * j, ta, ta + 3);
}

void gal_rod_material_frame_from(const gal_rod *rod, const double *q, int j, const double ta[6], double t[3],
                                 double d1[3])
{
    const double *a = ta + 3;
    for (int k = 0; k < 3; k++) t[k] = ta[k];
    double th = rod->p.torsion ? q[3 * rod->nn + j] : 0.0, b[3];
    gal_cross3(t, a, b);
    for (int k = 0; k < 3; k++) d1[k] = cos(th) * a[k] + sin(th) * b[k];
}

void gal_rod_material_frame(const gal_rod *rod, const double *q, int j, double t[3], double d1[3])
{
    double ta[6];
    gal_rod_edge_frame(rod, q, j, ta);
    gal_rod_material_frame_from(rod, q, j, ta, t, d1);
}

void gal_rod_node_directions(const gal_rod *rod, const double *q, int i, double t[3], double ey[3], double nv[3])
{
    int nn = rod->nn, a = i > 0 ? i - 1 : i, b = i < nn - 1 ? i + 1 : i;
    for (int k = 0; k < 3; k++) t[k] = q[3 * b + k] - q[3 * a + k], ey[k] = k == 1;
    double lt = gal_norm3(t);
    for (int k = 0; k < 3; k++) t[k] /= lt;
    double ty = gal_dot3(ey, t);
    for (int k = 0; k < 3; k++) ey[k] -= ty * t[k];
    double ly = gal_norm3(ey);
    for (int k = 0; k < 3; k++) ey[k] /= ly;
    gal_cross3(t, ey, nv);
}

int gal_rod_frames_init(gal_rod *rod, const double *q0)
{
    int nel = rod->p.elements;
    for (int j = 0; j < nel; j++) {
        /* reference frame: unit tangent of q0 and a first director normal to it, chosen as the
         * horizontal normal y carried into the plane normal to the tangent */
        double *t = rod->tbar + 3 * j, *a = rod->abar + 3 * j;
        for (int k = 0; k < 3; k++) t[k] = q0[3 * (j + 1) + k] - q0[3 * j + k];
        double le = gal_norm3(t);
        if (!(le > 0)) {
            gal_error(GAL_EINPUT, "rod: element %d of the reference geometry has zero length", j);
            return GAL_EINPUT;
        }
        for (int k = 0; k < 3; k++) t[k] /= le;
        double y[3] = {0, 1, 0}, ty = gal_dot3(t, y);
        for (int k = 0; k < 3; k++) a[k] = y[k] - ty * t[k];
        double na = gal_norm3(a);
        if (na < 1e-6) { /* tangent along y: fall back to z */
            double z[3] = {0, 0, 1}, tz = gal_dot3(t, z);
            for (int k = 0; k < 3; k++) a[k] = z[k] - tz * t[k];
            na = gal_norm3(a);
        }
        for (int k = 0; k < 3; k++) a[k] /= na;
    }
    return GAL_OK;
}
