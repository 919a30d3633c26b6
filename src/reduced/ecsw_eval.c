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

/* a . b with four partial sums (the loop is latency-bound otherwise) */
static double dot(const double *a, const double *b, int n)
{
    double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
    int k = 0;
    for (; k + 3 < n; k += 4) s0 += a[k] * b[k], s1 += a[k + 1] * b[k + 1], s2 += a[k + 2] * b[k + 2], s3 += a[k + 3] * b[k + 3];
    for (; k < n; k++) s0 += a[k] * b[k];
    return (s0 + s1) + (s2 + s3);
}

/* q = q_eq + V x (and v = V xd when xd) at sample S's entries of m->q (m->vq); returns the rows
 * of the tangent basis there (nu x r): V's, or on the manifold (qm.h) P(x)'s, with
 * q = q_eq + Phi x + Theta mono, P = Phi + Theta(x, .) (loops over the entries: no dependence
 * chains over the few coordinates). */
static const double *reconstruct(gal_rom *m, gal_rom_hyper_set *h, const double *x, const double *xd)
{
    int r = m->r, nu = h->nu;
    if (!m->qm) {
        for (int u = 0; u < nu; u++) {
            const double *vu = h->Vu + (size_t)u * r;
            m->q[h->uq[u]] = m->q_eq[h->uq[u]] + dot(vu, x, r);
            if (xd) m->vq[h->uq[u]] = dot(vu, xd, r);
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

int gal_rom_hyper_internal(gal_rom *m, const double *x, double *f, double *Kr)
{
    gal_rom_hyper *h = m->hyper;
    gal_rom_hyper_set *S = &h->set[0];
    const int NQ = GAL_ROD_ELEMENT_NQ;
    int r = m->r;
    double U = h->Uc, g[GAL_ROD_ELEMENT_NQ], H[GAL_ROD_ELEMENT_NQ * GAL_ROD_ELEMENT_NQ];
    const double *Bu = reconstruct(m, S, x, NULL);
    for (int i = 0; i < r; i++) { /* f = f_c + K_c x, U = U_c + f_c.x + x.K_c x / 2 */
        double kx = dot(h->Kc + (size_t)i * r, x, r);
        f[i] = h->fc[i] + kx, U += (h->fc[i] + 0.5 * kx) * x[i];
    }
    if (Kr) memcpy(Kr, h->Kc, (size_t)r * r * sizeof(double));
    double *gu = h->gu; /* the weighted gradient at the sample's entries, projected once at the end */
    memset(gu, 0, (size_t)S->nu * sizeof(double));
    double *T = h->T; /* NQ x r rows of w H V_e */
    for (int k = 0; k < S->n; k++) {
        double Ue, w = S->w[k];
        const int *idx = S->idx + (size_t)k * NQ;
        int st = gal_rod_element_eval(m->rod, S->elem[k], m->q, &Ue, g, Kr ? H : NULL);
        if (st) return st;
        U += w * Ue;
        int loc[GAL_ROD_ELEMENT_NQ], nl = 0;
        for (int a = 0; a < NQ; a++)
            if (idx[a] >= 0) loc[nl++] = a;
        for (int p = 0; p < nl; p++) gu[idx[loc[p]]] += w * g[loc[p]];
        if (!Kr) continue;
        for (int p = 0; p < nl; p++) { /* T_p = w sum_q H(p, q) V_q */
            double *tp = T + (size_t)p * r;
            memset(tp, 0, (size_t)r * sizeof(double));
            for (int q = 0; q < nl; q++) {
                double hpq = w * H[loc[p] * NQ + loc[q]];
                if (hpq == 0) continue;
                const double *vq = Bu + (size_t)idx[loc[q]] * r;
                for (int j = 0; j < r; j++) tp[j] += hpq * vq[j];
            }
        }
        for (int p = 0; p < nl; p++) { /* Kr += V_e^T T, the upper triangle */
            const double *vp = Bu + (size_t)idx[loc[p]] * r, *tp = T + (size_t)p * r;
            for (int i = 0; i < r; i++) {
                double vi = vp[i];
                if (vi == 0) continue;
                double *ki = Kr + (size_t)i * r;
                for (int j = i; j < r; j++) ki[j] += vi * tp[j];
            }
        }
    }
    if (Kr && m->qm) curvature(m, S, gu, Kr);
    for (int u = 0; u < S->nu; u++) { /* f += V_S^T gu */
        const double *vu = Bu + (size_t)u * r;
        double gv = gu[u];
        for (int i = 0; i < r; i++) f[i] += gv * vu[i];
    }
    if (Kr) /* the upper triangle was added to: K_c is symmetric */
        for (int i = 0; i < r; i++)
            for (int j = 0; j < i; j++) Kr[i * r + j] = Kr[j * r + i];
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
    for (int u = 0; u < S->nu; u++) {
        const double *vu = Bu + (size_t)u * r;
        double gv = gu[u];
        for (int i = 0; i < r; i++) f[i] += gv * vu[i];
    }
    return GAL_OK;
}
