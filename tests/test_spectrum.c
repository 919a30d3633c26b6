/* test_spectrum.c: Welch PSD, peaks, amplitudes, orbit, envelope, the CSV trace reader and the
 * analysis of a whole trace on synthetic signals of known content (tolerances stated at each
 * check). */
#include "check.h"
#include "gallop.h"
#include "gallop/analysis/trace_spectrum.h"

#include <stdint.h>
#include <unistd.h>

#define PI 3.14159265358979323846

/* A fixed-seed normal generator (xorshift64* and Box-Muller) so that the noise test is
 * reproducible. */
static uint64_t rng_state = 88172645463325252ull;
static double urand(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return ((rng_state * 2685821657736338717ull) >> 11) * (1.0 / 9007199254740992.0);
}
static double nrand(void)
{
    double u = urand(), v = urand();
    if (u < 1e-300) u = 1e-300;
    return sqrt(-2 * log(u)) * cos(2 * PI * v);
}

/* Measure x[0..n) with the chosen segment; returns the status. */
static int measure(const double *x, size_t n, double dt, gal_measures *m, double *df)
{
    size_t nseg = gal_spectrum_segment_choose(n);
    gal_welch *w = gal_spectrum_welch_alloc(nseg);
    if (!w) return GAL_EFAIL;
    int st = gal_spectrum_measure(w, x, n, dt, 4, NULL, m);
    *df = 1 / (nseg * dt);
    gal_spectrum_welch_free(w);
    return st;
}

static void test_segment_choose(void)
{
    CHECK(gal_spectrum_segment_choose(100) == 64, "n=100: %zu", gal_spectrum_segment_choose(100));
    CHECK(gal_spectrum_segment_choose(1000) == 256, "n=1000: %zu", gal_spectrum_segment_choose(1000));
    /* 8 segments of 4096 with 50% overlap need 4.5 * 4096 = 18432 samples */
    CHECK(gal_spectrum_segment_choose(18432) == 4096, "%zu", gal_spectrum_segment_choose(18432));
    CHECK(gal_spectrum_segment_choose(18431) == 2048, "%zu", gal_spectrum_segment_choose(18431));
}

/* A pure sine between two Welch bins: frequency within 0.1% of the bin width, amplitude 1%. */
static void test_pure_sine_between_bins(void)
{
    size_t n = 20000;
    double dt = 0.01, A = 0.73;
    size_t nseg = gal_spectrum_segment_choose(n);
    double df = 1 / (nseg * dt), f = 37.37 * df;   /* 0.37 bin off a bin */
    double *x = malloc(n * sizeof *x);
    for (size_t j = 0; j < n; j++) x[j] = 2.5 + A * sin(2 * PI * f * j * dt + 0.4);
    gal_measures m;
    double df2;
    CHECK(measure(x, n, dt, &m, &df2) == GAL_OK, "%s", gal_error_message());
    double ef = fabs(m.frequency - f) / df, ea = fabs(m.amplitude - A) / A;
    printf("    pure sine: frequency error %.2e bins, amplitude error %.2e\n", ef, ea);
    CHECK(ef < 1e-3, "frequency error %g bins", ef);
    CHECK(ea < 1e-2, "amplitude error %g", ea);
    CHECK_REL(m.mean, 2.5, 1e-3);
    CHECK_REL(m.rms, A / sqrt(2), 1e-2);
    CHECK_REL(m.peak_to_peak, 2 * A, 1e-3);
    CHECK(m.npeaks == 1, "a pure sine has one peak above the floor, got %zu", m.npeaks);
    free(x);
}

/* The worst case over many phases and sub-bin offsets, at low and high frequency. */
static void test_sine_sweep(void)
{
    size_t n = 9000;
    double dt = 0.002, A = 1.7, efmax = 0, eamax = 0;
    size_t nseg = gal_spectrum_segment_choose(n);
    double df = 1 / (nseg * dt);
    double *x = malloc(n * sizeof *x);
    for (int q = 0; q < 24; q++) {
        double f = (q < 12 ? 3.0 : 80.0 + 7.0 * q) * df + 0.083 * q * df, ph = 0.7 * q;
        for (size_t j = 0; j < n; j++) x[j] = A * cos(2 * PI * f * j * dt + ph);
        gal_measures m;
        double d;
        CHECK(measure(x, n, dt, &m, &d) == GAL_OK, "%s", gal_error_message());
        double ef = fabs(m.frequency - f) / df, ea = fabs(m.amplitude - A) / A;
        if (ef > efmax) efmax = ef;
        if (ea > eamax) eamax = ea;
    }
    printf("    sine sweep (24 cases, from 3 bins): max frequency error %.2e bins, max amplitude "
           "error %.2e\n", efmax, eamax);
    CHECK(efmax < 1e-3, "frequency error %g bins", efmax);
    CHECK(eamax < 1e-2, "amplitude error %g", eamax);
    free(x);
}

