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
    double x[GAL_WINDFIELD_POINTS];      /* m from the left support */
    int pt[GAL_WINDFIELD_POINTS];        /* field point at or left of each: u is linear between */
    double frac[GAL_WINDFIELD_POINTS];   /* the weight of point pt + 1 (0 on a field point) */
    double mean[GAL_WINDFIELD_POINTS];   /* U + mean of u over the record, m/s */
    double sd[GAL_WINDFIELD_POINTS];     /* population standard deviation of u, m/s */
} gal_wind_stats;

/* np points (1 .. GAL_WINDFIELD_POINTS) evenly spaced over a span of the given length (m; <= 0:
 * the field's extent), or mid-span alone when np = 1, the field there interpolated linearly
 * between its points as the loads do (turbulence.c); U is the mean speed (m/s). GAL_EINPUT for a
 * bad np. */
int gal_wind_stats_compute(const gal_wind *w, double U, double length, int np, gal_wind_stats *s);
/* The fluctuation (m/s) at written point i, sample k. */
double gal_wind_stats_u(const gal_wind *w, const gal_wind_stats *s, int i, long k);

#ifdef __cplusplus
}
#endif

#endif
