/* welch.h: Welch power and cross spectral estimates (Hann window, 50% overlap) for the wind
 * tests (test_wind.c, test_wind_vertical.c): static helpers of the tests, not library code. */
#ifndef GALLOP_TESTS_WELCH_H
#define GALLOP_TESTS_WELCH_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <fftw3.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

typedef struct {
    int nseg;          /* segment length */
    int nb;            /* nseg/2 + 1 bins */
    double fs;         /* Hz */
    double *win, *buf;
    fftw_complex *X;
    fftw_plan plan;
    double wss;        /* sum of window^2 */
} welch;

static void welch_init(welch *W, int nseg, double fs)
{
    W->nseg = nseg;
    W->nb = nseg / 2 + 1;
    W->fs = fs;
    W->win = malloc(nseg * sizeof(double));
    W->buf = fftw_malloc(nseg * sizeof(double));
    W->X = fftw_malloc(W->nb * sizeof(fftw_complex));
    W->plan = fftw_plan_dft_r2c_1d(nseg, W->buf, W->X, FFTW_ESTIMATE);
    W->wss = 0;
    for (int i = 0; i < nseg; i++) {
        W->win[i] = 0.5 - 0.5 * cos(2 * M_PI * i / nseg);
        W->wss += W->win[i] * W->win[i];
    }
}

static void welch_free(welch *W)
{
    fftw_destroy_plan(W->plan);
    fftw_free(W->buf);
    fftw_free(W->X);
    free(W->win);
}

/* Windowed FFT of one segment of x starting at s0; result in X (nb bins). */
static void welch_fft(welch *W, const double *x, long s0, fftw_complex *X)
{
    for (int i = 0; i < W->nseg; i++) W->buf[i] = W->win[i] * x[s0 + i];
    fftw_execute(W->plan);
    memcpy(X, W->X, W->nb * sizeof(fftw_complex));
}

/* Accumulate one-sided auto spectra of x (pxx) and the cross spectrum with y (pxy, complex, may
 * be NULL) over all segments; returns the number of segments. Scaling 2 / (fs sum w^2). */
static int welch_acc(welch *W, const double *x, const double *y, long n, double *pxx, double *pyy,
                     double *pxy_re)
{
    int cnt = 0;
    fftw_complex *X = fftw_malloc(W->nb * sizeof(fftw_complex));
    fftw_complex *Y = fftw_malloc(W->nb * sizeof(fftw_complex));
    double sc = 2.0 / (W->fs * W->wss);
    for (long s0 = 0; s0 + W->nseg <= n; s0 += W->nseg / 2, cnt++) {
        welch_fft(W, x, s0, X);
        if (y) welch_fft(W, y, s0, Y);
        for (int b = 1; b < W->nb; b++) {
            pxx[b] += sc * (X[b][0] * X[b][0] + X[b][1] * X[b][1]);
            if (y) {
                pyy[b] += sc * (Y[b][0] * Y[b][0] + Y[b][1] * Y[b][1]);
                pxy_re[b] += sc * (X[b][0] * Y[b][0] + X[b][1] * Y[b][1]); /* Re X conj(Y) */
            }
        }
    }
    fftw_free(X);
    fftw_free(Y);
    return cnt;
}

#endif
