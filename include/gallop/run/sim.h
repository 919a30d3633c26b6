/* sim.h: a galloping run of a scene (issues 5 and 6): the full model (generalized-alpha on the
 * whole rod) or the reduced model (the modes with the condensed restoring force), the same
 * equilibrium, the same loads and the same wind, traces at the probes. */
#ifndef GALLOP_SIM_H
#define GALLOP_SIM_H

#include "gallop/loads/loads.h"
#include "gallop/modes/modes.h"
#include "gallop/reduced/reduced.h"
#include "gallop/scene/scene.h"
#include "gallop/statics/statics.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum { GAL_MODEL_FULL, GAL_MODEL_REDUCED } gal_model_kind;

/* What the two models share: equilibrium, modes, loads and wind (built once per scene). */
typedef struct gal_sim_setup {
    const gal_scene *sc;
    gal_equilibrium eq;
    gal_modes md;          /* found when the reduced model is asked for */
    int have_modes;
    gal_aero_table *table; /* owned */
    gal_loads loads;
    double *wind_u;        /* owned turbulence field, or NULL */
    double *q_start;       /* owned: the start (the equilibrium, or under the mean wind) */
    double setup_time_s;
    double wind_time_s;
} gal_sim_setup;

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
    double build_time_s;           /* model set-up (reduced: identification) */
    double time_step_s;            /* full: the step; reduced: mean adaptive step */
    long steps, newton_iterations, factorizations, force_evaluations, rejected_steps;
    int basis;                     /* reduced: modes in the basis */
    int load_cases;                /* reduced: identification load cases */
} gal_sim_result;

int gal_sim_setup_init(gal_sim_setup *s, const gal_scene *sc, int need_modes);
void gal_sim_setup_clear(gal_sim_setup *s);
int gal_sim_run(gal_sim_setup *s, gal_model_kind kind, gal_sim_result *res);
void gal_sim_result_clear(gal_sim_result *res);

#ifdef __cplusplus
}
#endif

#endif
