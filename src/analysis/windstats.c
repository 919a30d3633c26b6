/* windstats.c: points along a generated wind field and the moments of U + u there (windstats.h). */
#include "gallop/analysis/windstats.h"
#include "gallop/base/core.h"

#include <math.h>

/* Mean and (population) standard deviation of U + u over the whole record at point j. */
static void moments(const gal_wind *w, int j, double U, double *mean, double *sd)
{
    const double *u = gal_wind_history(w, j);
    int n = gal_wind_samples(w);
    double s = 0, s2 = 0;
    for (int k = 0; k < n; k++) s += u[k];
    double mu = s / n;
    for (int k = 0; k < n; k++) s2 += (u[k] - mu) * (u[k] - mu); /* two passes: no cancellation */
    *mean = U + mu;
    *sd = sqrt(s2 / n);
}

int gal_wind_stats_compute(const gal_wind *w, double U, int np, gal_wind_stats *s)
{
    if (np < 1 || np > GAL_WINDFIELD_POINTS)
        return gal_error(GAL_EINPUT, "wind: %d points; allowed: 1 to %d", np, GAL_WINDFIELD_POINTS);
    int last = gal_wind_points(w) - 1;
    s->np = np;
    for (int i = 0; i < np; i++) s->pt[i] = np == 1 ? last / 2 : (int)lround((double)i * last / (np - 1));
    for (int i = 0; i < np; i++) moments(w, s->pt[i], U, s->mean + i, s->sd + i);
    return GAL_OK;
}
