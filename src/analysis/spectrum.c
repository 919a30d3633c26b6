/* spectrum.c: Welch power spectral density (Welch 1967, with the one-sided density convention of
 * spectrum.h), dominant peaks refined on the Hann-windowed DTFT of the whole record, amplitude
 * measures and the orbit ellipse (principal axes of the displacement covariance). */
#include "gallop/base/core.h"
#include "gallop/analysis/spectrum.h"

#include <fftw3.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>


struct gal_welch {
    size_t nseg, nfreq;
    double *win;        /* periodic Hann, nseg */
    double wss;         /* sum_j w_j^2 */
    double *buf;        /* windowed segment, nseg */
    fftw_complex *out;  /* its transform, nfreq */
    double *psd;        /* scratch PSD for gal_spectrum_measure, nfreq */
    fftw_plan plan;
};

size_t gal_spectrum_segment_choose(size_t n)
{
    if (n < 8) return n;
    size_t p = 8;
    if (n < 256) {
        while (2 * p <= n) p *= 2;    /* largest power of two <= n */
        return p;
    }
    p = 256;
    while (9 * (2 * p) <= 2 * n) p *= 2;   /* 8 segments of 2p need n >= 4.5 (2p) */
    return p;
}

gal_welch *gal_spectrum_welch_alloc(size_t nseg)
{
    if (nseg < 8) {
        gal_error(GAL_EINPUT, "Welch segment of %zu samples: at least 8 needed", nseg);
        return NULL;
    }
    gal_welch *w = calloc(1, sizeof *w);
    if (!w) return gal_error(GAL_ENOMEM, "out of memory"), NULL;
    w->nseg = nseg;
    w->nfreq = nseg / 2 + 1;
    w->win = malloc(nseg * sizeof *w->win);
    w->psd = malloc(w->nfreq * sizeof *w->psd);
    w->buf = fftw_malloc(nseg * sizeof *w->buf);
    w->out = fftw_malloc(w->nfreq * sizeof *w->out);
    if (!w->win || !w->psd || !w->buf || !w->out) {
        gal_error(GAL_ENOMEM, "out of memory for a Welch segment of %zu samples", nseg);
        return gal_spectrum_welch_free(w);
    }
    w->plan = fftw_plan_dft_r2c_1d((int)nseg, w->buf, w->out, FFTW_ESTIMATE);
    if (!w->plan) {
        gal_error(GAL_EFAIL, "FFTW could not plan a transform of %zu samples", nseg);
        return gal_spectrum_welch_free(w);
    }
    w->wss = 0;
    for (size_t j = 0; j < nseg; j++) {
        w->win[j] = 0.5 - 0.5 * cos(2 * GAL_PI * (double)j / (double)nseg);
        w->wss += w->win[j] * w->win[j];
    }
    return w;
}

gal_welch *gal_spectrum_welch_free(gal_welch *w)
{
    if (!w) return NULL;
    if (w->plan) fftw_destroy_plan(w->plan);
    fftw_free(w->buf);
    fftw_free(w->out);
    free(w->win);
    free(w->psd);
    free(w);
    return NULL;
}

size_t gal_spectrum_welch_segment(const gal_welch *w) { return w->nseg; }
size_t gal_spectrum_welch_nfreq(const gal_welch *w) { return w->nfreq; }

int gal_spectrum_psd(gal_welch *w, const double *x, size_t n, double dt, double *psd, double *df,
                     size_t *nsegments)
{
    size_t nseg = w->nseg, nf = w->nfreq, step = nseg / 2;
    if (!(dt > 0) || !isfinite(dt)) return gal_error(GAL_EINPUT, "time step %g s: must be > 0", dt);
    if (n < nseg)
        return gal_error(GAL_EINPUT, "record of %zu samples is shorter than the Welch segment (%zu)",
                         n, nseg);
    for (size_t j = 0; j < n; j++)
        if (!isfinite(x[j])) return gal_error(GAL_EINPUT, "sample %zu is not finite", j);
    size_t nsg = (n - nseg) / step + 1;
    double fs = 1 / dt;
    for (size_t k = 0; k < nf; k++) psd[k] = 0;
    for (size_t s = 0; s < nsg; s++) {
        const double *xs = x + s * step;
        double mean = 0;
        for (size_t j = 0; j < nseg; j++) mean += xs[j];
        mean /= (double)nseg;
        for (size_t j = 0; j < nseg; j++) w->buf[j] = w->win[j] * (xs[j] - mean);
        fftw_execute(w->plan);
        for (size_t k = 0; k < nf; k++)
            psd[k] += w->out[k][0] * w->out[k][0] + w->out[k][1] * w->out[k][1];
    }
    double scale = 1 / (fs * w->wss * (double)nsg);   /* P = c |X|^2 / (fs sum w^2), averaged */
    for (size_t k = 0; k < nf; k++) {
        int edge = (k == 0) || (nseg % 2 == 0 && k == nf - 1);
        psd[k] *= (edge ? 1 : 2) * scale;
    }
    if (df) *df = fs / (double)nseg;
    if (nsegments) *nsegments = nsg;
    return GAL_OK;
}

