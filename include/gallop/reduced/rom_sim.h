/* rom_sim.h: a galloping run of a scene by the recomputed reduced model (rom.h) on the set-up the
 * full model uses (gal_sim_setup: the same equilibrium, modes, loads and wind), written into a
 * gal_sim_result like gal_sim_run's, with the self-check at regular times. The bridge until
 * `gallop simulate` takes the model (issue 13). */
#ifndef GALLOP_ROM_SIM_H
#define GALLOP_ROM_SIM_H

#include "gallop/reduced/rom_adapt.h"
#include "gallop/run/sim.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct gal_rom_sim_opts {
    int derivatives;          /* basis with the modal derivatives (1, default) or modes only (0) */
    int manifold;             /* gal_rom_opts.manifold (-1, default: gal_rom_default_opts') */
    double h;                 /* s: time step; <= 0: the full model's */
    double check_interval;    /* s: residual check every so often (default 1) */
    double check_from;        /* s: checks start then (default 0) */
    double tolerance;         /* a check past it grows the basis (rom_adapt.h); <= 0: never (default:
                               * the scene's model.residual_tolerance) */
    int policy;               /* GAL_ROM_ADD_* bits (default both) */
    int relax;                /* the new stiff directions start quasi-static (1, default) */
    int replay;               /* a growth runs the grown model again from the start (1, default;
                               * rom_adapt.h), and the record before it is rewritten with the grown
                               * model's samples (and taut share); 0: restarted in place */
    const double *extra;      /* ndof x nextra: vectors added to the initial basis (gal_rom_opts) */
    int nextra;
} gal_rom_sim_opts;

typedef struct gal_rom_sim_info {
    int basis;                /* basis size */
    double residual_max;      /* the largest residual of the checks that did not grow the basis */
    int valid;                /* residual_max within the tolerance, and the conductor never slack */
    double taut_share;        /* the least gal_rom_taut_share over the samples (rom.h) */
    int basis_start;          /* the initial basis size */
    int nevents;              /* growths of the basis */
    gal_rom_event ev[GAL_ROM_EVENTS_MAX];
    double residual_family[GAL_FAMILY_COUNT]; /* the largest per family */
    double cubic_family[GAL_FAMILY_COUNT]; /* the largest cubic indicator per family (gal_rom_check.cubic) */
    int checks;
    double build_time_s;      /* the model's own set-up (after statics and modes) */
} gal_rom_sim_info;

void gal_rom_sim_default_opts(gal_rom_sim_opts *o);
int gal_rom_sim_run(gal_sim_setup *s, const gal_rom_sim_opts *o, gal_sim_result *res, gal_rom_sim_info *info);

#ifdef __cplusplus
}
#endif

#endif
