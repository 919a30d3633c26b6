/* rom_step.c: the time step of the recomputed reduced model (rom.h): the generalized-alpha method
 * with (modified) Newton on the reduced tangent, step halving on failure, and the sample's periodic
 * check. With V^T M V = I the residual at the generalized mid-point is
 *   R = a_m + Cr v_f + (1-af) (fi(x1) - fe1) + af (fi(x0) - fe0),
 * a_m = (1-am) a1 + am a0, v_f = (1-af) v1 + af v0, and x1, v1 the Newmark updates in a1. */
#include "gallop/reduced/rom.h"
#include "gallop/base/core.h"
#include "gallop/reduced/ecsw.h"
#include "reduced/hyper.h"
#include "base/dense.h"
#include "reduced/qm.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* y = A x (y += A x when add), A r x r row-major: four rows at a time, each row's sum over j in
 * order from 0 (the same sums as one row at a time, four independent chains instead of one) */
static void mult(int r, const double *A, const double *x, double *y, int add)
{
    int i = 0;
    for (; i + 4 <= r; i += 4) {
        const double *a0 = A + (size_t)i * r, *a1 = a0 + r, *a2 = a1 + r, *a3 = a2 + r;
        double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
        for (int j = 0; j < r; j++) s0 += a0[j] * x[j], s1 += a1[j] * x[j], s2 += a2[j] * x[j], s3 += a3[j] * x[j];
        if (add) y[i] += s0, y[i + 1] += s1, y[i + 2] += s2, y[i + 3] += s3;
        else y[i] = s0, y[i + 1] = s1, y[i + 2] = s2, y[i + 3] = s3;
    }
    for (; i < r; i++) {
        double s = 0;
        for (int j = 0; j < r; j++) s += A[(size_t)i * r + j] * x[j];
        y[i] = add ? y[i] + s : s;
    }
}

int gal_rom_start(gal_rom *m, double t, const double *q, const double *v)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof, r = m->r;
    m->t = t;
    gal_rom_irk_restart(m);
    m->hJ = 0, m->hfe = 0, m->lin_ok = 0, m->next_hyper_check = t + gal_rom_check_interval(m, m->o.hyper_check_interval);
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
    int st = gal_rom_eval_internal(m, m->x, m->fi, NULL);
    if (!st) st = gal_rom_eval_external(m, t, m->x, m->v, m->fe);
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

#define LINEAR_REJECT 1 /* positive: linear_step's "take a Newton step instead", not an error */

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
    double *c = m->res; /* the damping force Cr v_f (on the manifold its own, qm->d1) */
    if (qm) memcpy(c, qm->d1, (size_t)r * sizeof(double));
    else {
        for (int j = 0; j < r; j++) m->da[j] = (1 - af) * m->v1[j] + af * m->v[j]; /* scratch */
        mult(r, m->Cr, m->da, c, 0);
    }
    for (int i = 0; i < r; i++) {
        double fi = dg ? m->fdg[i] : (1 - af) * m->fi1[i] + af * m->fi[i];
        double in = qm ? qm->f1[i] : (1 - am) * m->a1[i] + am * m->a[i];
        m->res[i] = in + c[i] + fi - (1 - af) * m->fe1[i] - af * m->fe[i];
        double ar = fabs(m->res[i]), as = fabs(m->fi1[i]) + fabs(m->fe1[i]);
        if (ar > rn) rn = ar; /* fmax(rn, ar) without the call: a NaN entry is passed over as fmax does */
        if (as > sc) sc = as;
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
    if (gal_dense_lu_factor(m->J, r, m->piv)) return gal_error(GAL_EFAIL, "reduced model: singular iteration matrix");
    m->hJ = h;
    return GAL_OK;
}

/* fi1 += Kr (x1 - xs), xs into the start's value: the internal force carried over a correction */
static void carry_internal(gal_rom *m, double *xs)
{
    int r = m->r;
    for (int k = 0; k < r; k++) xs[k] = m->x1[k] - xs[k];
    mult(r, m->Kr, xs, m->fi1, 1);
}

/* The largest entry of fi(x1) - fi - Kr (x1 - x) at the predictor x1 over the step's force scale
 * (the Newton test's: the largest |fi1| + |fe1| entry, at least fscale): what the kept tangent
 * misses of the internal force over the predictor, plus the error that the state's own force
 * carries from an earlier linear step. m->da and m->res are scratch. */
static double linear_error(gal_rom *m)
{
    int r = m->r;
    double e = 0, sc = m->fscale;
    for (int k = 0; k < r; k++) m->da[k] = m->x1[k] - m->x[k];
    mult(r, m->Kr, m->da, m->res, 0);
    for (int k = 0; k < r; k++) {
        e = fmax(e, fabs(m->fi1[k] - m->fi[k] - m->res[k]));
        sc = fmax(sc, fabs(m->fi1[k]) + fabs(m->fe1[k]));
    }
    return isfinite(e) ? e / sc : INFINITY;
}

/* A Newton correction from m->res taken as the step's last (o.newton_carry): a1, x1, v1 updated,
 * the internal force carried over it by the kept tangent (its energy m->U1 is the last evaluated:
 * only the discrete gradient, rho_inf = 1, reads it). */
