/* rom.h: the reduced model whose coupling is recomputed from the rod itself (issue 13; DESIGN.md
 * "Time integration"). Basis V = [Phi, Theta]: the selected linear modes Phi and their static
 * modal derivatives theta_ij = -K0^-1 (dK/d eta_j) phi_i (Idelsohn & Cardona 1985), which carry
 * the stretching that the linear modes miss; V is M-orthonormalized and deflated (V^T M V = I).
 * The equations are the full ones projected on V (Galerkin), with every term evaluated at the
 * reconstructed rod state q = q_eq + V x:
 *   x'' + Cr x' + V^T grad U(q) = V^T F(t, q, V x'),
 *   Cr = V^T (alpha M + beta K0) V   (= alpha I + beta diag(w^2) on the modes: the full damping),
 * so the internal force is conservative by construction (the gradient of U(q(x))) and there is no
 * fitted range. The modal-derivative directions are stiff (axial): integrated implicitly by the
 * generalized-alpha method with Newton on the reduced tangent V^T K(q) V; with rho_inf = 1 the
 * internal force over a step is the discrete gradient (Gonzalez 1996) of U, so that T + U is
 * conserved to Newton's tolerance (undamped, unloaded). The model checks itself:
 * gal_rom_residual rebuilds the full state and evaluates the full equations' residual
 * M a + C v + grad U - F per family in a mass-weighted norm (gal_rom_check).
 * With o.hyper (default) grad U, its tangent and F are evaluated on sampled, weighted elements
 * only (energy-conserving sampling and weighting, ecsw.h): the cost of a step does not grow with
 * the mesh. */
#ifndef GALLOP_ROM_H
#define GALLOP_ROM_H

#include "gallop/full/dynamics.h"
#include "gallop/modes/modes.h"
#include "gallop/rod/rod.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A Newton residual within this relative tolerance (the default of simulation.newton_tolerance)
 * is converged whatever the iteration before it did; above it (a looser newton_tol) only after a
 * correction that reduced the residual. Shared by the full (dynamics.h) and reduced (rom.h) steps. */
#ifndef GAL_NEWTON_TOL_STRICT
#define GAL_NEWTON_TOL_STRICT 1e-8
#endif

/* The reduced model's time integration: generalized-alpha (rom_step.c), or the two-stage
 * Gauss-Legendre method (rom_irk.c: fourth order, A-stable, symplectic; a linear basis only; opt-in:
 * measured no faster at equal error, BENCHMARKS.md, issue 13, helper step10) */
enum { GAL_ROM_SCHEME_GALPHA = 0, GAL_ROM_SCHEME_GAUSS2 = 1 };

