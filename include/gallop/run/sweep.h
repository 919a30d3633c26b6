/* sweep.h: a sweep of a scene over a grid of scene keys (issue 18; `gallop sweep`): the grid and
 * its cases (sweep_grid.c), one case run as `gallop simulate` runs it, with the coupled onset of
 * `gallop stability` where the scene has an aero table (sweep_case.c). The records of finished
 * cases, their fingerprints and sweep.csv are output/sweepreport.h's.
 *
 * The grid: axes `section.key=LIST` (LIST `v1,v2,...` or `start:stop:step`), their product the
 * grid points, axis 0 varying fastest. Without continuation each point is one case and one unit of
 * work. With continuation a unit is a chain: the points of axis 0 at one point of the other axes,
 * run in order up (v1 .. vn) and then down (v(n-1) .. v1), each case starting from the final state
 * of the case before it, so that the hysteresis of galloping (onset on the way up, extinction on
 * the way down) shows. Rows of sweep.csv: unit by unit, each unit's cases in order. */
#ifndef GALLOP_SWEEP_H
#define GALLOP_SWEEP_H

#include <stdint.h>

#include "gallop/run/integrator.h"
#include "gallop/scene/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GAL_SWEEP_MAX_AXES 8
#define GAL_SWEEP_MAX_VALUES 10000     /* values of one axis */
#define GAL_SWEEP_MAX_CASES 1000000L   /* cases of a sweep */
#define GAL_SWEEP_KEY_MAX 96           /* "section.key" */
#define GAL_SWEEP_VALUE_MAX 64         /* one value's text */
#define GAL_SWEEP_MAX_SUB 8            /* sub-conductors of an explicit bundle (bundle.h's GAL_BUNDLE_MAX) */

typedef struct gal_sweep_axis {
    char key[GAL_SWEEP_KEY_MAX];       /* section.key as given (the column name) */
    int n;                             /* values */
    char (*value)[GAL_SWEEP_VALUE_MAX];/* n: the text given to the scene reader */
    double *num;                       /* n: its number, NaN when it is not one (a name) */
} gal_sweep_axis;

typedef enum { GAL_SWEEP_NONE, GAL_SWEEP_UP, GAL_SWEEP_DOWN } gal_sweep_branch;
extern const char *const gal_sweep_branch_names[3]; /* "", "up", "down" */

typedef struct gal_sweep_grid {
    int naxes;
    gal_sweep_axis axis[GAL_SWEEP_MAX_AXES];
    int continuation;                  /* 1: chains along axis 0, up then down */
    long npoints;                      /* product of the axes' n */
    long nunits;                       /* chains (continuation) or cases */
    long unit_cases;                   /* cases per unit: 2 n0 - 1 (continuation) or 1 */
    long ncases;                       /* rows: nunits * unit_cases */
} gal_sweep_grid;

/* One case: its row, its grid point and the value index on each axis, its branch. */
typedef struct gal_sweep_case {
    long row, point, unit;
    int pos;                           /* position in its unit: 0 .. unit_cases - 1 */
    int idx[GAL_SWEEP_MAX_AXES];
    gal_sweep_branch branch;
} gal_sweep_case;

/* Parse "section.key=LIST" into a (its arrays allocated: gal_sweep_grid_clear frees them).
 * GAL_EINPUT with a message naming the option and the allowed forms when the text is bad (the key
 * and the values themselves are the scene reader's to check: gal_sweep_grid_check). */
int gal_sweep_axis_parse(gal_sweep_axis *a, const char *spec);
/* The grid of the axes parsed in g->axis[0 .. naxes-1]: the counts; GAL_EINPUT when a key is given
 * twice or the grid has more than GAL_SWEEP_MAX_CASES cases. */
int gal_sweep_grid_init(gal_sweep_grid *g, int continuation);
void gal_sweep_grid_clear(gal_sweep_grid *g);
/* Case pos of unit u. */
void gal_sweep_case_of(const gal_sweep_grid *g, long unit, int pos, gal_sweep_case *c);
/* The overrides of a case after the user's: sets[0 .. nuser-1] = user[...], then "key=value" per
 * axis written into buf (GAL_SWEEP_MAX_AXES x (KEY_MAX + VALUE_MAX) chars). Returns the count. */
int gal_sweep_case_sets(const gal_sweep_grid *g, const gal_sweep_case *c, const char *const *user, int nuser,
                        char (*buf)[GAL_SWEEP_KEY_MAX + GAL_SWEEP_VALUE_MAX], const char **sets);
/* Every value of every axis through the scene reader, before anything is computed: GAL_EINPUT
 * with "--vary KEY=VALUE: " and the reader's message (file, key, allowed range) for the first bad
 * one. scene_path and the user's overrides as for gal_scene_load. */
int gal_sweep_grid_check(const gal_sweep_grid *g, const char *scene_path, const char *const *user, int nuser);

/* ---- one case (sweep_case.c) ---- */

