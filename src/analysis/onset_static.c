/* onset_static.c: the mean-wind equilibrium path of the onset analysis (issue 15): Newton on the
 * full tangent K(q) - dF/dq (the rod's stiffness less the aerodynamic stiffness, non-symmetric,
 * factored by UMFPACK) and pseudo-arclength continuation in (q, U) through the folds of the path
 * (Keller 1977; Allgower & Georg, "Introduction to numerical continuation methods", 2003). */
#include "onset_internal.h"
#include "gallop/base/core.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <umfpack.h>

typedef struct {
    const gal_rod *rod;
    gal_loads L;
    gal_csc *K;
    int n, nq, nt, nnz;
    int *Ti, *Tj, *Ap, *Ai, *Map;
    double *Tx, *Ax, *g, *f, *v, *r, *ru, *a, *b, *qt;
    void *sym, *num;
    double tol, fmax; /* N: the force tolerance asked for; the largest aerodynamic load of the last residual */
} path_ws;

static void ws_free(path_ws *w)
{
    if (w->num) umfpack_di_free_numeric(&w->num);
    if (w->sym) umfpack_di_free_symbolic(&w->sym);
    gal_csc_free(w->K);
    void *p[] = {w->Ti, w->Tj, w->Ap, w->Ai, w->Map, w->Tx, w->Ax, w->g, w->f, w->v, w->r, w->ru, w->a, w->b, w->qt};
    for (size_t k = 0; k < sizeof p / sizeof p[0]; k++) free(p[k]);
}

static int ws_alloc(path_ws *w, const gal_rod *rod, const gal_loads *L, double tol)
{
    memset(w, 0, sizeof *w);
    w->rod = rod, w->L = *L, w->n = rod->ndof, w->nq = rod->nq, w->tol = tol;
    w->L.u = NULL, w->L.nt = 0, w->L.ramp_time = 0, w->L.reverse_time = 0, w->L.rod = rod;
    w->K = gal_csc_clone(rod->K);
    size_t nt = 2 * (size_t)rod->K->nnz + 49 * (size_t)rod->p.elements, n = (size_t)w->n, nq = (size_t)w->nq;
    w->Ti = malloc(nt * sizeof(int)), w->Tj = malloc(nt * sizeof(int)), w->Map = malloc(nt * sizeof(int));
    w->Ai = malloc(nt * sizeof(int)), w->Ap = malloc((n + 1) * sizeof(int));
    w->Tx = malloc(nt * sizeof(double)), w->Ax = malloc(nt * sizeof(double));
    w->g = malloc(nq * sizeof(double)), w->f = malloc(nq * sizeof(double)), w->v = calloc(nq, sizeof(double));
    w->r = malloc(n * sizeof(double)), w->ru = malloc(n * sizeof(double)), w->a = malloc(n * sizeof(double));
    w->b = malloc(n * sizeof(double)), w->qt = malloc(nq * sizeof(double));
    if (!w->K || !w->Ti || !w->Tj || !w->Map || !w->Ai || !w->Ap || !w->Tx || !w->Ax || !w->g || !w->f || !w->v ||
        !w->r || !w->ru || !w->a || !w->b || !w->qt)
        return gal_error(GAL_ENOMEM, "onset: out of memory for the mean-wind equilibrium path");
    return GAL_OK;
}

/* Residual r = grad U(q) - F(q, U) and ru = dr/dU = -2 F / U on the free dofs (F ~ U^2 at rest);
 * with jac, the tangent's triplets (the rod's upper triangle mirrored, then each element's -dF/dq). */
