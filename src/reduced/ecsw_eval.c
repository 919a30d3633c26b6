/* ecsw_eval.c: the hyper-reduced reduced model's evaluations from its samples (ecsw.h): the
 * reconstruction of the sampled configuration entries alone, the weighted internal force, energy
 * and tangent
 *   f = f_c + sum_e w_e V_e^T g_e,  U_h = U_c + f_c . x + sum_e w_e U_e,  Kr = sum_e w_e V_e^T H_e V_e,
 * and the weighted loads sum_j w_j V_j^T F_j; V_e the rows of V at element e's entries. */
#include "gallop/reduced/ecsw.h"
#include "gallop/base/core.h"

#include <math.h>
#include <string.h>

#include "reduced/hyper.h"
#include "reduced/qm.h"

/* dgemv and dgemm of the BLAS (column-major): the products with the basis' rows at the sample */
void dgemv_(const char *trans, const int *m, const int *n, const double *alpha, const double *a, const int *lda,
            const double *x, const int *incx, const double *beta, double *y, const int *incy);
void dgemm_(const char *ta, const char *tb, const int *m, const int *n, const int *k, const double *alpha,
            const double *a, const int *lda, const double *b, const int *ldb, const double *beta, double *c,
            const int *ldc);

/* y = beta y + A^T x (trans "T") or A x ("N"), A the r x nu column-major matrix B (B's rows nu x r,
 * row-major) */
static void rows_mult(const char *trans, int r, int nu, const double *B, const double *x, double beta, double *y)
{
    const double one = 1;
    const int inc = 1;
    if (nu > 0 && r > 0) dgemv_(trans, &r, &nu, &one, B, &r, x, &inc, &beta, y, &inc);
}

/* q = q_eq + V x (and v = V xd when xd) at sample S's entries of m->q (m->vq); returns the rows
 * of the tangent basis there (nu x r): V's, or on the manifold (qm.h) P(x)'s, with
 * q = q_eq + Phi x + Theta mono, P = Phi + Theta(x, .) (loops over the entries: no dependence
 * chains over the few coordinates). */
static const double *reconstruct(gal_rom *m, gal_rom_hyper_set *h, const double *x, const double *xd)
{
    int r = m->r, nu = h->nu;
    if (!m->qm) {
        double *y = m->hyper->gu; /* scratch (nq >= nu) */
        rows_mult("T", r, nu, h->Vu, x, 0, y);
        for (int u = 0; u < nu; u++) m->q[h->uq[u]] = m->q_eq[h->uq[u]] + y[u];
        if (xd) {
            rows_mult("T", r, nu, h->Vu, xd, 0, y);
            for (int u = 0; u < nu; u++) m->vq[h->uq[u]] = y[u];
        }
        return h->Vu;
    }
    int np = m->qm->np, rn = r * nu;
    double z[64 + 64 * 65 / 2], *qs = h->qs, *Pc = h->Pc;
    memcpy(z, x, (size_t)r * sizeof(double));
    gal_rom_qm_mono(m, x, NULL, NULL, z + r, NULL, NULL);
    memset(qs, 0, (size_t)nu * sizeof(double));
    for (int c = 0; c < r + np; c++) {
        const double *col = h->Qz + (size_t)c * nu;
        double zc = z[c];
        if (zc != 0)
            for (int u = 0; u < nu; u++) qs[u] += col[u] * zc;
    }
    for (int u = 0; u < nu; u++) m->q[h->uq[u]] = m->q_eq[h->uq[u]] + qs[u];
    memcpy(Pc, h->Qz, (size_t)rn * sizeof(double));
    for (int j = 0; j < r; j++) {
        const double *t = h->Tt + (size_t)j * rn;
        double xj = x[j];
        if (xj != 0)
            for (int i = 0; i < rn; i++) Pc[i] += t[i] * xj;
    }
    for (int k = 0; k < r; k++)
        for (int u = 0; u < nu; u++) h->Vu[(size_t)u * r + k] = Pc[(size_t)k * nu + u];
    if (xd) {
        memset(qs, 0, (size_t)nu * sizeof(double));
        for (int k = 0; k < r; k++) {
            const double *pk = Pc + (size_t)k * nu;
            for (int u = 0; u < nu; u++) qs[u] += pk[u] * xd[k];
        }
        for (int u = 0; u < nu; u++) m->vq[h->uq[u]] = qs[u];
    }
    return h->Vu;
}