/* Two sines: both found, in the right order, with their frequencies and amplitudes. */
static void test_two_sines(void)
{
    size_t n = 40000;
    double dt = 0.005, f1 = 1.234, f2 = 3.71, a1 = 1.0, a2 = 0.3;
    double *x = malloc(n * sizeof *x);
    for (size_t j = 0; j < n; j++) {
        double t = j * dt;
        x[j] = a1 * sin(2 * PI * f1 * t) + a2 * cos(2 * PI * f2 * t + 1.0);
    }
    gal_measures m;
    double df;
    CHECK(measure(x, n, dt, &m, &df) == GAL_OK, "%s", gal_error_message());
    CHECK(m.npeaks == 2, "two peaks expected, got %zu", m.npeaks);
    if (m.npeaks >= 2) {
        printf("    two sines: errors %.2e and %.2e bins, amplitudes %.2e and %.2e\n",
               fabs(m.peaks[0].frequency - f1) / df, fabs(m.peaks[1].frequency - f2) / df,
               fabs(m.peaks[0].amplitude - a1) / a1, fabs(m.peaks[1].amplitude - a2) / a2);
        CHECK_NEAR(m.peaks[0].frequency, f1, 1e-3 * df);
        CHECK_NEAR(m.peaks[1].frequency, f2, 1e-3 * df);
        CHECK_REL(m.peaks[0].amplitude, a1, 1e-2);
        CHECK_REL(m.peaks[1].amplitude, a2, 1e-2);
    }
    free(x);
}

/* The fundamental (gal_spectrum_fundamental): a sine with a stronger 2nd (3rd, 4th) harmonic in
 * noise is periodic at f, not at the larger line; a lower line that is no subharmonic of the dominant
 * one, or a remainder under 5% of its amplitude, is not the fundamental. */
static void harmonic_case(const char *what, const double *f, const double *a, int nl, double want, int order)
{
    size_t n = 6000;
    double dt = 0.05, df, *x = malloc(n * sizeof *x);
    rng_state = 99;
    for (size_t j = 0; j < n; j++) {
        x[j] = 0.2 * nrand();
        for (int l = 0; l < nl; l++) x[j] += a[l] * sin(2 * PI * f[l] * j * dt + 0.7 * l);
    }
    gal_measures m;
    CHECK(measure(x, n, dt, &m, &df) == GAL_OK, "%s", gal_error_message());
    printf("    %s: dominant %.5f Hz, fundamental %.5f Hz, order %d\n", what, m.frequency, m.fundamental, m.harmonic);
    CHECK(fabs(m.fundamental - want) < 1e-3 * want && m.harmonic == order, "%s: fundamental %g Hz (order %d), want %g "
          "(%d)", what, m.fundamental, m.harmonic, want, order);
    free(x);
}

static void test_fundamental(void)
{
    double f2[] = {0.25, 0.5}, a2[] = {1.0, 1.5};
    harmonic_case("2nd harmonic 1.5x stronger", f2, a2, 2, 0.25, 2);
    double a2w[] = {1.0, 0.6};
    harmonic_case("2nd harmonic weaker", f2, a2w, 2, 0.25, 1);
    double a2s[] = {0.08, 1.0}; /* a small line (8%) still makes the period */
    harmonic_case("small fundamental", f2, a2s, 2, 0.25, 2);
    double f3[] = {0.3, 0.9}, a3[] = {0.5, 1.2};
    harmonic_case("3rd harmonic stronger", f3, a3, 2, 0.3, 3);
    double fx[] = {0.3, 0.5}, ax[] = {0.6, 1.0};
    harmonic_case("a lower line, not a subharmonic", fx, ax, 2, 0.5, 1);
    double a2t[] = {0.03, 1.0}; /* a remainder of 3%: no period of its own */
    harmonic_case("a remainder below 5%", f2, a2t, 2, 0.5, 1);
    double f4[] = {0.2, 0.4, 0.6, 0.8}, a4[] = {0.3, 0.5, 0.4, 1.0}; /* the 4th harmonic the largest */
    harmonic_case("4th harmonic largest", f4, a4, 4, 0.2, 4);
    gal_peak none[1];
    double f0;
    int order;
    gal_spectrum_fundamental(none, 0, &f0, &order);
    CHECK(isnan(f0) && order == 0, "no peak: %g, %d", f0, order);
}

