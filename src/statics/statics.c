/* statics.c: sagged equilibrium of the rod (paper Eq. 9 with no motion: grad U = 0) by Newton's
 * method from the elastic catenary, with an outer secant iteration on the unstretched length
 * when the span is specified by its horizontal tension or sag. */
#include "gallop/statics/statics.h"
#include "gallop/base/core.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/chol.h"


void gal_statics_default_opts(gal_statics_opts *o)
{
    o->force_tol = 1e-10;
    o->max_newton = 50;
    o->max_length_iter = 30;
}

void gal_equilibrium_clear(gal_equilibrium *eq)
{
    gal_tangent_free(eq->tangent);
    gal_tangent_free(eq->k0);
    gal_rod_free(eq->rod);
    free(eq->q);
    memset(eq, 0, sizeof *eq);
}

double gal_rod_sag(const gal_rod *rod, const double *q)
{
    double L = rod->p.length, h = rod->p.height_difference;
    int nn = rod->nn, i = 1;
    while (i < nn - 2 && q[3 * (i + 1)] < 0.5 * L) i++;
    /* quadratic through nodes i-1, i, i+1 (Lagrange form in x) */
    double x0 = q[3 * (i - 1)], x1 = q[3 * i], x2 = q[3 * (i + 1)];
    double z0 = q[3 * (i - 1) + 2], z1 = q[3 * i + 2], z2 = q[3 * (i + 1) + 2], x = 0.5 * L;
    double z = z0 * (x - x1) * (x - x2) / ((x0 - x1) * (x0 - x2)) +
               z1 * (x - x0) * (x - x2) / ((x1 - x0) * (x1 - x2)) +
               z2 * (x - x0) * (x - x1) / ((x2 - x0) * (x2 - x1));
    return 0.5 * h - z;
}

/* The Newton workspace of one solve: the stage owns its tangent and factorization (the rod's own
 * pattern is only copied). */
typedef struct {
    const gal_rod *rod;   /* the rod evaluated: the working rod, or a view of it with a softer
                           * bending stiffness while load stepping */
    gal_csc *K;           /* the tangent stiffness (values) */
    gal_chol *chol;
    double *g, *gt, *r, *d, *qt, *mdiag;
    double ftol;
    double xtol;          /* m, or 0: also stop only once a Newton step has moved no node by more
                           * than this (a sag specification: see solve_length) */
    int descent;          /* 1: shift every indefinite tangent (a descent direction, towards a
                           * minimum of the energy); 0: Newton on the tangent as it is */
    const double *fext;   /* configuration-sized dead load, or NULL */
} newton_ws;

static void ws_free(newton_ws *w)
{
    gal_chol_free(w->chol);
    gal_csc_free(w->K);
    free(w->g); free(w->gt); free(w->qt); free(w->r); free(w->d); free(w->mdiag);
}

static int ws_alloc(newton_ws *w, const gal_rod *rod)
{
    int n = rod->ndof, nq = rod->nq;
    memset(w, 0, sizeof *w);
    w->rod = rod;
    w->K = gal_csc_clone(rod->K);
    w->chol = w->K ? gal_chol_alloc(w->K) : NULL;
    w->g = malloc((size_t)nq * sizeof(double)), w->gt = malloc((size_t)nq * sizeof(double));
    w->qt = malloc((size_t)nq * sizeof(double)), w->r = malloc((size_t)n * sizeof(double));
    w->d = malloc((size_t)n * sizeof(double)), w->mdiag = malloc((size_t)n * sizeof(double));
    if (!w->K || !w->chol || !w->g || !w->gt || !w->qt || !w->r || !w->d || !w->mdiag) {
        ws_free(w);
        return gal_error(GAL_ENOMEM, "statics: out of memory for %d elements", rod->p.elements);
    }
    return GAL_OK;
}

/* Total potential U(q) - fext . q and its gradient (the load is dead: it does not follow q). */
static int eval_total(newton_ws *w, const double *q, double *U, double *g, gal_csc *K)
{
    int st = gal_rod_eval(w->rod, q, U, g, K);
    if (st || !w->fext) return st;
    for (int j = 0; j < w->rod->ndof; j++) {
        int k = w->rod->free_q[j];
        if (U) *U -= w->fext[k] * q[k];
        if (g) g[k] -= w->fext[k];
    }
    return GAL_OK;
}

