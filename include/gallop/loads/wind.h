/* wind.h: stochastic along-wind turbulence u(x_j, t) (or its vertical component w) at uniformly spaced points along a span
 * (DESIGN.md "Wind"), by the spectral representation method (Shinozuka & Deodatis 1991,
 * Deodatis 1996) with FFTW; seeded (GSL mt19937) and reproducible.
 *
 * The generator produces zero-mean fluctuations u_j(t_k), j = 0..points-1 at x_j = j dx,
 * t_k = k dt, k = 0..samples-1; the mean speed U is added by the caller (U + u).
 *
 * ---- Target one-sided spectra S(f) (m^2/s^2/Hz), f in Hz, sigma = I U, each normalized so that
 *      integral_0^inf S(f) df = sigma^2 ----
 * Kaimal (IEC 61400-1 form of Kaimal et al. 1972):
 *     f S(f) / sigma^2 = 4 n / (1 + 6 n)^(5/3),        n = f L / U,
 *     L = 8.1 Lambda, Lambda = 0.7 min(z, 60 m)  (z = 10 m: L = 56.7 m).
 * Davenport (1961), height-independent:
 *     f S(f) / sigma^2 = (2/3) x^2 / (1 + x^2)^(4/3),   x = f L / U,   L = 1200 m.
 *     (Davenport's f S / (kappa U10^2) = 4 x^2 / (1 + x^2)^(4/3) with sigma^2 = 6 kappa U10^2.)
 * von Karman (1948), along-wind:
 *     f S(f) / sigma^2 = 4 n / (1 + 70.8 n^2)^(5/6),    n = f L / U,
 *     L = 3.5 Lambda, Lambda = 0.7 min(z, 60 m)  (IEC 61400-1 ed. 2; z = 10 m: L = 24.5 m).
 * EN 1991-1-4 Annex B (Eq. B.2), the spectrum EN 50341-1 takes for conductors:
 *     f S(f) / sigma^2 = 6.8 n / (1 + 10.2 n)^(5/3),    n = f L / U,
 *     L = 300 m (z / 200 m)^0.52 (Eq. B.1 for terrain II, z0 = 0.05 m; a scene with a terrain
 *     gives its own L through length_scale: gallop/scene/terrain.h).
 * A length_scale > 0 in the parameters replaces the default L.
 *
 * ---- The vertical component w (component = GAL_WIND_VERTICAL; intensity is then sigma_w / U) ----
 * kaimal, davenport, en1991: the Kaimal w-component of IEC 61400-1 (ed. 3, Annex C, Table C.1:
 *     sigma_3 = 0.5 sigma_1, L_3 = 0.66 Lambda):
 *     f S_w(f) / sigma_w^2 = 4 n / (1 + 6 n)^(5/3),    n = f L_w / U,   L_w = 0.66 Lambda
 *     (z = 10 m: L_w = 4.62 m). Davenport (1961) and EN 1991-1-4 give no vertical spectrum: the
 *     IEC Kaimal w-component stands in for them.
 * von_karman: the transverse von Karman form (von Karman 1948; as in ESDU 85020 and IEC 61400-1
 *     ed. 2 Annex B):
 *     f S_w(f) / sigma_w^2 = 4 n (1 + 755.2 n^2) / (1 + 283.2 n^2)^(11/6),   n = f L_w / U,
 *     with 283.2 = 4 x 70.8 and 755.2 = (8/3) 283.2 (the along-wind form's constant), and
 *     L_w = L_u / 2 (isotropic turbulence: the transverse integral scale is half the
 *     longitudinal one), L_u = 3.5 Lambda (z = 10 m: L_w = 12.25 m).
 * A length_scale > 0 replaces L_w. The w field uses the same coherence form with its own decay C
 * and is statistically independent of u (the u-w cross-spectrum, the Reynolds stress, is left
 * out).
 *
 * ---- Coherence between two points dx apart (Davenport): coh(f) = exp(-C f dx / U) ----
 * For uniform spacing the coherence matrix Gamma_jk = r^|j-k|, r = exp(-C f dx / U), is that of an
 * AR(1) process (Kac-Murdock-Szego matrix). Its Cholesky factor is analytic:
 *     L_j0 = r^j,  L_jk = r^(j-k) sqrt(1 - r^2) (1 <= k <= j),  0 above the diagonal,
 * so the correlated complex amplitudes B_j = sum_k L_jk xi_k (xi_k = exp(i phi_k), phi_k uniform
 * in [0, 2 pi)) follow the recursion B_0 = xi_0, B_j = r B_(j-1) + sqrt(1 - r^2) xi_j: O(points)
 * per frequency. The history at point j is
 *     u_j(t) = sum_{m=1}^{M/2-1} sqrt(2 S(f_m) df) Re[B_j(f_m) exp(i 2 pi f_m t)],
 *     f_m = m df, df = 1 / (M dt), M = samples,
 * computed by one complex-to-real FFT of length M per point (plans made once). The record is
 * periodic with period M dt; frequencies below df and above the Nyquist f_N = 1/(2 dt) are not
 * represented (their share of sigma^2 is missing: see gal_wind_variance). Single-indexed
 * frequencies (the 1991 form, not Deodatis' 1996 double indexing): each point's history has
 * exactly the target spectrum's amplitudes in expectation; C = 0 gives full coherence (the same
 * history at every point, the single-point case). */
