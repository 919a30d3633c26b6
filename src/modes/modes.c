/* modes.c: modes of the linearized rod, K phi = w^2 M phi (paper Eq. 9 without damping and load),
 * by ARPACK shift-invert (mode 3) with CHOLMOD; classification by kinetic-energy shares. */
#include "gallop/modes/modes.h"
#include "gallop/base/core.h"
#include "gallop/base/vec3.h"

#include <arpack/arpack.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/chol.h"

const char *const gal_family_names[GAL_FAMILY_COUNT] = {"vertical", "horizontal", "torsional", "axial",
                                                          "subspan"};
const char *const gal_symmetry_names[3] = {"symmetric", "antisymmetric", "none"};

void gal_modes_clear(gal_modes *m)
{
    free(m->mode);
    free(m->shape);
    memset(m, 0, sizeof *m);
}


/* Shares of kinetic energy and symmetry of one mode. The local axes at node i: the tangent t,
 * the normal b of the span's plane (chord x mid-span offset; y when the span is straight) and the
 * in-plane normal n = t x b. */
static void classify(const gal_rod *rod, const double *q, const double *phi_free, double *full,
                     gal_mode *md)
{
    int nn = rod->nn, nel = rod->p.elements;
    memset(full, 0, (size_t)rod->nq * sizeof(double));
    gal_rod_scatter(rod, phi_free, full);
    double chord[3] = {q[3 * nel] - q[0], q[3 * nel + 1] - q[1], q[3 * nel + 2] - q[2]};
    int mid = nn / 2;
    double off[3] = {q[3 * mid] - 0.5 * (q[0] + q[3 * nel]), q[3 * mid + 1] - 0.5 * (q[1] + q[3 * nel + 1]),
                     q[3 * mid + 2] - 0.5 * (q[2] + q[3 * nel + 2])};
    double b[3] = {chord[1] * off[2] - chord[2] * off[1], chord[2] * off[0] - chord[0] * off[2],
                   chord[0] * off[1] - chord[1] * off[0]};
    double nb = sqrt(gal_dot3(b, b));
    if (nb < 1e-9 * gal_dot3(chord, chord)) b[0] = 0, b[1] = 1, b[2] = 0;
    else for (int k = 0; k < 3; k++) b[k] /= nb;

    double ke[GAL_FAMILY_COUNT] = {0};
    /* per node (or edge) family components, for the symmetry test */
    double *comp = malloc((size_t)(4 * (nn > nel ? nn : nel)) * sizeof(double));
    for (int i = 0; i < nn; i++) {
        int a = i > 0 ? i - 1 : 0, c = i < nel ? i : nel - 1;
        double t[3];
        for (int k = 0; k < 3; k++) t[k] = q[3 * (c + 1) + k] - q[3 * a + k];
        double nt = sqrt(gal_dot3(t, t));
        for (int k = 0; k < 3; k++) t[k] /= nt;
        double n[3] = {t[1] * b[2] - t[2] * b[1], t[2] * b[0] - t[0] * b[2], t[0] * b[1] - t[1] * b[0]};
        const double *u = full + 3 * i;
        double uv = gal_dot3(u, n), uh = gal_dot3(u, b), ua = gal_dot3(u, t), m = rod->node_mass[i];
        ke[GAL_FAMILY_VERTICAL] += m * uv * uv;
        ke[GAL_FAMILY_HORIZONTAL] += m * uh * uh;
        ke[GAL_FAMILY_AXIAL] += m * ua * ua;
        if (comp) comp[4 * i + 0] = uv, comp[4 * i + 1] = uh, comp[4 * i + 3] = ua;
    }
    if (rod->p.torsion)
        for (int j = 0; j < nel; j++) {
            double th = full[3 * nn + j];
            ke[GAL_FAMILY_TORSIONAL] += rod->edge_inertia[j] * th * th;
            if (comp) comp[4 * j + 2] = th;
        }
    double tot = ke[0] + ke[1] + ke[2] + ke[3];
    int fam = 0;
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) {
        md->share[f] = tot > 0 ? ke[f] / tot : 0;
        if (md->share[f] > md->share[fam]) fam = f;
    }
    md->family = (gal_family)fam;
    /* symmetry: correlation of the dominant component with its mirror image about mid-span
     * (node i <-> nn-1-i, edge j <-> nel-1-j); the axial component changes sign under the
     * mirror since the tangent does */
    md->symmetry = GAL_SYM_NONE;
    if (comp) {
        int cnt = fam == GAL_FAMILY_TORSIONAL ? nel : nn;
        double sgn = fam == GAL_FAMILY_AXIAL ? -1.0 : 1.0, num = 0, den = 0;
        for (int i = 0; i < cnt; i++) {
            double a = comp[4 * i + fam], m = comp[4 * (cnt - 1 - i) + fam];
            num += a * sgn * m;
            den += a * a;
        }
        double r = den > 0 ? num / den : 0;
        md->symmetry = r > 0.9 ? GAL_SYM_SYMMETRIC : r < -0.9 ? GAL_SYM_ANTISYMMETRIC : GAL_SYM_NONE;
        free(comp);
    }
}

