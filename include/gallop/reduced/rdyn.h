/* rdyn.h: time integration of the reduced model (issue 6):
 *   eta'' + Phi^T C Phi eta' + f(eta) = sum_q w_q [Phi(s_q)^T f_q + Phi_theta(s_q) m_q]
 * with f the identified restoring force (reduced.h), the structural damping C (model/damping.h)
 * projected exactly on the basis (the modal band's: 2 zeta w on the diagonal), and the distributed loads evaluated at
 * a fixed number of quadrature points along the span from the mode shapes, so that the cost of a
 * step does not depend on the number of elements. GSL odeiv2 (Runge-Kutta-Prince-Dormand 8(9)),
 * adaptive, with a relative tolerance. */
#ifndef GALLOP_RDYN_H
#define GALLOP_RDYN_H

#include <gsl/gsl_odeiv2.h>

#include "gallop/model/damping.h"
#include "gallop/model/force.h"
#include "gallop/reduced/reduced.h"
#include "gallop/rod/rod.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct gal_rdyn {
    const gal_reduced *rm;
    int r;
    int nqp;             /* quadrature points */
    double *wq;          /* nqp: weights, m of unstretched length */
    double *req, *teq, *aeq;   /* 3 nqp: equilibrium position, tangent, reference director */
    double *phr;         /* nqp x r x 3: mode shapes (translation) at the points */
    double *phs;         /* nqp x r x 3: their derivative along s */
    double *pht;         /* nqp x r: twist */
    double *damp;        /* r x r: Phi^T C Phi (column-major) */
    double *nt;          /* nqp: |dr/ds| at equilibrium */
    int obs_offset;      /* >= 0: kinematics at the points from the model's expansion (7 observations
                          * per point from this index on); -1: linear in the modes */
    double *ob, *obr;    /* scratch: observations and their rates */
    gal_pointload load;
    double t;            /* s */
    double *y;           /* 2r: eta, eta' */
    double t_prev;       /* s: the step before (gal_rdyn_sample) */
    double *y_prev;      /* 2r */
    double *fr, *fl;     /* scratch */
    gsl_odeiv2_system sys;
    gsl_odeiv2_driver *drv;
    long rhs_evaluations;
    int status;          /* set by the right-hand side on a failure */
    double tol;
} gal_rdyn;

/* damping: the structural damping (NULL: none), projected on the model's modes here. */
gal_rdyn *gal_rdyn_alloc(const gal_reduced *rm, const gal_rod *rod, const double *q_eq, const gal_damping *damping,
                         const gal_pointload *load, int nqp, double rel_tol, double h0, int obs_offset);
/* The observations at the nqp quadrature points that gal_rdyn uses when obs_offset >= 0: per
 * point its displacement (3), slope d u / ds (3) and twist (1), 7 nqp in all. */
void gal_rdyn_quadrature_obs(const gal_rod *rod, int nqp, gal_obs *obs);
gal_rdyn *gal_rdyn_free(gal_rdyn *d);
/* Integrate to t_target (adaptive steps). GAL_EFAIL with time and reason on failure (NaN, step
 * size underflow). */
int gal_rdyn_advance(gal_rdyn *d, double t_target);
/* The state at t_out (>= the last sample) by natural adaptive steps towards t_end and cubic
 * Hermite interpolation (eta and eta' at both ends of the step that holds t_out): outputs at any
 * rate cost no extra steps. y_out has 2r entries. */
int gal_rdyn_sample(gal_rdyn *d, double t_out, double t_end, double *y_out);
/* Steps taken and rejected by the adaptive control. */
void gal_rdyn_counts(const gal_rdyn *d, long *steps, long *rejected);

#ifdef __cplusplus
}
#endif

#endif
