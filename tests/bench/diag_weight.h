/* diag_weight.h: the share of a static response x = K0^-1 f the reduced model's basis misses
 * (tests/bench/diag_weight.c, tests/test_rom_weight.c): rom_m_share, the mass-norm share of x outside
 * span V (V^T M V = I); rom_energy_share, 1 - (V^T f)^T K0r^-1 (V^T f) / (x^T f), the share of the
 * static compliance the reduced statics misses. Include after gallop/reduced/rom.h. */
#ifndef GALLOP_DIAG_WEIGHT_H
#define GALLOP_DIAG_WEIGHT_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

void dposv_(const char *uplo, const int *n, const int *nrhs, double *a, const int *lda, double *b, const int *ldb,
            int *info);

static inline double rom_m_share(const gal_rom *m, const double *x)
{
    int n = m->ndof;
    double *Mx = malloc((size_t)2 * n * sizeof(double)), *y = Mx + n, nx = 0, ny = 0;
    gal_rod_mass_mult(m->rod, x, Mx);
    memcpy(y, x, (size_t)n * sizeof(double));
    for (int k = 0; k < m->r; k++) {
        const double *v = m->V + (size_t)k * n;
        double p = 0;
        for (int d = 0; d < n; d++) p += v[d] * Mx[d];
        for (int d = 0; d < n; d++) y[d] -= p * v[d];
    }
    for (int d = 0; d < n; d++) nx += x[d] * Mx[d];
    gal_rod_mass_mult(m->rod, y, Mx);
    for (int d = 0; d < n; d++) ny += y[d] * Mx[d];
    free(Mx);
    return sqrt(ny / nx);
}

static inline double rom_energy_share(const gal_rom *m, const double *f, const double *x)
{
    int n = m->ndof, r = m->r, one = 1, info = 0;
    double *A = malloc((size_t)r * (r + 2) * sizeof(double)), *b = A + (size_t)r * r, *c = b + r, xf = 0, q = 0;
    memcpy(A, m->K0r, (size_t)r * r * sizeof(double));
    for (int k = 0; k < r; k++) {
        double p = 0;
        for (int d = 0; d < n; d++) p += m->V[(size_t)k * n + d] * f[d];
        b[k] = c[k] = p;
    }
    dposv_("U", &r, &one, A, &r, b, &r, &info);
    for (int k = 0; k < r; k++) q += c[k] * b[k];
    for (int d = 0; d < n; d++) xf += x[d] * f[d];
    free(A);
    return info ? NAN : 1 - q / xf;
}

#endif
