/* damping.c: the structural damping matrix of a span: modal over a documented band, or Rayleigh. */
#include "gallop/model/damping.h"
#include "gallop/base/core.h"
#include "gallop/modes/modes.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

gal_damping *gal_damping_free(gal_damping *c)
{
    if (!c) return NULL;
    free(c->omega);
    free(c->mphi);
    gal_csc_free(c->K0);
    free(c);
    return NULL;
}

void gal_damping_rayleigh_fit(double zeta, double w1, double w2, double *alpha, double *beta)
{
    if (zeta <= 0) { *alpha = *beta = 0; return; }
    if (!(w2 > w1 * 1.0001)) w2 = 3 * w1;
    *alpha = 2 * zeta * w1 * w2 / (w1 + w2);
    *beta = 2 * zeta / (w1 + w2);
}

/* The modes of rod about q up to band_hz: asks for more until the highest found is above the band
 * or the cap is reached. */
static int band_modes(const gal_rod *rod, const double *q, double band_hz, gal_modes *md)
{
    int n = rod->ndof, nev = 16;
    for (;;) {
        if (nev > n - 1) nev = n - 1;
        if (nev > GAL_DAMPING_MAX_MODES + 1) nev = GAL_DAMPING_MAX_MODES + 1;
        int st = gal_modes_solve(rod, q, nev, md);
        if (st) return st;
        if (md->mode[md->n - 1].frequency_hz > band_hz || nev >= n - 1 || nev > GAL_DAMPING_MAX_MODES) return GAL_OK;
        gal_modes_clear(md);
        nev *= 2;
    }
}

gal_damping *gal_damping_modal_alloc(const gal_rod *rod, const double *q, double zeta, double band_hz)
{
    gal_damping *c = calloc(1, sizeof *c);
    if (!c) { gal_error(GAL_ENOMEM, "damping: out of memory"); return NULL; }
    c->rod = rod, c->ndof = rod->ndof, c->zeta = zeta;
    c->band_hz = band_hz > 0 ? band_hz : GAL_DAMPING_BAND_HZ;
    c->kind = zeta > 0 ? GAL_DAMPING_MODAL : GAL_DAMPING_NONE;
    if (c->kind == GAL_DAMPING_NONE) return c;
    gal_modes md;
    if (band_modes(rod, q, c->band_hz, &md)) {
        gal_error(GAL_EFAIL, "damping: modes of the band: %s", gal_error_message());
        return gal_damping_free(c);
    }
    int nb = 0;
    while (nb < md.n && nb < GAL_DAMPING_MAX_MODES && md.mode[nb].frequency_hz <= c->band_hz) nb++;
    if (nb == 0) nb = 1; /* the band holds at least the fundamental */
    if (nb < md.n && md.mode[nb].frequency_hz <= c->band_hz) c->band_hz = md.mode[nb - 1].frequency_hz;
    int n = rod->ndof;
    c->nb = nb;
    c->omega = malloc((size_t)nb * sizeof(double));
    c->mphi = malloc((size_t)nb * n * sizeof(double));
    if (!c->omega || !c->mphi) {
        gal_modes_clear(&md);
        gal_error(GAL_ENOMEM, "damping: out of memory for %d modes", nb);
        return gal_damping_free(c);
    }
    for (int k = 0; k < nb; k++) {
        c->omega[k] = md.mode[k].omega;
        gal_rod_mass_mult(rod, md.shape + (size_t)k * n, c->mphi + (size_t)k * n);
    }
    gal_modes_clear(&md);
    return c;
}

gal_damping *gal_damping_rayleigh_alloc(const gal_rod *rod, const double *q, double alpha, double beta)
{
    gal_damping *c = calloc(1, sizeof *c);
    if (!c) { gal_error(GAL_ENOMEM, "damping: out of memory"); return NULL; }
    c->rod = rod, c->ndof = rod->ndof, c->alpha = alpha, c->beta = beta;
    c->kind = (alpha != 0 || beta != 0) ? GAL_DAMPING_RAYLEIGH : GAL_DAMPING_NONE;
    if (c->kind == GAL_DAMPING_NONE) return c;
    c->K0 = gal_csc_clone(rod->K);
    if (!c->K0) { gal_error(GAL_ENOMEM, "damping: out of memory"); return gal_damping_free(c); }
    if (gal_rod_eval(rod, q, NULL, NULL, c->K0)) {
        gal_error(GAL_EFAIL, "damping: tangent at the equilibrium: %s", gal_error_message());
        return gal_damping_free(c);
    }
    return c;
}

/* y += s A v for a symmetric matrix stored by its upper triangle */
static void symv_add(const gal_csc *A, double s, const double *v, double *y)
{
    for (int j = 0; j < A->n; j++)
        for (int p = A->colptr[j]; p < A->colptr[j + 1]; p++) {
            int i = A->rowind[p];
            double a = s * A->val[p];
            y[i] += a * v[j];
            if (i != j) y[j] += a * v[i];
        }
}

