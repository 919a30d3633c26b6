/* rom.c: time integration of the recomputed reduced model (rom.h) by the generalized-alpha method
 * with Newton on the reduced tangent, its reconstruction of the full state and its self-check
 * against the full equations' residual. With V^T M V = I the residual at the generalized
 * mid-point is
 *   R = a_m + Cr v_f + (1-af) (fi(x1) - fe1) + af (fi(x0) - fe0),
 * a_m = (1-am) a1 + am a0, v_f = (1-af) v1 + af v0, and x1, v1 the Newmark updates in a1. */
#include "gallop/reduced/rom.h"
#include "gallop/base/core.h"
#include "gallop/reduced/ecsw.h"
#include "reduced/hyper.h"
#include "reduced/qm.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* q = q_eq + V x over the free dofs (m->q); the velocity V xd into m->vq when xd != NULL (on the
 * manifold: q_eq + u(x), P(x) xd). */
static void reconstruct(gal_rom *m, const double *x, const double *xd)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof, r = m->r;
    memcpy(m->q, m->q_eq, (size_t)m->nq * sizeof(double));
    if (m->qm) {
        gal_rom_qm_displacement(m, x, xd, m->wn, m->wn2);
        for (int d = 0; d < n; d++) {
            m->q[rod->free_q[d]] += m->wn[d];
            if (xd) m->vq[rod->free_q[d]] = m->wn2[d];
        }
        return;
    }
    double *s = m->wn, *sv = m->wn2; /* the sums over the columns in order, a column at a time */
    memset(s, 0, (size_t)n * sizeof(double)), memset(sv, 0, (size_t)n * sizeof(double));
    for (int k = 0; k < r; k++) {
        const double *vk = m->V + (size_t)k * n;
        if (x[k] != 0) for (int d = 0; d < n; d++) s[d] += vk[d] * x[k]; /* a 0 adds +-0 */
        if (xd && xd[k] != 0) for (int d = 0; d < n; d++) sv[d] += vk[d] * xd[k];
    }
    for (int d = 0; d < n; d++) {
        m->q[rod->free_q[d]] += s[d];
        if (xd) m->vq[rod->free_q[d]] = sv[d];
    }
}

const double *gal_rom_basis_at(gal_rom *m, const double *x)
{
    return m->qm ? gal_rom_qm_basis(m, x) : m->V;
}

/* f = B^T (free part of a configuration-sized vector g), B the tangent basis at x */
static void project(gal_rom *m, const double *x, const double *g, double *f)
{
    int n = m->ndof;
    const double *B = gal_rom_basis_at(m, x);
    for (int k = 0; k < m->r; k++) {
        const double *vk = B + (size_t)k * n;
        double s = 0;
        for (int d = 0; d < n; d++) s += vk[d] * g[m->rod->free_q[d]];
        f[k] = s;
    }
}

static int internal(gal_rom *m, const double *x, double *f, double *Kr);
static int external(gal_rom *m, double t, const double *x, const double *xd, double *f);

/* The reduced equations' own acceleration at the state into ac: fe - Cr v - fi (the integrator's
 * a lags it by the step's truncation error). m->da is scratch. */
static int consistent_acceleration(gal_rom *m, double *ac)
{
    int r = m->r, st = internal(m, m->x, ac, NULL);
    if (!st) st = external(m, m->t, m->x, m->v, m->da);
    if (st) return st;
    for (int i = 0; i < r; i++) {
        double c = 0;
        for (int j = 0; j < r; j++) c += m->Cr[i * r + j] * m->v[j];
        ac[i] = m->da[i] - c - ac[i];
    }
    return GAL_OK;
}

