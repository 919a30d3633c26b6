/* ecsw_train.c: the training of the hyper-reduced reduced model (ecsw.h): the training states
 * (the selected modes at random amplitudes and directions at the scale of the motion, the
 * modal-derivative coordinates at zero), the candidate elements, the per-element snapshot
 * matrices and their non-negative fits (nnls.c). The set-up's cost does not grow with the mesh
 * but for one exact evaluation of the rod (or the loads) per training state: on a fine mesh the
 * candidates are a fixed number spread over the span, and the fits' targets come from the
 * assembled forces instead of the sum of every element's column. */
#include "gallop/reduced/ecsw.h"
#include "gallop/base/core.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "reduced/hyper.h"
#include "reduced/qm.h"

/* x -> a small deterministic generator (xorshift64*), uniform in (0, 1) */
static double unif(unsigned long long *s)
{
    *s ^= *s >> 12, *s ^= *s << 25, *s ^= *s >> 27;
    return ((*s * 2685821657736338717ULL) >> 11) * (1.0 / 9007199254740992.0) + 1e-17;
}

static double gauss(unsigned long long *s)
{
    return sqrt(-2 * log(unif(s))) * cos(2 * GAL_PI * unif(s));
}

/* Training state s: the modes at a random amplitude and direction, each mode's largest
 * translation up to the sag (at least 1% of the span) and its largest twist up to hyper_twist;
 * the modal-derivative coordinates at zero; a velocity of the same scale in the modes. (Until
 * issue 13's set-up work the derivative coordinates were meant to be relaxed quasi-statically by
 * Newton on their block of the reduced tangent, but that loop stopped before its first step: its
 * convergence test compared with an infinite first residual. It cost one full tangent a state and
 * changed nothing, so it is gone; relaxing them would change the training set, see BENCHMARKS.) */
int gal_rom_hyper_training_state(gal_rom *m, int s, double *x, double *v)
{
    gal_rom_hyper *h = m->hyper;
    const gal_rod *rod = m->rod;
    int n = m->ndof, r = m->r, nm = m->nmodes;
    unsigned long long seed = 0x9E3779B97F4A7C15ULL * (unsigned long long)(s + 1);
    double u[64], uu = 0, a = s == 0 ? 0.1 : 0.1 + 1.1 * unif(&seed);
    for (int k = 0; k < nm && k < 64; k++) u[k] = gauss(&seed), uu += u[k] * u[k];
    memset(x, 0, (size_t)r * sizeof(double));
    memset(v, 0, (size_t)r * sizeof(double));
    if (!h->emax) { /* each mode's largest amplitude, once */
        if (!(h->emax = malloc((size_t)(nm > 0 ? nm : 1) * sizeof(double)))) return gal_error(GAL_ENOMEM, "reduced model: out of memory");
        for (int k = 0; k < nm; k++) {
            const double *vk = m->V + (size_t)k * n;
            double st = 0, sr = 0;
            for (int d = 0; d < n; d++) {
                int qi = rod->free_q[d];
                if (qi < 3 * rod->nn) st = fmax(st, fabs(vk[d]));
                else sr = fmax(sr, fabs(vk[d]));
            }
            double emax = INFINITY;
            if (st > 0) emax = h->amp / st;
            if (sr > 0) emax = fmin(emax, m->o.hyper_twist / sr);
            h->emax[k] = emax;
        }
    }
    for (int k = 0; k < nm && k < 64; k++) {
        double emax = h->emax[k];
        x[k] = a * u[k] / sqrt(uu) * emax;
        v[k] = sqrt(m->omega2[k]) * emax * a * gauss(&seed) / sqrt((double)nm);
    }
    return GAL_OK;
}


/* The candidates of sample `set` (0: the rod's energy, 1: the loads) into cand, in increasing
 * order; returns their count (-1: out of memory). Each kind of element (edges; for the energy
 * also the interior nodes' stencils) has GAL_ROM_CANDIDATES / 2 positions evenly spread from
 * support to support (both ends in), each two neighbouring elements (towards the middle, so the
 * set is its own mirror image on a symmetric span), closed under the mirror when the fit pairs
 * mirror images; every element of a kind when there are no more than GAL_ROM_CANDIDATES (a mesh
 * of up to that many elements trains as before). Neighbours, not single elements: measured at
 * 400 elements, every other element alone cannot fit the target (NNLS residual 0.76, the
 * element-scale alternation of the forces), neighbouring pairs at 64 positions fit to 0.0074. */