typedef struct gal_rom_opts {
    int derivatives;        /* 1: add the static modal derivatives (default); 0: linear modes only */
    int manifold;           /* 1: the modal derivatives as the quadratic term of a manifold
                             * q = q_eq + Phi eta + 1/2 Theta(eta, eta) in the modal coordinates
                             * eta alone (Jain et al. 2017) with its full mass P^T M P, convective
                             * term and damping P^T C P (qm.h); 2: the same with the quadratic
                             * part's inertia dropped (mass Phi^T M Phi = I); 0: a linear basis
                             * V = [Phi, Theta] (the modal derivatives as coordinates) */
    const double *mean_load; /* nq: the mean wind's load at rest at the equilibrium (gal_loads_mean)
                             * or NULL; not owned, not kept past the build (o.wind_vector: it must
                             * outlive an adaptation that rebuilds the model on these options) */
    int weight_vector;      /* 1: on a linear basis, the linear static response to the span's weight
                             * K0^-1 W (conductor and ice, the eccentric ice's moment included)
                             * appended after the modal derivatives; 0: not (default) */
    int wind_vector;        /* 1: on a linear basis with mean_load, its static response K0^-1 F_mean
                             * appended after those (the blown-out direction; wind-dependent: no
                             * shared set-up); 0: not (default). Both off by default, measured
                             * (BENCHMARKS.md, helper weight, session 11): the modes and modal
                             * derivatives already hold K0^-1 W and K0^-1 F_mean to 2e-4 of their
                             * static energy; on the limit-cycle spans at 100/125 elements the
                             * weight's vector moves the largest tension closer or the same (e.g.
                             * +0.84 -> +0.18%) but twist and residual mixed (condor_150 at 100:
                             * twist +5.4 -> +6.1%, residual 0.058 -> 0.093), the wind's mixed
                             * (drake_200 at 125: twist +2.1 -> +9.0%) */
    int static_vectors;     /* on the manifold with mean_load: its static response K0^-1 F_mean less
                             * its modal content as extra linear coordinates (qm.h): 0 none
                             * (default), 1 one vector, 2 the out-of-plane, in-plane and twist
                             * parts' apart */
    double deflation_tol;   /* drop a basis vector whose M-norm falls below this share after
                             * orthogonalization; default 1e-6 */
    double derivative_floor; /* leave out a modal derivative whose M-norm is below this share of
                             * the largest derivative's: at equal modal amplitudes it carries less
                             * of the quadratic motion (rom_basis.c); default 0: keep all */
    double fd_step_m;       /* m: largest translation of the finite-difference steps; default 1e-3 */
    double h;               /* s: time step; default 0.01 */
    double rho_inf;         /* generalized-alpha spectral radius at infinite frequency; default 1 */
    const gal_damping *damping; /* the full model's structural damping C (not owned; NULL: none) */
    double newton_tol;      /* relative; default 1e-8 */
    int max_newton;         /* per step; default 20 */
    int scheme;             /* GAL_ROM_SCHEME_GALPHA (default) or GAL_ROM_SCHEME_GAUSS2 (rom_irk.c) */
    /* hyper-reduction (ecsw.h) */
    int hyper;              /* 1: sampled, weighted elements (default); 0: every element */
    int hyper_loads;        /* 1: the aerodynamic loads on a sample too (default); 0: on every element */
    double hyper_tol;       /* relative residual of the weights' fit; default 1e-2 */
    double hyper_check_tol; /* gal_rom_hyper_check's tolerance before re-sampling; default 2e-2 */
    double hyper_twist;     /* rad: the twist amplitude of the training states; default 1.5 */
    int hyper_snapshots;    /* training states; default 24 */
    int hyper_snapshots_fine; /* > 0: the training states on a mesh of more elements than the
                             * training's candidates (ecsw.h: 128), where each state's targets cost
                             * a whole-mesh evaluation of the rod and the loads; default 0: as
                             * hyper_snapshots (12 makes the set-up at 1000 elements 3.1x its cost
                             * at 100 instead of 4.2x, but moved condor_150_taut_dshape at 400
                             * elements from 0.02% to 3.4% in vertical p-p: BENCHMARKS.md, setup3) */
    double hyper_check_interval; /* s: gal_rom_hyper_check every so often (default 1; 0: never) */
    double newton_contraction; /* a fresh tangent when an iteration gains less than this factor
                             * (default 0.1) */
    int newton_kept_max;    /* ... or a kept one has not converged in this many (default 3) */
    int reuse_tangent;      /* 1: keep the iteration matrix over steps while Newton converges fast
                             * (default); 0: a fresh tangent each step */
    int loads_once;         /* 1: the loads evaluated once a step (default), after Newton's first
                             * correction, and held over the later ones (the first pass takes them
                             * extrapolated from the last two steps); 0: at every Newton pass */
    int one_pass;           /* N > 0 (with loads_once and rho_inf < 1): of each N steps all but one
                             * take one evaluation of the internal force (at the predictor) and
                             * carry it over the corrections with the kept tangent (linearly
                             * implicit), the N-th a full Newton (which refreshes the tangent when
                             * it contracts slowly); 0: Newton every step (default: the linear
                             * steps' force error is measured against the stretching forces, which
                             * swamp the twist's, so nothing bounds them per family; measured on
                             * data/scenes/iced_gallop.ini, 300 s: at 600 elements they missed the
                             * twist 3x, 54.6 deg against the full 18.3, with the self-check
                             * passing, and 800/900 ended exit 1; with Newton every step 80-1000
                             * elements are valid, amplitudes within 0.7%, twist within 23%) */
    int newton_carry;       /* 1: Newton's last correction is taken without the evaluation that
                             * would confirm it, when the kept iteration matrix contracted the
                             * residual so that the next one is predicted within GAL_ROM_CARRY_TOL
                             * of the tolerance (the internal force carried over it by the kept
                             * tangent, as o.one_pass's steps carry theirs); not at rho_inf = 1
                             * (the discrete gradient needs the energy there) nor on the manifold.
                             * 0: every correction confirmed (default). Measured (BENCHMARKS.md,
                             * session 11): the sampled energy evaluated 8-10% less on the cycle at
                             * 100 elements, compare's figures the same to 3 digits on the limit-cycle
                             * spans, but grosbeak_300_soft_gj at 100 elements (the known miss) then
                             * grows to 59 vectors and ends valid 170 deg p-p in twist where Newton
                             * confirming every correction ends refused (test_cli_rom_cubic.sh) */
    const double *extra;    /* ndof x nextra, column-major: vectors appended after the modal
                             * derivatives (the adaptation's corrections, rom_adapt.h); not owned */
    int nextra;
    const struct gal_rom *setup; /* a wind-independent set-up (gal_rom_setup_alloc) of the same rod,
                             * equilibrium, modes and selection: copied instead of computed when it
                             * matches (gal_rom_alloc); its factorization of K0 is read by the model,
                             * so it must outlive it; not owned, not kept; NULL: computed */
    const struct gal_tangent *k0; /* the tangent at q_eq with its numeric factorization (the
                             * statics': gal_equilibrium.k0): its values and a copy of its factor
                             * are taken instead of evaluating, analysing and factorizing K0 again
                             * (the same numbers) when it is of this rod at q_eq; not owned, not
                             * kept past the build; NULL: computed */
} gal_rom_opts;

