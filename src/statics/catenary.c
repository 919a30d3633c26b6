/* catenary.c: the elastic catenary (Irvine 1981, Eqs. 1.21-1.22 in Lagrangian form). */
#include "gallop/statics/catenary.h"
#include "gallop/base/core.h"

#include <float.h>
#include <math.h>

void gal_catenary_point(const gal_catenary *c, double s, double *x, double *z, double *tension)
{
    double H = c->H, V0 = c->V0, w = c->w, EA = c->EA;
    if (w == 0) { /* a straight line under tension T: dx/ds = H (1/EA + 1/T) */
        double T = sqrt(H * H + V0 * V0);
        *x = H * s / EA + H / T * s;
        *z = V0 * s / EA + V0 / T * s;
        if (tension) *tension = T;
        return;
    }
    double V = V0 + w * s;
    *x = H * s / EA + H / w * (asinh(V / H) - asinh(V0 / H));
    *z = (V0 * s + 0.5 * w * s * s) / EA + (sqrt(H * H + V * V) - sqrt(H * H + V0 * V0)) / w;
    if (tension) *tension = sqrt(H * H + V * V);
}

/* Closure residuals: the right end at (L, h). */
static void ends(const gal_catenary *c, double *rx, double *rz)
{
    double x, z;
    gal_catenary_point(c, c->L0, &x, &z, NULL);
    *rx = x - c->L;
    *rz = z - c->h;
}

/* Newton on two of (log H, V0, L0) with a finite-difference Jacobian and step halving. */
static int solve2(gal_catenary *c, int spec)
{
    double scale = fmax(c->L, 1.0);
    for (int it = 0; it < 100; it++) {
        double r[2];
        ends(c, &r[0], &r[1]);
        if (!isfinite(r[0]) || !isfinite(r[1])) return GAL_EFAIL;
        double rn = fmax(fabs(r[0]), fabs(r[1]));
        if (rn < 1e-12 * scale) return GAL_OK;
        /* unknowns u0, u1: spec 0 -> (V0, L0); spec 2 -> (log H, V0) */
        double J[2][2], u[2], hstep[2];
        if (spec == 0) u[0] = c->V0, u[1] = c->L0;
        else u[0] = log(c->H), u[1] = c->V0;
        hstep[0] = spec == 0 ? 1e-7 * (fabs(c->V0) + c->H) : 1e-7;
        hstep[1] = spec == 0 ? 1e-8 * c->L0 : 1e-7 * (fabs(c->V0) + c->H);
        for (int k = 0; k < 2; k++) {
            gal_catenary t = *c;
            double v = u[k] + hstep[k];
            if (spec == 0) { if (k == 0) t.V0 = v; else t.L0 = v; }
            else { if (k == 0) t.H = exp(v); else t.V0 = v; }
            double q[2];
            ends(&t, &q[0], &q[1]);
            J[0][k] = (q[0] - r[0]) / hstep[k];
            J[1][k] = (q[1] - r[1]) / hstep[k];
        }
        double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
        if (!(fabs(det) > 0)) return GAL_EFAIL;
        double d0 = -(J[1][1] * r[0] - J[0][1] * r[1]) / det;
        double d1 = -(-J[1][0] * r[0] + J[0][0] * r[1]) / det;
        if (spec != 0 && fabs(d0) > 1.0) d1 /= fabs(d0), d0 /= fabs(d0); /* at most a factor e in H */
        gal_catenary best = *c;
        double a = 1.0;
        for (int ls = 0; ls < 30; ls++, a *= 0.5) {
            gal_catenary t = best;
            if (spec == 0) t.V0 = u[0] + a * d0, t.L0 = u[1] + a * d1;
            else t.H = exp(u[0] + a * d0), t.V0 = u[1] + a * d1;
            if (spec == 0 && !(t.L0 > 0)) continue;
            double q[2];
            ends(&t, &q[0], &q[1]);
            if (isfinite(q[0]) && isfinite(q[1]) && fmax(fabs(q[0]), fabs(q[1])) < rn) {
                *c = t;
                break;
            }
            if (ls == 29) return rn < 1e-9 * scale ? GAL_OK : GAL_EFAIL;
        }
    }
    return GAL_EFAIL;
}

double gal_catenary_sag(const gal_catenary *c)
{
    /* find s with x(s) = L/2 by Newton (x is increasing in s), then sag = h/2 - z(s) */
    double s = 0.5 * c->L0, x, z;
    for (int it = 0; it < 60; it++) {
        double x1, z1;
        gal_catenary_point(c, s, &x, &z, NULL);
        double ds = 1e-7 * c->L0;
        gal_catenary_point(c, s + ds, &x1, &z1, NULL);
        double step = (0.5 * c->L - x) / ((x1 - x) / ds);
        s += step;
        if (fabs(step) < 1e-13 * c->L0) break;
    }
    gal_catenary_point(c, s, &x, &z, NULL);
    return 0.5 * c->h - z;
}

