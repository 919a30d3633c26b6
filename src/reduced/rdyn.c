/* rdyn.c: the reduced equations of motion on the modes, integrated by GSL odeiv2 (rk8pd). */
#include "gallop/reduced/rdyn.h"
#include "gallop/base/core.h"
#include "gallop/base/vec3.h"

#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

gal_rdyn *gal_rdyn_free(gal_rdyn *d)
{
    if (d) {
        free(d->wq); free(d->req); free(d->teq); free(d->aeq); free(d->phr); free(d->phs); free(d->pht);
        free(d->damp); free(d->y); free(d->fr); free(d->fl); free(d->nt); free(d->ob); free(d->obr); free(d->y_prev);
        if (d->drv) gsl_odeiv2_driver_free(d->drv);
        free(d);
    }
    return NULL;
}

/* y = (eta, eta'): eta'' = F(t, eta, eta') - damp eta' - f(eta) */
static int rhs(double t, const double y[], double dydt[], void *params)
{
    gal_rdyn *d = params;
    int r = d->r;
    const double *eta = y, *deta = y + r;
    d->rhs_evaluations++;
    gal_reduced_force(d->rm, eta, d->fr);
    memset(d->fl, 0, (size_t)r * sizeof(double));
    if (d->load.eval) {
        if (d->obs_offset >= 0) gal_reduced_observe_rate(d->rm, eta, deta, d->ob, d->obr);
        for (int q = 0; q < d->nqp; q++) {
            const double *P = d->phr + (size_t)q * r * 3, *Ps = d->phs + (size_t)q * r * 3, *Pt = d->pht + (size_t)q * r;
            double pos[3], vel[3] = {0, 0, 0}, rs[3], th = 0;
            for (int k = 0; k < 3; k++) pos[k] = d->req[3 * q + k], rs[k] = d->teq[3 * q + k];
            if (d->obs_offset >= 0) {
                /* the expansion: the condensed motion (stretching, the rise of a swinging span)
                 * moves the points too */
                const double *o = d->ob + d->obs_offset + 7 * q, *orate = d->obr + d->obs_offset + 7 * q;
                for (int k = 0; k < 3; k++) {
                    pos[k] += o[k];
                    vel[k] = orate[k];
                    rs[k] += o[3 + k] / d->nt[q];
                }
                th = o[6];
            } else {
                for (int i = 0; i < r; i++) {
                    for (int k = 0; k < 3; k++) {
                        pos[k] += P[3 * i + k] * eta[i];
                        vel[k] += P[3 * i + k] * deta[i];
                        rs[k] += Ps[3 * i + k] * eta[i];
                    }
                    th += Pt[i] * eta[i];
                }
            }
            /* tangent and reference director: the equilibrium director carried by the minimal
             * rotation to the current tangent, turned by the twist */
            double nrm = sqrt(gal_dot3(rs, rs)), tg[3], a[3], b[3], d1[3];
            for (int k = 0; k < 3; k++) tg[k] = rs[k] / nrm;
            const double *te = d->teq + 3 * q, *ae = d->aeq + 3 * q;
            double fct = gal_dot3(tg, ae) / (1.0 + gal_dot3(te, tg));
            for (int k = 0; k < 3; k++) a[k] = ae[k] - fct * (te[k] + tg[k]);
            gal_cross3(tg, a, b);
            for (int k = 0; k < 3; k++) d1[k] = cos(th) * a[k] + sin(th) * b[k];
            double f[3] = {0, 0, 0}, m = 0;
            int st = d->load.eval(d->load.ctx, t, pos[0], pos, vel, tg, d1, f, &m);
            if (st) { d->status = st; return GSL_EBADFUNC; }
            for (int i = 0; i < r; i++)
                d->fl[i] += d->wq[q] * (P[3 * i] * f[0] + P[3 * i + 1] * f[1] + P[3 * i + 2] * f[2] + Pt[i] * m);
        }
    }
    for (int j = 0; j < r; j++)
        for (int i = 0; i < r; i++) d->fl[i] -= d->damp[(size_t)j * r + i] * deta[j];
    for (int i = 0; i < r; i++) {
        dydt[i] = deta[i];
        dydt[r + i] = d->fl[i] - d->fr[i];
        if (!isfinite(dydt[r + i])) {
            d->status = gal_error(GAL_EFAIL, "reduced model: the %s force of mode %d is not finite at t = %.6g s",
                                  !isfinite(d->fl[i]) ? "aerodynamic" : "restoring", i + 1, t);
            return GSL_EBADFUNC;
        }
    }
    return GSL_SUCCESS;
}

