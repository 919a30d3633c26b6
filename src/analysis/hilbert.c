/* hilbert.c: envelope of a record as the modulus of its analytic signal (FFT-based Hilbert
 * transform: Z_k = 2 X_k for positive, 0 for negative frequencies, Marple 1999), with the record
 * continued by reflection about a crest near each end as the edge guard, and the time to steady
 * galloping from the envelope. */
#include "gallop/base/core.h"
#include "gallop/analysis/spectrum.h"

#include <fftw3.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

struct gal_hilbert {
    size_t n, pad, m;     /* record, reflection at each end, transform length m = n + 2 pad */
    double *ext;          /* the extended centred record, m */
    fftw_complex *z;      /* its spectrum, then the analytic signal, m */
    fftw_plan fwd, bwd;
};

gal_hilbert *gal_spectrum_hilbert_alloc(size_t n)
{
    if (n < GAL_TRACE_MIN_SAMPLES) {
        gal_error(GAL_EINPUT, "envelope of %zu samples: at least %d needed", n,
                  GAL_TRACE_MIN_SAMPLES);
        return NULL;
    }
    gal_hilbert *h = calloc(1, sizeof *h);
    if (!h) return gal_error(GAL_ENOMEM, "out of memory"), NULL;
    h->n = n;
    h->pad = n / 4;
    h->m = n + 2 * h->pad;
    h->ext = fftw_malloc(h->m * sizeof *h->ext);
    h->z = fftw_malloc(h->m * sizeof *h->z);
    if (!h->ext || !h->z) {
        gal_error(GAL_ENOMEM, "out of memory for the envelope of %zu samples", n);
        return gal_spectrum_hilbert_free(h);
    }
    h->fwd = fftw_plan_dft_r2c_1d((int)h->m, h->ext, h->z, FFTW_ESTIMATE);
    h->bwd = fftw_plan_dft_1d((int)h->m, h->z, h->z, FFTW_BACKWARD, FFTW_ESTIMATE);
    if (!h->fwd || !h->bwd) {
        gal_error(GAL_EFAIL, "FFTW could not plan a transform of %zu samples", h->m);
        return gal_spectrum_hilbert_free(h);
    }
    return h;
}

gal_hilbert *gal_spectrum_hilbert_free(gal_hilbert *h)
{
    if (!h) return NULL;
    if (h->fwd) fftw_destroy_plan(h->fwd);
    if (h->bwd) fftw_destroy_plan(h->bwd);
    fftw_free(h->ext);
    fftw_free(h->z);
    free(h);
    return NULL;
}

/* ---- edge guard ----
 * The record is continued past each end by reflection about a centre c near that end,
 * x(r) = x(2c - r). For an oscillation the best centre is a crest or a trough, about which it is
 * symmetric: there the reflection continues it smoothly, while reflection about the end sample
 * leaves a kink whose Hilbert transform decays only like 1/distance. The centre minimises the
 * relative asymmetry of the record over L samples on either side (a grid of half samples, then
 * a parabola for the fraction), and the continuation is interpolated (cubic Lagrange). */

/* Relative asymmetry of x about c = c2/2 over L pairs (x(c+s), x(c-s)). */
static double asymmetry(const double *x, size_t c2, size_t L, double mean)
{
    double num = 0, den = 0;
    for (size_t i = c2 / 2 + 1; i <= c2 / 2 + L; i++) {
        double a = x[i] - mean, b = x[c2 - i] - mean;
        num += (a - b) * (a - b);
        den += a * a + b * b;
    }
    return den > 0 ? num / den : 0;
}

/* Twice the best centre, c2 in [lo, hi] (half samples), refined to a fraction. */
static double best_centre(const double *x, size_t lo, size_t hi, size_t L, double mean)
{
    size_t best = hi;
    double eb = INFINITY;
    for (size_t c2 = lo; c2 <= hi; c2++) {
        double e = asymmetry(x, c2, L, mean);
        if (e < eb) eb = e, best = c2;
    }
    if (best == lo || best == hi) return (double)best;
    double em = asymmetry(x, best - 1, L, mean), ep = asymmetry(x, best + 1, L, mean);
    double curv = em - 2 * eb + ep, d = curv > 0 ? 0.5 * (em - ep) / curv : 0;
    return (double)best + (d < -1 ? -1 : d > 1 ? 1 : d);   /* vertex of the parabola */
}

/* x at a fractional index u, 1 <= u <= n - 3 (cubic Lagrange through 4 samples). */
static double interp(const double *x, double u)
{
    size_t k = (size_t)floor(u);
    double t = u - (double)k;
    const double *q = x + k - 1;
    return q[0] * (-t * (t - 1) * (t - 2) / 6) + q[1] * ((t + 1) * (t - 1) * (t - 2) / 2)
         + q[2] * (-(t + 1) * t * (t - 2) / 2) + q[3] * ((t + 1) * t * (t - 1) / 6);
}

