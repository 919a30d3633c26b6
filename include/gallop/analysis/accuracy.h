/* accuracy.h: what accuracy costs in time (issue 7, DESIGN.md "Command line": gallop accuracy).
 * For one scene, each study sweeps one choice (mesh, reduced basis, time step, reduced tolerance,
 * physical effects), measures the error of every setting against a reference setting of the same
 * study and the wall time it took, and names the cheapest setting whose error is within the
 * tolerance. The scene itself is never changed: every setting runs on a copy. */
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
    GAL_ACC_TOLERANCE, /* reduced model: simulation.tolerance 1e-4 .. 1e-9 against 1e-11 */
    GAL_ACC_EFFECTS,   /* reduced model with one effect off at a time against all on */
    GAL_ACC_NSTUDY
} gal_acc_study;

extern const char *const gal_acc_study_names[GAL_ACC_NSTUDY];

typedef struct gal_acc_opts {
    double tolerance;   /* relative error a setting must meet; default 0.01 */
    unsigned studies;   /* bit (1u << study) per study to run; default all */
    int repeats;        /* timing repeats (median) for settings cheaper than 1 s; default 3 */
    int progress;       /* 1: one line per setting on stderr */
} gal_acc_opts;

/* One setting of one study. */
typedef struct gal_acc_row {
    gal_acc_study study;
    char setting[48];     /* key name, e.g. model.elements */
    char value[48];       /* its value as written on the command line (no spaces) */
    double error;         /* relative, against the study's reference (0 for the reference) */
    double wall_time_s;   /* elements: statics + modes (median); dynamic: integration */
    double build_time_s;  /* elements: statics part; reduced: identification; full: 0 */
    int reference;        /* the study's reference row */
    int chosen;           /* the cheapest non-reference row with error <= tolerance */
    /* the parts of the error (NaN when they do not apply) */
    double err_frequency; /* elements: worst over the selected modes; dynamic: dominant vertical */
    double err_amplitude; /* dynamic: mid-span vertical peak-to-peak */
    double err_sag, err_tension; /* elements */
    double string_error;  /* elements, level span with gravity: first out-of-plane frequency
                           * against n/(2L) sqrt(H/m) (n = 1); NaN otherwise */
    double frequency_hz;  /* elements: first selected mode; dynamic: dominant vertical */
    double amplitude_m;   /* dynamic: vertical peak-to-peak at mid-span */
    char failed[256];     /* why the setting failed (error = +inf), or "" */
} gal_acc_row;

typedef struct gal_acc_summary {
    int ran;
    int reference;        /* row index of the reference, -1 if none */
    int chosen;           /* row index of the chosen setting, -1 if none meets the tolerance */
    double steady_from_s; /* dynamic studies: start of the steady window (the reference's), s */
    double output_interval_s; /* dynamic studies: trace sampling, s */
    char buys[512];       /* a sentence saying what the chosen setting buys */
    char note[512];       /* what went wrong on the way (a requested reference that failed), or "" */
} gal_acc_summary;

typedef struct gal_acc_result {
    int n, cap;
    gal_acc_row *row;
    gal_acc_summary study[GAL_ACC_NSTUDY];
    double tolerance;
    double string_hz;     /* first out-of-plane string frequency, Hz (NaN if no cable theory) */
    double wall_time_s;   /* the whole sweep */
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
