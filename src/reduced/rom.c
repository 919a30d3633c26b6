/* rom.c: the recomputed reduced model's (rom.h) evaluations: the reconstruction of the full state,
 * the reduced internal force (and tangent) and loads, whole or from the sample (ecsw_eval.c), the
 * rates, probes, tensions and energy of the reduced state. Its time step is in rom_step.c. */
#include "gallop/reduced/rom.h"
#include "gallop/base/core.h"
#include "gallop/reduced/ecsw.h"
#include "reduced/hyper.h"
#include "reduced/qm.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* s += V y (and t += V z when z) over V's columns k0 .. k1-1, one at a time: each entry's sum over
 * the columns in order, a column whose coefficient is 0 left out (it adds +-0) */
static void accumulate_columns(const double *V, int n, int k0, int k1, const double *y, const double *z, double *s,
                               double *t)
{
    for (int k = k0; k < k1; k++) {
        const double *vk = V + (size_t)k * n;
        if (y[k] != 0)
            for (int d = 0; d < n; d++) s[d] += vk[d] * y[k];
        if (z && z[k] != 0)
            for (int d = 0; d < n; d++) t[d] += vk[d] * z[k];
    }
}

/* accumulate_columns over V's r columns with its numbers, four columns a pass over the entries
 * where none of their coefficients is 0 (V read once for both vectors, s and t once a pass) */
static void accumulate(const double *V, int n, int r, const double *y, const double *z, double *s, double *t)
{
    int k = 0;
    for (; k + 4 <= r; k += 4) {
        const double *v0 = V + (size_t)k * n, *v1 = v0 + n, *v2 = v1 + n, *v3 = v2 + n;
        double y0 = y[k], y1 = y[k + 1], y2 = y[k + 2], y3 = y[k + 3];
        int yall = y0 != 0 && y1 != 0 && y2 != 0 && y3 != 0;
        if (yall && z && z[k] != 0 && z[k + 1] != 0 && z[k + 2] != 0 && z[k + 3] != 0) {
            double z0 = z[k], z1 = z[k + 1], z2 = z[k + 2], z3 = z[k + 3];
            for (int d = 0; d < n; d++) {
                double a = v0[d], b = v1[d], c = v2[d], e = v3[d];
                s[d] = s[d] + a * y0 + b * y1 + c * y2 + e * y3;
                t[d] = t[d] + a * z0 + b * z1 + c * z2 + e * z3;
            }
        } else if (yall && !z) {
            for (int d = 0; d < n; d++) s[d] = s[d] + v0[d] * y0 + v1[d] * y1 + v2[d] * y2 + v3[d] * y3;
        } else accumulate_columns(V, n, k, k + 4, y, z, s, t);
    }
    accumulate_columns(V, n, k, r, y, z, s, t);
}

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
    double *s = m->wn, *sv = m->wn2;
    memset(s, 0, (size_t)n * sizeof(double)), memset(sv, 0, (size_t)n * sizeof(double));
    accumulate(m->V, n, r, x, xd, s, sv);
    for (int d = 0; d < n; d++) {
        m->q[rod->free_q[d]] += s[d];
        if (xd) m->vq[rod->free_q[d]] = sv[d];
    }
}

const double *gal_rom_basis_at(gal_rom *m, const double *x)
{
    return m->qm ? gal_rom_qm_basis(m, x) : m->V;
}

/* f = B^T (free part of a configuration-sized vector g), B the tangent basis at x (ecsw_project.c's
 * four columns a pass, each sum over the entries in order) */
static void project(gal_rom *m, const double *x, const double *g, double *f)
{
    gal_rom_project_free(m, gal_rom_basis_at(m, x), g, NULL, f, NULL);
}

/* The reduced equations' own acceleration at the state into ac: fe - Cr v - fi (the integrator's
 * a lags it by the step's truncation error). m->da is scratch. */
static int consistent_acceleration(gal_rom *m, double *ac)
{
    int r = m->r, st = gal_rom_eval_internal(m, m->x, ac, NULL);
    if (!st) st = gal_rom_eval_external(m, m->t, m->x, m->v, m->da);
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
int gal_rom_eval_internal(gal_rom *m, const double *x, double *f, double *Kr)
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
int gal_rom_eval_external(gal_rom *m, double t, const double *x, const double *xd, double *f)
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
    return gal_rom_eval_internal(m, x, f, NULL);
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