void gal_rom_full_rates(gal_rom *m, double *vf, double *af, double *u)
{
    int n = m->ndof, r = m->r;
    if (m->qm) { /* v = P x', a = P x'' + Theta(x', x') */
        const gal_rom_qm *qm = m->qm;
        int np = qm->np;
        double *mono = qm->mono, *dmono = mono + np, *ddmono = dmono + np;
        const double *P = gal_rom_qm_basis(m, m->x);
        gal_rom_qm_mono(m, m->x, m->v, m->a, mono, dmono, ddmono);
        for (int d = 0; d < n; d++) {
            double sv = 0, sa = 0, su = 0;
            for (int k = 0; k < r; k++) {
                double vk = m->V[(size_t)k * n + d];
                sv += P[(size_t)k * n + d] * m->v[k], sa += vk * m->a[k], su += vk * m->x[k];
            }
            for (int p = 0; p < np; p++) {
                double t = qm->Th[(size_t)p * n + d];
                sa += t * ddmono[p], su += t * mono[p];
            }
            vf[d] = sv, af[d] = sa, u[d] = su;
        }
        return;
    }
    const double *acc = m->a;
    if (!consistent_acceleration(m, m->fr)) acc = m->fr; /* else the integrator's */
    for (int d = 0; d < n; d++) {
        double sv = 0, sa = 0, su = 0;
        for (int k = 0; k < r; k++) {
            double vk = m->V[(size_t)k * n + d];
            sv += vk * m->v[k], sa += vk * acc[k], su += vk * m->x[k];
        }
        vf[d] = sv, af[d] = sa, u[d] = su;
    }
}

double *gal_rom_reconstruct_q(gal_rom *m, const double *x)
{
    reconstruct(m, x, NULL);
    return m->q;
}

void gal_rom_reconstruct_at(gal_rom *m, const double *x, const double *xd)
{
    if (x) reconstruct(m, x, xd);
    else memcpy(m->q, m->q_eq, (size_t)m->nq * sizeof(double));
    if (!xd) memset(m->vq, 0, (size_t)m->nq * sizeof(double));
}

/* Internal force at x, its energy into m->U1 (and the reduced tangent into Kr when Kr != NULL):
 * from the sample when the model is hyper-reduced. */
static int internal(gal_rom *m, const double *x, double *f, double *Kr)
{
    if (m->hyper) {
        int st = gal_rom_hyper_internal(m, x, f, Kr);
        if (!st && Kr) m->tangents++;
        return st;
    }
    reconstruct(m, x, NULL);
    m->element_evaluations += gal_rod_element_count(m->rod);
    int st = gal_rod_eval(m->rod, m->q, &m->U1, m->gq, Kr ? m->K : NULL);
    if (st) return st;
    project(m, x, m->gq, f);
    if (Kr) {
        if (m->qm) { /* P^T K P + the manifold's curvature */
            const double *P = m->qm->P; /* at x, from project */
            for (int j = 0; j < m->r; j++) {
                gal_csc_symv(m->K, P + (size_t)j * m->ndof, m->wn);
                for (int i = 0; i <= j; i++) {
                    double s = 0;
                    for (int d = 0; d < m->ndof; d++) s += P[(size_t)i * m->ndof + d] * m->wn[d];
                    Kr[i * m->r + j] = Kr[j * m->r + i] = s;
                }
            }
            gal_rom_qm_curvature(m, m->gq, Kr);
        } else gal_rom_project_tangent(m, m->K, Kr, m->wn);
        m->tangents++;
    }
    return GAL_OK;
}

/* External force at (t, x, xd). */
static int external(gal_rom *m, double t, const double *x, const double *xd, double *f)
{
    if (!m->force.eval) { memset(f, 0, (size_t)m->r * sizeof(double)); return GAL_OK; }
    m->force_evaluations++;
    if (m->hyper && m->hyper->loads) return gal_rom_hyper_external(m, t, x, xd, f);
    reconstruct(m, x, xd);
    m->load_element_evaluations += m->rod->p.elements;
    memset(m->fq, 0, (size_t)m->nq * sizeof(double));
    int st = m->force.eval(m->force.ctx, t, m->q, m->vq, m->fq);
    if (st) return st;
    project(m, x, m->fq, f);
    return GAL_OK;
}

int gal_rom_internal_force(gal_rom *m, const double *x, double *f)
{
    return internal(m, x, f, NULL);
}

/* LU with partial pivoting of the r x r row-major A in place; 0 on success. */
static int lu_factor(double *A, int r, int *piv)
{
    for (int k = 0; k < r; k++) {
        int p = k;
        for (int i = k + 1; i < r; i++)
            if (fabs(A[i * r + k]) > fabs(A[p * r + k])) p = i;
        piv[k] = p;
        if (A[p * r + k] == 0) return -1;
        if (p != k)
            for (int j = 0; j < r; j++) { double t = A[k * r + j]; A[k * r + j] = A[p * r + j]; A[p * r + j] = t; }
        for (int i = k + 1; i < r; i++) {
            double l = A[i * r + k] /= A[k * r + k];
            for (int j = k + 1; j < r; j++) A[i * r + j] -= l * A[k * r + j];
        }
    }
    return 0;
}

