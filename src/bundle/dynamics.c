/* dynamics.c: generalized-alpha integration of the explicit bundle (bundle_dyn.h) with modified
 * Newton on the assembled tangent, the scheme of src/full/dynamics.c over the system's dofs z:
 *   R = M(s1) a_m + C v_f + (1-af) g(s1) + af g(s0) - (1-af) F1 - af F0,
 *   dz = h v0 + h^2 ((1/2 - beta) a0 + beta a1),  s1 = s0 (+) dz,  v1 = v0 + h ((1-gamma) a0 + gamma a1),
 * Jacobian in dz: (1-am)/(beta h^2) M + (1-af) gamma/(beta h) C + (1-af) K(s1) (the loads' dependence
 * on the state left out: it changes the convergence rate, not the solution). */
#include "gallop/bundle/bundle_dyn.h"
#include "gallop/base/core.h"
#include "bundle_impl.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/chol.h"
#include "gallop/full/dynamics.h"

void gal_bundle_dyn_default_opts(gal_bundle_dyn_opts *o)
{
    memset(o, 0, sizeof *o);
    o->h = 0.01;
    o->rho_inf = 1.0;
    o->newton_tol = 1e-8;
    o->max_newton = 20;
    o->max_halvings = 6;
}

gal_bundle_dyn *gal_bundle_dyn_free(gal_bundle_dyn *d)
{
    if (!d) return NULL;
    free(d->s), free(d->s1), free(d->v), free(d->a), free(d->v1), free(d->a1), free(d->dz);
    gal_csc_free(d->S), gal_csc_free(d->K0), gal_csc_free(d->M0);
    gal_chol_free(d->chol);
    free(d->g0), free(d->g1), free(d->f0), free(d->f1), free(d->r), free(d->dx), free(d->tmp), free(d->Cv);
    free(d->wrk);
    free(d);
    return NULL;
}

void gal_bundle_mass_mult(const gal_bundle *b, const double *s, const double *x, double *y, double *wrk)
{
    memset(y, 0, (size_t)b->ndof * sizeof(double));
    for (int r = 0; r < b->n; r++) {
        int nd = b->rod[r]->ndof;
        gal_bundle_map(b, r, x, wrk);
        gal_rod_mass_mult(b->rod[r], wrk, wrk + nd);
        gal_bundle_map_add_t(b, r, wrk + nd, y);
    }
    double m = b->bp.spacer_mass, J = b->bp.spacer_inertia, Jb[3] = {J, 0.5 * J, 0.5 * J};
    for (int sp = 0; sp < b->ns; sp++) {
        int u = b->sp0 + (3 + b->nrot) * sp;
        for (int k = 0; k < 3; k++) y[u + k] += m * x[u + k];
        if (J == 0) continue;
        const double *R = SP_R(b, s, sp);
        double E[3][3], w[3] = {0, 0, 0}, bw[3], hw[3];
        int nr = gal_bundle_basis(b, s, sp, E);
        for (int j = 0; j < nr; j++)
            for (int k = 0; k < 3; k++) w[k] += x[u + 3 + j] * E[j][k];
        for (int l = 0; l < 3; l++) bw[l] = Jb[l] * (R[l] * w[0] + R[3 + l] * w[1] + R[6 + l] * w[2]);
        for (int k = 0; k < 3; k++) hw[k] = R[3 * k] * bw[0] + R[3 * k + 1] * bw[1] + R[3 * k + 2] * bw[2];
        for (int j = 0; j < nr; j++) y[u + 3 + j] += E[j][0] * hw[0] + E[j][1] * hw[1] + E[j][2] * hw[2];
    }
}

static int external(gal_bundle_dyn *d, double t, const double *s, const double *v, double *f)
{
    memset(f, 0, (size_t)d->b->ndof * sizeof(double));
    if (!d->force.eval) return GAL_OK;
    d->force_evaluations++;
    return d->force.eval(d->force.ctx, d->b, t, s, v, f);
}