/* Kr += sum_u gu_u theta_u (the manifold's curvature; upper triangle). */
static void curvature(const gal_rom *m, const gal_rom_hyper_set *S, const double *gu, double *Kr)
{
    int r = m->r, nu = S->nu;
    for (int j = 0, p = 0; j < r; j++)
        for (int i = 0; i <= j; i++, p++) {
            const double *col = S->Qz + (size_t)(r + p) * nu;
            double s = 0;
            for (int u = 0; u < nu; u++) s += gu[u] * col[u];
            Kr[i * r + j] += s;
        }
}

/* Y_p += w sum_q H(p, q) B_q over element k's entries p, q (Y, B: nu x r, row-major): for each p,
 * eight entries of Y_p a pass held in registers over the q's (each entry's sums in increasing q,
 * one product and one addition at a time, the zero H(p, q) skipped: the numbers of the pass over
 * q outside, stored once per p). */
static void tangent_element(int r, const int *idx, double w, const double *H, const double *B, double *Y)
{
    const int NQ = GAL_ROD_ELEMENT_NQ;
    int loc[GAL_ROD_ELEMENT_NQ], nl = 0;
    for (int a = 0; a < NQ; a++)
        if (idx[a] >= 0) loc[nl++] = a;
    for (int p = 0; p < nl; p++) {
        double *yp = Y + (size_t)idx[loc[p]] * r, hp[GAL_ROD_ELEMENT_NQ];
        const double *bp[GAL_ROD_ELEMENT_NQ];
        int nh = 0;
        for (int q = 0; q < nl; q++) { /* the row's nonzero w H(p, q) and their rows of B */
            double hpq = w * H[loc[p] * NQ + loc[q]];
            if (hpq == 0) continue;
            hp[nh] = hpq, bp[nh++] = B + (size_t)idx[loc[q]] * r;
        }
        if (!nh) continue;
        int j = 0;
        for (; j + 8 <= r; j += 8) {
            double y0 = yp[j], y1 = yp[j + 1], y2 = yp[j + 2], y3 = yp[j + 3];
            double y4 = yp[j + 4], y5 = yp[j + 5], y6 = yp[j + 6], y7 = yp[j + 7];
            for (int c = 0; c < nh; c++) {
                const double *b = bp[c] + j;
                double h = hp[c];
                y0 = y0 + h * b[0], y1 = y1 + h * b[1], y2 = y2 + h * b[2], y3 = y3 + h * b[3];
                y4 = y4 + h * b[4], y5 = y5 + h * b[5], y6 = y6 + h * b[6], y7 = y7 + h * b[7];
            }
            yp[j] = y0, yp[j + 1] = y1, yp[j + 2] = y2, yp[j + 3] = y3;
            yp[j + 4] = y4, yp[j + 5] = y5, yp[j + 6] = y6, yp[j + 7] = y7;
        }
        if (j + 4 <= r) {
            double y0 = yp[j], y1 = yp[j + 1], y2 = yp[j + 2], y3 = yp[j + 3];
            for (int c = 0; c < nh; c++) {
                const double *b = bp[c] + j;
                double h = hp[c];
                y0 = y0 + h * b[0], y1 = y1 + h * b[1], y2 = y2 + h * b[2], y3 = y3 + h * b[3];
            }
            yp[j] = y0, yp[j + 1] = y1, yp[j + 2] = y2, yp[j + 3] = y3;
            j += 4;
        }
        if (j < r) { /* the last one to three entries: their sums side by side, c outside */
            double y[3] = {0, 0, 0};
            int t = r - j;
            for (int e = 0; e < t; e++) y[e] = yp[j + e];
            for (int c = 0; c < nh; c++)
                for (int e = 0; e < t; e++) y[e] = y[e] + hp[c] * bp[c][j + e];
            for (int e = 0; e < t; e++) yp[j + e] = y[e];
        }
    }
}

/* Kr += B^T Y (B, Y: nu x r row-major; Kr r x r holds K_c, symmetric), symmetrized; on the manifold
 * its curvature sum_u gu_u theta_u too. One dgemm: the O(nu r^2) part of a tangent. */