static void lu_solve(const double *A, int r, const int *piv, double *b)
{
    for (int k = 0; k < r; k++) {
        double t = b[piv[k]]; b[piv[k]] = b[k]; b[k] = t;
        for (int i = k + 1; i < r; i++) b[i] -= A[i * r + k] * b[k];
    }
    for (int k = r - 1; k >= 0; k--) {
        for (int j = k + 1; j < r; j++) b[k] -= A[k * r + j] * b[j];
        b[k] /= A[k * r + k];
    }
}

int gal_rom_start(gal_rom *m, double t, const double *q, const double *v)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof, r = m->r;
    m->t = t;
    m->hJ = 0, m->next_hyper_check = t + gal_rom_check_interval(m, m->o.hyper_check_interval);
    /* x = V^T M (q - q_eq), x' = V^T M v (on the manifold: the closest state on it) */
    if (m->qm) {
        int st = gal_rom_qm_project_state(m, q, v, m->x, m->v);
        if (st) return st;
    }
    for (int s = 0; s < 2 && !m->qm; s++) {
        double *dst = s ? m->v : m->x;
        if (s && !v) { memset(dst, 0, (size_t)r * sizeof(double)); break; }
        for (int d = 0; d < n; d++) {
            int k = rod->free_q[d];
            m->wn2[d] = s ? v[k] : q[k] - m->q_eq[k];
        }
        gal_rod_mass_mult(rod, m->wn2, m->wn);
        for (int k = 0; k < r; k++) {
            double e = 0;
            for (int d = 0; d < n; d++) e += m->V[(size_t)k * n + d] * m->wn[d];
            dst[k] = e;
        }
    }
    int st = internal(m, m->x, m->fi, NULL);
    if (!st) st = external(m, t, m->x, m->v, m->fe);
    if (st) return st;
    m->U = m->U1;
    if (m->qm && m->qm->inertia) { /* M(x) a = fe - fi - c(x, v) - C(x) v (qm.h) */
        for (int i = 0; i < r; i++) m->fr[i] = m->fe[i] - m->fi[i];
        return gal_rom_qm_acceleration(m, m->x, m->v, m->fr, m->a);
    }
    /* a = fe - fi - Cr v */
    for (int i = 0; i < r; i++) {
        double c = 0;
        for (int j = 0; j < r; j++) c += m->Cr[i * r + j] * m->v[j];
        m->a[i] = m->fe[i] - m->fi[i] - c;
    }
    return GAL_OK;
}

/* The Newmark updates of x1, v1 from the current a1. */
static void newmark(gal_rom *m, double h)
{
    for (int k = 0; k < m->r; k++) {
        m->x1[k] = m->x[k] + h * m->v[k] + h * h * ((0.5 - m->beta) * m->a[k] + m->beta * m->a1[k]);
        m->v1[k] = m->v[k] + h * ((1 - m->gamma) * m->a[k] + m->gamma * m->a1[k]);
    }
}

/* The discrete gradient of the internal force over the step (Gonzalez 1996) into m->fdg:
 * fbar = (fi(x0) + fi(x1)) / 2 corrected along dx = x1 - x0 so that fdg . dx = U(x1) - U(x0)
 * exactly: with the trapezoidal Newmark updates (rho_inf = 1) the step then conserves T + U. Not
 * where U(x1) - U(x0) - fbar . dx is within the energy's round-off m->ufloor: the correction would
 * be that round-off over |dx|, noise that stops Newton on small steps (free vibration of 1 mm). */
static void discrete_gradient(gal_rom *m)
{
    int r = m->r;
    double dd = 0, fd = 0, xs = 0;
    for (int i = 0; i < r; i++) {
        double dx = m->x1[i] - m->x[i];
        m->fdg[i] = 0.5 * (m->fi[i] + m->fi1[i]);
        dd += dx * dx, fd += m->fdg[i] * dx, xs += m->x1[i] * m->x1[i] + m->x[i] * m->x[i];
    }
    if (!(dd > 1e-28 * xs) || !(dd > 0) || !(fabs(m->U1 - m->U - fd) > m->ufloor)) return;
    double c = (m->U1 - m->U - fd) / dd;
    for (int i = 0; i < r; i++) m->fdg[i] += c * (m->x1[i] - m->x[i]);
}

