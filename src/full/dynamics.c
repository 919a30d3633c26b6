/* dynamics.c: generalized-alpha integration of the full rod (paper Eq. 9) with Newton's method.
 * Residual at the generalized mid-point (forces interpolated, as in HHT):
 *   R = M a_m + C v_f + (1-af) g(q1) + af g(q0) - (1-af) F1 - af F0,
 *   a_m = (1-am) a1 + am a0,  v_f = (1-af) v1 + af v0,
 *   q1 = q0 + h v0 + h^2 ((1/2 - beta) a0 + beta a1),  v1 = v0 + h ((1-gamma) a0 + gamma a1).
 * Jacobian in q1: (1-am)/(beta h^2) M + (1-af) gamma/(beta h) C + (1-af) K(q1); the loads'
 * dependence on q and v is left out of it, and so is a modal C (dense, of low rank; its term is
 * 2 zeta w h gamma / (1-am) of the inertia's, below 1e-3 at the steps used): both change the
 * convergence rate, not the solution. A Rayleigh C (sparse, the pattern of K) is kept in it. */
#include "gallop/full/dynamics.h"
#include "gallop/base/core.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/chol.h"

void gal_dyn_default_opts(gal_dyn_opts *o)
{
    o->h = 0.01;
    o->rho_inf = 1.0;
    o->damping = NULL;
    o->newton_tol = 1e-8;
    o->max_newton = 20;
    o->max_halvings = 6;
}

gal_dyn *gal_dyn_free(gal_dyn *d)
{
    if (d) {
        free(d->q); free(d->v); free(d->a); free(d->mdiag);
        gal_csc_free(d->S);
        gal_chol_free(d->chol);
        free(d->q1); free(d->v1); free(d->a1); free(d->fint0); free(d->fint1); free(d->fext0);
        free(d->fext1); free(d->r); free(d->dq); free(d->tmp); free(d->Cv);
        free(d);
    }
    return NULL;
}

/* Structural damping Cv = C v over the free dofs (v free-dof-sized). */
static void damping_force(gal_dyn *d, const double *v, double *Cv)
{
    memset(Cv, 0, (size_t)d->rod->ndof * sizeof(double));
    if (d->o.damping) gal_damping_apply(d->o.damping, v, Cv);
}

static int external(gal_dyn *d, double t, const double *q, const double *v, double *f)
{
    memset(f, 0, (size_t)d->rod->nq * sizeof(double));
    if (!d->force.eval) return GAL_OK;
    d->force_evaluations++;
    return d->force.eval(d->force.ctx, t, q, v, f);
}

