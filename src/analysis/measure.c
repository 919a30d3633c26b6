/* measure.c: what the spectral module measures on the traces of a run (issue 5): dominant
 * frequencies, amplitudes, orbit ellipse, time to steady galloping, support tensions. */
#include "gallop/analysis/measure.h"
#include "gallop/base/core.h"
#include "gallop/analysis/spectrum.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* column c of probe k over samples [i0, n) */
static void column(const gal_sim_result *r, int k, int c, long i0, double *out)
{
    int w = 4 * r->nprobe;
    for (long i = i0; i < r->nsamples; i++) out[i - i0] = r->trace[(size_t)i * w + 4 * k + c];
}

/* The slow part of x[0..n) (the mean lift and drag change as the motion grows) removed by a
 * centred running mean over one period of the dominant frequency of the second half; env is
 * scratch. */
static void detrend(double *x, long n, double dt, double *env)
{
    double fdom = NAN;
    long h0 = n / 2;
    gal_welch *w0 = gal_spectrum_welch_alloc(gal_spectrum_segment_choose((size_t)(n - h0)));
    gal_measures g0;
    if (w0 && gal_spectrum_measure(w0, x + h0, (size_t)(n - h0), dt, 1, NULL, &g0) == GAL_OK) fdom = g0.frequency;
    gal_spectrum_welch_free(w0);
    if (!(isfinite(fdom) && fdom > 0)) return;
    long wlen = (long)floor(1.0 / (fdom * dt) + 0.5);
    if (!(wlen >= 2 && wlen < n / 4)) return;
    /* centred running mean by a prefix sum (env is scratch) */
    double acc = 0;
    env[0] = 0;
    for (long i = 0; i < n; i++) acc += x[i], env[i] = acc;
    double *y = malloc((size_t)n * sizeof(double));
    if (!y) return;
    for (long i = 0; i < n; i++) {
        long a = i - wlen / 2, b = a + wlen - 1;
        if (a < 0) a = 0, b = wlen - 1;
        if (b > n - 1) b = n - 1, a = n - wlen;
        double sum = env[b] - (a > 0 ? env[a - 1] : 0);
        y[i] = x[i] - sum / wlen;
    }
    memcpy(x, y, (size_t)n * sizeof(double));
    free(y);
}

/* Time to steady and rise time from the envelope of the (detrended) vertical displacement x. */
static void envelope_times(const double *x, long n, double dt, double *env, gal_sim_measures *m)
{
    double level = 0, ts = NAN;
    gal_hilbert *h = gal_spectrum_hilbert_alloc((size_t)n);
    m->rise_time_s = NAN;
    if (h && gal_spectrum_envelope(h, x, GAL_SPECTRUM_ENVELOPE_BAND, env) == GAL_OK) {
        gal_spectrum_steady_time(env, (size_t)n, dt, 0.05, &ts, &level);
        /* first time the envelope reaches 90% of its final level: robust to a final level that
         * still breathes by a few per cent */
        if (level > 0)
            for (long i = 0; i < n; i++)
                if (env[i] >= 0.9 * level) { m->rise_time_s = i * dt; break; }
    }
    gal_spectrum_hilbert_free(h);
    m->time_to_steady_s = ts;
}

/* Frequencies, amplitudes and orbit of probe k over samples [i0, n); x is scratch of n. */
static int window_measures(const gal_sim_result *r, int k, long i0, double *x, gal_sim_measures *m)
{
    long ns = r->nsamples - i0;
    int st = GAL_OK;
    gal_welch *w = gal_spectrum_welch_alloc(gal_spectrum_segment_choose((size_t)ns));
    if (!w) return GAL_ENOMEM;
    for (int c = 0; c < 4; c++) {
        column(r, k, c, i0, x);
        gal_measures gm;
        if ((st = gal_spectrum_measure(w, x, (size_t)ns, r->dt_out, GAL_SPECTRUM_MAX_PEAKS, NULL, &gm))) break;
        m->frequency_hz[c] = gm.fundamental;
        m->dominant_hz[c] = gm.frequency;
        m->harmonic[c] = gm.harmonic;
        m->peak_to_peak[c] = gm.peak_to_peak;
        m->rms[c] = gm.rms;
        m->mean[c] = gm.mean;
    }
    gal_spectrum_welch_free(w);
    if (st) return st;
    double *y = malloc((size_t)ns * sizeof(double));
    if (y) {
        column(r, k, 0, i0, y);
        column(r, k, 1, i0, x);
        gal_orbit o;
        if (gal_spectrum_orbit(y, x, (size_t)ns, &o) == GAL_OK)
            m->orbit_major = o.major, m->orbit_minor = o.minor, m->orbit_tilt_deg = o.tilt_deg;
        free(y);
    }
    return GAL_OK;
}

int gal_sim_measure(const gal_sim_result *r, int k, double from, gal_sim_measures *m)
{
    memset(m, 0, sizeof *m);
    long n = r->nsamples;
    if (n < 64) return gal_error(GAL_EINPUT, "simulate: %ld samples are too few to measure (at least 64)", n);
    double dt = r->dt_out;
    double *x = malloc((size_t)n * sizeof(double)), *env = malloc((size_t)n * sizeof(double));
    if (!x || !env) { free(x); free(env); return gal_error(GAL_ENOMEM, "out of memory"); }
    /* time to steady galloping from the envelope of the vertical displacement */
    column(r, k, 1, 0, x);
    detrend(x, n, dt, env);
    envelope_times(x, n, dt, env, m);
    double ts = m->time_to_steady_s;
    /* the steady part: after `from` when given, else after the time to steady, but at least the
     * last third of the run */
    double t0 = from >= 0 ? from : (isfinite(ts) ? fmin(ts, (2.0 / 3.0) * r->time[n - 1]) : 0.5 * r->time[n - 1]);
    long i0 = (long)floor(t0 / dt);
    if (n - i0 < 64) i0 = n - 64;
    m->steady_from_s = i0 * dt;
    int st = window_measures(r, k, i0, x, m);
    m->tension_min = m->tension_min_steady = INFINITY;
    m->tension_max = m->tension_max_steady = -INFINITY;
    for (long i = 0; i < n; i++)
        for (int s = 0; s < 2; s++) {
            double T = r->tension[2 * i + s];
            m->tension_min = fmin(m->tension_min, T);
            m->tension_max = fmax(m->tension_max, T);
            if (i < i0) continue;
            m->tension_min_steady = fmin(m->tension_min_steady, T);
            m->tension_max_steady = fmax(m->tension_max_steady, T);
        }
    free(x);
    free(env);
    return st;
}

int gal_sim_mid_probe(const gal_sim_result *r)
{
    int best = 0;
    for (int k = 1; k < r->nprobe; k++)
        if (fabs(r->probe[k] - 0.5) < fabs(r->probe[best] - 0.5)) best = k;
    return best;
}
