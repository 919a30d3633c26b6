/* test_windstats.c: the points and moments `gallop wind` reports (analysis/windstats.c). The field
 * is a sum of cosines at f_m = m / (M dt) over one period M dt: the record mean of u is 0 and its
 * mean square is sum_m S(f_m) df |B_j|^2 exactly, with |B_0| = 1 (and |B_j| = 1 at every point
 * under full coherence), i.e. the discrete variance of gal_wind_variance. */
#include "check.h"
#include "gallop.h"
#include "gallop/analysis/windstats.h"

static gal_wind *field(double coherence_decay)
{
    gal_wind_params p;
    gal_wind_params_default(&p);
    p.speed = 12, p.intensity = 0.15, p.points = GAL_WINDFIELD_POINTS, p.spacing = 200.0 / (p.points - 1);
    p.duration = 120, p.time_step = 0.05, p.coherence_decay = coherence_decay, p.seed = 7;
    gal_wind *w = gal_wind_alloc(&p);
    if (w && gal_wind_generate(w)) w = gal_wind_free(w);
    return w;
}

static void test_points(void)
{
    gal_wind *w = field(10);
    CHECK(w != NULL, "%s", gal_error_message());
    if (!w) return;
    gal_wind_stats s;
    CHECK(gal_wind_stats_compute(w, 12, 200, 5, &s) == GAL_OK && s.np == 5, "5 points");
    int want[5] = {0, 16, 32, 48, 64};
    for (int i = 0; i < 5; i++) CHECK(s.pt[i] == want[i], "point %d at %d, want %d", i, s.pt[i], want[i]);
    CHECK(gal_wind_stats_compute(w, 12, 200, 1, &s) == GAL_OK && s.np == 1 && s.pt[0] == 32, "one point: mid-span");
    CHECK(gal_wind_stats_compute(w, 12, 200, 3, &s) == GAL_OK && s.pt[1] == 32 && s.pt[2] == 64, "three points");
    CHECK(gal_wind_stats_compute(w, 12, 200, 0, &s) == GAL_EINPUT, "0 points refused");
    CHECK(gal_wind_stats_compute(w, 12, 200, GAL_WINDFIELD_POINTS + 1, &s) == GAL_EINPUT, "66 points refused");
    /* between the field's points: linear, at x = 50 m on a 3.125 m grid after a 190 m span */
    CHECK(gal_wind_stats_compute(w, 12, 190, 5, &s) == GAL_OK, "%s", gal_error_message());
    CHECK(s.pt[1] == 15 && fabs(s.frac[1] - (47.5 / 3.125 - 15)) < 1e-12 && s.x[4] == 190, "x = 47.5 between 15, 16");
    CHECK_NEAR(gal_wind_stats_u(w, &s, 1, 7), 0.8 * gal_wind_u(w, 15, 7) + 0.2 * gal_wind_u(w, 16, 7), 1e-12);
    gal_wind_free(w);
}

/* point 0: mean U, standard deviation sqrt(discrete variance), to rounding */
static void test_moments_exact(void)
{
    gal_wind *w = field(10);
    if (!w) { CHECK(0, "%s", gal_error_message()); return; }
    gal_wind_stats s;
    CHECK(gal_wind_stats_compute(w, 12, 200, 65, &s) == GAL_OK, "%s", gal_error_message());
    double sigma = sqrt(gal_wind_variance(w));
    CHECK(sigma > 0.5 && sigma < 1.8, "discrete sigma %g against I U = 1.8", sigma);
    CHECK_NEAR(s.mean[0], 12, 1e-12 * 12);
    CHECK_REL(s.sd[0], sigma, 1e-9);
    /* the other points: the mean is U to rounding; the sd against a direct one-pass sum */
    int n = gal_wind_samples(w);
    for (int i = 1; i < 65; i += 21) {
        long double a = 0, b = 0;
        for (int k = 0; k < n; k++) a += gal_wind_u(w, s.pt[i], k), b += (long double)gal_wind_u(w, s.pt[i], k) * gal_wind_u(w, s.pt[i], k);
        double mu = (double)(a / n), sd = sqrt((double)(b / n) - mu * mu);
        CHECK_NEAR(s.mean[i], 12 + mu, 1e-12 * 12);
        CHECK_NEAR(mu, 0, 1e-9);
        CHECK_REL(s.sd[i], sd, 1e-9);
    }
    gal_wind_free(w);
}

/* full coherence: the same history everywhere, every sd the discrete sigma */
static void test_full_coherence(void)
{
    gal_wind *w = field(0);
    if (!w) { CHECK(0, "%s", gal_error_message()); return; }
    gal_wind_stats s;
    CHECK(gal_wind_stats_compute(w, 12, 200, 5, &s) == GAL_OK, "%s", gal_error_message());
    double sigma = sqrt(gal_wind_variance(w));
    for (int i = 0; i < 5; i++) CHECK_REL(s.sd[i], sigma, 1e-9);
    gal_wind_free(w);
}

int main(void)
{
    RUN(test_points);
    RUN(test_moments_exact);
    RUN(test_full_coherence);
    return CHECK_SUMMARY();
}