static double inf_norm_free(const gal_rod *rod, const double *g)
{
    double m = 0;
    for (int k = 0; k < rod->ndof; k++) m = fmax(m, fabs(g[rod->free_q[k]]));
    return m;
}

/* Factor K, with a growing shift K + mu M where it is not positive definite (in descent mode,
 * also where the factorization succeeds with negative pivots). */
static int factor_shifted(newton_ws *w, int it)
{
    const gal_rod *rod = w->rod;
    gal_rod_mass_diag(rod, w->mdiag);
    double kmax = 0;
    for (int j = 0; j < rod->ndof; j++) kmax = fmax(kmax, w->K->val[w->K->diag[j]] / w->mdiag[j]);
    double mu = 0;
    int max_tries = w->descent ? 40 : 8;
    for (int tries = 0; ; tries++) {
        int st = gal_chol_factor(w->chol, w->K, mu, w->mdiag);
        if (st == GAL_ENOMEM) return st; /* memory is memory, not an indefinite tangent */
        if (st == GAL_OK && !(w->descent && w->chol->negative_pivots)) return GAL_OK;
        if (tries >= max_tries) return gal_error(GAL_EFAIL, "statics: the tangent stiffness stays indefinite at Newton iteration %d", it);
        /* descent: small factors, the shift just above the most negative curvature */
        mu = mu == 0 ? (w->descent ? 1e-14 : 1e-8) * kmax : mu * (w->descent ? 4 : 100);
    }
}

/* Newton with line search on the energy; q updated in place. */
static int newton(newton_ws *w, double *q, int max_iter, int *iters, double *res)
{
    const gal_rod *rod = w->rod;
    int n = rod->ndof, nq = rod->nq;
    double U, step = 0; /* the last step's largest node displacement */
    int st = eval_total(w, q, &U, w->g, w->K);
    if (st) return st;
    for (int it = 0; ; it++) {
        double rn = inf_norm_free(rod, w->g);
        *res = rn;
        if (!isfinite(rn)) return gal_error(GAL_EFAIL, "statics: the residual force is not finite (Newton iteration %d)", it);
        if (rn <= w->ftol && (w->xtol == 0 || (it > 0 && step <= w->xtol))) { *iters += it; return GAL_OK; }
        if (it >= max_iter) {
            *iters += it;
            return gal_error(GAL_EFAIL, "statics: Newton did not converge in %d iterations (residual %.3g N, tolerance %.3g N)",
                             max_iter, rn, w->ftol);
        }
        if ((st = factor_shifted(w, it))) return st;
        gal_rod_gather(rod, w->g, w->r);
        if ((st = gal_chol_solve(w->chol, w->r, w->d))) return st;
        double slope = 0;
        for (int j = 0; j < n; j++) w->d[j] = -w->d[j], slope += w->r[j] * w->d[j];
        /* backtracking: Armijo on U, or a smaller residual (near convergence U stalls in
         * round-off); none when the force test already passes (only a step test keeps Newton
         * going, and both U and the residual are then round-off: the full step is the answer) */
        double a = 1.0, Ut = 0;
        int accepted = 0;
        for (int ls = 0; ls < 40; ls++, a *= 0.5) {
            memcpy(w->qt, q, (size_t)nq * sizeof(double));
            for (int j = 0; j < n; j++) w->qt[rod->free_q[j]] += a * w->d[j];
            if (eval_total(w, w->qt, &Ut, w->gt, NULL) != GAL_OK) continue;
            if (rn <= w->ftol || Ut <= U + 1e-4 * a * slope || inf_norm_free(rod, w->gt) < rn) {
                accepted = 1;
                break;
            }
        }
        if (!accepted)
            return gal_error(GAL_EFAIL, "statics: the line search failed at Newton iteration %d (residual %.3g N)", it, rn);
        memcpy(q, w->qt, (size_t)nq * sizeof(double));
        step = 0;
        for (int j = 0; j < n; j++)
            if (rod->free_q[j] < 3 * rod->nn) step = fmax(step, fabs(a * w->d[j]));
        if ((st = eval_total(w, q, &U, w->g, w->K))) return st;
    }
}

int gal_statics_solve_loaded(const gal_rod *rod, double *q, const double *fext, double force_tol, int max_newton,
                            int *iterations)
{
    newton_ws w;
    int st = ws_alloc(&w, rod);
    if (st) return st;
    w.fext = fext, w.ftol = force_tol;
    double res;
    int it = 0;
    st = newton(&w, q, max_newton, &it, &res);
    if (iterations) *iterations += it;
    ws_free(&w);
    return st;
}

