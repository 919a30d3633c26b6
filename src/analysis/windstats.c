/* windstats.c: points along a generated wind field and the moments of U + u there (windstats.h). */
#include "gallop/analysis/windstats.h"
#include "gallop/base/core.h"

#include <math.h>

double gal_wind_stats_u(const gal_wind *w, const gal_wind_stats *s, int i, long k)
{
    double a = s->frac[i], u = gal_wind_u(w, s->pt[i], k);
    return a > 0 ? (1 - a) * u + a * gal_wind_u(w, s->pt[i] + 1, k) : u;
}

/* Mean and (population) standard deviation of U + u over the whole record at written point i. */
static void moments(const gal_wind *w, const gal_wind_stats *st, int i, double U, double *mean, double *sd)
{
    int n = gal_wind_samples(w);
    double s = 0, s2 = 0;
    for (int k = 0; k < n; k++) s += gal_wind_stats_u(w, st, i, k);
    double mu = s / n;
    for (int k = 0; k < n; k++) { /* two passes: no cancellation */
        double d = gal_wind_stats_u(w, st, i, k) - mu;
        s2 += d * d;
    }
    *mean = U + mu;
    *sd = sqrt(s2 / n);
}

int gal_wind_stats_compute(const gal_wind *w, double U, double length, int np, gal_wind_stats *s)
{
    if (np < 1 || np > GAL_WINDFIELD_POINTS)
        return gal_error(GAL_EINPUT, "wind: %d points; allowed: 1 to %d", np, GAL_WINDFIELD_POINTS);
    int last = gal_wind_points(w) - 1;
    double dx = gal_wind_spacing(w), extent = last * dx;
    if (!(length > 0) || length > extent) length = extent;
    s->np = np;
    for (int i = 0; i < np; i++) {
        s->x[i] = np == 1 ? 0.5 * length : length * i / (np - 1);
        double f = last > 0 ? s->x[i] / dx : 0, j = floor(f + 1e-9); /* on a point when within rounding */
        s->pt[i] = j < last ? (int)j : last;
        s->frac[i] = j < last && f - j > 1e-9 ? f - j : 0;
    }
    for (int i = 0; i < np; i++) moments(w, s, i, U, s->mean + i, s->sd + i);
    return GAL_OK;
}