/* Residual at the generalized mid-point into m->res; returns its largest entry over the Newton
 * tolerance newton_tol times the step's force scale (the largest |fi1| + |fe1| entry, at least the
 * projected weights fscale; not below the round-off floor ffloor), converged at <= 1, and into
 * *strict the same over GAL_NEWTON_TOL_STRICT's (or a tighter newton_tol's), the largest entry itself into *raw. With
 * rho_inf = 1 the internal force is the discrete gradient. */
static double residual(gal_rom *m, double *strict, double *raw)
{
    int r = m->r;
    double am = m->am, af = m->af, rn = 0, sc = 0;
    int dg = m->o.rho_inf == 1.0;
    if (dg) discrete_gradient(m);
    const gal_rom_qm *qm = m->qm && m->qm->inertia ? m->qm : NULL; /* the manifold's mass (qm.h) */
    for (int i = 0; i < r; i++) {
        double c = 0;
        for (int j = 0; j < r && !qm; j++) c += m->Cr[i * r + j] * ((1 - af) * m->v1[j] + af * m->v[j]);
        double fi = dg ? m->fdg[i] : (1 - af) * m->fi1[i] + af * m->fi[i];
        double in = qm ? qm->f1[i] : (1 - am) * m->a1[i] + am * m->a[i];
        if (qm) c = qm->d1[i];
        m->res[i] = in + c + fi - (1 - af) * m->fe1[i] - af * m->fe[i];
        rn = fmax(rn, fabs(m->res[i]));
        sc = fmax(sc, fabs(m->fi1[i]) + fabs(m->fe1[i]));
    }
    double tol = m->o.newton_tol, ts = fmin(tol, GAL_NEWTON_TOL_STRICT);
    *strict = rn / fmax(ts * fmax(sc, m->fscale), m->ffloor), *raw = rn;
    return rn / fmax(tol * fmax(sc, m->fscale), m->ffloor);
}

/* The iteration matrix J = (1-am) I + (1-af) (gamma h Cr + beta h^2 Kr), LU-factored. The loads'
 * derivatives are left out (measured: with them, by differences, Newton takes as many iterations
 * at the steps used and each fresh matrix costs r more evaluations of the loads). */
static int iteration_matrix(gal_rom *m, double h)
{
    int r = m->r;
    double af = m->af, cm = 1 - m->am, cc = (1 - af) * m->gamma * h, ck = (1 - af) * m->beta * h * h;
    for (int k = 0; k < r * r; k++) m->J[k] = cc * m->Cr[k] + ck * m->Kr[k];
    for (int k = 0; k < r; k++) m->J[k * r + k] += cm;
    if (m->qm && m->qm->inertia) { /* the manifold's mass, damping and convective term */
        for (int k = 0; k < r * r; k++) m->J[k] = ck * m->Kr[k];
        gal_rom_qm_iteration(m, m->x1, m->v1, cm, cc, m->J);
    }
    m->hJ = 0;
    if (lu_factor(m->J, r, m->piv)) return gal_error(GAL_EFAIL, "reduced model: singular iteration matrix");
    m->hJ = h;
    return GAL_OK;
}

