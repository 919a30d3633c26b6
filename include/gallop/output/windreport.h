/* windreport.h: the outputs of `gallop wind`: wind.csv (U + u, and w when on, at the points),
 * summary.json, a table. */
#ifndef GALLOP_OUTPUT_WINDREPORT_H
#define GALLOP_OUTPUT_WINDREPORT_H

#include <stdio.h>

#include "gallop/analysis/windstats.h"
#include "gallop/scene/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The field of scene sc generated from wp in gen_time_s; its statistics s; with
 * wind.vertical_turbulence = on the vertical field wv from wpv and its statistics sv at the same
 * points (NULL when off). */
typedef struct gal_wind_report {
    const gal_scene *sc;
    const gal_wind_params *wp;
    const gal_wind *w;
    const gal_wind_stats *s;
    double gen_time_s;   /* generation, s (both components) */
    const gal_wind_params *wpv;
    const gal_wind *wv;
    const gal_wind_stats *sv;
} gal_wind_report;

/* DIR/wind.csv and DIR/summary.json. */
int gal_wind_write(const char *dir, const gal_wind_report *r, double wall_time_s);
/* The figures and the table of `gallop wind`. */
void gal_wind_print(FILE *fp, const gal_wind_report *r);

#ifdef __cplusplus
}
#endif

#endif
