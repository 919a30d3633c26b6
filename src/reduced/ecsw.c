/* ecsw.c: energy-conserving sampling and weighting of the recomputed reduced model (ecsw.h):
 * the training states, the per-element snapshot matrices, their non-negative fits (nnls.c), the
 * sampled entries of the basis, and the check that re-samples. The evaluations from the sample
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
    free(h->T); free(h->gu); free(h->Jdd); free(h->fc); free(h->Kc); free(h->snap); free(h->F0);
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
        if (!S->uq || !S->Vu) { free(where); return gal_error(GAL_ENOMEM, "reduced model: out of memory for the sample"); }
        if (m->qm) {
            int np = m->qm->np;
            S->Qz = malloc((size_t)nu1 * (r + np) * sizeof(double)), S->Tt = malloc((size_t)nu1 * r * r * sizeof(double));
            S->Pc = malloc((size_t)nu1 * r * sizeof(double)), S->qs = malloc((size_t)nu1 * sizeof(double));
            if (!S->Qz || !S->Tt || !S->Pc || !S->qs) { free(where); return gal_error(GAL_ENOMEM, "reduced model: out of memory for the sample"); }
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

/* Column e of a snapshot block: B_e^T g_e for element e's local gradient g (11 or 7 entries
 * mapped like gal_rod_element_q) at the reconstructed state m->q; B the tangent basis there. */
static void project_local(const gal_rom *m, const double *B, const int *qi, const double *g, int nloc, double *col)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof, r = m->r;
    static const int load_to_el[7] = {0, 1, 2, 3, 4, 5, 9};
    memset(col, 0, (size_t)r * sizeof(double));
    for (int a = 0; a < nloc; a++) {
        int qa = qi[nloc == 7 ? load_to_el[a] : a];
        int d = qa < 0 ? -1 : rod->dof[qa];
        if (d < 0 || g[a] == 0) continue;
        for (int k = 0; k < r; k++) col[k] += B[(size_t)k * n + d] * g[a];
    }
}


/* Kr = V_e^T H_e V_e (r x r) of element e's Hessian at the state in m->q (the basis at the
 * equilibrium: V, on the manifold Phi plus the curvature sum_a g_a theta_a), and its gradient's
 * projection into col (r). */
static int element_reduced(gal_rom *m, int e, double *col, double *Kr)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof, r = m->r, NQ = GAL_ROD_ELEMENT_NQ, qi[GAL_ROD_ELEMENT_NQ], d[GAL_ROD_ELEMENT_NQ];
    double U, g[GAL_ROD_ELEMENT_NQ], H[GAL_ROD_ELEMENT_NQ * GAL_ROD_ELEMENT_NQ], *T = m->hyper->T;
    gal_rod_element_q(rod, e, qi);
    int st = gal_rod_element_eval(rod, e, m->q, &U, g, H);
    if (st) return st;
    project_local(m, m->V, qi, g, NQ, col);
    for (int a = 0; a < NQ; a++) d[a] = qi[a] < 0 ? -1 : rod->dof[qi[a]];
    for (int a = 0; a < NQ; a++) { /* T = H V_e */
        for (int j = 0; j < r; j++) T[a * r + j] = 0;
        for (int b = 0; b < NQ; b++)
            if (d[b] >= 0 && H[a * NQ + b] != 0)
                for (int j = 0; j < r; j++) T[a * r + j] += H[a * NQ + b] * m->V[(size_t)j * n + d[b]];
    }
    memset(Kr, 0, (size_t)r * r * sizeof(double));
    for (int a = 0; a < NQ; a++)
        if (d[a] >= 0)
            for (int i = 0; i < r; i++) {
                double vi = m->V[(size_t)i * n + d[a]];
                for (int j = 0; j < r; j++) Kr[i * r + j] += vi * T[a * r + j];
            }
    if (m->qm)
        for (int a = 0; a < NQ; a++)
            if (d[a] >= 0 && g[a] != 0)
                for (int i = 0; i < r; i++)
                    for (int j = 0; j < r; j++) Kr[i * r + j] += g[a] * m->qm->Th[(size_t)m->qm->pair[i * r + j] * n + d[a]];
    return GAL_OK;
}

/* The snapshot matrix of sample s (0: the rod's energy, 1: the loads) over every element, with
 * each training state's block normalized by its target's norm; A (ns r x nel) and b (ns r). */
