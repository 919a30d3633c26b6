/* rom_irk.c: the reduced model's step by the two-stage Gauss-Legendre method (rom.h, o.scheme =
 * GAL_ROM_SCHEME_GAUSS2): fourth order, A-stable, symplectic, on the reduced second-order system
 *   x'' = fe(t, x, x') - Cr x' - fi(x)
 * written for the stage accelerations A_i (r each, i = 1, 2):
 *   V_i = v0 + h sum_j a_ij A_j,  Q_i = x0 + h c_i v0 + h^2 sum_j (a^2)_ij A_j,
 *   G_i = A_i + Cr V_i + fi(Q_i) - fe(t0 + c_i h, Q_i, V_i) = 0,
 *   x1 = x0 + h v0 + h^2 sum_j (b^T a)_j A_j,  v1 = v0 + h sum_j b_j A_j,
 * by modified Newton on the 2r x 2r matrix I + h a (x) Cr + h^2 a^2 (x) Kr (row block i with stage
 * i's reduced tangent; the loads' derivatives left out, as rom_step.c's; kept over steps while
 * Newton contracts), the predictor the last step's collocation acceleration (linear in time)
 * extrapolated. The loads at every Newton pass, whatever o.loads_once (measured: held from the
 * first correction as rom_step.c holds them, the observed order falls to 1-2 and at 10 steps a
 * period the trajectory error grows 10-20x). A study of issue 13's step count (BENCHMARKS.md,
 * helper step10): opt-in, not the default; the manifold (o.manifold) is not supported. */
#include "gallop/reduced/rom.h"
#include "gallop/base/core.h"
#include "reduced/hyper.h"
#include "base/dense.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* LAPACK (the library links it): the 2r x 2r matrix by dgetrf, 2-3x the plain LU's speed there */
void dgetrf_(const int *m, const int *n, double *a, const int *lda, int *ipiv, int *info);
void dgetrs_(const char *trans, const int *n, const int *nrhs, const double *a, const int *lda, const int *ipiv,
             double *b, const int *ldb, int *info);

struct gal_rom_irk {
    int r;
    double hJ, hA;                 /* s: the step of J (0: none), of the stages held in A (0: none) */
    double *A, *Q, *V, *F, *E, *G; /* 2 r each: stage accelerations, states, rates, forces, residual */
    double *J, *K, *K2;            /* 2r x 2r, r x r, r x r */
    int *piv;
};

#define S3 0.28867513459481288225 /* sqrt(3)/6 */
static const double ca[2] = {0.5 - S3, 0.5 + S3};
static const double aa[2][2] = {{0.25, 0.25 - S3}, {0.25 + S3, 0.25}};
static const double a2[2][2] = {{1.0 / 24, 0.5 * (0.25 - S3)}, {0.5 * (0.25 + S3), 1.0 / 24}};
static const double ba[2] = {0.25 + 0.5 * S3, 0.25 - 0.5 * S3}; /* b^T a */

void gal_rom_irk_free(gal_rom *m)
{
    struct gal_rom_irk *w = m->irk;
    if (!w) return;
    free(w->A), free(w->Q), free(w->V), free(w->F), free(w->E), free(w->G);
    free(w->J), free(w->K), free(w->K2), free(w->piv);
    free(w);
    m->irk = NULL;
}

static int irk_alloc(gal_rom *m)
{
    int r = m->r;
    if (m->irk && m->irk->r == r) return GAL_OK;
    gal_rom_irk_free(m);
    struct gal_rom_irk *w = calloc(1, sizeof *w);
    if (!w) return gal_error(GAL_ENOMEM, "reduced model: out of memory");
    m->irk = w;
    w->r = r;
    size_t n2 = 2 * (size_t)r;
    w->A = malloc(n2 * sizeof(double)), w->Q = malloc(n2 * sizeof(double)), w->V = malloc(n2 * sizeof(double));
    w->F = malloc(n2 * sizeof(double)), w->E = malloc(n2 * sizeof(double)), w->G = malloc(n2 * sizeof(double));
    w->J = malloc(n2 * n2 * sizeof(double)), w->K = malloc((size_t)r * r * sizeof(double));
    w->K2 = malloc((size_t)r * r * sizeof(double)), w->piv = malloc(n2 * sizeof(int));
    if (!w->A || !w->Q || !w->V || !w->F || !w->E || !w->G || !w->J || !w->K || !w->K2 || !w->piv) {
        gal_rom_irk_free(m);
        return gal_error(GAL_ENOMEM, "reduced model: out of memory");
    }
    return GAL_OK;
}