static int residual(path_ws *w, double *q, double U, int jac)
{
    const gal_rod *rod = w->rod;
    memset(w->f, 0, (size_t)w->nq * sizeof(double));
    w->L.speed = U;
    int st = gal_rod_eval(rod, q, NULL, w->g, jac ? w->K : NULL);
    if (!st && U > 0) st = gal_loads_full(&w->L, 0.0, q, w->v, w->f);
    if (st) return st;
    w->fmax = 0;
    for (int j = 0; j < w->n; j++) {
        int k = rod->free_q[j];
        w->r[j] = w->g[k] - w->f[k], w->ru[j] = U > 0 ? -2 * w->f[k] / U : 0;
        w->fmax = fmax(w->fmax, fabs(w->f[k]));
    }
    if (!jac) return GAL_OK;
    int t = 0;
    const gal_csc *K = w->K;
    for (int j = 0; j < K->n; j++)
        for (int p = K->colptr[j]; p < K->colptr[j + 1]; p++) {
            int i = K->rowind[p];
            w->Ti[t] = i, w->Tj[t] = j, w->Tx[t++] = K->val[p];
            if (i != j) w->Ti[t] = j, w->Tj[t] = i, w->Tx[t++] = K->val[p];
        }
    int nn = rod->nn, nc = rod->p.torsion ? 7 : 6;
    double hx = GAL_ONSET_HX(rod), J[49];
    for (int e = 0; e < rod->p.elements; e++) {
        int qi[7], d[7];
        for (int k = 0; k < 3; k++) qi[k] = 3 * e + k, qi[3 + k] = 3 * (e + 1) + k;
        qi[6] = 3 * nn + e;
        for (int c = 0; c < nc; c++) d[c] = rod->dof[qi[c]];
        for (int c = 0; c < nc && !st; c++)
            if (d[c] >= 0 && U > 0) st = gal_onset_elem_column(&w->L, rod, q, w->v, e, q, qi[c], c < 6 ? hx : GAL_ONSET_HT, J + 7 * c);
            else memset(J + 7 * c, 0, 7 * sizeof(double));
        for (int c = 0; c < nc; c++)
            for (int r = 0; r < nc; r++)
                if (d[c] >= 0 && d[r] >= 0) w->Ti[t] = d[r], w->Tj[t] = d[c], w->Tx[t++] = -J[7 * c + r];
    }
    w->nt = t;
    return st;
}

/* Factor the tangent of the last residual(jac = 1): the pattern once, values through Map. */
static int factor(path_ws *w)
{
    if (!w->sym) {
        if (umfpack_di_triplet_to_col(w->n, w->n, w->nt, w->Ti, w->Tj, w->Tx, w->Ap, w->Ai, w->Ax, w->Map) != UMFPACK_OK ||
            umfpack_di_symbolic(w->n, w->n, w->Ap, w->Ai, w->Ax, &w->sym, NULL, NULL) != UMFPACK_OK)
            return gal_error(GAL_EFAIL, "onset: UMFPACK could not analyse the %d x %d static tangent", w->n, w->n);
    } else {
        memset(w->Ax, 0, (size_t)w->Ap[w->n] * sizeof(double));
        for (int t = 0; t < w->nt; t++) w->Ax[w->Map[t]] += w->Tx[t];
    }
    if (w->num) umfpack_di_free_numeric(&w->num);
    int s = umfpack_di_numeric(w->Ap, w->Ai, w->Ax, w->sym, &w->num, NULL, NULL);
    if (s != UMFPACK_OK && s != UMFPACK_WARNING_singular_matrix)
        return gal_error(GAL_EFAIL, "onset: UMFPACK failed on the static tangent (status %d)", s);
    return s == UMFPACK_OK ? GAL_OK : GAL_EFAIL;
}

static int solve(path_ws *w, const double *rhs, double *x)
{
    return umfpack_di_solve(UMFPACK_A, w->Ap, w->Ai, w->Ax, x, rhs, w->num, NULL, NULL) == UMFPACK_OK ? GAL_OK : GAL_EFAIL;
}

/* Converged: the residual below the tolerance asked for and below 1e-6 of the aerodynamic load (a
 * light wind's load is far below a tolerance scaled on the tension) or 1e-4 of the tolerance,
 * and never below the round-off of the rod's forces (1e3 eps EA). */
static int converged(const path_ws *w, double rn)
{
    double noise = 1e3 * DBL_EPSILON * w->rod->p.EA;
    return rn <= fmax(noise, fmin(w->tol, fmax(1e-6 * w->fmax, 1e-4 * w->tol)));
}

