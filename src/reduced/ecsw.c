/* ecsw.c: energy-conserving sampling and weighting of the recomputed reduced model (ecsw.h):
 * the sample's build (its training in ecsw_train.c), the constants, the sampled entries of the
 * basis, and the check that re-samples. The evaluations from the sample
 * are in ecsw_eval.c. */
#include "gallop/reduced/ecsw.h"
#include "gallop/base/core.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "reduced/hyper.h"
#include "reduced/qm.h"

void gal_rom_hyper_free(gal_rom *m)
{
    gal_rom_hyper *h = m->hyper;
    if (!h) return;
    for (int s = 0; s < 2; s++) {
        free(h->set[s].elem), free(h->set[s].w), free(h->set[s].idx), free(h->set[s].uq), free(h->set[s].Vu), free(h->set[s].rw);
        free(h->set[s].Qz), free(h->set[s].Tt), free(h->set[s].Pc), free(h->set[s].qs);
    }
    free(h->T); free(h->gu); free(h->fc); free(h->Kc); free(h->snap); free(h->F0); free(h->emax);
    free(h->whole_g); free(h->whole_f); free(h->whole_xv);
    free(h);
    m->hyper = NULL;
}

/* Each sample's free configuration entries (uq, their V rows Vu) and each sampled element's
 * local map into them (idx: GAL_ROD_ELEMENT_NQ per element, -1 where absent, fixed, or not the
 * load's: a load element has x_j, x_{j+1}, theta_j). */
static int sample_entries(gal_rom *m)
{
    gal_rom_hyper *h = m->hyper;
    const gal_rod *rod = m->rod;
    int n = m->ndof, r = m->r, NQ = GAL_ROD_ELEMENT_NQ, qi[GAL_ROD_ELEMENT_NQ];
    int *where = malloc((size_t)m->nq * sizeof(int));
    if (!where) return gal_error(GAL_ENOMEM, "reduced model: out of memory for the sample");
    for (int s = 0; s < 2; s++) {
        gal_rom_hyper_set *S = &h->set[s];
        int nu = 0;
        for (int k = 0; k < m->nq; k++) where[k] = -1;
        for (int k = 0; k < S->n; k++) {
            gal_rod_element_q(rod, S->elem[k], qi);
            for (int a = 0; a < NQ; a++) {
                int d = qi[a] < 0 ? -1 : rod->dof[qi[a]];
                if (s == 1 && !(a < 6 || a == 9)) d = -1;
                if (d >= 0 && where[qi[a]] < 0) where[qi[a]] = nu++;
                S->idx[k * NQ + a] = d < 0 ? -1 : where[qi[a]];
            }
        }
        free(S->uq), free(S->Vu), free(S->Qz), free(S->Tt), free(S->Pc), free(S->qs);
        S->Qz = S->Tt = S->Pc = S->qs = NULL;
        int nu1 = nu ? nu : 1;
        S->uq = malloc((size_t)nu1 * sizeof(int)), S->Vu = malloc((size_t)nu1 * r * sizeof(double));
        S->Pc = malloc((size_t)nu1 * r * sizeof(double)); /* also the tangent's scratch (ecsw_eval.c) */
        if (!S->uq || !S->Vu || !S->Pc) { free(where); return gal_error(GAL_ENOMEM, "reduced model: out of memory for the sample"); }
        if (m->qm) {
            int np = m->qm->np;
            S->Qz = malloc((size_t)nu1 * (r + np) * sizeof(double)), S->Tt = malloc((size_t)nu1 * r * r * sizeof(double));
            S->qs = malloc((size_t)nu1 * sizeof(double));
            if (!S->Qz || !S->Tt || !S->qs) { free(where); return gal_error(GAL_ENOMEM, "reduced model: out of memory for the sample"); }
        }
        for (int qk = 0; qk < m->nq; qk++) {
            int u = where[qk];
            if (u < 0) continue;
            S->uq[u] = qk;
            for (int k = 0; k < r; k++) S->Vu[(size_t)u * r + k] = m->V[(size_t)k * n + rod->dof[qk]];
            if (!m->qm) continue;
            const double *Th = m->qm->Th;
            for (int c = 0; c < r + m->qm->np; c++)
                S->Qz[(size_t)c * nu + u] = c < r ? m->V[(size_t)c * n + rod->dof[qk]] : Th[(size_t)(c - r) * n + rod->dof[qk]];
            for (int j = 0; j < r; j++)
                for (int k = 0; k < r; k++)
                    S->Tt[((size_t)j * r + k) * nu + u] = Th[(size_t)m->qm->pair[k * r + j] * n + rod->dof[qk]];
        }
        S->nu = nu;
    }
    free(where);
    return GAL_OK;
}