static int snapshots(gal_rom *m, int set, double *A, double *b)
{
    gal_rom_hyper *h = m->hyper;
    const gal_rod *rod = m->rod;
    int r = m->r, nel = set == 0 ? gal_rod_element_count(rod) : rod->p.elements, rows = h->ns * r;
    int NQ = GAL_ROD_ELEMENT_NQ, qi[GAL_ROD_ELEMENT_NQ];
    double g[GAL_ROD_ELEMENT_NQ], U, *col = m->fr;
    for (int s = 0; s < h->ns; s++) {
        const double *x = h->snap + (size_t)s * (2 * r + 1), *v = x + r, t = x[2 * r];
        gal_rom_reconstruct_at(m, x, v);
        const double *B = gal_rom_basis_at(m, x);
        for (int e = 0; e < nel; e++) {
            double *a = A + (size_t)e * rows + (size_t)s * r;
            int st;
            gal_rod_element_q(rod, e, qi);
            if (set == 0) {
                if ((st = gal_rod_element_eval(rod, e, m->q, &U, g, NULL))) return st;
                project_local(m, B, qi, g, NQ, a);
            } else {
                if ((st = m->force.element(m->force.ctx, t, m->q, m->vq, e, g))) return st;
                project_local(m, B, qi, g, 7, a);
            }
        }
    }
    if (set == 0) { /* less the equilibrium's force and its linear part: the nonlinear remainder */
        gal_rom_reconstruct_at(m, NULL, NULL);
        for (int e = 0; e < nel; e++) {
            int st = element_reduced(m, e, col, h->Kc);
            if (st) return st;
            for (int s = 0; s < h->ns; s++) {
                const double *x = h->snap + (size_t)s * (2 * r + 1);
                for (int k = 0; k < r; k++) {
                    double kx = 0;
                    for (int j = 0; j < r; j++) kx += h->Kc[k * r + j] * x[j];
                    A[(size_t)e * rows + (size_t)s * r + k] -= col[k] + kx;
                }
            }
        }
    }
    /* the target, and each component weighed by its RMS over the training states (every
     * coordinate's force counts, not only the stiff stretching ones), floored at 1e-6 of the largest */
    double *rw = h->set[set].rw, big = 0;
    for (int k = 0; k < r; k++) rw[k] = 0;
    for (int s = 0; s < h->ns; s++)
        for (int k = 0; k < r; k++) {
            double sum = 0;
            for (int e = 0; e < nel; e++) sum += A[(size_t)e * rows + (size_t)s * r + k];
            b[s * r + k] = sum, rw[k] += sum * sum / h->ns;
        }
    for (int k = 0; k < r; k++) big = fmax(big, sqrt(rw[k]));
    for (int k = 0; k < r; k++) rw[k] = big > 0 ? 1 / fmax(sqrt(rw[k]), 1e-6 * big) : 1;
    /* the loads along the modal derivatives (stretching) count against a tenth of the internal
     * force there, which they hardly move, not against their own small size (measured: 14 load
     * elements instead of 26 at 100 elements, amplitudes within 0.2% on bersimis_250_crescent) */
    if (set == 1)
        for (int k = m->nmodes; k < r; k++) rw[k] = fmin(rw[k], 10 * h->set[0].rw[k]);
    for (int s = 0; s < h->ns; s++) {
        double nb = 0;
        for (int k = 0; k < r; k++) {
            b[s * r + k] *= rw[k], nb += b[s * r + k] * b[s * r + k];
            for (int e = 0; e < nel; e++) A[(size_t)e * rows + (size_t)s * r + k] *= rw[k];
        }
        nb = nb > 0 ? 1 / sqrt(nb) : 0;
        for (int k = 0; k < r; k++) b[s * r + k] *= nb;
        for (int e = 0; e < nel; e++)
            for (int k = 0; k < r; k++) A[(size_t)e * rows + (size_t)s * r + k] *= nb;
    }
    return GAL_OK;
}

/* Fit sample s by NNLS on the training states; the elements with positive weight are kept. On a
 * mirror-symmetric span the columns are mirror pairs (one weight for both): the sampled energy and
 * loads keep the symmetry, and a symmetric motion stays symmetric. */
