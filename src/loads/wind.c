/* wind.c: along-wind turbulence at uniformly spaced points by the spectral representation method
 * (Shinozuka & Deodatis 1991; Deodatis 1996) with the analytic Cholesky factor of the exponential
 * (Davenport) coherence matrix and one FFTW c2r transform per point (DESIGN.md "Wind"; the
 * formulas are stated in include/gallop/wind.h). */
#define _POSIX_C_SOURCE 200809L
#include "gallop/loads/wind.h"
#include "gallop/base/core.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <fftw3.h>
#include <gsl/gsl_rng.h>


#define MIN_SAMPLES 16
#define MAX_VALUES 250000000L /* points * samples: 2 GB of doubles */

struct gal_wind {
    gal_wind_params p;
    int P;              /* points */
    long M;             /* samples = FFT length */
    long nf;            /* M/2 + 1 complex coefficients */
    long mmax;          /* highest frequency index used: below Nyquist */
    double df;          /* Hz, 1 / (M dt) */
    double variance;    /* m^2/s^2, sum_m S(f_m) df */
    double *amp;        /* nf: sqrt(2 S(f_m) df) / 2, the c2r half amplitude */
    double *r, *s;      /* nf: r = exp(-C f dx / U), s = sqrt(1 - r^2) */
    double *bre, *bim;  /* nf: the AR(1) recursion state B_j(f_m) */
    double *field;      /* P * M, row j is point j */
    fftw_complex *spec; /* nf */
    double *out;        /* M */
    fftw_plan plan;
    gsl_rng *rng;
};

void gal_wind_params_default(gal_wind_params *p)
{
    memset(p, 0, sizeof *p);
    p->speed = 10.0;
    p->intensity = 0.1;
    p->spectrum = GAL_WIND_KAIMAL;
    p->height = 10.0;
    p->length_scale = 0.0;
    p->coherence_decay = 10.0;
    p->points = 1;
    p->spacing = 1.0;
    p->duration = 600.0;
    p->time_step = 0.05;
    p->seed = 1;
    p->component = GAL_WIND_ALONG;
}

int gal_wind_params_check(const gal_wind_params *p)
{
    if (!p) return gal_error(GAL_EINPUT, "wind: no parameters");
    if (!(isfinite(p->speed) && p->speed > 0))
        return gal_error(GAL_EINPUT, "wind: speed = %g m/s: must be finite and > 0", p->speed);
    if (!(p->intensity >= 0 && p->intensity <= 1))
        return gal_error(GAL_EINPUT, "wind: intensity = %g: allowed range [0, 1]", p->intensity);
    if (p->spectrum != GAL_WIND_KAIMAL && p->spectrum != GAL_WIND_DAVENPORT &&
        p->spectrum != GAL_WIND_VON_KARMAN && p->spectrum != GAL_WIND_EN1991)
        return gal_error(GAL_EINPUT, "wind: spectrum = %d: allowed kaimal (%d), davenport (%d), "
                         "von_karman (%d), en1991 (%d)", (int)p->spectrum, GAL_WIND_KAIMAL,
                         GAL_WIND_DAVENPORT, GAL_WIND_VON_KARMAN, GAL_WIND_EN1991);
    if (!(isfinite(p->height) && p->height > 0))
        return gal_error(GAL_EINPUT, "wind: height = %g m: must be finite and > 0", p->height);
    if (!(isfinite(p->length_scale) && p->length_scale >= 0))
        return gal_error(GAL_EINPUT, "wind: length_scale = %g m: must be finite and >= 0 "
                         "(0: the spectrum's default)", p->length_scale);
    if (!(isfinite(p->coherence_decay) && p->coherence_decay >= 0))
        return gal_error(GAL_EINPUT, "wind: coherence_decay = %g: must be finite and >= 0",
                         p->coherence_decay);
    if (p->component != GAL_WIND_ALONG && p->component != GAL_WIND_VERTICAL)
        return gal_error(GAL_EINPUT, "wind: component = %d: allowed along (%d), vertical (%d)",
                         (int)p->component, GAL_WIND_ALONG, GAL_WIND_VERTICAL);
    if (p->points < 1 || p->points > 1000000)
        return gal_error(GAL_EINPUT, "wind: points = %d: allowed range [1, 1000000]", p->points);
    if (p->points > 1 && !(isfinite(p->spacing) && p->spacing > 0))
        return gal_error(GAL_EINPUT, "wind: spacing = %g m: must be finite and > 0", p->spacing);
    if (!(isfinite(p->time_step) && p->time_step > 0))
        return gal_error(GAL_EINPUT, "wind: time_step = %g s: must be finite and > 0",
                         p->time_step);
    if (!(isfinite(p->duration) && p->duration > 0))
        return gal_error(GAL_EINPUT, "wind: duration = %g s: must be finite and > 0", p->duration);
    double M = floor(p->duration / p->time_step + 0.5);
    if (!(M >= MIN_SAMPLES) || M * p->points > (double)MAX_VALUES)
        return gal_error(GAL_EINPUT, "wind: duration / time_step = %g samples at %d points: "
                         "allowed at least %d samples and at most %ld values in all",
                         M, p->points, MIN_SAMPLES, MAX_VALUES);
    return GAL_OK;
}

