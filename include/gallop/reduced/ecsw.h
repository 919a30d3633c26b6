/* ecsw.h: hyper-reduction of the recomputed reduced model (rom.h) by energy-conserving sampling
 * and weighting (ECSW; Farhat, Avery, Chapman & Cortial 2014). The rod's energy is split into
 * elements (rod.h, gal_rod_element_eval); the reduced model keeps a sampled set of them with
 * weights w_e >= 0 and uses
 *   U_h(x) = sum_{e in S} w_e U_e(q(x)) + U_c + f_c . x + x . K_c x / 2,
 * q(x) = q_eq + V x, with U_c, f_c, K_c the constants that make U_h, its gradient and its Hessian
 * exact at the equilibrium (x = 0: the linear dynamics, the modes' frequencies, are the
 * unreduced model's; the sample carries the nonlinear remainder): a conservative potential, so
 * the discrete-gradient step keeps conserving T + U_h. Its gradient and tangent touch only the rows of V at the sampled elements' entries:
 * the cost of a step does not grow with the mesh. The aerodynamic loads get their own sample and
 * weights, at the current state (gal_force.element).
 * The weights come from a non-negative least-squares fit (gal_nnls, stopped once the residual is
 * below opts.hyper_tol of the target) of the per-element reduced forces V_e^T grad U_e, less their
 * value and linear part at the equilibrium, to their sum on training states: modal states at the
 * scale of the motion (the sag, at least 1% of the span, and opts.hyper_twist for the twist) with
 * the modal-derivative coordinates at zero; each coordinate's force weighed by its RMS over the
 * states, each state normalized; on a mirror-symmetric span the columns are mirror pairs. On a
 * mesh of more than 128 elements the columns are those of 128 candidates of each kind spread
 * over the span (ecsw_train.c) and the targets the assembled forces: the set-up's cost grows with
 * the mesh only by one evaluation of the rod and the loads per training state. The model checks its sample (gal_rom_hyper_check) against the exact projected force at
 * its own state and, beyond opts.hyper_check_tol, adds that state to the training set and
 * re-samples. */
#ifndef GALLOP_ECSW_H
#define GALLOP_ECSW_H

#include "gallop/reduced/rom.h"

#ifdef __cplusplus
extern "C" {
#endif

/* min |A x - b| subject to x >= 0 (Lawson & Hanson), A m x n column-major; stops once
 * |A x - b| <= tol |b| or at most pmax entries of x are positive (pmax <= 0: no limit). x: n. */
int gal_nnls(int m, int n, const double *A, const double *b, double tol, int pmax, double *x, int *iterations);

typedef struct gal_rom_hyper_info {
    int elements;          /* sampled energy elements (of gal_rod_element_count) */
    int load_elements;     /* sampled elements of the aerodynamic loads */
    int snapshots;         /* training states */
    int refits;            /* re-samplings after a failed check */
    int refits_energy;     /* of them, those that fitted the rod's sample again (its check failed:
                           * both samples fitted again) */
    int refits_loads;      /* and the loads' (with the rod's, or alone when only theirs failed) */
    int loads_whole;       /* the loads' sample grew past half the edges at a re-fit: the loads
                           * over every edge since (load_elements -1) */
    double fit_error;      /* the NNLS residual of the rod's sample, relative */
    double load_fit_error; /* and of the loads' */
    int mirror;            /* the samples are mirror pairs */
    double check_error;    /* the last check's relative error (gal_rom_hyper_check) */
    long train_element_evals; /* element evaluations of the fits' candidate columns so far (set-up
                           * and re-samplings): at most 128 of each kind per training state */
    long train_full_evals; /* evaluations of the whole rod or loads for the fits' targets (none
                           * when every element is a candidate) */
} gal_rom_hyper_info;

/* Build the sample and weights of m (called by gal_rom_alloc when opts.hyper is on). */
int gal_rom_hyper_build(gal_rom *m);
void gal_rom_hyper_free(gal_rom *m);
/* The model's internal force at x and its energy into m->U1 (its tangent into Kr when non-NULL),
 * from the sample alone. */
int gal_rom_hyper_internal(gal_rom *m, const double *x, double *f, double *Kr);
/* The reduced loads at (t, x, xd) from the load sample alone. */
int gal_rom_hyper_external(gal_rom *m, double t, const double *x, const double *xd, double *f);
/* At the current state: the relative difference of the hyper-reduced internal force from the
 * exact projected one, V^T grad U (and of the loads), in the K0r^-1 norm of the force's change
 * from the equilibrium; beyond opts.hyper_check_tol the state joins the training set and both
 * samples are re-fitted (the integrator's state is re-evaluated). *err may be NULL. */
int gal_rom_hyper_check(gal_rom *m, double *err);
/* The exact projected internal force V^T grad U(q_eq + V x) (every element; m->q is overwritten). */
int gal_rom_exact_force(gal_rom *m, const double *x, double *f);
/* Every element at weight 1 (the unreduced model's forces, to round-off): a check of the machinery. */
int gal_rom_hyper_use_all(gal_rom *m);
void gal_rom_hyper_get_info(const gal_rom *m, gal_rom_hyper_info *info);

#ifdef __cplusplus
}
#endif

#endif