/* White noise: sum(PSD) df equals the variance within 3% (Parseval), and the PSD is flat. */
static void test_white_noise_parseval(void)
{
    size_t n = 65536;
    double dt = 0.01, sigma = 0.8;
    double *x = malloc(n * sizeof *x);
    rng_state = 88172645463325252ull;
    for (size_t j = 0; j < n; j++) x[j] = 1.0 + sigma * nrand();
    size_t nseg = gal_spectrum_segment_choose(n);
    gal_welch *w = gal_spectrum_welch_alloc(nseg);
    size_t nf = gal_spectrum_welch_nfreq(w), nsg = 0;
    double *psd = malloc(nf * sizeof *psd), df = 0;
    CHECK(gal_spectrum_psd(w, x, n, dt, psd, &df, &nsg) == GAL_OK, "%s", gal_error_message());
    CHECK(nsg >= 8, "at least 8 segments, got %zu", nsg);
    double var = 0, mean = 0, integral = 0;
    for (size_t j = 0; j < n; j++) mean += x[j];
    mean /= n;
    for (size_t j = 0; j < n; j++) var += (x[j] - mean) * (x[j] - mean);
    var /= n;
    for (size_t k = 0; k < nf; k++) integral += psd[k] * df;
    printf("    white noise: sum(PSD) df / variance = %.4f\n", integral / var);
    CHECK_REL(integral, var, 0.03);
    /* flat: the mean over the upper half of the band is sigma^2 / (fs/2) = 2 sigma^2 dt, 5% */
    double up = 0;
    for (size_t k = nf / 2; k < nf - 1; k++) up += psd[k];
    up /= (double)(nf - 1 - nf / 2);
    CHECK_REL(up, 2 * sigma * sigma * dt, 0.05);
    /* a sine: the PSD integral is A^2/2 */
    for (size_t j = 0; j < n; j++) x[j] = 2.0 * sin(2 * PI * 7.3 * j * dt);
    CHECK(gal_spectrum_psd(w, x, n, dt, psd, &df, NULL) == GAL_OK, "%s", gal_error_message());
    integral = 0;
    for (size_t k = 0; k < nf; k++) integral += psd[k] * df;
    CHECK_REL(integral, 2.0, 0.01);
    free(psd);
    free(x);
    gal_spectrum_welch_free(w);
}

/* A growing-then-steady oscillation with a logistic amplitude A(t) = As / (1 + e^{-(t-tc)/tau}):
 * the envelope reaches 95% of As at tc + tau ln 19; the estimate must be within 0.1 s (0.13 period). */
static void test_time_to_steady(void)
{
    double dt = 0.01, f = 1.3, As = 0.5, tc = 40, tau = 5, T = 200;
    size_t n = (size_t)(T / dt);
    double *x = malloc(n * sizeof *x), *env = malloc(n * sizeof *env);
    for (size_t j = 0; j < n; j++) {
        double t = j * dt;
        x[j] = -3.0 + As / (1 + exp(-(t - tc) / tau)) * sin(2 * PI * f * t);
    }
    gal_hilbert *h = gal_spectrum_hilbert_alloc(n);
    CHECK(h != NULL, "%s", gal_error_message());
    CHECK(gal_spectrum_envelope(h, x, 0, env) == GAL_OK, "%s", gal_error_message());
    double ts, level, want = tc + tau * log(19.0);
    CHECK(gal_spectrum_steady_time(env, n, dt, 0.05, &ts, &level) == GAL_OK, "%s",
          gal_error_message());
    printf("    time to steady: %.3f s, true %.3f s; level %.5f, true %.5f\n", ts, want, level, As);
    CHECK_NEAR(ts, want, 0.1);
    CHECK_REL(level, As, 0.005);
    /* with white noise of 4% of the final amplitude, the band-limited envelope (0 < f < 1.5 f_d)
     * still finds it within 0.5 s; the full-band envelope ripples by more than 5% */
    rng_state = 12345;
    for (size_t j = 0; j < n; j++) x[j] += 0.04 * As * nrand();
    CHECK(gal_spectrum_envelope(h, x, GAL_SPECTRUM_ENVELOPE_BAND, env) == GAL_OK, "status");
    CHECK(gal_spectrum_steady_time(env, n, dt, 0.05, &ts, &level) == GAL_OK, "status");
    printf("    time to steady with 4%% noise: %.3f s, true %.3f s\n", ts, want);
    CHECK_NEAR(ts, want, 0.5);
    CHECK_REL(level, As, 0.01);
    /* the envelope of a steady sine is flat within 1e-4, at the ends too (edge guard) */
    for (size_t j = 0; j < n; j++) x[j] = 0.2 * cos(2 * PI * 0.77 * j * dt + 0.3);
    CHECK(gal_spectrum_envelope(h, x, 0, env) == GAL_OK, "%s", gal_error_message());
    double emid = 0, eend = 0;
    for (int q = 0; q < 12; q++) {   /* periods of 125 and 129.87 samples, 6 phases each */
        double fq = q < 6 ? 0.8 : 0.77, ph = 0.3 + 0.5 * q;
        for (size_t j = 0; j < n; j++) x[j] = 0.2 * cos(2 * PI * fq * j * dt + ph);
        CHECK(gal_spectrum_envelope(h, x, 0, env) == GAL_OK, "%s", gal_error_message());
        for (size_t j = 0; j < n; j++) {
            double e = fabs(env[j] - 0.2) / 0.2;
            if (j > n / 50 && j < n - n / 50) emid = e > emid ? e : emid;
            else eend = e > eend ? e : eend;
        }
    }
    printf("    envelope of a steady sine: max error %.2e inside, %.2e in the 2%% edges\n", emid,
           eend);
    CHECK(emid < 1e-4, "inside %g", emid);
    CHECK(eend < 1e-4, "ends %g", eend);
    CHECK(gal_spectrum_steady_time(env, n, dt, 0.05, &ts, NULL) == GAL_OK, "status");
    CHECK(ts == 0, "a steady sine is steady from the start, got %g s", ts);
    gal_spectrum_hilbert_free(h);
    free(x);
    free(env);
}

