/* section.c: the quasi-steady load per unit length on a conductor section and its derivative
 * (paper Eq. 10; DESIGN.md "Aerodynamics"; the angle and sign convention is stated in
 * include/gallop/loads/aero.h). */
#include "gallop/loads/aero.h"
#include "gallop/base/core.h"
#include "gallop/base/vec3.h"

#include <math.h>
#include <string.h>

static int finite3(const double a[3]) { return isfinite(a[0]) && isfinite(a[1]) && isfinite(a[2]); }

/* The section frame: e3 = unit tangent, e1 = unit part of d1 normal to it, e2 = e3 x e1. */
static int frame(const double tan[3], const double d1[3], double e1[3], double e2[3], double e3[3])
{
    if (!finite3(tan) || !finite3(d1))
        return gal_error(GAL_EINPUT, "aerodynamic load: non-finite tangent or reference direction");
    double nt = sqrt(gal_dot3(tan, tan));
    if (!(nt > 0)) return gal_error(GAL_EINPUT, "aerodynamic load: zero tangent");
    for (int i = 0; i < 3; i++) e3[i] = tan[i] / nt;
    double s = gal_dot3(d1, e3);
    for (int i = 0; i < 3; i++) e1[i] = d1[i] - s * e3[i]; /* e1 = (I - e3 e3^T) d1 */
    double n1 = sqrt(gal_dot3(e1, e1)), nd = sqrt(gal_dot3(d1, d1));
    if (!(n1 > 1e-12 * nd) || !(nd > 0))
        return gal_error(GAL_EINPUT, "aerodynamic load: reference direction d1 is zero or parallel "
                         "to the tangent");
    for (int i = 0; i < 3; i++) e1[i] /= n1;
    gal_cross3(e3, e1, e2);
    return GAL_OK;
}

double gal_aero_alpha(const double tan[3], const double d1[3], const double wrel[3])
{
    double e1[3], e2[3], e3[3];
    if (frame(tan, d1, e1, e2, e3) != GAL_OK || !finite3(wrel)) return 0.0;
    double x = gal_dot3(wrel, e1), y = gal_dot3(wrel, e2);
    if (x == 0.0 && y == 0.0) return 0.0;
    return atan2(y, x);
}

int gal_aero_load_deriv(const gal_aero_table *t, const double tan[3], const double d1[3],
                        const double wrel[3], double rho, double diam, unsigned flags,
                        double f[3], double *m, double df[9], double dm[3])
{
    double e1[3], e2[3], e3[3];
    if (f) f[0] = f[1] = f[2] = 0.0;
    if (m) *m = 0.0;
    if (df) memset(df, 0, 9 * sizeof(double));
    if (dm) dm[0] = dm[1] = dm[2] = 0.0;
    int st = frame(tan, d1, e1, e2, e3);
    if (st) return st;
    if (!finite3(wrel) || !isfinite(rho) || !isfinite(diam) || rho < 0 || diam < 0)
        return gal_error(GAL_EINPUT, "aerodynamic load: relative wind, air density or diameter not "
                         "finite or negative (rho = %g, d = %g)", rho, diam);

    /* ---- normal part of the relative wind, its speed and direction ---- */
    double x = gal_dot3(wrel, e1), y = gal_dot3(wrel, e2);   /* wn = x e1 + y e2 */
    double V = hypot(x, y);
    if (!(V > 1e-100)) return GAL_OK;              /* no wind, no load; load ~ V^2: zero slope */
    double wh[3], lh[3];                            /* w^ and l^ = e3 x w^ */
    for (int i = 0; i < 3; i++) {
        wh[i] = (x * e1[i] + y * e2[i]) / V;
        lh[i] = (x * e2[i] - y * e1[i]) / V;
    }
    double alpha = atan2(y, x);
    double c[3], dc[3];
    gal_aero_eval(t, alpha, c, dc);
    double cd = (flags & GAL_AERO_DRAG) ? c[0] : 0.0, dcd = (flags & GAL_AERO_DRAG) ? dc[0] : 0.0;
    double cl = (flags & GAL_AERO_LIFT) ? c[1] : 0.0, dcl = (flags & GAL_AERO_LIFT) ? dc[1] : 0.0;
    double cm = (flags & GAL_AERO_MOMENT) ? c[2] : 0.0, dcm = (flags & GAL_AERO_MOMENT) ? dc[2] : 0.0;
    double q = 0.5 * rho * diam;                   /* f = q V^2 (C_D w^ + C_L l^) */

    double g[3];                                   /* C_D w^ + C_L l^ */
    for (int i = 0; i < 3; i++) g[i] = cd * wh[i] + cl * lh[i];
    if (f)
        for (int i = 0; i < 3; i++) f[i] = q * V * V * g[i];
    if (m) *m = q * diam * V * V * cm;

    if (df) {
        /* dV/dw = w^T, dalpha/dw = l^T / V, d(V w^)/dw = P = I - e3 e3^T, d(V l^)/dw = [e3]x:
         * df/dw = q V [ (C_D w^ + C_L l^) w^T + (C_D' w^ + C_L' l^) l^T + C_D P + C_L [e3]x ] */
        double h[3];
        for (int i = 0; i < 3; i++) h[i] = dcd * wh[i] + dcl * lh[i];
        double X[9] = {0, -e3[2], e3[1], e3[2], 0, -e3[0], -e3[1], e3[0], 0}; /* [e3]x */
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                double P = (i == j) - e3[i] * e3[j];
                df[3 * i + j] = q * V * (g[i] * wh[j] + h[i] * lh[j] + cd * P + cl * X[3 * i + j]);
            }
    }
    if (dm)
        for (int j = 0; j < 3; j++) /* dm/dw = q d V (2 C_M w^ + C_M' l^)^T */
            dm[j] = q * diam * V * (2.0 * cm * wh[j] + dcm * lh[j]);
    return GAL_OK;
}

int gal_aero_load(const gal_aero_table *t, const double tan[3], const double d1[3],
                  const double wrel[3], double rho, double diam, unsigned flags, double f[3],
                  double *m)
{
    return gal_aero_load_deriv(t, tan, d1, wrel, rho, diam, flags, f, m, NULL, NULL);
}
