/* sim.h: a galloping run of a model (issues 5 and 6): the pipeline forwarded as far as the
 * integrator needs (run/forward.h), then one loop over the output times whatever the integrator
 * (run/integrator.h): the full model (generalized-alpha on the whole rod) or the reduced model (modes
 * and modal derivatives, the rod's own forces at the reconstructed state, self-checked: a reduced
 * run whose check did not run fails), on the same equilibrium, loads and wind; traces at the
 * probes. */
#ifndef GALLOP_SIM_H
#define GALLOP_SIM_H

#include "gallop/run/integrator.h"
#include "gallop/scene/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct gal_sim_result {
    gal_model_kind kind;
    int nprobe;
    double probe[GAL_MAX_PROBES];  /* fractions of the span */
    long nsamples;
    double dt_out;                 /* s */
    double *time;                  /* nsamples */
    double *trace;                 /* nsamples x 4 nprobe: horizontal, vertical, along (m), twist (deg) */
    double *tension;               /* nsamples x 2: left and right support tensions (N) */
    double wall_time_s;            /* integration */
    double build_time_s;           /* reduced: the model's own set-up (its basis) */
    int setup_reused;              /* reduced: its wind-independent part an earlier run's */
    double time_step_s;            /* s: the step */
    long steps, newton_iterations, factorizations, force_evaluations, rejected_steps;
    int basis;                     /* reduced: basis size (modes and modal derivatives) */
    int checked;                   /* reduced: self-checked (residual_max, valid) */
    double residual_max;
    int valid;
    char invalid_why[256];         /* not valid for another reason than the residual ("" if none) */
    int basis_start, growths;      /* recomputed reduced model: the initial basis, its growths */
    gal_rom_event growth[GAL_ROM_EVENTS_MAX];
} gal_sim_result;

/* The run controls of a scene's [simulation]. */
void gal_run_opts_from_scene(const gal_scene *sc, gal_run_opts *o);

/* Run the model with integrator T: d forwarded to T->needs, samples every output interval from 0
 * to the duration. GAL_EINPUT when the output interval cannot resolve the highest selected mode;
 * the integrator's status when it fails. res is filled (free it with gal_sim_result_clear). */
/* Before a run that will be measured (simulate, compare): the modes forwarded, the output
 * interval chosen, and enough samples for the measures (GAL_SCENE_MIN_SAMPLES), else GAL_EINPUT
 * naming [simulation] duration and the least allowed (issue 14: refused before the run). */
int gal_run_check_measurable(const gal_model *m, gal_data *d, const gal_run_opts *o);
int gal_run(const gal_model *m, gal_data *d, const gal_integrator_type *T, const gal_run_opts *o,
            gal_sim_result *res);
/* The same, and the full state at the end of the run into q_end, v_end (nq entries each, both
 * given): the start of a continued run (gal_data_start_from). GAL_EINPUT when T cannot give it. */
int gal_run_to_state(const gal_model *m, gal_data *d, const gal_integrator_type *T, const gal_run_opts *o,
                     gal_sim_result *res, double *q_end, double *v_end);
void gal_sim_result_clear(gal_sim_result *res);

/* A scene's model and data for runs whose controls are read from the scene at each run (a sweep
 * changes them between runs of one set-up): the data forwarded to the start. */
typedef struct gal_sim_setup {
    const gal_scene *sc;
    gal_model *model;
    gal_data *data;
    double setup_time_s;           /* model and pipeline to the start */
} gal_sim_setup;

/* need_modes is ignored: the modes are always found (the damping is built at the modes stage). */
int gal_sim_setup_init(gal_sim_setup *s, const gal_scene *sc, int need_modes);
void gal_sim_setup_clear(gal_sim_setup *s);
int gal_sim_run(gal_sim_setup *s, gal_model_kind kind, gal_sim_result *res);

#ifdef __cplusplus
}
#endif

#endif
