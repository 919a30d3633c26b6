/* test_numfmt.c: output/numfmt.c writes "%.9g" and "%d" exactly as snprintf does: over many
 * doubles spread over every decade, near powers of ten, near ties, signed zero, subnormals,
 * infinities and NaN, and the integer extremes. */
#include "check.h"
#include "output/numfmt.h"

#include <float.h>
#include <limits.h>
#include <stdint.h>

static int same_g9(double x)
{
    char want[40], got[40];
    snprintf(want, sizeof want, "%.9g", x);
    int n = gal_fmt_g9(got, x);
    got[n] = 0;
    if (strcmp(want, got)) printf("    %.17g: printf %s, gal_fmt_g9 %s\n", x, want, got);
    return !strcmp(want, got);
}

static uint64_t rng = 88172645463325252u;
static double next_unit(void)
{
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

static void test_g9_random(void)
{
    int bad = 0;
    for (int i = 0; i < 200000 && bad < 5; i++) {
        double x = (next_unit() - 0.5) * pow(10, -30 + 60 * next_unit());
        bad += !same_g9(x);
    }
    CHECK(bad == 0, "%d differ", bad);
}

static void test_g9_edges(void)
{
    int bad = 0;
    double special[] = {0.0, -0.0, 1, -1, 0.5, 1e-5, 1e-4, 9.9999999949999e-5, 123456789, 999999999.5, 999999999.4,
                        1e9, 1e22, 1e23, 1e-22, 1e-23, DBL_MAX, DBL_MIN, DBL_TRUE_MIN, INFINITY, -INFINITY, NAN,
                        0.1, 0.3, 2.5e-7, 1.00000000500000001, 1.0000000050000002, 0.123456789049999};
    for (size_t i = 0; i < sizeof special / sizeof *special; i++) bad += !same_g9(special[i]);
    for (int p = -30; p <= 30; p++) /* around each power of ten, and halfway cases of the 9th digit */
        for (int s = -3; s <= 3; s++) {
            double x = pow(10, p);
            for (int k = 0; k < abs(s); k++) x = nextafter(x, s > 0 ? INFINITY : 0);
            bad += !same_g9(x) + !same_g9(x * 1.0000000005) + !same_g9(x * 9.999999995);
        }
    CHECK(bad == 0, "%d differ", bad);
}

static void test_int(void)
{
    int v[] = {0, 1, -1, 9, 10, 12345, -99999, INT_MAX, INT_MIN}, bad = 0;
    for (size_t i = 0; i < sizeof v / sizeof *v; i++) {
        char want[16], got[16];
        snprintf(want, sizeof want, "%d", v[i]);
        int n = gal_fmt_int(got, v[i]);
        got[n] = 0;
        bad += strcmp(want, got) != 0;
    }
    CHECK(bad == 0, "%d differ", bad);
}

int main(void)
{
    RUN(test_g9_random);
    RUN(test_g9_edges);
    RUN(test_int);
    return CHECK_SUMMARY();
}
