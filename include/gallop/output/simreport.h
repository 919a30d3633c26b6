/* simreport.h: the output files of `gallop simulate` (trace.csv, summary.json) and `gallop
 * compare` (compare.csv, summary.json). */
#ifndef GALLOP_SIMREPORT_H
#define GALLOP_SIMREPORT_H

#include "gallop/scene/scene.h"
#include "gallop/run/sim.h"
#include "gallop/analysis/measure.h"
#include "gallop/analysis/compare.h"
#include "gallop/output/json.h"

#ifdef __cplusplus
extern "C" {
#endif

/* compare's summary.json figures into the open object of j: frequency_error, amplitude_error,
 * amplitude_errors {vertical, horizontal, twist}, speedup (the headline, compare.h), then
 * headline_probes {vertical, horizontal, twist} (their positions) and probes: per probe
 * both runs' measures and their errors (the single rod's and the bundle's). */
void gal_compare_figures_json(gal_json *j, const gal_compare_figures *c);

/* DIR/trace.csv and DIR/summary.json of `gallop simulate`, one output set. */
int gal_sim_write(const char *dir, const gal_scene *sc, const gal_sim_result *r);
/* The same, and the measures at the probe nearest mid-span (gal_sim_mid_probe) into *mid, those of
 * summary.json (each probe measured once). */
int gal_sim_write_measured(const char *dir, const gal_scene *sc, const gal_sim_result *r, gal_sim_measures *mid);
/* A lone trace.csv at path (temporary file, then rename), outside any output set. */
int gal_sim_write_trace(const char *path, const gal_sim_result *res);
/* DIR/compare.csv and DIR/summary.json of `gallop compare`, one output set; the figures in *out
 * (may be NULL). */
int gal_sim_write_compare(const char *dir, const gal_scene *sc, const gal_sim_result *full,
                          const gal_sim_result *red, gal_compare_figures *out);

#ifdef __cplusplus
}
#endif

#endif
