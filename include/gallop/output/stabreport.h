/* stabreport.h: the outputs of `gallop stability`: stability.csv, summary.json, a table. */
#ifndef GALLOP_OUTPUT_STABREPORT_H
#define GALLOP_OUTPUT_STABREPORT_H

#include <stdio.h>

#include "gallop/analysis/stability.h"
#include "gallop/scene/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* DIR/stability.csv (every degree: coefficients, dC_L/dalpha, H, the onset speed of each mode,
 * empty where stable) and DIR/summary.json. */
int gal_stability_write(const char *dir, const gal_scene *sc, const gal_stability *S, double wall_time_s);
/* The table of `gallop stability` (every 10 deg) and the figures of each mode. */
void gal_stability_print(FILE *fp, const gal_scene *sc, const gal_stability *S);

#ifdef __cplusplus
}
#endif

#endif