/* The quadrature: Gauss-Legendre, 2 points on each of nqp/2 equal segments of the unstretched
 * length; s_q and the element holding it. */
static void quad_point(const gal_rod *rod, int nqp, int q, int *e, double *xi, double *w, int *e0, int *e1, double *w1)
{
    int nel = rod->p.elements, nseg = nqp / 2;
    double L0 = rod->p.unstretched_length, l0 = L0 / nel;
    double gx = (q % 2) ? 0.5 + 0.5 / sqrt(3.0) : 0.5 - 0.5 / sqrt(3.0);
    double s = (q / 2 + gx) * L0 / nseg;
    *w = 0.5 * L0 / nseg;
    *e = (int)(s / l0);
    if (*e > nel - 1) *e = nel - 1;
    *xi = s / l0 - *e;
    double se = s / l0 - 0.5;
    *e0 = (int)floor(se);
    *w1 = se - *e0;
    if (*e0 < 0) *e0 = 0, *w1 = 0;
    if (*e0 >= nel - 1) *e0 = nel - 1, *w1 = 0;
    *e1 = *e0 + 1 < nel ? *e0 + 1 : *e0;
}

static int alloc_arrays(gal_rdyn *d, const gal_reduced *rm, int nqp, int obs_offset)
{
    int r = rm->r;
    d->wq = malloc((size_t)nqp * sizeof(double));
    d->req = malloc((size_t)3 * nqp * sizeof(double));
    d->teq = malloc((size_t)3 * nqp * sizeof(double));
    d->aeq = malloc((size_t)3 * nqp * sizeof(double));
    d->phr = calloc((size_t)nqp * r * 3, sizeof(double));
    d->phs = calloc((size_t)nqp * r * 3, sizeof(double));
    d->pht = calloc((size_t)nqp * r, sizeof(double));
    d->damp = calloc((size_t)r * r, sizeof(double));
    d->y = calloc((size_t)2 * r, sizeof(double));
    d->y_prev = calloc((size_t)2 * r, sizeof(double));
    d->fr = malloc((size_t)r * sizeof(double));
    d->fl = malloc((size_t)r * sizeof(double));
    d->nt = malloc((size_t)nqp * sizeof(double));
    d->obs_offset = obs_offset;
    if (obs_offset >= 0) {
        if (obs_offset + 7 * nqp > rm->nobs)
            return gal_error(GAL_EINPUT, "reduced model: %d observations, the quadrature needs %d from %d", rm->nobs, 7 * nqp, obs_offset);
        d->ob = malloc((size_t)rm->nobs * sizeof(double));
        d->obr = malloc((size_t)rm->nobs * sizeof(double));
        if (!d->ob || !d->obr) return gal_error(GAL_ENOMEM, "reduced model: out of memory");
    }
    if (!d->wq || !d->req || !d->teq || !d->aeq || !d->phr || !d->phs || !d->pht || !d->damp || !d->y || !d->y_prev ||
        !d->fr || !d->fl || !d->nt)
        return gal_error(GAL_ENOMEM, "reduced model: out of memory");
    return GAL_OK;
}

/* The quadrature tables: at each point its weight, equilibrium position, unit tangent, reference
 * director and |dr/ds|, and the mode shapes there (translation, its derivative along s, twist);
 * `full` holds the modes over the whole configuration (r x nq). */