static void carry_correction(gal_rom *m, double h)
{
    int r = m->r;
    double *xs = m->fdg; /* scratch: rho_inf < 1 has no discrete gradient */
    for (int k = 0; k < r; k++) m->da[k] = -m->res[k];
    gal_dense_lu_solve(m->J, r, m->piv, m->da);
    memcpy(xs, m->x1, (size_t)r * sizeof(double));
    for (int k = 0; k < r; k++) m->a1[k] += m->da[k];
    newmark(m, h);
    carry_internal(m, xs);
}

/* A linearly implicit step (o.one_pass): the internal force at the predictor, the loads
 * extrapolated; a correction; the loads there (held); a second correction; the internal force
 * carried over both by the kept tangent Kr, whose matrix J is factored for h (o.one_pass: after a
 * Newton step that converged within two passes with it). LINEAR_REJECT, nothing done, when the
 * kept tangent misses the force at the predictor by more than GAL_ROM_LINEAR_TOL (linear_error):
 * the carried forces' errors then grow from step to step (measured on data/scenes/iced_gallop.ini
 * past 500 elements: the stiffest basis vector, the torsional mode's modal derivative, localizes at
 * the node next to a support and its h omega grows with the mesh, 6.1 up to 500 elements, 8.9 at
 * 800, 11 at 1000; there the error went from 0.1 to 1 in five linear steps and the rod's energy at
 * element 0 then was not finite). */
static int linear_step(gal_rom *m, double h)
{
    int r = m->r, st;
    double rs, raw;
    newmark(m, h);
    if ((st = gal_rom_eval_internal(m, m->x1, m->fi1, NULL))) return st;
    for (int k = 0; k < r; k++) m->fe1[k] = m->hfe == h ? 2 * m->fe[k] - m->fe_prev[k] : m->fe[k];
    if (!(linear_error(m) <= GAL_ROM_LINEAR_TOL)) return LINEAR_REJECT;
    for (int pass = 0; pass < 2; pass++) {
        if (!isfinite(residual(m, &rs, &raw))) return gal_error(GAL_EFAIL, "reduced model: the residual is not finite");
        carry_correction(m, h);
        if (!pass && (st = gal_rom_eval_external(m, m->t + h, m->x1, m->v1, m->fe1))) return st;
    }
    return GAL_OK;
}

/* The loads at Newton pass `it` into m->fe1: at every pass, or (once: o.loads_once) extrapolated
 * over the last two steps of h at the first (measured: the loads at the predictor instead, held,
 * miss a 5:1 twist resonance by 2x), evaluated at the second and held. */
static int pass_loads(gal_rom *m, int it, int once, double h)
{
    if (once && it == 0) {
        for (int k = 0; k < m->r; k++) m->fe1[k] = m->hfe == h ? 2 * m->fe[k] - m->fe_prev[k] : m->fe[k];
        return GAL_OK;
    }
    if (once && it != 1) return GAL_OK;
    return gal_rom_eval_external(m, m->t + h, m->x1, m->v1, m->fe1);
}

/* o.newton_carry: the kept matrix's contraction c = rn / prev over the last correction, measured on
 * the same equations (with o.loads_once from the third pass: the second's loads changed), at most
 * o.newton_contraction, and the residual it predicts after the next correction, c rn, within
 * GAL_ROM_CARRY_TOL of the tolerance (the convergence test of CVODE's and IDA's Newton, Hindmarsh et
 * al. 2005: a correction times the convergence rate). Measured on data/scenes/iced_gallop.ini at
 * 600 elements: carried from the second pass of o.loads_once too (its contraction taken before the
 * loads changed), the twist read 23-31 deg against 18.1 at 80 (Newton confirming every correction:
 * 21.5-21.8; from the third pass: 18.7-19.4; the full model 18.3). */
static int carry_ok(const gal_rom *m, int it, int once, double rn, double prev)
{
    double c = rn / prev;
    return it >= (once ? 2 : 1) && isfinite(prev) && c <= m->o.newton_contraction && rn * c <= GAL_ROM_CARRY_TOL;
}

/* o.one_pass applies: the loads once a step, rho_inf < 1, a linear basis */
static int linear_steps(const gal_rom *m)
{
    return m->o.one_pass > 0 && m->o.loads_once && m->force.eval && m->o.rho_inf < 1 && !m->qm;
}

