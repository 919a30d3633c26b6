/* accuracy.h: what accuracy costs in time (issue 7, DESIGN.md "Command line": gallop accuracy).
 * For one scene, each study sweeps one choice (mesh, reduced basis, time step, physical effects),
 * measures the error of every setting against a reference setting of the same study and the wall
 * time it took, and names the cheapest setting whose error is within the tolerance.
 * The scene itself is never changed: every setting runs on a copy. */
#ifndef GALLOP_ACCURACY_H
#define GALLOP_ACCURACY_H

#include "gallop/scene/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    GAL_ACC_ELEMENTS,  /* model.elements: statics + modes against a fine mesh */
    GAL_ACC_MODES,     /* reduced basis size against one full-model run */
    GAL_ACC_TIME_STEP, /* full model: simulation.time_step = T/10 .. T/80 against T/160 */
    GAL_ACC_EFFECTS,   /* reduced model with one effect off at a time against all on */
    GAL_ACC_NEWTON_TOL,/* full model: simulation.newton_tolerance = 1e-3 .. 1e-8 against 1e-10 */
    GAL_ACC_FRONT,     /* every choice against a converged full-model reference: the Pareto front
                        * of error against wall time (accuracy_front.c; the default study) */
    GAL_ACC_NSTUDY
} gal_acc_study;

extern const char *const gal_acc_study_names[GAL_ACC_NSTUDY];

typedef struct gal_acc_opts {
    double tolerance;   /* relative error a setting must meet; default 0.01 */
    unsigned studies;   /* bit (1u << study) per study to run; default all */
    int repeats;        /* timing repeats (median) for settings cheaper than 1 s; default 3 */
    int progress;       /* 1: one line per setting on stderr */
    double budget_s;    /* front: wall-time limit of the whole study, s; 0: none (a fixed set) */
    int seeds;          /* front, turbulent wind: seeds the statistics are taken over; default 3 */
    int max_levels;     /* front: reference refinements at most (elements x2 and step /2 each);
                         * default 3 */
} gal_acc_opts;

/* One setting of one study. */
typedef struct gal_acc_row {
    gal_acc_study study;
    char setting[48];     /* key name, e.g. model.elements */
    char value[48];       /* its value as written on the command line (no spaces) */
    double error;         /* relative, against the study's reference (0 for the reference) */
    double wall_time_s;   /* elements: statics + modes (median); dynamic: integration */
    double build_time_s;  /* elements: statics part; reduced: its own set-up (basis); full: 0 */
    int reference;        /* the study's reference row */
    int chosen;           /* the cheapest non-reference row with error <= tolerance */
    /* the parts of the error (NaN when they do not apply) */
    double err_frequency; /* elements: worst over the selected modes; dynamic: vertical fundamental */
    double err_amplitude; /* dynamic: vertical peak-to-peak at the study's probe */
    double err_sag, err_tension; /* elements */
    double string_error;  /* elements, level span with gravity: first out-of-plane frequency
                           * against n/(2L) sqrt(H/m) (n = 1); NaN otherwise */
    double frequency_hz;  /* elements: first selected mode; dynamic: vertical fundamental */
    double amplitude_m;   /* dynamic: vertical peak-to-peak at the study's probe */
    char failed[256];     /* why the setting failed (error = +inf), or "" */
} gal_acc_row;

typedef struct gal_acc_summary {
    int ran;
    int reference;        /* row index of the reference, -1 if none */
    int chosen;           /* row index of the chosen setting, -1 if none meets the tolerance */
    double steady_from_s; /* dynamic studies: start of the steady window (the reference's), s */
    double probe;         /* dynamic studies: where the rows are measured, the probe of the reference's
                           * largest vertical peak-to-peak (gal_compare_reference), fraction of the span */
    double output_interval_s; /* dynamic studies: trace sampling, s */
    char buys[512];       /* a sentence saying what the chosen setting buys */
    char note[512];       /* what went wrong on the way (a requested reference that failed), or "" */
} gal_acc_summary;

/* ---- the front study ---- */

/* The measures every configuration is scored on (as `gallop compare` takes them: each family at the
 * probe where the reference moves most (front.probe), over the reference's steady window;
 * amplitudes are RMS values (smooth in the discretization, and the statistic of a turbulent run);
 * in turbulent wind every measure is averaged over the seeds). */
typedef enum {
    GAL_ACC_M_FREQUENCY,  /* Hz: fundamental frequency of the larger translation (vertical or horizontal) */
    GAL_ACC_M_VERTICAL,   /* m: vertical amplitude, RMS about the mean over the window */
    GAL_ACC_M_HORIZONTAL, /* m: horizontal amplitude (RMS) */
    GAL_ACC_M_TWIST,      /* deg: twist amplitude (RMS) */
    GAL_ACC_M_TENSION,    /* N: largest support tension over the steady window */
    GAL_ACC_M_STEADY,     /* s: time to steady galloping (no order: compared directly) */
    GAL_ACC_NMEAS
} gal_acc_measure;