/* A growing-then-steady oscillation with a strong second harmonic (35% of the fundamental, as the
 * mid-span vertical of a sagged span galloping in its symmetric mode), the fundamental between
 * bins: the band-limited envelope must drop the harmonic, so that it is flat within 3% once steady
 * and the time to steady is found within 2 s. With the cut at 2 f_d the harmonic's line is split
 * and half kept: the envelope ripples at f_d by ~+-25% and the steady band swallows the whole
 * record (time to steady 0 s; the soft-torsion span at 40 elements, BENCHMARKS.md, helper forty). */
static void test_time_to_steady_harmonic(void)
{
    double dt = 0.05, f = 0.3766, As = 1.1, tc = 80, tau = 15, T = 400;
    size_t n = (size_t)(T / dt);
    double *x = malloc(n * sizeof *x), *env = malloc(n * sizeof *env);
    for (size_t j = 0; j < n; j++) {
        double t = j * dt, A = As / (1 + exp(-(t - tc) / tau));
        x[j] = A * (sin(2 * PI * f * t) + 0.35 * sin(4 * PI * f * t + 0.4));
    }
    gal_hilbert *h = gal_spectrum_hilbert_alloc(n);
    CHECK(h != NULL, "%s", gal_error_message());
    CHECK(gal_spectrum_envelope(h, x, GAL_SPECTRUM_ENVELOPE_BAND, env) == GAL_OK, "%s", gal_error_message());
    double ripple = 0, ts, level, want = tc + tau * log(19.0);
    for (size_t j = (size_t)(250 / dt); j < n - n / 50; j++) ripple = fmax(ripple, fabs(env[j] / As - 1));
    CHECK(gal_spectrum_steady_time(env, n, dt, 0.05, &ts, &level) == GAL_OK, "%s", gal_error_message());
    printf("    with a 35%% second harmonic: envelope ripple %.4f once steady, time to steady %.2f s (true "
           "%.2f s), level %.4f (true %.4f)\n", ripple, ts, want, level, As);
    CHECK(ripple < 0.03, "ripple %g", ripple);
    CHECK_NEAR(ts, want, 2.0);
    CHECK_REL(level, As, 0.01);
    gal_spectrum_hilbert_free(h);
    free(x);
    free(env);
}

/* A tilted elliptic orbit: semi-axes within 1%, tilt within 0.5 deg, for several tilts. */
static void test_orbit_ellipse(void)
{
    size_t n = 10000;
    double dt = 0.01, f = 0.9, a = 1.2, b = 0.35;
    double tilts[] = {30, -55, 90, 0, 89.5, -12};
    double *y = malloc(n * sizeof *y), *z = malloc(n * sizeof *z);
    for (size_t q = 0; q < sizeof tilts / sizeof tilts[0]; q++) {
        double ph = tilts[q] * PI / 180;
        for (size_t j = 0; j < n; j++) {
            double c = cos(2 * PI * f * j * dt), s = sin(2 * PI * f * j * dt);
            y[j] = 0.1 + a * cos(ph) * c - b * sin(ph) * s;
            z[j] = -2.0 + a * sin(ph) * c + b * cos(ph) * s;
        }
        gal_orbit o;
        CHECK(gal_spectrum_orbit(y, z, n, &o) == GAL_OK, "%s", gal_error_message());
        CHECK_REL(o.major, a, 0.01);
        CHECK_REL(o.minor, b, 0.01);
        CHECK_NEAR(o.tilt_deg, tilts[q], 0.5);
        CHECK(o.tilt_deg > -90 && o.tilt_deg <= 90, "tilt %g in (-90, 90]", o.tilt_deg);
    }
    /* a straight vertical line: minor 0, tilt 90 */
    for (size_t j = 0; j < n; j++) y[j] = 0, z[j] = sin(2 * PI * f * j * dt);
    gal_orbit o;
    CHECK(gal_spectrum_orbit(y, z, n, &o) == GAL_OK, "status");
    CHECK_NEAR(o.minor, 0, 1e-12);
    CHECK_NEAR(o.tilt_deg, 90, 1e-9);
    free(y);
    free(z);
}

/* A constant record: no crash, zero RMS, no frequency; envelope gives no steady time. */
static void test_constant_record(void)
{
    size_t n = 512;
    double *x = malloc(n * sizeof *x), *env = malloc(n * sizeof *env);
    for (size_t j = 0; j < n; j++) x[j] = 1.1;
    gal_measures m;
    double df;
    CHECK(measure(x, n, 0.1, &m, &df) == GAL_OK, "%s", gal_error_message());
    CHECK(m.rms == 0, "rms %g", m.rms);
    CHECK(m.npeaks == 0, "no peaks, got %zu", m.npeaks);
    CHECK(isnan(m.frequency), "frequency %g must be NaN", m.frequency);
    gal_hilbert *h = gal_spectrum_hilbert_alloc(n);
    CHECK(gal_spectrum_envelope(h, x, 0, env) == GAL_OK, "status");
    double ts;
    CHECK(gal_spectrum_steady_time(env, n, 0.1, 0.05, &ts, NULL) == GAL_OK, "status");
    CHECK(isnan(ts), "no steady time for a constant record, got %g", ts);
    gal_spectrum_hilbert_free(h);
    free(x);
    free(env);
}

