/* cigre.c: the outputs of a galloping study as CIGRE TB 322 (2007) reports them (cigre.h): the
 * galloping ellipse (principal axes of the orbit, peak-to-peak extents along them), its clearance
 * to a neighbouring phase, the dynamic support tensions, the empirical amplitude envelope.
 * The envelope's coefficients (80, 500) could not be checked against TB 322 or Lilien & Havard
 * (2000): searched 2026-11 through the project's search tools (pages, docs, code, issues:
 * "TB 322 galloping amplitude envelope", "A/D = 80 ln(L/500D)", "Lilien Havard galloping data base
 * prediction of maximum amplitudes", exact-string searches of public code); only the brochure's
 * title page was reachable. The source string says so in every summary.json. */
#include "gallop/analysis/cigre.h"
#include "gallop/analysis/spectrum.h"
#include "gallop/base/core.h"

#include <math.h>

const char *const gal_cigre_envelope_source =
    "A/D = 80 ln(L/(500 D)), single conductors: J.-L. Lilien, D. G. Havard, Galloping data base on single and "
    "bundle conductors, prediction of maximum amplitudes, IEEE Trans. Power Delivery 15(2), 2000, 670-674; "
    "CIGRE TB 322 (2007), section 4. NOT VERIFIED against either text: neither was reachable here (the brochure "
    "and the paper are not public; searches of public pages, documentation, code and issue threads for the "
    "formula found none); verify before design use";

int gal_cigre_ellipse(const double *y, const double *z, size_t n, gal_ellipse *e)
{
    gal_orbit o;
    int st = gal_spectrum_orbit(y, z, n, &o);
    if (st) return st;
    double th = o.tilt_deg * GAL_PI / 180, c = cos(th), s = sin(th);
    double amin = INFINITY, amax = -INFINITY, bmin = INFINITY, bmax = -INFINITY;
    for (size_t i = 0; i < n; i++) {
        double a = c * y[i] + s * z[i], b = -s * y[i] + c * z[i];   /* along the major, minor axis */
        amin = fmin(amin, a), amax = fmax(amax, a), bmin = fmin(bmin, b), bmax = fmax(bmax, b);
    }
    double am = 0.5 * (amin + amax), bm = 0.5 * (bmin + bmax);
    e->major_pp = amax - amin;
    e->minor_pp = bmax - bmin;
    e->tilt_deg = o.tilt_deg;
    e->centre_y = c * am - s * bm;
    e->centre_z = s * am + c * bm;
    return GAL_OK;
}

/* distance from (u, v), in the ellipse's frame, to the boundary u = a cos t, v = b sin t: the
 * nearest of 3600 points refined by Newton on the angle */
static double boundary_distance(double a, double b, double u, double v)
{
    int best = 0;
    double dbest = INFINITY;
    for (int k = 0; k < 3600; k++) {
        double t = 2 * GAL_PI * k / 3600, du = u - a * cos(t), dv = v - b * sin(t);
        if (du * du + dv * dv < dbest) dbest = du * du + dv * dv, best = k;
    }
    double t = 2 * GAL_PI * best / 3600;
    for (int it = 0; it < 20; it++) {   /* f(t) = d/dt |p - x(t)|^2 / 2 = 0 */
        double ct = cos(t), st = sin(t);
        double f = (a * ct - u) * (-a * st) + (b * st - v) * (b * ct);
        double df = (a * a - b * b) * (st * st - ct * ct) + u * a * ct + v * b * st;
        if (!(fabs(df) > 0)) break;
        double dt = f / df;
        t -= dt;
        if (fabs(dt) < 1e-14) break;
    }
    double du = u - a * cos(t), dv = v - b * sin(t);
    return fmin(sqrt(du * du + dv * dv), sqrt(dbest));
}

double gal_cigre_clearance(const gal_ellipse *e, double py, double pz)
{
    double th = e->tilt_deg * GAL_PI / 180, c = cos(th), s = sin(th);
    double dy = py - e->centre_y, dz = pz - e->centre_z;
    double u = c * dy + s * dz, v = -s * dy + c * dz;
    double a = 0.5 * e->major_pp, b = 0.5 * e->minor_pp;
    double d = boundary_distance(a, b, u, v);
    int inside = a > 0 && b > 0 ? (u * u) / (a * a) + (v * v) / (b * b) < 1 : 0;
    return inside ? -d : d;
}

double gal_cigre_envelope_single(double span_m, double diameter_m)
{
    if (!(span_m > 0 && diameter_m > 0)) return NAN;
    double r = span_m / (500 * diameter_m);
    return r > 1 ? 80 * diameter_m * log(r) : 0;
}

void gal_cigre_tensions(const double *tension, long nsamples, double rts_n, gal_tension_range *t)
{
    t->min_n = INFINITY, t->max_n = -INFINITY;
    for (long i = 0; i < 2 * nsamples; i++) t->min_n = fmin(t->min_n, tension[i]), t->max_n = fmax(t->max_n, tension[i]);
    t->static_n = nsamples > 0 ? fmax(tension[0], tension[1]) : NAN;
    t->max_over_static = t->static_n > 0 ? t->max_n / t->static_n : NAN;
    t->max_over_rts = rts_n > 0 ? t->max_n / rts_n : NAN;
}