int gal_spectrum_envelope(gal_hilbert *h, const double *x, double band, double *env)
{
    size_t n = h->n, p = h->pad, m = h->m, w = n / 8;
    double mean = 0;
    for (size_t j = 0; j < n; j++) {
        if (!isfinite(x[j])) return gal_error(GAL_EINPUT, "envelope: sample %zu is not finite", j);
        mean += (x[j] - mean) / (double)(j + 1);   /* running mean: no overflow */
    }
    double dev = 0;
    for (size_t j = 0; j < n; j++) dev = fmax(dev, fabs(x[j] - mean));
    if (dev <= 1e-13 * (fabs(mean) + 1e-300)) {           /* constant record: no oscillation */
        for (size_t j = 0; j < n; j++) env[j] = 0;
        return GAL_OK;
    }
    /* centres within w = n/8 of each end, symmetric over L samples; with the pad p = n/4 every
     * reflected index stays inside [1, n - 3] */
    size_t L = n / 16 < 64 ? n / 16 : 64;
    double cs = best_centre(x, 2 * L, 2 * w, L, mean);
    double ce = best_centre(x, 2 * (n - 1 - w), 2 * (n - 1 - L), L, mean);
    for (size_t j = 0; j < n; j++) h->ext[p + j] = x[j] - mean;
    for (size_t j = 1; j <= p; j++) {
        h->ext[p - j] = interp(x, cs + (double)j) - mean;                   /* x(-j) */
        h->ext[p + n - 1 + j] = interp(x, ce - (double)(n - 1 + j)) - mean; /* x(n-1+j) */
    }
    fftw_execute(h->fwd);                                 /* z[0..m/2] = X_k */
    if (band > 0) {                                       /* keep 0 < f < band f_dominant */
        size_t kd = 1;
        double pd = -1;
        for (size_t k = 1; k <= m / 2; k++) {
            double pk = h->z[k][0] * h->z[k][0] + h->z[k][1] * h->z[k][1];
            if (pk > pd) pd = pk, kd = k;
        }
        for (size_t k = 1; k <= m / 2; k++)
            if ((double)k >= band * (double)kd) h->z[k][0] = h->z[k][1] = 0;
    }
    /* positive frequencies 1..(m-1)/2 doubled; DC and (m even) Nyquist kept; negative ones 0 */
    for (size_t k = 1; k < (m + 1) / 2; k++) h->z[k][0] *= 2, h->z[k][1] *= 2;
    for (size_t k = m / 2 + 1; k < m; k++) h->z[k][0] = h->z[k][1] = 0;
    fftw_execute(h->bwd);                                 /* z_j = m * analytic signal */
    for (size_t j = 0; j < n; j++) env[j] = hypot(h->z[p + j][0], h->z[p + j][1]) / (double)m;
    return GAL_OK;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int gal_spectrum_steady_time(const double *env, size_t n, double dt, double tol, double *t_steady,
                             double *level)
{
    *t_steady = NAN;
    if (level) *level = NAN;
    if (n < GAL_TRACE_MIN_SAMPLES)
        return gal_error(GAL_EINPUT, "time to steady: %zu samples, at least %d needed", n,
                         GAL_TRACE_MIN_SAMPLES);
    size_t nl = n / 5 > 0 ? n / 5 : 1;                    /* the last 20% */
    double *tail = malloc(nl * sizeof *tail);
    if (!tail) return gal_error(GAL_ENOMEM, "out of memory");
    memcpy(tail, env + n - nl, nl * sizeof *tail);
    double m1 = 0, m2 = 0, m0 = 0;   /* the means of its two halves and of the 20% before it */
    for (size_t j = 0; j < nl; j++) *(j < nl / 2 ? &m1 : &m2) += tail[j];
    for (size_t j = n - 2 * nl; j < n - nl; j++) m0 += env[j];
    m0 /= (double)nl;
    double mt = (m1 + m2) / (double)nl;
    m1 /= (double)(nl / 2 > 0 ? nl / 2 : 1), m2 /= (double)(nl - nl / 2);
    qsort(tail, nl, sizeof *tail, cmp_double);
    double L = nl % 2 ? tail[nl / 2] : 0.5 * (tail[nl / 2 - 1] + tail[nl / 2]);
    for (size_t j = 0; j < nl; j++) tail[j] = fabs(tail[j] - L);
    qsort(tail, nl, sizeof *tail, cmp_double);
    double sd = 1.4826 * (nl % 2 ? tail[nl / 2] : 0.5 * (tail[nl / 2 - 1] + tail[nl / 2])); /* MAD */
    double half = fmax(tol * L, 5 * sd), lo = L - half, hi = L + half;
    free(tail);
    if (level) *level = L;
    if (!(L > 0) || !isfinite(L)) return GAL_OK;          /* constant record: no steady level */
    /* still growing or decaying: the tail's halves, or the tail and the 20% before it, differ by
     * more than 2 tol L (the halves: also more than 2 sigma) */
    if (nl >= 2 && (fabs(m2 - m1) > fmax(2 * tol * L, 2 * sd) || fabs(mt - m0) > 2 * tol * L)) {
        *t_steady = (double)(n - nl) * dt;
        return GAL_OK;
    }
    /* steady from the first time the envelope reaches the band of its final fluctuation
     * (L +- max(tol L, 5 sigma), sigma the tail's robust spread: noise, beating lines), and after
     * the last time it rose above it (an overshoot): a stationary record is steady from the start */
    size_t guard = n / 50, end = n - guard;               /* the last 2% are not judged */
    size_t first = 0;
    while (first < end && env[first] < lo) first++;
    for (size_t j = end; j-- > first;)
        if (env[j] > hi) {
            first = j + 1;
            break;
        }
    *t_steady = (double)first * dt;
    return GAL_OK;
}
