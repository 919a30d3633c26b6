/* simreport.h: the output files of `gallop simulate` (trace.csv, summary.json) and `gallop
 * compare` (compare.csv, summary.json). */
#ifndef GALLOP_SIMREPORT_H
#define GALLOP_SIMREPORT_H

#include "gallop/scene/scene.h"
#include "gallop/run/sim.h"
#include "gallop/analysis/measure.h"

typedef struct gal_compare_figures {
    double frequency_error, amplitude_error;        /* relative; amplitude: the worst of the three */
    double err_vertical, err_horizontal, err_twist;
    double speedup;                                  /* full over reduced wall time per simulated second */
} gal_compare_figures;

/* trace.csv of a run (temporary file, then rename). */
int gal_sim_write_trace(const char *path, const gal_sim_result *res);
int gal_sim_write_summary(const char *path, const gal_scene *sc, const gal_sim_result *r);
int gal_sim_write_compare(const char *dir, const gal_scene *sc, const gal_sim_result *full,
                          const gal_sim_result *red, gal_compare_figures *out);

#endif
