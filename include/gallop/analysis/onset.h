/* onset.h: the galloping onset of the coupled aeroelastic system about the mean-wind equilibrium
 * (issue 15). For each wind speed of a range:
 *   1. the static equilibrium under the mean wind (drag, lift, moment: gal_loads_static), followed
 *      by continuation from the previous speed; a jump of the path (a fold) is reported;
 *   2. the linearization there of the full equations M u'' + C u' + K u = F(q + u, v):
 *        K_t = K(q) - dF/dq,   C_t = C - dF/dv
 *      with K the rod's tangent, C the structural damping (gal_damping: the one the dynamic models
 *      apply), dF/dq and dF/dv the quasi-steady aerodynamic stiffness and damping, derivatives of
 *      gal_loads_full's element loads (central differences element by element: each element's load
 *      depends on its two nodes, its twist and its nodes' velocities only);
 *   3. projected on the lowest `basis` natural modes of (K(q), M) at that speed (with torsion, plus
 *      the lowest GAL_ONSET_TORSIONAL torsional modes not among them), the state matrix
 *      [0 I; -K_t -C_t] and its eigenvalues (LAPACK dgeev): lambda = -zeta w +- i w sqrt(1-zeta^2).
 * The lowest `nmodes` aeroelastic modes at the first speed are followed over the speeds by
 * continuity (MAC of the physical shapes, less the relative frequency change). The onset is the
 * lowest speed at which a followed mode's damping ratio crosses zero (linear interpolation);
 * torsional divergence is where the smallest real eigenvalue of K_t crosses zero (at the linear
 * divergence speed about the last stable configuration when that falls between the two speeds). */
#ifndef GALLOP_ONSET_H
#define GALLOP_ONSET_H

#include "gallop/loads/loads.h"
#include "gallop/model/damping.h"
#include "gallop/modes/modes.h"
#include "gallop/rod/rod.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GAL_ONSET_SPEED_MIN 0.5   /* m/s, defaults of [stability] speed_min, speed_max, speed_step */
#define GAL_ONSET_SPEED_MAX 20.0
#define GAL_ONSET_SPEED_STEP 0.25
#define GAL_ONSET_BASIS 30        /* natural modes in the basis (converged: see tests/test_onset.c) */
#define GAL_ONSET_NMODES 8        /* aeroelastic modes followed */
#define GAL_ONSET_TORSIONAL 4     /* torsional modes the basis holds at least (appended above the
                                   * lowest `basis` when they are not among them) */

typedef struct gal_onset_opts {
    double speed_min, speed_max, speed_step; /* m/s; speed_min may be 0 */
    int basis;        /* natural modes in the basis (capped at ndof - 1) */
    unsigned families;/* bit (1u << gal_family) of the families the basis takes (0: all) */
    int nmodes;       /* aeroelastic modes followed (at most basis) */
    double static_tol;/* N, force tolerance of the static solutions (0: 1e-6 H / elements) */
} gal_onset_opts;

/* The mean-wind equilibrium and the classic criteria at one speed (mid-span values). */
typedef struct gal_onset_speed {
    double speed;          /* m/s */
    int ok;                /* the static solution converged (else the rest is NaN) */
    int fold;              /* the static path jumped between the previous speed and this one */
    double swing_deg;      /* angle of the mid-span sag from the vertical, downwind positive */
    double twist_deg;      /* mid-span twist */
    double alpha_deg;      /* angle of attack of the mean wind at mid-span */
    double den_hartog;     /* H = dC_L/dalpha + C_D at alpha (per rad) */
    double den_hartog_onset; /* m/s: -4 m zeta w / (rho d H) of the lowest vertical natural mode at
                              * this speed with the ratio the applied damping gives it; inf: H >= 0 */
    double zeta_vertical;  /* that ratio */
    double nigol_dcm;      /* dC_M/dalpha at alpha (per rad); Nigol: < 0 torsionally unstable */
    double zeta_torsional; /* the applied damping's ratio at the lowest torsional natural mode */
    double nigol_onset;    /* m/s: Nigol's torsional onset of that mode at alpha (stability.h:
                            * gal_stability_nigol_onset); inf: dC_M/dalpha >= 0; NaN: no torsion */
    double kt_min;         /* smallest real eigenvalue of the modal K_t, (rad/s)^2; < 0 diverged */
    double divergence_linear; /* m/s: the speed at which K_t about this configuration, its aerodynamic
                              * stiffness scaled with U^2, would turn singular (inf: never) */
} gal_onset_speed;