double gal_wind_length_scale(const gal_wind_params *p)
{
    if (p->length_scale > 0) return p->length_scale;
    double Lambda = 0.7 * fmin(p->height, 60.0); /* IEC 61400-1 turbulence scale parameter */
    if (p->component == GAL_WIND_VERTICAL)        /* L_w (wind.h) */
        return p->spectrum == GAL_WIND_VON_KARMAN ? 0.5 * 3.5 * Lambda : 0.66 * Lambda;
    switch (p->spectrum) {
    case GAL_WIND_KAIMAL: return 8.1 * Lambda;
    case GAL_WIND_VON_KARMAN: return 3.5 * Lambda;
    case GAL_WIND_DAVENPORT: return 1200.0;
    case GAL_WIND_EN1991: return 300.0 * pow(fmin(p->height, 200.0) / 200.0, 0.52); /* Eq. B.1, II */
    }
    return 0.0;
}

double gal_wind_psd(const gal_wind_params *p, double f)
{
    if (!(f > 0)) return 0.0;
    double U = p->speed, sig2 = pow(p->intensity * U, 2), L = gal_wind_length_scale(p);
    double n = f * L / U;
    if (p->component == GAL_WIND_VERTICAL) {
        if (p->spectrum == GAL_WIND_VON_KARMAN) /* f S / sigma^2 = 4 n (1 + 755.2 n^2) / (1 + 283.2 n^2)^(11/6) */
            return sig2 * 4.0 * L / U * (1.0 + 755.2 * n * n) / pow(1.0 + 283.2 * n * n, 11.0 / 6.0);
        return sig2 * 4.0 * L / U / pow(1.0 + 6.0 * n, 5.0 / 3.0); /* Kaimal w (IEC 61400-1) */
    }
    switch (p->spectrum) {
    case GAL_WIND_KAIMAL:     /* f S / sigma^2 = 4 n / (1 + 6 n)^(5/3) */
        return sig2 * 4.0 * L / U / pow(1.0 + 6.0 * n, 5.0 / 3.0);
    case GAL_WIND_DAVENPORT:  /* f S / sigma^2 = (2/3) x^2 / (1 + x^2)^(4/3) */
        return sig2 * (2.0 / 3.0) * (L / U) * n / pow(1.0 + n * n, 4.0 / 3.0);
    case GAL_WIND_VON_KARMAN: /* f S / sigma^2 = 4 n / (1 + 70.8 n^2)^(5/6) */
        return sig2 * 4.0 * L / U / pow(1.0 + 70.8 * n * n, 5.0 / 6.0);
    case GAL_WIND_EN1991:     /* f S / sigma^2 = 6.8 n / (1 + 10.2 n)^(5/3) (EN 1991-1-4 B.2) */
        return sig2 * 6.8 * L / U / pow(1.0 + 10.2 * n, 5.0 / 3.0);
    }
    return 0.0;
}

double gal_wind_coherence(const gal_wind_params *p, double f, double dx)
{
    return exp(-p->coherence_decay * fabs(f) * fabs(dx) / p->speed);
}

gal_wind *gal_wind_free(gal_wind *w)
{
    if (!w) return NULL;
    if (w->plan) fftw_destroy_plan(w->plan);
    fftw_free(w->spec);
    fftw_free(w->out);
    free(w->amp);
    free(w->r);
    free(w->s);
    free(w->bre);
    free(w->bim);
    free(w->field);
    if (w->rng) gsl_rng_free(w->rng);
    free(w);
    return NULL;
}

