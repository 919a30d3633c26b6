/* modes_find.c: the modes a scene asks for by family: the flexural ones from the bottom of the
 * spectrum, each torsional one by a shift at its estimate from the twist block (so that two
 * torsional modes far above the flexural ones do not cost every mode below them), with a check
 * and, failing it, the search from the bottom. */
#include "gallop/base/core.h"
#include "gallop/modes/modes.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "modes_impl.h"

#define WINDOW_NEV 1      /* modes nearest each torsional shift, first try */
#define WINDOW_NEV_MAX 4  /* the most before the search from the bottom takes over */

/* Eigenvalues of the symmetric tridiagonal (a, b) below x (Sturm count by the pivots d_i of the
 * LDL' of T - x I), and in *step Newton's step towards a zero of det(T - x I) = prod d_i:
 * -det/det' = -1 / sum(d_i'/d_i), the d_i' by differentiating the pivots' recurrence. */
static int sturm_newton(int m, const double *a, const double *b, double x, double *step)
{
    int cnt = 0;
    double d = 1, dd = 0, s = 0;
    for (int i = 0; i < m; i++) {
        double bb = i ? b[i - 1] * b[i - 1] : 0, q = i ? bb / d : 0;
        double ddn = -1 + (i ? q * dd / d : 0);
        d = a[i] - x - q;
        if (d == 0) d = -1e-300;
        dd = ddn;
        cnt += d < 0;
        s += dd / d;
    }
    *step = s != 0 ? -1 / s : 0;
    return cnt;
}

/* The lowest eigenvalues lam (omega^2) of the twist block of (K0, M), at most nt, and past the
 * first `need` only while below `stop`: the free edge twists in edge order couple only to their
 * neighbours (a tridiagonal pencil with a diagonal mass), scaled by the mass. The first `exact`
 * (the shifts) to 1e-10, the others (a spacing, a count below a bound) to 1e-6. Returns how many
 * it gave (0: no torsion). */
static int twist_estimates(const gal_rod *rod, const gal_csc *K0, int nt, int need, int exact, double stop,
                           double *lam)
{
    int nel = rod->p.elements, m = 0;
    if (!rod->p.torsion || nt < 1) return 0;
    double *a = malloc((size_t)nel * sizeof(double)), *b = calloc((size_t)nel, sizeof(double));
    int *dof = malloc((size_t)nel * sizeof(int));
    if (!a || !b || !dof) { free(a); free(b); free(dof); return 0; }
    for (int j = 0; j < nel; j++) {
        int d = rod->dof[3 * rod->nn + j];
        if (d < 0) continue;
        a[m] = K0->val[K0->diag[d]] / rod->mdiag[d];
        if (m > 0) {
            int e = dof[m - 1], p = gal_csc_find(K0, e < d ? e : d, e < d ? d : e);
            b[m - 1] = p < 0 ? 0 : K0->val[p] / sqrt(rod->mdiag[d] * rod->mdiag[e]);
        }
        dof[m++] = d;
    }
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < m; i++) {
        double r = (i ? fabs(b[i - 1]) : 0) + fabs(b[i]);
        lo = fmin(lo, a[i] - r), hi = fmax(hi, a[i] + r);
    }
    if (nt > m) nt = m;
    for (int k = 0; k < nt; k++) { /* the (k+1)-th eigenvalue, bracketed by the counts (k below l,
                                    * k + 1 below h), by Newton's steps that stay in the bracket,
                                    * else bisection (of the logarithm: the matrix is positive
                                    * definite) */
        double l = k > 0 ? fmax(lo, lam[k - 1]) : fmax(lo, 1e-16 * hi), h = hi, x = sqrt(l * h), step;
        double tol = k < exact ? 1e-10 : 1e-6;
        for (int it = 0; it < 200; it++) {
            if (sturm_newton(m, a, b, x, &step) <= k) l = x; else h = x;
            double xn = x + step;
            if (!(xn > l && xn < h)) xn = sqrt(l * h);
            int done = fabs(xn - x) < tol * x || h - l < tol * h;
            x = xn;
            if (done) break;
        }
        lam[k] = x;
        if (k + 1 >= need && x >= stop) nt = k + 1;
    }
    free(a); free(b); free(dof);
    return nt;
}

