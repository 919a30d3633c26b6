/* bundle_rom.h: the reduced model of the explicit bundle (README "Bundles", issue 19): a Galerkin
 * projection of the assembled system of bundle.h / bundle_dyn.h on a basis V = [Phi, Theta] over
 * the system's dofs z: the selected bundle modes Phi and their static modal derivatives
 * theta_ij = -K0^-1 (dK/d eta_j) phi_i (the assembled tangent differentiated by central
 * differences along phi_j, i <= j), and with a wind the static responses to its mean load and to
 * that load's derivatives along each mode (load-dependent Ritz vectors: the sub-conductors' own twist
 * between spacers under their aerodynamic moments, which no low bundle mode carries),
 * then each of those static vectors' inertia K0^-1 M0 u (its next Krylov vector),
 * M0-orthonormalized and deflated (V^T M0 V = I). The state is
 * the equilibrium stepped by z = V x (gal_bundle_step from b->state: rods' dofs added, spacers
 * rotated by exp(z_phi x)); every term is the full model's at that state, projected:
 *   V^T M(s) V x'' + Cr x' + V^T grad U(s) = V^T F(t, s, V x'),   Cr = V^T (alpha M0 + beta K0) V,
 * integrated by generalized-alpha with modified Newton on the reduced tangent V^T K(s) V (dense,
 * r x r, refreshed when a correction shrinks the residual less than 0.3x), and of each o.one_pass
 * steps all but one linearly implicit after a Newton step that converged within two corrections (the
 * forces once, at the predictor; rom.c). V^T M(s) V x = x + V_S^T (M(s) - M0)_SS V_S x over the few
 * dofs S where the mass moves with the state (the spacers'), as V^T M0 V = I. No hyper-reduction:
 * each pass evaluates the whole assembled gradient and loads (the single rod's ECSW samples
 * elements of one gal_rod and does not take the spacer map). The model
 * checks itself as the single rod's (rom.h): the full residual R = M(s) a + C v + grad U - F at the
 * reconstructed state (a: the reduced equations' own acceleration there), du = K0^-1 R split into
 * the bundle's families (gal_bundle_classify: centroid vertical, horizontal, axial, rotation about
 * it, subspan) in the mass norm, each against the family's own displacement V x (at least 2% of the
 * whole). No adaptation: a check past the tolerance marks the run invalid. */
#ifndef GALLOP_BUNDLE_ROM_H
#define GALLOP_BUNDLE_ROM_H

#include "gallop/bundle/bundle_dyn.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct gal_bundle_rom_opts {
    int derivatives;        /* 1: the modal derivatives (default); 0: the modes alone */
    double h;               /* s: time step; default 0.01 */
    double rho_inf;         /* default 1 */
    double alpha, beta;     /* Rayleigh damping of the assembled system (bundle_dyn.h), when damping
                             * is NULL */
    const gal_damping *damping; /* the full model's modal damping over the system's dofs
                             * (gal_bundle_damping_modal), projected: Cr = V^T C V; not owned */
    double newton_tol;      /* relative; default 1e-8 */
    int max_newton;         /* per step; default 20 */
    int max_halvings;       /* default 6 */
    double fd_step_m;       /* the modal derivatives' differences: largest entry of eps phi_j; 1e-3 */
    double deflation_tol;   /* drop a basis vector left with less of its M-norm; default 1e-6 */
    const gal_bundle_loads *mean_loads; /* the loads of the run with the mean wind alone (no
                             * turbulence, no ramp: gal_bundle_rom_mean_loads), or NULL; not kept */
    int load_vectors;       /* with mean_loads, appended after the modal derivatives (each split into
                             * the sub-conductors' own twist and the rest, which no low bundle mode
                             * carries apart): 1 the static response to the mean load K0^-1 F;
                             * 2 (default) also K0^-1 of the load's derivatives along each selected
                             * mode's displacement and velocity; 0 none */
    int inertia_vectors;    /* 1 (default): K0^-1 M0 u appended for every vector u past the modes
                             * (the static vectors' inertia, the next Krylov vector); 0 none */
    int one_pass;           /* of each one_pass steps, all but one linearly implicit (rom.c: the
                             * forces once, at the predictor, one correction by the kept iteration
                             * matrix, the forces carried over it by the kept tangent) after a Newton
                             * step that converged within two corrections; the others Newton's;
                             * default 8, 0 or 1: Newton at every step */
} gal_bundle_rom_opts;

/* The self-check's figures (per gal_family, as gal_rom_check). */
typedef struct gal_bundle_rom_check {
    double rel[GAL_FAMILY_COUNT];
    double max;
} gal_bundle_rom_check;

