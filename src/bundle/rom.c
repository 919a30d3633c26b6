/* rom.c: the explicit bundle's reduced model (bundle_rom.h): the products with the basis, the
 * reduced forces and mass, and the generalized-alpha steps (modified Newton on the reduced tangent,
 * or linearly implicit with the kept one), every term the assembled system's at the reconstructed
 * state; the basis itself is rombasis.c's. */
#include "gallop/bundle/bundle_rom.h"
#include "gallop/base/core.h"
#include "bundle_impl.h"
#include "rom_impl.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/chol.h"
#include "base/dense.h"
#include "gallop/full/dynamics.h"

/* o.one_pass's linear steps follow a Newton step that converged within this many corrections (the
 * quad over 500 s: with 3, or after any converged step, the self-check stops the run, 0.10 to 0.27) */
#define LINEAR_PASSES 2
/* A fresh reduced tangent when a Newton correction shrank the residual by less than this: it costs
 * some 20 passes (r symmetric products with K and r^2 ndof sums), so it is refreshed less eagerly
 * than the full model's sparse one (GAL_DYN_RATE = 0.1; the quad over 500 s: 1887 tangents and 52771
 * passes at 0.1, 746 and 62054 at 0.3, 359 and 69839 at 0.6) */
#define REFRESH_RATE 0.3

void gal_bundle_rom_default_opts(gal_bundle_rom_opts *o)
{
    memset(o, 0, sizeof *o);
    o->derivatives = 1;
    o->h = 0.01;
    o->rho_inf = 1.0;
    o->newton_tol = 1e-8;
    o->max_newton = 20;
    o->max_halvings = 6;
    o->fd_step_m = 1e-3;
    o->deflation_tol = 1e-6;
    o->load_vectors = 2;
    o->inertia_vectors = 1;
    o->one_pass = 8;
}

gal_bundle_rom *gal_bundle_rom_free(gal_bundle_rom *m)
{
    if (!m) return NULL;
    free(m->V), free(m->Cr), free(m->ap), free(m->x), free(m->v), free(m->a), free(m->fi), free(m->fe), free(m->s);
    free(m->s1), free(m->x1), free(m->v1), free(m->a1), free(m->fi1), free(m->fe1), free(m->res), free(m->dx);
    free(m->J), free(m->Kr), free(m->sidx), free(m->VS), free(m->MS), free(m->xs), free(m->ys), free(m->Kl), free(m->Cl), free(m->tmpr), free(m->piv), free(m->piv2), free(m->wr), free(m->z), free(m->g), free(m->wrk);
    gal_csc_free(m->K0), gal_csc_free(m->M0);
    gal_chol_free(m->chol0);
    free(m);
    return NULL;
}

/* y[c] = V_c . x for the first nc columns of V (ndof n, column-major): 8 columns at a time, each
 * sum over the dofs in order. */
static void tdots(const double *V, int n, int nc, const double *x, double *y)
{
    int c = 0;
    for (; c + 8 <= nc; c += 8) {
        const double *v = V + (size_t)c * n;
        const double *v1 = v + n, *v2 = v1 + n, *v3 = v2 + n, *v4 = v3 + n, *v5 = v4 + n, *v6 = v5 + n,
                     *v7 = v6 + n;
        double s0 = 0, s1 = 0, s2 = 0, s3 = 0, s4 = 0, s5 = 0, s6 = 0, s7 = 0;
        for (int j = 0; j < n; j++) {
            double xj = x[j];
            s0 += v[j] * xj, s1 += v1[j] * xj, s2 += v2[j] * xj, s3 += v3[j] * xj;
            s4 += v4[j] * xj, s5 += v5[j] * xj, s6 += v6[j] * xj, s7 += v7[j] * xj;
        }
        y[c] = s0, y[c + 1] = s1, y[c + 2] = s2, y[c + 3] = s3;
        y[c + 4] = s4, y[c + 5] = s5, y[c + 6] = s6, y[c + 7] = s7;
    }
    for (; c < nc; c++) {
        const double *v = V + (size_t)c * n;
        double s0 = 0;
        for (int j = 0; j < n; j++) s0 += v[j] * x[j];
        y[c] = s0;
    }
}