/* Whether the span is its own mirror image (level, no eccentric ice, a symmetric equilibrium). */
static int mirror_symmetric(const gal_rom *m)
{
    const gal_rod *rod = m->rod;
    double L = rod->p.length, tol = 1e-9 * L;
    if (rod->p.height_difference != 0 || rod->ecc_c) return 0;
    for (int i = 0; i < rod->nn; i++) {
        const double *a = m->q_eq + 3 * i, *b = m->q_eq + 3 * (rod->nn - 1 - i);
        if (fabs(a[0] + b[0] - L) > tol || fabs(a[1] - b[1]) > tol || fabs(a[2] - b[2]) > tol) return 0;
    }
    return 1;
}

/* The constants U_c, f_c, K_c: U_h, its gradient and its Hessian equal U, V^T grad U and
 * V^T K0 V at the equilibrium (the linear dynamics, the modes' frequencies, are exact); and the
 * round-off of U_h, m->ufloor: an element's energy moves by |g_e| |q_e| eps when its coordinates
 * are rounded (the tension times the coordinates' round-off), summed with the weights, times
 * UFLOOR_SAFETY. */
#define UFLOOR_SAFETY 4.0
static int constants(gal_rom *m)
{
    gal_rom_hyper *h = m->hyper;
    const gal_rod *rod = m->rod;
    int r = m->r, qi[GAL_ROD_ELEMENT_NQ];
    double U0, Ue, g[GAL_ROD_ELEMENT_NQ], fl = 0, *col = m->fr, *Ke = m->Kr; /* Kr: scratch, refreshed after */
    gal_rom_reconstruct_at(m, NULL, NULL);
    int st = gal_rod_eval(rod, m->q, &U0, m->gq, NULL);
    if (st) return st;
    memcpy(h->fc, h->F0, (size_t)r * sizeof(double));
    memcpy(h->Kc, m->K0r, (size_t)r * r * sizeof(double));
    if (m->qm) gal_rom_qm_curvature(m, m->gq, h->Kc); /* the exact Hessian at the equilibrium */
    h->Uc = U0;
    const gal_rom_hyper_set *S = &h->set[0];
    for (int k = 0; k < S->n; k++) {
        gal_rod_element_q(rod, S->elem[k], qi);
        if ((st = gal_rod_element_eval(rod, S->elem[k], m->q, &Ue, g, NULL))) return st;
        if ((st = gal_rom_hyper_element_reduced(m, S->elem[k], col, Ke))) return st;
        for (int i = 0; i < r; i++) h->fc[i] -= S->w[k] * col[i];
        for (int i = 0; i < r * r; i++) h->Kc[i] -= S->w[k] * Ke[i];
        h->Uc -= S->w[k] * Ue;
        double ue = 0;
        for (int i = 0; i < GAL_ROD_ELEMENT_NQ; i++)
            if (qi[i] >= 0) ue += fabs(g[i] * m->q[qi[i]]);
        fl += S->w[k] * ue;
    }
    m->ufloor = UFLOOR_SAFETY * 2.2e-16 * fl;
    m->hJ = 0;
    return GAL_OK;
}

#define LOADS_WHOLE 0.5

/* The samples fitted again on the training states held after a failed check (fail[0]: the rod's
 * energy, fail[1]: the loads'): the rod's failing, both (one pass) and the constants, as before;
 * the loads' alone failing (turbulent wind: BENCHMARKS.md, helper turbsample), the loads' alone, the
 * rod's sample and constants left as they were. Then the sampled entries. */
static int resample(gal_rom *m, const int fail[2])
{
    gal_rom_hyper *h = m->hyper;
    int st = fail[0] ? gal_rom_hyper_fit_all(m) : gal_rom_hyper_fit(m, 1);
    if (!st && fail[0]) st = constants(m);
    if (!st) h->set_refits[0] += fail[0], h->set_refits[1] += h->loads;
    /* a loads' sample of more than LOADS_WHOLE of the edges saves little over the whole loads and
     * re-fits on: from now on the loads over every edge (a load field that varies along the span at
     * random, turbulent wind, needs most of them: BENCHMARKS.md, helper turbsample) */
    if (!st && fail[1] && h->set[1].n > LOADS_WHOLE * m->rod->p.elements) h->loads = 0, h->set[1].n = 0, h->loads_whole = 1;
    if (!st) st = sample_entries(m);
    return st;
}