static int candidates(const gal_rom *m, int set, int *cand)
{
    const gal_rod *rod = m->rod;
    int nel = rod->p.elements, ne = set == 0 ? gal_rod_element_count(rod) : nel, nc = 0, P = GAL_ROM_CANDIDATES / 2;
    if (nel <= GAL_ROM_CANDIDATES) {
        for (int e = 0; e < ne; e++) cand[nc++] = e;
        return nc;
    }
    char *mark = calloc((size_t)ne, 1);
    if (!mark) return -1;
    for (int kind = 0; kind < (set == 0 ? 2 : 1); kind++) {
        int first = kind ? nel : 0, count = kind ? nel - 1 : nel; /* edges; interior nodes 1..nel-1 */
        for (int k = 0; k < P; k++) {
            int i = (int)floor((double)k * (count - 1) / (P - 1) + 0.5);
            mark[first + i] = mark[first + (2 * i < count - 1 ? i + 1 : i - 1)] = 1;
        }
    }
    if (m->hyper->mirror)
        for (int e = 0; e < ne; e++)
            if (mark[e]) mark[set == 0 ? gal_rod_element_mirror(rod, e) : nel - 1 - e] = 1;
    for (int e = 0; e < ne; e++)
        if (mark[e]) cand[nc++] = e;
    free(mark);
    return nc;
}

/* Column e of a snapshot block: B_e^T g_e for element e's local gradient g (11 or 7 entries
 * mapped like gal_rod_element_q) at the reconstructed state m->q; B the tangent basis there,
 * column-major (n x r), or row-major (r entries a dof: Bt, the same sums in the same order, without
 * striding over the whole basis for each entry) when Bt != NULL. */
static void project_local(const gal_rom *m, const double *B, const double *Bt, const int *qi, const double *g, int nloc,
                          double *col)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof, r = m->r;
    static const int load_to_el[7] = {0, 1, 2, 3, 4, 5, 9};
    memset(col, 0, (size_t)r * sizeof(double));
    for (int a = 0; a < nloc; a++) {
        int qa = qi[nloc == 7 ? load_to_el[a] : a];
        int d = qa < 0 ? -1 : rod->dof[qa];
        if (d < 0 || g[a] == 0) continue;
        if (Bt) {
            const double *row = Bt + (size_t)d * r;
            for (int k = 0; k < r; k++) col[k] += row[k] * g[a];
        } else
            for (int k = 0; k < r; k++) col[k] += B[(size_t)k * n + d] * g[a];
    }
}

/* Vt = V^T (r entries a dof, row-major) of the model's constant basis; NULL on the manifold (its
 * tangent basis moves with the state) or when out of memory (then V itself is read). */
static double *basis_rows(const gal_rom *m)
{
    int n = m->ndof, r = m->r;
    double *Vt = m->qm ? NULL : malloc((size_t)n * r * sizeof(double));
    if (Vt)
        for (int d = 0; d < n; d++)
            for (int k = 0; k < r; k++) Vt[(size_t)d * r + k] = m->V[(size_t)k * n + d];
    return Vt;
}