/* Within a cluster of (numerically) equal frequencies any orthonormal combination is a mode:
 * choose the one that diagonalizes the horizontal kinetic energy, so that a straight span's
 * coincident vertical and horizontal modes come out pure. */
static void split_clusters(const gal_rod *rod, gal_modes *out, const double *mdiag, const double *lam)
{
    int n = out->ndof, nm = out->n;
    for (int a = 0; a < nm;) {
        int b = a + 1;
        while (b < nm && fabs(lam[b] - lam[a]) <= 1e-7 * fabs(lam[a])) b++;
        if (b - a == 2) { /* pairs are what occurs (a straight span); a Jacobi rotation */
            double *p = out->shape + (size_t)a * n, *q = out->shape + (size_t)(a + 1) * n;
            double hpp = 0, hqq = 0, hpq = 0;
            for (int j = 0; j < n; j++) {
                int k = rod->free_q[j];
                if (k < 3 * rod->nn && k % 3 == 1) {
                    hpp += mdiag[j] * p[j] * p[j];
                    hqq += mdiag[j] * q[j] * q[j];
                    hpq += mdiag[j] * p[j] * q[j];
                }
            }
            double th = 0.5 * atan2(2 * hpq, hpp - hqq), c = cos(th), s = sin(th);
            for (int j = 0; j < n; j++) {
                double x = p[j], y = q[j];
                p[j] = c * x + s * y;
                q[j] = -s * x + c * y;
            }
        }
        a = b;
    }
}

/* The workspace of one ARPACK run: the stage's own K - sigma M and its factorization. */
typedef struct {
    int n, nev, ncv, lworkl;
    double *mdiag, *tmp, *resid, *v, *workd, *workl, *d, *z, *full;
    int *select;
    gal_csc *K;
    gal_chol *chol;
} modes_ws;

static void ws_free(modes_ws *w)
{
    gal_chol_free(w->chol);
    gal_csc_free(w->K);
    free(w->mdiag); free(w->tmp); free(w->resid); free(w->v); free(w->workd); free(w->workl); free(w->d);
    free(w->z); free(w->full); free(w->select);
}