static int add_snapshot(gal_rom_hyper *h, int r, const double *x, const double *v, double t)
{
    if (h->ns == h->cap) {
        int cap = 2 * h->cap + 8;
        double *p = realloc(h->snap, (size_t)cap * (2 * r + 1) * sizeof(double));
        if (!p) return gal_error(GAL_ENOMEM, "reduced model: out of memory for the training states");
        h->snap = p, h->cap = cap;
    }
    double *row = h->snap + (size_t)h->ns++ * (2 * r + 1);
    memcpy(row, x, (size_t)r * sizeof(double));
    memcpy(row + r, v, (size_t)r * sizeof(double));
    row[2 * r] = t;
    return GAL_OK;
}

/* m->hyper with its arrays (set 0: the rod's energy, every element's room; set 1: the loads', every
 * edge's), empty. */
static int hyper_alloc(gal_rom *m)
{
    const gal_rod *rod = m->rod;
    int r = m->r, st = GAL_OK;
    gal_rom_hyper *h = calloc(1, sizeof *h);
    if (!h) return gal_error(GAL_ENOMEM, "reduced model: out of memory for the sample");
    m->hyper = h;
    for (int s = 0; s < 2; s++) {
        int ne = s == 0 ? gal_rod_element_count(rod) : rod->p.elements;
        h->set[s].elem = malloc((size_t)ne * sizeof(int)), h->set[s].w = malloc((size_t)ne * sizeof(double));
        h->set[s].idx = malloc((size_t)ne * GAL_ROD_ELEMENT_NQ * sizeof(int));
        h->set[s].rw = malloc((size_t)r * sizeof(double));
        if (!h->set[s].elem || !h->set[s].w || !h->set[s].idx || !h->set[s].rw) st = GAL_ENOMEM;
    }
    h->fc = malloc((size_t)r * sizeof(double)), h->Kc = malloc((size_t)r * r * sizeof(double)), h->F0 = malloc((size_t)r * sizeof(double));
    h->gu = malloc((size_t)m->nq * sizeof(double));
    h->T = malloc((size_t)GAL_ROD_ELEMENT_NQ * r * sizeof(double));
    h->whole_g = malloc((size_t)m->nq * sizeof(double)), h->whole_f = malloc((size_t)m->nq * sizeof(double));
    h->whole_xv = malloc((size_t)2 * r * sizeof(double));
    if (st || !h->gu || !h->T || !h->fc || !h->Kc || !h->F0 || !h->whole_g || !h->whole_f || !h->whole_xv)
        return gal_error(GAL_ENOMEM, "reduced model: out of memory for the sample (basis %d)", r);
    return GAL_OK;
}

int gal_rom_hyper_build(gal_rom *m)
{
    const gal_rod *rod = m->rod;
    int r = m->r, st = hyper_alloc(m);
    double *x = st ? NULL : malloc((size_t)3 * r * sizeof(double));
    if (!st && !x) st = gal_error(GAL_ENOMEM, "reduced model: out of memory for the sample (basis %d)", r);
    if (st) return st;
    gal_rom_hyper *h = m->hyper;
    h->mirror = mirror_symmetric(m);
    /* the amplitude: the sag below the chord, at least 1% of the span */
    double L = rod->p.length, hd = rod->p.height_difference, sag = 0;
    for (int i = 0; i < rod->nn; i++) {
        double xi = m->q_eq[3 * i];
        sag = fmax(sag, hd * xi / L - m->q_eq[3 * i + 2]);
    }
    h->amp = fmax(sag, 0.01 * sqrt(L * L + hd * hd));
    memset(x, 0, (size_t)r * sizeof(double));
    if ((st = gal_rom_exact_force(m, x, h->F0))) goto done;
    int ns = m->o.hyper_snapshots; /* fewer on a fine mesh: each costs a whole-mesh evaluation there */
    if (rod->p.elements > GAL_ROM_CANDIDATES && m->o.hyper_snapshots_fine > 0) ns = m->o.hyper_snapshots_fine;
    for (int s = 0; s < ns && !st; s++) {
        st = gal_rom_hyper_training_state(m, s, x, x + r);
        if (!st) st = add_snapshot(h, r, x, x + r, 10.0 + 7.3 * s);
    }
    /* the rod's sample, then the loads' (apart: the first does not depend on the wind); both in one
     * pass over the training states when the loads are known already (gal_rom_alloc computing its
     * own set-up), the same samples */
    h->loads = m->force.eval && m->force.element && m->o.hyper_loads;
    if (!st) st = h->loads ? gal_rom_hyper_fit_all(m) : gal_rom_hyper_fit(m, 0);
    if (!st) st = constants(m);
    if (!st) st = sample_entries(m);
done:
    free(x);
    return st;
}

