/* spectrum.h: spectral analysis of sampled traces (DESIGN.md "Spectra and galloping measures"):
 * Welch power spectral density, dominant peaks with sub-bin frequency, amplitude measures, the
 * orbit ellipse of a probe, the Hilbert envelope and the time to steady galloping, and reading
 * traces from CSV files. Works on any uniformly sampled record `x[0..n)` with step `dt` (s).
 *
 * Lifecycle: gal_spectrum_welch_alloc (plans the segment FFT once) -> gal_spectrum_psd /
 * gal_spectrum_measure for every column -> gal_spectrum_welch_free. The same for the envelope:
 * gal_spectrum_hilbert_alloc(n) -> gal_spectrum_envelope for every column -> _free. */
#ifndef GALLOP_SPECTRUM_H
#define GALLOP_SPECTRUM_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ======================================================================================
 * Traces: CSV with a header line of column names, '#' comment lines and blank lines allowed.
 * The time column is the one named `time`, `t` or `time_s` (any case), else the first column.
 * ====================================================================================== */

#define GAL_TRACE_MIN_SAMPLES 16   /* fewer samples: GAL_EINPUT */
#define GAL_TRACE_DT_SPREAD 1e-3   /* (max dt - min dt) / mean dt above this: not uniform, GAL_EINPUT */

typedef struct gal_trace {
    size_t n;          /* samples */
    size_t ncol;       /* data columns (the time column excluded) */
    double *t;         /* n times, s */
    double **x;        /* ncol columns of n values each */
    char **names;      /* ncol column names */
    char *time_name;   /* name of the time column */
    double dt;         /* uniform step (t[n-1] - t[0]) / (n - 1), s */
} gal_trace;

/* Read a trace. GAL_EIO when the file cannot be opened; GAL_EINPUT, with a message naming the
 * file, line and column, for: no header, an empty or duplicate name, a wrong number of fields, a
 * non-numeric field, NaN or Inf, fewer than GAL_TRACE_MIN_SAMPLES rows, no data column,
 * non-increasing time, or a time step that is not uniform (reports min and max dt). */
int gal_trace_read(const char *path, gal_trace **trace);
gal_trace *gal_trace_free(gal_trace *tr);
/* Index of the data column called `name`, or -1. */
int gal_trace_column(const gal_trace *tr, const char *name);

/* ======================================================================================
 * Welch power spectral density.
 * Convention: one-sided density in unit^2/Hz on the bins f_k = k df, df = 1/(nseg dt),
 * k = 0..nseg/2; periodic Hann window w_j = 0.5 - 0.5 cos(2 pi j / nseg); segments of nseg
 * samples with 50% overlap (step nseg/2; samples past the last whole segment are not used),
 * each with its own mean removed; averaged periodograms
 *     P_k = c_k |sum_j w_j x_j exp(-2 pi i j k / nseg)|^2 / (fs sum_j w_j^2),  fs = 1/dt,
 * c_k = 1 at k = 0 and at the Nyquist bin, 2 elsewhere. Hence sum_k P_k df equals the
 * window-weighted mean square of the (segment-centred) record: the variance (Parseval).
 * ====================================================================================== */

typedef struct gal_welch gal_welch;   /* workspace: window, buffers and the FFTW plan */

/* Segment length chosen for n samples: the largest power of two that gives at least 8
 * segments, but at least 256 when n >= 256, and the largest power of two <= n when n < 256. */
size_t gal_spectrum_segment_choose(size_t n);
/* Workspace for segments of nseg >= 8 samples (any length). NULL on failure (message set). */
gal_welch *gal_spectrum_welch_alloc(size_t nseg);
gal_welch *gal_spectrum_welch_free(gal_welch *w);
size_t gal_spectrum_welch_segment(const gal_welch *w);   /* nseg */
size_t gal_spectrum_welch_nfreq(const gal_welch *w);     /* nseg/2 + 1 bins */

/* PSD of x[0..n), n >= nseg, into psd[0..nfreq); df (Hz) and the number of segments averaged
 * are returned through the pointers when not NULL. GAL_EINPUT for n < nseg, dt <= 0 or a
 * non-finite sample. */
int gal_spectrum_psd(gal_welch *w, const double *x, size_t n, double dt, double *psd, double *df,
                     size_t *nsegments);

/* ======================================================================================
 * Peaks, amplitudes, orbit.
 * ====================================================================================== */

