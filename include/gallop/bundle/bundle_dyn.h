/* bundle_dyn.h: the explicit bundle's nonlinear dynamics (README "Bundles", issue 19): the
 * assembled system of bundle.h (the sub-conductors' rods joined by rigid spacers, eliminated
 * exactly) integrated by the same generalized-alpha scheme with modified Newton as the single rod's
 * full model (full/dynamics.h), in the system's dofs z:
 *   M(s) a + C v + T^T grad U(s) = T^T F(t, s, v),
 * M(s) = T^T M_r T plus the spacers' mass and inertia (at the current spacer rotations), C the
 * structural damping (modal, gal_bundle_damping_modal, as the single rod's; or Rayleigh alpha M0 +
 * beta K0 of the assembled system at its equilibrium), F the loads on every rod.
 * A step's increment dz is applied from the step's start (gal_bundle_step: rods' dofs added, the
 * spacers rotated by exp(dz_phi x)); the rotation dofs' velocities are angular velocities. The
 * gyroscopic terms of the spacers and the centripetal term d(T)/dt v of the spacer nodes are left
 * out of the inertia: both are of order (omega r)^2 with r the bundle radius (0.2 m) and a bundle
 * rotating at a few rad/s, and the energy test (tests/test_bundle_dyn.c) bounds what they cost.
 *
 * The loads (gal_bundle_loads): the quasi-steady table of the scene on every sub-conductor at its
 * own relative wind and twist (gal_loads_full on its rod), with bundle.wake_factor multiplying the
 * dynamic pressure of the leeward sub-conductors: those in the wake of another (downwind of it and
 * within one diameter of its line along the wind, at rest). */
#ifndef GALLOP_BUNDLE_DYN_H
#define GALLOP_BUNDLE_DYN_H

#include "gallop/analysis/onset.h"
#include "gallop/bundle/bundle.h"
#include "gallop/loads/loads.h"
#include "gallop/model/damping.h"
#include "gallop/run/sim.h"