/* Newton on a1 for one step of h from the state; x1, v1, a1, fi1, fe1 hold the result. */
static int newton(gal_rom *m, double h)
{
    int r = m->r, st = GAL_OK;
    double t1 = m->t + h;
    memcpy(m->a1, m->a, (size_t)r * sizeof(double));
    if (m->qm && m->qm->inertia) gal_rom_qm_begin(m);
    /* modified Newton: the iteration matrix of an earlier step is kept (o.reuse_tangent) while it
     * converges fast; a fresh tangent whenever an iteration did not gain a factor of 10 (the
     * stretching directions are strongly nonlinear) */
    int it, conv = 0, fresh = !(m->o.reuse_tangent && m->hJ == h), kept = !fresh;
    double prev = INFINITY, rawprev = INFINITY;
    for (it = 0; it < m->o.max_newton; it++) {
        newmark(m, h);
        if ((st = internal(m, m->x1, m->fi1, fresh ? m->Kr : NULL))) break;
        if ((st = external(m, t1, m->x1, m->v1, m->fe1))) break;
        if (m->qm && m->qm->inertia) gal_rom_qm_end(m, h);
        double rs, raw, rn = residual(m, &rs, &raw);
        /* as the full model (dynamics.c): within a looser tolerance than GAL_NEWTON_TOL_STRICT's
         * only after a correction that reduced the residual */
        if (rs <= 1 || (it > 0 && rn <= 1 && raw < rawprev)) { conv = 1; break; }
        if (!isfinite(rn)) { st = gal_error(GAL_EFAIL, "reduced model: the residual is not finite"); break; }
        if (!fresh && (rn > m->o.newton_contraction * prev || (kept && it >= m->o.newton_kept_max))) {
            fresh = 1, kept = 0;
            if ((st = internal(m, m->x1, m->fi1, m->Kr))) break;
        }
        prev = rn, rawprev = raw;
        if (fresh) {
            if ((st = iteration_matrix(m, h))) break;
            fresh = 0;
        }
        for (int k = 0; k < r; k++) m->da[k] = -m->res[k];
        lu_solve(m->J, r, m->piv, m->da);
        for (int k = 0; k < r; k++) m->a1[k] += m->da[k];
        m->newton_iterations++;
    }
    if (!st && !conv)
        st = gal_error(GAL_EFAIL, "reduced model: Newton did not converge in %d iterations at t = %.6g s "
                       "(time step %g s)", m->o.max_newton, t1, h);
    return st;
}

/* A step of h; on failure, two of h/2 (up to GAL_ROM_HALVINGS times deep). The state changes only
 * on success. */
static int step(gal_rom *m, double h, int depth)
{
    int r = m->r, st = newton(m, h);
    if (st && st != GAL_ENOMEM && depth < GAL_ROM_HALVINGS) {
        m->halvings++;
        st = step(m, 0.5 * h, depth + 1);
        if (!st) st = step(m, 0.5 * h, depth + 1);
        return st;
    }
    if (st) return st;
    memcpy(m->x, m->x1, (size_t)r * sizeof(double));
    memcpy(m->v, m->v1, (size_t)r * sizeof(double));
    memcpy(m->a, m->a1, (size_t)r * sizeof(double));
    memcpy(m->fi, m->fi1, (size_t)r * sizeof(double));
    memcpy(m->fe, m->fe1, (size_t)r * sizeof(double));
    m->U = m->U1;
    m->t += h;
    m->steps++;
    return GAL_OK;
}

double gal_rom_check_interval(const gal_rom *m, double base_s)
{
    const gal_rom_hyper *h = m->hyper;
    if (!h || !(base_s > 0)) return base_s;
    int nel = m->rod->p.elements, loads = m->force.eval != NULL;
    double sample = h->set[0].n + (loads ? (h->loads ? h->set[1].n : nel) : 0);
    double check = 2.0 * (gal_rod_element_count(m->rod) + (loads ? nel : 0)); /* the sample's and the residual's */
    double per_s = 2.0 * sample / m->o.h; /* the steps' element evaluations per simulated second */
    return fmax(base_s, check / (GAL_ROM_CHECK_SHARE * per_s));
}

int gal_rom_step(gal_rom *m)
{
    double t1 = m->t + m->o.h;
    int st = step(m, m->o.h, 0);
    if (st) return gal_error(st, "at t = %.6g s (after %d step halvings): %s", t1, GAL_ROM_HALVINGS, gal_error_message());
    /* the sample against the exact projected forces every hyper_check_interval */
    if (m->hyper && m->o.hyper_check_interval > 0 && m->t >= m->next_hyper_check - 1e-3 * m->o.h) {
        m->next_hyper_check = m->t + gal_rom_check_interval(m, m->o.hyper_check_interval);
        long e0 = m->element_evaluations, l0 = m->load_element_evaluations;
        st = gal_rom_hyper_check(m, NULL); /* the exact forces over the whole rod, and the sample's */
        m->check_element_evaluations += gal_rod_element_count(m->rod) + (m->hyper->loads ? m->rod->p.elements : 0) +
                                        m->element_evaluations - e0 + m->load_element_evaluations - l0;
        m->element_evaluations = e0, m->load_element_evaluations = l0;
        if (st) return gal_error(st, "at t = %.6g s: %s", m->t, gal_error_message());
    }
    return GAL_OK;
}