typedef struct gal_bundle_rom {
    gal_bundle *b;          /* not owned; b->state is the equilibrium */
    gal_bundle_rom_opts o;
    gal_bundle_force force;
    int ndof, r, nmodes;    /* the first nmodes columns of V are the selected modes */
    double *V;              /* ndof x r, column-major */
    double *Cr;             /* r x r */
    double *Kr;             /* r x r: V^T K V at the last fresh tangent (o.one_pass's steps) */
    int nS, *sidx;          /* the dofs where M(s) can differ from M0 (the spacers' and those the
                             * sub-conductors' dofs at the spacers depend on); 0: none known */
    double *VS, *MS;        /* V's rows there (nS x r, row-major), (M0)_SS (nS x nS) */
    double *xs, *ys;        /* ndof (kept zero), ndof of scratch */
    double *Kl, *Cl;        /* r x r: -V^T dF/ds V, -V^T dF/dv V of the mean loads at the equilibrium
                             * (the iteration matrix's share of the loads), or NULL */
    gal_csc *K0, *M0;       /* at the equilibrium */
    void *chol0;            /* K0's factorization (gal_chol) */
    double am, af, beta, gamma;
    double fscale;          /* reduced force scale of the Newton test: g sqrt(total mass) */
    /* state */
    double t;
    double *x, *v, *a, *fi, *fe; /* r */
    double *ap, hprev;      /* the acceleration before the last step, and its size (the predictor's) */
    double *s;              /* nstate: the reconstructed state at x (after gal_bundle_rom_sync) */
    int s_stale, lin_ok;    /* s lags x (a linear step); a linear step may follow */
    /* workspace */
    double *s1, *x1, *v1, *a1, *fi1, *fe1, *res, *dx, *wr, *J, *tmpr; /* nstate, r, 7 r, r x r */
    int *piv, *piv2;        /* J's, tmpr's */
    double hJ, floor0, floor1;
    double *z, *zv, *g, *f, *wrk; /* ndof each (zv after z, f after g), 2 nq */
    /* counters */
    long steps, newton_iterations, tangents, force_evaluations, rejected_steps, linear_steps;
    double build_time_s;
    /* the run's self-check (gal_bundle_rom_selfcheck) */
    int checks, valid;
    double residual_max;
    gal_bundle_rom_check worst;
} gal_bundle_rom;

void gal_bundle_rom_default_opts(gal_bundle_rom_opts *o);
/* The basis about b->state from the selected modes of md (shapes over the system's dofs), started
 * at rest there. NULL with a message on failure. */
gal_bundle_rom *gal_bundle_rom_alloc(gal_bundle *b, const gal_modes *md, const gal_bundle_rom_opts *o,
                                     const gal_bundle_force *force);
gal_bundle_rom *gal_bundle_rom_free(gal_bundle_rom *m);
/* out: a copy of bl with the mean wind alone (after the ramp, no turbulence, no reversal). */
void gal_bundle_rom_mean_loads(const gal_bundle_loads *bl, gal_bundle_loads *out);
/* One step of o.h (halved on Newton failure, o.max_halvings deep). */
int gal_bundle_rom_step(gal_bundle_rom *m);
/* m->s rebuilt at x when a linear step left it behind. */
void gal_bundle_rom_sync(gal_bundle_rom *m);
/* The full residual at the state (see above). */
int gal_bundle_rom_residual(gal_bundle_rom *m, gal_bundle_rom_check *chk);
/* The run's check at the state reached: the residual, residual_max and valid kept; past tol a
 * GAL_EFAIL naming the family and the keys unless warn (then the run goes on, valid = 0). path:
 * the scene's, for the message. */
int gal_bundle_rom_selfcheck(gal_bundle_rom *m, double tol, int warn, const char *path);
/* y = V^T x (x: ndof); r entries. */
void gal_bundle_rom_project(const gal_bundle_rom *m, const double *x, double *y);

/* A reduced galloping run of the explicit bundle (`gallop simulate` on [bundle] model = explicit):
 * gal_bundle_simulate's set-up, sampling, damping, loads and outputs, the reduced model above as the
 * integrator, checked every simulated second and at the end against model.residual_tolerance
 * (res->c.checked, residual_max, valid, basis). */
struct gal_model;
struct gal_run_opts;
int gal_bundle_simulate_reduced(const struct gal_model *m, const struct gal_run_opts *o, gal_bundle_sim_result *res);

/* `gallop compare` of the explicit bundle: DIR/compare.csv (time_s, then the centroid's
 * full_/reduced_ vertical, horizontal and twist at the mid probe under the single rod's names,
 * then the same per sub-conductor suffixed _s<k> with its support tensions) and DIR/summary.json
 * (both runs' figures, the centroid's errors and each sub-conductor's), one output set; the figures
 * (the centroid's) in *out (may be NULL). */
struct gal_compare_figures;
int gal_bundle_write_compare(const char *dir, const gal_scene *sc, const gal_bundle_sim_result *full,
                             const gal_bundle_sim_result *red, struct gal_compare_figures *out);

#ifdef __cplusplus
}
#endif

#endif