/* Per family (gal_family order: vertical, horizontal, torsional, axial): the full equations'
 * residual R at a reconstructed state turned into the displacement that would correct it,
 * du = K0^-1 R, measured in the mass norm (|u|^2 = sum m_d u_d^2, the same unit for twist and
 * translation) and set against the family's own displacement from the equilibrium (at least 2% of
 * the whole motion's, and at least the floor below): a relative amplitude error. */
/* The scale's floor in the vertical, horizontal and axial families: the displacement K0^-1 W that
 * a load of this fraction of the span's own weight along the family would cause (rom_check.c).
 * About the drag of a 1 m/s breeze on a bare conductor (Drake: 0.017 N/m against a weight of
 * 16 N/m), far below any wind that gallops a span: a motion smaller than its response is no
 * scale, so the round-off of a still span is no alarm. */
#define GAL_ROM_CHECK_LOAD 1e-3
typedef struct gal_rom_check {
    double rel[GAL_FAMILY_COUNT];
    double max;             /* the largest of rel */
    double err[GAL_FAMILY_COUNT];   /* the mass norms of du per family */
    double disp[GAL_FAMILY_COUNT];  /* ... and of the displacement from the equilibrium */
    double scale[GAL_FAMILY_COUNT]; /* ... and the scale rel is relative to */
    double power[3][GAL_FAMILY_COUNT]; /* W: the power along the full velocity, per family, of the
                                        * residual R, the load F and the damping force C v */
    double cubic[GAL_FAMILY_COUNT]; /* the cubic indicator (gal_rom_cubic) over scale, per family
                                     * (filled by gal_rom_adapt_residual; 0 otherwise) */
    double ring;            /* the twist's ringing above the damping band (gal_rom_band_amplitude)
                             * over the twist's scale, times GAL_ROM_BAND_WEIGHT (filled by
                             * gal_rom_adapt_residual; 0 otherwise) */
} gal_rom_check;