/* Y (r x k) = V^T X (X: ndof x k), or Y = V X (trans "N"), column-major. Each column's sum runs
 * over the dofs (T) or the basis (N) in order, as a plain loop would; the loops only take several
 * columns of V at once, so that the sums are independent (T: 8 at a time) or each entry of Y is
 * loaded and stored once per 4 columns (N). (Not the BLAS: it would start its threads on these
 * sizes, in the library, and sum in another order.) */
static void multi(const gal_bundle_rom *m, const char *trans, int k, const double *X, double *Y)
{
    int n = m->ndof, r = m->r;
    const double *V = m->V;
    if (trans[0] == 'T') {
        for (int kk = 0; kk < k; kk++) tdots(V, n, r, X + (size_t)kk * n, Y + (size_t)kk * r);
        return;
    }
    memset(Y, 0, (size_t)k * n * sizeof(double));
    for (int kk = 0; kk < k; kk++) {
        const double *a = X + (size_t)kk * r;
        double *y = Y + (size_t)kk * n;
        int c = 0;
        for (; c + 4 <= r; c += 4) {
            const double *v0 = V + (size_t)c * n, *v1 = v0 + n, *v2 = v1 + n, *v3 = v2 + n;
            double a0 = a[c], a1 = a[c + 1], a2 = a[c + 2], a3 = a[c + 3];
            for (int j = 0; j < n; j++) y[j] = (((y[j] + a0 * v0[j]) + a1 * v1[j]) + a2 * v2[j]) + a3 * v3[j];
        }
        for (; c < r; c++) {
            const double *v = V + (size_t)c * n;
            for (int j = 0; j < n; j++) y[j] += a[c] * v[j];
        }
    }
}

void gal_bundle_rom_project(const gal_bundle_rom *m, const double *x, double *y)
{
    multi(m, "T", 1, x, y);
}

void gal_bundle_rom_expand(const gal_bundle_rom *m, const double *x, double *y)
{
    multi(m, "N", 1, x, y);
}

int gal_bundle_rom_alloc_state(gal_bundle_rom *m, int rmax)
{
    size_t r = (size_t)rmax, bn = (size_t)m->ndof * sizeof(double), bs = (size_t)m->b->nstate * sizeof(double);
    m->V = malloc(r * bn);
    m->Cr = calloc(r * r, sizeof(double)), m->J = calloc(r * r, sizeof(double)), m->Kr = calloc(r * r, sizeof(double)), m->tmpr = calloc(r * r, sizeof(double));
    m->x = calloc(r, sizeof(double)), m->v = calloc(r, sizeof(double)), m->ap = calloc(r, sizeof(double)), m->a = calloc(r, sizeof(double));
    m->fi = calloc(r, sizeof(double)), m->fe = calloc(r, sizeof(double)), m->x1 = calloc(r, sizeof(double));
    m->v1 = calloc(r, sizeof(double)), m->a1 = calloc(r, sizeof(double)), m->fi1 = calloc(r, sizeof(double));
    m->fe1 = calloc(r, sizeof(double)), m->res = calloc(r, sizeof(double)), m->dx = calloc(r, sizeof(double));
    m->piv = calloc(r, sizeof(int)), m->piv2 = calloc(r, sizeof(int)), m->wr = calloc(7 * r, sizeof(double));
    m->s = malloc(bs), m->s1 = malloc(bs);
    m->z = malloc(2 * bn), m->g = malloc(2 * bn);
    m->zv = m->z ? m->z + m->ndof : NULL, m->f = m->g ? m->g + m->ndof : NULL; /* adjacent: one product */
    m->wrk = malloc((size_t)2 * m->b->rod[0]->nq * sizeof(double));
    if (!m->V || !m->Cr || !m->J || !m->Kr || !m->ap || !m->tmpr || !m->x || !m->v || !m->a || !m->fi || !m->fe || !m->x1 || !m->v1 ||
        !m->a1 || !m->fi1 || !m->fe1 || !m->res || !m->dx || !m->piv || !m->piv2 || !m->wr || !m->s || !m->s1 || !m->z || !m->zv ||
        !m->g || !m->f || !m->wrk)
        return gal_error(GAL_ENOMEM, "bundle reduced model: out of memory for a basis of %d", rmax);
    return GAL_OK;
}

