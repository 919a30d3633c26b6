/* windstats.h: what `gallop wind` reports of a generated turbulent field (loads/wind.h): N points
 * evenly spaced along the field and the mean and standard deviation of U + u at each. */
#ifndef GALLOP_WINDSTATS_H
#define GALLOP_WINDSTATS_H

#include "gallop/loads/wind.h"
#include "gallop/loads/windfield.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct gal_wind_stats {
    int np;                              /* points, 1 .. GAL_WINDFIELD_POINTS */
    int pt[GAL_WINDFIELD_POINTS];        /* field point index of each */
    double mean[GAL_WINDFIELD_POINTS];   /* U + mean of u over the record, m/s */
    double sd[GAL_WINDFIELD_POINTS];     /* population standard deviation of u, m/s */
} gal_wind_stats;

/* np points (1 .. GAL_WINDFIELD_POINTS) of the generated field w: the nearest to evenly spaced
 * over its points, or mid-span alone when np = 1; U is the mean speed (m/s). GAL_EINPUT for a
 * bad np. */
int gal_wind_stats_compute(const gal_wind *w, double U, int np, gal_wind_stats *s);

#ifdef __cplusplus
}
#endif

#endif