/* |K0 phi - lam M phi| / |lam M phi| of mode k of md. */
static double residual(const gal_modes_ctx *c, const gal_modes *md, int k, double *y, double *z)
{
    const double *phi = md->shape + (size_t)k * md->ndof;
    double lam = md->mode[k].omega * md->mode[k].omega, rr = 0, mm = 0;
    gal_csc_symv(&c->K0, phi, y);
    gal_rod_mass_mult(c->rod, phi, z);
    for (int j = 0; j < md->ndof; j++) rr += (y[j] - lam * z[j]) * (y[j] - lam * z[j]), mm += lam * lam * z[j] * z[j];
    return mm > 0 ? sqrt(rr / mm) : INFINITY;
}

/* The twist's share of a mass-normalized mode's kinetic energy (a quick sieve before classify). */
static double twist_share(const gal_rod *rod, const double *phi)
{
    double e = 0;
    for (int j = 0; j < rod->p.elements; j++) {
        int d = rod->dof[3 * rod->nn + j];
        if (d >= 0) e += rod->mdiag[d] * phi[d] * phi[d];
    }
    return e;
}

static void add_counters(gal_modes *acc, const gal_modes *r)
{
    acc->op_applications += r->op_applications, acc->factorizations += r->factorizations;
    acc->solves += r->solves, acc->arpack_restarts += r->arpack_restarts, acc->rounds++;
}

/* Torsional mode k (from 0) near its estimate est[k] (est[k+1] the next, for the spacing), above
 * lam_top: the window's torsional mode nearest the estimate, nearer it than the neighbouring
 * estimates, with a small residual; into *pick (a one-mode gal_modes). GAL_OK and pick->n = 0 when
 * the check fails (the caller searches from the bottom). */
static int torsional_window(gal_modes_ctx *c, const double *est, int k, double lam_top, gal_modes *acc,
                            gal_modes *pick, double *y, double *z)
{
    double half = 0.5 * fmin(k > 0 ? est[k] - est[k - 1] : est[k], est[k + 1] - est[k]);
    memset(pick, 0, sizeof *pick);
    for (int nev = WINDOW_NEV; nev <= WINDOW_NEV_MAX && nev < c->rod->ndof; nev *= 2) {
        gal_modes w;
        int st = gal_modes_run(c, nev, est[k], 0, &w);
        if (st == GAL_EFAIL) st = gal_modes_run(c, nev, est[k] * (1 + 1e-3), 0, &w); /* a zero pivot */
        add_counters(acc, &w);
        if (st == GAL_EFAIL) return GAL_OK; /* no pick: from the bottom */
        if (st) return st;
        int best = -1;
        for (int i = 0; i < w.n; i++)
            if (twist_share(c->rod, w.shape + (size_t)i * w.ndof) > 0.25 &&
                (best < 0 || fabs(w.mode[i].omega * w.mode[i].omega - est[k]) <
                                 fabs(w.mode[best].omega * w.mode[best].omega - est[k])))
                best = i;
        if (best >= 0) gal_modes_classify(c, &w, best);
        if (best >= 0 && w.mode[best].family == GAL_FAMILY_TORSIONAL) {
            double lam = w.mode[best].omega * w.mode[best].omega;
            if (fabs(lam - est[k]) < half && lam > lam_top && residual(c, &w, best, y, z) < 1e-6) {
                pick->n = 1, pick->ndof = w.ndof;
                pick->mode = malloc(sizeof(gal_mode));
                pick->shape = malloc((size_t)w.ndof * sizeof(double));
                if (!pick->mode || !pick->shape) { gal_modes_clear(&w); gal_modes_clear(pick); return GAL_ENOMEM; }
                pick->mode[0] = w.mode[best];
                memcpy(pick->shape, w.shape + (size_t)best * w.ndof, (size_t)w.ndof * sizeof(double));
            }
            gal_modes_clear(&w);
            return GAL_OK;
        }
        gal_modes_clear(&w);
    }
    return GAL_OK;
}

/* out (the modes from the bottom) extended by the picked torsional modes, in order. */
static int append(const gal_modes_ctx *c, gal_modes *out, gal_modes *pick, int np)
{
    int n = out->ndof, m = out->n + np;
    if (m > c->capacity) { /* the run from below left no room for them */
        gal_mode *mode = realloc(out->mode, (size_t)m * sizeof(gal_mode));
        if (mode) out->mode = mode;
        double *shape = realloc(out->shape, (size_t)m * n * sizeof(double));
        if (shape) out->shape = shape;
        if (!mode || !shape) return gal_error(GAL_ENOMEM, "modes: out of memory");
    }
    for (int i = 0; i < np; i++) {
        out->mode[out->n] = pick[i].mode[0];
        memcpy(out->shape + (size_t)out->n * n, pick[i].shape, (size_t)n * sizeof(double));
        out->found[GAL_FAMILY_TORSIONAL]++;
        out->n++;
    }
    return GAL_OK;
}

