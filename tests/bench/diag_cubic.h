/* diag_cubic.h: the candidate vectors of tests/bench/diag_project.c (included by it alone): mass-
 * weighted algebra (diagonal M), the POD of snapshots, the static responses to the aerodynamic
 * load's derivatives, the third-order modal derivatives, and the POD of the cubic part's tangent at
 * given states (the trajectory's, or training states at the scale of the motion), and the cost
 * probe of --cost. */
#ifndef DIAG_CUBIC_H
#define DIAG_CUBIC_H
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <gsl/gsl_eigen.h>

#include "gallop.h"
#include "gallop/base/core.h"
#include "gallop/reduced/rom.h"
#include "base/chol.h"

/* ---- mass-weighted algebra (diagonal M: no eccentric ice; checked in main) ---- */
static double mdot(const gal_rod *rod, const double *a, const double *b)
{
    double s = 0;
    for (int k = 0; k < rod->ndof; k++) s += a[k] * rod->mdiag[k] * b[k];
    return s;
}

/* c -= B B^T M c over nb M-orthonormal columns (twice) */
static void orth(const gal_rod *rod, const double *B, int nb, double *c)
{
    int n = rod->ndof;
    for (int pass = 0; pass < 2; pass++)
        for (int j = 0; j < nb; j++) {
            double p = mdot(rod, B + (size_t)j * n, c);
            for (int k = 0; k < n; k++) c[k] -= p * B[(size_t)j * n + k];
        }
}

/* ---- the POD of the error: eigenvectors of W W^T, W = M^1/2 E (n x n) ---- */
static int pod(const gal_rod *rod, const double *E, int ns, int npod, double *P, double *share)
{
    int n = rod->ndof;
    gsl_matrix *A = gsl_matrix_calloc(n, n), *Z = gsl_matrix_alloc(n, n);
    gsl_vector *lam = gsl_vector_alloc(n);
    gsl_eigen_symmv_workspace *w = gsl_eigen_symmv_alloc(n);
    for (int s = 0; s < ns; s++) {
        const double *e = E + (size_t)s * n;
        for (int i = 0; i < n; i++) {
            double wi = sqrt(rod->mdiag[i]) * e[i];
            if (wi == 0) continue;
            double *row = gsl_matrix_ptr(A, i, 0);
            for (int j = 0; j < n; j++) row[j] += wi * sqrt(rod->mdiag[j]) * e[j];
        }
    }
    gsl_eigen_symmv(A, lam, Z, w);
    gsl_eigen_symmv_sort(lam, Z, GSL_EIGEN_SORT_VAL_DESC);
    double tot = 0;
    for (int i = 0; i < n; i++) tot += fmax(gsl_vector_get(lam, i), 0);
    for (int k = 0; k < npod && k < n; k++) {
        share[k] = gsl_vector_get(lam, k) / tot;
        for (int i = 0; i < n; i++) P[(size_t)k * n + i] = gsl_matrix_get(Z, i, k) / sqrt(rod->mdiag[i]);
    }
    gsl_eigen_symmv_free(w), gsl_vector_free(lam), gsl_matrix_free(A), gsl_matrix_free(Z);
    return GAL_OK;
}

/* ---- candidates ---- */
typedef struct { int n, cap, ndof; double *X; char (*name)[32]; } cands;

static void cand_add(cands *c, const double *x, const char *name)
{
    if (c->n >= c->cap) return;
    memcpy(c->X + (size_t)c->n * c->ndof, x, (size_t)c->ndof * sizeof(double));
    snprintf(c->name[c->n++], 32, "%s", name);
}

/* the free-dof part of a configuration-sized vector */
static void to_free(const gal_rod *rod, const double *fq, double *y)
{
    for (int k = 0; k < rod->ndof; k++) y[k] = fq[rod->free_q[k]];
}