static int fit(gal_rom *m, int set)
{
    gal_rom_hyper *h = m->hyper;
    const gal_rod *rod = m->rod;
    int r = m->r, nel = rod->p.elements, ne = set == 0 ? gal_rod_element_count(rod) : nel, rows = h->ns * r, st, it;
    double *A = malloc((size_t)rows * ne * sizeof(double)), *b = malloc((size_t)rows * sizeof(double));
    double *w = malloc((size_t)ne * sizeof(double));
    int *grp = malloc((size_t)ne * sizeof(int)), ng = 0;
    if (!A || !b || !w || !grp) {
        free(A), free(b), free(w), free(grp);
        return gal_error(GAL_ENOMEM, "reduced model: out of memory for the sampling");
    }
    st = snapshots(m, set, A, b);
    for (int e = 0; e < ne && !st; e++) { /* the columns of the groups, in place */
        int me = !h->mirror ? e : set == 0 ? gal_rod_element_mirror(rod, e) : nel - 1 - e;
        if (me < e) continue;
        double *c = A + (size_t)ng * rows, *a = A + (size_t)e * rows, *am = A + (size_t)me * rows;
        for (int i = 0; i < rows; i++) c[i] = a[i] + (me != e ? am[i] : 0);
        grp[ng++] = e;
    }
    if (!st) st = gal_nnls(rows, ng, A, b, m->o.hyper_tol, 0, w, &it);
    if (!st) {
        gal_rom_hyper_set *S = &h->set[set];
        double rn = 0, nb = 0;
        for (int i = 0; i < rows; i++) { /* the fit's residual */
            double s = -b[i];
            for (int k = 0; k < ng; k++) s += w[k] > 0 ? A[(size_t)k * rows + i] * w[k] : 0;
            rn += s * s, nb += b[i] * b[i];
        }
        S->fit_error = nb > 0 ? sqrt(rn / nb) : 0;
        S->n = 0;
        for (int k = 0; k < ng; k++) {
            if (!(w[k] > 0)) continue;
            int e = grp[k], me = !h->mirror ? e : set == 0 ? gal_rod_element_mirror(rod, e) : nel - 1 - e;
            S->elem[S->n] = e, S->w[S->n++] = w[k];
            if (me != e) S->elem[S->n] = me, S->w[S->n++] = w[k];
        }
    }
    free(A), free(b), free(w), free(grp);
    return st;
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
 * V^T K0 V at the equilibrium (the linear dynamics, the modes' frequencies, are exact). */
static int constants(gal_rom *m)
{
    gal_rom_hyper *h = m->hyper;
    const gal_rod *rod = m->rod;
    int r = m->r, qi[GAL_ROD_ELEMENT_NQ];
    double U0, Ue, g[GAL_ROD_ELEMENT_NQ], *col = m->fr, *Ke = m->Kr; /* Kr: scratch, refreshed after */
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
        if ((st = element_reduced(m, S->elem[k], col, Ke))) return st;
        for (int i = 0; i < r; i++) h->fc[i] -= S->w[k] * col[i];
        for (int i = 0; i < r * r; i++) h->Kc[i] -= S->w[k] * Ke[i];
        h->Uc -= S->w[k] * Ue;
    }
    m->hJ = 0;
    return GAL_OK;
}

/* Both fits, the constants and the sampled entries from the training states held. */
static int resample(gal_rom *m)
{
    int st = fit(m, 0);
    if (!st && m->hyper->loads) st = fit(m, 1);
    if (!st) st = constants(m);
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

int gal_rom_hyper_build(gal_rom *m)
{
    const gal_rod *rod = m->rod;
    int r = m->r, nm = m->nmodes, nd = r - nm, nel = rod->p.elements, st = GAL_OK;
    gal_rom_hyper *h = calloc(1, sizeof *h);
    if (!h) return gal_error(GAL_ENOMEM, "reduced model: out of memory for the sample");
    m->hyper = h;
    h->loads = m->force.eval && m->force.element && m->o.hyper_loads;
    h->mirror = mirror_symmetric(m);
    for (int s = 0; s < 2; s++) {
        int ne = s == 0 ? gal_rod_element_count(rod) : nel;
        h->set[s].elem = malloc((size_t)ne * sizeof(int)), h->set[s].w = malloc((size_t)ne * sizeof(double));
        h->set[s].idx = malloc((size_t)ne * GAL_ROD_ELEMENT_NQ * sizeof(int));
        h->set[s].rw = malloc((size_t)r * sizeof(double));
        if (!h->set[s].elem || !h->set[s].w || !h->set[s].idx || !h->set[s].rw) st = GAL_ENOMEM;
    }
    h->fc = malloc((size_t)r * sizeof(double)), h->Kc = malloc((size_t)r * r * sizeof(double)), h->F0 = malloc((size_t)r * sizeof(double));
    h->gu = malloc((size_t)m->nq * sizeof(double));
    h->T = malloc((size_t)GAL_ROD_ELEMENT_NQ * r * sizeof(double)), h->Jdd = malloc((size_t)(nd ? nd * nd : 1) * sizeof(double));
    double *x = malloc((size_t)3 * r * sizeof(double));
    if (st || !h->gu || !h->T || !h->Jdd || !h->fc || !h->Kc || !h->F0 || !x || nd > 256) {
        free(x);
        return gal_error(GAL_ENOMEM, "reduced model: out of memory for the sample (basis %d)", r);
    }
    /* the amplitude: the sag below the chord, at least 1% of the span */
    double L = rod->p.length, hd = rod->p.height_difference, sag = 0;
    for (int i = 0; i < rod->nn; i++) {
        double xi = m->q_eq[3 * i];
        sag = fmax(sag, hd * xi / L - m->q_eq[3 * i + 2]);
    }
    h->amp = fmax(sag, 0.01 * sqrt(L * L + hd * hd));
    memset(x, 0, (size_t)r * sizeof(double));
    if ((st = gal_rom_exact_force(m, x, h->F0))) goto done;
    for (int s = 0; s < m->o.hyper_snapshots && !st; s++) {
        st = gal_rom_hyper_training_state(m, s, x, x + r);
        if (!st) st = add_snapshot(h, r, x, x + r, 10.0 + 7.3 * s);
    }
    if (!st) st = resample(m);
done:
    free(x);
    return st;
}

/* |rw .* a| */
static double wnorm(const double *rw, const double *a, int r)
{
    double s = 0;
    for (int k = 0; k < r; k++) s += rw[k] * rw[k] * a[k] * a[k];
    return sqrt(s);
}

/* The exact projected loads at the current state into f (the full reconstruction in m->q, m->vq). */
static int exact_loads(gal_rom *m, double *f)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof;
    gal_rom_reconstruct_at(m, m->x, m->v);
    memset(m->fq, 0, (size_t)m->nq * sizeof(double));
    int st = m->force.eval(m->force.ctx, m->t, m->q, m->vq, m->fq);
    if (st) return st;
    const double *B = gal_rom_basis_at(m, m->x);
    for (int k = 0; k < m->r; k++) {
        double s = 0;
        for (int d = 0; d < n; d++) s += B[(size_t)k * n + d] * m->fq[rod->free_q[d]];
        f[k] = s;
    }
    return GAL_OK;
}

int gal_rom_hyper_check(gal_rom *m, double *err)
{
    gal_rom_hyper *h = m->hyper;
    int r = m->r, st;
    double e = 0, *fa = m->fr, *fb = m->res; /* scratch between steps */
    if (err) *err = 0;
    if (!h) return GAL_OK;
    /* the internal force, against its change from the equilibrium */
    if ((st = gal_rom_exact_force(m, m->x, fa)) || (st = gal_rom_hyper_internal(m, m->x, fb, NULL))) return st;
    for (int k = 0; k < r; k++) fb[k] -= fa[k], fa[k] -= h->F0[k];
    double den = wnorm(h->set[0].rw, fa, r);
    if (den > 0) e = wnorm(h->set[0].rw, fb, r) / den;
    if (h->loads) {
        if ((st = exact_loads(m, fa)) || (st = gal_rom_hyper_external(m, m->t, m->x, m->v, fb))) return st;
        for (int k = 0; k < r; k++) fb[k] -= fa[k];
        den = wnorm(h->set[1].rw, fa, r);
        if (den > 0) e = fmax(e, wnorm(h->set[1].rw, fb, r) / den);
    }
    h->check_error = e;
    if (err) *err = e;
    if (!(e > m->o.hyper_check_tol)) return GAL_OK;
    /* re-sample with this state among the training states; the state's forces from the new sample */
    if ((st = add_snapshot(h, r, m->x, m->v, m->t)) || (st = resample(m))) return st;
    h->refits++;
    m->hJ = 0;
    if ((st = gal_rom_hyper_internal(m, m->x, m->fi, NULL))) return st;
    m->U = m->U1;
    if (h->loads && (st = gal_rom_hyper_external(m, m->t, m->x, m->v, m->fe))) return st;
    return GAL_OK;
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
    info->fit_error = h->set[0].fit_error;
    info->load_fit_error = h->loads ? h->set[1].fit_error : 0;
    info->mirror = h->mirror;
    info->check_error = h->check_error;
}