/* Newton on a1 for one step of h from the state; x1, v1, a1, fi1, fe1 hold the result. */
static int newton(gal_rom *m, double h)
{
    int r = m->r, st = GAL_OK;
    double t1 = m->t + h;
    memcpy(m->a1, m->a, (size_t)r * sizeof(double));
    if (linear_steps(m) && m->hJ == h && m->lin_ok && m->steps % m->o.one_pass) {
        if ((st = linear_step(m, h)) != LINEAR_REJECT) return st;
        /* a Newton step instead, from the state's own force (it may carry a linear step's error) */
        m->linear_rejections++;
        if ((st = gal_rom_eval_internal(m, m->x, m->fi, NULL))) return st;
        m->U = m->U1;
        memcpy(m->a1, m->a, (size_t)r * sizeof(double));
    }
    if (m->qm && m->qm->inertia) gal_rom_qm_begin(m);
    /* modified Newton: the iteration matrix of an earlier step is kept (o.reuse_tangent) while it
     * converges fast; a fresh tangent whenever an iteration did not gain a factor of 10 (the
     * stretching directions are strongly nonlinear) */
    int it, conv = 0, fresh = !(m->o.reuse_tangent && m->hJ == h), kept = !fresh;
    double prev = INFINITY, rawprev = INFINITY;
    int once = m->o.loads_once && m->force.eval; /* the loads at the first correction (it = 1) alone */
    int carry = m->o.newton_carry && m->o.rho_inf != 1.0 && !m->qm;
    for (it = 0; it < m->o.max_newton; it++) {
        newmark(m, h);
        if ((st = gal_rom_eval_internal(m, m->x1, m->fi1, fresh ? m->Kr : NULL))) break;
        if ((st = pass_loads(m, it, once, h))) break;
        if (m->qm && m->qm->inertia) gal_rom_qm_end(m, h);
        double rs, raw, rn = residual(m, &rs, &raw);
        /* as the full model (dynamics.c): within a looser tolerance than GAL_NEWTON_TOL_STRICT's
         * only after a correction that reduced the residual */
        if ((rs <= 1 || (it > 0 && rn <= 1 && raw < rawprev)) && !(once && it == 0)) { conv = 1; break; }
        if (!isfinite(rn)) { st = gal_error(GAL_EFAIL, "reduced model: the residual is not finite"); break; }
        if (carry && !fresh && carry_ok(m, it, once, rn, prev)) { /* the last correction, unconfirmed */
            carry_correction(m, h);
            m->newton_iterations++, m->carried++;
            conv = 1;
            break;
        }
        if (once && it == 1) prev = INFINITY; /* the loads changed from their extrapolation: no contraction to judge */
        if (!fresh && (rn > m->o.newton_contraction * prev || (kept && it >= m->o.newton_kept_max))) {
            fresh = 1, kept = 0;
            if ((st = gal_rom_eval_internal(m, m->x1, m->fi1, m->Kr))) break;
        }
        prev = rn, rawprev = raw;
        if (fresh) {
            if ((st = iteration_matrix(m, h))) break;
            fresh = 0;
        }
        for (int k = 0; k < r; k++) m->da[k] = -m->res[k];
        gal_dense_lu_solve(m->J, r, m->piv, m->da);
        for (int k = 0; k < r; k++) m->a1[k] += m->da[k];
        m->newton_iterations++;
    }
    m->lin_ok = conv && it <= 1; /* within two passes: the kept tangent is good enough for o.one_pass */
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
    memcpy(m->fe_prev, m->fe, (size_t)r * sizeof(double));
    memcpy(m->fe, m->fe1, (size_t)r * sizeof(double));
    m->hfe = h;
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
    /* a step: Newton's usual two passes of the energy (one on o.one_pass's linear steps), and the
     * loads once (o.loads_once) or twice */
    double pe = linear_steps(m) ? 1.0 + 1.0 / m->o.one_pass : 2.0;
    double sample = pe * h->set[0].n + (loads ? (h->loads ? h->set[1].n : nel) * (m->o.loads_once ? 1.0 : 2.0) : 0);
    double check = 2.0 * (gal_rod_element_count(m->rod) + (loads ? nel : 0)); /* the sample's and the residual's */
    double per_s = sample / m->o.h; /* the steps' element evaluations per simulated second */
    return fmax(base_s, check / (GAL_ROM_CHECK_SHARE * per_s));
}

int gal_rom_step(gal_rom *m)
{
    double t1 = m->t + m->o.h;
    int st = m->o.scheme != GAL_ROM_SCHEME_GALPHA ? gal_rom_irk_step(m, m->o.h) : step(m, m->o.h, 0);
    if (st) return gal_error(st, "at t = %.6g s (after %d step halvings): %s", t1, GAL_ROM_HALVINGS, gal_error_message());
    /* the sample against the exact projected forces every hyper_check_interval */
    if (m->hyper && m->o.hyper_check_interval > 0 && m->t >= m->next_hyper_check - 1e-3 * m->o.h) {
        m->next_hyper_check = m->t + gal_rom_check_interval(m, m->o.hyper_check_interval);
        return gal_rom_sample_check(m);
    }
    return GAL_OK;
}

int gal_rom_sample_check(gal_rom *m)
{
    if (!m->hyper) return GAL_OK;
    long e0 = m->element_evaluations, l0 = m->load_element_evaluations;
    int st = gal_rom_hyper_check(m, NULL); /* the exact forces over the whole rod, and the sample's */
    m->check_element_evaluations += gal_rod_element_count(m->rod) + (m->hyper->loads ? m->rod->p.elements : 0) +
                                    m->element_evaluations - e0 + m->load_element_evaluations - l0;
    m->element_evaluations = e0, m->load_element_evaluations = l0;
    if (st) return gal_error(st, "at t = %.6g s: %s", m->t, gal_error_message());
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