#ifdef __cplusplus
extern "C" {
#endif

/* External generalized forces on the system: add T^T F(t, s, v) to f (ndof), with the map's values
 * at s (gal_bundle_eval at s was the last evaluation). */
typedef struct gal_bundle_force {
    int (*eval)(void *ctx, gal_bundle *b, double t, const double *s, const double *v, double *f);
    void *ctx;
} gal_bundle_force;

typedef struct gal_bundle_dyn_opts {
    double h;            /* s, time step */
    double rho_inf;      /* [0, 1]; 1: no numerical dissipation */
    double alpha, beta;  /* Rayleigh damping C = alpha M0 + beta K0 (1/s, s); 0, 0: none */
    const gal_damping *damping; /* modal damping over the system's dofs (gal_bundle_damping_modal), in
                          * place of alpha, beta when given (not owned); left out of the iteration
                          * matrix as the single rod's modal damping */
    double newton_tol;   /* relative residual; default 1e-8 (simulation.newton_tolerance; above
                          * GAL_NEWTON_TOL_STRICT accepted only after a correction that reduced it) */
    int max_newton;      /* per step; default 20 */
    int max_halvings;    /* default 6 */
} gal_bundle_dyn_opts;

typedef struct gal_bundle_dyn {
    gal_bundle *b;               /* not owned; its state is the equilibrium, its scratch is used */
    gal_bundle_dyn_opts o;
    double am, af, beta, gamma;
    double t;
    double *s, *s1;              /* nstate: the state, the iterate */
    double *v, *a, *v1, *a1, *dz; /* ndof: velocity, acceleration, the step's increment */
    gal_csc *S, *K0, *M0;        /* iteration matrix; the tangent and mass at the start (damping) */
    void *chol;
    double factor_h;
    gal_bundle_force force;
    double *g0, *g1, *f0, *f1, *r, *dx, *tmp, *Cv, *wrk;
    long steps, newton_iterations, factorizations, force_evaluations, rejected_steps;
    double energy0;
} gal_bundle_dyn;

void gal_bundle_dyn_default_opts(gal_bundle_dyn_opts *o);
/* The single rod's modal damping (model/damping.h) for the assembled bundle b about its equilibrium
 * (b->state): zeta on every bundle mode up to band_hz (<= 0: GAL_DAMPING_BAND_HZ), at most
 * GAL_DAMPING_MAX_MODES, none above; c->mphi holds M0 phi_k over the system's dofs. zeta = 0: the
 * NONE kind. NULL with a message on failure. Free with gal_damping_free. */
gal_damping *gal_bundle_damping_modal(gal_bundle *b, double zeta, double band_hz);
/* Start at the state s0 (nstate; b->state when NULL) with velocity v0 (ndof, NULL: at rest); the
 * damping's K0 and M0 are taken at b->state. NULL with a message on failure. */
gal_bundle_dyn *gal_bundle_dyn_alloc(gal_bundle *b, const double *s0, const double *v0,
                                     const gal_bundle_dyn_opts *o, const gal_bundle_force *force);
gal_bundle_dyn *gal_bundle_dyn_free(gal_bundle_dyn *d);
/* One step of o.h (halved internally when Newton fails). */
int gal_bundle_dyn_step(gal_bundle_dyn *d);
/* Kinetic + elastic + gravity energy (J) at the current state. */
double gal_bundle_dyn_energy(gal_bundle_dyn *d);
/* y = M(s) x over the system's dofs, with the map's values at s already set (gal_bundle_eval);
 * wrk: 2 nq doubles of scratch. */
void gal_bundle_mass_mult(const gal_bundle *b, const double *s, const double *x, double *y, double *wrk);

/* The loads on every sub-conductor. */
typedef struct gal_bundle_loads {
    gal_loads L[GAL_BUNDLE_MAX]; /* per sub-conductor: the scene's, on its rod, its air density */
    int leeward[GAL_BUNDLE_MAX]; /* 1: in another's wake (its density times the wake factor) */
    double *vq, *fq;             /* scratch, nq each */
} gal_bundle_loads;

/* Per sub-conductor copies of base (rho: one sub-conductor's air density) with the wake factor on
 * the leeward ones. GAL_ENOMEM or GAL_OK; gal_bundle_loads_clear frees. */
int gal_bundle_loads_init(gal_bundle_loads *bl, const gal_bundle *b, const gal_loads *base, double rho,
                          double wake_factor);
void gal_bundle_loads_clear(gal_bundle_loads *bl);
/* gal_bundle_force.eval of the loads (ctx: a gal_bundle_loads). */
int gal_bundle_loads_eval(void *ctx, gal_bundle *b, double t, const double *s, const double *v, double *f);

/* A galloping run of the explicit bundle (`gallop simulate --model full` on [bundle] model =
 * explicit): the bundle's statics and modes (gal_bundle_solve_model), modal damping at the scene's
 * ratio on every bundle mode in the band (gal_bundle_damping_modal), the loads above, the same output
 * interval and time step rules as the single rod's full model (run/sim.h). res->c holds the
 * bundle's centroid: per probe its horizontal, vertical and along displacement (the mean of the
 * sub-conductors') and the bundle's rotation about it (deg, in the twist column), the support
 * tensions summed over the sub-conductors; sub holds each sub-conductor's probes (4 per probe as a
 * single rod's) and tension the left and right support tension of each. */
typedef struct gal_bundle_sim_result {
    gal_sim_result c;
    int n;                       /* sub-conductors */
    int leeward[GAL_BUNDLE_MAX];
    double wake_factor;
    double alpha, beta;          /* Rayleigh damping applied (0, 0: the modal damping below) */
    int damping_modes;           /* modes the modal damping holds */
    double damping_band_hz;      /* Hz, its band limit */
    double setup_time_s;         /* statics and modes */
    int ndof;
    double *sub;                 /* nsamples x n x 4 nprobe */
    double *tension;             /* nsamples x n x 2 */
} gal_bundle_sim_result;

struct gal_model;
struct gal_run_opts;
int gal_bundle_simulate(const struct gal_model *m, const struct gal_run_opts *o, gal_bundle_sim_result *res);
void gal_bundle_sim_result_clear(gal_bundle_sim_result *res);
/* Sub-conductor r's run as a single rod's result (its probes and support tensions; the time and
 * counters shared with res->c), for analysis/measure.h. Its trace and tension are malloc'ed: free
 * them (not gal_sim_result_clear, which would free the shared time). */
int gal_bundle_sim_sub(const gal_bundle_sim_result *res, int r, gal_sim_result *out);
/* DIR/trace.csv and DIR/summary.json of the run, one output set (README "Bundles"). */
int gal_bundle_sim_write(const char *dir, const gal_scene *sc, const gal_bundle_sim_result *res);

/* The coupled galloping onset of the explicit bundle (`gallop stability` on [bundle] model =
 * explicit; README "Bundles"): at each speed of o's range the mean-wind equilibrium of the assembled
 * system (Newton with its structural tangent, from the previous speed's), its lowest o->basis
 * natural modes there, the loads of gal_bundle_loads_eval (every sub-conductor at its own relative
 * wind, the wake factor) linearized about it by central differences along each mode (stiffness:
 * the state stepped by gal_bundle_step, the map T re-evaluated; damping: the system's velocity),
 * the modal damping of gal_bundle_simulate projected, and analysis/onset.h's eigen-sweep
 * (gal_onset_track). The speed's columns are sub-conductor 1's at mid-span (swing, twist, angle of
 * attack); Den Hartog's column with one sub-conductor's mass and the lowest vertical bundle mode;
 * Nigol's is NaN (a bundle's torsion is not a single section's). No continuation through folds:
 * the speeds above one without an equilibrium have ok = 0. */
int gal_bundle_onset(const struct gal_model *m, const gal_onset_opts *o, gal_onset *out);
/* The same for a scene ([stability] speed_min, speed_max, speed_step; the default basis). */
int gal_bundle_scene_onset(const gal_scene *sc, gal_onset *O);

#ifdef __cplusplus
}
#endif

#endif
