/* dynamics.h: the full nonlinear equations of motion of the discretized rod (paper Eq. 9),
 *   M a + C v + grad U(q) = F(t, q, v),
 * integrated by the generalized-alpha method (Chung & Hulbert 1993) with modified Newton at each
 * step on the sparse tangent (CHOLMOD: symbolic analysis once, a numeric factorization kept while
 * it converges fast, see GAL_DYN_RATE). M is the lumped mass; C the structural damping (model/damping.h: the one object the
 * reduced model projects and the stability analysis linearizes with); F holds the external loads
 * (aerodynamics), given by a callback. rho_inf = 1 gives no numerical dissipation. */
#ifndef GALLOP_DYNAMICS_H
#define GALLOP_DYNAMICS_H

#include "gallop/model/damping.h"
#include "gallop/model/force.h"
#include "gallop/rod/rod.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Modified Newton: the factorization is kept while each iteration divides the residual by
 * 1/GAL_DYN_RATE at least. */
#define GAL_DYN_RATE 0.1
/* A Newton residual within this relative tolerance (the default of simulation.newton_tolerance)
 * is converged whatever the iteration before it did; above it (a looser newton_tol) only after a
 * correction that reduced the residual. Shared by the full (dynamics.h) and reduced (rom.h) steps. */
#ifndef GAL_NEWTON_TOL_STRICT
#define GAL_NEWTON_TOL_STRICT 1e-8
#endif

typedef struct gal_dyn_opts {
    double h;            /* s, time step */
    double rho_inf;      /* spectral radius at infinite frequency, [0, 1]; 1: no dissipation */
    const gal_damping *damping; /* the structural damping C (not owned; NULL: none) */
    double newton_tol;   /* relative residual (over the step's force scale); default 1e-8
                          * (simulation.newton_tolerance) */
    int max_newton;      /* per step; default 20 */
    int max_halvings;    /* step halvings on a failed step before giving up; default 6 */
} gal_dyn_opts;

typedef struct gal_dyn {
    const gal_rod *rod;
    gal_dyn_opts o;
    double am, af, beta, gamma; /* generalized-alpha parameters */
    double t;                   /* s */
    double *q;                  /* nq: configuration */
    double *v, *a;              /* nq: velocity and acceleration (zero at fixed dofs) */
    double *mdiag;              /* ndof */
    gal_csc *S;                 /* iteration matrix */
    void *chol;                 /* its factorization, kept over iterations and steps */
    double factor_h;            /* s: the step size it was made for (0: none) */
    gal_force force;
    /* workspace */
    double *q1, *v1, *a1, *fint0, *fint1, *fext0, *fext1, *r, *dq, *tmp, *Cv;
    /* counters */
    long steps, newton_iterations, factorizations, force_evaluations, rejected_steps;
    double energy0;             /* J, mechanical energy at the start */
} gal_dyn;

void gal_dyn_default_opts(gal_dyn_opts *o);
/* Start at configuration q0 (an equilibrium) with velocity v0 (configuration-sized, may be NULL:
 * at rest). The initial acceleration is solved from the equations of motion. */
gal_dyn *gal_dyn_alloc(const gal_rod *rod, const double *q0, const double *v0, const gal_dyn_opts *o,
                       const gal_force *force);
gal_dyn *gal_dyn_free(gal_dyn *d);
/* Advance by one step of o.h (halving internally when Newton fails: the state is restored and the
 * interval is covered by smaller steps). GAL_EFAIL with time, step and reason when it cannot. */
int gal_dyn_step(gal_dyn *d);
/* Kinetic + elastic + gravity energy, J. */
double gal_dyn_energy(const gal_dyn *d);
/* One step of length h covered by attempts try_step(ctx, hh) (each restoring the state on failure),
 * halving hh after a failure up to max_halvings times; *rejected counts the failed attempts. who
 * names the integrator in the message, *t is its current time (read at a failure). GAL_ENOMEM at once;
 * GAL_EFAIL with time, halvings and the last attempt's reason when it cannot. */
int gal_dyn_subdivide(int (*try_step)(void *ctx, double hh), void *ctx, double h, int max_halvings,
                      long *rejected, const double *t, const char *who);

#ifdef __cplusplus
}
#endif

#endif