/* The elastic catenary of the specification and the working rod discretized on it (eq->rod at
 * the catenary's unstretched length, eq->q its start configuration). */
static int start(const gal_rod_params *p, gal_statics_spec spec, double value, gal_equilibrium *eq)
{
    gal_catenary *cat = &eq->cat;
    cat->L = p->length, cat->h = p->height_difference, cat->EA = p->EA;
    cat->w = p->mass * p->gravity;
    int st = gal_catenary_solve(cat, (int)spec, value);
    if (st) return st;
    gal_rod_params rp = *p;
    rp.unstretched_length = cat->L0;
    int nel = p->elements, nn = nel + 1;
    int nq = gal_rod_nq(p);
    double *q = calloc((size_t)nq, sizeof(double));
    if (!q) return gal_error(GAL_ENOMEM, "statics: out of memory");
    for (int i = 0; i < nn; i++) {
        double x, z;
        gal_catenary_point(cat, cat->L0 * i / nel, &x, &z, NULL);
        q[3 * i] = x, q[3 * i + 2] = z;
    }
    q[3 * nel] = p->length, q[3 * nel + 2] = p->height_difference; /* supports exactly */
    gal_rod *rod = gal_rod_alloc(&rp, q);
    if (!rod) { free(q); return gal_error_status() == GAL_ENOMEM ? GAL_ENOMEM : GAL_EINPUT; }
    eq->rod = rod, eq->q = q;
    return GAL_OK;
}

/* Equilibrium at the rod's unstretched length; on failure, continuation on the bending stiffness
 * from 0 (where the catenary start is nearly exact): the load-stepping state is a view of the
 * working rod with a scaled EI, the rod itself is not changed. */
static int solve_fixed_length(newton_ws *w, gal_equilibrium *eq, const gal_statics_opts *opts, double *qsave,
                              double *res)
{
    const gal_rod *rod = eq->rod;
    double *q = eq->q;
    size_t bq = (size_t)rod->nq * sizeof(double);
    memcpy(qsave, q, bq);
    int st = newton(w, q, opts->max_newton, &eq->newton_iterations, res);
    if (st == GAL_OK || !(rod->p.EI > 0)) return st;
    memcpy(q, qsave, bq);
    gal_rod soft = *rod;
    w->rod = &soft;
    double lam = 0, dl = 0.125;
    st = GAL_OK;
    while (lam < 1 && st == GAL_OK) {
        double next = fmin(1.0, lam + dl);
        soft.p.EI = next * rod->p.EI;
        memcpy(qsave, q, bq);
        int s2 = newton(w, q, opts->max_newton, &eq->newton_iterations, res);
        eq->load_steps++;
        if (s2 == GAL_OK) { lam = next; dl *= 2; }
        else {
            memcpy(q, qsave, bq);
            dl *= 0.25;
            if (dl < 1e-6) st = s2;
        }
        if (eq->load_steps > 200) st = gal_error(GAL_EFAIL, "statics: load stepping on the bending stiffness did not reach the full value (%.3g of it)", lam);
    }
    w->rod = rod;
    return st;
}

/* The measure that a tension or sag specification fixes, minus its target. */
static double spec_misfit(newton_ws *w, gal_statics_spec spec, double value, const double *q)
{
    gal_rod_eval(w->rod, q, NULL, w->g, NULL);
    return spec == GAL_BY_TENSION ? -w->g[0] - value : gal_rod_sag(w->rod, q) - value;
}

/* The outer iteration on L0 for a given H or sag: secant on f(L0) = measure - target, started with
 * the catenary's slope. The working rod's unstretched length is what this stage solves for.
 * Both measures are met to 1e-10 of the target (the sag: not below 1e-12 of the span). For the
 * sag that is about 100 times what the problem resolves: at one L0 the sag of the Newton iterates
 * at the force floor moves by ~1e-12 of itself, and one ulp of L0 moves it by eps L0 dsag/dL0
 * (4e-13 m on a 400-m span); tests/test_statics_sag.c and the sag-given spans of tests/rom/ at
 * 100-1000 elements meet it in 1-2 outer iterations. What makes that reachable on fine meshes:
 * - on a sag specification Newton also stops only once its last step moved no node by more than
 *   the sag tolerance (xtol). The force test alone cannot see a change of L0: one that moves the
 *   sag by 1e-6 of itself moves the free forces by less than the force floor (20 eps L EA / l,
 *   which grows with the elements), so at 350+ elements the nodes did not move, the sag read was
 *   the old one, and the iteration stalled ("sag off by 7.6e-06", issue 13). Newton converges
 *   quadratically, so a step below xtol leaves an error far below it. The horizontal tension
 *   needs no such test: the support reaction sees L0 through the first element at once, and it
 *   is met to the force floor it is read at.
 * - the secant slope is updated only from a difference well above the tolerance (10 tol), not
 *   from two measures that differ by their round-off. */