/* Bad arguments: short records, bad step, tiny segments. */
static void test_bad_arguments(void)
{
    double x[32] = {0};
    CHECK(gal_spectrum_welch_alloc(4) == NULL, "segment of 4 must be refused");
    CHECK(gal_spectrum_hilbert_alloc(8) == NULL, "envelope of 8 samples must be refused");
    gal_welch *w = gal_spectrum_welch_alloc(64);
    double psd[33];
    CHECK(gal_spectrum_psd(w, x, 32, 0.1, psd, NULL, NULL) == GAL_EINPUT, "n < nseg");
    CHECK(gal_spectrum_psd(w, x, 32, 0.0, psd, NULL, NULL) == GAL_EINPUT, "dt = 0");
    gal_spectrum_welch_free(w);
    CHECK(gal_spectrum_welch_free(NULL) == NULL, "free(NULL)");
    CHECK(gal_spectrum_hilbert_free(NULL) == NULL, "free(NULL)");
    CHECK(gal_trace_free(NULL) == NULL, "free(NULL)");
}

/* ---- CSV traces ---- */

static char tmpdir[64];

static char *write_file(const char *name, const char *text)
{
    char *p = gal_path_join(tmpdir, name);
    FILE *fp = fopen(p, "w");
    fputs(text, fp);
    fclose(fp);
    return p;
}

/* Reading `text` must fail with `status` and a message holding each of the given strings. */
static void expect_error(const char *text, int status, const char *want1, const char *want2)
{
    char *p = write_file("bad.csv", text);
    gal_trace *tr = (gal_trace *)1;
    int st = gal_trace_read(p, &tr);
    const char *msg = gal_error_message();
    CHECK(st == status, "status %d, want %d (%s)", st, status, msg);
    CHECK(tr == NULL, "no trace on failure");
    CHECK(strstr(msg, p) != NULL, "message names the file: %s", msg);
    CHECK(!want1 || strstr(msg, want1), "message has '%s': %s", want1, msg);
    CHECK(!want2 || strstr(msg, want2), "message has '%s': %s", want2, msg);
    remove(p);
    free(p);
}

/* A good CSV with n rows, an optional defect inserted at row `bad` (text replaces the row). */
static char *csv(size_t n, size_t bad, const char *badrow, double jitter)
{
    size_t cap = 64 * (n + 4);
    char *s = malloc(cap), *e = s;
    e += sprintf(e, "# a comment\nprobe_y,time,probe_z\n");
    for (size_t k = 0; k < n; k++) {
        if (k == bad) e += sprintf(e, "%s\n", badrow);
        else e += sprintf(e, "%.6f,%.6f,%.6f\n", sin(0.3 * k), 0.05 * k + (k == 10 ? jitter : 0),
                          cos(0.3 * k));
    }
    return s;
}

static void test_trace_good(void)
{
    char *text = csv(40, 99, "", 0);
    char *p = write_file("good.csv", text);
    gal_trace *tr = NULL;
    CHECK(gal_trace_read(p, &tr) == GAL_OK, "%s", gal_error_message());
    if (tr) {
        CHECK(tr->n == 40 && tr->ncol == 2, "n %zu ncol %zu", tr->n, tr->ncol);
        CHECK(!strcmp(tr->time_name, "time"), "time column is 'time', not the first");
        CHECK(gal_trace_column(tr, "probe_z") == 1, "probe_z is data column 1");
        CHECK(gal_trace_column(tr, "nope") == -1, "unknown column");
        CHECK_REL(tr->dt, 0.05, 1e-9);
        CHECK_NEAR(tr->x[1][3], cos(0.9), 1e-6);
    }
    tr = gal_trace_free(tr);
    remove(p);
    free(p);
    free(text);
}