/* From the bottom of the spectrum: nev modes, doubled until each family of mask (bit f) holds
 * want[f] modes or max_modes is reached. */
static int from_bottom(gal_modes_ctx *c, int nev, int max_modes, const int want[GAL_FAMILY_COUNT], int mask,
                       gal_modes *out, gal_modes *acc)
{
    for (;;) {
        if (nev > max_modes) nev = max_modes;
        int st = gal_modes_run(c, nev, 0, 1, out);
        add_counters(acc, out);
        if (st) return st;
        int short_family = 0;
        for (int f = 0; f < 3; f++)
            if ((mask >> f & 1) && out->found[f] < want[f]) short_family = 1;
        if (!short_family || nev >= max_modes) return GAL_OK;
        gal_modes_clear(out);
        nev *= 2;
    }
}

/* The torsional modes out lacks, each from its own shift; 1 in *done when all passed the check. */
static int torsional_windows(gal_modes_ctx *c, const double *est, int wt, gal_modes *out, gal_modes *acc, int *done)
{
    int tl = out->found[GAL_FAMILY_TORSIONAL], st = GAL_OK, np = 0;
    gal_modes *pick = calloc((size_t)wt, sizeof(gal_modes));
    double *y = c->y, *z = c->z;
    double lam_top = out->mode[out->n - 1].omega * out->mode[out->n - 1].omega;
    *done = 0;
    if (!pick) st = gal_error(GAL_ENOMEM, "modes: out of memory");
    for (int k = tl; !st && k < wt; k++) {
        st = torsional_window(c, est, k, lam_top, acc, &pick[np], y, z);
        if (st || pick[np].n == 0) break;
        lam_top = pick[np].mode[0].omega * pick[np].mode[0].omega; /* in increasing order */
        np++;
    }
    if (!st && np == wt - tl) {
        st = append(c, out, pick, np);
        *done = !st;
    }
    for (int i = 0; pick && i < wt; i++) gal_modes_clear(&pick[i]);
    free(pick);
    return st;
}

/* How many modes from the bottom should reach the wt-th torsional mode, estimated at lam_t
 * (omega^2, 1.5 times over in frequency: its coupling to the motion may raise it) when the
 * flexural modes (out, the first run) are spaced by their lowest frequency: at least twice out. */
static int bottom_count(const gal_modes *out, double lam_t, int wt)
{
    double f1 = 0;
    for (int k = 0; k < out->n && !(f1 > 0); k++) f1 = out->mode[k].frequency_hz;
    int nev = 2 * out->n;
    if (f1 > 0 && lam_t > 0) {
        double below = 2 * 1.5 * sqrt(lam_t) / (2 * GAL_PI) / f1 + wt + 4;
        if (below > nev) nev = below < 1e6 ? (int)below : 1000000;
    }
    return nev;
}

/* omega^2 of the lowest string mode, (pi/L0)^2 T/m, T from the first element's stretch. */
static double string_lambda1(const gal_rod *rod, const double *q)
{
    double d[3] = {q[3] - q[0], q[4] - q[1], q[5] - q[2]}, L0 = rod->p.unstretched_length;
    double T = rod->p.EA * (sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) / (L0 / rod->p.elements) - 1);
    return T > 0 && L0 > 0 && rod->p.mass > 0 ? GAL_PI * GAL_PI / (L0 * L0) * T / rod->p.mass : 0;
}

/* The torsional partners' band (gal_modes_select): when a torsional mode may lie in it above the
 * modes from the bottom (the lowest twist estimate lam_t, omega^2, below its top: the estimates
 * are low, never high, for the bundle's symmetric twist and eccentric ice), the modes from the
 * bottom up to its top. */
static int partner_band(gal_modes_ctx *c, double lam_t, const int want[GAL_FAMILY_COUNT], int max_modes,
                        gal_modes *out, gal_modes *acc)
{
    double top = 2 * GAL_PI * gal_modes_partner_top(out, want);
    if (!(lam_t < top * top)) return GAL_OK;
    int nev = out->n;
    while (out->mode[out->n - 1].omega < top && nev < max_modes) {
        nev = 2 * nev < max_modes ? 2 * nev : max_modes;
        gal_modes_clear(out);
        int st = gal_modes_run(c, nev, 0, 1, out);
        add_counters(acc, out);
        if (st) return st;
    }
    return GAL_OK;
}