static void cand_aero(cands *c, gal_rom *m, gal_data *d, double t)
{
    const gal_rod *rod = m->rod;
    int n = rod->ndof, nq = rod->nq;
    double *q = malloc(nq * sizeof(double)), *v = calloc(nq, sizeof(double)), *fp = malloc(nq * sizeof(double)),
           *fm = malloc(nq * sizeof(double)), *y = malloc(n * sizeof(double));
    char nm[32];
    for (int i = 0; i < m->nmodes; i++) {
        const double *phi = m->V + (size_t)i * n; /* M-orthonormal modes (the first nmodes columns) */
        double mx = 0;
        for (int k = 0; k < n; k++) mx = fmax(mx, fabs(phi[k]));
        for (int kind = 0; kind < 2; kind++) {
            double e = kind ? 1e-3 / mx : 1e-3 / mx; /* 1 mm of translation, or 1 mm/s */
            for (int s = 0; s < 2; s++) {
                memcpy(q, d->q_start, nq * sizeof(double));
                memset(v, 0, nq * sizeof(double));
                for (int k = 0; k < n; k++) (kind ? v : q)[rod->free_q[k]] += (s ? -e : e) * phi[k];
                double *f = s ? fm : fp;
                memset(f, 0, nq * sizeof(double));
                gal_loads_full(&d->loads, t, q, v, f);
            }
            for (int k = 0; k < nq; k++) fp[k] = (fp[k] - fm[k]) / (2 * e);
            to_free(rod, fp, y);
            gal_chol_solve(m->chol0, y, y);
            snprintf(nm, sizeof nm, "aero_%s%d", kind ? "v" : "q", i);
            cand_add(c, y, nm);
        }
    }
    free(q), free(v), free(fp), free(fm), free(y);
}

