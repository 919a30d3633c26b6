/* internal.h: what the reduced model's sources share (not public): the monomials of the restoring
 * force and the condensation workspace. */
#ifndef GALLOP_REDUCED_INTERNAL_H
#define GALLOP_REDUCED_INTERNAL_H

#include "gallop/reduced/reduced.h"

#include "base/chol.h"

/* monomial values of x: mu[0..n2) quadratic, then cubic, then the pure 4th and 5th powers */
void gal_reduced_monomials(const gal_reduced *rm, const double *x, double *mu);

/* Static condensation at prescribed modal coordinates: minimize U(q) subject to
 * Phi^T M (q - q_eq) = eta. The multipliers are the reduced restoring force f(eta) (per unit modal
 * mass, since Phi^T M Phi = I); every other dof, the stretching of the cable among them, relaxes.
 * Newton on the KKT system, by its Schur complement on the r multipliers:
 *   [K        -MPhi] [dq  ]     [g - MPhi lam              ]
 *   [(MPhi)^T     0] [dlam] = - [Phi^T M (q - q_eq) - eta]. */
typedef struct {
    gal_csc *K;           /* the tangent stiffness (the stage's own values on the rod's pattern) */
    gal_chol *chol;
    double *g, *r1, *r2, *Y, *S, *x, *mdiag, *MPhi, *dq, *dl, *qt;
} gal_kkt_ws;

/* The workspace of the condensation, with M Phi (r columns of n). */
int gal_kkt_alloc(gal_kkt_ws *w, const gal_rod *rod, const gal_reduced *rm);
void gal_kkt_free(gal_kkt_ws *w);
/* Condense at eta from the start q (updated in place) and multipliers lam (updated: f(eta));
 * Newton iterations are added to *iters. */
int gal_kkt_condense(const gal_rod *rod, const double *q_eq, const gal_reduced *rm, gal_kkt_ws *w, const double *eta,
                     double *q, double *lam, double ftol, long *iters);

#endif
