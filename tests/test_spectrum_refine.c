/* test_spectrum_refine.c: gal_spectrum_refine (four frequencies a pass over the record, two golden
 * iterations a pass) against the refinement one frequency a pass, bit for bit. */
#include "check.h"
#include "gallop.h"

#include <stdint.h>

/* A fixed-seed normal generator (xorshift64* and Box-Muller): reproducible records. */
static uint64_t rng_state = 88172645463325252ull;
static double urand(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 2685821657736338717ull) >> 11) * (1.0 / 9007199254740992.0);
}
static double nrand(void)
{
    double u = urand(), v = urand();
    return sqrt(-2 * log(u + 1e-300)) * cos(2 * GAL_PI * v);
}

/* The sub-bin refinement as it was written first, one frequency a pass over the record (the grid,
 * then the golden section): gal_spectrum_refine evaluates four frequencies a pass and two golden
 * iterations a pass, and must give these numbers bit for bit. */
static double ref_dtft2(const double *x, size_t n, double dt, double mean, double f, double *wsum)
{
    double om = 2 * GAL_PI * f * dt, th = 2 * GAL_PI / (double)n;
    double cr = cos(om), sr = -sin(om), ct = cos(th), st = sin(th), re = 0, im = 0, ws = 0;
    for (size_t j0 = 0; j0 < n; j0 += 1024) {
        double zr = cos(om * (double)j0), zi = -sin(om * (double)j0);
        double ur = cos(th * (double)j0), ui = sin(th * (double)j0);
        size_t j1 = j0 + 1024 < n ? j0 + 1024 : n;
        for (size_t j = j0; j < j1; j++) {
            double wj = 0.5 - 0.5 * ur, v = wj * (x[j] - mean);
            re += v * zr, im += v * zi, ws += wj;
            double t = zr * cr - zi * sr;
            zi = zr * sr + zi * cr, zr = t;
            t = ur * ct - ui * st;
            ui = ur * st + ui * ct, ur = t;
        }
    }
    if (wsum) *wsum = ws;
    return re * re + im * im;
}

static void ref_refine(const double *x, size_t n, double dt, double f0, double hw, double *f, double *amp)
{
    double mean = 0;
    for (size_t j = 0; j < n; j++) mean += (x[j] - mean) / (double)(j + 1);
    double h = 0.5 / ((double)n * dt), lo = f0 - hw, hi = f0 + hw;
    if (lo < 0) lo = 0;
    if (hi > 0.5 / dt) hi = 0.5 / dt;
    size_t ng = (size_t)ceil((hi - lo) / h) + 1;
    if (ng > 513) ng = 513, h = (hi - lo) / 512;
    double best = -1, fb = f0;
    for (size_t g = 0; g < ng; g++) {
        double fg = lo + (hi - lo) * (ng > 1 ? (double)g / (double)(ng - 1) : 0.5);
        double p = ref_dtft2(x, n, dt, mean, fg, NULL);
        if (p > best) best = p, fb = fg;
    }
    double a = fb - h, b = fb + h, gr = 0.5 * (sqrt(5.0) - 1);
    if (a < lo) a = lo;
    if (b > hi) b = hi;
    double c = b - gr * (b - a), d = a + gr * (b - a);
    double pc = ref_dtft2(x, n, dt, mean, c, NULL), pd = ref_dtft2(x, n, dt, mean, d, NULL);
    for (int it = 0; it < 60 && (b - a) > 1e-9 * h; it++) {
        if (pc >= pd) b = d, d = c, pd = pc, c = b - gr * (b - a), pc = ref_dtft2(x, n, dt, mean, c, NULL);
        else a = c, c = d, pc = pd, d = a + gr * (b - a), pd = ref_dtft2(x, n, dt, mean, d, NULL);
    }
    double fr = 0.5 * (a + b), ws, p = ref_dtft2(x, n, dt, mean, fr, &ws);
    if (p < best) fr = fb, p = ref_dtft2(x, n, dt, mean, fr, &ws);
    *f = fr, *amp = 2 * sqrt(p) / ws;
}

static void test_refine_bitwise(void)
{
    static double x[5000];
    const size_t ns[] = {64, 1023, 1024, 2500, 5000};
    int same = 0, cases = 0;
    for (int c = 0; c < 5; c++) {
        size_t n = ns[c];
        double dt = 0.05;
        for (size_t j = 0; j < n; j++)
            x[j] = 1.5 + sin(2 * GAL_PI * (0.37 + 0.011 * c) * (double)j * dt) + 0.4 * sin(2 * GAL_PI * 1.21 * (double)j * dt + 0.3) +
                   0.05 * nrand();
        /* f0 between bins, at 0 (the range's low edge), at Nyquist, and a wide range (the grid's
         * 513-point cap) */
        const double f0s[] = {0.37 + 0.011 * c, 1.2, 0.0, 10.0, 3.0}, hws[] = {0.05, 0.02, 0.1, 0.3, 2.5};
        for (int q = 0; q < 5; q++) {
            double f1, a1, f2, a2;
            CHECK(gal_spectrum_refine(x, n, dt, f0s[q], hws[q], &f1, &a1) == GAL_OK, "%s", gal_error_message());
            ref_refine(x, n, dt, f0s[q], hws[q], &f2, &a2);
            cases++;
            if (memcmp(&f1, &f2, sizeof f1) == 0 && memcmp(&a1, &a2, sizeof a1) == 0) same++;
            else printf("    n %zu, f0 %g: %.17g %.17g against %.17g %.17g\n", n, f0s[q], f1, a1, f2, a2);
        }
    }
    CHECK(same == cases, "%d of %d refinements equal the one-point-a-pass reference bit for bit", same, cases);
}

int main(void)
{
    RUN(test_refine_bitwise);
    return CHECK_SUMMARY();
}