/* ---- sub-bin refinement on the whole record ---- */

/* |X(f)|^2 of the Hann-windowed centred record (spectrum.h, gal_spectrum_refine) at the four
 * frequencies f[0..3] into p (and sum w into *wsum); the phasors e^{-i w j} and e^{i th j} run by
 * rotation and are reset exactly every 1024 samples. Each frequency's sums are those of a loop over
 * that frequency alone, in the same order (the four interleaved: four dependency chains instead
 * of one, the window's shared). */
static void dtft2x4(const double *x, size_t n, double dt, double mean, const double *f, double *p, double *wsum)
{
    double th = 2 * GAL_PI / (double)n, ct = cos(th), st = sin(th), ws = 0;
    double om[4], cr[4], sr[4], re[4] = {0, 0, 0, 0}, im[4] = {0, 0, 0, 0}, zr[4], zi[4];
    for (int q = 0; q < 4; q++) om[q] = 2 * GAL_PI * f[q] * dt, cr[q] = cos(om[q]), sr[q] = -sin(om[q]);
    for (size_t j0 = 0; j0 < n; j0 += 1024) {
        for (int q = 0; q < 4; q++) zr[q] = cos(om[q] * (double)j0), zi[q] = -sin(om[q] * (double)j0); /* e^{-i om j} */
        double ur = cos(th * (double)j0), ui = sin(th * (double)j0); /* e^{i th j} */
        size_t j1 = j0 + 1024 < n ? j0 + 1024 : n;
        double r0 = re[0], r1 = re[1], r2 = re[2], r3 = re[3], i0 = im[0], i1 = im[1], i2 = im[2], i3 = im[3];
        double a0 = zr[0], a1 = zr[1], a2 = zr[2], a3 = zr[3], b0 = zi[0], b1 = zi[1], b2 = zi[2], b3 = zi[3];
        for (size_t j = j0; j < j1; j++) {
            double wj = 0.5 - 0.5 * ur;
            double v = wj * (x[j] - mean), t;
            ws += wj;
#define GAL_DTFT_ROTATE(R, I, A, B, q) \
    R += v * A, I += v * B, t = A * cr[q] - B * sr[q], B = A * sr[q] + B * cr[q], A = t
            GAL_DTFT_ROTATE(r0, i0, a0, b0, 0);
            GAL_DTFT_ROTATE(r1, i1, a1, b1, 1);
            GAL_DTFT_ROTATE(r2, i2, a2, b2, 2);
            GAL_DTFT_ROTATE(r3, i3, a3, b3, 3);
#undef GAL_DTFT_ROTATE
            t = ur * ct - ui * st;
            ui = ur * st + ui * ct;
            ur = t;
        }
        re[0] = r0, re[1] = r1, re[2] = r2, re[3] = r3, im[0] = i0, im[1] = i1, im[2] = i2, im[3] = i3;
    }
    if (wsum) *wsum = ws;
    for (int q = 0; q < 4; q++) p[q] = re[q] * re[q] + im[q] * im[q];
}

/* |X(f)|^2 at one frequency (dtft2x4's) */
static double dtft2(const double *x, size_t n, double dt, double mean, double f, double *wsum)
{
    double fs[4] = {f, f, f, f}, p[4];
    dtft2x4(x, n, dt, mean, fs, p, wsum);
    return p[0];
}