static void quadrature_tables(gal_rdyn *d, const gal_rod *rod, const double *q_eq, const double *full)
{
    int r = d->r, nn = rod->nn, nel = rod->p.elements;
    double l0 = rod->p.unstretched_length / nel;
    for (int q = 0; q < d->nqp; q++) {
        int e, e0, e1;
        double xi, w1;
        quad_point(rod, d->nqp, q, &e, &xi, &d->wq[q], &e0, &e1, &w1);
        for (int k = 0; k < 3; k++) {
            d->req[3 * q + k] = (1 - xi) * q_eq[3 * e + k] + xi * q_eq[3 * (e + 1) + k];
            d->teq[3 * q + k] = (q_eq[3 * (e + 1) + k] - q_eq[3 * e + k]) / l0; /* dr/ds */
        }
        double tt[3], a[3];
        gal_rod_material_frame(rod, q_eq, e, tt, a);
        /* reference director normal to the tangent at equilibrium; twist is added by pht */
        for (int k = 0; k < 3; k++) d->aeq[3 * q + k] = a[k];
        /* keep teq as the unit tangent for the frame transport and rs as dr/ds: since
         * |dr/ds| differs from 1 only by the strain, normalize */
        double nt = sqrt(gal_dot3(d->teq + 3 * q, d->teq + 3 * q));
        d->nt[q] = nt;
        for (int k = 0; k < 3; k++) d->teq[3 * q + k] /= nt;
        /* twist at s: piecewise linear between edge centres (e0, e1, w1) */
        for (int i = 0; i < r; i++) {
            const double *F = full + (size_t)i * rod->nq;
            for (int k = 0; k < 3; k++) {
                d->phr[((size_t)q * r + i) * 3 + k] = (1 - xi) * F[3 * e + k] + xi * F[3 * (e + 1) + k];
                d->phs[((size_t)q * r + i) * 3 + k] = (F[3 * (e + 1) + k] - F[3 * e + k]) / l0 / nt;
            }
            if (rod->p.torsion)
                d->pht[(size_t)q * r + i] = (1 - w1) * F[3 * nn + e0] + w1 * F[3 * nn + e1];
        }
    }
}

/* GSL's rk8pd driver. The error per step: tol relative to the state, and tol times the
 * identification amplitude (and that amplitude times the frequency for the velocities) in absolute
 * terms, so that a state at rest is not held to a zero error. */
static int driver(gal_rdyn *d, double h0)
{
    const gal_reduced *rm = d->rm;
    int r = d->r;
    d->sys.function = rhs;
    d->sys.jacobian = NULL;
    d->sys.dimension = (size_t)2 * r;
    d->sys.params = d;
    double *sc = malloc((size_t)2 * r * sizeof(double));
    if (!sc) return gal_error(GAL_ENOMEM, "reduced model: out of memory");
    for (int i = 0; i < r; i++) sc[i] = rm->eta_ref[i], sc[r + i] = rm->eta_ref[i] * sqrt(rm->omega2[i]);
    d->drv = gsl_odeiv2_driver_alloc_scaled_new(&d->sys, gsl_odeiv2_step_rk8pd, h0, d->tol, d->tol, 1.0, 0.0, sc);
    free(sc);
    if (!d->drv) return gal_error(GAL_ENOMEM, "reduced model: cannot allocate the ODE driver");
    gsl_odeiv2_driver_set_hmin(d->drv, 1e-10);
    return GAL_OK;
}

gal_rdyn *gal_rdyn_alloc(const gal_reduced *rm, const gal_rod *rod, const double *q_eq, const gal_damping *damping,
                         const gal_pointload *load, int nqp, double tol, double h0, int obs_offset)
{
    gal_rdyn *d = calloc(1, sizeof *d);
    if (!d) return NULL;
    int r = rm->r, n = rm->ndof;
    d->rm = rm, d->r = r, d->nqp = nqp, d->tol = tol;
    if (load) d->load = *load;
    if (alloc_arrays(d, rm, nqp, obs_offset)) return gal_rdyn_free(d);
    double *full = calloc((size_t)rod->nq * r, sizeof(double));
    if (!full) {
        gal_error(GAL_ENOMEM, "reduced model: out of memory");
        return gal_rdyn_free(d);
    }
    if (damping && gal_damping_project(damping, rm->phi, r, d->damp)) {
        free(full);
        return gal_rdyn_free(d);
    }
    for (int i = 0; i < r; i++) {
        for (int j = 0; j < n; j++) full[(size_t)i * rod->nq + rod->free_q[j]] = rm->phi[(size_t)i * n + j];
    }
    quadrature_tables(d, rod, q_eq, full);
    free(full);
    if (driver(d, h0)) return gal_rdyn_free(d);
    return d;
}

