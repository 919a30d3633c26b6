/* stabreport.h: the outputs of `gallop stability`: stability.csv, summary.json, a table. */
#ifndef GALLOP_OUTPUT_STABREPORT_H
#define GALLOP_OUTPUT_STABREPORT_H

#include <stdio.h>

#include "gallop/analysis/onset.h"
#include "gallop/analysis/stability.h"
#include "gallop/output/json.h"
#include "gallop/output/outset.h"
#include "gallop/scene/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* DIR/stability.csv (every degree: coefficients, dC_L/dalpha, H, the onset speed of each mode,
 * empty where stable), DIR/summary.json and, with the coupled analysis O (may be NULL), DIR/vg.csv. */
int gal_stability_write(const char *dir, const gal_scene *sc, const gal_stability *S, const gal_onset *O,
                        double wall_time_s);
/* The coupled analysis (onsetreport.c): vg.csv into the output set, its figures and V-g table into
 * an open summary, its lines on stdout. */
int gal_onset_write_csv(const gal_onset *O, gal_outset *o);
void gal_onset_write_json(const gal_onset *O, gal_json *j);
void gal_onset_print(FILE *fp, const gal_onset *O);
/* The table of `gallop stability` (every 10 deg) and the figures of each mode. */
void gal_stability_print(FILE *fp, const gal_scene *sc, const gal_stability *S);

#ifdef __cplusplus
}
#endif

#endif