gal_dyn *gal_dyn_alloc(const gal_rod *rod, const double *q0, const double *v0, const gal_dyn_opts *o,
                       const gal_force *force)
{
    gal_dyn *d = calloc(1, sizeof *d);
    if (!d) return NULL;
    d->rod = rod;
    if (o) d->o = *o;
    else gal_dyn_default_opts(&d->o);
    if (force) d->force = *force;
    double rho = d->o.rho_inf;
    if (!(rho >= 0 && rho <= 1) || !(d->o.h > 0)) {
        gal_error(GAL_EINPUT, "dynamics: time step %g s and rho_inf %g; allowed: h > 0, 0 <= rho_inf <= 1", d->o.h, rho);
        return gal_dyn_free(d);
    }
    d->am = (2 * rho - 1) / (rho + 1);
    d->af = rho / (rho + 1);
    d->gamma = 0.5 - d->am + d->af;
    d->beta = 0.25 * (1 - d->am + d->af) * (1 - d->am + d->af);
    int nq = rod->nq, n = rod->ndof;
    size_t bq = (size_t)nq * sizeof(double), bn = (size_t)n * sizeof(double);
    d->q = malloc(bq), d->v = calloc(nq, sizeof(double)), d->a = calloc(nq, sizeof(double));
    d->q1 = malloc(bq), d->v1 = calloc(nq, sizeof(double)), d->a1 = calloc(nq, sizeof(double)); /* fixed dofs stay 0 */
    d->fint0 = malloc(bq), d->fint1 = malloc(bq), d->fext0 = malloc(bq), d->fext1 = malloc(bq);
    d->mdiag = malloc(bn), d->r = malloc(bn), d->dq = malloc(bn), d->tmp = malloc(bn), d->Cv = malloc(bn);
    d->S = gal_csc_clone(rod->K);
    if (!d->q || !d->v || !d->a || !d->q1 || !d->v1 || !d->a1 || !d->fint0 || !d->fint1 || !d->fext0 ||
        !d->fext1 || !d->mdiag || !d->r || !d->dq || !d->tmp || !d->Cv || !d->S) {
        gal_error(GAL_ENOMEM, "dynamics: out of memory");
        return gal_dyn_free(d);
    }
    d->chol = gal_chol_alloc(rod->K);
    if (!d->chol) return gal_dyn_free(d);
    memcpy(d->q, q0, bq);
    if (v0) memcpy(d->v, v0, bq);
    for (int k = 0; k < nq; k++)
        if (rod->dof[k] < 0) d->v[k] = 0;
    gal_rod_mass_diag(rod, d->mdiag);
    if (d->o.damping && d->o.damping->ndof != n) {
        gal_error(GAL_EINPUT, "dynamics: the damping has %d dofs, the rod %d", d->o.damping->ndof, n);
        return gal_dyn_free(d);
    }
    if (gal_rod_eval(rod, q0, NULL, d->fint0, NULL) != GAL_OK) return gal_dyn_free(d);
    if (external(d, 0.0, d->q, d->v, d->fext0) != GAL_OK) return gal_dyn_free(d);
    /* M a0 = F0 - g(q0) - C v0 */
    gal_rod_gather(rod, d->v, d->dq);
    damping_force(d, d->dq, d->Cv);
    for (int j = 0; j < n; j++) {
        int k = rod->free_q[j];
        d->dq[j] = d->fext0[k] - d->fint0[k] - d->Cv[j];
    }
    if (gal_chol_factor(d->chol, rod->M, 0, NULL) != GAL_OK || gal_chol_solve(d->chol, d->dq, d->tmp) != GAL_OK) {
        gal_error(GAL_EFAIL, "dynamics: the mass matrix is not positive definite");
        return gal_dyn_free(d);
    }
    for (int j = 0; j < n; j++) d->a[rod->free_q[j]] = d->tmp[j];
    d->energy0 = gal_dyn_energy(d);
    return d;
}

double gal_dyn_energy(const gal_dyn *d)
{
    double U = 0, T = 0;
    gal_rod_eval(d->rod, d->q, &U, NULL, NULL);
    int n = d->rod->ndof;
    double *vf = malloc((size_t)2 * n * sizeof(double));
    if (!vf) return NAN;
    gal_rod_gather(d->rod, d->v, vf);
    gal_rod_mass_mult(d->rod, vf, vf + n);
    for (int j = 0; j < n; j++) T += 0.5 * vf[j] * vf[n + j];
    free(vf);
    return T + U;
}

/* The predictor (constant acceleration) of a step of size h. */
static void predict(gal_dyn *d, double h)
{
    const gal_rod *rod = d->rod;
    int n = rod->ndof, nq = rod->nq;
    double be = d->beta;
    memcpy(d->q1, d->q, (size_t)nq * sizeof(double));
    memcpy(d->a1, d->a, (size_t)nq * sizeof(double));
    for (int j = 0; j < n; j++) {
        int k = rod->free_q[j];
        d->q1[k] = d->q[k] + h * d->v[k] + h * h * ((0.5 - be) * d->a[k] + be * d->a1[k]);
    }
}

/* The convergence test's force tolerance for a step of size h at the relative tolerance rel, N:
 * rel times the step's force scale (the largest elastic + load entry at its start, at least the
 * weight of one node), not below the round-off floors. */
static void force_tolerance(const gal_dyn *d, double h, double rel, double rel_strict, double *tol,
                            double *strict)
{
    const gal_rod *rod = d->rod;
    int n = rod->ndof;
    double scale = 0, qm = 0;
    /* the maxima of nonnegative entries by comparison: fmax's value (a NaN entry passed over as fmax
     * does) without its call */
    for (int j = 0; j < n; j++) {
        double f = fabs(d->fint0[rod->free_q[j]]) + fabs(d->fext0[rod->free_q[j]]);
        /* a force scale for the convergence test: the weight of one node at least */
        double w = d->mdiag[j] * 9.81;
        /* the round-off of the inertia term (1-am) M (q1 - q0 - h v0) / (beta h^2): q1 known to
         * eps |q|, times the mass over beta h^2 (it grows as 1/h^2: at h = 1e-4 s it passes the
         * relative tolerance on a 200 m span) */
        double m = fabs(d->q[rod->free_q[j]]) * d->mdiag[j];
        if (f > scale) scale = f;
        if (w > scale) scale = w;
        if (m > qm) qm = m;
    }
    /* not below the round-off of the elastic forces: positions known to eps L, times the axial
     * stiffness of an element EA / l0 */
    double elastic = 20 * DBL_EPSILON * fmax(rod->p.length, fabs(rod->p.height_difference)) * rod->p.EA / rod->l0[0];
    double inertia = 20 * DBL_EPSILON * qm * (1 - d->am) / (d->beta * h * h);
    double floor = fmax(elastic, inertia);
    *tol = fmax(rel * scale, floor);
    *strict = fmax(rel_strict * scale, floor);
}