/* One followed aeroelastic mode at one speed. */
typedef struct gal_onset_mode {
    double frequency_hz;   /* |Im lambda| / 2 pi; 0 for a real eigenvalue */
    double damping_ratio;  /* -Re lambda / |lambda|; < 0 grows */
    double growth_rate;    /* Re lambda, 1/s */
    double share[3];       /* kinetic-energy shares: vertical, horizontal, torsional (+ axial = 1) */
    double mac;            /* MAC with the same mode at the previous speed (1 at the first) */
} gal_onset_mode;

typedef struct gal_onset {
    int nspeed, nmodes, basis;
    gal_onset_speed *sp;   /* nspeed */
    gal_onset_mode *m;     /* nspeed x nmodes: m[i * nmodes + k] */
    double speed_max;      /* m/s, the range studied */
    /* the onset: lowest speed where a followed mode's damping ratio crosses zero; NaN when stable
     * over the whole range (index -1); speed_min when already unstable there */
    double onset_speed;
    int onset_mode;        /* index of the followed mode (0-based), -1 */
    double onset_frequency_hz;
    double onset_share[3]; /* vertical, horizontal, torsional at the onset (interpolated) */
    double restable_speed; /* m/s, above it every followed mode is damped again up to speed_max
                              * (interpolated); NaN: unstable at speed_max, or never unstable */
    double divergence_speed; /* m/s, kt_min crossing zero (interpolated); NaN: none */
    double fold_speed;     /* m/s, the first jump of the static path (midpoint); NaN: none */
    double wall_time_s;
} gal_onset;

void gal_onset_default_opts(gal_onset_opts *o);

/* The analysis of a span `rod` (its reference configuration set at q_eq, the no-wind equilibrium)
 * under the loads L (table, flags, air density, diameter, attack angle, direction as the runs
 * use them; speed, turbulence and ramp ignored), with the structural damping C. `mass` (kg/m, the
 * conductor and ice) is for the classic Den Hartog column. The rod's scratch values are used.
 * GAL_OK, or GAL_EINPUT (bad options, no table), GAL_EFAIL (no equilibrium at the first speed,
 * modes or LAPACK failed), GAL_ENOMEM. */
int gal_onset_analyse(const gal_rod *rod, const double *q_eq, const gal_loads *L, const gal_damping *C, double mass,
                      const gal_onset_opts *o, gal_onset *out);
void gal_onset_clear(gal_onset *r);

/* ---- the linearization (onset_linear.c), for tests and other analyses ---- */

/* Aerodynamic stiffness and damping projected on a basis Phi (ndof x n, column-major):
 * Ka = -Phi^T dF/dq Phi, Ca = -Phi^T dF/dv Phi (n x n, column-major; either may be NULL), with F
 * the generalized loads of gal_loads_full at configuration q and zero velocity. */
int gal_onset_aero_matrices(const gal_rod *rod, const double *q, const gal_loads *L, const double *phi, int n,
                            double *Ka, double *Ca);

/* Swing, twist, angle of attack and the table's criteria (den_hartog, nigol_dcm) at mid-span of the
 * rod's configuration q under L at L->speed. */
void gal_onset_measures(const gal_rod *rod, const double *q, const gal_loads *L, gal_onset_speed *sp);

/* ---- the eigen-sweep on another discretization (the explicit bundle's, bundle/onset.c) ----
 * The caller finds the equilibrium and the basis at each speed; the track does what
 * gal_onset_analyse does from there: K_t = diag(omega^2) + Ka, C_t = Cs + Ca, K_t's smallest
 * eigenvalue and the linear divergence speed (sp->kt_min, divergence_linear), the state matrix's
 * eigenvalues, the followed modes of row i of out->m (MAC weighted by mdiag, shares by `shares`).
 * gal_onset_conclude then finds the onset, restabilization and divergence over out's speeds (the
 * rows whose sp->ok is 0 set to NaN first). */
typedef void (*gal_onset_shares_fn)(void *ctx, const double *ure, const double *uim, double share[3]);
typedef struct gal_onset_track gal_onset_track;
/* n dofs of the shapes, nb basis modes, nm followed; mdiag (n) copied. NULL with a message. */
gal_onset_track *gal_onset_track_alloc(int n, int nb, int nm, const double *mdiag);
gal_onset_track *gal_onset_track_free(gal_onset_track *t);
/* phi: n x nb column-major, mass-normalized natural modes of circular frequencies omega (nb); Ka,
 * Ca, Cs: nb x nb column-major (aerodynamic stiffness, aerodynamic and structural damping). */
int gal_onset_track_speed(gal_onset_track *t, const double *phi, const double *omega, const double *Ka,
                          const double *Ca, const double *Cs, gal_onset_shares_fn shares, void *ctx,
                          gal_onset_speed *sp, gal_onset *out, int i);
void gal_onset_conclude(gal_onset *out);

#ifdef __cplusplus
}
#endif

#endif