static void tangent_finish(const gal_rom *m, const gal_rom_hyper_set *S, const double *B, const double *Y,
                           const double *gu, double *Kr)
{
    int r = m->r, nu = S->nu;
    double one = 1;
    if (nu > 0) dgemm_("N", "T", &r, &r, &nu, &one, B, &r, Y, &r, &one, Kr, &r);
    for (int i = 0; i < r; i++)
        for (int j = i + 1; j < r; j++) Kr[i * r + j] = 0.5 * (Kr[i * r + j] + Kr[j * r + i]);
    if (m->qm) curvature(m, S, gu, Kr);
    for (int i = 0; i < r; i++)
        for (int j = 0; j < i; j++) Kr[i * r + j] = Kr[j * r + i];
}

int gal_rom_hyper_internal(gal_rom *m, const double *x, double *f, double *Kr)
{
    gal_rom_hyper *h = m->hyper;
    gal_rom_hyper_set *S = &h->set[0];
    const int NQ = GAL_ROD_ELEMENT_NQ;
    int r = m->r;
    double U = h->Uc, g[GAL_ROD_ELEMENT_NQ], H[GAL_ROD_ELEMENT_NQ * GAL_ROD_ELEMENT_NQ];
    const double *Bu = reconstruct(m, S, x, NULL);
    rows_mult("N", r, r, h->Kc, x, 0, f); /* f = f_c + K_c x, U = U_c + f_c.x + x.K_c x / 2 */
    for (int i = 0; i < r; i++) U += (h->fc[i] + 0.5 * f[i]) * x[i], f[i] += h->fc[i];
    double *gu = h->gu; /* the weighted gradient at the sample's entries, projected once at the end */
    memset(gu, 0, (size_t)S->nu * sizeof(double));
    double *Y = S->Pc; /* the weighted Hessian times B at the entries (free after reconstruct) */
    if (Kr) {
        memcpy(Kr, h->Kc, (size_t)r * r * sizeof(double));
        memset(Y, 0, (size_t)S->nu * r * sizeof(double));
    }
    for (int k = 0; k < S->n; k++) {
        double Ue, w = S->w[k];
        const int *idx = S->idx + (size_t)k * NQ;
        int st = gal_rod_element_eval(m->rod, S->elem[k], m->q, &Ue, g, Kr ? H : NULL);
        if (st) return st;
        U += w * Ue;
        for (int a = 0; a < NQ; a++)
            if (idx[a] >= 0) gu[idx[a]] += w * g[a];
        if (Kr) tangent_element(r, idx, w, H, Bu, Y);
    }
    m->element_evaluations += S->n;
    if (Kr) tangent_finish(m, S, Bu, Y, gu, Kr);
    rows_mult("N", r, S->nu, Bu, gu, 1, f); /* f += V_S^T gu */
    m->U1 = U;
    if (!isfinite(U)) return gal_error(GAL_EFAIL, "reduced model: the sampled energy is not finite");
    return GAL_OK;
}

int gal_rom_hyper_external(gal_rom *m, double t, const double *x, const double *xd, double *f)
{
    gal_rom_hyper *h = m->hyper;
    gal_rom_hyper_set *S = &h->set[1];
    static const int load_to_el[7] = {0, 1, 2, 3, 4, 5, 9};
    int r = m->r;
    memset(f, 0, (size_t)r * sizeof(double));
    const double *Bu = reconstruct(m, S, x, xd);
    double *gu = m->hyper->gu;
    memset(gu, 0, (size_t)S->nu * sizeof(double));
    m->load_element_evaluations += S->n;
    for (int k = 0; k < S->n; k++) {
        double fl[7];
        int st = m->force.element(m->force.ctx, t, m->q, m->vq, S->elem[k], fl);
        if (st) return st;
        const int *idx = S->idx + (size_t)k * GAL_ROD_ELEMENT_NQ;
        for (int a = 0; a < 7; a++) {
            int u = idx[load_to_el[a]];
            if (u >= 0) gu[u] += S->w[k] * fl[a];
        }
    }
    rows_mult("N", r, S->nu, Bu, gu, 1, f);
    return GAL_OK;
}
