/* compare.h: the figures of `gallop compare` (the single rod's and the explicit bundle's): the
 * full and the reduced run measured at every probe over one window, and per family (vertical,
 * horizontal, twist) a headline taken at the probe where the full model's peak-to-peak is
 * largest (an antisymmetric galloping barely moves mid-span). */
#ifndef GALLOP_ANALYSIS_COMPARE_H
#define GALLOP_ANALYSIS_COMPARE_H

#include "gallop/analysis/measure.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* the families of the headline, in this order: vertical, horizontal, twist */
enum { GAL_CMP_VERTICAL, GAL_CMP_HORIZONTAL, GAL_CMP_TWIST, GAL_CMP_FAMILIES };

typedef struct gal_compare_probe {
    double position;                   /* fraction of the span */
    gal_sim_measures full, reduced;    /* over the common window */
    double frequency_error;            /* relative, of the vertical fundamental frequency (measure.h:
                                        * frequency_hz; each run's dominant line and its harmonic
                                        * order are in dominant_hz, harmonic) */
    double err[GAL_CMP_FAMILIES];      /* relative peak-to-peak errors: vertical, horizontal, twist */
} gal_compare_probe;

typedef struct gal_compare_figures {
    /* the headline: each family at its probe (headline[]); frequency_error the vertical fundamental
     * frequency at the vertical headline probe; amplitude_error the worst of the three */
    double frequency_error, amplitude_error;
    double err_vertical, err_horizontal, err_twist;
    double speedup;                    /* full over reduced wall time (per simulated second) */
    int headline[GAL_CMP_FAMILIES];    /* probe index of each family's headline */
    /* both runs' measures as one record: those of the vertical headline probe, with the
     * horizontal and twist frequency and amplitude taken at their own headline probes */
    gal_sim_measures full, reduced;
    /* is the reference steady over the window? the full run's vertical peak-to-peak at the vertical
     * headline probe in the window's first and second halves, and their relative difference;
     * steady when it is at most GAL_CMP_STEADY_DRIFT (a run still in its transient, or bursting,
     * compares two transients: their figures say nothing of the reduced model's accuracy) */
    double window_pp_first, window_pp_second, window_drift;
    /* the same for every family at its headline probe (m, m, deg; [GAL_CMP_VERTICAL] repeats the
     * three above): a family is unsteady past GAL_CMP_STEADY_DRIFT when its change also passes what
     * issue 13's limits allow besides the 5% (horizontal: GAL_CMP_STEADY_H_OF_V of the vertical
     * peak-to-peak, twist: GAL_CMP_STEADY_TWIST_DEG), so that a small family's ripple is not taken
     * for a transient (a horizontal burst under a steady vertical was: BENCHMARKS.md, session 12) */
    double family_first[GAL_CMP_FAMILIES], family_second[GAL_CMP_FAMILIES], family_drift[GAL_CMP_FAMILIES];
    int family_steady[GAL_CMP_FAMILIES];
    int full_steady;                   /* every family steady */
    /* the window: its start is full.steady_from_s. The automatic one (gal_compare_runs with from < 0)
     * starts at the reference's time to steady (at least the run's last third: gal_sim_measure);
     * where the reference is unsteady over it, it moves later by a GAL_CMP_WINDOW_STEPS-th of its
     * length, up to GAL_CMP_WINDOW_TRIES - 1 times while each half keeps GAL_CMP_WINDOW_PERIODS
     * periods of the reference's vertical fundamental, to the first start over which the reference
     * is steady (window_moved = 1; window_first_from_s the automatic start); none: the automatic
     * window, unsteady, as before. A window given (from >= 0) is kept. Chosen on the reference
     * alone: the reduced run does not move it. */
    double window_first_from_s;
    int window_moved;
    int nprobe;
    gal_compare_probe probe[GAL_MAX_PROBES];
} gal_compare_figures;

#define GAL_CMP_STEADY_DRIFT 0.05
#define GAL_CMP_STEADY_H_OF_V 0.02
#define GAL_CMP_STEADY_TWIST_DEG 3.0
#define GAL_CMP_WINDOW_TRIES 3     /* the automatic start and two later ones */
#define GAL_CMP_WINDOW_STEPS 4     /* each a quarter of the automatic window later */
#define GAL_CMP_WINDOW_PERIODS 5.0 /* the least periods in each half of a moved window */

/* A family whose full peak-to-peak is below these (a micrometre; a ten-thousandth of a degree) does
 * not move: its relative error (and the vertical one's frequency error) is NaN, written null and
 * printed n/a, never a quotient of round-off (a span at rest, a decayed one). */
#define GAL_CMP_STILL_M 1e-6
#define GAL_CMP_STILL_DEG 1e-4

/* Measure both runs at every probe over one window and fill *c. The window is the full run's
 * steady part detected at the probe of largest full vertical peak-to-peak (from >= 0: from that
 * time instead). The runs must share their probes. */
int gal_compare_runs(const gal_sim_result *full, const gal_sim_result *red, double from, gal_compare_figures *c);

/* The same measure for a reference and any run measured against it (gallop accuracy, the tests of
 * tests/rom/): the reference's window (its steady part at the probe of largest vertical
 * peak-to-peak; from >= 0: from then) and per family the probe where it moves most, as
 * gal_compare_runs takes them. */
typedef struct gal_compare_ref {
    double from;                       /* window start, s */
    int headline[GAL_CMP_FAMILIES];    /* probe index per family: vertical, horizontal, twist */
    double position[GAL_CMP_FAMILIES]; /* those probes, fractions of the span */
} gal_compare_ref;

int gal_compare_reference(const gal_sim_result *full, double from, gal_compare_ref *h);
/* Run r measured over h's window: *m holds the vertical headline probe's measures, with the
 * horizontal and twist frequency, peak-to-peak, RMS and mean taken at their own headline probes
 * (gal_compare_figures' full and reduced records). The run must have the reference's probes. */
int gal_compare_measure(const gal_sim_result *r, const gal_compare_ref *h, gal_sim_measures *m);

#ifdef __cplusplus
}
#endif

#endif