typedef struct gal_sweep_result {
    int status;                        /* GAL_OK, or the status of the failure */
    char message[512];                 /* why it failed */
    double vertical_pp_m, horizontal_pp_m, twist_pp_deg; /* first probe, steady window */
    double frequency_hz;               /* first probe, vertical */
    double tension_max_n;              /* largest support tension over the steady window */
    double onset_speed_m_s;            /* coupled onset (analysis/onset.h); NaN: stable over the
                                        * [stability] range or no aero table */
    int has_onset;                     /* the scene has an aero table (onset computed) */
    int valid;                         /* the reduced model's self-check: 1, 0; -1 not checked */
    double residual_max;
    double wall_time_s;                /* the whole case: set-up, run, onset */
    /* this process only (not in the case's record): */
    int setup_reused;                  /* 1: the equilibrium, modes and damping were another
                                        * case's (gal_sweep_setup_cache); 2: the equilibrium and
                                        * modes, the damping built anew (another ratio); 0: none */
    int rom_setup;                     /* the reduced model's own wind-independent set-up
                                        * (gal_data.rom_setup): 1 computed by this case, 2 an
                                        * earlier case's of the span; 0: none (full model) */
    double setup_time_s;               /* the pipeline's stages to the start and the reduced
                                        * model's own set-up (s) */
    /* an explicit bundle ([bundle] model = explicit): the figures above are its centroid's (twist:
     * the bundle's rotation; tension: summed over the sub-conductors), and per sub-conductor k at
     * the first probe over the centroid's steady window: */
    int nsub;                          /* sub-conductors (0: a single rod or an equivalent bundle) */
    double sub_vertical_pp_m[GAL_SWEEP_MAX_SUB], sub_horizontal_pp_m[GAL_SWEEP_MAX_SUB];
    double sub_twist_pp_deg[GAL_SWEEP_MAX_SUB], sub_tension_max_n[GAL_SWEEP_MAX_SUB];
} gal_sweep_result;

/* The onsets already computed by this process, keyed by the scene less what the onset ignores
 * (wind speed, [simulation]): a sweep over the wind speed analyses its span once. */
#define GAL_SWEEP_ONSET_CACHE 32
typedef struct gal_sweep_onset_cache {
    const char *dir;               /* also kept as DIR/onset-<key> files (NULL: in memory only), so
                                    * that other processes, and a rerun, find them */
    int n, next;
    uint64_t key[GAL_SWEEP_ONSET_CACHE];
    double speed[GAL_SWEEP_ONSET_CACHE];
} gal_sweep_onset_cache;

/* The set-ups of spans kept by this process between its cases (forward.h, gal_data_share): the
 * equilibrium, modes and structural damping of the last GAL_SWEEP_SETUP_CACHE cases that computed
 * them, taken by a later case whose stage key (gal_stage_key at the modes) is the same: a sweep
 * over the wind, or over any key the equilibrium and the modes do not read, finds them once per
 * span (while no more than GAL_SWEEP_SETUP_CACHE spans alternate). */
#define GAL_SWEEP_SETUP_CACHE 16
struct gal_model;
struct gal_data;
typedef struct gal_sweep_setup_cache {
    int n, next;
    struct gal_model *m[GAL_SWEEP_SETUP_CACHE]; /* owned */
    struct gal_data *d[GAL_SWEEP_SETUP_CACHE];  /* owned: forwarded at least to the modes */
    uint64_t key[GAL_SWEEP_SETUP_CACHE];
} gal_sweep_setup_cache;
void gal_sweep_setup_cache_clear(gal_sweep_setup_cache *c);

/* 1 when sc is an explicit bundle ([bundle] model = explicit, more than one sub-conductor): its
 * cases run the explicit bundle's full model whatever the kind (it has no reduced model in a sweep),
 * start at rest (no continuation) and take its coupled onset (bundle_dyn.h). */
int gal_sweep_explicit_bundle(const gal_scene *sc);

/* Run scene sc with the full model (kind GAL_MODEL_FULL) or the scene's reduced model, from the
 * start state (q0, v0) of nq0 entries each when q0 is given (a continuation), else as `gallop
 * simulate` starts; measures at the first probe; the onset (cache may be NULL); the equilibrium and
 * modes from setup when it holds those of the same key, else computed and kept there (setup may be
 * NULL: computed, not kept); the figures are the same either way, bit for bit. When q_end is
 * given, *q_end and *v_end receive the final state (malloc'ed, *nq entries; NULL on failure).
 * A failed case is a result (status, message), not an error: returns GAL_ENOMEM only when memory
 * ran out, else GAL_OK. */
int gal_sweep_case_run(const gal_scene *sc, gal_model_kind kind, const double *q0, const double *v0, int nq0,
                       gal_sweep_onset_cache *cache, gal_sweep_setup_cache *setup, gal_sweep_result *r,
                       double **q_end, double **v_end, int *nq);

#ifdef __cplusplus
}
#endif

#endif