typedef struct gal_rom {
    const gal_rod *rod;
    gal_rom_opts o;
    int ndof, nq;
    int r;                  /* basis size */
    int nmodes;             /* the first nmodes columns of V are the selected modes */
    double *V;              /* ndof x r, column-major, V^T M V = I */
    double *omega2;         /* nmodes: (rad/s)^2 of the modes */
    double *Cr;             /* r x r: V^T C V */
    double *K0r;            /* r x r: V^T K0 V */
    double *q_eq;           /* nq: the equilibrium */
    gal_csc *K0;            /* the tangent at the equilibrium (the damping's) */
    void *chol0;            /* its factorization (gal_chol): modal derivatives and the check */
    gal_force force;
    double am, af, beta, gamma;
    double fscale, ffloor;  /* reduced force scales of the Newton test: the weight of the nodes
                             * projected, and the round-off of the elastic forces */
    double ufloor;          /* J: the round-off of the rod's energy U (the sampled model's; 0: every
                             * element): below it the discrete gradient is not corrected */
    /* state */
    double t;
    double *x, *v, *a;      /* r */
    double *fi, *fe;        /* r: internal and external reduced forces at the state */
    double U, U1;           /* J: the rod's energy at the state, and at the last evaluation */
    /* workspace */
    double *q, *vq, *gq, *fq;   /* nq */
    double *wn, *wn2;           /* ndof */
    double *x1, *v1, *a1, *fi1, *fe1, *fdg, *res, *da, *J, *Kr; /* r, r x r */
    int *piv;
    gal_csc *K;
    /* counters */
    long steps, newton_iterations, tangents, force_evaluations;
    int lin_ok;             /* the last Newton step converged within two passes (o.one_pass) */
    long halvings;          /* steps retried as two halves after Newton failed */
    long linear_rejections; /* o.one_pass's linear steps refused (GAL_ROM_LINEAR_TOL): Newton instead */
    long carried;           /* o.newton_carry's corrections taken unconfirmed */
    long element_evaluations;      /* energy elements of the rod evaluated by the steps (from the
                             * sample; an evaluation of the whole rod counts all of them) */
    long load_element_evaluations; /* the same for the elements of the aerodynamic loads */
    long check_element_evaluations; /* elements (energy and loads) evaluated by the sample's
                             * checks (gal_rom_hyper_check): O(mesh) each, every
                             * o.hyper_check_interval */
    double build_time_s;
    int setup_reused;       /* 1: the wind-independent set-up was copied from o.setup (chol0 is its) */
    const double *setup_shape; /* the modes (their shapes, not owned) and selection the basis was
                             * built from */
    int setup_nsel, *setup_sel;
    struct gal_rom_hyper *hyper; /* the sample (ecsw.h), or NULL: every element */
    struct gal_rom_qm *qm;  /* o.manifold: the quadratic term (r = nmodes, V = Phi), else NULL */
    double next_hyper_check; /* s */
    double hJ;              /* s: the time step of the factorized iteration matrix J (0: none) */
    double *fr;             /* r: scratch */
    double *fe_prev;        /* r: the loads of the step before (o.loads_once's extrapolation) */
    double hfe;             /* s: the step that led to fe from fe_prev (0: none since the start) */
    double check_floor[GAL_FAMILY_COUNT]; /* the self-check's scale floors (rom_check.c), computed
                             * once: they depend on the equilibrium, K0 and the masses alone */
    int check_floor_set;    /* 1: check_floor holds them */
    double *node_dir;       /* 9 nn: each node's axial, horizontal and vertical unit directions at the
                             * equilibrium (gal_rod_node_directions at q_eq), made at the first
                             * check that needs them (rom_check.c), or NULL */
    struct gal_rom_irk *irk; /* o.scheme GAL_ROM_SCHEME_GAUSS2's workspace (rom_irk.c), or NULL */
} gal_rom;