/* gal_rom_hyper_element_reduced with V's rows from Vt (basis_rows) when not NULL. */
static int element_reduced(gal_rom *m, const double *Vt, int e, double *col, double *Kr)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof, r = m->r, NQ = GAL_ROD_ELEMENT_NQ, qi[GAL_ROD_ELEMENT_NQ], d[GAL_ROD_ELEMENT_NQ];
    double U, g[GAL_ROD_ELEMENT_NQ], H[GAL_ROD_ELEMENT_NQ * GAL_ROD_ELEMENT_NQ], *T = m->hyper->T;
    gal_rod_element_q(rod, e, qi);
    int st = gal_rod_element_eval(rod, e, m->q, &U, g, H);
    if (st) return st;
    project_local(m, m->V, Vt, qi, g, NQ, col);
    for (int a = 0; a < NQ; a++) d[a] = qi[a] < 0 ? -1 : rod->dof[qi[a]];
    for (int a = 0; a < NQ; a++) { /* T = H V_e */
        for (int j = 0; j < r; j++) T[a * r + j] = 0;
        for (int b = 0; b < NQ; b++)
            if (d[b] >= 0 && H[a * NQ + b] != 0) {
                double hab = H[a * NQ + b];
                if (Vt) {
                    const double *row = Vt + (size_t)d[b] * r;
                    for (int j = 0; j < r; j++) T[a * r + j] += hab * row[j];
                } else
                    for (int j = 0; j < r; j++) T[a * r + j] += hab * m->V[(size_t)j * n + d[b]];
            }
    }
    memset(Kr, 0, (size_t)r * r * sizeof(double));
    for (int a = 0; a < NQ; a++)
        if (d[a] >= 0)
            for (int i = 0; i < r; i++) {
                double vi = Vt ? Vt[(size_t)d[a] * r + i] : m->V[(size_t)i * n + d[a]];
                for (int j = 0; j < r; j++) Kr[i * r + j] += vi * T[a * r + j];
            }
    if (m->qm)
        for (int a = 0; a < NQ; a++)
            if (d[a] >= 0 && g[a] != 0)
                for (int i = 0; i < r; i++)
                    for (int j = 0; j < r; j++) Kr[i * r + j] += g[a] * m->qm->Th[(size_t)m->qm->pair[i * r + j] * n + d[a]];
    return GAL_OK;
}

int gal_rom_hyper_element_reduced(gal_rom *m, int e, double *col, double *Kr)
{
    return element_reduced(m, NULL, e, col, Kr);
}

/* The work of one sample's fit (0: the rod's energy, 1: the loads): its candidates, the snapshot
 * matrix A (ns r x nc) and the target b (ns r); all: every element is a candidate. */
typedef struct train_set {
    int set, nc, all;
    int *cand;
    double *A, *b;
} train_set;

/* The targets at training state s (at time t, reconstructed in m->q, m->vq; B the tangent basis)
 * of the samples not fitted on every element: the force of every element at once (assembled: one
 * evaluation of the rod, one of the loads). With G (the model's constant basis) its free part is
 * gathered into G[set] + (s % TARGET_CHUNK) n, projected a chunk of states at a time (columns:
 * gal_rom_project_states); else projected here, both in one pass. The rod's are corrected after.
 * With frames (6 a rod edge; both samples' targets and the loads' force.eval_framed) the rod's
 * evaluation hands its edge frames to the loads': the same numbers, not computed twice. */
#define TARGET_CHUNK 4 /* the states whose targets are projected together: V read once for them, a
                        * small buffer (a whole-mesh buffer for every state, 0.8 MB at 1000
                        * elements, made glibc give the heap's top back and fault it in again at
                        * every build: more than the pass saved) */
static int targets(gal_rom *m, train_set *T, int nt, int s, double t, const double *B, double *const *G,
                   double *frames)
{
    const int *fq = m->rod->free_q;
    int r = m->r, n = m->ndof, st = GAL_OK;
    double *b[2] = {NULL, NULL};
    for (int i = 0; i < nt && !st; i++) {
        if (T[i].all) continue;
        b[T[i].set] = T[i].b + (size_t)s * r;
        double *f = T[i].set == 0 ? m->gq : m->fq;
        if (T[i].set == 0) st = frames ? gal_rod_eval_frames(m->rod, m->q, NULL, m->gq, NULL, frames)
                                       : gal_rod_eval(m->rod, m->q, NULL, m->gq, NULL);
        else {
            memset(m->fq, 0, (size_t)m->nq * sizeof(double));
            st = frames ? m->force.eval_framed(m->force.ctx, t, m->q, m->vq, frames, m->fq)
                        : m->force.eval(m->force.ctx, t, m->q, m->vq, m->fq);
        }
        m->hyper->train_full_evals++;
        if (G && !st)
            for (int d = 0; d < n; d++) G[T[i].set][(size_t)(s % TARGET_CHUNK) * n + d] = f[fq[d]];
    }
    if (st || G || (!b[0] && !b[1])) return st;
    if (b[0]) gal_rom_project_free(m, B, m->gq, b[1] ? m->fq : NULL, b[0], b[1]);
    else gal_rom_project_free(m, B, m->fq, NULL, b[1], NULL);
    return GAL_OK;
}

