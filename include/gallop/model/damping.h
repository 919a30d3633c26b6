/* damping.h: the structural damping of a span as a property of the structure (DESIGN.md "The rod",
 * issue 15), the same matrix C for the full model, the reduced model and the stability analysis,
 * independent of which modes a scene selects.
 *
 * Modal damping (the default, what `conductor.damping_ratio` states): every natural mode of the
 * span about its no-wind equilibrium whose frequency is at most the band limit gets the stated
 * ratio zeta, modes above it get none:
 *     C = M Phi_b diag(2 zeta w_k) Phi_b^T M,   Phi_b = the mass-normalized modes with f_k <= band
 * so phi_k^T C phi_j = 2 zeta w_k delta_kj for every pair in the band, to round-off. The band
 * limit is GAL_DAMPING_BAND_HZ (5 Hz) unless given: galloping lives below 3 Hz, so every mode a
 * scene may select or the aeroelastic coupling may reach is in it; it holds at most
 * GAL_DAMPING_MAX_MODES modes (the limit is lowered to the last mode kept when a fine mesh would
 * put more below it; `band_hz` then says the limit used). C is dense but of rank nb: applying it
 * costs 2 nb ndof.
 *
 * Rayleigh damping C = alpha M + beta K0 (K0 the tangent at the equilibrium) is kept as a second
 * kind: it is what the dynamic models applied before issue 15 (fitted to zeta at the lowest and
 * highest selected modes), so that the analysis can reproduce those runs. */
#ifndef GALLOP_DAMPING_H
#define GALLOP_DAMPING_H

#include "gallop/base/sparse.h"
#include "gallop/rod/rod.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GAL_DAMPING_BAND_HZ 5.0    /* Hz: default band limit of modal damping */
#define GAL_DAMPING_MAX_MODES 300  /* modes in the band at most */

typedef enum { GAL_DAMPING_NONE, GAL_DAMPING_MODAL, GAL_DAMPING_RAYLEIGH } gal_damping_kind;

typedef struct gal_damping {
    gal_damping_kind kind;
    int ndof;
    double zeta;      /* -, the stated modal ratio (modal kind; Rayleigh: 0) */
    double band_hz;   /* Hz, the band limit used (modal kind) */
    int nb;           /* modes in the band (modal kind) */
    double *omega;    /* nb: rad/s of each band mode */
    double *mphi;     /* ndof x nb, column k = M phi_k over the free dofs */
    double alpha;     /* 1/s, Rayleigh mass coefficient */
    double beta;      /* s, Rayleigh stiffness coefficient */
    gal_csc *K0;      /* Rayleigh: the tangent at the equilibrium (owned) */
    const gal_rod *rod;
} gal_damping;

/* Modal damping zeta over the modes of `rod` about its equilibrium q with f <= band_hz (<= 0: the
 * default GAL_DAMPING_BAND_HZ). zeta = 0 gives the NONE kind (no modes computed). NULL with a
 * message on failure (no modes, out of memory). */
gal_damping *gal_damping_modal_alloc(const gal_rod *rod, const double *q, double zeta, double band_hz);
/* Rayleigh damping alpha M + beta K(q). NULL with a message on failure. */
gal_damping *gal_damping_rayleigh_alloc(const gal_rod *rod, const double *q, double alpha, double beta);
/* Rayleigh coefficients giving zeta at w1 and w2 (rad/s): zeta(w) = alpha/(2w) + beta w/2 (the
 * fit the dynamic models made before issue 15; w2 <= w1 takes w2 = 3 w1). */
void gal_damping_rayleigh_fit(double zeta, double w1, double w2, double *alpha, double *beta);
/* Free; accepts NULL; returns NULL. */
gal_damping *gal_damping_free(gal_damping *c);

/* y += C v over the free dofs (ndof each); y and v must not overlap. */
void gal_damping_apply(const gal_damping *c, const double *v, double *y);
/* P = Phi^T C Phi (n x n, column-major) for a basis Phi (ndof x n, column-major). GAL_OK or
 * GAL_ENOMEM. */
int gal_damping_project(const gal_damping *c, const double *phi, int n, double *P);
/* The damping ratio a mode of shape phi (ndof) and circular frequency omega gets:
 * phi^T C phi / (2 omega phi^T M phi). */
double gal_damping_ratio(const gal_damping *c, const double *phi, double omega);

#ifdef __cplusplus
}
#endif

#endif