/* Kr = V^T A V (r x r, row-major) for a symmetric A on the system's pattern; uses m->z, m->g. */
void gal_bundle_rom_project_matrix(gal_bundle_rom *m, const gal_csc *A, double *Kr)
{
    int r = m->r;
    for (int c = 0; c < r; c++) { /* the upper triangle, mirrored: Kr[k][c] = V_k . (A V_c), k <= c */
        gal_csc_symv(A, m->V + (size_t)c * m->ndof, m->g);
        tdots(m->V, m->ndof, c + 1, m->g, m->z);
        for (int k = 0; k <= c; k++) Kr[k * r + c] = Kr[c * r + k] = m->z[k];
    }
}

/* The state at x, its gradient (b->grad; the tangent in b->K when asked) and the reduced internal
 * and external forces at time t and rate xd; the round-off of the projected gradient in m->floor1. */
int gal_bundle_rom_forces(gal_bundle_rom *m, const double *x, const double *xd, double t, int tangent, double *s,
                          double *fi, double *fe)
{
    gal_bundle *b = m->b;
    int n = m->ndof, st;
    double *xx = m->wr + 3 * m->r, *fr = xx + 2 * m->r; /* [x xd] and [fi fe], r x 2 */
    memcpy(xx, x, (size_t)m->r * sizeof(double)), memcpy(xx + m->r, xd, (size_t)m->r * sizeof(double));
    multi(m, "N", m->force.eval ? 2 : 1, xx, m->z); /* z = V x, zv = V xd */
    gal_bundle_step(b, b->state, m->z, 1.0, s);
    if ((st = gal_bundle_eval(b, s, NULL, tangent))) return st;
    memcpy(m->g, b->grad, (size_t)n * sizeof(double));
    if (tangent) { /* the round-off of the projected gradient, at each fresh tangent */
        double fl = 0;
        for (int c = 0; c < m->r; c++) {
            const double *vc = m->V + (size_t)c * n;
            double mag = 0;
            for (int j = 0; j < n; j++) mag += fabs(vc[j] * m->g[j]);
            fl = fmax(fl, mag);
        }
        m->floor1 = 1e3 * DBL_EPSILON * fl;
    }
    memset(m->f, 0, (size_t)n * sizeof(double));
    if (m->force.eval) {
        m->force_evaluations++;
        if ((st = m->force.eval(m->force.ctx, b, t, s, m->zv, m->f))) return st;
    }
    for (int j = 0; j < n; j++) m->g[j] -= m->f[j]; /* one product: the equations take fi - fe */
    multi(m, "T", 1, m->g, fr);
    memcpy(fi, fr, (size_t)m->r * sizeof(double)), memset(fe, 0, (size_t)m->r * sizeof(double));
    return GAL_OK;
}

/* The dofs where the mass can differ from the equilibrium's, M(s) - M0 (rom_impl.h); none (the
 * whole product at every pass) when a rod's mass couples its dofs (eccentric ice). */