static double norm_inf(const double *x, int n)
{
    double m = 0;
    for (int j = 0; j < n; j++) m = fmax(m, fabs(x[j]));
    return m;
}

/* Newton at the fixed speed U from q (in place), backtracking on the residual. */
static int newton_at(path_ws *w, double *q, double U, int max_iter)
{
    const gal_rod *rod = w->rod;
    for (int it = 0; ; it++) {
        int st = residual(w, q, U, 1);
        if (st) return st;
        double rn = norm_inf(w->r, w->n);
        if (!isfinite(rn)) return GAL_EFAIL;
        if (converged(w, rn)) return GAL_OK;
        if (it >= max_iter || factor(w) || solve(w, w->r, w->a)) return GAL_EFAIL;
        int done = 0;
        for (double s = 1; s > 1e-3 && !done; s *= 0.5) {
            memcpy(w->qt, q, (size_t)w->nq * sizeof(double));
            for (int j = 0; j < w->n; j++) w->qt[rod->free_q[j]] -= s * w->a[j];
            if (residual(w, w->qt, U, 0) == GAL_OK && norm_inf(w->r, w->n) < rn) done = 1;
        }
        if (!done) return GAL_EFAIL;
        memcpy(q, w->qt, (size_t)w->nq * sizeof(double));
    }
}

/* The path's unit tangent at (q, U) (after residual(jac = 1) and factor): J b = -ru, t = (b, 1)/|.|,
 * turned to agree with the previous tangent tp (NULL: U rising). t: n + 1 entries. */
static int tangent(path_ws *w, const double *tp, double *t)
{
    int n = w->n;
    for (int j = 0; j < n; j++) w->a[j] = -w->ru[j];
    if (solve(w, w->a, t)) return GAL_EFAIL;
    t[n] = 1;
    double s = 0, dot = 0;
    for (int j = 0; j <= n; j++) s += t[j] * t[j];
    s = 1 / sqrt(s);
    for (int j = 0; j <= n; j++) t[j] *= s, dot += tp ? t[j] * tp[j] : t[j] * (j == n);
    if (dot < 0)
        for (int j = 0; j <= n; j++) t[j] = -t[j];
    return GAL_OK;
}

/* One pseudo-arclength step of length ds from (q0, U0) along t: predictor, then Newton on
 * r(q, U) = 0 with t . ((q, U) - (q0, U0)) = ds (Keller's block elimination). (q, *U) out. */
static int arc_step(path_ws *w, const double *q0, double U0, const double *t, double ds, double *q, double *U, int *iters)
{
    const gal_rod *rod = w->rod;
    int n = w->n;
    memcpy(q, q0, (size_t)w->nq * sizeof(double));
    for (int j = 0; j < n; j++) q[rod->free_q[j]] += ds * t[j];
    *U = U0 + ds * t[n];
    for (int it = 0; it < 12; it++) {
        if (*U < -1 || residual(w, q, fmax(*U, 0), 1)) return GAL_EFAIL;
        double c = (*U - U0) * t[n] - ds;
        for (int j = 0; j < n; j++) c += (q[rod->free_q[j]] - q0[rod->free_q[j]]) * t[j];
        if (converged(w, norm_inf(w->r, n)) && fabs(c) <= 1e-9 * ds) { *iters = it; return GAL_OK; }
        if (factor(w) || solve(w, w->r, w->a)) return GAL_EFAIL;
        for (int j = 0; j < n; j++) w->qt[j] = -w->ru[j]; /* qt: scratch of n */
        if (solve(w, w->qt, w->b)) return GAL_EFAIL;
        /* J a = r, J b = -ru: dq = -a + dU b; t_q . dq + t_U dU = -c */
        double ta = 0, tb = 0;
        for (int j = 0; j < n; j++) ta += t[j] * w->a[j], tb += t[j] * w->b[j];
        double den = tb + t[n];
        if (fabs(den) < 1e-14) return GAL_EFAIL;
        double dU = (ta - c) / den;
        for (int j = 0; j < n; j++) q[rod->free_q[j]] += -w->a[j] + dU * w->b[j];
        *U += dU;
    }
    return GAL_EFAIL;
}

