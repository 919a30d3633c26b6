/* modes.c: the explicit bundle's modes (bundle.h): K phi = w^2 M phi of the assembled system by
 * ARPACK in shift-invert mode with a CHOLMOD factorization of K - sigma M, and the modes' families
 * from the bundle's kinematics (classify.c). */
#include "gallop/bundle/bundle.h"
#include "gallop/base/core.h"
#include "bundle_impl.h"

#include <arpack/arpack.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/chol.h"

typedef struct {
    int n, nev, ncv, lworkl;
    double *tmp, *resid, *v, *workd, *workl, *d, *z;
    int *select;
    gal_csc *A;
    gal_chol *chol;
} ws;

static void ws_free(ws *w)
{
    gal_chol_free(w->chol), gal_csc_free(w->A);
    free(w->tmp), free(w->resid), free(w->v), free(w->workd), free(w->workl), free(w->d), free(w->z);
    free(w->select);
}

static int ws_alloc(ws *w, const gal_bundle *b, int nev)
{
    int n = b->ndof;
    memset(w, 0, sizeof *w);
    w->n = n, w->nev = nev;
    w->ncv = 2 * nev + 1 > nev + 20 ? 2 * nev + 1 : nev + 20;
    if (w->ncv > n) w->ncv = n;
    w->lworkl = w->ncv * (w->ncv + 8);
    w->tmp = malloc((size_t)n * sizeof(double)), w->resid = malloc((size_t)n * sizeof(double));
    w->v = malloc((size_t)n * w->ncv * sizeof(double)), w->workd = malloc((size_t)3 * n * sizeof(double));
    w->workl = malloc((size_t)w->lworkl * sizeof(double)), w->d = malloc((size_t)nev * sizeof(double));
    w->z = malloc((size_t)n * nev * sizeof(double)), w->select = calloc((size_t)w->ncv, sizeof(int));
    w->A = gal_csc_clone(b->K);
    w->chol = w->A ? gal_chol_alloc(w->A) : NULL;
    if (!w->tmp || !w->resid || !w->v || !w->workd || !w->workl || !w->d || !w->z || !w->select || !w->chol) {
        ws_free(w);
        return gal_error(GAL_ENOMEM, "bundle modes: out of memory for %d modes of %d dofs", nev, n);
    }
    return GAL_OK;
}

/* K - sigma M, sigma below the lowest frequency, factored. */
static int shift_factor(gal_bundle *b, ws *w, gal_modes *out)
{
    int st = gal_bundle_eval(b, NULL, NULL, 1);
    if (st) return st;
    const gal_csc *K = b->K, *M = b->M;
    double kmin = INFINITY;
    for (int j = 0; j < w->n; j++)
        if (M->val[M->diag[j]] > 0) kmin = fmin(kmin, K->val[K->diag[j]] / M->val[M->diag[j]]);
    double sigma = -0.1 * kmin * pow(GAL_PI / b->rod[0]->p.elements, 2);
    if (!(sigma < 0)) sigma = -1e-3;
    out->sigma = sigma;
    for (int k = 0; k < K->nnz; k++) w->A->val[k] = K->val[k] - sigma * M->val[k];
    if (gal_chol_factor(w->chol, w->A, 0, NULL) != GAL_OK || w->chol->negative_pivots)
        return gal_error(GAL_EFAIL, "bundle modes: K - sigma M is not positive definite at sigma = %g (%d negative "
                         "pivots): the equilibrium has lost stability", sigma, w->chol->negative_pivots);
    return GAL_OK;
}

static int arpack(const gal_bundle *b, ws *w, gal_modes *out)
{
    int n = w->n, ido = 0, info = 1, iparam[11] = {0}, ipntr[14] = {0}, st;
    iparam[0] = 1, iparam[2] = 1000, iparam[6] = 3;
    double tol = 1e-12;
    for (int k = 0; k < n; k++) w->resid[k] = 1.0 + 0.37 * sin(1.3 * k);
    for (;;) {
        dsaupd_c(&ido, "G", n, "LM", w->nev, tol, w->resid, w->ncv, w->v, n, iparam, ipntr, w->workd, w->workl,
                 w->lworkl, &info);
        double *x = w->workd + ipntr[0] - 1, *y = w->workd + ipntr[1] - 1;
        if (ido == -1) {
            gal_csc_symv(b->M, x, w->tmp);
            if ((st = gal_chol_solve(w->chol, w->tmp, y))) return st;
            out->op_applications++;
        } else if (ido == 1) {
            if ((st = gal_chol_solve(w->chol, w->workd + ipntr[2] - 1, y))) return st;
            out->op_applications++;
        } else if (ido == 2) {
            gal_csc_symv(b->M, x, y);
        } else {
            break;
        }
    }
    if (info < 0 || info == 1)
        return gal_error(GAL_EFAIL, "bundle modes: ARPACK dsaupd failed (info %d)", info);
    out->arpack_restarts = iparam[2];
    dseupd_c(1, "A", w->select, w->d, w->z, n, out->sigma, "G", n, "LM", w->nev, tol, w->resid, w->ncv, w->v, n,
             iparam, ipntr, w->workd, w->workl, w->lworkl, &info);
    if (info != 0) return gal_error(GAL_EFAIL, "bundle modes: ARPACK dseupd failed (info %d)", info);
    if (iparam[4] < w->nev)
        return gal_error(GAL_EFAIL, "bundle modes: ARPACK converged %d of %d modes", iparam[4], w->nev);
    return GAL_OK;
}