int gal_rom_hyper_loads(gal_rom *m)
{
    gal_rom_hyper *h = m->hyper;
    h->loads = m->force.eval && m->force.element && m->o.hyper_loads;
    int st = h->loads ? gal_rom_hyper_fit(m, 1) : GAL_OK;
    if (!st) st = sample_entries(m);
    return st;
}

/* a fresh copy of n doubles (NULL: out of memory) */
static double *dup(const double *src, size_t n)
{
    double *p = malloc((n > 0 ? n : 1) * sizeof(double));
    if (p && n) memcpy(p, src, n * sizeof(double));
    return p;
}

int gal_rom_hyper_copy(gal_rom *m, const gal_rom *from)
{
    const gal_rom_hyper *f = from->hyper;
    int r = m->r, NQ = GAL_ROD_ELEMENT_NQ, st = hyper_alloc(m);
    if (st) return st;
    gal_rom_hyper *h = m->hyper;
    const gal_rom_hyper_set *F = &f->set[0];
    gal_rom_hyper_set *S = &h->set[0];
    S->n = F->n, S->fit_error = F->fit_error;
    memcpy(S->elem, F->elem, (size_t)F->n * sizeof(int)), memcpy(S->w, F->w, (size_t)F->n * sizeof(double));
    memcpy(S->idx, F->idx, (size_t)F->n * NQ * sizeof(int)), memcpy(S->rw, F->rw, (size_t)r * sizeof(double));
    memcpy(h->fc, f->fc, (size_t)r * sizeof(double)), memcpy(h->Kc, f->Kc, (size_t)r * r * sizeof(double));
    memcpy(h->F0, f->F0, (size_t)r * sizeof(double));
    h->Uc = f->Uc, h->amp = f->amp, h->mirror = f->mirror, h->refits = f->refits, h->set_refits[0] = f->set_refits[0], h->set_refits[1] = f->set_refits[1], h->check_error = f->check_error;
    h->train_element_evals = f->train_element_evals, h->train_full_evals = f->train_full_evals;
    h->ns = h->cap = f->ns;
    if (f->emax && !(h->emax = dup(f->emax, (size_t)m->nmodes))) st = GAL_ENOMEM;
    if (!(h->snap = dup(f->snap, (size_t)f->ns * (2 * r + 1)))) st = GAL_ENOMEM;
    return st ? gal_error(GAL_ENOMEM, "reduced model: out of memory for the sample") : GAL_OK;
}

/* |rw .* a| */
static double wnorm(const double *rw, const double *a, int r)
{
    double s = 0;
    for (int k = 0; k < r; k++) s += rw[k] * rw[k] * a[k] * a[k];
    return sqrt(s);
}

/* The exact projected internal force fi = B^T grad U(q) and, when fl, loads fl = B^T F(t, q, v) at
 * the current state, from one full reconstruction of q and v (m->q, m->vq; the whole rod's gradient
 * in m->gq, its loads in m->fq); B the tangent basis at x. Each sum runs over the dofs in order:
 * gal_rom_exact_force's numbers. */
static int exact_forces(gal_rom *m, double *fi, double *fl)
{
    gal_rom_reconstruct_at(m, m->x, fl ? m->v : NULL);
    int st = gal_rod_eval(m->rod, m->q, NULL, m->gq, NULL);
    if (!st && fl) {
        memset(m->fq, 0, (size_t)m->nq * sizeof(double));
        st = m->force.eval(m->force.ctx, m->t, m->q, m->vq, m->fq);
    }
    if (!st) gal_rom_project_free(m, gal_rom_basis_at(m, m->x), m->gq, fl ? m->fq : NULL, fi, fl);
    return st;
}