extern const char *const gal_acc_measure_names[GAL_ACC_NMEAS];

/* One configuration: what a run chooses. */
typedef struct gal_acc_config {
    int reduced;          /* 0: full model; 1: the recomputed reduced model */
    int elements;         /* model.elements */
    int modes[3];         /* reduced: modes vertical, horizontal, torsional */
    double time_step;     /* s (divides the study's output interval) */
    int effect_off;       /* a gal_effect switched off, or -1 */
    double newton_tol;    /* simulation.newton_tolerance; 0: the scene's */
} gal_acc_config;

typedef struct gal_acc_point {
    gal_acc_config c;
    char label[96];       /* e.g. "full N=80 h=0.0125", "reduced 3/2/1 N=80 h=0.0125", "full -aero_lift" */
    char group[24];       /* what it varies: reference, model, elements, time_step, newton_tolerance,
                           * modes, effect, combined */
    double value[GAL_ACC_NMEAS]; /* the measures (NaN: not measured) */
    double err[GAL_ACC_NMEAS];   /* relative error against the reference (NaN: not scored) */
    double spread[GAL_ACC_NMEAS];/* over the seeds: the standard error of the mean, relative (NaN: one seed) */
    double error;         /* the worst scored measure (+inf when the run failed) */
    double wall_time_s;   /* set-up (model, statics, modes) + integration, all seeds */
    long newton_iterations; /* the integrator's, all seeds */
    int on_front;         /* 1: no other point is both cheaper and at least as accurate */
    int predicted;        /* combined point chosen from a prediction (additive errors) */
    double predicted_error, predicted_time_s;
    char failed[256];
} gal_acc_point;

typedef struct gal_acc_front {
    int n, cap;
    gal_acc_point *pt;
    /* the reference: full model refined (elements x2, step /2) until every scored measure's
     * estimated error is below a tenth of the tolerance, Richardson-extrapolated where the order
     * is known */
    int levels;                           /* refinements run (finest level = levels - 1) */
    int ref_elements[8];
    double ref_time_step[8];              /* s */
    double ref_level_value[8][GAL_ACC_NMEAS];
    double ref_level_wall_s[8];
    double ref_value[GAL_ACC_NMEAS];      /* the reference values the errors are taken against */
    double ref_error[GAL_ACC_NMEAS];      /* their estimated relative error: the finest level's
                                           * Richardson estimate, and in turbulent wind at least
                                           * its standard error over the seeds */
    double ref_disc_error[GAL_ACC_NMEAS]; /* its discretization part alone (what the refinement
                                           * stops on): Richardson's with the observed order where
                                           * it is known (1 <= p <= 3), else the last change */
    double ref_change[GAL_ACC_NMEAS];     /* relative change over the last refinement */
    double ref_spread[GAL_ACC_NMEAS];     /* the finest level's standard error over the seeds */
    double order[GAL_ACC_NMEAS];          /* observed order of the refinement (NaN: fewer than 3
                                           * levels, or changes that do not shrink) */
    int scored[GAL_ACC_NMEAS];            /* 1: the measure is scored (finite, above its floor) */
    int converged;                        /* every scored ref_disc_error below tolerance / 10 */
    char ref_note[256];
    int nseeds;
    double output_interval_s, steady_from_s, base_time_step_s;
    double probe[3];                      /* where the vertical, horizontal and twist measures are taken
                                           * (gal_compare_reference of the first reference run) */
    double base_newton_tol;               /* the scene's simulation.newton_tolerance */
    int base_elements;
    /* --tolerance: the cheapest point within it, checked by a second run */
    int chosen;                           /* index, -1 none */
    gal_acc_point check;                  /* the check run of the chosen configuration */
    int checked;
    char effects[2048];                   /* the effects that may be switched off, and why not others */
    char note[512];                       /* turbulent wind, budget exhausted... */
} gal_acc_front;

typedef struct gal_acc_result {
    int n, cap;
    gal_acc_row *row;
    gal_acc_summary study[GAL_ACC_NSTUDY];
    double tolerance;
    double string_hz;     /* first out-of-plane string frequency, Hz (NaN if no cable theory) */
    double wall_time_s;   /* the whole sweep */
    gal_acc_front front;  /* the front study */
} gal_acc_result;

void gal_accuracy_default_opts(gal_acc_opts *o);

/* Run the studies of `o` on copies of `sc`; rows in `r` (free with gal_accuracy_clear, also after
 * a failure). GAL_EINPUT on bad options; GAL_EFAIL when a reference fails (with the reason).
 * A non-reference setting that fails is kept as a row with error = +inf (never chosen). */
int gal_accuracy_run(const gal_scene *sc, const gal_acc_opts *o, gal_acc_result *r);
void gal_accuracy_clear(gal_acc_result *r);

#ifdef __cplusplus
}
#endif

#endif
