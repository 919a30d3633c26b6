/* forward.h: the pipeline (MuJoCo's mj_forward): the stages of an analysis run in a fixed order on
 * a const model (model/model.h), each writing what it finds into a gal_data, up to the stage a
 * caller asks for:
 *   equilibrium  statics: the sagged equilibrium, the unstretched length it solves for (statics.h)
 *   modes        the modes about it, those the scene selects marked (modes.h), and the structural
 *                damping (model/damping.h: modal over the band, built from the span's own modes up
 *                to GAL_DAMPING_BAND_HZ, independent of the modes selected)
 *   wind         the loads on the equilibrium rod, with the turbulent wind field when there is one
 *   start        the start of a run: the equilibrium, or the equilibrium under the mean wind
 *   reduced      the reduced model's basis modes: the selected ones, none at or near 0 Hz (the
 *                reduced integrator, run/integrator.h, builds its basis on them: reduced/rom.h)
 * Every command calls it: `gallop modes` to the modes, `stability` to the modes, `accuracy` and the
 * runs (`simulate`, `compare`, run/sim.h) as far as their integrator needs. Another model's data of
 * the same span may lend its equilibrium and modes (gal_data_share, forward_share.c: a sweep over
 * the wind sets its span up once). */
#ifndef GALLOP_FORWARD_H
#define GALLOP_FORWARD_H

#include <stdint.h>

#include "gallop/loads/loads.h"
#include "gallop/model/damping.h"
#include "gallop/model/model.h"
#include "gallop/modes/modes.h"
#include "gallop/statics/statics.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    GAL_STAGE_NONE = 0,
    GAL_STAGE_EQUILIBRIUM,
    GAL_STAGE_MODES,
    GAL_STAGE_WIND,
    GAL_STAGE_START,
    GAL_STAGE_REDUCED,
    GAL_STAGE_COUNT
} gal_stage;

extern const char *const gal_stage_names[GAL_STAGE_COUNT];

#define GAL_BASIS_MAX 64 /* selected modes taken into the reduced basis */
#define GAL_MODE_FLOOR_HZ 0.01 /* Hz: a selected mode below this is a rigid or free-twist motion, refused
                                * by the reduced stage */

/* The holder of a data's reduced set-up (NULL rom: none yet); a pointer in gal_data, so that a
 * run on a const data can fill it. */
typedef struct gal_rom_setup_slot {
    struct gal_rom *rom;
    double time_s;           /* s: its wall time */
} gal_rom_setup_slot;

/* Everything the stages find or change (the model holds what they read). */
typedef struct gal_data {
    const gal_model *model;  /* the model the data were made for */
    gal_stage stage;         /* the last stage done */
    /* equilibrium: the working rod at the unstretched length found (owned by eq), its
     * configuration, the Newton and load-stepping (bending stiffness continuation) counts */
    gal_equilibrium eq;
    /* modes */
    gal_modes md;
    gal_damping *damping;    /* owned: the structural damping both integrators and the stability
                              * analysis apply */
    /* wind: the model's loads on eq.rod, with the turbulent field (owned, nt x nx) or none */
    gal_loads loads;
    double *wind_u;
    /* start */
    double *q_start;         /* nq */
    double *v_start;         /* nq: the start velocity (gal_data_start_from), or NULL: at rest */
    int mean_wind_iterations;/* Newton iterations of the equilibrium under the mean wind */
    /* reduced */
    int basis;               /* modes in the basis */
    int sel[GAL_BASIS_MAX];  /* their indices in md */
    double stage_time_s[GAL_STAGE_COUNT]; /* wall time of each stage */
    /* the stages up to this one are another data's (gal_data_share): read, never freed, here;
     * GAL_STAGE_NONE: all its own */
    gal_stage borrowed;
    int damping_borrowed;    /* 1: damping is the other data's too */
    /* the reduced model's own wind-independent set-up (reduced/rom.h gal_rom_setup_alloc), made
     * by the first reduced run on these modes and copied by the later ones, the data's and those
     * of the data that borrow its modes (a sweep over the wind: once per span); owned by the data
     * that made its modes */
    gal_rom_setup_slot *rom_setup;
} gal_data;

gal_data *gal_data_alloc(const gal_model *m);
gal_data *gal_data_free(gal_data *d);

/* Run the stages after d->stage up to `upto` (stages already done in d are not repeated: the model
 * does not change, so neither would they). The status of the first stage that fails, its message
 * naming the scene; d then holds the stages before it. */
int gal_forward(const gal_model *m, gal_data *d, gal_stage upto);

/* Start the runs of d from a given state (a sweep's continuation: the previous case's final state):
 * d forwarded to the start stage, then q_start = q and v_start = v (nq entries each; v NULL: at
 * rest), and the wind blows at full speed from t = 0 (no ramp: the span is already in it). */
int gal_data_start_from(const gal_model *m, gal_data *d, const double *q, const double *v);

/* ---- reuse of the set-up between models (a sweep over the wind: issue 13) ---- */

/* A fingerprint of what the stages up to s read from m (s: GAL_STAGE_EQUILIBRIUM, the rod's
 * parameters, its equilibrium specification and the statics options; GAL_STAGE_MODES, those and
 * the modes wanted; the damping ratio is not in it: gal_data_share builds the damping anew when it
 * differs). Two models of one key find the same equilibrium and modes, bit for bit. GAL_EINPUT
 * for another stage. */
int gal_stage_key(const gal_model *m, gal_stage s, uint64_t *key);

/* Take the stages up to `upto` (GAL_STAGE_EQUILIBRIUM or GAL_STAGE_MODES) of `from` into d: d of
 * another model m whose gal_stage_key at `upto` is from's (GAL_EINPUT otherwise), not forwarded
 * yet; `from` forwarded at least to GAL_STAGE_MODES. The equilibrium (its rod) and the modes are
 * borrowed, not copied: `from` must outlive d and is not changed by d's later stages; the
 * structural damping too when m's damping ratio is from's, else it is built for d (as the modes
 * stage builds it). d->stage_time_s of the stages taken: 0. */
int gal_data_share(const gal_model *m, gal_data *d, const gal_data *from, gal_stage upto);

#ifdef __cplusplus
}
#endif

#endif
