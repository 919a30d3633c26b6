/* simreport.h: measures of a run's traces (spectral module) and the output files of `gallop
 * simulate` (summary.json) and `gallop compare` (compare.csv, summary.json). */
#ifndef GALLOP_SIMREPORT_H
#define GALLOP_SIMREPORT_H

#include "gallop/scene/scene.h"
#include "gallop/run/sim.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct gal_sim_measures {
    double time_to_steady_s;      /* vertical envelope within 5% of its final level from then on */
    double rise_time_s;           /* vertical envelope first at 90% of its final level */
    double steady_from_s;         /* start of the window the measures are taken over */
    double frequency_hz[4];       /* horizontal, vertical, along, twist */
    double peak_to_peak[4];       /* m, m, m, deg */
    double rms[4], mean[4];
    double orbit_major, orbit_minor, orbit_tilt_deg; /* m, m, deg */
    double tension_min, tension_max;                 /* N, supports */
} gal_sim_measures;

typedef struct gal_compare_figures {
    double frequency_error, amplitude_error;        /* relative; amplitude: the worst of the three */
    double err_vertical, err_horizontal, err_twist;
    double speedup;                                  /* full over reduced wall time per simulated second */
} gal_compare_figures;

/* Measures at probe k over the steady part (from `from` s, or detected when from < 0). */
int gal_sim_measure(const gal_sim_result *r, int k, double from, gal_sim_measures *m);
int gal_sim_mid_probe(const gal_sim_result *r);
int gal_sim_write_summary(const char *path, const gal_scene *sc, const gal_sim_result *r);
int gal_sim_write_compare(const char *dir, const gal_scene *sc, const gal_sim_result *full,
                          const gal_sim_result *red, gal_compare_figures *out);

#ifdef __cplusplus
}
#endif

#endif