int gal_bundle_rom_mass_dofs(gal_bundle_rom *m)
{
    gal_bundle *b = m->b;
    int n = m->ndof, r = m->r;
    m->nS = 0;
    for (int k = 0; k < b->n; k++)
        if (b->rod[k]->ecc_c) return GAL_OK;
    char *mark = calloc((size_t)n, 1);
    if (!mark) return gal_error(GAL_ENOMEM, "bundle reduced model: out of memory");
    for (int j = b->sp0; j < n; j++) mark[j] = 1; /* the spacers' */
    for (int k = 0; k < b->n; k++) /* and every dof a sub-conductor's dof at a spacer depends on */
        for (int d = 0; d < b->rod[k]->ndof; d++)
            for (int e = 0; b->tcnt[k][d] > 1 && e < b->tcnt[k][d]; e++) mark[b->tidx[k][4 * d + e]] = 1;
    int ns = 0;
    for (int j = 0; j < n; j++) ns += mark[j];
    m->sidx = malloc((size_t)ns * sizeof(int)), m->VS = malloc((size_t)ns * r * sizeof(double));
    m->xs = calloc((size_t)n, sizeof(double)), m->ys = malloc((size_t)n * sizeof(double));
    m->MS = calloc((size_t)ns * ns, sizeof(double));
    int *pos = malloc((size_t)n * sizeof(int));
    if (!m->sidx || !m->VS || !m->xs || !m->ys || !m->MS || !pos) {
        free(pos);
        free(mark);
        return gal_error(GAL_ENOMEM, "bundle reduced model: out of memory");
    }
    for (int j = 0, i = 0; j < n; j++)
        if (mark[j]) m->sidx[i++] = j;
    for (int i = 0; i < ns; i++)
        for (int c = 0; c < r; c++) m->VS[(size_t)i * r + c] = m->V[(size_t)c * n + m->sidx[i]];
    for (int j = 0; j < n; j++) pos[j] = -1;
    for (int i = 0; i < ns; i++) pos[m->sidx[i]] = i;
    const gal_csc *M0 = m->M0; /* (M0)_SS, dense, from the stored triangle (gal_csc_symv's) */
    for (int j = 0; j < n; j++)
        for (int p = M0->colptr[j]; pos[j] >= 0 && p < M0->colptr[j + 1]; p++) {
            int i = M0->rowind[p];
            if (pos[i] < 0) continue;
            m->MS[(size_t)pos[i] * ns + pos[j]] = M0->val[p];
            m->MS[(size_t)pos[j] * ns + pos[i]] = M0->val[p];
        }
    m->nS = ns;
    free(mark), free(pos);
    return GAL_OK;
}

/* y = V^T M(s) V x at the state of the last evaluation (r entries); uses m->z, m->g. With the mass
 * dofs S: V^T M0 V = I and M(s) - M0 nonzero on S x S alone, so y = x + V_S^T (M(s) - M0)_SS V_S x. */
void gal_bundle_rom_mass_mult(gal_bundle_rom *m, const double *s, const double *x, double *y)
{
    int r = m->r, ns = m->nS;
    if (ns == 0) {
        gal_bundle_rom_expand(m, x, m->z);
        gal_bundle_mass_mult(m->b, s, m->z, m->g, m->wrk);
        gal_bundle_rom_project(m, m->g, y);
        return;
    }
    for (int i = 0; i < ns; i++) {
        double e = 0;
        for (int c = 0; c < r; c++) e += m->VS[(size_t)i * r + c] * x[c];
        m->xs[m->sidx[i]] = e;
    }
    gal_bundle_mass_mult(m->b, s, m->xs, m->ys, m->wrk);
    memcpy(y, x, (size_t)r * sizeof(double));
    for (int i = 0; i < ns; i++) {
        double d = m->ys[m->sidx[i]];
        for (int k = 0; k < ns; k++) d -= m->MS[(size_t)i * ns + k] * m->xs[m->sidx[k]];
        for (int c = 0; c < r; c++) y[c] += m->VS[(size_t)i * r + c] * d;
    }
    for (int i = 0; i < ns; i++) m->xs[m->sidx[i]] = 0;
}