static int solve_length(newton_ws *w, gal_equilibrium *eq, gal_statics_spec spec, double value,
                        const gal_statics_opts *opts, double *res)
{
    gal_rod *rod = eq->rod;
    const gal_catenary *cat = &eq->cat;
    int st = GAL_OK;
    double tol = spec == GAL_BY_TENSION ? 1e-10 * value : fmax(1e-10 * value, 1e-12 * rod->p.length);
    w->xtol = spec == GAL_BY_SAG ? tol : 0; /* the start too: it was solved to the force test alone */
    if (w->xtol > 0 && (st = newton(w, eq->q, opts->max_newton, &eq->newton_iterations, res))) {
        w->xtol = 0;
        return st;
    }
    double L0a = rod->p.unstretched_length, fa = spec_misfit(w, spec, value, eq->q);
    /* slope from the catenary: d(measure)/dL0 */
    gal_catenary c2 = *cat;
    double dL = 1e-6 * cat->L0;
    gal_catenary_solve(&c2, GAL_BY_LENGTH, cat->L0 + dL);
    double slope = spec == GAL_BY_TENSION ? (c2.H - cat->H) / dL : (gal_catenary_sag(&c2) - gal_catenary_sag(cat)) / dL;
    while (fabs(fa) > tol) {
        if (eq->length_iterations++ >= opts->max_length_iter) {
            st = gal_error(GAL_EFAIL, "statics: the unstretched length iteration did not converge (%s off by %.3g)",
                           spec == GAL_BY_TENSION ? "horizontal tension" : "sag", fa);
            break;
        }
        double L0b = L0a - fa / slope;
        gal_rod_set_unstretched_length(rod, L0b);
        if ((st = newton(w, eq->q, opts->max_newton, &eq->newton_iterations, res))) break;
        double fb = spec_misfit(w, spec, value, eq->q);
        if (fabs(fb - fa) > 10 * tol) slope = (fb - fa) / (L0b - L0a);
        L0a = L0b, fa = fb;
    }
    w->xtol = 0;
    if (st) return st;
    return GAL_OK;
}

/* Stability: the tangent at the equilibrium must be positive definite (a free twist end leaves one
 * neutral rotation, allowed for by a tiny shift). Leaves the forces at q in w->g. */
static int check_stable(newton_ws *w, const double *q)
{
    const gal_rod *rod = w->rod;
    gal_rod_eval(rod, q, NULL, w->g, w->K);
    gal_rod_mass_diag(rod, w->mdiag);
    double kmax = 0;
    for (int j = 0; j < rod->ndof; j++) kmax = fmax(kmax, w->K->val[w->K->diag[j]] / w->mdiag[j]);
    double shift = (rod->p.torsion && !rod->p.twist_clamped) ? 1e-12 * kmax : 0;
    if (gal_chol_factor(w->chol, w->K, shift, w->mdiag) != GAL_OK)
        return gal_error(GAL_EFAIL, "statics: the equilibrium found is not stable: %s", gal_error_message());
    if (w->chol->negative_pivots)
        return gal_error(GAL_EFAIL, "statics: the equilibrium found is not stable: the tangent stiffness has "
                         "%d negative eigenvalue%s", w->chol->negative_pivots, w->chol->negative_pivots > 1 ? "s" : "");
    return GAL_OK;
}

/* Eccentric ice above the axis (an inverted pendulum) can make the untwisted equilibrium unstable:
 * the ice weight then twists the span until its centre hangs below the axis. From the unstable
 * equilibrium turned a little (a half sine of twist), Newton in descent mode (every indefinite
 * tangent shifted) goes down to that twisted equilibrium; it is checked like any other. */
