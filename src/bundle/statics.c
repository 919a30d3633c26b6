/* statics.c: the explicit bundle's equilibrium under gravity (bundle.h): Newton with a line search
 * on the assembled system (CHOLMOD), started from the single sub-conductor's equilibrium, and the
 * secant iteration on the sub-conductors' common unstretched length for a tension or sag. */
#include "gallop/bundle/bundle.h"
#include "gallop/base/core.h"
#include "bundle_impl.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/chol.h"

typedef struct {
    gal_bundle *b;
    gal_chol *chol;
    double *d, *st, *g0;
    double ftol;
    int max_newton;
} newton_ws;

static double inf_norm(const double *v, int n)
{
    double m = 0;
    for (int k = 0; k < n; k++) m = fmax(m, fabs(v[k]));
    return m;
}

/* Newton on the system's energy from b->state (updated in place). */
static int newton(newton_ws *w, double *res)
{
    gal_bundle *b = w->b;
    int n = b->ndof, st;
    double E, Et;
    for (int it = 0;; it++) {
        if ((st = gal_bundle_eval(b, NULL, &E, 1))) return st;
        double rn = inf_norm(b->grad, n);
        *res = rn;
        if (!isfinite(rn)) return gal_error(GAL_EFAIL, "bundle statics: the residual force is not finite (Newton iteration %d)", it);
        if (rn <= w->ftol) return GAL_OK;
        if (it >= w->max_newton)
            return gal_error(GAL_EFAIL, "bundle statics: Newton did not converge in %d iterations (residual %.3g N, "
                             "tolerance %.3g N)", w->max_newton, rn, w->ftol);
        b->newton_iterations++;
        if ((st = gal_chol_factor(w->chol, b->K, 0, NULL)) || w->chol->negative_pivots)
            return gal_error(GAL_EFAIL, "bundle statics: the assembled tangent is not positive definite at Newton "
                             "iteration %d (%d negative pivots)", it, w->chol->negative_pivots);
        memcpy(w->g0, b->grad, (size_t)n * sizeof(double));
        if ((st = gal_chol_solve(w->chol, w->g0, w->d))) return st;
        double slope = 0;
        for (int j = 0; j < n; j++) w->d[j] = -w->d[j], slope += w->g0[j] * w->d[j];
        int accepted = 0;
        for (double a = 1.0; a > 1e-12 && !accepted; a *= 0.5) {
            gal_bundle_step(b, b->state, w->d, a, w->st);
            if (gal_bundle_eval(b, w->st, &Et, 0) != GAL_OK) continue;
            accepted = Et <= E + 1e-4 * a * slope || inf_norm(b->grad, n) < rn;
        }
        if (!accepted) return gal_error(GAL_EFAIL, "bundle statics: the line search failed at Newton iteration %d "
                                        "(residual %.3g N)", it, rn);
        memcpy(b->state, w->st, (size_t)b->nstate * sizeof(double));
    }
}

/* Sub-conductor 1's horizontal tension (its left support's reaction) or sag, minus the target. */
static double misfit(gal_bundle *b, gal_statics_spec spec, double value)
{
    const gal_rod *rod = b->rod[0];
    const double *q = b->state;
    if (spec == GAL_BY_TENSION) {
        gal_rod_eval(rod, q, NULL, b->gq, NULL);
        return -b->gq[0] - value;
    }
    return gal_rod_sag(rod, q) + b->off[0][2] - value;
}

/* The first-order move of the equilibrium b->state (converged at the rods' unstretched length) to
 * the length L0: dz = -K^-1 (g(L0) - g), K the tangent at the equilibrium (positive definite
 * there). Without it Newton would start the new length from the old shape: a length increase of
 * more than the sub-conductors' elastic stretch (low tension, heavy spacers) leaves every element
 * compressed there, and the tangent indefinite. */
static int predict(newton_ws *w, double L0)
{
    gal_bundle *b = w->b;
    int n = b->ndof, st;
    if ((st = gal_bundle_eval(b, NULL, NULL, 1))) return st;
    if ((st = gal_chol_factor(w->chol, b->K, 0, NULL)) || w->chol->negative_pivots)
        return gal_error(GAL_EFAIL, "bundle statics: the equilibrium at the unstretched length %.9g m is not stable "
                         "(%d negative pivots)", b->rod[0]->p.unstretched_length, w->chol->negative_pivots);
    memcpy(w->g0, b->grad, (size_t)n * sizeof(double));
    for (int r = 0; r < b->n; r++) gal_rod_set_unstretched_length(b->rod[r], L0);
    if ((st = gal_bundle_eval(b, NULL, NULL, 0))) return st;
    for (int j = 0; j < n; j++) w->g0[j] = b->grad[j] - w->g0[j];
    if ((st = gal_chol_solve(w->chol, w->g0, w->d))) return st;
    for (int j = 0; j < n; j++) w->d[j] = -w->d[j];
    gal_bundle_step(b, b->state, w->d, 1.0, w->st);
    memcpy(b->state, w->st, (size_t)b->nstate * sizeof(double));
    return GAL_OK;
}