static void test_trace_errors(void)
{
    char *p = gal_path_join(tmpdir, "missing.csv");
    gal_trace *tr;
    CHECK(gal_trace_read(p, &tr) == GAL_EIO, "missing file");
    CHECK(strstr(gal_error_message(), "missing.csv") != NULL, "%s", gal_error_message());
    free(p);
    expect_error("", GAL_EINPUT, "no header", NULL);
    expect_error("# only a comment\n\n", GAL_EINPUT, "no header", NULL);
    expect_error("0,1\n1,2\n", GAL_EINPUT, ":1:", "no header");
    expect_error("time,a,a\n", GAL_EINPUT, "'a' appears twice", NULL);
    expect_error("time,,b\n", GAL_EINPUT, "empty name", NULL);
    expect_error("time\n0\n", GAL_EINPUT, "data column", NULL);
    char *s;
    /* the data start on line 3 (comment, header): row k is on line k + 3 */
    s = csv(40, 5, "nan,0.25,1", 0);
    expect_error(s, GAL_EINPUT, ":8:", "'probe_y'");
    free(s);
    s = csv(40, 5, "0.1,0.25,inf", 0);
    expect_error(s, GAL_EINPUT, ":8:", "NaN or Inf");
    free(s);
    s = csv(40, 7, "0.1,0.35,abc", 0);
    expect_error(s, GAL_EINPUT, ":10:", "'abc' is not a number");
    free(s);
    s = csv(40, 7, "0.1,0.35", 0);
    expect_error(s, GAL_EINPUT, ":10:", "2 fields, the header has 3");
    free(s);
    s = csv(40, 7, "0.1,0.35,1,4", 0);
    expect_error(s, GAL_EINPUT, ":10:", "4 fields");
    free(s);
    s = csv(40, 7, "0.1, ,1", 0);
    expect_error(s, GAL_EINPUT, ":10:", "empty");
    free(s);
    s = csv(10, 99, "", 0);
    expect_error(s, GAL_EINPUT, "10 samples", "at least 16");
    free(s);
    s = csv(40, 7, "0.1,0.30,1", 0);   /* time 0.30 after 0.30: not increasing */
    expect_error(s, GAL_EINPUT, ":10:", "time must increase");
    free(s);
    s = csv(40, 99, "", 0.004);        /* one step 8% longer, the next 8% shorter */
    expect_error(s, GAL_EINPUT, "not uniform", "resample");
    free(s);
    expect_error("t,x\n\x01\x02\xff,zz\n", GAL_EINPUT, "not a number", NULL);
}

/* Nearly uniform sampling (rounding of printed times) is accepted. */
static void test_trace_nearly_uniform(void)
{
    char *s = csv(40, 99, "", 1e-6);
    char *p = write_file("near.csv", s);
    gal_trace *tr = NULL;
    CHECK(gal_trace_read(p, &tr) == GAL_OK, "%s", gal_error_message());
    gal_trace_free(tr);
    remove(p);
    free(p);
    free(s);
}

/* ---- the analysis of a whole trace (analysis/trace_spectrum.c) ---- */

/* An in-memory trace: orbit y = 1.5 a(t) cos(w t), z = -3 + 0.5 a(t) sin(w t) at f = 0.8 Hz,
 * a(t) a logistic rise to 1 about t = 15 s, and a constant column; 6000 samples at 0.01 s. */
#define TS_N 6000
static double ts_t[TS_N], ts_x[3][TS_N];
static double *ts_cols[3] = {ts_x[0], ts_x[1], ts_x[2]};
static char *ts_names[3] = {"mid_y", "mid_z", "flat"};
static gal_trace ts_tr = {TS_N, 3, ts_t, ts_cols, ts_names, "time", 0.01};

static void ts_fill(void)
{
    for (size_t k = 0; k < TS_N; k++) {
        double t = ts_t[k] = k * 0.01, a = 1 / (1 + exp(-(t - 15) / 2));
        ts_x[0][k] = 1.5 * a * cos(2 * PI * 0.8 * t);
        ts_x[1][k] = -3 + 0.5 * a * sin(2 * PI * 0.8 * t);
        ts_x[2][k] = 7;
    }
}

static void test_trace_spectrum_auto(void)
{
    ts_fill();
    int sel[3] = {0, 1, 2};
    gal_trace_pair pairs[6];
    size_t np = gal_trace_auto_pairs(&ts_tr, sel, 3, pairs);
    CHECK(np == 1 && pairs[0].y == 0 && pairs[0].z == 1, "%zu pairs", np);
    gal_trace_spectrum s;
    int st = gal_trace_spectrum_run(&ts_tr, sel, 3, pairs, np, NAN, 0, &s);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (st) { gal_trace_spectrum_clear(&s); return; }
    /* the envelope is within 5% of 1 once a(t) > 0.95: t > 15 + 2 ln 19 = 20.9 s */
    CHECK(s.auto_from && fabs(ts_t[s.i0] - 20.9) < 1.5, "steady from %g s, want about 20.9", ts_t[s.i0]);
    CHECK(fabs(s.tss[0] - 20.9) < 1.5 && fabs(s.tss[1] - 20.9) < 1.5, "times to steady %g %g", s.tss[0], s.tss[1]);
    CHECK(isnan(s.tss[2]) && isnan(s.m[2].frequency) && s.m[2].npeaks == 0, "constant column");
    CHECK_REL(s.m[0].frequency, 0.8, 1e-4);
    CHECK_REL(s.m[1].frequency, 0.8, 1e-4);
    CHECK_REL(s.m[0].amplitude, 1.5, 1e-2);
    CHECK_REL(s.m[1].amplitude, 0.5, 1e-2);
    CHECK_NEAR(s.m[1].mean, -3, 1e-2);
    CHECK(s.nseg == gal_spectrum_segment_choose(TS_N - s.i0) && s.nf == s.nseg / 2 + 1, "segment %zu", s.nseg);
    CHECK_REL(s.df, 1 / (s.nseg * 0.01), 1e-12);
    CHECK(s.nsegments == (TS_N - s.i0 - s.nseg) / (s.nseg / 2) + 1 && !s.coarse, "%zu segments", s.nsegments);
    double var = 0; /* Parseval: the PSD integrates to the variance of the steady part, 1.5^2 / 2 */
    for (size_t k = 0; k < s.nf; k++) var += s.psd[k] * s.df;
    CHECK_REL(var, 1.125, 0.05);
    /* orbit: semi-axes 1.5 (horizontal) and 0.5, not tilted (up to the end of the window) */
    CHECK_REL(s.pairs[0].orbit.major, 1.5, 2e-2);
    CHECK_REL(s.pairs[0].orbit.minor, 0.5, 2e-2);
    CHECK(fabs(s.pairs[0].orbit.tilt_deg) < 1, "tilt %g deg", s.pairs[0].orbit.tilt_deg);
    gal_trace_spectrum_clear(&s);
}