int gal_catenary_solve(gal_catenary *c, int spec, double value)
{
    double chord = sqrt(c->L * c->L + c->h * c->h);
    if (!(c->L > 0) || !(c->EA > 0) || !(c->w >= 0) || !(value > 0))
        return gal_error(GAL_EINPUT, "catenary: invalid span (L %g, EA %g, w %g, value %g)", c->L,
                         c->EA, c->w, value);
    if (c->w == 0) { /* straight line */
        if (spec == 1)
            return gal_error(GAL_EINPUT, "span.sag = %g m needs gravity: with gravity off the "
                             "conductor is a straight line; give horizontal_tension or "
                             "unstretched_length", value);
        if (spec == 0) {
            double T = value * chord / c->L;
            c->H = value, c->V0 = value * c->h / c->L;
            c->L0 = chord / (1.0 + T / c->EA);
        } else {
            if (!(value < chord))
                return gal_error(GAL_EINPUT, "span.unstretched_length = %g m: without gravity the "
                                 "conductor must be shorter than the chord (%g m) to be in tension",
                                 value, chord);
            double T = c->EA * (chord / value - 1.0);
            c->L0 = value, c->H = T * c->L / chord, c->V0 = T * c->h / chord;
        }
        return GAL_OK;
    }
    /* start from the parabolic cable: sag d = w L^2 / (8 H) */
    if (spec == 0) {
        c->H = value;
        double d = c->w * c->L * c->L / (8 * value);
        c->L0 = (chord + 8 * d * d / (3 * c->L)) / (1 + value / c->EA);
        c->V0 = value * c->h / c->L - 0.5 * c->w * c->L0;
        int st = solve2(c, 0);
        if (st != GAL_OK)
            return gal_error(GAL_EFAIL, "catenary: no equilibrium found for H = %g N", value);
        return GAL_OK;
    }
    if (spec == 2) {
        c->L0 = value;
        double slack = value - chord;
        double d = slack > 0 ? sqrt(3 * c->L * slack / 8) : 0.001 * c->L;
        c->H = fmax(c->w * c->L * c->L / (8 * d), c->EA * fmax(-slack / value, 0));
        c->V0 = c->H * c->h / c->L - 0.5 * c->w * value;
        int st = solve2(c, 2);
        if (st != GAL_OK)
            return gal_error(GAL_EFAIL, "catenary: no equilibrium found for L0 = %g m", value);
        return GAL_OK;
    }
    /* spec 1: sag; find H by safeguarded secant on log H (sag decreases as H grows) */
    if (!(value < 0.5 * c->L))
        return gal_error(GAL_EINPUT, "span.sag = %g m must be below half the span (%g m)", value, 0.5 * c->L);
    double lo = log(c->w * c->L * c->L / (8 * value)) - 3, hi = lo + 6;
    double flo, fhi;
    gal_catenary t = *c;
    if (gal_catenary_solve(&t, 0, exp(lo)) != GAL_OK) return GAL_EFAIL;
    flo = gal_catenary_sag(&t) - value;
    t = *c;
    if (gal_catenary_solve(&t, 0, exp(hi)) != GAL_OK) return GAL_EFAIL;
    fhi = gal_catenary_sag(&t) - value;
    for (int k = 0; k < 20 && flo < 0; k++) { lo -= 2; t = *c; gal_catenary_solve(&t, 0, exp(lo)); flo = gal_catenary_sag(&t) - value; }
    for (int k = 0; k < 20 && fhi > 0; k++) { hi += 2; t = *c; gal_catenary_solve(&t, 0, exp(hi)); fhi = gal_catenary_sag(&t) - value; }
    if (!(flo >= 0 && fhi <= 0))
        return gal_error(GAL_EFAIL, "catenary: no tension gives a sag of %g m", value);
    for (int it = 0; it < 200; it++) {
        double m = (fhi - flo) != 0 ? lo - flo * (hi - lo) / (fhi - flo) : 0.5 * (lo + hi);
        if (!(m > lo && m < hi) || it % 3 == 2) m = 0.5 * (lo + hi); /* keep the bracket shrinking */
        t = *c;
        if (gal_catenary_solve(&t, 0, exp(m)) != GAL_OK) return GAL_EFAIL;
        double f = gal_catenary_sag(&t) - value;
        /* the bracket on log H cannot shrink below a few doubles' spacing at |log H| ~ 10 */
        if (fabs(f) < 1e-12 * value || hi - lo < 8 * DBL_EPSILON * fmax(1, fabs(m))) {
            *c = t;
            return GAL_OK;
        }
        if (f > 0) lo = m, flo = f;
        else hi = m, fhi = f;
    }
    return gal_error(GAL_EFAIL, "catenary: the sag iteration did not converge");
}