gal_wind *gal_wind_alloc(const gal_wind_params *p)
{
    if (gal_wind_params_check(p) != GAL_OK) return NULL;
    gal_gsl_errors_install(); /* GSL errors as gallop errors, never an abort */
    gal_wind *w = calloc(1, sizeof *w);
    if (!w) goto nomem;
    w->p = *p;
    w->P = p->points;
    w->M = (long)floor(p->duration / p->time_step + 0.5);
    w->nf = w->M / 2 + 1;
    w->mmax = (w->M % 2 == 0) ? w->M / 2 - 1 : (w->M - 1) / 2; /* the Nyquist term is left out */
    w->df = 1.0 / (w->M * p->time_step);
    size_t nf = (size_t)w->nf;
    w->amp = calloc(nf, sizeof(double));
    w->r = calloc(nf, sizeof(double));
    w->s = calloc(nf, sizeof(double));
    w->bre = calloc(nf, sizeof(double));
    w->bim = calloc(nf, sizeof(double));
    w->field = calloc((size_t)w->P * (size_t)w->M, sizeof(double));
    w->spec = fftw_malloc(nf * sizeof(fftw_complex));
    w->out = fftw_malloc((size_t)w->M * sizeof(double));
    w->rng = gsl_rng_alloc(gsl_rng_mt19937);
    if (!w->amp || !w->r || !w->s || !w->bre || !w->bim || !w->field || !w->spec || !w->out ||
        !w->rng)
        goto nomem;
    /* ---- per frequency: amplitude and the AR(1) coefficients of the coherence factor ---- */
    double dx = w->P > 1 ? p->spacing : 0.0;
    for (long m = 1; m <= w->mmax; m++) {
        double f = m * w->df, S = gal_wind_psd(p, f);
        w->amp[m] = 0.5 * sqrt(2.0 * S * w->df);   /* c2r doubles the m > 0 terms */
        w->variance += S * w->df;                  /* E[u^2] = sum (sqrt(2 S df))^2 / 2 */
        double r = exp(-p->coherence_decay * f * dx / p->speed);
        w->r[m] = r;
        w->s[m] = sqrt(fmax(0.0, 1.0 - r * r));
    }
    /* one plan, executed once per point (FFTW_ESTIMATE: no trial runs, the arrays are kept) */
    w->plan = fftw_plan_dft_c2r_1d((int)w->M, w->spec, w->out, FFTW_ESTIMATE);
    if (!w->plan) {
        gal_error(GAL_EFAIL, "wind: FFTW could not plan a transform of length %ld", w->M);
        return gal_wind_free(w);
    }
    return w;
nomem:
    gal_error(GAL_ENOMEM, "wind: out of memory for %d points x %.0f samples", p->points,
              floor(p->duration / p->time_step + 0.5));
    return gal_wind_free(w);
}

int gal_wind_generate(gal_wind *w)
{
    if (!w) return gal_error(GAL_EINPUT, "wind: no generator");
    gsl_rng_set(w->rng, w->p.seed);
    const long mmax = w->mmax;
    for (int j = 0; j < w->P; j++) {
        /* B_0 = xi_0; B_j = r B_(j-1) + sqrt(1 - r^2) xi_j  (row j of the analytic Cholesky
         * factor of Gamma_jk = r^|j-k| applied to unit random phasors) */
        for (long m = 1; m <= mmax; m++) {
            double phi = 2.0 * GAL_PI * gsl_rng_uniform(w->rng);
            double xr = cos(phi), xi = sin(phi);
            if (j == 0) {
                w->bre[m] = xr;
                w->bim[m] = xi;
            } else {
                w->bre[m] = w->r[m] * w->bre[m] + w->s[m] * xr;
                w->bim[m] = w->r[m] * w->bim[m] + w->s[m] * xi;
            }
            w->spec[m][0] = w->amp[m] * w->bre[m];
            w->spec[m][1] = w->amp[m] * w->bim[m];
        }
        w->spec[0][0] = w->spec[0][1] = 0.0;       /* zero mean: the mean speed is separate */
        for (long m = mmax + 1; m < w->nf; m++) w->spec[m][0] = w->spec[m][1] = 0.0;
        fftw_execute(w->plan);                     /* u_j(t_k) = Re sum_m 2 Y_m e^{i 2 pi m k / M} */
        memcpy(w->field + (size_t)j * w->M, w->out, (size_t)w->M * sizeof(double));
    }
    return GAL_OK;
}

int gal_wind_points(const gal_wind *w) { return w->P; }
int gal_wind_samples(const gal_wind *w) { return (int)w->M; }
double gal_wind_time_step(const gal_wind *w) { return w->p.time_step; }
double gal_wind_spacing(const gal_wind *w) { return w->p.spacing; }
double gal_wind_variance(const gal_wind *w) { return w->variance; }

const double *gal_wind_history(const gal_wind *w, int j)
{
    if (j < 0 || j >= w->P) return NULL;
    return w->field + (size_t)j * w->M;
}

double gal_wind_u(const gal_wind *w, int j, long k)
{
    if (j < 0 || j >= w->P) return NAN;
    k %= w->M;
    if (k < 0) k += w->M;
    return w->field[(size_t)j * w->M + k];
}

double gal_wind_u_at(const gal_wind *w, int j, double t)
{
    if (j < 0 || j >= w->P || !isfinite(t)) return NAN;
    double x = t / w->p.time_step, T = (double)w->M;
    x -= T * floor(x / T);                         /* periodic record */
    long k = (long)floor(x);
    double a = x - k;
    if (k >= w->M) k = 0, a = 0;
    const double *u = w->field + (size_t)j * w->M;
    return (1 - a) * u[k] + a * u[(k + 1) % w->M];
}