/* The rod's targets at state x (b: r) less the equilibrium's force and its linear part (Kl: V^T K0
 * V, and the curvature on the manifold). */
static void correct(const gal_rom *m, const double *x, const double *Kl, double *b)
{
    int r = m->r;
    for (int k = 0; k < r; k++) {
        b[k] -= m->hyper->F0[k];
        for (int j = 0; j < r; j++) b[k] -= Kl[k * r + j] * x[j];
    }
}

/* Kl for the rod's targets: the exact linear part of the whole rod (into Kl, r x r). */
static int linear_part(gal_rom *m, double *Kl)
{
    memcpy(Kl, m->K0r, (size_t)m->r * m->r * sizeof(double));
    if (!m->qm) return GAL_OK;
    gal_rom_reconstruct_at(m, NULL, NULL);
    int st = gal_rod_eval(m->rod, m->q, NULL, m->gq, NULL);
    if (!st) gal_rom_qm_curvature(m, m->gq, Kl);
    return st;
}

/* The raw snapshot columns of every sample's candidates at every training state, and the targets
 * of those not fitted on every element (all: the targets are summed later), in one pass over the
 * training states: each state reconstructed once for both samples. */
static int columns(gal_rom *m, train_set *T, int nt, const double *Vt)
{
    gal_rom_hyper *h = m->hyper;
    const gal_rod *rod = m->rod;
    int r = m->r, rows = h->ns * r, NQ = GAL_ROD_ELEMENT_NQ, qi[GAL_ROD_ELEMENT_NQ], st = GAL_OK;
    double g[GAL_ROD_ELEMENT_NQ], U, *Kl = NULL;
    for (int i = 0; i < nt && !st; i++)
        if (T[i].set == 0 && !T[i].all) {
            if (!(Kl = malloc((size_t)r * r * sizeof(double)))) return gal_error(GAL_ENOMEM, "reduced model: out of memory for the sampling");
            st = linear_part(m, Kl);
        }
    int loads = 0, whole[2] = {0, 0}, n = m->ndof; /* the velocity is the loads' alone */
    for (int i = 0; i < nt; i++) loads |= T[i].set == 1, whole[T[i].set] |= !T[i].all;
    double *frames = NULL; /* both targets whole, the rod's evaluated first (T in set order) */
    if (!st && whole[0] && whole[1] && T[0].set == 0 && m->force.eval_framed &&
        !(frames = malloc((size_t)6 * rod->p.elements * sizeof(double))))
        st = gal_error(GAL_ENOMEM, "reduced model: out of memory for the sampling");
    double *G[2] = {NULL, NULL}; /* the targets' free parts, state by state, with the constant basis */
    for (int i = 0; i < nt && !st && !m->qm; i++)
        if (!T[i].all && !(G[T[i].set] = malloc((size_t)TARGET_CHUNK * n * sizeof(double))))
            st = gal_error(GAL_ENOMEM, "reduced model: out of memory for the sampling");
    for (int s = 0; s < h->ns && !st; s++) {
        const double *x = h->snap + (size_t)s * (2 * r + 1), *v = x + r, t = x[2 * r];
        gal_rom_reconstruct_at(m, x, loads ? v : NULL);
        const double *B = gal_rom_basis_at(m, x);
        for (int i = 0; i < nt && !st; i++)
            for (int c = 0; c < T[i].nc && !st; c++) {
                int e = T[i].cand[c];
                gal_rod_element_q(rod, e, qi);
                if (T[i].set == 0) st = gal_rod_element_eval(rod, e, m->q, &U, g, NULL);
                else st = m->force.element(m->force.ctx, t, m->q, m->vq, e, g);
                project_local(m, B, Vt, qi, g, T[i].set == 0 ? NQ : 7, T[i].A + (size_t)c * rows + (size_t)s * r);
                h->train_element_evals++;
            }
        if (!st) st = targets(m, T, nt, s, t, B, m->qm ? NULL : G, frames);
        int s0 = s - s % TARGET_CHUNK; /* a full chunk, or the last states: projected */
        for (int i = 0; i < nt && !st && !m->qm && (s - s0 == TARGET_CHUNK - 1 || s == h->ns - 1); i++)
            if (!T[i].all) gal_rom_project_states(m, G[T[i].set], s - s0 + 1, T[i].b + (size_t)s0 * r);
    }
    for (int i = 0; i < nt && !st; i++) {
        if (T[i].all) continue;
        if (T[i].set == 0)
            for (int s = 0; s < h->ns; s++) correct(m, h->snap + (size_t)s * (2 * r + 1), Kl, T[i].b + (size_t)s * r);
    }
    free(Kl), free(G[0]), free(G[1]), free(frames);
    return st;
}