static int ws_alloc(modes_ws *w, const gal_rod *rod, int nev)
{
    int n = rod->ndof;
    memset(w, 0, sizeof *w);
    w->n = n, w->nev = nev;
    w->ncv = 2 * nev + 1 > nev + 20 ? 2 * nev + 1 : nev + 20;
    if (w->ncv > n) w->ncv = n;
    int ncv = w->ncv;
    w->lworkl = ncv * (ncv + 8);
    w->mdiag = malloc((size_t)n * sizeof(double)), w->tmp = malloc((size_t)n * sizeof(double));
    w->resid = malloc((size_t)n * sizeof(double)), w->v = malloc((size_t)n * ncv * sizeof(double));
    w->workd = malloc((size_t)3 * n * sizeof(double)), w->workl = malloc((size_t)w->lworkl * sizeof(double));
    w->d = malloc((size_t)nev * sizeof(double)), w->z = malloc((size_t)n * nev * sizeof(double));
    w->full = malloc((size_t)rod->nq * sizeof(double));
    w->select = calloc((size_t)ncv, sizeof(int));
    w->K = gal_csc_clone(rod->K);
    w->chol = w->K ? gal_chol_alloc(w->K) : NULL;
    if (!w->mdiag || !w->tmp || !w->resid || !w->v || !w->workd || !w->workl || !w->d || !w->z || !w->full ||
        !w->select || !w->K || !w->chol) {
        ws_free(w);
        return gal_error(GAL_ENOMEM, "modes: out of memory for %d modes of %d dofs", nev, n);
    }
    return GAL_OK;
}

/* The tangent at q, the shift sigma below the lowest frequency, and the factorization of
 * K - sigma M. */
static int shift_factor(const gal_rod *rod, const double *q, modes_ws *w, gal_modes *out)
{
    gal_csc *K = w->K;
    int n = w->n, st;
    if ((st = gal_rod_eval(rod, q, NULL, NULL, K))) return st;
    gal_rod_mass_diag(rod, w->mdiag);
    /* shift below the lowest frequency: a fraction of the lowest string frequency
     * (pi/L)^2 T/m, from the smallest ratio of stiffness to mass on the diagonal scaled */
    double kmin = INFINITY;
    for (int j = 0; j < n; j++) kmin = fmin(kmin, K->val[K->diag[j]] / w->mdiag[j]);
    double sigma = -0.1 * kmin * pow(GAL_PI / rod->p.elements, 2);
    if (!(sigma < 0)) sigma = -1e-3;
    out->sigma = sigma;
    /* K - sigma M on the common pattern (M is not diagonal with eccentric ice) */
    for (int k = 0; k < K->nnz; k++) K->val[k] -= sigma * rod->M->val[k];
    if (gal_chol_factor(w->chol, K, 0, NULL) != GAL_OK)
        return gal_error(GAL_EFAIL, "modes: K - sigma M is not positive definite at sigma = %g: the "
                         "equilibrium has lost stability (%s)", sigma, gal_error_message());
    if (w->chol->negative_pivots)
        return gal_error(GAL_EFAIL, "modes: K - sigma M has %d negative eigenvalue%s at sigma = %g: the "
                         "equilibrium has lost stability", w->chol->negative_pivots,
                         w->chol->negative_pivots > 1 ? "s" : "", sigma);
    return GAL_OK;
}