/* The residual R at the iterate q1 of a step of size h into d->r (a1, v1, the elastic forces
 * fint1, the loads fext1 and, when K is not NULL, the tangent into K evaluated on the way); its
 * max norm in *rn. */
static int residual(gal_dyn *d, double h, double t1, gal_csc *K, double *rn)
{
    const gal_rod *rod = d->rod;
    int n = rod->ndof, st;
    double am = d->am, af = d->af, be = d->beta, ga = d->gamma;
    /* a1, v1 from q1 */
    for (int j = 0; j < n; j++) {
        int k = rod->free_q[j];
        d->a1[k] = (d->q1[k] - d->q[k] - h * d->v[k]) / (be * h * h) - (0.5 - be) / be * d->a[k];
        d->v1[k] = d->v[k] + h * ((1 - ga) * d->a[k] + ga * d->a1[k]);
    }
    if ((st = gal_rod_eval(rod, d->q1, NULL, d->fint1, K))) return st;
    if ((st = external(d, t1, d->q1, d->v1, d->fext1))) return st;
    /* v_f = (1-af) v1 + af v0 over the free dofs (dq is scratch until the solve), and C v_f */
    for (int j = 0; j < n; j++) {
        int k = rod->free_q[j];
        d->dq[j] = (1 - af) * d->v1[k] + af * d->v[k];
    }
    damping_force(d, d->dq, d->Cv);
    /* M a_m */
    for (int j = 0; j < n; j++) {
        int k = rod->free_q[j];
        d->dq[j] = (1 - am) * d->a1[k] + am * d->a[k];
    }
    gal_rod_mass_mult(rod, d->dq, d->tmp);
    *rn = 0;
    for (int j = 0; j < n; j++) {
        int k = rod->free_q[j];
        d->r[j] = d->tmp[j] + d->Cv[j] + (1 - af) * d->fint1[k] + af * d->fint0[k] -
                  (1 - af) * d->fext1[k] - af * d->fext0[k];
        *rn = fmax(*rn, fabs(d->r[j]));
    }
    return GAL_OK;
}

/* The term of the residual that is not finite. */
static const char *bad_term(const gal_dyn *d)
{
    const gal_rod *rod = d->rod;
    for (int j = 0; j < rod->ndof; j++) {
        int k = rod->free_q[j];
        if (!isfinite(d->fext1[k])) return "aerodynamic load";
        if (!isfinite(d->fint1[k])) return "elastic force";
        if (!isfinite(d->Cv[j])) return "damping force";
    }
    return "inertia";
}

/* Accept the converged iterate: (q, v, a) = (q1, v1, a1), the forces of the new step kept. */
static void accept(gal_dyn *d, double t1)
{
    size_t bq = (size_t)d->rod->nq * sizeof(double);
    memcpy(d->q, d->q1, bq);
    memcpy(d->v, d->v1, bq);
    memcpy(d->a, d->a1, bq);
    double *sw = d->fint0; d->fint0 = d->fint1; d->fint1 = sw;
    sw = d->fext0; d->fext0 = d->fext1; d->fext1 = sw;
    d->t = t1;
}

/* S = cm M + cc C + (1-af) K(q1) with K(q1) in S on entry (C: Rayleigh only, see the top). */
static void iteration_matrix(gal_dyn *d, double cm, double cc)
{
    const gal_damping *c = d->o.damping;
    double ca = 0, cb = 0, af = d->af;
    const double *k0 = NULL, *mv = d->rod->M->val;
    if (c && c->kind == GAL_DAMPING_RAYLEIGH) ca = cc * c->alpha, cb = cc * c->beta, k0 = c->K0->val;
    double *sv = d->S->val;
    if (k0)
        for (int p = 0; p < d->S->nnz; p++) sv[p] = (1 - af) * sv[p] + cb * k0[p] + (cm + ca) * mv[p];
    else
        for (int p = 0; p < d->S->nnz; p++) sv[p] = (1 - af) * sv[p] + cm * mv[p];
}