/* a = (V^T M(s) V)^-1 (fe - Cr v - fi) at the state of the last evaluation (s). */
int gal_bundle_rom_acceleration(gal_bundle_rom *m, const double *s, const double *v, const double *fi,
                                const double *fe, double *a)
{
    int r = m->r;
    for (int c = 0; c < r; c++) {
        memset(m->dx, 0, (size_t)r * sizeof(double));
        m->dx[c] = 1;
        gal_bundle_rom_mass_mult(m, s, m->dx, m->res);
        for (int k = 0; k < r; k++) m->tmpr[k * r + c] = m->res[k];
    }
    if (gal_dense_lu_factor(m->tmpr, r, m->piv2)) return gal_error(GAL_EFAIL, "bundle reduced model: singular reduced mass");
    for (int k = 0; k < r; k++) {
        a[k] = fe[k] - fi[k];
        for (int j = 0; j < r; j++) a[k] -= m->Cr[k * r + j] * v[j];
    }
    gal_dense_lu_solve(m->tmpr, r, m->piv2, a);
    return GAL_OK;
}

gal_bundle_rom *gal_bundle_rom_alloc(gal_bundle *b, const gal_modes *md, const gal_bundle_rom_opts *o,
                                     const gal_bundle_force *force)
{
    double t0 = gal_wall_time();
    gal_bundle_rom *m = calloc(1, sizeof *m);
    if (!m) return NULL;
    m->b = b, m->ndof = b->ndof, m->valid = 1;
    if (o) m->o = *o;
    else gal_bundle_rom_default_opts(&m->o);
    if (force) m->force = *force;
    double rho = m->o.rho_inf;
    if (!(rho >= 0 && rho <= 1) || !(m->o.h > 0) || md->ndof != b->ndof) {
        gal_error(GAL_EINPUT, "bundle reduced model: time step %g s, rho_inf %g, modes over %d dofs of %d; allowed: "
                  "h > 0, 0 <= rho_inf <= 1, the bundle's modes", m->o.h, rho, md->ndof, b->ndof);
        return gal_bundle_rom_free(m);
    }
    m->am = (2 * rho - 1) / (rho + 1), m->af = rho / (rho + 1);
    m->gamma = 0.5 - m->am + m->af, m->beta = 0.25 * (1 - m->am + m->af) * (1 - m->am + m->af);
    if (gal_bundle_eval(b, NULL, NULL, 1)) return gal_bundle_rom_free(m);
    m->K0 = gal_csc_clone(b->K), m->M0 = gal_csc_clone(b->M);
    if (!m->K0 || !m->M0 || !(m->chol0 = gal_chol_alloc(b->K))) {
        gal_error(GAL_ENOMEM, "bundle reduced model: out of memory");
        return gal_bundle_rom_free(m);
    }
    memcpy(m->K0->val, b->K->val, (size_t)b->K->nnz * sizeof(double));
    memcpy(m->M0->val, b->M->val, (size_t)b->M->nnz * sizeof(double));
    if (gal_chol_factor(m->chol0, m->K0, 0, NULL)) {
        gal_error(GAL_EFAIL, "bundle reduced model: the tangent at the equilibrium is not positive definite");
        return gal_bundle_rom_free(m);
    }
    if (gal_bundle_rom_basis(m, md) || gal_bundle_rom_mass_dofs(m)) return gal_bundle_rom_free(m);
    double mass = 0; /* the weight's scale of the reduced forces (Cauchy-Schwarz with V^T M0 V = I) */
    for (int r = 0; r < b->n; r++)
        for (int i = 0; i < b->nn; i++) mass += b->rod[r]->node_mass[i];
    mass += b->ns * b->bp.spacer_mass;
    m->fscale = 9.81 * sqrt(mass);
    memset(m->x, 0, (size_t)m->r * sizeof(double));
    if (gal_bundle_rom_forces(m, m->x, m->v, 0.0, 0, m->s, m->fi, m->fe) ||
        gal_bundle_rom_acceleration(m, m->s, m->v, m->fi, m->fe, m->a))
        return gal_bundle_rom_free(m);
    m->floor0 = m->floor1;
    m->build_time_s = gal_wall_time() - t0;
    return m;
}

/* The residual at the increment m->dx of a step of size h into m->res (the iterate in x1, v1, a1,
 * fi1, fe1, s1); the tangent into b->K when asked. */