typedef struct {
    int ns, gi, pending_fold;
    const double *u;
    double *Q, umax, *fold_speed;
    int *ok, *fold;
} path_out;

/* The grid speeds the accepted step (q0, U0) -> (q1, U1) rises past: each solved at its speed from
 * the chord's point. */
static void record(path_ws *w, path_out *o, const double *q0, double U0, const double *q1, double U1)
{
    size_t nq = (size_t)w->nq;
    while (o->gi < o->ns && o->u[o->gi] <= U1 && U1 > U0) {
        double *q = o->Q + (size_t)o->gi * nq, s = (o->u[o->gi] - U0) / (U1 - U0);
        for (size_t k = 0; k < nq; k++) q[k] = q0[k] + s * (q1[k] - q0[k]);
        o->ok[o->gi] = newton_at(w, q, o->u[o->gi], 30) == GAL_OK;
        o->fold[o->gi] = o->pending_fold;
        o->pending_fold = 0;
        o->gi++;
    }
}

int gal_onset_static_path(const gal_rod *rod, const double *q_eq, const gal_loads *L, double tol, int ns,
                          const double *u, double *Q, int *ok, int *fold, double *fold_speed)
{
    path_ws w;
    int n = rod->ndof, nq = rod->nq;
    double *q0 = malloc(2 * (size_t)nq * sizeof(double)), *q1 = q0 ? q0 + nq : NULL;
    double *t0 = malloc(2 * ((size_t)n + 1) * sizeof(double)), *t1 = t0 ? t0 + n + 1 : NULL;
    int st = ws_alloc(&w, rod, L, tol);
    if (!st && (!q0 || !t0)) st = gal_error(GAL_ENOMEM, "onset: out of memory");
    *fold_speed = NAN;
    for (int i = 0; i < ns; i++) ok[i] = fold[i] = 0;
    path_out o = {ns, 0, 0, u, Q, 0, fold_speed, ok, fold};
    if (!st) {
        memcpy(q0, q_eq, (size_t)nq * sizeof(double));
        st = residual(&w, q0, 0, 1);
        if (!st) st = factor(&w);
        if (!st) st = tangent(&w, NULL, t0);
    }
    double U0 = 0, U1, span = u[ns - 1], hmax = fmax(span / 40, 1e-3), ds = fmin(hmax, fmax(u[0], hmax));
    for (int i = 0; i < ns && u[i] <= 0; i++) { /* speeds of 0: the no-wind equilibrium */
        memcpy(Q + (size_t)i * nq, q_eq, (size_t)nq * sizeof(double));
        ok[i] = 1, o.gi = i + 1;
    }
    for (int step = 0; !st && o.gi < ns && step < 200 * ns + 2000; step++) {
        int it = 0;
        if (arc_step(&w, q0, U0, t0, ds, q1, &U1, &it) || U1 < 0) {
            if ((ds *= 0.5) < 1e-6 * hmax) break; /* lost the path: the rest is not reached */
            continue;
        }
        if (factor(&w) || tangent(&w, t0, t1)) {
            if ((ds *= 0.5) < 1e-6 * hmax) break;
            continue;
        }
        if (t0[n] > 0 && t1[n] <= 0 && fmax(U0, U1) >= o.umax) { /* the path turns back: a fold */
            if (isnan(*fold_speed)) *fold_speed = fmax(U0, U1);
            o.pending_fold = 1;
        }
        record(&w, &o, q0, U0, q1, U1);
        o.umax = fmax(o.umax, U1);
        memcpy(q0, q1, (size_t)nq * sizeof(double));
        memcpy(t0, t1, ((size_t)n + 1) * sizeof(double));
        U0 = U1;
        ds = fmin(it <= 3 ? 1.5 * ds : it >= 8 ? 0.5 * ds : ds, hmax);
    }
    ws_free(&w);
    free(q0);
    free(t0);
    if (!st && !ok[0]) st = gal_error(GAL_EFAIL, "onset: no equilibrium under the mean wind at %.4g m/s", u[0]);
    return st;
}
