/* section.c: the quasi-steady load per unit length on a conductor section and its derivative
 * (paper Eq. 10; DESIGN.md "Aerodynamics"; the angle and sign convention is stated in
 * include/gallop/loads/aero.h), as the sum of its terms drag, lift and moment over the flow at
 * the section (the relative wind's normal part, its angle of attack and the coefficients). */
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

/* ---- the terms: each adds its coefficient and, with deriv, its part of the derivative ---- */

/* drag D = q V^2 C_D w^: d(V^2 C_D w^)/dw = V [C_D w^ w^T + C_D' w^ l^T + C_D P], P = I - e3 e3^T
 * (dV/dw = w^T, dalpha/dw = l^T / V, d(V w^)/dw = P) */
static void drag(const gal_aero_flow *fl, int deriv, gal_aero_sum *s)
{
    double cd = fl->c[0], dcd = fl->dc[0];
    for (int i = 0; i < 3; i++) s->g[i] += cd * fl->wh[i];
    if (deriv)
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                double P = (i == j) - fl->e3[i] * fl->e3[j];
                s->G[3 * i + j] += cd * fl->wh[i] * fl->wh[j] + dcd * fl->wh[i] * fl->lh[j] + cd * P;
            }
}

/* lift L = q V^2 C_L l^: d(V^2 C_L l^)/dw = V [C_L l^ w^T + C_L' l^ l^T + C_L [e3]x]
 * (d(V l^)/dw = [e3]x) */
static void lift(const gal_aero_flow *fl, int deriv, gal_aero_sum *s)
{
    double cl = fl->c[1], dcl = fl->dc[1];
    const double *e3 = fl->e3;
    for (int i = 0; i < 3; i++) s->g[i] += cl * fl->lh[i];
    if (deriv) {
        double X[9] = {0, -e3[2], e3[1], e3[2], 0, -e3[0], -e3[1], e3[0], 0}; /* [e3]x */
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                s->G[3 * i + j] += cl * fl->lh[i] * fl->wh[j] + dcl * fl->lh[i] * fl->lh[j] + cl * X[3 * i + j];
    }
}

/* moment M = q d V^2 C_M about +e3: d(V^2 C_M)/dw = V (2 C_M w^ + C_M' l^)^T */
static void moment(const gal_aero_flow *fl, int deriv, gal_aero_sum *s)
{
    s->cm += fl->c[2];
    if (deriv)
        for (int j = 0; j < 3; j++) s->Gm[j] += 2.0 * fl->c[2] * fl->wh[j] + fl->dc[2] * fl->lh[j];
}

const gal_aero_term gal_aero_term_drag = {"aero_drag", GAL_AERO_DRAG, drag};
const gal_aero_term gal_aero_term_lift = {"aero_lift", GAL_AERO_LIFT, lift};
const gal_aero_term gal_aero_term_moment = {"aero_moment", GAL_AERO_MOMENT, moment};

int gal_aero_terms(unsigned flags, const gal_aero_term *list[3])
{
    static const gal_aero_term *const all[3] = {&gal_aero_term_drag, &gal_aero_term_lift,
                                                &gal_aero_term_moment};
    int n = 0;
    for (int k = 0; k < 3; k++)
        if (flags & all[k]->flag) list[n++] = all[k];
    return n;
}

/* ---- the load: the flow at the section, then the sum of the terms ---- */

/* The flow: the normal part of the relative wind, its speed, direction and angle of attack, and
 * the coefficients there. GAL_OK with fl->V = 0 when there is no wind. */
static int flow(const gal_aero_table *t, const double tan[3], const double d1[3],
                const double wrel[3], double rho, double diam, int deriv, gal_aero_flow *fl)
{
    double e1[3], e2[3];
    int st = frame(tan, d1, e1, e2, fl->e3);
    if (st) return st;
    if (!finite3(wrel) || !isfinite(rho) || !isfinite(diam) || rho < 0 || diam < 0)
        return gal_error(GAL_EINPUT, "aerodynamic load: relative wind, air density or diameter not "
                         "finite or negative (rho = %g, d = %g)", rho, diam);
    double x = gal_dot3(wrel, e1), y = gal_dot3(wrel, e2);   /* wn = x e1 + y e2 */
    fl->V = hypot(x, y);
    if (!(fl->V > 1e-100)) {                       /* no wind, no load; load ~ V^2: zero slope */
        fl->V = 0;
        return GAL_OK;
    }
    for (int i = 0; i < 3; i++) {                  /* w^ and l^ = e3 x w^ */
        fl->wh[i] = (x * e1[i] + y * e2[i]) / fl->V;
        fl->lh[i] = (x * e2[i] - y * e1[i]) / fl->V;
    }
    if (!deriv) fl->dc[0] = fl->dc[1] = fl->dc[2] = 0; /* the slopes only for the derivative */
    gal_aero_eval(t, atan2(y, x), fl->c, deriv ? fl->dc : NULL);
    return GAL_OK;
}

int gal_aero_load_terms(const gal_aero_table *t, const double tan[3], const double d1[3],
                        const double wrel[3], double rho, double diam,
                        const gal_aero_term *const *terms, int nterms, double f[3], double *m,
                        double df[9], double dm[3])
{
    if (f) f[0] = f[1] = f[2] = 0.0;
    if (m) *m = 0.0;
    if (df) memset(df, 0, 9 * sizeof(double));
    if (dm) dm[0] = dm[1] = dm[2] = 0.0;
    gal_aero_flow fl;
    int deriv = df || dm;
    int st = flow(t, tan, d1, wrel, rho, diam, deriv, &fl);
    if (st || fl.V == 0) return st;
    gal_aero_sum s = {{0, 0, 0}, 0, {0}, {0, 0, 0}};
    for (int k = 0; k < nterms; k++) terms[k]->add(&fl, deriv, &s);
    double q = 0.5 * rho * diam, V = fl.V;         /* f = q V^2 g, m = q d V^2 cm */
    if (f)
        for (int i = 0; i < 3; i++) f[i] = q * V * V * s.g[i];
    if (m) *m = q * diam * V * V * s.cm;
    if (df)
        for (int k = 0; k < 9; k++) df[k] = q * V * s.G[k];
    if (dm)
        for (int j = 0; j < 3; j++) dm[j] = q * diam * V * s.Gm[j];
    return GAL_OK;
}

int gal_aero_load_deriv(const gal_aero_table *t, const double tan[3], const double d1[3],
                        const double wrel[3], double rho, double diam, unsigned flags,
                        double f[3], double *m, double df[9], double dm[3])
{
    const gal_aero_term *list[3];
    int n = gal_aero_terms(flags, list);
    return gal_aero_load_terms(t, tan, d1, wrel, rho, diam, list, n, f, m, df, dm);
}

int gal_aero_load(const gal_aero_table *t, const double tan[3], const double d1[3],
                  const double wrel[3], double rho, double diam, unsigned flags, double f[3],
                  double *m)
{
    return gal_aero_load_deriv(t, tan, d1, wrel, rho, diam, flags, f, m, NULL, NULL);
}