static int solve_length(newton_ws *w, const gal_catenary *cat, gal_statics_spec spec, double value,
                        int max_iter, double *res)
{
    gal_bundle *b = w->b;
    double L0a = b->rod[0]->p.unstretched_length, fa = misfit(b, spec, value);
    gal_catenary c2 = *cat;
    double dL = 1e-6 * cat->L0;
    gal_catenary_solve(&c2, GAL_BY_LENGTH, cat->L0 + dL);
    double slope = spec == GAL_BY_TENSION ? (c2.H - cat->H) / dL : (gal_catenary_sag(&c2) - gal_catenary_sag(cat)) / dL;
    double tol = spec == GAL_BY_TENSION ? 1e-10 * value : 1e-8 * value;
    int st;
    while (fabs(fa) > tol) {
        if (b->length_iterations++ >= max_iter)
            return gal_error(GAL_EFAIL, "bundle statics: the unstretched length iteration did not converge (off by %.3g)", fa);
        double L0b = L0a - fa / slope;
        if ((st = predict(w, L0b)) || (st = newton(w, res))) return st;
        double fb = misfit(b, spec, value);
        if (fb != fa) slope = (fb - fa) / (L0b - L0a);
        L0a = L0b, fa = fb;
    }
    return GAL_OK;
}

/* The figures: sub-conductor 1's tension and sag, the largest element tension, the asymmetry. */
static void figures(gal_bundle *b)
{
    const gal_rod *r0 = b->rod[0];
    int nel = r0->p.elements;
    double *T = malloc((size_t)nel * sizeof(double));
    gal_rod_eval(r0, b->state, NULL, b->gq, NULL);
    b->horizontal_tension = -b->gq[0];
    b->sag = gal_rod_sag(r0, b->state) + b->off[0][2];
    b->unstretched_length = r0->p.unstretched_length;
    b->tension_max = 0, b->asymmetry = 0;
    for (int r = 0; r < b->n; r++) {
        const double *q = gal_bundle_q(b, b->state, r);
        if (T) {
            gal_rod_tensions(b->rod[r], q, T);
            for (int j = 0; j < nel; j++) b->tension_max = fmax(b->tension_max, T[j]);
        }
        for (int i = 0; i < b->nn; i++)
            for (int k = 0; k < 3; k++)
                b->asymmetry = fmax(b->asymmetry, fabs(q[3 * i + k] - b->off[r][k] - b->state[3 * i + k] + b->off[0][k]));
    }
    free(T);
}

int gal_bundle_statics(const gal_rod_params *p, const gal_bundle_params *bp, gal_statics_spec spec,
                       double value, const gal_statics_opts *opts_in, gal_bundle **out)
{
    double t0 = gal_wall_time();
    gal_statics_opts opts;
    if (opts_in) opts = *opts_in;
    else gal_statics_default_opts(&opts);
    *out = NULL;
    gal_rod_params p1 = *p;
    p1.elements = gal_bundle_mesh(p->elements, bp);
    if (p1.elements <= 0)
        return gal_error(GAL_EINPUT, "bundle: no mesh of %d to 1000 elements puts each of the %d spacers within "
                         "%g of the span of a node with 2 elements between them", p->elements, bp->spacers,
                         GAL_BUNDLE_SNAP);
    gal_equilibrium eq1; /* one sub-conductor: the start, and the answer without spacer weight */
    int st = gal_statics_solve(&p1, spec, value, &opts, &eq1);
    if (st) return st;
    p1.unstretched_length = eq1.unstretched_length;
    gal_bundle *b = gal_bundle_alloc(&p1, bp, eq1.q);
    newton_ws w = {b, NULL, NULL, NULL, NULL, 0, opts.max_newton};
    if (!b) { st = gal_error_status(); goto done; }
    int n = b->ndof;
    w.chol = gal_chol_alloc(b->K);
    w.d = malloc((size_t)n * sizeof(double)), w.g0 = malloc((size_t)n * sizeof(double));
    w.st = malloc((size_t)b->nstate * sizeof(double));
    if (!w.chol || !w.d || !w.g0 || !w.st) { st = gal_error(GAL_ENOMEM, "bundle statics: out of memory"); goto done; }
    const gal_catenary *cat = &eq1.cat;
    double Tcat = sqrt(cat->H * cat->H + cat->V0 * cat->V0);
    w.ftol = fmax(opts.force_tol * fmax(fmax(Tcat, cat->w * cat->L0), 1.0),
                  20 * DBL_EPSILON * fmax(p1.length, fabs(p1.height_difference)) *
                      fmax(p1.EA * p1.elements / cat->L0, bp->spacer_stiffness));
    st = newton(&w, &b->residual);
    if (!st && spec != GAL_BY_LENGTH) st = solve_length(&w, cat, spec, value, opts.max_length_iter, &b->residual);
    if (!st) figures(b);
done:
    if (w.chol) b->factorizations = w.chol->factorizations;
    gal_chol_free(w.chol);
    free(w.d), free(w.g0), free(w.st);
    gal_equilibrium_clear(&eq1);
    if (st) b = gal_bundle_free(b);
    else b->wall_time_s = gal_wall_time() - t0;
    *out = b;
    return st;
}