/* By increasing frequency, mass-normalized, largest entry positive, classified. */
static int extract(const gal_bundle *b, ws *w, gal_modes *out)
{
    int n = w->n, nev = w->nev;
    out->n = nev, out->ndof = n;
    out->mode = calloc((size_t)nev, sizeof(gal_mode));
    out->shape = malloc((size_t)n * nev * sizeof(double));
    int *ord = malloc((size_t)nev * sizeof(int));
    double *scratch = malloc(gal_bundle_classify_scratch(b) * sizeof(double));
    if (!out->mode || !out->shape || !ord || !scratch) { free(ord), free(scratch); return gal_error(GAL_ENOMEM, "bundle modes: out of memory"); }
    for (int k = 0; k < nev; k++) ord[k] = k;
    for (int a = 1; a < nev; a++)
        for (int c = a; c > 0 && w->d[ord[c]] < w->d[ord[c - 1]]; c--) { int t = ord[c]; ord[c] = ord[c - 1]; ord[c - 1] = t; }
    int st = GAL_OK;
    for (int k = 0; k < nev && !st; k++) {
        const double *phi = w->z + (size_t)ord[k] * n;
        double *dst = out->shape + (size_t)k * n, mm = 0, big = 0, lam = w->d[ord[k]];
        gal_csc_symv(b->M, phi, w->tmp);
        for (int j = 0; j < n; j++) {
            mm += w->tmp[j] * phi[j];
            if (fabs(phi[j]) > fabs(big)) big = phi[j];
        }
        double s = (big < 0 ? -1.0 : 1.0) / sqrt(mm);
        for (int j = 0; j < n; j++) dst[j] = s * phi[j];
        if (lam < -1e-6 * fabs(out->sigma))
            st = gal_error(GAL_EFAIL, "bundle modes: mode %d has omega^2 = %.3g < 0: the equilibrium has lost "
                           "stability", k + 1, lam);
        gal_mode *md = out->mode + k;
        md->index = k + 1;
        md->omega = lam > 0 ? sqrt(lam) : 0;
        md->frequency_hz = md->omega / (2 * GAL_PI);
        gal_bundle_classify(b, dst, scratch, md);
        out->found[md->family]++;
    }
    free(ord), free(scratch);
    return st;
}

int gal_bundle_modes_solve(gal_bundle *b, int nev, gal_modes *out)
{
    double t0 = gal_wall_time();
    memset(out, 0, sizeof *out);
    if (nev < 1 || nev > b->ndof - 1)
        return gal_error(GAL_EINPUT, "bundle modes: %d modes asked of a system with %d dofs (allowed: 1 to %d)", nev,
                         b->ndof, b->ndof - 1);
    ws w;
    int st = ws_alloc(&w, b, nev);
    if (st) return st;
    st = shift_factor(b, &w, out);
    if (!st) st = arpack(b, &w, out);
    if (!st) st = extract(b, &w, out);
    out->factorizations = w.chol->factorizations, out->solves = w.chol->solves;
    ws_free(&w);
    out->rounds = 1;
    out->wall_time_s = gal_wall_time() - t0;
    if (st) gal_modes_clear(out);
    return st;
}

int gal_bundle_modes_find(gal_bundle *b, const int want[GAL_FAMILY_COUNT], int max_modes, gal_modes *out)
{
    double t0 = gal_wall_time();
    if (max_modes > b->ndof - 1) max_modes = b->ndof - 1;
    int nev = 2 * (want[0] + want[1] + want[2]) + 8, rounds = 0;
    long op = 0, fact = 0, solves = 0;
    for (;;) {
        if (nev > max_modes) nev = max_modes;
        int st = gal_bundle_modes_solve(b, nev, out);
        rounds++;
        op += out->op_applications, fact += out->factorizations, solves += out->solves;
        if (st) return st;
        int short_family = 0;
        for (int f = 0; f < 3; f++) short_family |= out->found[f] < want[f];
        /* every mode up to the torsional partners' band (gal_modes_select) */
        short_family |= out->mode[out->n - 1].frequency_hz < gal_modes_partner_top(out, want);
        if (!short_family || nev >= max_modes) break;
        gal_modes_clear(out);
        nev *= 2;
    }
    gal_modes_select(out, want);
    out->rounds = rounds, out->op_applications = op, out->factorizations = fact, out->solves = solves;
    out->wall_time_s = gal_wall_time() - t0;
    return GAL_OK;
}