int gal_rom_advance(gal_rom *m, double t_target)
{
    while (m->t < t_target - 1e-3 * m->o.h) {
        int st = gal_rom_step(m);
        if (st) return st;
    }
    return GAL_OK;
}

void gal_rom_reconstruct(const gal_rom *m, double *q, double *v)
{
    gal_rom *mm = (gal_rom *)m; /* the workspace only */
    reconstruct(mm, m->x, m->v);
    if (q) memcpy(q, m->q, (size_t)m->nq * sizeof(double));
    if (v) memcpy(v, m->vq, (size_t)m->nq * sizeof(double));
}

double gal_rom_entry(const gal_rom *m, int qi, int rate)
{
    int d = m->rod->dof[qi];
    double s = rate ? 0 : m->q_eq[qi];
    if (d < 0) return s;
    if (m->qm) { /* u_d(x) = Phi_d x + Theta_d mono, rate P_d(x) x' */
        const gal_rom_qm *qm = m->qm;
        int n = m->ndof, nm = m->nmodes;
        for (int i = 0; i < nm; i++) {
            double pi = m->V[(size_t)i * n + d], ti = 0;
            for (int j = 0; j < nm; j++) ti += qm->Th[(size_t)qm->pair[i * nm + j] * n + d] * m->x[j];
            s += rate ? (pi + ti) * m->v[i] : (pi + 0.5 * ti) * m->x[i];
        }
        return s;
    }
    const double *y = rate ? m->v : m->x;
    for (int k = 0; k < m->r; k++) s += m->V[(size_t)k * m->ndof + d] * y[k];
    return s;
}

double gal_rom_element_tension(const gal_rom *m, int j)
{
    double e[3];
    for (int k = 0; k < 3; k++) e[k] = gal_rom_entry(m, 3 * (j + 1) + k, 0) - gal_rom_entry(m, 3 * j + k, 0);
    return m->rod->p.EA * (sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]) / m->rod->l0[j] - 1);
}

double gal_rom_energy(gal_rom *m)
{
    double U = 0, T = 0;
    if (m->hyper) { /* the model's own energy U_h */
        if (gal_rom_hyper_internal(m, m->x, m->fr, NULL)) return NAN;
        U = m->U1;
    } else {
        reconstruct(m, m->x, NULL);
        if (gal_rod_eval(m->rod, m->q, &U, NULL, NULL)) return NAN;
    }
    for (int k = 0; k < m->r; k++) T += 0.5 * m->v[k] * m->v[k];
    if (m->qm && m->qm->inertia) T = gal_rom_qm_kinetic(m, m->x, m->v);
    return T + U;
}

void gal_rom_observe(const gal_rom *m, int nprobe, const double *probe, double *row, double tension[2])
{
    const gal_rod *rod = m->rod;
    int nel = rod->p.elements, nn = rod->nn;
    for (int k = 0; k < nprobe; k++) {
        double s = probe[k] * nel, se = s - 0.5;
        int e = (int)s < nel - 1 ? (int)s : nel - 1, e0 = (int)floor(se);
        double xi = s - e, w1 = se - e0;
        if (e0 < 0) e0 = 0, w1 = 0;
        if (e0 >= nel - 1) e0 = nel - 1, w1 = 0;
        int e1 = e0 + 1 < nel ? e0 + 1 : e0;
        double d[3];
        for (int c = 0; c < 3; c++)
            d[c] = (1 - xi) * (gal_rom_entry(m, 3 * e + c, 0) - m->q_eq[3 * e + c]) +
                   xi * (gal_rom_entry(m, 3 * (e + 1) + c, 0) - m->q_eq[3 * (e + 1) + c]);
        double th = 0;
        if (rod->p.torsion)
            th = (1 - w1) * (gal_rom_entry(m, 3 * nn + e0, 0) - m->q_eq[3 * nn + e0]) +
                 w1 * (gal_rom_entry(m, 3 * nn + e1, 0) - m->q_eq[3 * nn + e1]);
        row[4 * k] = d[1], row[4 * k + 1] = d[2], row[4 * k + 2] = d[0], row[4 * k + 3] = th * 180 / GAL_PI;
    }
    tension[0] = gal_rom_element_tension(m, 0);
    tension[1] = gal_rom_element_tension(m, nel - 1);
}