/* The stage states and rates from the stage accelerations. */
static void stages(const gal_rom *m, struct gal_rom_irk *w, double h)
{
    int r = m->r;
    for (int i = 0; i < 2; i++)
        for (int k = 0; k < r; k++) {
            const double A0 = w->A[k], A1 = w->A[r + k];
            w->V[i * r + k] = m->v[k] + h * (aa[i][0] * A0 + aa[i][1] * A1);
            w->Q[i * r + k] = m->x[k] + h * ca[i] * m->v[k] + h * h * (a2[i][0] * A0 + a2[i][1] * A1);
        }
}

/* J = I + h a (x) Cr + h^2 a^2 (x) K, row block i with stage i's tangent, LU-factored */
static int factor(gal_rom *m, struct gal_rom_irk *w, double h)
{
    int r = m->r, n = 2 * r;
    for (int bi = 0; bi < 2; bi++)
        for (int bj = 0; bj < 2; bj++)
            for (int i = 0; i < r; i++)
                for (int j = 0; j < r; j++)
                    w->J[(size_t)(bi * r + i) * n + bj * r + j] =
                        (bi == bj && i == j) + h * aa[bi][bj] * m->Cr[i * r + j] +
                        h * h * a2[bi][bj] * (bi ? w->K2 : w->K)[i * r + j];
    w->hJ = 0;
    int info = 0;
    dgetrf_(&n, &n, w->J, &n, w->piv, &info); /* J row-major: the factors of J^T */
    if (info) return gal_error(GAL_EFAIL, "reduced model: singular Gauss iteration matrix");
    w->hJ = h;
    m->tangents++;
    return GAL_OK;
}

/* The stages' forces (tangents into K when fresh; the loads when loads), the residual G; its largest
 * entry over the Newton tolerance times the force scale (rom_step.c's test) into *rn, strict *rs. */
static int residual(gal_rom *m, struct gal_rom_irk *w, double h, int fresh, int loads, double *rn, double *rs,
                    double *raw)
{
    int r = m->r, st;
    for (int i = 0; i < 2; i++) {
        if ((st = gal_rom_eval_internal(m, w->Q + i * r, w->F + i * r, fresh ? (i ? w->K2 : w->K) : NULL))) return st;
        if (loads && m->force.eval && (st = gal_rom_eval_external(m, m->t + ca[i] * h, w->Q + i * r, w->V + i * r, w->E + i * r)))
            return st;
        if (!m->force.eval) memset(w->E + i * r, 0, (size_t)r * sizeof(double));
    }
    double mx = 0, sc = 0;
    for (int i = 0; i < 2; i++)
        for (int k = 0; k < r; k++) {
            double c = 0;
            const double *cr = m->Cr + (size_t)k * r, *v = w->V + i * r;
            for (int j = 0; j < r; j++) c += cr[j] * v[j];
            double g = w->A[i * r + k] + c + w->F[i * r + k] - w->E[i * r + k];
            w->G[i * r + k] = g;
            mx = fmax(mx, fabs(g)), sc = fmax(sc, fabs(w->F[i * r + k]) + fabs(w->E[i * r + k]));
        }
    double tol = m->o.newton_tol, ts = fmin(tol, GAL_NEWTON_TOL_STRICT);
    *raw = mx;
    *rs = mx / fmax(ts * fmax(sc, m->fscale), m->ffloor);
    *rn = mx / fmax(tol * fmax(sc, m->fscale), m->ffloor);
    return isfinite(mx) ? GAL_OK : gal_error(GAL_EFAIL, "reduced model: the residual is not finite");
}

/* The predictor: the last step's collocation acceleration (linear through its stages) at the new
 * stages' times, or the state's acceleration. */