/* ARPACK reverse communication, OP = (K - sigma M)^-1 M, B = M, then the eigenpairs (w->d, w->z). */
static int arpack(const gal_rod *rod, modes_ws *w, gal_modes *out)
{
    int n = w->n, nev = w->nev, ncv = w->ncv, st;
    int ido = 0, info = 0, iparam[11] = {0}, ipntr[14] = {0};
    iparam[0] = 1;     /* exact shifts */
    iparam[2] = 1000;  /* maximum restarts */
    iparam[6] = 3;     /* shift-invert mode */
    double tol = 1e-12, sigma = out->sigma;
    for (int k = 0; k < n; k++) w->resid[k] = 1.0 + 0.37 * sin(1.3 * k); /* deterministic start */
    info = 1;
    for (;;) {
        dsaupd_c(&ido, "G", n, "LM", nev, tol, w->resid, ncv, w->v, n, iparam, ipntr, w->workd, w->workl,
                 w->lworkl, &info);
        double *x = w->workd + ipntr[0] - 1, *y = w->workd + ipntr[1] - 1;
        if (ido == -1) {
            gal_rod_mass_mult(rod, x, w->tmp);
            if ((st = gal_chol_solve(w->chol, w->tmp, y))) return st;
            out->op_applications++;
        } else if (ido == 1) {
            if ((st = gal_chol_solve(w->chol, w->workd + ipntr[2] - 1, y))) return st;
            out->op_applications++;
        } else if (ido == 2) {
            gal_rod_mass_mult(rod, x, y);
        } else {
            break;
        }
    }
    if (info < 0 || info == 1)
        return gal_error(GAL_EFAIL, "modes: ARPACK dsaupd failed (info %d%s)", info,
                         info == 1 ? ": maximum number of restarts reached" : "");
    out->arpack_restarts = iparam[2];
    dseupd_c(1, "A", w->select, w->d, w->z, n, sigma, "G", n, "LM", nev, tol, w->resid, ncv, w->v, n, iparam,
             ipntr, w->workd, w->workl, w->lworkl, &info);
    if (info != 0) return gal_error(GAL_EFAIL, "modes: ARPACK dseupd failed (info %d)", info);
    int nconv = iparam[4];
    if (nconv < nev) return gal_error(GAL_EFAIL, "modes: ARPACK converged %d of %d modes", nconv, nev);
    return GAL_OK;
}

/* The modes by increasing frequency, mass-normalized, coincident pairs split, signs fixed,
 * classified. */
static int extract(const gal_rod *rod, const double *q, modes_ws *w, gal_modes *out)
{
    int n = w->n, nev = w->nev;
    out->n = nev;
    out->ndof = n;
    out->mode = calloc((size_t)nev, sizeof(gal_mode));
    out->shape = malloc((size_t)n * nev * sizeof(double));
    int *ord = malloc((size_t)nev * sizeof(int));
    if (!out->mode || !out->shape || !ord) {
        free(ord);
        return gal_error(GAL_ENOMEM, "modes: out of memory");
    }
    /* sort by eigenvalue (dseupd returns them ascending, but do not rely on it) */
    const double *d = w->d;
    for (int k = 0; k < nev; k++) ord[k] = k;
    for (int a = 1; a < nev; a++)
        for (int b = a; b > 0 && d[ord[b]] < d[ord[b - 1]]; b--) { int t = ord[b]; ord[b] = ord[b - 1]; ord[b - 1] = t; }
    for (int k = 0; k < nev; k++) {
        const double *phi = w->z + (size_t)ord[k] * n;
        double *dst = out->shape + (size_t)k * n;
        /* mass-normalize (ARPACK's are M-orthonormal already; renormalize against round-off) and
         * fix the sign: largest entry positive */
        double mm = 0, big = 0;
        gal_rod_mass_mult(rod, phi, w->tmp);
        for (int j = 0; j < n; j++) {
            mm += w->tmp[j] * phi[j];
            if (fabs(phi[j]) > fabs(big)) big = phi[j];
        }
        double s = (big < 0 ? -1.0 : 1.0) / sqrt(mm);
        for (int j = 0; j < n; j++) dst[j] = s * phi[j];
        gal_mode *md = out->mode + k;
        double lam = d[ord[k]];
        /* a negative eigenvalue is lost stability, never a 0 Hz mode; a round-off one (the
         * neutral rotation of a span free to twist) is 0 */
        if (lam < -1e-6 * fabs(out->sigma)) {
            free(ord);
            return gal_error(GAL_EFAIL, "modes: mode %d has omega^2 = %.3g < 0: the equilibrium has lost "
                             "stability", k + 1, lam);
        }
        md->omega = lam > 0 ? sqrt(lam) : 0;
        md->frequency_hz = md->omega / (2 * GAL_PI);
    }
    free(ord);
    double *lam = malloc((size_t)nev * sizeof(double));
    if (lam) {
        for (int k = 0; k < nev; k++) lam[k] = out->mode[k].omega * out->mode[k].omega;
        split_clusters(rod, out, w->mdiag, lam);
        free(lam);
    }
    for (int k = 0; k < nev; k++) {
        gal_mode *md = out->mode + k;
        /* sign: largest entry positive */
        double *dst = out->shape + (size_t)k * n, big = 0;
        for (int j = 0; j < n; j++) if (fabs(dst[j]) > fabs(big)) big = dst[j];
        if (big < 0) for (int j = 0; j < n; j++) dst[j] = -dst[j];
        classify(rod, q, dst, w->full, md);
        out->found[md->family]++;
    }
    return GAL_OK;
}