/* Less each candidate's force and linear part at the equilibrium (the rod's sample: the fit is of
 * the nonlinear remainder); with every element a candidate, the targets are the columns' sums. */
static int nonlinear_part(gal_rom *m, const double *Vt, int set, const int *cand, int nc, int all, double *A, double *b)
{
    gal_rom_hyper *h = m->hyper;
    int r = m->r, rows = h->ns * r;
    double *col = m->fr;
    if (set == 0) {
        int *jz = malloc((size_t)r * sizeof(int));
        if (!jz) return gal_error(GAL_ENOMEM, "reduced model: out of memory for the sampling");
        gal_rom_reconstruct_at(m, NULL, NULL);
        for (int c = 0; c < nc; c++) {
            int st = element_reduced(m, Vt, cand[c], col, h->Kc);
            if (st) { free(jz); return st; }
            for (int s = 0; s < h->ns; s++) {
                const double *x = h->snap + (size_t)s * (2 * r + 1);
                double *a = A + (size_t)c * rows + (size_t)s * r;
                int nz = 0; /* the state's nonzero coordinates: a zero one adds +-0 to kx, nothing */
                for (int j = 0; j < r; j++)
                    if (x[j] != 0) jz[nz++] = j;
                for (int k = 0; k < r; k++) {
                    double kx = 0;
                    for (int z = 0; z < nz; z++) kx += h->Kc[k * r + jz[z]] * x[jz[z]];
                    a[k] -= col[k] + kx;
                }
            }
        }
        free(jz);
    }
    if (all) {
        memset(b, 0, (size_t)rows * sizeof(double));
        for (int c = 0; c < nc; c++)
            for (int i = 0; i < rows; i++) b[i] += A[(size_t)c * rows + i];
    }
    return GAL_OK;
}

/* Each component weighed by its RMS over the training states (every coordinate's force counts,
 * not only the stiff stretching ones), floored at 1e-6 of the largest, and each state's block
 * normalized by its target's norm. */
static int weigh(gal_rom *m, int set, int nc, double *A, double *b)
{
    gal_rom_hyper *h = m->hyper;
    int r = m->r, rows = h->ns * r;
    double *rw = h->set[set].rw, big = 0, *nbs = malloc((size_t)h->ns * sizeof(double));
    if (!nbs) return gal_error(GAL_ENOMEM, "reduced model: out of memory for the sampling");
    for (int k = 0; k < r; k++) rw[k] = 0;
    for (int s = 0; s < h->ns; s++)
        for (int k = 0; k < r; k++) rw[k] += b[s * r + k] * b[s * r + k] / h->ns;
    for (int k = 0; k < r; k++) big = fmax(big, sqrt(rw[k]));
    for (int k = 0; k < r; k++) rw[k] = big > 0 ? 1 / fmax(sqrt(rw[k]), 1e-6 * big) : 1;
    /* the loads along the modal derivatives (stretching) count against a tenth of the internal
     * force there, which they hardly move, not against their own small size (measured: 14 load
     * elements instead of 26 at 100 elements, amplitudes within 0.2% on bersimis_250_crescent) */
    if (set == 1)
        for (int k = m->nmodes; k < r; k++) rw[k] = fmin(rw[k], 10 * h->set[0].rw[k]);
    for (int s = 0; s < h->ns; s++) {
        double nb = 0;
        for (int k = 0; k < r; k++) b[s * r + k] *= rw[k], nb += b[s * r + k] * b[s * r + k];
        nbs[s] = nb = nb > 0 ? 1 / sqrt(nb) : 0;
        for (int k = 0; k < r; k++) b[s * r + k] *= nb;
    }
    for (int c = 0; c < nc; c++)
        for (int s = 0; s < h->ns; s++) {
            double *a = A + (size_t)c * rows + (size_t)s * r;
            for (int k = 0; k < r; k++) a[k] *= rw[k];
            for (int k = 0; k < r; k++) a[k] *= nbs[s];
        }
    free(nbs);
    return GAL_OK;
}

