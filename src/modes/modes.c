/* modes.c: modes of the linearized rod, K phi = w^2 M phi (paper Eq. 9 without damping and load),
 * by ARPACK shift-invert (mode 3) with CHOLMOD, at a shift below the spectrum or inside it;
 * classification by kinetic-energy shares. The search by family is in modes_find.c. */
#include "gallop/modes/modes.h"
#include "gallop/base/core.h"
#include "gallop/base/vec3.h"

#include <arpack/arpack.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/chol.h"
#include "modes_impl.h"

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
                     double *comp, gal_mode *md)
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
    /* comp: per node (or edge) family components, for the symmetry test */
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
        comp[4 * i + 0] = uv, comp[4 * i + 1] = uh, comp[4 * i + 3] = ua;
    }
    if (rod->p.torsion)
        for (int j = 0; j < nel; j++) {
            double th = full[3 * nn + j];
            ke[GAL_FAMILY_TORSIONAL] += rod->edge_inertia[j] * th * th;
            comp[4 * j + 2] = th;
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
    int cnt = fam == GAL_FAMILY_TORSIONAL ? nel : nn;
    double sgn = fam == GAL_FAMILY_AXIAL ? -1.0 : 1.0, num = 0, den = 0;
    for (int i = 0; i < cnt; i++) {
        double a = comp[4 * i + fam], m = comp[4 * (cnt - 1 - i) + fam];
        num += a * sgn * m;
        den += a * a;
    }
    double r = den > 0 ? num / den : 0;
    md->symmetry = r > 0.9 ? GAL_SYM_SYMMETRIC : r < -0.9 ? GAL_SYM_ANTISYMMETRIC : GAL_SYM_NONE;
    md->parity = r >= 0 ? GAL_SYM_SYMMETRIC : GAL_SYM_ANTISYMMETRIC; /* r: the symmetric part's energy
                                                                       * less the other's, over both */
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

/* The arrays of one ARPACK run (kept by the context for the next when large enough). */
typedef struct modes_ws {
    int n, nev, ncv, lworkl, cap_nev, cap_ncv, v_cols;
    double *tmp, *resid, *workd, *workl, *d;
    double *v; /* v_cols columns: the Lanczos basis, then the Ritz vectors, which become the modes'
                * shapes in place (the run hands v over: a fresh one for the next) */
    int *select;
} modes_ws;

static void ws_free(modes_ws *w)
{
    if (!w) return;
    free(w->tmp); free(w->resid); free(w->v); free(w->workd); free(w->workl); free(w->d);
    free(w->select);
    free(w);
}

/* ARPACK's advice is ncv >= 2 nev; a larger basis buys fewer restarts at a cost that grows as
 * n ncv^2 per restart (the reorthogonalization). Measured at 1000 elements (issue 16; CPU ms,
 * operator applications): one mode at an inner shift 4 applications at ncv = 3, 10 at 9; 9 modes
 * from the bottom 32 at 2 nev + 1, 35 at nev + 8; 39 modes 20.7 ms at 2 nev + 1 (the old rule
 * gave 79: 100 applications), 18.7 at nev + 12, 17.1 at 1.5 nev + 4; 64 modes 44.3, 43.2, 36.8. */
int gal_modes_ncv(int nev, int n)
{
    int ncv = 2 * nev + 1 < 3 * nev / 2 + 4 ? 2 * nev + 1 : 3 * nev / 2 + 4;
    return ncv > n ? n : ncv;
}

/* The context's workspace for nev modes (reallocated only when it is too small). One mode at an
 * inner shift with ARPACK's smallest basis (ncv 2) took 3 operator applications where ncv 3 takes
 * 4, the frequencies to the last bit but the shapes 1 ulp off, which the adaptive reduced run of
 * iced_gallop_turbulent.ini (`gallop compare`) turned into 1e-3 of its amplitudes: not taken. */
static modes_ws *ws_get(gal_modes_ctx *c, int n, int nev)
{
    int ncv = gal_modes_ncv(nev, n);
    modes_ws *w = c->ws;
    if (w && w->cap_nev >= nev && w->cap_ncv >= ncv) {
        w->nev = nev, w->ncv = ncv, w->lworkl = ncv * (ncv + 8);
        if (!w->v || w->v_cols < ncv) {
            free(w->v);
            w->v = malloc((size_t)n * ncv * sizeof(double)), w->v_cols = ncv;
            if (!w->v) {
                gal_error(GAL_ENOMEM, "modes: out of memory for %d modes of %d dofs", nev, n);
                return NULL;
            }
        }
        return w;
    }
    ws_free(w);
    c->ws = w = calloc(1, sizeof *w);
    if (!w) {
        gal_error(GAL_ENOMEM, "modes: out of memory for %d modes of %d dofs", nev, n);
        return NULL;
    }
    w->n = n, w->nev = w->cap_nev = nev, w->ncv = w->cap_ncv = w->v_cols = ncv;
    w->lworkl = ncv * (ncv + 8);
    w->tmp = malloc((size_t)n * sizeof(double)), w->resid = malloc((size_t)n * sizeof(double));
    w->v = malloc((size_t)n * ncv * sizeof(double)), w->workd = malloc((size_t)3 * n * sizeof(double));
    w->workl = malloc((size_t)w->lworkl * sizeof(double)), w->d = malloc((size_t)nev * sizeof(double));
    w->select = calloc((size_t)ncv, sizeof(int));
    if (!w->tmp || !w->resid || !w->v || !w->workd || !w->workl || !w->d || !w->select) {
        ws_free(w);
        c->ws = NULL;
        gal_error(GAL_ENOMEM, "modes: out of memory for %d modes of %d dofs", nev, n);
        return NULL;
    }
    return w;
}

void gal_modes_ctx_clear(gal_modes_ctx *c)
{
    gal_chol_free(c->chol);
    ws_free(c->ws);
    free(c->K0.val);
    free(c->full);
    free(c->comp);
    free(c->y);
    free(c->z);
    free(c->start);
    memset(c, 0, sizeof *c);
}

/* 1 when t holds rod's tangent at q (same pattern, length and configuration). */
static int tangent_fits(const gal_tangent *t, const gal_rod *rod, const double *q)
{
    return t && t->K && t->K->val && t->chol && t->nq == rod->nq && t->K->n == rod->K->n &&
           t->K->nnz == rod->K->nnz && t->L0 == rod->p.unstretched_length &&
           !memcmp(t->q, q, (size_t)rod->nq * sizeof(double));
}

int gal_modes_ctx_init(gal_modes_ctx *c, const gal_rod *rod, const double *q, gal_tangent *t)
{
    memset(c, 0, sizeof *c);
    c->rod = rod, c->q = q;
    int n = rod->ndof, taken = tangent_fits(t, rod, q);
    c->K0 = *rod->K; /* a view of the pattern: only the values are the context's */
    if (taken) { /* the values and the analysis taken over */
        c->K0.val = t->K->val, c->chol = t->chol;
        t->K->val = NULL, t->chol = NULL;
    } else {
        c->K0.val = malloc((size_t)rod->K->nnz * sizeof(double));
    }
    c->full = malloc((size_t)rod->nq * sizeof(double)), c->start = malloc((size_t)n * sizeof(double));
    c->comp = malloc((size_t)4 * (rod->nn > rod->p.elements ? rod->nn : rod->p.elements) * sizeof(double));
    c->y = malloc((size_t)n * sizeof(double)), c->z = malloc((size_t)n * sizeof(double));
    if (!taken) c->chol = c->K0.val ? gal_chol_alloc(&c->K0) : NULL;
    if (!c->K0.val || !c->full || !c->start || !c->comp || !c->y || !c->z || !c->chol) {
        gal_modes_ctx_clear(c);
        return gal_error(GAL_ENOMEM, "modes: out of memory for %d dofs", n);
    }
    for (int k = 0; k < n; k++) c->start[k] = 1.0 + 0.37 * sin(1.3 * k); /* deterministic */
    int st = taken ? GAL_OK : gal_rod_eval(rod, q, NULL, NULL, &c->K0);
    if (st) gal_modes_ctx_clear(c);
    return st;
}

/* The shift (below the lowest frequency when below: a fraction of the lowest string frequency
 * (pi/L)^2 T/m, from the smallest ratio of stiffness to mass on the diagonal) and the
 * factorization of K - sigma M on the common pattern (M is not diagonal with eccentric ice). */
static int shift_factor(gal_modes_ctx *c, double sigma, int below, gal_modes *out)
{
    const gal_rod *rod = c->rod;
    int n = rod->ndof;
    if (below) {
        double kmin = INFINITY;
        for (int j = 0; j < n; j++) kmin = fmin(kmin, c->K0.val[c->K0.diag[j]] / rod->mdiag[j]);
        sigma = -0.1 * kmin * pow(GAL_PI / rod->p.elements, 2);
        if (!(sigma < 0)) sigma = -1e-3;
    }
    out->sigma = sigma;
    int st = gal_chol_factor_pencil(c->chol, &c->K0, sigma, rod->M);
    if (st == GAL_ENOMEM) return st;
    if (st != GAL_OK && below)
        return gal_error(GAL_EFAIL, "modes: K - sigma M is not positive definite at sigma = %g: the "
                         "equilibrium has lost stability (%s)", sigma, gal_error_message());
    if (st != GAL_OK) return gal_error(GAL_EFAIL, "modes: K - sigma M at sigma = %g: %s", sigma, gal_error_message());
    if (below && c->chol->negative_pivots)
        return gal_error(GAL_EFAIL, "modes: K - sigma M has %d negative eigenvalue%s at sigma = %g: the "
                         "equilibrium has lost stability", c->chol->negative_pivots,
                         c->chol->negative_pivots > 1 ? "s" : "", sigma);
    if (!below && c->chol->L->is_super)
        return gal_error(GAL_EFAIL, "modes: no inertia from a supernodal factorization at sigma = %g", sigma);
    return GAL_OK;
}

/* ARPACK reverse communication, OP = (K - sigma M)^-1 M, B = M, then the eigenpairs (w->d, and the
 * Ritz vectors over the first nev columns of the basis w->v: dseupd computes them there anyway). */
static int arpack(gal_modes_ctx *c, modes_ws *w, gal_modes *out)
{
    const gal_rod *rod = c->rod;
    int n = w->n, nev = w->nev, ncv = w->ncv, st;
    int ido = 0, info = 0, iparam[11] = {0}, ipntr[14] = {0};
    iparam[0] = 1;     /* exact shifts */
    iparam[2] = 1000;  /* maximum restarts */
    iparam[6] = 3;     /* shift-invert mode */
    double tol = 1e-12, sigma = out->sigma;
    memcpy(w->resid, c->start, (size_t)n * sizeof(double));
    info = 1;
    for (;;) {
        dsaupd_c(&ido, "G", n, "LM", nev, tol, w->resid, ncv, w->v, n, iparam, ipntr, w->workd, w->workl,
                 w->lworkl, &info);
        double *x = w->workd + ipntr[0] - 1, *y = w->workd + ipntr[1] - 1;
        if (ido == -1) {
            gal_rod_mass_mult(rod, x, w->tmp);
            if ((st = gal_chol_solve(c->chol, w->tmp, y))) return st;
            out->op_applications++;
        } else if (ido == 1) {
            if ((st = gal_chol_solve(c->chol, w->workd + ipntr[2] - 1, y))) return st;
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
    dseupd_c(1, "A", w->select, w->d, w->v, n, sigma, "G", n, "LM", nev, tol, w->resid, ncv, w->v, n, iparam,
             ipntr, w->workd, w->workl, w->lworkl, &info);
    if (info != 0) return gal_error(GAL_EFAIL, "modes: ARPACK dseupd failed (info %d)", info);
    int nconv = iparam[4];
    if (nconv < nev) return gal_error(GAL_EFAIL, "modes: ARPACK converged %d of %d modes", nconv, nev);
    return GAL_OK;
}

/* Mode k's shape from ARPACK's Ritz vector in its column: mass-normalized (ARPACK's are M-orthonormal already;
 * renormalized against round-off), sign fixed (largest entry positive); its frequency. */
static int store_mode(gal_modes_ctx *c, double lam, double *tmp, gal_modes *out, int k)
{
    int n = out->ndof;
    double *dst = out->shape + (size_t)k * n, *phi = dst, mm = 0, big = 0; /* in place */
    gal_rod_mass_mult(c->rod, phi, tmp);
    for (int j = 0; j < n; j++) {
        mm += tmp[j] * phi[j];
        if (fabs(phi[j]) > fabs(big)) big = phi[j];
    }
    double s = (big < 0 ? -1.0 : 1.0) / sqrt(mm);
    for (int j = 0; j < n; j++) dst[j] = s * phi[j];
    /* a negative eigenvalue is lost stability, never a 0 Hz mode; a round-off one (the neutral
     * rotation of a span free to twist) is 0 */
    if (lam < -1e-6 * fabs(out->sigma))
        return gal_error(GAL_EFAIL, "modes: mode %d has omega^2 = %.3g < 0: the equilibrium has lost "
                         "stability", k + 1, lam);
    gal_mode *md = out->mode + k;
    md->omega = lam > 0 ? sqrt(lam) : 0;
    md->frequency_hz = md->omega / (2 * GAL_PI);
    return GAL_OK;
}

/* The modes by increasing frequency, mass-normalized, coincident pairs split, signs fixed,
 * classified, ranked (from below the spectrum: 1..nev; inside it: from the negative pivots). */
static int extract(gal_modes_ctx *c, modes_ws *w, int below, gal_modes *out)
{
    const gal_rod *rod = c->rod;
    int n = w->n, nev = w->nev, st = GAL_OK;
    out->n = nev;
    out->ndof = n;
    int cap = nev + (below ? c->spare : 0); /* room for the modes a search appends (no copy) */
    out->mode = calloc((size_t)cap, sizeof(gal_mode));
    if (below) c->capacity = cap;
    int *ord = malloc((size_t)nev * sizeof(int));
    double *lam = malloc((size_t)nev * sizeof(double));
    if (!out->mode || !ord || !lam) {
        free(ord); free(lam);
        return gal_error(GAL_ENOMEM, "modes: out of memory");
    }
    /* sort by eigenvalue (dseupd returns them ascending, but do not rely on it) */
    const double *d = w->d;
    int sorted = 1;
    for (int k = 0; k < nev; k++) ord[k] = k;
    for (int a = 1; a < nev; a++)
        for (int b = a; b > 0 && d[ord[b]] < d[ord[b - 1]]; b--) { int t = ord[b]; ord[b] = ord[b - 1]; ord[b - 1] = t; sorted = 0; }
    /* the Ritz vectors become the shapes where dseupd left them (the first nev columns of v) */
    double *shape = sorted ? w->v : malloc((size_t)n * nev * sizeof(double));
    if (shape && !sorted) {
        for (int k = 0; k < nev; k++) memcpy(shape + (size_t)k * n, w->v + (size_t)ord[k] * n, (size_t)n * sizeof(double));
        memcpy(w->v, shape, (size_t)n * nev * sizeof(double));
        free(shape);
        shape = w->v;
    }
    if (shape) shape = realloc(shape, (size_t)n * cap * sizeof(double));
    if (!shape) {
        free(ord); free(lam);
        return gal_error(GAL_ENOMEM, "modes: out of memory");
    }
    out->shape = shape, w->v = NULL;
    int nlow = 0; /* modes of the window below the shift */
    for (int k = 0; k < nev && !st; k++) {
        st = store_mode(c, d[ord[k]], w->tmp, out, k);
        nlow += d[ord[k]] < out->sigma;
    }
    free(ord);
    if (st) { free(lam); return st; }
    for (int k = 0; k < nev; k++) lam[k] = out->mode[k].omega * out->mode[k].omega;
    split_clusters(rod, out, rod->mdiag, lam);
    free(lam);
    int first = below ? 1 : c->chol->negative_pivots - nlow + 1;
    for (int k = 0; k < nev; k++) {
        /* sign: largest entry positive */
        double *dst = out->shape + (size_t)k * n, big = 0;
        for (int j = 0; j < n; j++) if (fabs(dst[j]) > fabs(big)) big = dst[j];
        if (big < 0) for (int j = 0; j < n; j++) dst[j] = -dst[j];
        out->mode[k].index = first + k;
        if (below) gal_modes_classify(c, out, k);
    }
    return GAL_OK;
}

void gal_modes_classify(gal_modes_ctx *c, gal_modes *out, int k)
{
    classify(c->rod, c->q, out->shape + (size_t)k * out->ndof, c->full, c->comp, out->mode + k);
    out->found[out->mode[k].family]++;
}

int gal_modes_run(gal_modes_ctx *c, int nev, double sigma, int below, gal_modes *out)
{
    double t0 = gal_wall_time();
    memset(out, 0, sizeof *out);
    int n = c->rod->ndof;
    if (nev < 1 || nev > n - 1)
        return gal_error(GAL_EINPUT, "modes: %d modes asked of a system with %d degrees of freedom "
                         "(allowed: 1 to %d)", nev, n, n - 1);
    modes_ws *w = ws_get(c, n, nev);
    if (!w) return GAL_ENOMEM;
    long f0 = c->chol->factorizations, s0 = c->chol->solves;
    int st = shift_factor(c, sigma, below, out);
    if (!st) st = arpack(c, w, out);
    if (!st) st = extract(c, w, below, out);
    out->factorizations = c->chol->factorizations - f0;
    out->solves = c->chol->solves - s0;
    out->rounds = 1;
    out->wall_time_s = gal_wall_time() - t0;
    if (st) {
        free(out->mode); free(out->shape);
        out->mode = NULL, out->shape = NULL, out->n = 0;
    }
    return st;
}

/* gal_modes_solve with a tangent handed over (or NULL). */
static int solve_with(const gal_rod *rod, const double *q, gal_tangent *t, int nev, gal_modes *out)
{
    double t0 = gal_wall_time();
    memset(out, 0, sizeof *out);
    int n = rod->ndof;
    if (nev < 1 || nev > n - 1)
        return gal_error(GAL_EINPUT, "modes: %d modes asked of a system with %d degrees of freedom "
                         "(allowed: 1 to %d)", nev, n, n - 1);
    gal_modes_ctx c;
    int st = gal_modes_ctx_init(&c, rod, q, t);
    if (st) return st;
    st = gal_modes_run(&c, nev, 0, 1, out);
    gal_modes_ctx_clear(&c);
    out->wall_time_s = gal_wall_time() - t0;
    return st;
}

int gal_modes_solve(const gal_rod *rod, const double *q, int nev, gal_modes *out)
{
    return solve_with(rod, q, NULL, nev, out);
}

int gal_modes_solve_eq(gal_equilibrium *eq, int nev, gal_modes *out)
{
    int st = solve_with(eq->rod, eq->q, eq->tangent, nev, out);
    eq->tangent = gal_tangent_free(eq->tangent); /* taken over, or of no use now */
    return st;
}