static int find(gal_modes_ctx *c, const int want[GAL_FAMILY_COUNT], int max_modes, gal_modes *out, gal_modes *acc)
{
    /* the vertical and horizontal modes come in near pairs from the bottom (exact pairs on a
     * straight span, which split_clusters can only split whole: an even count), so the lowest
     * 2 max(v, h) modes usually hold both families (one pair more when v = h), with the torsional
     * modes estimated below the last of them, (max(v, h) + 1)^2 times the string's lowest (a
     * bundle's twist is that low) */
    int v = want[GAL_FAMILY_VERTICAL], h = want[GAL_FAMILY_HORIZONTAL], pairs = v > h ? v : h;
    if (pairs < (v + h + 2) / 2) pairs = (v + h + 2) / 2;
    int wt = want[GAL_FAMILY_TORSIONAL], ne = (wt > 2 * pairs ? wt : 2 * pairs) + 1, st, done = 0;
    double *est = malloc((size_t)ne * sizeof(double));
    if (!est) return gal_error(GAL_ENOMEM, "modes: out of memory");
    double bound = (pairs + 1) * (pairs + 1) * string_lambda1(c->rod, c->q);
    /* with torsional modes asked, the partners' band too (gal_modes_select: up to 1 + GAL_PARTNER_BAND
     * times the last vertical mode's frequency, estimated as the string's pairs-th) */
    double wb = (1 + GAL_PARTNER_BAND) * pairs / (pairs + 1.0), band = wt > 0 ? wb * wb * bound : 0;
    int wide = (int)ceil((1 + GAL_PARTNER_BAND) * pairs);
    if (band > bound) bound = band;
    int nest = wt > 0 || bound > 0 ? twist_estimates(c->rod, &c->K0, ne, wt > 0 ? wt + 1 : 1, wt, bound, est) : 0, low = 0;
    while (low < nest && est[low] < bound) low++;
    /* the twist block holds the torsional modes where the twist is not coupled to the motion
     * through the mass: not with eccentric ice (there they came out 1.3 times higher) */
    int windows = nest >= wt + 1 && !c->rod->ecc_c;
    c->spare = windows ? wt : 0;
    /* torsional modes in the band: the flexural ones up to its top too (one run, foreseen) */
    st = from_bottom(c, 2 * (low > 0 && band > 0 && wide > pairs ? wide : pairs) + low, max_modes, want, 3, out, acc);
    if (!st && nest > 0) st = partner_band(c, est[0], want, max_modes, out, acc);
    c->spare = 0;
    if (!st && wt > 0 && out->found[GAL_FAMILY_TORSIONAL] < wt && out->n < max_modes) {
        if (windows) st = torsional_windows(c, est, wt, out, acc, &done);
        if (!st && !done) { /* from the bottom, every family */
            int nev = bottom_count(out, nest >= wt ? est[wt - 1] : 0, wt);
            gal_modes_clear(out);
            st = from_bottom(c, nev, max_modes, want, 7, out, acc);
        }
    }
    free(est);
    return st;
}

/* gal_modes_find, with a tangent handed over (or NULL). */
static int find_with(const gal_rod *rod, const double *q, gal_tangent *t, const int want[GAL_FAMILY_COUNT],
                     int max_modes, gal_modes *out)
{
    double t0 = gal_wall_time();
    int n = rod->ndof;
    if (max_modes > n - 1) max_modes = n - 1;
    memset(out, 0, sizeof *out);
    gal_modes_ctx c;
    int st = gal_modes_ctx_init(&c, rod, q, t);
    if (st) return st;
    gal_modes acc = {0};
    st = find(&c, want, max_modes, out, &acc);
    gal_modes_ctx_clear(&c);
    if (st) {
        gal_modes_clear(out);
        return st;
    }
    gal_modes_select(out, want);
    out->rounds = acc.rounds, out->arpack_restarts = acc.arpack_restarts;
    out->op_applications = acc.op_applications, out->factorizations = acc.factorizations, out->solves = acc.solves;
    out->wall_time_s = gal_wall_time() - t0;
    return GAL_OK;
}

int gal_modes_find(const gal_rod *rod, const double *q, const int want[GAL_FAMILY_COUNT],
                   int max_modes, gal_modes *out)
{
    return find_with(rod, q, NULL, want, max_modes, out);
}

int gal_modes_find_eq(gal_equilibrium *eq, const int want[GAL_FAMILY_COUNT], int max_modes, gal_modes *out)
{
    int st = find_with(eq->rod, eq->q, eq->tangent, want, max_modes, out);
    eq->tangent = gal_tangent_free(eq->tangent); /* taken over, or of no use now: its memory back */
    return st;
}