/* The golden section's state: the bracket [a, b], its inner points c < d and |X|^2 there. */
typedef struct { double a, b, c, d, pc, pd; } golden;

/* One golden-section iteration with p the value at the point it adds (golden_next's). */
static void golden_step(golden *g, double gr, double p)
{
    if (g->pc >= g->pd) {
        g->b = g->d, g->d = g->c, g->pd = g->pc;
        g->c = g->b - gr * (g->b - g->a), g->pc = p;
    } else {
        g->a = g->c, g->c = g->d, g->pc = g->pd;
        g->d = g->a + gr * (g->b - g->a), g->pd = p;
    }
}

/* The point the next iteration from g adds. */
static double golden_next(const golden *g, double gr)
{
    return g->pc >= g->pd ? g->d - gr * (g->d - g->a) : g->c + gr * (g->b - g->c);
}

/* The golden section from g down to (b - a) <= tol or 60 iterations, two iterations a pass over
 * the record: the next point and both points the one after may add (the iterations and their
 * values exactly those of one point at a time). */
static void golden_run(const double *x, size_t n, double dt, double mean, double gr, double tol, golden *g)
{
    int it = 0;
    while (it < 60 && (g->b - g->a) > tol) {
        double f[4], p[4];
        golden lo = *g, hi;
        f[0] = golden_next(g, gr);
        golden_step(&lo, gr, 0); /* the state after it, for either outcome of its comparison */
        hi = lo;
        lo.pc = 1, lo.pd = 0; /* pc >= pd */
        hi.pc = 0, hi.pd = 1;
        f[1] = golden_next(&lo, gr), f[2] = golden_next(&hi, gr), f[3] = f[2];
        dtft2x4(x, n, dt, mean, f, p, NULL);
        golden_step(g, gr, p[0]);
        if (++it >= 60 || !((g->b - g->a) > tol)) break;
        golden_step(g, gr, g->pc >= g->pd ? p[1] : p[2]);
        it++;
    }
}
int gal_spectrum_refine(const double *x, size_t n, double dt, double f0, double halfwidth,
                        double *f, double *amplitude)
{
    if (n < 2 || !(dt > 0)) return gal_error(GAL_EINPUT, "refine: %zu samples, dt %g s", n, dt);
    double mean = 0;
    for (size_t j = 0; j < n; j++) mean += (x[j] - mean) / (double)(j + 1);   /* running mean */
    double fnyq = 0.5 / dt, h = 0.5 / ((double)n * dt);   /* grid: half a record bin */
    double lo = f0 - halfwidth, hi = f0 + halfwidth;
    if (lo < 0) lo = 0;
    if (hi > fnyq) hi = fnyq;
    if (!(hi >= lo)) return gal_error(GAL_EINPUT, "refine: no frequency range near %g Hz", f0);
    /* grid search for the bracket; at most 513 points (a segment far shorter than the record,
     * n > 200 nseg, gets a grid coarser than half a record bin); four points a pass */
    size_t ng = (size_t)ceil((hi - lo) / h) + 1;
    if (ng > 513) ng = 513, h = (hi - lo) / 512;
    double best = -1, fb = f0;
    for (size_t g0 = 0; g0 < ng; g0 += 4) {
        double fg[4], p[4];
        for (size_t q = 0; q < 4; q++) {
            size_t g = g0 + q < ng ? g0 + q : ng - 1;
            fg[q] = lo + (hi - lo) * (ng > 1 ? (double)g / (double)(ng - 1) : 0.5);
        }
        dtft2x4(x, n, dt, mean, fg, p, NULL);
        for (size_t q = 0; q < 4 && g0 + q < ng; q++)
            if (p[q] > best) best = p[q], fb = fg[q];
    }
    /* golden section on [fb - h, fb + h]: the Hann main lobe (+-2 record bins) is unimodal there */
    golden g;
    g.a = fb - h, g.b = fb + h;
    if (g.a < lo) g.a = lo;
    if (g.b > hi) g.b = hi;
    const double gr = 0.5 * (sqrt(5.0) - 1);
    double fcd[4], pcd[4];
    g.c = g.b - gr * (g.b - g.a), g.d = g.a + gr * (g.b - g.a);
    fcd[0] = g.c, fcd[1] = fcd[2] = fcd[3] = g.d;
    dtft2x4(x, n, dt, mean, fcd, pcd, NULL);
    g.pc = pcd[0], g.pd = pcd[1];
    golden_run(x, n, dt, mean, gr, 1e-9 * h, &g);
    double fr = 0.5 * (g.a + g.b), ws;
    double p = dtft2(x, n, dt, mean, fr, &ws);
    if (p < best) {   /* the grid point was better (edge of the range) */
        fr = fb;
        p = dtft2(x, n, dt, mean, fr, &ws);
    }
    *f = fr;
    if (amplitude) *amplitude = 2 * sqrt(p) / ws;   /* A = 2 |X| / sum w */
    return GAL_OK;
}