/* The sample's elements and weights from the NNLS weights w of the ng groups grp (mirror pairs
 * share one weight), and the fit's relative residual. */
static void keep(gal_rom *m, int set, int rows, int ng, const int *grp, const double *A, const double *b, const double *w)
{
    gal_rom_hyper *h = m->hyper;
    const gal_rod *rod = m->rod;
    gal_rom_hyper_set *S = &h->set[set];
    int nel = rod->p.elements;
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

/* Fit T's sample by NNLS over its candidates' groups (mirror pairs summed: one weight each) and
 * keep it; w, grp: scratch of the candidates' count. */
static int solve(gal_rom *m, train_set *T, double *w, int *grp)
{
    gal_rom_hyper *h = m->hyper;
    const gal_rod *rod = m->rod;
    int set = T->set, nel = rod->p.elements, rows = h->ns * m->r, ng = 0, it, *cand = T->cand;
    double *A = T->A;
    for (int c = 0; c < T->nc; c++) { /* the columns of the groups, in place */
        int e = cand[c], me = !h->mirror ? e : set == 0 ? gal_rod_element_mirror(rod, e) : nel - 1 - e;
        if (me < e) continue;
        int cm = c; /* the mirror's column: the candidates are sorted and mirror-closed */
        while (me != e && cand[cm] != me) cm++;
        double *g = A + (size_t)ng * rows, *a = A + (size_t)c * rows, *am = A + (size_t)cm * rows;
        for (int i = 0; i < rows; i++) g[i] = a[i] + (me != e ? am[i] : 0);
        grp[ng++] = e;
    }
    int st = gal_nnls(rows, ng, A, T->b, m->o.hyper_tol, 0, w, &it);
    if (!st) keep(m, set, rows, ng, grp, A, T->b, w);
    return st;
}

/* Fit the nt samples sets[] from one pass over the training states. */
static int fit(gal_rom *m, int nt, const int *sets)
{
    const gal_rod *rod = m->rod;
    int rows = m->hyper->ns * m->r, ne = gal_rod_element_count(rod), st = GAL_OK; /* the most elements of either kind */
    train_set T[2];
    memset(T, 0, sizeof T);
    int *grp = malloc((size_t)ne * sizeof(int));
    double *w = malloc((size_t)ne * sizeof(double));
    for (int i = 0; i < nt && !st; i++) {
        int nei = sets[i] == 0 ? ne : rod->p.elements;
        T[i].set = sets[i];
        if ((T[i].cand = malloc((size_t)nei * sizeof(int)))) T[i].nc = candidates(m, sets[i], T[i].cand);
        T[i].all = T[i].nc == nei;
        T[i].A = malloc((size_t)rows * (T[i].nc > 0 ? T[i].nc : 1) * sizeof(double));
        T[i].b = malloc((size_t)rows * sizeof(double));
        if (!T[i].cand || T[i].nc < 0 || !T[i].A || !T[i].b) st = GAL_ENOMEM;
    }
    if (st || !grp || !w) st = gal_error(GAL_ENOMEM, "reduced model: out of memory for the sampling");
    double *Vt = st ? NULL : basis_rows(m);
    if (!st) st = columns(m, T, nt, Vt);
    for (int i = 0; i < nt && !st; i++) {
        st = nonlinear_part(m, Vt, T[i].set, T[i].cand, T[i].nc, T[i].all, T[i].A, T[i].b);
        if (!st) st = weigh(m, T[i].set, T[i].nc, T[i].A, T[i].b);
        if (!st) st = solve(m, T + i, w, grp);
    }
    for (int i = 0; i < nt; i++) free(T[i].cand), free(T[i].A), free(T[i].b);
    free(grp), free(w), free(Vt);
    return st;
}

int gal_rom_hyper_fit(gal_rom *m, int set)
{
    return fit(m, 1, &set);
}

int gal_rom_hyper_fit_all(gal_rom *m)
{
    static const int both[2] = {0, 1};
    return fit(m, m->hyper->loads ? 2 : 1, both);
}