static void newmark(gal_bundle_rom *m, double h)
{
    double be = m->beta, ga = m->gamma;
    for (int k = 0; k < m->r; k++) {
        m->a1[k] = (m->dx[k] - h * m->v[k]) / (be * h * h) - (0.5 - be) / be * m->a[k];
        m->v1[k] = m->v[k] + h * ((1 - ga) * m->a[k] + ga * m->a1[k]);
        m->x1[k] = m->x[k] + m->dx[k];
    }
}

static int residual(gal_bundle_rom *m, double h, double t1, int tangent, double *rn)
{
    int r = m->r, st;
    double am = m->am, af = m->af, *ma = m->wr, *vf = m->wr + r, *Ma = m->wr + 2 * r;
    newmark(m, h);
    if ((st = gal_bundle_rom_forces(m, m->x1, m->v1, t1, tangent, m->s1, m->fi1, m->fe1))) return st;
    for (int k = 0; k < r; k++) ma[k] = (1 - am) * m->a1[k] + am * m->a[k], vf[k] = (1 - af) * m->v1[k] + af * m->v[k];
    gal_bundle_rom_mass_mult(m, m->s1, ma, Ma);
    *rn = 0;
    for (int k = 0; k < r; k++) {
        double c = 0;
        for (int j = 0; j < r; j++) c += m->Cr[k * r + j] * vf[j];
        m->res[k] = Ma[k] + c + (1 - af) * m->fi1[k] + af * m->fi[k] - (1 - af) * m->fe1[k] - af * m->fe[k];
        *rn = fmax(*rn, fabs(m->res[k]));
    }
    return GAL_OK;
}

/* J = cm I + cc Cr + (1 - af) V^T K V with K in b->K (the state of the last evaluation); factored. */
static int refactor(gal_bundle_rom *m, double h, double t1)
{
    int r = m->r;
    double cm = (1 - m->am) / (m->beta * h * h), cc = (1 - m->af) * m->gamma / (m->beta * h);
    gal_bundle_rom_project_matrix(m, m->b->K, m->Kr);
    for (int k = 0; k < r * r; k++) m->J[k] = (1 - m->af) * m->Kr[k] + cc * m->Cr[k];
    if (m->Kl) /* the mean loads' Jacobians at the equilibrium (the loads' share of the tangent) */
        for (int k = 0; k < r * r; k++) m->J[k] += (1 - m->af) * m->Kl[k] + cc * m->Cl[k];
    for (int k = 0; k < r; k++) m->J[k * r + k] += cm;
    m->tangents++;
    m->hJ = 0;
    if (gal_dense_lu_factor(m->J, r, m->piv))
        return gal_error(GAL_EFAIL, "bundle reduced model: singular iteration matrix at t = %.6g s", t1);
    m->hJ = h;
    return GAL_OK;
}

static void accept(gal_bundle_rom *m, double t1, double h)
{
    size_t br = (size_t)m->r * sizeof(double);
    m->hprev = h;
    memcpy(m->ap, m->a, br);
    memcpy(m->x, m->x1, br), memcpy(m->v, m->v1, br), memcpy(m->a, m->a1, br);
    memcpy(m->fi, m->fi1, br), memcpy(m->fe, m->fe1, br);
    memcpy(m->s, m->s1, (size_t)m->b->nstate * sizeof(double));
    m->t = t1, m->s_stale = 0;
}

/* The predictor dx: the acceleration extrapolated from the last two steps of the same size (the
 * first step, and after a halving: held). */
static void predict(gal_bundle_rom *m, double h)
{
    double be = m->beta, ex = m->hprev == h ? 1.0 : 0.0;
    for (int k = 0; k < m->r; k++) {
        double a1 = m->a[k] + ex * (m->a[k] - m->ap[k]);
        m->dx[k] = h * m->v[k] + h * h * ((0.5 - be) * m->a[k] + be * a1);
    }
}

/* A linearly implicit step (o.one_pass): the forces at the predictor, one correction by the kept
 * iteration matrix J (factored for h), and the internal force and the loads carried over the
 * correction dx by the kept tangent Kr and the loads' Jacobians Kl, Cl (J's own terms): the step
 * solves the linearized residual exactly. The state s is rebuilt when asked (gal_bundle_rom_sync). */