static void test_trace_spectrum_options(void)
{
    ts_fill();
    int sel[1] = {1};
    gal_trace_spectrum s;
    int st = gal_trace_spectrum_run(&ts_tr, sel, 1, NULL, 0, 30.004, 1024, &s);
    CHECK(st == GAL_OK && !s.auto_from && s.i0 == 3001 && s.nseg == 1024 && s.npairs == 0, "from 30.004 s: "
          "sample %zu, segment %zu", s.i0, s.nseg);
    gal_trace_spectrum_clear(&s);
    st = gal_trace_spectrum_run(&ts_tr, sel, 1, NULL, 0, 0, 16, &s);
    CHECK(st == GAL_OK && s.i0 == 0 && s.coarse, "a 16-sample segment on 6000 samples is coarse");
    gal_trace_spectrum_clear(&s);
    st = gal_trace_spectrum_run(&ts_tr, sel, 1, NULL, 0, 60, 0, &s);
    CHECK(st == GAL_EINPUT && strstr(gal_error_message(), "--from 60"), "from past the end: %s", gal_error_message());
    gal_trace_spectrum_clear(&s);
    st = gal_trace_spectrum_run(&ts_tr, sel, 1, NULL, 0, 59.95, 0, &s);
    CHECK(st == GAL_EINPUT && strstr(gal_error_message(), "at least 16"), "5 samples: %s", gal_error_message());
    gal_trace_spectrum_clear(&s);
    st = gal_trace_spectrum_run(&ts_tr, sel, 1, NULL, 0, 50, 2048, &s);
    CHECK(st == GAL_EINPUT && strstr(gal_error_message(), "--segment 2048"), "long segment: %s", gal_error_message());
    gal_trace_spectrum_clear(&s);
}

static void test_trace_auto_pairs(void)
{
    char *names[6] = {"a_y", "b_horizontal", "a_z", "b_vertical", "c_y", "a_zz"};
    gal_trace tr = {0};
    tr.ncol = 6, tr.names = names;
    int sel[6] = {0, 1, 2, 3, 4, 5};
    gal_trace_pair p[12];
    size_t n = gal_trace_auto_pairs(&tr, sel, 6, p);
    CHECK(n == 2 && p[0].y == 0 && p[0].z == 2 && p[1].y == 1 && p[1].z == 3, "%zu pairs", n);
    CHECK(gal_trace_auto_pairs(&tr, sel, 2, p) == 0, "only among the selected columns");
}

/* issue 14: stationary noisy multi-line traces. Two lines (0.4227 Hz, amplitude 1, and 0.45 Hz
 * at half of it: they beat every 36.6 s) in white noise over 600 s: the automatic rule calls it
 * steady from the start (not near the end), the whole record is analysed, both lines are
 * reported with their amplitudes, and no noise peak is (10 dB above the local floor). A sine in
 * noise likewise; pure noise gives no peak. */
#define ML_N 12000
static double ml_t[ML_N], ml_x[3][ML_N];
static double *ml_cols[3] = {ml_x[0], ml_x[1], ml_x[2]};
static char *ml_names[3] = {"two_lines", "sine_noise", "noise"};
static gal_trace ml_tr = {ML_N, 3, ml_t, ml_cols, ml_names, "time", 0.05};