/* Cv = C v: modal, or (alpha M0 + beta K0) v */
static void damping_force(gal_bundle_dyn *d, const double *v, double *Cv)
{
    int n = d->b->ndof;
    memset(Cv, 0, (size_t)n * sizeof(double));
    if (d->o.damping) {
        gal_damping_apply(d->o.damping, v, Cv);
        return;
    }
    if (d->o.alpha == 0 && d->o.beta == 0) return;
    gal_csc_symv(d->M0, v, d->tmp);
    for (int j = 0; j < n; j++) Cv[j] = d->o.alpha * d->tmp[j];
    gal_csc_symv(d->K0, v, d->tmp);
    for (int j = 0; j < n; j++) Cv[j] += d->o.beta * d->tmp[j];
}

static int alloc_arrays(gal_bundle_dyn *d)
{
    const gal_bundle *b = d->b;
    size_t bs = (size_t)b->nstate * sizeof(double), bn = (size_t)b->ndof * sizeof(double);
    d->s = malloc(bs), d->s1 = malloc(bs);
    d->v = calloc(1, bn), d->a = calloc(1, bn), d->v1 = calloc(1, bn), d->a1 = calloc(1, bn), d->dz = calloc(1, bn);
    d->g0 = malloc(bn), d->g1 = malloc(bn), d->f0 = malloc(bn), d->f1 = malloc(bn), d->r = malloc(bn);
    d->dx = malloc(bn), d->tmp = malloc(bn), d->Cv = malloc(bn);
    d->wrk = malloc((size_t)2 * b->rod[0]->nq * sizeof(double));
    d->S = gal_csc_clone(b->K), d->K0 = gal_csc_clone(b->K), d->M0 = gal_csc_clone(b->M);
    if (!d->s || !d->s1 || !d->v || !d->a || !d->v1 || !d->a1 || !d->dz || !d->g0 || !d->g1 || !d->f0 || !d->f1 ||
        !d->r || !d->dx || !d->tmp || !d->Cv || !d->wrk || !d->S || !d->K0 || !d->M0)
        return gal_error(GAL_ENOMEM, "bundle dynamics: out of memory for %d dofs", b->ndof);
    d->chol = gal_chol_alloc(b->K);
    return d->chol ? GAL_OK : GAL_ENOMEM;
}

/* a0 from M a0 = F0 - g(s0) - C v0 */
static int initial_acceleration(gal_bundle_dyn *d)
{
    gal_bundle *b = d->b;
    int n = b->ndof, st;
    if ((st = gal_bundle_eval(b, d->s, NULL, 1))) return st;
    memcpy(d->g0, b->grad, (size_t)n * sizeof(double));
    if ((st = external(d, 0.0, d->s, d->v, d->f0))) return st;
    damping_force(d, d->v, d->Cv);
    for (int j = 0; j < n; j++) d->dx[j] = d->f0[j] - d->g0[j] - d->Cv[j];
    if (gal_chol_factor(d->chol, b->M, 0, NULL) != GAL_OK || gal_chol_solve(d->chol, d->dx, d->a) != GAL_OK)
        return gal_error(GAL_EFAIL, "bundle dynamics: the mass matrix is not positive definite");
    return GAL_OK;
}

gal_bundle_dyn *gal_bundle_dyn_alloc(gal_bundle *b, const double *s0, const double *v0,
                                     const gal_bundle_dyn_opts *o, const gal_bundle_force *force)
{
    gal_bundle_dyn *d = calloc(1, sizeof *d);
    if (!d) return NULL;
    d->b = b;
    if (o) d->o = *o;
    else gal_bundle_dyn_default_opts(&d->o);
    if (force) d->force = *force;
    double rho = d->o.rho_inf;
    if (d->o.damping) d->o.alpha = d->o.beta = 0; /* the modal damping in their place */
    if (d->o.damping && d->o.damping->ndof != b->ndof) {
        gal_error(GAL_EINPUT, "bundle dynamics: the damping has %d dofs, the bundle %d", d->o.damping->ndof, b->ndof);
        return gal_bundle_dyn_free(d);
    }
    if (!(rho >= 0 && rho <= 1) || !(d->o.h > 0) || !(d->o.alpha >= 0) || !(d->o.beta >= 0)) {
        gal_error(GAL_EINPUT, "bundle dynamics: time step %g s, rho_inf %g, Rayleigh %g, %g; allowed: h > 0, "
                  "0 <= rho_inf <= 1, alpha, beta >= 0", d->o.h, rho, d->o.alpha, d->o.beta);
        return gal_bundle_dyn_free(d);
    }
    d->am = (2 * rho - 1) / (rho + 1);
    d->af = rho / (rho + 1);
    d->gamma = 0.5 - d->am + d->af;
    d->beta = 0.25 * (1 - d->am + d->af) * (1 - d->am + d->af);
    if (gal_bundle_eval(b, NULL, NULL, 1) || alloc_arrays(d)) return gal_bundle_dyn_free(d);
    memcpy(d->K0->val, b->K->val, (size_t)b->K->nnz * sizeof(double)); /* at the equilibrium */
    memcpy(d->M0->val, b->M->val, (size_t)b->M->nnz * sizeof(double));
    memcpy(d->s, s0 ? s0 : b->state, (size_t)b->nstate * sizeof(double));
    if (v0) memcpy(d->v, v0, (size_t)b->ndof * sizeof(double));
    if (initial_acceleration(d)) return gal_bundle_dyn_free(d);
    d->energy0 = gal_bundle_dyn_energy(d);
    return d;
}