/* -K0^-1 (d2K / d eta_j d eta_k) phi_i, i <= j <= k: central second differences of the tangent */
static void cand_third(cands *c, gal_rom *m)
{
    const gal_rod *rod = m->rod;
    int n = rod->ndof, nq = rod->nq, nm = m->nmodes;
    gal_csc *K[4];
    for (int s = 0; s < 4; s++) K[s] = gal_csc_clone(rod->K);
    double *q = malloc(nq * sizeof(double)), *y = malloc(n * sizeof(double)), *w = malloc(n * sizeof(double));
    double sg[4][2] = {{1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
    char name[48];
    for (int j = 0; j < nm; j++)
        for (int k = j; k < nm; k++) {
            const double *pj = m->V + (size_t)j * n, *pk = m->V + (size_t)k * n;
            double mj = 0, mk = 0;
            for (int d = 0; d < n; d++) mj = fmax(mj, fabs(pj[d])), mk = fmax(mk, fabs(pk[d]));
            double ej = 2e-2 / mj, ek = 2e-2 / mk; /* 2 cm: a second difference needs a larger step */
            for (int s = 0; s < 4; s++) {
                memcpy(q, m->q_eq, nq * sizeof(double));
                for (int d = 0; d < n; d++) q[rod->free_q[d]] += sg[s][0] * ej * pj[d] + sg[s][1] * ek * pk[d];
                gal_rod_eval(rod, q, NULL, NULL, K[s]);
            }
            for (int i = 0; i <= j; i++) {
                const double *pi = m->V + (size_t)i * n;
                memset(y, 0, n * sizeof(double));
                for (int s = 0; s < 4; s++) {
                    gal_csc_symv(K[s], pi, w);
                    for (int d = 0; d < n; d++) y[d] -= sg[s][0] * sg[s][1] * w[d] / (4 * ej * ek);
                }
                gal_chol_solve(m->chol0, y, y);
                snprintf(name, sizeof name, "third_%d_%d_%d", i % 100, j % 100, k % 100);
                cand_add(c, y, name);
            }
        }
    for (int s = 0; s < 4; s++) gal_csc_free(K[s]);
    free(q), free(y), free(w);
}

/* Orthonormalize the candidates [from, to) against V and each other in place (M inner product);
 * returns how many are kept (moved to the front of the range). */
static int cand_orth(cands *c, const gal_rom *m, int from, int to, double *Q)
{
    const gal_rod *rod = m->rod;
    int n = rod->ndof, kept = 0;
    for (int j = from; j < to; j++) {
        double *x = Q + (size_t)kept * n;
        memcpy(x, c->X + (size_t)j * n, n * sizeof(double));
        double n0 = sqrt(mdot(rod, x, x));
        orth(rod, m->V, m->r, x);
        orth(rod, Q, kept, x);
        double n1 = sqrt(mdot(rod, x, x));
        if (!(n1 > 1e-6 * n0)) continue;
        for (int k = 0; k < n; k++) x[k] /= n1;
        kept++;
    }
    return kept;
}

/* share of the error snapshots E (n x ns) captured by the span of Q (nq M-orthonormal columns) */
static double captured(const gal_rod *rod, const double *E, int ns, const double *Q, int nq)
{
    int n = rod->ndof;
    double tot = 0, cap = 0;
    for (int s = 0; s < ns; s++) {
        const double *e = E + (size_t)s * n;
        tot += mdot(rod, e, e);
        for (int j = 0; j < nq; j++) {
            double p = mdot(rod, Q + (size_t)j * n, e);
            cap += p * p;
        }
    }
    return cap / fmax(tot, 1e-300);
}

/* the tangent of the cubic part along each mode at the states eta[t*nm..]: d/d eta_i =
 * 1/2 sum_qr Xi_iqr eta_q eta_r (Xi: the third-order derivatives th[], in cand_third's order),
 * less its content in V, and its POD (npod vectors into P, shares) */
static void cubic_tangent_pod(const gal_rom *m, const double *th0, const double *eta, int nst, int normalize, int npod,
                              double *P, double *share)
{
    const gal_rod *rod = m->rod;
    int n = rod->ndof, nm = m->nmodes;
    double *W = calloc((size_t)n * nm * nst, sizeof(double));
    for (int t = 0; t < nst; t++) {
        const double *e = eta + (size_t)t * nm;
        int id = 0;
        for (int j = 0; j < nm; j++)
            for (int k = j; k < nm; k++)
                for (int i = 0; i <= j; i++, id++) {
                    int tr[3] = {i, j, k};
                    const double *th = th0 + (size_t)id * n;
                    for (int p3 = 0; p3 < 3; p3++) {
                        if (p3 > 0 && tr[p3] == tr[p3 - 1]) continue; /* each distinct index once */
                        int o1 = tr[(p3 + 1) % 3], o2 = tr[(p3 + 2) % 3];
                        double w = 0.5 * (o1 == o2 ? 1 : 2) * e[o1] * e[o2];
                        double *y = W + ((size_t)t * nm + tr[p3]) * n;
                        for (int d2 = 0; d2 < n; d2++) y[d2] += w * th[d2];
                    }
                }
    }
    for (int t = 0; t < nst * nm; t++) {
        double *y = W + (size_t)t * n;
        orth(rod, m->V, m->r, y);
        if (normalize) { /* each snapshot at unit M-norm: the twist's are not swamped */
            double nr = sqrt(mdot(rod, y, y));
            if (nr > 0)
                for (int d2 = 0; d2 < n; d2++) y[d2] /= nr;
        }
    }
    pod(rod, W, nst * nm, npod, P, share);
    free(W);
}

/* training states at the scale of the motion, as the hyper-reduction's (ecsw_train.c): the modes
 * at random directions, each mode's largest translation up to the sag (at least 1% of the span)
 * and its largest twist up to 1.5 rad, overall amplitudes 0.1-1.2 of that */
static void training_states(const gal_rom *m, int nst, double *eta)
{
    const gal_rod *rod = m->rod;
    int n = rod->ndof, nm = m->nmodes, nn = rod->nn;
    const double *q = m->q_eq;
    double L = q[3 * (nn - 1)] - q[0], hd = q[3 * (nn - 1) + 2] - q[2], sag = 0;
    for (int i = 0; i < nn; i++) sag = fmax(sag, q[2] + hd * (q[3 * i] - q[0]) / L - q[3 * i + 2]);
    double amp = fmax(sag, 0.01 * L), emax[64];
    for (int k = 0; k < nm; k++) {
        double st = 0, sr = 0;
        for (int d = 0; d < n; d++) {
            double v = fabs(m->V[(size_t)k * n + d]);
            if (rod->free_q[d] < 3 * nn) st = fmax(st, v);
            else sr = fmax(sr, v);
        }
        emax[k] = INFINITY;
        if (st > 0) emax[k] = amp / st;
        if (sr > 0) emax[k] = fmin(emax[k], 1.5 / sr);
    }
    unsigned long long seed = 0x9E3779B97F4A7C15ULL;
    for (int s = 0; s < nst; s++) {
        double u[64], uu = 0;
        seed ^= seed >> 12, seed ^= seed << 25, seed ^= seed >> 27;
        double a = 0.1 + 1.1 * (double)((seed * 2685821657736338717ULL) >> 11) / 9007199254740992.0;
        for (int k = 0; k < nm; k++) {
            seed ^= seed >> 12, seed ^= seed << 25, seed ^= seed >> 27;
            double r1 = ((seed * 2685821657736338717ULL) >> 11) / 9007199254740992.0 + 1e-17;
            seed ^= seed >> 12, seed ^= seed << 25, seed ^= seed >> 27;
            double r2 = ((seed * 2685821657736338717ULL) >> 11) / 9007199254740992.0;
            u[k] = sqrt(-2 * log(r1)) * cos(2 * GAL_PI * r2), uu += u[k] * u[k];
        }
        for (int k = 0; k < nm; k++) eta[(size_t)s * nm + k] = a * u[k] / sqrt(uu) * emax[k];
    }
}

/* ---- the cost of a step (diag_project --cost) ---- */
/* --cost: where a step's time goes with nx extra vectors: the model as a run builds it (sampled,
 * the scene's step and damping), started at the full run's state at --cost-from, stepped for
 * --cost-span s without checks; the sample sizes, Newton iterations, tangents, halvings and element
 * evaluations per step, CPU per step; then the same with every element (hyper off) and with the
 * basis's stiffest direction's frequency (sqrt of the largest eigenvalue of V^T K0 V) */
static double cost_from = -1, cost_span = 20;
static void cost_probe(gal_sim_setup *s, const double *X, int nx, const char *label)
{
    gal_data *d = s->data;
    const gal_modes *md = &d->md;
    int sel[64], nsel = 0;
    double fhi = 0;
    for (int k = 0; k < md->n && nsel < 64; k++)
        if (md->mode[k].selected) sel[nsel++] = k, fhi = fmax(fhi, md->mode[k].frequency_hz);
    double dt_out = s->sc->simulation.output_interval;
    if (!(dt_out > 0)) dt_out = fmin(0.05, 1.0 / (10 * fhi));
    double h = s->sc->simulation.time_step;
    if (!(h > 0)) h = fmin(dt_out, 1.0 / (40 * fhi));
    int sub = (int)ceil(dt_out / h - 1e-9);
    gal_force F = {0};
    if (d->loads.table) F.eval = gal_loads_full, F.element = gal_loads_element, F.ctx = (void *)&d->loads;
    for (int hyper = 1; hyper >= 0; hyper--) {
        gal_rom_opts ro;
        gal_rom_default_opts(&ro);
        ro.h = dt_out / sub, ro.rho_inf = s->sc->simulation.rho_inf, ro.damping = d->damping, ro.hyper = hyper;
        ro.extra = nx ? X : NULL, ro.nextra = nx;
        clock_t c0 = clock();
        gal_rom *m = gal_rom_alloc(d->eq.rod, d->eq.q, md, sel, nsel, &ro, &F);
        if (!m) { printf("COST %s: %s\n", label, gal_error_message()); return; }
        double tb = (double)(clock() - c0) / CLOCKS_PER_SEC;
        /* the stiffest direction of the basis: V^T K0 V's largest eigenvalue */
        gsl_matrix *A = gsl_matrix_alloc(m->r, m->r);
        for (int i = 0; i < m->r * m->r; i++) A->data[i] = m->K0r[i];
        gsl_vector *ev = gsl_vector_alloc(m->r);
        gsl_eigen_symm_workspace *ew = gsl_eigen_symm_alloc(m->r);
        gsl_eigen_symm(A, ev, ew);
        double lmax = gsl_vector_max(ev);
        gsl_eigen_symm_free(ew), gsl_vector_free(ev), gsl_matrix_free(A);
        gal_rom_start(m, 0.0, d->q_start, NULL);
        double t1 = cost_from >= 0 ? cost_from : 0;
        int st = 0;
        while (!st && m->t < t1 - 1e-9) st = gal_rom_step(m);
        long s0 = m->steps, n0 = m->newton_iterations, k0 = m->tangents, f0 = m->force_evaluations, hv0 = m->halvings;
        long e0 = m->element_evaluations, l0 = m->load_element_evaluations, c0e = m->check_element_evaluations;
        c0 = clock();
        while (!st && m->t < t1 + cost_span - 1e-9) st = gal_rom_step(m);
        double cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
        long ns = m->steps - s0;
        gal_rom_hyper_info hi;
        gal_rom_hyper_get_info(m, &hi);
        printf("COST %s hyper %d: basis %d, sample %d energy / %d load elements (fit %.1e), stiffest %.1f Hz, h %.4f s "
               "(w h %.1f); set-up %.2f s CPU; %ld steps from %.0f s%s: %.2f Newton, %.2f tangents, %.2f force evals, "
               "%ld halvings, %.0f energy + %.0f load elements a step, %d re-samplings, %.0f check elements a step; %.1f us CPU a step\n",
               label, hyper, m->r, hi.elements, hi.load_elements, hi.fit_error, sqrt(fmax(lmax, 0)) / (2 * GAL_PI), ro.h,
               sqrt(fmax(lmax, 0)) * ro.h, tb, ns, t1, st ? " (FAILED)" : "", (double)(m->newton_iterations - n0) / ns,
               (double)(m->tangents - k0) / ns, (double)(m->force_evaluations - f0) / ns, m->halvings - hv0,
               (double)(m->element_evaluations - e0) / ns, (double)(m->load_element_evaluations - l0) / ns, hi.refits,
               (double)(m->check_element_evaluations - c0e) / ns, 1e6 * cpu / fmax(ns, 1));
        gal_rom_free(m);
    }
}

#endif