void gal_rom_default_opts(gal_rom_opts *o);

/* Build the basis about the equilibrium q_eq from the modes sel[0..nsel-1] of md (their shapes
 * over the free dofs), and start at rest at q_eq. `force` (may be NULL) gives the external loads
 * F(t, q, v) on the full configuration, as for the full model. NULL with a message on failure. */
gal_rom *gal_rom_alloc(const gal_rod *rod, const double *q_eq, const gal_modes *md, const int *sel, int nsel,
                       const gal_rom_opts *o, const gal_force *force);
gal_rom *gal_rom_free(gal_rom *m);

/* The part of gal_rom_alloc that does not depend on the loads, the damping or the time step (a
 * sweep over the wind on one span computes it once): the basis (the modes and their modal
 * derivatives), the factorization of K0, V^T K0 V and the internal force's sample (ecsw.h) with its
 * constants; not a model to run: give it to gal_rom_alloc as o.setup, which copies it and adds
 * the loads' sample, the damping and the start (bit for bit the model gal_rom_alloc computes
 * alone). The quadratic manifold (o.manifold) has no such set-up: NULL with a message. */
gal_rom *gal_rom_setup_alloc(const gal_rod *rod, const double *q_eq, const gal_modes *md, const int *sel, int nsel,
                             const gal_rom_opts *o);

/* Start at time t from the full state (q, v) (v may be NULL: at rest), projected on the basis:
 * x = V^T M (q - q_eq). */
int gal_rom_start(gal_rom *m, double t, const double *q, const double *v);
#define GAL_ROM_HALVINGS 4 /* a step whose Newton fails is retried as two halves, this deep */
/* o.one_pass: a linear step is taken only while the kept tangent predicts the internal force at
 * the step's predictor within this share of the step's force scale (the Newton test's), else a
 * Newton step from the state's own force (rom_step.c) */
#define GAL_ROM_LINEAR_TOL 0.1
/* o.newton_carry: a correction is taken unconfirmed when the residual it corrects, times the
 * contraction the kept matrix gained on the one before (the residual it predicts next), is within
 * this fraction of Newton's tolerance */
#define GAL_ROM_CARRY_TOL 1.0

/* One step of o.h (retried in halves, GAL_ROM_HALVINGS deep, when Newton fails or the rod
 * degenerates); GAL_EFAIL with time and reason when even the smallest fails. */
int gal_rom_step(gal_rom *m);
/* The sample's check now (gal_rom_hyper_check, ecsw.h: re-sampled past o.hyper_check_tol), counted
 * in check_element_evaluations; what gal_rom_step does every o.hyper_check_interval. A caller that
 * schedules it itself (o.hyper_check_interval = 0) puts it at the state of its self-check
 * (gal_rom_residual), which then takes the whole rod's gradient and loads from it. GAL_OK without
 * a sample. */
int gal_rom_sample_check(gal_rom *m);
/* The checks' share of the element evaluations: a check (the sample's, gal_rom_hyper_check, or the
 * full residual, gal_rom_residual) evaluates the whole rod and its loads, a step only the samples
 * (the energy's twice, Newton's usual passes; the loads once, o.loads_once): on a fine mesh the
 * checks come less often, so that they cost at most this share of the steps and the cost per
 * simulated second does not grow with the mesh. */
#define GAL_ROM_CHECK_SHARE 0.2
/* s: the interval between checks, at least base_s (the caller's) and long enough for
 * GAL_ROM_CHECK_SHARE (base_s on a model that is not hyper-reduced). On the shipped scenes (at
 * most ~250 elements) it is base_s. */