static int twisted(newton_ws *w, gal_equilibrium *eq, gal_statics_spec spec, double value,
                   const gal_statics_opts *opts, double *res)
{
    const gal_rod *rod = eq->rod;
    const char *why = gal_error_message();
    int nel = rod->p.elements, nn = rod->nn, st;
    if (!(rod->p.ecc_mass > 0 && rod->p.ecc != 0 && rod->p.torsion)) return GAL_EFAIL;
    char first[256];
    snprintf(first, sizeof first, "%s", why);
    for (int j = 0; j < nel; j++) eq->q[3 * nn + j] += 0.1 * sin(GAL_PI * (j + 0.5) / nel);
    w->descent = 1;
    st = newton(w, eq->q, 8 * opts->max_newton, &eq->newton_iterations, res);
    if (!st && spec != GAL_BY_LENGTH) st = solve_length(w, eq, spec, value, opts, res);
    w->descent = 0;
    if (!st) st = check_stable(w, eq->q);
    if (st)
        return gal_error(GAL_EFAIL, "%s; no stable twisted equilibrium found from it either (%s): the "
                         "eccentric ice makes the span lose stability", first, gal_error_message());
    eq->twisted = 1;
    return GAL_OK;
}

/* The figures of the equilibrium from the support forces in w->g. */
static void figures(const newton_ws *w, gal_equilibrium *eq)
{
    const gal_rod *rod = eq->rod;
    const double *g = w->g;
    int nel = rod->p.elements, r = 3 * nel;
    eq->unstretched_length = rod->p.unstretched_length;
    eq->horizontal_tension = -g[0];
    eq->sag = gal_rod_sag(rod, eq->q);
    eq->tension_left = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    eq->tension_right = sqrt(g[r] * g[r] + g[r + 1] * g[r + 1] + g[r + 2] * g[r + 2]);
    double *T = malloc((size_t)nel * sizeof(double));
    if (T) {
        gal_rod_tensions(rod, eq->q, T);
        for (int j = 0; j < nel; j++) eq->tension_max = fmax(eq->tension_max, T[j]);
        free(T);
    }
}

int gal_statics_solve(const gal_rod_params *p, gal_statics_spec spec, double value,
                      const gal_statics_opts *opts_in, gal_equilibrium *eq)
{
    double t0 = gal_wall_time();
    gal_statics_opts opts;
    if (opts_in) opts = *opts_in;
    else gal_statics_default_opts(&opts);
    memset(eq, 0, sizeof *eq);
    int st = start(p, spec, value, eq);
    if (st) return st;
    const gal_catenary *cat = &eq->cat;
    newton_ws w;
    double *qsave = malloc((size_t)eq->rod->nq * sizeof(double));
    if ((st = ws_alloc(&w, eq->rod)) || !qsave) {
        if (!st) ws_free(&w);
        st = gal_error(GAL_ENOMEM, "statics: out of memory for %d elements", p->elements);
        goto fail;
    }
    double Tcat = sqrt(cat->H * cat->H + cat->V0 * cat->V0);
    /* the tolerance: relative to the force scale, but not below the round-off of positions
     * (eps L) times the axial stiffness of one element (EA / l0) */
    w.ftol = fmax(opts.force_tol * fmax(fmax(Tcat, cat->w * cat->L0), 1.0),
                  20 * DBL_EPSILON * fmax(p->length, fabs(p->height_difference)) * p->EA * p->elements / cat->L0);
    double res = 0;
    st = solve_fixed_length(&w, eq, &opts, qsave, &res);
    if (!st && spec != GAL_BY_LENGTH) st = solve_length(&w, eq, spec, value, &opts, &res);
    if (!st && (st = check_stable(&w, eq->q)) == GAL_EFAIL) st = twisted(&w, eq, spec, value, &opts, &res);
    if (!st) {
        eq->residual = res;
        figures(&w, eq);
    }
    eq->factorizations = w.chol->factorizations;
    /* the stability check's tangent at eq->q and its analysis, for the modes (none when out of
     * memory: they then make their own) */
    if (!st && !(eq->rod->p.torsion && !eq->rod->p.twist_clamped)) /* check_stable's shift 0: K0's factor */
        eq->k0 = gal_tangent_copy(w.K, w.chol, eq->q, eq->rod->nq, eq->rod->p.unstretched_length);
    if (!st) eq->tangent = gal_tangent_alloc(&w.K, &w.chol, eq->q, eq->rod->nq, eq->rod->p.unstretched_length);
    ws_free(&w);
fail:
    free(qsave);
    eq->wall_time_s = gal_wall_time() - t0;
    if (st != GAL_OK) {
        gal_rod_free(eq->rod);
        free(eq->q);
        eq->rod = NULL, eq->q = NULL;
    }
    return st;
}