static void test_noisy_multiline(void)
{
    rng_state = 4242;
    for (size_t k = 0; k < ML_N; k++) {
        double t = ml_t[k] = k * 0.05;
        ml_x[0][k] = sin(2 * PI * 0.4227 * t) + 0.5 * sin(2 * PI * 0.45 * t + 1) + 0.3 * nrand();
        ml_x[1][k] = 2 + 0.8 * cos(2 * PI * 1.3 * t) + 0.5 * nrand();
        ml_x[2][k] = 0.7 * nrand();
    }
    int sel[3] = {0, 1, 2};
    gal_trace_spectrum s;
    int st = gal_trace_spectrum_run(&ml_tr, sel, 3, NULL, 0, NAN, 0, &s);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (st) { gal_trace_spectrum_clear(&s); return; }
    printf("    steady from %g s; times to steady %g %g %g s\n", ml_t[s.i0], s.tss[0], s.tss[1], s.tss[2]);
    CHECK(s.tss[0] < 60 && s.tss[1] < 60, "stationary traces steady near the start: %g %g s", s.tss[0], s.tss[1]);
    CHECK(ml_t[s.i0] < 60, "the analysis starts at %g s, not in the second half", ml_t[s.i0]);
    const gal_measures *m = &s.m[0];
    int f1 = -1, f2 = -1;
    for (size_t q = 0; q < m->npeaks; q++) {
        printf("    two lines: peak %zu at %.5f Hz, amplitude %.4f\n", q, m->peaks[q].frequency, m->peaks[q].amplitude);
        if (fabs(m->peaks[q].frequency - 0.4227) < 0.002) f1 = (int)q;
        else if (fabs(m->peaks[q].frequency - 0.45) < 0.002) f2 = (int)q;
    }
    CHECK(f1 == 0, "the 0.4227 Hz line is the dominant one (%d)", f1);
    CHECK(f2 >= 0, "the 0.45 Hz line at half amplitude is reported");
    if (f1 >= 0) CHECK_REL(m->peaks[f1].amplitude, 1.0, 0.05);
    if (f2 >= 0) CHECK_REL(m->peaks[f2].amplitude, 0.5, 0.05);
    CHECK(m->npeaks == 2, "%zu peaks: only the two lines stand above the noise", m->npeaks);
    CHECK(s.m[1].npeaks == 1 && fabs(s.m[1].frequency - 1.3) < 1e-3, "sine in noise: %zu peaks, %g Hz",
          s.m[1].npeaks, s.m[1].frequency);
    CHECK_REL(s.m[1].amplitude, 0.8, 0.05);
    CHECK(s.m[2].npeaks == 0, "pure noise: %zu peaks (%g Hz)", s.m[2].npeaks, s.m[2].frequency);
    gal_trace_spectrum_clear(&s);
}

/* The local noise floor is the median of the PSD around the bin (a line does not raise it). */
static void test_noise_floor(void)
{
    double psd[201], scratch[2 * 16 + 1];
    for (int k = 0; k < 201; k++) psd[k] = 1.0 + 0.01 * (k % 3);
    psd[100] = 1e6, psd[99] = psd[101] = 1e3;
    double fl = gal_spectrum_noise_floor(psd, 201, 100, scratch);
    CHECK(fl >= 1.0 && fl <= 1.02, "floor %g", fl);
}

/* issue 14: the one-sided factor: 2 inside, 1 at DC and (even segment) Nyquist. With one segment
 * Parseval's identity for the windowed record is exact: sum(PSD) df = sum w^2 (x - mean)^2 / sum
 * w^2, for any signal; a drift puts power at DC, a tone at the Nyquist frequency at the last bin. */
static void test_one_sided_edges(void)
{
    size_t n = 256;
    double dt = 0.1, x[256], psd[129], df, w2 = 0, e = 0, mean = 0;
    rng_state = 777;
    for (size_t j = 0; j < n; j++) x[j] = 0.5 * nrand() + 0.02 * (double)j + ((j % 2) ? -1.0 : 1.0);
    for (size_t j = 0; j < n; j++) mean += x[j] / (double)n;
    for (size_t j = 0; j < n; j++) {
        double wj = 0.5 - 0.5 * cos(2 * PI * (double)j / (double)n);
        w2 += wj * wj, e += wj * wj * (x[j] - mean) * (x[j] - mean);
    }
    gal_welch *w = gal_spectrum_welch_alloc(n);
    CHECK(w && gal_spectrum_psd(w, x, n, dt, psd, &df, NULL) == GAL_OK, "%s", gal_error_message());
    double sum = 0;
    for (size_t k = 0; k < 129; k++) sum += psd[k] * df;
    CHECK_REL(sum, e / w2, 1e-12);
    CHECK(psd[0] * df > 1e-6 * sum && psd[128] * df > 1e-3 * sum, "power at DC %g and Nyquist %g", psd[0], psd[128]);
    gal_spectrum_welch_free(w);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/gallop_spectrum_XXXXXX");
    if (!mkdtemp(tmpdir)) return 1;
    RUN(test_segment_choose);
    RUN(test_pure_sine_between_bins);
    RUN(test_sine_sweep);
    RUN(test_two_sines);
    RUN(test_fundamental);
    RUN(test_white_noise_parseval);
    RUN(test_time_to_steady);
    RUN(test_time_to_steady_harmonic);
    RUN(test_orbit_ellipse);
    RUN(test_constant_record);
    RUN(test_bad_arguments);
    RUN(test_trace_good);
    RUN(test_trace_errors);
    RUN(test_trace_nearly_uniform);
    RUN(test_trace_spectrum_auto);
    RUN(test_trace_spectrum_options);
    RUN(test_trace_auto_pairs);
    RUN(test_noisy_multiline);
    RUN(test_noise_floor);
    RUN(test_one_sided_edges);
    rmdir(tmpdir);
    return CHECK_SUMMARY();
}
