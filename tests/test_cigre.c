/* test_cigre.c: the CIGRE TB 322 outputs (analysis/cigre.c): the galloping ellipse of a sampled
 * tilted ellipse (axes, tilt, centre exact), the clearance to a point against closed forms (a
 * circle, points on the axes, inside negative), the empirical envelope's formula, the tensions. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "gallop/analysis/cigre.h"
#include "gallop/base/core.h"

#define N 2000

/* y, z of an ellipse with semi-axes a, b, tilt th (rad), centre (cy, cz), whole periods */
static void sample(double a, double b, double th, double cy, double cz, double *y, double *z)
{
    for (int i = 0; i < N; i++) {
        double t = 2 * GAL_PI * 5 * i / N, u = a * cos(t), v = b * sin(t);
        y[i] = cy + cos(th) * u - sin(th) * v;
        z[i] = cz + sin(th) * u + cos(th) * v;
    }
}

static void test_ellipse_of_a_tilted_ellipse(void)
{
    double y[N], z[N];
    sample(3.0, 1.0, 30 * GAL_PI / 180, 0.4, -0.2, y, z);
    gal_ellipse e;
    CHECK(gal_cigre_ellipse(y, z, N, &e) == GAL_OK, "ellipse");
    CHECK_REL(e.major_pp, 6.0, 1e-6);
    CHECK_REL(e.minor_pp, 2.0, 1e-6);
    CHECK_NEAR(e.tilt_deg, 30.0, 1e-6);
    CHECK_NEAR(e.centre_y, 0.4, 1e-9);
    CHECK_NEAR(e.centre_z, -0.2, 1e-9);
}

static void test_clearance(void)
{
    gal_ellipse c = {4.0, 4.0, 0.0, 1.0, 1.0};   /* a circle of radius 2 about (1, 1) */
    CHECK_NEAR(gal_cigre_clearance(&c, 1.0, 6.0), 3.0, 1e-9);
    CHECK_NEAR(gal_cigre_clearance(&c, 1.0 + 3 / sqrt(2), 1.0 + 3 / sqrt(2)), 1.0, 1e-9);
    CHECK_NEAR(gal_cigre_clearance(&c, 1.5, 1.0), -1.5, 1e-9);   /* inside: negative */
    /* a vertical ellipse (tilt 90): semi-axes 3 (vertical) and 1, centred at 0 */
    gal_ellipse v = {6.0, 2.0, 90.0, 0.0, 0.0};
    CHECK_NEAR(gal_cigre_clearance(&v, 0.0, -8.0), 5.0, 1e-9);   /* below, on the major axis */
    CHECK_NEAR(gal_cigre_clearance(&v, 7.0, 0.0), 6.0, 1e-9);    /* beside, on the minor axis */
    /* an off-axis point: the nearest boundary point satisfies the normal condition; check by
     * brute force over 10^6 boundary points */
    gal_ellipse t = {5.0, 1.6, 20.0, 0.3, -0.1};
    double py = 2.9, pz = 2.2, best = INFINITY, th = 20 * GAL_PI / 180;
    for (int k = 0; k < 1000000; k++) {
        double s = 2 * GAL_PI * k / 1e6, u = 2.5 * cos(s), w = 0.8 * sin(s);
        double by = 0.3 + cos(th) * u - sin(th) * w, bz = -0.1 + sin(th) * u + cos(th) * w;
        best = fmin(best, hypot(py - by, pz - bz));
    }
    CHECK_NEAR(gal_cigre_clearance(&t, py, pz), best, 1e-6);
}

static void test_envelope(void)
{
    /* 300 m of Drake (28.1 mm): A = 80 D ln(L / (500 D)) */
    double D = 0.0281, L = 300;
    CHECK_REL(gal_cigre_envelope_single(L, D), 80 * D * log(L / (500 * D)), 1e-12);
    CHECK_NEAR(gal_cigre_envelope_single(10, D), 0.0, 0);   /* below L = 500 D: none */
    CHECK(isnan(gal_cigre_envelope_single(0, D)), "no span: NaN");
}

static void test_tensions(void)
{
    double T[8] = {100, 101, 120, 90, 80, 130, 100, 100};
    gal_tension_range t;
    gal_cigre_tensions(T, 4, 1000, &t);
    CHECK_NEAR(t.min_n, 80, 0);
    CHECK_NEAR(t.max_n, 130, 0);
    CHECK_NEAR(t.static_n, 101, 0);
    CHECK_REL(t.max_over_static, 130.0 / 101, 1e-15);
    CHECK_REL(t.max_over_rts, 0.13, 1e-15);
    gal_cigre_tensions(T, 4, NAN, &t);
    CHECK(isnan(t.max_over_rts), "no rated strength: NaN");
}

int main(void)
{
    RUN(test_ellipse_of_a_tilted_ellipse);
    RUN(test_clearance);
    RUN(test_envelope);
    RUN(test_tensions);
    return CHECK_SUMMARY();
}