void gal_rdyn_quadrature_obs(const gal_rod *rod, int nqp, gal_obs *obs)
{
    double l0 = rod->p.unstretched_length / rod->p.elements;
    for (int q = 0; q < nqp; q++) {
        int e, e0, e1;
        double xi, w, w1;
        quad_point(rod, nqp, q, &e, &xi, &w, &e0, &e1, &w1);
        gal_obs *o = obs + 7 * q;
        for (int k = 0; k < 3; k++) {
            o[k] = (gal_obs){{3 * e + k, 3 * (e + 1) + k}, {1 - xi, xi}};
            o[3 + k] = (gal_obs){{3 * e + k, 3 * (e + 1) + k}, {-1 / l0, 1 / l0}};
        }
        if (rod->p.torsion) o[6] = (gal_obs){{3 * rod->nn + e0, 3 * rod->nn + e1}, {1 - w1, w1}};
        else o[6] = (gal_obs){{-1, -1}, {0, 0}};
    }
}

int gal_rdyn_advance(gal_rdyn *d, double t_target)
{
    d->status = GAL_OK;
    int st = gsl_odeiv2_driver_apply(d->drv, &d->t, t_target, d->y);
    if (st != GSL_SUCCESS) {
        if (d->status != GAL_OK) return d->status;
        return gal_error(GAL_EFAIL, "reduced model: the integrator failed at t = %.6g s (GSL status %d: %s)",
                         d->t, st, gsl_strerror(st));
    }
    return GAL_OK;
}

int gal_rdyn_sample(gal_rdyn *d, double t_out, double t_end, double *y_out)
{
    int r = d->r;
    d->status = GAL_OK;
    if (d->t == 0 && d->t_prev == 0) memcpy(d->y_prev, d->y, (size_t)2 * r * sizeof(double));
    while (d->t < t_out) {
        d->t_prev = d->t;
        memcpy(d->y_prev, d->y, (size_t)2 * r * sizeof(double));
        int st = gsl_odeiv2_evolve_apply(d->drv->e, d->drv->c, d->drv->s, &d->sys, &d->t, t_end, &d->drv->h, d->y);
        if (st != GSL_SUCCESS || !(d->t > d->t_prev)) {
            if (d->status != GAL_OK) return d->status;
            return gal_error(GAL_EFAIL, "reduced model: the integrator failed at t = %.6g s (GSL status %d: %s)",
                             d->t, st, gsl_strerror(st));
        }
        if (d->drv->h < 1e-10)
            return gal_error(GAL_EFAIL, "reduced model: the step size fell to %.3g s at t = %.6g s", d->drv->h, d->t);
    }
    double h = d->t - d->t_prev;
    if (h <= 0) {
        memcpy(y_out, d->y, (size_t)2 * r * sizeof(double));
        return GAL_OK;
    }
    /* cubic Hermite on [t_prev, t] for eta with eta' as slopes; eta' from its derivative */
    double s = (t_out - d->t_prev) / h, s2 = s * s, s3 = s2 * s;
    double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
    double d00 = (6 * s2 - 6 * s) / h, d10 = 3 * s2 - 4 * s + 1, d01 = (-6 * s2 + 6 * s) / h, d11 = 3 * s2 - 2 * s;
    for (int i = 0; i < r; i++) {
        double p0 = d->y_prev[i], m0 = d->y_prev[r + i], p1 = d->y[i], m1 = d->y[r + i];
        y_out[i] = h00 * p0 + h10 * h * m0 + h01 * p1 + h11 * h * m1;
        y_out[r + i] = d00 * p0 + d10 * m0 + d01 * p1 + d11 * m1;
    }
    return GAL_OK;
}

void gal_rdyn_counts(const gal_rdyn *d, long *steps, long *rejected)
{
    *steps = (long)d->drv->e->count;
    *rejected = (long)d->drv->e->failed_steps;
}
