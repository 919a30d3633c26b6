/* test_stringing.c: the scene's equilibrium as a statics specification (src/model/stringing.c):
 * tension_rts, and the sag-tension change of state from a [stringing] condition against the
 * classic state-change cubic of a level parabolic span and against the exact catenary. */
#include "check.h"
#include "gallop/base/error.h"
#include "gallop/model/model.h"
#include "gallop/model/stringing.h"
#include "gallop/statics/catenary.h"

/* A level 300 m Drake-like span strung at 25 kN, 15 deg C. */
static gal_scene span(void)
{
    gal_scene sc;
    memset(&sc, 0, sizeof sc);
    strcpy(sc.path, "test.ini");
    sc.span.length = 300;
    sc.span.spec = GAL_SPEC_STRINGING;
    sc.stringing.present = 1;
    sc.stringing.temperature = 15;
    sc.stringing.horizontal_tension = 25000;
    sc.span.temperature = 15;
    sc.conductor.mass_per_length = 1.628;
    sc.conductor.axial_stiffness = 3.73e7;
    sc.conductor.thermal_expansion = 18.9e-6;
    sc.conductor.rated_strength = 1.3878e5;
    return sc;
}

/* The load case's horizontal tension: the catenary of unstretched length L0 under weight w2. */
static double load_case_H(const gal_scene *sc, double L0, double w2)
{
    gal_catenary c = {.L = sc->span.length, .h = sc->span.height_difference, .w = w2,
                      .EA = sc->conductor.axial_stiffness};
    int st = gal_catenary_solve(&c, 2, L0);
    CHECK(st == 0, "catenary by length: %d", st);
    return c.H;
}

/* The parabolic state-change cubic, H2^2 (H2 - H1 + EA w1^2 L^2/(24 H1^2) + EA alpha dT)
 * = EA w2^2 L^2 / 24, solved by bisection (its left side increases with H2 > 0). */
static double cubic_H2(double H1, double w1, double w2, double L, double EA, double adT)
{
    double K = -H1 + EA * w1 * w1 * L * L / (24 * H1 * H1) + EA * adT, R = EA * w2 * w2 * L * L / 24;
    double lo = 1, hi = 1e7;
    for (int i = 0; i < 200; i++) {
        double m = 0.5 * (lo + hi);
        if (m * m * (m + K) > R) hi = m;
        else lo = m;
    }
    return 0.5 * (lo + hi);
}

/* Same temperature, no ice: the change of state gives back the stringing tension exactly. */
static void test_round_trip(void)
{
    gal_scene sc = span();
    gal_statics_spec spec;
    double L0;
    CHECK(gal_stringing_spec(&sc, GAL_GRAVITY, &spec, &L0) == 0, "%s", gal_error_message());
    CHECK(spec == GAL_BY_LENGTH, "a length");
    CHECK_REL(load_case_H(&sc, L0, 1.628 * GAL_GRAVITY), 25000.0, 1e-9);
    /* by sag: the sag of that span gives the same length */
    gal_catenary c = {.L = 300, .w = 1.628 * GAL_GRAVITY, .EA = 3.73e7};
    gal_catenary_solve(&c, 0, 25000);
    sc.stringing.by_sag = 1, sc.stringing.sag = gal_catenary_sag(&c);
    double L0s;
    CHECK(gal_stringing_length(&sc, GAL_GRAVITY, &L0s) == 0, "%s", gal_error_message());
    CHECK_REL(L0s, L0, 1e-10);
}

/* Cold, hot and iced: against the parabolic cubic, within its approximation error (sag/L)^2. */
static void test_state_change_cubic(void)
{
    double w1 = 1.628 * GAL_GRAVITY;
    double cases[][2] = {{-5, 1.0}, {-20, 0.0}, {40, 0.0}, {0, 2.5}}; /* T2 (deg C), ice kg/m */
    for (int i = 0; i < 4; i++) {
        gal_scene sc = span();
        sc.span.temperature = cases[i][0];
        double L0, w2 = (1.628 + cases[i][1]) * GAL_GRAVITY;
        CHECK(gal_stringing_length(&sc, GAL_GRAVITY, &L0) == 0, "%s", gal_error_message());
        double H2 = load_case_H(&sc, L0, w2);
        double Hc = cubic_H2(25000, w1, w2, 300, 3.73e7, 18.9e-6 * (cases[i][0] - 15));
        double e = w2 * 300 / (8 * Hc);   /* sag / span of the parabola: its error ~ e^2 */
        CHECK_REL(H2, Hc, 2 * e * e);      /* here 0.013..0.097 % apart, 2 e^2 = 0.12..0.15 % */
        /* and the direction: colder or heavier is tighter, warmer is slacker */
        if (cases[i][0] < 15 || cases[i][1] > 0) CHECK(H2 > 25000, "tighter: %g", H2);
        else CHECK(H2 < 25000, "slacker: %g", H2);
    }
}

/* tension_rts: H = tension_rts RTS; the other specifications pass through. */
static void test_specs(void)
{
    gal_scene sc = span();
    gal_statics_spec spec;
    double v;
    sc.span.spec = GAL_SPEC_TENSION_RTS, sc.span.tension_rts = 0.2;
    CHECK(gal_stringing_spec(&sc, GAL_GRAVITY, &spec, &v) == 0 && spec == GAL_BY_TENSION, "rts");
    CHECK_REL(v, 0.2 * 1.3878e5, 1e-15);
    sc.span.spec = GAL_SPEC_SAG, sc.span.sag = 7;
    CHECK(gal_stringing_spec(&sc, GAL_GRAVITY, &spec, &v) == 0 && spec == GAL_BY_SAG && v == 7, "sag");
    sc.span.spec = GAL_SPEC_STRINGING, sc.stringing.by_sag = 1, sc.stringing.sag = 7;
    CHECK(gal_stringing_spec(&sc, 0.0, &spec, &v) != 0, "a sag without gravity has no solution");
}

int main(void)
{
    RUN(test_round_trip);
    RUN(test_state_change_cubic);
    RUN(test_specs);
    return CHECK_SUMMARY();
}
