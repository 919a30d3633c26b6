/* integrator.h: the two integrators of a galloping run behind one interface (GSL's
 * gsl_odeiv2_step_type): a const table of methods that start from the pipeline's data, bring the
 * state to each output time, observe the probes and the support tensions there, and count what
 * they did; run/sim.h drives either with one loop.
 *   gal_integrator_full     generalized-alpha on the whole rod (full/dynamics.h), fixed steps
 *   gal_integrator_reduced  the reduced model (reduced/rom.h; src/run/integrator_rom.c):
 *                           generalized-alpha on modes and modal derivatives, the rod's own forces
 *                           at the reconstructed state, its residual checked every second and at
 *                           the end of the run */
#ifndef GALLOP_INTEGRATOR_H
#define GALLOP_INTEGRATOR_H

#include "gallop/reduced/rom_adapt.h"
#include "gallop/run/forward.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum { GAL_MODEL_FULL, GAL_MODEL_REDUCED } gal_model_kind;

/* The controls of a run (they may change between runs of one model: a sweep of time steps). */
typedef struct gal_run_opts {
    double duration;         /* s */
    double time_step;        /* s, full model; 0: chosen from the highest selected mode */
    double output_interval;  /* s; 0: chosen */
    double rho_inf;          /* -, full model's numerical dissipation (1 = none) */
    double newton_tol;       /* -, both models' Newton tolerance (dynamics.h, rom.h); <= 0: 1e-8 */
    int rom_scheme;          /* the reduced model's step (rom.h GAL_ROM_SCHEME_*; 0 generalized-alpha) */
} gal_run_opts;

/* What an integrator counts. */
typedef struct gal_run_counters {
    double time_step_s;      /* s: the step */
    long steps, newton_iterations, factorizations, force_evaluations, rejected_steps;
    int basis;               /* reduced: basis size (modes and modal derivatives) */
    double build_time_s;     /* reduced: the model's own set-up (basis, after statics and modes) */
    int setup_reused;        /* reduced: its wind-independent set-up was an earlier run's
                              * (gal_data.rom_setup: a sweep over the wind) */
    int checked;             /* reduced: its self-check ran (then the two below) */
    double residual_max;     /* the largest relative residual it found */
    int valid;               /* 1: residual_max within model.residual_tolerance (and the
                              * reduced conductor never slack) */
    char invalid_why[256];   /* not valid for another reason than the residual: which ("" if none) */
    int basis_start, growths;/* recomputed reduced model: its initial basis and how often it grew */
    gal_rom_event growth[GAL_ROM_EVENTS_MAX];
} gal_run_counters;

typedef struct gal_integrator_type {
    const char *name;        /* "full", "reduced" */
    gal_model_kind kind;
    gal_stage needs;         /* the pipeline stage its start reads */
    /* The integrator at the start of a run (d forwarded to `needs`) sampled every dt_out s, fhi the
     * highest selected mode frequency (Hz). A status; *state NULL on failure. */
    int (*alloc)(const gal_model *m, const gal_data *d, const gal_run_opts *o, double dt_out, double fhi,
                 void **state);
    /* The state at t_out (the first call at 0, then increasing; t_end the end of the run). */
    int (*advance)(void *state, double t_out, double t_end);
    /* At the state reached: the probes' displacements from the equilibrium (4 per probe:
     * horizontal, vertical, along in m, twist in deg) and the left and right support tensions (N). */
    void (*observe)(void *state, double *probes, double tension[2]);
    void (*counters)(const void *state, gal_run_counters *c);
    void (*free)(void *state);
    /* The full state reached, configuration and velocity (nq each); NULL: this integrator cannot
     * give it (then no run can continue from it). */
    void (*state)(const void *state, double *q, double *v);
    /* Optional (NULL: never): after the observation of sample i, the samples before it that the
     * integrator computed again since the last call (a reduced model grown and run again from the
     * start, rom_adapt.h) written over trace (4 per probe each) and tension (2 each) from sample 0. */
    void (*rewrite)(void *state, long i, double *trace, double *tension);
} gal_integrator_type;

extern const gal_integrator_type gal_integrator_full;
extern const gal_integrator_type gal_integrator_reduced;

#ifdef __cplusplus
}
#endif

#endif