int gal_rom_hyper_check(gal_rom *m, double *err)
{
    gal_rom_hyper *h = m->hyper;
    int r = m->r, st;
    double e = 0, *fa = m->fr, *fb = m->res, *fl = m->da; /* scratch between steps */
    if (err) *err = 0;
    if (!h) return GAL_OK;
    /* the exact internal force (against its change from the equilibrium) and loads, the whole rod's
     * gradient and loads kept for the self-check at this state */
    h->whole_has = 0;
    if ((st = exact_forces(m, fa, h->loads ? fl : NULL))) return st;
    memcpy(h->whole_g, m->gq, (size_t)m->nq * sizeof(double));
    if (h->loads) memcpy(h->whole_f, m->fq, (size_t)m->nq * sizeof(double));
    memcpy(h->whole_xv, m->x, (size_t)r * sizeof(double)), memcpy(h->whole_xv + r, m->v, (size_t)r * sizeof(double));
    h->whole_t = m->t, h->whole_has = h->loads ? 2 : 1;
    if ((st = gal_rom_hyper_internal(m, m->x, fb, NULL))) return st;
    for (int k = 0; k < r; k++) fb[k] -= fa[k], fa[k] -= h->F0[k];
    double den = wnorm(h->set[0].rw, fa, r), es[2] = {0, 0};
    if (den > 0) es[0] = wnorm(h->set[0].rw, fb, r) / den;
    if (h->loads) {
        if ((st = gal_rom_hyper_external(m, m->t, m->x, m->v, fb))) return st;
        for (int k = 0; k < r; k++) fb[k] -= fl[k];
        den = wnorm(h->set[1].rw, fl, r);
        if (den > 0) es[1] = wnorm(h->set[1].rw, fb, r) / den;
    }
    e = h->loads ? fmax(es[0], es[1]) : es[0];
    h->check_error = e;
    if (err) *err = e;
    int fail[2] = {es[0] > m->o.hyper_check_tol, h->loads && es[1] > m->o.hyper_check_tol};
    if (!(e <= m->o.hyper_check_tol) && !fail[1]) fail[0] = 1; /* NaN: both, as before */
    if (!fail[0] && !fail[1]) return GAL_OK;
    /* re-sample what failed with this state among the training states; the state's forces from the
     * new samples */
    if ((st = add_snapshot(h, r, m->x, m->v, m->t)) || (st = resample(m, fail))) return st;
    h->refits++;
    m->hJ = 0;
    if ((st = gal_rom_hyper_internal(m, m->x, m->fi, NULL))) return st;
    m->U = m->U1;
    if (h->loads && (st = gal_rom_hyper_external(m, m->t, m->x, m->v, m->fe))) return st;
    if (!h->loads && fail[1] && (st = gal_rom_eval_external(m, m->t, m->x, m->v, m->fe))) return st; /* whole since */
    return GAL_OK;
}

int gal_rom_hyper_whole(const gal_rom *m, const double **g, const double **f)
{
    const gal_rom_hyper *h = m->hyper;
    size_t br = (size_t)m->r * sizeof(double);
    *g = *f = NULL;
    if (!h || !h->whole_has || h->whole_t != m->t || memcmp(h->whole_xv, m->x, br) || memcmp(h->whole_xv + m->r, m->v, br))
        return 0;
    *g = h->whole_g;
    if (h->whole_has == 2) *f = h->whole_f;
    return 1;
}

int gal_rom_hyper_use_all(gal_rom *m)
{
    gal_rom_hyper *h = m->hyper;
    if (!h) return gal_error(GAL_EINPUT, "reduced model: not hyper-reduced");
    for (int s = 0; s < 2; s++) {
        gal_rom_hyper_set *S = &h->set[s];
        S->n = s == 0 ? gal_rod_element_count(m->rod) : m->rod->p.elements;
        for (int e = 0; e < S->n; e++) S->elem[e] = e, S->w[e] = 1;
    }
    int st = constants(m);
    if (!st) st = sample_entries(m);
    m->hJ = 0;
    return st;
}

void gal_rom_hyper_get_info(const gal_rom *m, gal_rom_hyper_info *info)
{
    memset(info, 0, sizeof *info);
    const gal_rom_hyper *h = m->hyper;
    if (!h) return;
    info->elements = h->set[0].n;
    info->load_elements = h->loads ? h->set[1].n : -1;
    info->snapshots = h->ns;
    info->refits = h->refits;
    info->refits_energy = h->set_refits[0], info->refits_loads = h->set_refits[1], info->loads_whole = h->loads_whole;
    info->fit_error = h->set[0].fit_error;
    info->load_fit_error = h->loads ? h->set[1].fit_error : 0;
    info->mirror = h->mirror;
    info->check_error = h->check_error;
    info->train_element_evals = h->train_element_evals;
    info->train_full_evals = h->train_full_evals;
}