#ifndef GALLOP_WIND_H
#define GALLOP_WIND_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Which velocity component a generator makes (the spectra above). */
typedef enum { GAL_WIND_ALONG = 0, GAL_WIND_VERTICAL = 1 } gal_wind_component;

/* Values match gal_turbulence in scene.h (GAL_TURB_KAIMAL = 1, ...). */
typedef enum {
    GAL_WIND_KAIMAL = 1,
    GAL_WIND_DAVENPORT = 2,
    GAL_WIND_VON_KARMAN = 3,
    GAL_WIND_EN1991 = 4
} gal_wind_spectrum;

typedef struct gal_wind_params {
    double speed;           /* m/s, mean wind speed U normal to the span, > 0 */
    double intensity;       /* -, turbulence intensity I = sigma_u / U, in [0, 1] */
    gal_wind_spectrum spectrum;
    double height;          /* m, reference height z (Kaimal, von Karman), > 0; default 10 */
    double length_scale;    /* m, L of the spectrum (see above); 0 = the default for the spectrum */
    double coherence_decay; /* -, C in exp(-C f dx / U), >= 0; default 10 */
    int points;             /* count of points along the span, >= 1 */
    double spacing;         /* m, dx between neighbouring points, > 0 when points > 1 */
    double duration;        /* s, T: samples = round(T / dt) >= 16 */
    double time_step;       /* s, dt > 0 */
    unsigned long seed;     /* GSL mt19937 seed: same seed, same field */
    gal_wind_component component; /* along-wind u (default) or vertical w: the spectrum's form */
} gal_wind_params;

typedef struct gal_wind gal_wind;

/* Defaults: U = 10 m/s, I = 0.1, Kaimal, z = 10 m, L default, C = 10, 1 point, dx = 1 m,
 * T = 600 s, dt = 0.05 s, seed 1, the along-wind component. */
void gal_wind_params_default(gal_wind_params *p);

/* Check parameters: GAL_OK or GAL_EINPUT with a message naming the field, value and range. */
int gal_wind_params_check(const gal_wind_params *p);

/* One-sided target PSD S(f) (m^2/s^2/Hz) at f (Hz) for these parameters (0 for f <= 0). */
double gal_wind_psd(const gal_wind_params *p, double f);
/* The length scale L (m) that the spectrum uses (the default when p->length_scale is 0). */
double gal_wind_length_scale(const gal_wind_params *p);
/* Target coherence exp(-C f dx / U) at frequency f (Hz) for a separation dx (m). */
double gal_wind_coherence(const gal_wind_params *p, double f, double dx);

/* Create a generator (validates p; NULL with a message on bad parameters or no memory). FFTW
 * plans and all work arrays are made here; the FFTW planner is not thread-safe, so create
 * generators from one thread. */
gal_wind *gal_wind_alloc(const gal_wind_params *p);
/* Generate the field (seeded from p->seed each call: calling twice gives the same field). */
int gal_wind_generate(gal_wind *w);
/* Free; accepts NULL; returns NULL. */
gal_wind *gal_wind_free(gal_wind *w);

int gal_wind_points(const gal_wind *w);
int gal_wind_samples(const gal_wind *w);        /* M */
double gal_wind_time_step(const gal_wind *w);   /* s */
double gal_wind_spacing(const gal_wind *w);     /* m */
/* Fluctuation u (m/s) at point j, sample k (t = k dt); k is taken modulo M (periodic record). */
double gal_wind_u(const gal_wind *w, int j, long k);
/* The history at point j: M samples (m/s), or NULL if j is out of range. */
const double *gal_wind_history(const gal_wind *w, int j);
/* Fluctuation at point j and any time t (s), linear between samples, periodic in M dt. */
double gal_wind_u_at(const gal_wind *w, int j, double t);
/* Variance the discrete spectrum carries, sum_m S(f_m) df (m^2/s^2): the expected variance of
 * every history; sigma^2 minus what lies below df and above the Nyquist frequency. */
double gal_wind_variance(const gal_wind *w);

#ifdef __cplusplus
}
#endif

#endif