double gal_rom_check_interval(const gal_rom *m, double base_s);
/* Steps until t >= t_target - h/1000. */
int gal_rom_advance(gal_rom *m, double t_target);

/* Over the free dofs at the state: the velocity vf, the acceleration af and the displacement u
 * from the equilibrium (V x', V x'', V x; on the manifold P x', P x'' + Theta(x', x'), u(x)). x''
 * is the reduced equations' own acceleration at the state, fe - Cr x' - fi (one evaluation), not
 * the integrator's a, which lags it by the step's truncation error (the self-check measures the
 * model, not the step); on the manifold, and if that evaluation fails, the integrator's a. */
void gal_rom_full_rates(gal_rom *m, double *vf, double *af, double *u);
/* The tangent basis at x (ndof x r, column-major): V, or P(x) on the manifold (held by m). */
const double *gal_rom_basis_at(gal_rom *m, const double *x);

/* The reconstructed full state: q = q_eq + V x, v = V x' (configuration-sized; either may be NULL). */
void gal_rom_reconstruct(const gal_rom *m, double *q, double *v);
/* The full reconstruction of x (NULL: the equilibrium) and xd (NULL: at rest) into m->q, m->vq. */
void gal_rom_reconstruct_at(gal_rom *m, const double *x, const double *xd);
/* The same for x alone; returns m->q. */
double *gal_rom_reconstruct_q(gal_rom *m, const double *x);
/* Axial tension (N) of element j of the reconstructed rod. */
double gal_rom_element_tension(const gal_rom *m, int j);
/* Kinetic plus elastic and gravity energy of the reduced state, J. */
double gal_rom_energy(gal_rom *m);
/* The full equations' residual at the reconstructed state (see gal_rom_check). */
int gal_rom_residual(gal_rom *m, gal_rom_check *chk);

/* The reduced modes of (K0r, I) above a frequency band (rom_check.c): the basis's vectors there are
 * Ritz approximations of modes the structural damping does not reach (damping.h: modal damping
 * stops at its band), so an oscillation they carry rings undamped on a frequency that is a few
 * tenths of a percent to percents off the rod's; data/scenes/iced_gallop.ini at 600 elements rang
 * 1.6 deg of twist at 6.38 Hz where the full model has 5e-5 deg, and the residual did not see it
 * (the cause, a growth's correction carrying stiff translations into the twist's Ritz vector, is
 * fixed: gal_rom_residual_family). The self-check reads the twist's part (rom_adapt.h,
 * GAL_ROM_BAND_WEIGHT): tests/rom/partridge_180_dshape.ini's third-order set rings 2.3 deg at
 * 11.7 Hz (BENCHMARKS.md, issue 13, helper partridge). */
typedef struct gal_rom_band {
    int r, n;               /* basis size it was computed for; modes above the band */
    double *y;              /* r x n: the modes' reduced shapes (owns the block) */
    double *w2;             /* n: their (rad/s)^2 */
    double *share;          /* n x GAL_FAMILY_COUNT: each mode's mass share per family */
} gal_rom_band;
/* Compute the modes of m above band_hz into b (cleared first). */
int gal_rom_band_init(gal_rom *m, double band_hz, gal_rom_band *b);
/* Per family, the mass norm of the ringing in those modes, from the state's velocity and
 * acceleration, sqrt(sum_k ((y_k^T v)^2 / w_k^2 + (y_k^T a)^2 / w_k^4) share_kf): the displacement
 * amplitude of a mode ringing at its frequency, at any phase; a quasi-static part at a frequency W
 * reads W / w_k of its size. */
void gal_rom_band_amplitude(const gal_rom *m, const gal_rom_band *b, double amp[GAL_FAMILY_COUNT]);
void gal_rom_band_clear(gal_rom_band *b);
/* The same, with the correcting displacement du = K0^-1 R over the free dofs into du (ndof; may
 * be NULL). */