double gal_bundle_dyn_energy(gal_bundle_dyn *d)
{
    gal_bundle *b = d->b;
    double U = 0, T = 0;
    if (gal_bundle_eval(b, d->s, &U, 0)) return NAN;
    gal_bundle_mass_mult(b, d->s, d->v, d->tmp, d->wrk);
    for (int j = 0; j < b->ndof; j++) T += 0.5 * d->v[j] * d->tmp[j];
    return T + U;
}

/* The convergence test's force tolerance at the relative tolerance rel (as src/full/dynamics.c: the
 * forces' scale, at least a node's weight, not below the round-off of the elastic and inertia terms). */
static double force_tolerance(const gal_bundle_dyn *d, double h, double rel)
{
    const gal_bundle *b = d->b;
    const gal_rod *rod = b->rod[0];
    double scale = 0, mmax = 0, qm = 0;
    for (int j = 0; j < b->ndof; j++) {
        scale = fmax(scale, fabs(d->g0[j]) + fabs(d->f0[j]));
        mmax = fmax(mmax, d->M0->val[d->M0->diag[j]]);
    }
    scale = fmax(scale, mmax * 9.81);
    for (int k = 0; k < 3 * b->nn; k++) qm = fmax(qm, fabs(d->s[k]));
    double kmax = fmax(rod->p.EA / rod->l0[0], b->bp.spacer_stiffness); /* flexible spacers' arms too */
    double elastic = 20 * DBL_EPSILON * fmax(rod->p.length, fabs(rod->p.height_difference)) * kmax;
    double inertia = 20 * DBL_EPSILON * qm * mmax * (1 - d->am) / (d->beta * h * h);
    return fmax(rel * scale, fmax(elastic, inertia));
}

/* The residual at the increment d->dz of a step of size h into d->r; the tangent into b->K, b->M
 * when asked. */
static int residual(gal_bundle_dyn *d, double h, double t1, int tangent, double *rn)
{
    gal_bundle *b = d->b;
    int n = b->ndof, st;
    double am = d->am, af = d->af, be = d->beta, ga = d->gamma;
    for (int j = 0; j < n; j++) {
        d->a1[j] = (d->dz[j] - h * d->v[j]) / (be * h * h) - (0.5 - be) / be * d->a[j];
        d->v1[j] = d->v[j] + h * ((1 - ga) * d->a[j] + ga * d->a1[j]);
    }
    gal_bundle_step(b, d->s, d->dz, 1.0, d->s1);
    if ((st = gal_bundle_eval(b, d->s1, NULL, tangent))) return st;
    memcpy(d->g1, b->grad, (size_t)n * sizeof(double));
    if ((st = external(d, t1, d->s1, d->v1, d->f1))) return st;
    for (int j = 0; j < n; j++) d->dx[j] = (1 - af) * d->v1[j] + af * d->v[j];
    damping_force(d, d->dx, d->Cv);
    for (int j = 0; j < n; j++) d->dx[j] = (1 - am) * d->a1[j] + am * d->a[j];
    gal_bundle_mass_mult(b, d->s1, d->dx, d->r, d->wrk);
    *rn = 0;
    for (int j = 0; j < n; j++) {
        d->r[j] += d->Cv[j] + (1 - af) * d->g1[j] + af * d->g0[j] - (1 - af) * d->f1[j] - af * d->f0[j];
        *rn = fmax(*rn, fabs(d->r[j]));
    }
    return GAL_OK;
}