static int cmp_dbl(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double gal_spectrum_noise_floor(const double *psd, size_t nfreq, size_t k, double *scratch)
{
    size_t w = nfreq / 16 > GAL_SPECTRUM_FLOOR_HALFWIDTH ? nfreq / 16 : GAL_SPECTRUM_FLOOR_HALFWIDTH;
    size_t a = k > w ? k - w : 1, b = k + w < nfreq ? k + w : nfreq - 1, m = 0;
    if (a >= nfreq) return 0;
    for (size_t q = a; q <= b; q++) scratch[m++] = psd[q];
    qsort(scratch, m, sizeof *scratch, cmp_dbl);
    return m % 2 ? scratch[m / 2] : 0.5 * (scratch[m / 2 - 1] + scratch[m / 2]);
}

int gal_spectrum_peaks(const double *psd, size_t nfreq, double df, const double *x, size_t n,
                       double dt, size_t kmax, gal_peak *peaks, size_t *npeaks)
{
    *npeaks = 0;
    if (kmax > GAL_SPECTRUM_MAX_PEAKS) kmax = GAL_SPECTRUM_MAX_PEAKS;
    if (nfreq < 3 || kmax == 0) return GAL_OK;
    double pmax = 0;
    for (size_t k = 1; k < nfreq; k++)
        if (psd[k] > pmax) pmax = psd[k];
    if (!(pmax > 0)) return GAL_OK;
    size_t np = 0, hw = nfreq / 16 > GAL_SPECTRUM_FLOOR_HALFWIDTH ? nfreq / 16 : GAL_SPECTRUM_FLOOR_HALFWIDTH;
    double *scratch = malloc((2 * hw + 1) * sizeof *scratch);
    if (!scratch) return gal_error(GAL_ENOMEM, "out of memory");
    /* the kmax largest local maxima standing GAL_SPECTRUM_PEAK_SNR above the local noise floor,
     * kept sorted by decreasing PSD (insertion) */
    for (size_t k = 1; k + 1 < nfreq; k++) {
        if (!(psd[k] > psd[k - 1] && psd[k] >= psd[k + 1])) continue;
        if (psd[k] < GAL_SPECTRUM_PEAK_FLOOR * pmax) continue;
        if (psd[k] < GAL_SPECTRUM_PEAK_SNR * gal_spectrum_noise_floor(psd, nfreq, k, scratch)) continue;
        size_t pos = np;
        while (pos > 0 && peaks[pos - 1].psd < psd[k]) pos--;
        if (pos >= kmax) continue;
        size_t last = np < kmax ? np : kmax - 1;
        for (size_t q = last; q > pos; q--) peaks[q] = peaks[q - 1];
        peaks[pos].psd = psd[k];
        peaks[pos].bin = k;
        if (np < kmax) np++;
    }
    free(scratch);
    for (size_t q = 0; q < np; q++) {
        double f0 = (double)peaks[q].bin * df;
        int st = gal_spectrum_refine(x, n, dt, f0, 0.6 * df, &peaks[q].frequency,
                                     &peaks[q].amplitude);
        if (st) return st;
    }
    *npeaks = np;
    return GAL_OK;
}

void gal_spectrum_fundamental(const gal_peak *pk, size_t np, double *f0, int *order)
{
    *f0 = np ? pk[0].frequency : NAN, *order = np ? 1 : 0;
    for (size_t q = 1; q < np; q++) {
        double fd = pk[0].frequency, fq = pk[q].frequency, n = floor(fd / fq + 0.5);
        if (!(fq < *f0 && pk[q].amplitude >= GAL_SPECTRUM_FUNDAMENTAL_AMP * pk[0].amplitude)) continue;
        if (n >= 2 && n <= GAL_SPECTRUM_MAX_HARMONIC && fabs(fd - n * fq) <= GAL_SPECTRUM_HARMONIC_TOL * fd)
            *f0 = fq, *order = (int)n;
    }
}

int gal_spectrum_measure(gal_welch *w, const double *x, size_t n, double dt, size_t kmax,
                         double *psd, gal_measures *m)
{
    memset(m, 0, sizeof *m);
    m->frequency = m->amplitude = m->fundamental = NAN;
    if (n == 0) return gal_error(GAL_EINPUT, "empty record");
    double mean = 0, lo = x[0], hi = x[0], ss = 0;
    for (size_t j = 0; j < n; j++) {
        if (!isfinite(x[j])) return gal_error(GAL_EINPUT, "sample %zu is not finite", j);
        mean += (x[j] - mean) / (double)(j + 1);   /* running mean: no overflow */
        if (x[j] < lo) lo = x[j];
        if (x[j] > hi) hi = x[j];
    }
    for (size_t j = 0; j < n; j++) ss += (x[j] - mean) * (x[j] - mean);   /* two-pass variance */
    m->mean = mean;
    m->rms = sqrt(ss / (double)n);
    m->peak_to_peak = hi - lo;
    double *p = psd ? psd : w->psd, df;
    int st = gal_spectrum_psd(w, x, n, dt, p, &df, NULL);
    if (st) return st;
    if (m->rms <= 1e-13 * (fabs(mean) + 1e-300) || hi == lo) {   /* constant: no spectral line */
        m->rms = hi == lo ? 0 : m->rms;
        return GAL_OK;
    }
    st = gal_spectrum_peaks(p, w->nfreq, df, x, n, dt, kmax, m->peaks, &m->npeaks);
    if (st) return st;
    if (m->npeaks > 0) {
        m->frequency = m->peaks[0].frequency;
        m->amplitude = m->peaks[0].amplitude;
        gal_spectrum_fundamental(m->peaks, m->npeaks, &m->fundamental, &m->harmonic);
    } else {
        /* no line above the noise floor: the dominant frequency is still the largest local
         * maximum (m->npeaks = 0 says it is not significant) */
        size_t kb = 0;
        for (size_t k = 1; k + 1 < w->nfreq; k++)
            if (p[k] > p[k - 1] && p[k] >= p[k + 1] && (kb == 0 || p[k] > p[kb])) kb = k;
        if (kb > 0 && (st = gal_spectrum_refine(x, n, dt, (double)kb * df, 0.6 * df, &m->frequency,
                                                &m->amplitude)))
            return st;
        m->fundamental = m->frequency, m->harmonic = kb > 0;
    }
    return GAL_OK;
}

int gal_spectrum_orbit(const double *y, const double *z, size_t n, gal_orbit *o)
{
    o->major = o->minor = o->tilt_deg = NAN;
    if (n < 2) return gal_error(GAL_EINPUT, "orbit of %zu samples: at least 2 needed", n);
    double my = 0, mz = 0;
    for (size_t j = 0; j < n; j++) {
        if (!isfinite(y[j]) || !isfinite(z[j]))
            return gal_error(GAL_EINPUT, "orbit: sample %zu is not finite", j);
        my += y[j], mz += z[j];
    }
    my /= (double)n, mz /= (double)n;
    double cyy = 0, czz = 0, cyz = 0;
    for (size_t j = 0; j < n; j++) {
        double a = y[j] - my, b = z[j] - mz;
        cyy += a * a, czz += b * b, cyz += a * b;
    }
    cyy /= (double)n, czz /= (double)n, cyz /= (double)n;
    double mid = 0.5 * (cyy + czz), rad = hypot(0.5 * (cyy - czz), cyz);
    double l1 = mid + rad, l2 = mid - rad;   /* eigenvalues of C, l1 >= l2 */
    o->major = sqrt(2 * l1);
    o->minor = sqrt(2 * (l2 > 0 ? l2 : 0));
    double tilt = 0.5 * atan2(2 * cyz, cyy - czz) * 180 / GAL_PI;   /* in (-90, 90] */
    if (tilt <= -90) tilt += 180;
    o->tilt_deg = tilt;
    return GAL_OK;
}