static int linear_step(gal_bundle_rom *m, double h)
{
    int r = m->r, st;
    double t1 = m->t + h, rn, cv = m->gamma / (m->beta * h), *d = m->wr + 3 * r, *dv = m->wr + 4 * r;
    predict(m, h);
    if ((st = residual(m, h, t1, 0, &rn))) return st;
    if (!isfinite(rn)) return gal_error(GAL_EFAIL, "bundle reduced model: the residual is not finite at t = %.6g s", t1);
    m->newton_iterations++;
    memcpy(d, m->res, (size_t)r * sizeof(double));
    gal_dense_lu_solve(m->J, r, m->piv, d);
    for (int k = 0; k < r; k++) d[k] = -d[k], m->dx[k] += d[k], dv[k] = cv * d[k];
    newmark(m, h);
    for (int k = 0; k < r; k++) {
        double fi = 0, fe = 0;
        for (int j = 0; j < r; j++) fi += m->Kr[k * r + j] * d[j];
        if (m->Kl)
            for (int j = 0; j < r; j++) fe += m->Kl[k * r + j] * d[j] + m->Cl[k * r + j] * dv[j];
        m->fi1[k] += fi, m->fe1[k] -= fe;
    }
    accept(m, t1, h);
    m->s_stale = 1, m->linear_steps++;
    return GAL_OK;
}

void gal_bundle_rom_sync(gal_bundle_rom *m)
{
    if (!m->s_stale) return;
    gal_bundle_rom_expand(m, m->x, m->z);
    gal_bundle_step(m->b, m->b->state, m->z, 1.0, m->s);
    m->s_stale = 0;
}

/* One step of size h (the state unchanged on failure): modified Newton as src/bundle/dynamics.c. */
static int try_step(gal_bundle_rom *m, double h)
{
    int r = m->r, st;
    double t1 = m->t + h, rprev = INFINITY;
    if (m->o.one_pass > 1 && m->lin_ok && m->hJ == h && m->steps % m->o.one_pass) return linear_step(m, h);
    m->lin_ok = 0;
    predict(m, h);
    for (int it = 0; it < m->o.max_newton; it++) {
        double rn;
        int fresh = m->hJ != h;
        if ((st = residual(m, h, t1, fresh, &rn))) return st;
        if (!isfinite(rn))
            return gal_error(GAL_EFAIL, "bundle reduced model: the residual is not finite at t = %.6g s", t1);
        m->newton_iterations++;
        double tol = fmax(m->o.newton_tol * m->fscale, fmax(m->floor0, m->floor1));
        if (rn <= tol && it > 0) {
            accept(m, t1, h);
            m->lin_ok = it <= LINEAR_PASSES && m->hJ == h;
            return GAL_OK;
        }
        if (!fresh && rn > REFRESH_RATE * rprev) {
            if ((st = gal_bundle_eval(m->b, m->s1, NULL, 1))) return st;
            fresh = 1;
        }
        if (fresh && (st = refactor(m, h, t1))) return st;
        rprev = rn;
        memcpy(m->wr, m->res, (size_t)r * sizeof(double));
        gal_dense_lu_solve(m->J, r, m->piv, m->wr);
        for (int k = 0; k < r; k++) m->dx[k] -= m->wr[k];
    }
    return gal_error(GAL_EFAIL, "bundle reduced model: Newton did not converge in %d iterations at t = %.6g s",
                     m->o.max_newton, t1);
}

static int try_step_cb(void *ctx, double hh)
{
    return try_step(ctx, hh);
}

int gal_bundle_rom_step(gal_bundle_rom *m)
{
    int st = gal_dyn_subdivide(try_step_cb, m, m->o.h, m->o.max_halvings, &m->rejected_steps, &m->t,
                               "bundle reduced model");
    if (st == GAL_OK) m->steps++;
    return st;
}