#define GAL_SPECTRUM_MAX_PEAKS 8
#define GAL_SPECTRUM_PEAK_FLOOR 1e-4   /* peaks below this fraction of the largest PSD are dropped */
/* A peak counts only where its PSD stands this factor (10 dB) above the local noise floor: the
 * median of the PSD over +-max(GAL_SPECTRUM_FLOOR_HALFWIDTH, nfreq/16) bins around it. White
 * noise alone exceeds it rarely: about one bin in a thousand for a single Welch segment, far
 * fewer with the usual 8 or more segments averaged. */
#define GAL_SPECTRUM_PEAK_SNR 10.0
#define GAL_SPECTRUM_FLOOR_HALFWIDTH 16
/* The local noise floor of psd at bin k (the median above); scratch holds 2 max(16, nfreq/16) + 1. */
double gal_spectrum_noise_floor(const double *psd, size_t nfreq, size_t k, double *scratch);

typedef struct gal_peak {
    double frequency;   /* Hz, refined below the bin width (see gal_spectrum_refine) */
    double amplitude;   /* amplitude of a sine at that frequency, unit of x */
    double psd;         /* Welch PSD at the peak bin, unit^2/Hz */
    size_t bin;         /* Welch bin of the local maximum */
} gal_peak;

/* Sub-bin frequency and amplitude of a spectral line near f0 (Hz): maximises the modulus of the
 * Hann-windowed discrete-time Fourier transform of the whole centred record,
 *     X(f) = sum_j w_j (x_j - mean) exp(-2 pi i f j dt),  w_j = 0.5 - 0.5 cos(2 pi j / n),
 * over [f0 - halfwidth, f0 + halfwidth] (a grid of half record bins 1/(2 n dt), then golden
 * section), and returns amplitude = 2 |X(f)| / sum_j w_j, exact for a pure sine up to the
 * leakage of other lines. No allocation; costs about 40 + min(4 halfwidth n dt, 513) passes
 * over x (the grid is capped at 513 points, coarser than half a record bin when halfwidth is
 * more than 128 record bins, i.e. for a Welch segment shorter than n/200). */
int gal_spectrum_refine(const double *x, size_t n, double dt, double f0, double halfwidth,
                        double *f, double *amplitude);

/* The (at most kmax <= GAL_SPECTRUM_MAX_PEAKS) largest local maxima of psd[1..nfreq-1) above
 * GAL_SPECTRUM_PEAK_FLOOR times the largest and GAL_SPECTRUM_PEAK_SNR times the local noise
 * floor, in decreasing PSD, each refined by
 * gal_spectrum_refine on x[0..n) within +-0.6 df. *npeaks may be 0 (e.g. a constant record). */
int gal_spectrum_peaks(const double *psd, size_t nfreq, double df, const double *x, size_t n,
                       double dt, size_t kmax, gal_peak *peaks, size_t *npeaks);

/* The fundamental of a periodic trace: a galloping orbit of period 1/f0 puts its power on f0 and
 * its harmonics, and where the second harmonic is the stronger line (twist and horizontal motion,
 * which follow the tension's 2f; a probe near a node of the first harmonic) the largest peak is 2f,
 * and which of the two lines is the larger flips between two runs that agree. The fundamental is
 * the lowest significant line (a peak of gal_spectrum_peaks: 10 dB above the local noise floor) of
 * at least GAL_SPECTRUM_FUNDAMENTAL_AMP times the dominant line's amplitude of which the dominant
 * line is the n-th harmonic, 2 <= n <= GAL_SPECTRUM_MAX_HARMONIC, within GAL_SPECTRUM_HARMONIC_TOL
 * (relative: a transient's lines are a few tenths of a per cent off the exact ratio); else the
 * dominant line itself (n = 1). A line under 5% of the dominant amplitude changes successive crests
 * by under a tenth: the remainder of a transient or another mode's small share, not the period of
 * the trace; a lower line that is no subharmonic of the dominant one is another mode. */
#define GAL_SPECTRUM_FUNDAMENTAL_AMP 0.05
#define GAL_SPECTRUM_MAX_HARMONIC 4
#define GAL_SPECTRUM_HARMONIC_TOL 0.02
/* The fundamental of the peaks pk[0..np) (pk[0] the dominant one): its frequency in *f0 and the
 * dominant line's harmonic order in *order (NaN and 0 when np = 0). */
void gal_spectrum_fundamental(const gal_peak *pk, size_t np, double *f0, int *order);