void gal_damping_apply(const gal_damping *c, const double *v, double *y)
{
    int n = c->ndof;
    if (c->kind == GAL_DAMPING_MODAL) {
        /* four band modes at a time: their dots in one pass over v (four chains, each summed in
         * order), then y updated by the four in mode order, each entry's sum as one mode at a time
         * makes it (y and v apart) */
        int k = 0;
        for (; k + 4 <= c->nb; k += 4) {
            const double *m0 = c->mphi + (size_t)k * n, *m1 = m0 + n, *m2 = m1 + n, *m3 = m2 + n;
            double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
            for (int j = 0; j < n; j++) {
                double x = v[j];
                s0 += m0[j] * x, s1 += m1[j] * x, s2 += m2[j] * x, s3 += m3[j] * x;
            }
            s0 *= 2 * c->zeta * c->omega[k], s1 *= 2 * c->zeta * c->omega[k + 1];
            s2 *= 2 * c->zeta * c->omega[k + 2], s3 *= 2 * c->zeta * c->omega[k + 3];
            for (int j = 0; j < n; j++) {
                double t = y[j];
                t += s0 * m0[j];
                t += s1 * m1[j];
                t += s2 * m2[j];
                t += s3 * m3[j];
                y[j] = t;
            }
        }
        for (; k < c->nb; k++) {
            const double *m = c->mphi + (size_t)k * n;
            double s = 0;
            for (int j = 0; j < n; j++) s += m[j] * v[j];
            s *= 2 * c->zeta * c->omega[k];
            for (int j = 0; j < n; j++) y[j] += s * m[j];
        }
    } else if (c->kind == GAL_DAMPING_RAYLEIGH) {
        if (c->alpha != 0) symv_add(c->rod->M, c->alpha, v, y);
        if (c->beta != 0) symv_add(c->K0, c->beta, v, y);
    }
}

/* B[a' nb + k'] = (M phi_k')^T phi_a' for the band modes k' = k..k+3 and the basis columns
 * a' = a, a + 1 (those that exist): eight dots at once, each summed in order (the round-off of one
 * at a time). */
static void dots4x2(const gal_damping *c, const double *phi, int a, int nbasis, int k, double *B)
{
    int n = c->ndof, nb = c->nb, ka = nb - k < 4 ? nb - k : 4, na = nbasis - a < 2 ? nbasis - a : 2;
    const double *p0 = phi + (size_t)a * n, *p1 = na > 1 ? p0 + n : p0;
    const double *m0 = c->mphi + (size_t)k * n, *m1 = ka > 1 ? m0 + n : m0, *m2 = ka > 2 ? m0 + 2 * n : m0,
                 *m3 = ka > 3 ? m0 + 3 * n : m0;
    double s0 = 0, s1 = 0, s2 = 0, s3 = 0, t0 = 0, t1 = 0, t2 = 0, t3 = 0;
    for (int j = 0; j < n; j++) {
        double x = p0[j], y = p1[j];
        s0 += m0[j] * x, s1 += m1[j] * x, s2 += m2[j] * x, s3 += m3[j] * x;
        t0 += m0[j] * y, t1 += m1[j] * y, t2 += m2[j] * y, t3 += m3[j] * y;
    }
    double s[4] = {s0, s1, s2, s3}, t[4] = {t0, t1, t2, t3};
    for (int i = 0; i < ka; i++) {
        B[(size_t)a * nb + k + i] = s[i];
        if (na > 1) B[(size_t)(a + 1) * nb + k + i] = t[i];
    }
}

int gal_damping_project(const gal_damping *c, const double *phi, int nbasis, double *P)
{
    int n = c->ndof;
    memset(P, 0, (size_t)nbasis * nbasis * sizeof(double));
    if (c->kind == GAL_DAMPING_MODAL) {
        /* P = B^T D B with B = Mphi_b^T Phi (nb x nbasis) */
        double *B = malloc((size_t)c->nb * nbasis * sizeof(double));
        if (!B) return gal_error(GAL_ENOMEM, "damping: out of memory");
        for (int a = 0; a < nbasis; a += 2)
            for (int k = 0; k < c->nb; k += 4) dots4x2(c, phi, a, nbasis, k, B);
        for (int a = 0; a < nbasis; a++)
            for (int b = 0; b < nbasis; b++) {
                double s = 0;
                for (int k = 0; k < c->nb; k++)
                    s += 2 * c->zeta * c->omega[k] * B[(size_t)a * c->nb + k] * B[(size_t)b * c->nb + k];
                P[(size_t)b * nbasis + a] = s;
            }
        free(B);
    } else if (c->kind == GAL_DAMPING_RAYLEIGH) {
        double *cv = malloc((size_t)n * sizeof(double));
        if (!cv) return gal_error(GAL_ENOMEM, "damping: out of memory");
        for (int b = 0; b < nbasis; b++) {
            memset(cv, 0, (size_t)n * sizeof(double));
            gal_damping_apply(c, phi + (size_t)b * n, cv);
            for (int a = 0; a < nbasis; a++) {
                const double *pa = phi + (size_t)a * n;
                double s = 0;
                for (int j = 0; j < n; j++) s += pa[j] * cv[j];
                P[(size_t)b * nbasis + a] = s;
            }
        }
        free(cv);
    }
    return GAL_OK;
}

double gal_damping_ratio(const gal_damping *c, const double *phi, double omega)
{
    int n = c->ndof;
    double *w = calloc((size_t)2 * n, sizeof(double));
    if (!w) return NAN;
    gal_damping_apply(c, phi, w);
    gal_rod_mass_mult(c->rod, phi, w + n);
    double num = 0, den = 0;
    for (int j = 0; j < n; j++) num += phi[j] * w[j], den += phi[j] * w[n + j];
    free(w);
    return num / (2 * omega * den);
}