/* S = (1-af) K + cm M + cc C from the tangent in b->K, b->M (C: Rayleigh only; the modal damping is
 * left out, as the single rod's); factored. */
static int refactor(gal_bundle_dyn *d, double h, double t1)
{
    const gal_bundle *b = d->b;
    double cm = (1 - d->am) / (d->beta * h * h), cc = (1 - d->af) * d->gamma / (d->beta * h);
    double ca = cc * d->o.alpha, cb = cc * d->o.beta, af = d->af;
    for (int p = 0; p < d->S->nnz; p++)
        d->S->val[p] = (1 - af) * b->K->val[p] + cm * b->M->val[p] + ca * d->M0->val[p] + cb * d->K0->val[p];
    d->factorizations++;
    d->factor_h = 0;
    if (gal_chol_factor(d->chol, d->S, 0, NULL))
        return gal_error(GAL_EFAIL, "bundle dynamics: the iteration matrix is not positive definite at t = %.6g s", t1);
    d->factor_h = h;
    return GAL_OK;
}

static void accept(gal_bundle_dyn *d, double t1)
{
    const gal_bundle *b = d->b;
    size_t bn = (size_t)b->ndof * sizeof(double);
    memcpy(d->s, d->s1, (size_t)b->nstate * sizeof(double));
    memcpy(d->v, d->v1, bn), memcpy(d->a, d->a1, bn);
    double *sw = d->g0; d->g0 = d->g1; d->g1 = sw;
    sw = d->f0; d->f0 = d->f1; d->f1 = sw;
    d->t = t1;
}

/* One step of size h (the state unchanged on failure): modified Newton as src/full/dynamics.c,
 * with its test: converged after a correction within GAL_NEWTON_TOL_STRICT (or a tighter
 * newton_tol), or within a looser newton_tol when that correction reduced the residual. */
static int try_step(gal_bundle_dyn *d, double h)
{
    gal_bundle *b = d->b;
    int n = b->ndof, st;
    double t1 = d->t + h, tol = force_tolerance(d, h, d->o.newton_tol), rprev = INFINITY;
    double strict = force_tolerance(d, h, fmin(d->o.newton_tol, GAL_NEWTON_TOL_STRICT));
    for (int j = 0; j < n; j++) d->dz[j] = h * d->v[j] + 0.5 * h * h * d->a[j]; /* a1 = a0 */
    for (int it = 0; it < d->o.max_newton; it++) {
        double rn;
        int fresh = d->factor_h != h;
        if ((st = residual(d, h, t1, fresh, &rn))) return st;
        if (!isfinite(rn))
            return gal_error(GAL_EFAIL, "bundle dynamics: the residual is not finite at t = %.6g s (step %ld, Newton "
                             "iteration %d)", t1, d->steps + 1, it);
        d->newton_iterations++;
        if (it > 0 && (rn <= strict || (rn <= tol && rn < rprev))) {
            accept(d, t1);
            return GAL_OK;
        }
        if (!fresh && rn > GAL_DYN_RATE * rprev) {
            if ((st = gal_bundle_eval(b, d->s1, NULL, 1))) return st;
            fresh = 1;
        }
        if (fresh && (st = refactor(d, h, t1))) return st;
        rprev = rn;
        if ((st = gal_chol_solve(d->chol, d->r, d->dx))) return st;
        for (int j = 0; j < n; j++) d->dz[j] -= d->dx[j];
    }
    return gal_error(GAL_EFAIL, "bundle dynamics: Newton did not converge in %d iterations at t = %.6g s (step %ld)",
                     d->o.max_newton, t1, d->steps + 1);
}

static int try_step_cb(void *ctx, double hh)
{
    return try_step(ctx, hh);
}

int gal_bundle_dyn_step(gal_bundle_dyn *d)
{
    int st = gal_dyn_subdivide(try_step_cb, d, d->o.h, d->o.max_halvings, &d->rejected_steps, &d->t, "bundle dynamics");
    if (st == GAL_OK) d->steps++;
    return st;
}