/* The measures of one column over a steady part x[0..n). */
typedef struct gal_measures {
    double mean;          /* unit of x */
    double rms;           /* RMS of x - mean */
    double peak_to_peak;  /* max - min */
    double frequency;     /* dominant frequency, Hz: peaks[0], or with npeaks = 0 the largest local
                           * maximum of the PSD (not significant); NaN for a constant record */
    double amplitude;     /* spectral amplitude of the dominant sine; NaN when none */
    double fundamental;   /* Hz, gal_spectrum_fundamental of the peaks (the dominant frequency when
                           * npeaks = 0; NaN for a constant record) */
    int harmonic;         /* the dominant line's order as a harmonic of the fundamental (1: it is) */
    size_t npeaks;
    gal_peak peaks[GAL_SPECTRUM_MAX_PEAKS];   /* peaks[0] is the dominant one */
} gal_measures;

/* All measures of x[0..n) (n >= the workspace's nseg); the PSD goes to psd[0..nfreq) when psd is
 * not NULL. A record with rms <= 1e-13 (|mean| + 1e-300) is constant: no peaks, NaN frequency. */
int gal_spectrum_measure(gal_welch *w, const double *x, size_t n, double dt, size_t kmax,
                         double *psd, gal_measures *m);

/* Orbit ellipse of a probe from its horizontal (y) and vertical (z) displacements: principal
 * axes of the covariance C of the centred pair, semi-axes sqrt(2 lambda) (exact for a
 * sinusoidal orbit over whole periods), major >= minor, tilt of the major axis from the
 * horizontal in degrees, in (-90, 90], positive towards +z: tilt = atan2(2 Cyz, Cyy - Czz) / 2. */
typedef struct gal_orbit {
    double major;      /* semi-axis, unit of y and z */
    double minor;      /* semi-axis */
    double tilt_deg;   /* deg */
} gal_orbit;
int gal_spectrum_orbit(const double *y, const double *z, size_t n, gal_orbit *o);

/* ======================================================================================
 * Envelope and time to steady galloping.
 * ====================================================================================== */

#define GAL_SPECTRUM_ENVELOPE_BAND 1.5

typedef struct gal_hilbert gal_hilbert;   /* workspace: buffers and the FFTW plans for n */

gal_hilbert *gal_spectrum_hilbert_alloc(size_t n);   /* n >= GAL_TRACE_MIN_SAMPLES */
gal_hilbert *gal_spectrum_hilbert_free(gal_hilbert *h);

/* env[j] = |x_j - mean + i H[x - mean]_j|, the modulus of the analytic signal (FFT-based
 * Hilbert transform); all zeros for a constant record. Edge guard: before the transform the
 * record is continued by n/4 samples past each end by reflection, x(r) = x(2c - r), about the
 * centre c within n/8 samples of that end about which the record is most symmetric (over
 * min(n/16, 64) samples; for an oscillation: a crest or trough, found to a fraction of a sample),
 * so that an oscillation continues smoothly (a steady sine: envelope error ~1e-8 at the ends).
 * Reflecting about the end sample itself would leave a kink whose error decays like 1/distance.
 * band > 0 keeps only the frequencies 0 < f < band f_d, f_d the largest bin of the (extended)
 * record's spectrum, so that broadband noise and harmonics do not ripple the envelope of the
 * dominant oscillation (band = 1.5 is GAL_SPECTRUM_ENVELOPE_BAND: halfway to the second harmonic,
 * whose line a cut at 2 f_d would split and half keep, rippling the envelope at f_d by up to the
 * harmonic's share; the soft-torsion span at 40 elements, BENCHMARKS.md, helper forty);
 * band <= 0 keeps every frequency. */
int gal_spectrum_envelope(gal_hilbert *h, const double *x, double band, double *env);

/* Time to steady: final level L = median of env over the last 20% of the record, sigma = 1.4826
 * times the median absolute deviation from L there (the envelope's own fluctuation: noise,
 * beating lines), the band L +- max(tol L, 5 sigma) (tol = 0.05 for the usual 5%). *t_steady
 * (s, from the first sample) is the first time the envelope reaches the band, or later the time
 * after its last rise above it (an overshoot), judged up to the end guard (the last 2% of the
 * record, where the envelope is least reliable). A stationary record is steady from the start
 * (0); a growing one from when its envelope reaches the band. *t_steady = NaN when L = 0
 * (constant record). When the tail still trends (the means of its two halves differ by more
 * than max(2 tol L, 2 sigma), or its mean and that of the 20% before it by more than 2 tol L:
 * not steady yet), the start of the tail: the record's last 20%.
 * *level (may be NULL) receives L. */
int gal_spectrum_steady_time(const double *env, size_t n, double dt, double tol, double *t_steady,
                             double *level);

#ifdef __cplusplus
}
#endif

#endif