int gal_modes_solve(const gal_rod *rod, const double *q, int nev, gal_modes *out)
{
    double t0 = gal_wall_time();
    memset(out, 0, sizeof *out);
    int n = rod->ndof;
    if (nev < 1 || nev > n - 1)
        return gal_error(GAL_EINPUT, "modes: %d modes asked of a system with %d degrees of freedom "
                         "(allowed: 1 to %d)", nev, n, n - 1);
    modes_ws w;
    int st = ws_alloc(&w, rod, nev);
    if (st) return st;
    st = shift_factor(rod, q, &w, out);
    if (!st) st = arpack(rod, &w, out);
    if (!st) st = extract(rod, q, &w, out);
    out->factorizations = w.chol->factorizations;
    out->solves = w.chol->solves;
    ws_free(&w);
    out->rounds = 1;
    out->wall_time_s = gal_wall_time() - t0;
    if (st) {
        free(out->mode); free(out->shape);
        out->mode = NULL, out->shape = NULL, out->n = 0;
    }
    return st;
}

int gal_modes_find(const gal_rod *rod, const double *q, const int want[GAL_FAMILY_COUNT],
                   int max_modes, gal_modes *out)
{
    double t0 = gal_wall_time();
    int n = rod->ndof;
    if (max_modes > n - 1) max_modes = n - 1;
    /* estimate by string theory: transverse f_k = k f1, torsional f_k = k/(2 L0) sqrt(GJ/I) */
    int total = want[0] + want[1] + want[2];
    int nev = total + 4;
    if (rod->p.torsion && want[GAL_FAMILY_TORSIONAL] > 0) {
        double *g = malloc((size_t)rod->nq * sizeof(double));
        double H = rod->p.EA; /* fallback */
        if (g && gal_rod_eval(rod, q, NULL, g, NULL) == GAL_OK) H = fabs(g[0]);
        free(g);
        double L0 = rod->p.unstretched_length;
        double f1 = sqrt(H / rod->p.mass) / (2 * L0);
        double ft = want[GAL_FAMILY_TORSIONAL] * sqrt(rod->p.GJ / rod->p.polar_inertia) / (2 * L0);
        int below = (int)(2 * ft / f1) + want[GAL_FAMILY_TORSIONAL];
        if (below + 4 > nev) nev = below + 4;
    }
    int rounds = 0;
    long op = 0, fact = 0, solves = 0;
    for (;;) {
        if (nev > max_modes) nev = max_modes;
        int st = gal_modes_solve(rod, q, nev, out);
        rounds++;
        op += out->op_applications, fact += out->factorizations, solves += out->solves;
        if (st) return st;
        int short_family = 0;
        for (int f = 0; f < 3; f++)
            if (out->found[f] < want[f]) short_family = 1;
        if (!short_family || nev >= max_modes) break;
        gal_modes_clear(out);
        nev *= 2;
    }
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) out->selected[f] = 0;
    for (int k = 0; k < out->n; k++) {
        gal_mode *md = out->mode + k;
        if (md->family < 3 && out->selected[md->family] < want[md->family]) {
            md->selected = 1;
            out->selected[md->family]++;
        }
    }
    out->rounds = rounds;
    out->op_applications = op, out->factorizations = fact, out->solves = solves;
    out->wall_time_s = gal_wall_time() - t0;
    return GAL_OK;
}
