/* measure.h: measures of a run's traces (spectral module): dominant frequencies, amplitudes,
 * orbit ellipse, time to steady galloping, support tensions. */
#ifndef GALLOP_ANALYSIS_MEASURE_H
#define GALLOP_ANALYSIS_MEASURE_H

#include "gallop/run/sim.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct gal_sim_measures {
    double time_to_steady_s;      /* vertical envelope within 5% of its final level from then on */
    double rise_time_s;           /* vertical envelope first at 90% of its final level */
    double steady_from_s;         /* start of the window the measures are taken over */
    /* horizontal, vertical, along, twist: the fundamental of each trace (gal_spectrum_fundamental,
     * spectrum.h: the lowest significant line of which the dominant one is a harmonic), the
     * dominant (largest) line and its order as a harmonic of the fundamental (1: the same line) */
    double frequency_hz[4];
    double dominant_hz[4];
    int harmonic[4];
    double peak_to_peak[4];       /* m, m, m, deg */
    double rms[4], mean[4];
    double orbit_major, orbit_minor, orbit_tilt_deg; /* m, m, deg */
    /* the support tensions (the end elements' tensions, trace.csv tension_left_n/right_n), the
     * smallest and largest of both supports: over the whole run, and over the steady window
     * [steady_from_s, end] the other measures are taken over (summary.json: tension_min_run_n,
     * tension_max_run_n, tension_min_steady_n, tension_max_steady_n; tension_min_n and
     * tension_max_n are the whole run's) */
    double tension_min, tension_max;                 /* N, whole run */
    double tension_min_steady, tension_max_steady;   /* N, steady window */
} gal_sim_measures;

/* Measures at probe k over the steady part (from `from` s, or detected when from < 0). */
int gal_sim_measure(const gal_sim_result *r, int k, double from, gal_sim_measures *m);
/* The probe nearest to mid-span. */
int gal_sim_mid_probe(const gal_sim_result *r);

#ifdef __cplusplus
}
#endif

#endif