int gal_rom_residual_dir(gal_rom *m, gal_rom_check *chk, double *du);
/* The correction of one family alone: K0^-1 of the part of the residual R = K0 du (du from
 * gal_rom_residual_dir) in family f (at each node its translation along f's direction, as the check
 * splits them; the twist), into df (ndof; may be du). What a growth on f's residual adds: the
 * other families' parts of R are within the tolerance (their share is noise of the basis and the
 * sample), and their static response is stiff translation that a twist correction then carries
 * into the basis's twist vectors: on data/scenes/iced_gallop.ini at 600 elements it made the
 * third torsional Ritz vector's stiffness follow the galloping tension (6.54-6.62 Hz along the
 * cycle, the rod's mode a constant 6.3436), and the rod's internal force pumped a 1.6-deg 6.38-Hz
 * line into it (BENCHMARKS.md, issue 13, helper line). */
int gal_rom_residual_family(gal_rom *m, const double *du, gal_family f, double *df);

/* y (ndof) minus its part in m's basis (V^T M V = I): y -= V V^T M y; Mc (ndof) and p (r) scratch
 * (rom_check.c). */
void gal_rom_deflate(const gal_rom *m, double *y, double *Mc, double *p);
/* The basis's next term, an a-priori error indicator (the check of rom_adapt.h): the third-order
 * part of the static response along the modes' displacement w = Phi eta (nmodes entries),
 * c = -(1/6) K0^-1 D2K[w, w] w (D2K: the second directional derivative of the tangent, by central
 * differences over a translation of GAL_ROM_CUBIC_STEP m along w; the third-order modal
 * derivatives -K0^-1 d2K/d eta_j d eta_k phi_i summed over the state, Idelsohn & Cardona's
 * construction one order up), less its part in the basis; per family (gal_rom_check's directions)
 * the mass norm of what is left into err. Two tangents of the whole rod and one solve. Zeros on
 * the manifold. */
#define GAL_ROM_CUBIC_STEP 0.02
int gal_rom_cubic(gal_rom *m, const double *eta, double err[GAL_FAMILY_COUNT]);
/* How taut the reconstructed conductor still is: the lesser, over the two supports, of the support
 * element's tension at the reduced state over its tension at the equilibrium (1 at rest, 0 slack,
 * negative in compression; 1 when the equilibrium has no tension). The basis (modes and modal
 * derivatives about the taut equilibrium) carries the stretch only near that tension: a conductor
 * going slack is outside it, and the residual does not see it (the reduced equations are the full
 * ones projected on the basis; BENCHMARKS.md, issue 13, helper turb, session 11). Below
 * GAL_ROM_SLACK_SHARE a reduced run is not valid (integrator_rom.c, rom_sim.c): calibrated on
 * tests/rom/, data/scenes/ and tests/hard/, whose runs within issue 13's figures keep 0.50 or more
 * of the static tension, where every run of drake_300_turbulent and cardinal_500_sagged_stats
 * (9-54% off, or refused) goes below 0; O(r). */
#define GAL_ROM_SLACK_SHARE 0.1
double gal_rom_taut_share(const gal_rom *m);
/* The reduced internal force V^T grad U(q_eq + V x) (r entries). */
int gal_rom_internal_force(gal_rom *m, const double *x, double *f);
/* Kr = V^T K V (r x r) for a tangent K on the rod's pattern; work: ndof. */
void gal_rom_project_tangent(const gal_rom *m, const gal_csc *K, double *Kr, double *work);
/* At the reconstructed state: per probe (fractions of the span) the displacement from the
 * equilibrium, horizontal, vertical, along (m) and twist (deg), 4 entries each into row; the
 * support elements' tensions (N). */
void gal_rom_observe(const gal_rom *m, int nprobe, const double *probe, double *row, double tension[2]);
/* Configuration entry qi of the reconstructed state (rate: of its velocity), O(r). */
double gal_rom_entry(const gal_rom *m, int qi, int rate);

#ifdef __cplusplus
}
#endif

#endif
