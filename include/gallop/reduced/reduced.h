/* reduced.h: the reduced-order model on the modes (DESIGN.md "Time integration", issue 6).
 * Coordinates eta on a basis Phi of selected mass-normalized modes; the restoring force is a
 * cubic polynomial
 *   f_i(eta) = w_i^2 eta_i + sum_{j<=k} B_ijk eta_j eta_k + sum_{j<=k<=l} A_ijkl eta_j eta_k eta_l
 *            + sum_j (P4_ij eta_j^4 + P5_ij eta_j^5),
 * (the pure 4th and 5th powers carry the strong one-mode softening of a sagged span),
 * identified once by static condensation at prescribed modal amplitudes (the displacement cases of
 * Muravyov & Rizzi 2003's stiffness evaluation, with every other dof relaxed as in implicit
 * condensation, Hollkamp & Gordon 2008): the full rod is held at Phi^T M u = eta and its nonlinear
 * equilibrium carries the stretching (the axial motion of the cable, quasi-static at these
 * frequencies) that a projection on the linear modes alone cannot; the constraint forces are f(eta).
 * The cost of evaluating f does not depend on the number of elements. A quadratic-plus-cubic
 * expansion recovers chosen full coordinates (the probes) from eta. */
#ifndef GALLOP_REDUCED_H
#define GALLOP_REDUCED_H

#include "gallop/modes/modes.h"
#include "gallop/rod/rod.h"

#ifdef __cplusplus
extern "C" {
#endif

/* An observed quantity: w[0] u[q[0]] + w[1] u[q[1]] of the displacement u = q - q_eq over the
 * configuration (q[1] = -1: one entry). Positions and slopes between nodes are such. */
typedef struct gal_obs {
    int q[2];
    double w[2];
} gal_obs;

typedef struct gal_reduced_opts {
    double amplitude_m;     /* m: largest translation of a load case (per mode) */
    double amplitude_rad;   /* rad: largest twist of a load case (torsional modes) */
} gal_reduced_opts;

typedef struct gal_reduced {
    int r;                  /* basis size */
    int ndof;
    double *phi;            /* ndof x r, columns mass-normalized modes */
    double *omega2;         /* r: (rad/s)^2 */
    int *mode_index;        /* r: index in the gal_modes it came from */
    gal_family *family;     /* r */
    int n2, n3;             /* quadratic and cubic monomials */
    int *m2;                /* 2 n2: (j, k), j <= k */
    int *m3;                /* 3 n3: (j, k, l), j <= k <= l */
    double *B;              /* r x n2 */
    double *A;              /* r x n3 */
    double *P;              /* r x 2r: coefficients of eta_j^4 (first r) and eta_j^5 (next r) */
    double *eta_ref;        /* r: modal amplitude of the load cases */
    int nobs;               /* observed quantities */
    gal_obs *obs;           /* nobs */
    double *obs_lin;        /* nobs x r: Phi rows */
    double *obs_nl;         /* nobs x (n2 + n3 + 2 r): expansion coefficients */
    /* identification figures */
    int load_cases;
    int shrunk_cases;       /* cases taken at a smaller amplitude (the span folded at the full one) */
    long newton_iterations;
    double fit_residual;    /* relative rms residual of the force fit */
    double build_time_s;
} gal_reduced;

void gal_reduced_default_opts(gal_reduced_opts *o);

/* Identify the model about the equilibrium q_eq on the modes of `md` with indices sel[0..r-1].
 * obs (nobs) are the quantities to be recovered by expansion. */
gal_reduced *gal_reduced_build(const gal_rod *rod, const double *q_eq, const gal_modes *md, const int *sel,
                               int r, const gal_obs *obs, int nobs, const gal_reduced_opts *o);
gal_reduced *gal_reduced_free(gal_reduced *rm);

/* f(eta), the reduced restoring force (per unit modal mass). */
void gal_reduced_force(const gal_reduced *rm, const double *eta, double *f);
/* Observed quantities at eta: out[nobs]; and, when rate != NULL, their rates for eta' = deta. */
void gal_reduced_observe(const gal_reduced *rm, const double *eta, double *out);
void gal_reduced_observe_rate(const gal_reduced *rm, const double *eta, const double *deta, double *out,
                              double *rate);
/* The exact condensed restoring force at eta: the constraint forces of the full rod held at
 * Phi^T M u = eta with every other dof relaxed (what the polynomial f fits; costs a Newton solve). */
int gal_reduced_condensed_force(const gal_reduced *rm, const gal_rod *rod, const double *q_eq, const double *eta,
                                double *f);
/* The Galerkin projection on the same linear modes, Phi^T grad U(q_eq + Phi eta) (cost grows with
 * the elements; what the condensation corrects; for comparison). */
int gal_reduced_projected_force(const gal_reduced *rm, const gal_rod *rod, const double *q_eq,
                                const double *eta, double *f, double *work_q, double *work_g);

#ifdef __cplusplus
}
#endif

#endif