/* Factor the iteration matrix at the iterate whose tangent is in d->S, for steps of size h. */
static int refactor(gal_dyn *d, double h, double t1)
{
    double cm = (1 - d->am) / (d->beta * h * h), cc = (1 - d->af) * d->gamma / (d->beta * h);
    iteration_matrix(d, cm, cc);
    d->factorizations++;
    d->factor_h = 0;
    if (gal_chol_factor(d->chol, d->S, 0, NULL))
        return gal_error(GAL_EFAIL, "dynamics: the iteration matrix is not positive definite at t = %.6g s", t1);
    d->factor_h = h;
    return GAL_OK;
}

/* One step of size h from the current state; on failure the state is unchanged. Modified Newton:
 * the factorization of an earlier iterate (or step) is kept while the residual falls by at least
 * GAL_DYN_RATE per iteration; when it falls slower, the tangent is evaluated at the iterate and
 * factored again (and always when h changes). Converged after a correction whose residual is
 * within GAL_NEWTON_TOL_STRICT (or a tighter newton_tol); with a looser newton_tol, within it only
 * when that correction reduced the residual: a growing (diverging) iteration is not accepted, it
 * goes on to fail and the step is halved. */
static int try_step(gal_dyn *d, double h)
{
    const gal_rod *rod = d->rod;
    int n = rod->ndof, st;
    double t1 = d->t + h, rprev = INFINITY, tol, strict;
    force_tolerance(d, h, d->o.newton_tol, fmin(d->o.newton_tol, GAL_NEWTON_TOL_STRICT), &tol, &strict);
    predict(d, h);
    for (int it = 0; it < d->o.max_newton; it++) {
        double rn;
        int fresh = d->factor_h != h; /* no factorization for this h: the tangent here */
        if ((st = residual(d, h, t1, fresh ? d->S : NULL, &rn))) return st;
        if (!isfinite(rn))
            return gal_error(GAL_EFAIL, "dynamics: the residual is not finite at t = %.6g s (step %ld, "
                             "Newton iteration %d): the %s", t1, d->steps + 1, it, bad_term(d));
        d->newton_iterations++;
        if (it > 0 && (rn <= strict || (rn <= tol && rn < rprev))) {
            accept(d, t1);
            return GAL_OK;
        }
        if (!fresh && rn > GAL_DYN_RATE * rprev) { /* converging slowly: the tangent at this iterate */
            if ((st = gal_rod_eval(rod, d->q1, NULL, NULL, d->S))) return st;
            fresh = 1;
        }
        if (fresh && (st = refactor(d, h, t1))) return st;
        rprev = rn;
        if ((st = gal_chol_solve(d->chol, d->r, d->dq))) return st;
        for (int j = 0; j < n; j++) d->q1[rod->free_q[j]] -= d->dq[j];
    }
    return gal_error(GAL_EFAIL, "dynamics: Newton did not converge in %d iterations at t = %.6g s (step %ld)",
                     d->o.max_newton, t1, d->steps + 1);
}

static int try_step_cb(void *ctx, double hh)
{
    return try_step(ctx, hh);
}

int gal_dyn_step(gal_dyn *d)
{
    int st = gal_dyn_subdivide(try_step_cb, d, d->o.h, d->o.max_halvings, &d->rejected_steps, &d->t, "dynamics");
    if (st == GAL_OK) d->steps++;
    return st;
}

int gal_dyn_subdivide(int (*try_step)(void *ctx, double hh), void *ctx, double h, int max_halvings,
                      long *rejected, const double *t, const char *who)
{
    double step = h, done = 0;
    int halvings = 0;
    while (done < h * (1 - 1e-12)) {
        double hh = fmin(step, h - done);
        int st = try_step(ctx, hh);
        if (st == GAL_OK) {
            done += hh;
            continue;
        }
        if (st == GAL_ENOMEM) return st;
        (*rejected)++;
        if (++halvings > max_halvings)
            return gal_error(GAL_EFAIL, "%s: step failed at t = %.6g s after %d halvings of the time step (h = %.3g s): %s",
                             who, *t, max_halvings, hh, gal_error_message());
        step = 0.5 * hh;
    }
    return GAL_OK;
}