static void predict(gal_rom *m, struct gal_rom_irk *w, double h)
{
    int r = m->r;
    if (w->hA != h) {
        for (int i = 0; i < 2; i++) memcpy(w->A + i * r, m->a, (size_t)r * sizeof(double));
        return;
    }
    const double e = (1 + ca[1] - ca[0]);
    for (int k = 0; k < r; k++) { /* at 1 + c_i */
        double A0 = w->A[k], d = (w->A[r + k] - A0) / (ca[1] - ca[0]);
        w->A[k] = A0 + d, w->A[r + k] = A0 + e * d;
    }
}

/* Modified Newton for one step of h; the state unchanged (w->A the stages) */
static int newton(gal_rom *m, struct gal_rom_irk *w, double h)
{
    int r = m->r, st = GAL_OK, conv = 0, it;
    int fresh = !(m->o.reuse_tangent && w->hJ == h), kept = !fresh;
    double prev = INFINITY, rawprev = INFINITY;
    predict(m, w, h);
    for (it = 0; it < m->o.max_newton; it++) {
        double rn, rs, raw;
        stages(m, w, h);
        if ((st = residual(m, w, h, fresh, 1, &rn, &rs, &raw))) break;
        if (rs <= 1 || (it > 0 && rn <= 1 && raw < rawprev)) { conv = 1; break; }
        if (!fresh && (rn > m->o.newton_contraction * prev || (kept && it >= m->o.newton_kept_max))) {
            fresh = 1, kept = 0;
            if ((st = residual(m, w, h, 1, 0, &rn, &rs, &raw))) break;
        }
        prev = rn, rawprev = raw;
        if (fresh) {
            if ((st = factor(m, w, h))) break;
            fresh = 0;
        }
        for (int k = 0; k < 2 * r; k++) w->G[k] = -w->G[k];
        int n = 2 * r, one = 1, info = 0;
        dgetrs_("T", &n, &one, w->J, &n, w->piv, w->G, &n, &info); /* J x = b from J^T's factors */
        for (int k = 0; k < 2 * r; k++) w->A[k] += w->G[k];
        m->newton_iterations++;
    }
    if (!st && !conv)
        st = gal_error(GAL_EFAIL, "reduced model: Gauss-Legendre Newton did not converge in %d iterations at t = %.6g s "
                       "(time step %g s)", m->o.max_newton, m->t + h, h);
    return st;
}

/* A step of h; on failure two of h/2 (GAL_ROM_HALVINGS deep). */
static int step(gal_rom *m, double h, int depth)
{
    struct gal_rom_irk *w = m->irk;
    int r = m->r, st = newton(m, w, h);
    if (st && st != GAL_ENOMEM && depth < GAL_ROM_HALVINGS) {
        m->halvings++;
        w->hA = 0;
        st = step(m, 0.5 * h, depth + 1);
        if (!st) st = step(m, 0.5 * h, depth + 1);
        w->hA = 0;
        return st;
    }
    if (st) return st;
    /* the end state; the acceleration and forces there the collocation's, extrapolated (a later
     * generalized-alpha step or check re-evaluates what it needs) */
    double e = (1 - ca[0]) / (ca[1] - ca[0]);
    for (int k = 0; k < r; k++) {
        const double A0 = w->A[k], A1 = w->A[r + k];
        m->x[k] += h * m->v[k] + h * h * (ba[0] * A0 + ba[1] * A1);
        m->v[k] += 0.5 * h * (A0 + A1);
        m->a[k] = A0 + e * (A1 - A0);
        m->fi[k] = w->F[k] + e * (w->F[r + k] - w->F[k]);
        m->fe[k] = w->E[k] + e * (w->E[r + k] - w->E[k]);
    }
    w->hA = h;
    m->hfe = 0, m->hJ = 0, m->lin_ok = 0;
    m->t += h;
    m->steps++;
    return GAL_OK;
}

int gal_rom_irk_step(gal_rom *m, double h)
{
    int st = irk_alloc(m);
    if (st) return st;
    if (m->qm) return gal_error(GAL_EINPUT, "reduced model: the Gauss-Legendre step has no quadratic manifold");
    return step(m, h, 0);
}

void gal_rom_irk_restart(gal_rom *m)
{
    if (m->irk) m->irk->hA = 0, m->irk->hJ = 0;
}

