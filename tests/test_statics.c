/* test_statics.c: the elastic catenary, and the rod's equilibrium against it (H and sag within
 * 0.1% for small EI), for every way of specifying a span, level and inclined. */
#include "check.h"
#include "gallop.h"
#include "gallop/statics/catenary.h"
#include "gallop/statics/statics.h"

/* ACSR Drake-like conductor on a 300 m span */
static gal_rod_params drake(double L, double h, int nel)
{
    gal_rod_params p = {.length = L, .height_difference = h, .elements = nel, .EA = 2.9e7 * 1.0,
                        .EI = 20.0, .GJ = 150, .mass = 1.628, .polar_inertia = 1.6e-4,
                        .gravity = 9.80665, .torsion = 1, .twist_clamped = 1};
    return p;
}

/* The catenary closes on its supports and reproduces a given H, sag or L0 from the others. */
static void test_catenary_roundtrip(void)
{
    gal_catenary c = {.L = 300, .h = 40, .w = 1.628 * 9.80665, .EA = 2.9e7};
    CHECK(gal_catenary_solve(&c, 0, 28000) == GAL_OK, "%s", gal_error_message());
    double x, z;
    gal_catenary_point(&c, c.L0, &x, &z, NULL);
    CHECK_NEAR(x, 300, 1e-9);
    CHECK_NEAR(z, 40, 1e-9);
    double sag = gal_catenary_sag(&c), L0 = c.L0;
    gal_catenary c2 = {.L = 300, .h = 40, .w = 1.628 * 9.80665, .EA = 2.9e7};
    CHECK(gal_catenary_solve(&c2, 1, sag) == GAL_OK, "%s", gal_error_message());
    CHECK_REL(c2.H, 28000, 1e-9);
    gal_catenary c3 = {.L = 300, .h = 40, .w = 1.628 * 9.80665, .EA = 2.9e7};
    CHECK(gal_catenary_solve(&c3, 2, L0) == GAL_OK, "%s", gal_error_message());
    CHECK_REL(c3.H, 28000, 1e-8);
    /* shallow cable: sag close to the parabola w L^2 / (8 H) */
    CHECK_REL(sag, 1.628 * 9.80665 * 300 * 300 / (8 * 28000) * sqrt(1 + (40.0 / 300) * (40.0 / 300)), 0.01);
}

static void check_equilibrium(double h, gal_statics_spec spec, double EI)
{
    gal_rod_params p = drake(300, h, 100);
    p.EI = EI;
    gal_catenary c = {.L = 300, .h = h, .w = p.mass * p.gravity, .EA = p.EA};
    gal_catenary_solve(&c, 0, 28000);
    double value = spec == GAL_BY_TENSION ? 28000 : spec == GAL_BY_SAG ? gal_catenary_sag(&c) : c.L0;
    gal_equilibrium eq;
    int st = gal_statics_solve(&p, spec, value, NULL, &eq);
    CHECK(st == GAL_OK, "statics: %s", gal_error_message());
    if (st) return;
    printf("    (h %g, spec %d: H %.6g N, sag %.6g m vs catenary %.6g N, %.6g m; %d Newton, %d L0 "
           "iterations, %.2f ms)\n", h, spec, eq.horizontal_tension, eq.sag, c.H, gal_catenary_sag(&c),
           eq.newton_iterations, eq.length_iterations, 1e3 * eq.wall_time_s);
    /* Against the continuous elastic catenary (Irvine 1981), an independent reference: at 100
     * elements the discrete rod's unstretched length for a given H is 1.2e-7 (relative) off it (its
     * O(h^2) discretization error, measured), so by tension or sag H and sag agree to 1e-7; by
     * length that error on L0 - chord (0.3 m) moves H and sag by 3.6e-5. Tolerances ~3x that. */
    double tol = spec == GAL_BY_LENGTH ? 1e-4 : 5e-7;
    CHECK_REL(eq.horizontal_tension, c.H, tol);
    CHECK_REL(eq.sag, gal_catenary_sag(&c), tol);
    CHECK_REL(eq.unstretched_length, c.L0, 4e-7);
    if (spec == GAL_BY_TENSION) CHECK_REL(eq.horizontal_tension, 28000, 1e-9);
    if (spec == GAL_BY_SAG) CHECK_REL(eq.sag, value, 1e-8);
    /* the equilibrium is planar and untwisted */
    double ymax = 0;
    for (int k = 0; k < eq.rod->nq; k++)
        if (k >= 3 * eq.rod->nn || k % 3 == 1) ymax = fmax(ymax, fabs(eq.q[k]));
    CHECK(ymax < 1e-9, "out-of-plane or twist %g", ymax);
    gal_equilibrium_clear(&eq);
}

static void test_level_by_tension(void) { check_equilibrium(0, GAL_BY_TENSION, 20); }
static void test_level_by_sag(void) { check_equilibrium(0, GAL_BY_SAG, 20); }
static void test_level_by_length(void) { check_equilibrium(0, GAL_BY_LENGTH, 20); }
static void test_inclined_by_tension(void) { check_equilibrium(60, GAL_BY_TENSION, 20); }
static void test_inclined_by_sag(void) { check_equilibrium(60, GAL_BY_SAG, 20); }
static void test_inclined_by_length(void) { check_equilibrium(-60, GAL_BY_LENGTH, 20); }
static void test_cable_no_bending(void) { check_equilibrium(30, GAL_BY_TENSION, 0); }

/* A taut span (issue 14): a 300 m Drake span at 42 kN (30 % of its rated strength) has an
 * unstretched length shorter than the chord (the elastic stretch exceeds the sag's extra length).
 * Given that length the rod finds the same H and sag as given the tension, and the catenary agrees. */
static void test_taut_by_length(void)
{
    gal_rod_params p = drake(300, 0, 100);
    p.EA = 3.73e7;
    gal_equilibrium et, el;
    CHECK(gal_statics_solve(&p, GAL_BY_TENSION, 42000, NULL, &et) == GAL_OK, "%s", gal_error_message());
    double L0 = et.unstretched_length;
    CHECK(L0 < 300 && L0 > 299.8, "L0 %.6f m is not below the chord", L0);
    CHECK(gal_statics_solve(&p, GAL_BY_LENGTH, L0, NULL, &el) == GAL_OK, "%s", gal_error_message());
    gal_catenary c = {.L = 300, .h = 0, .w = p.mass * p.gravity, .EA = p.EA};
    CHECK(gal_catenary_solve(&c, 2, L0) == GAL_OK, "%s", gal_error_message());
    printf("    (L0 %.6f m: by tension H %.8g N sag %.8g m, by length H %.8g N sag %.8g m, catenary "
           "%.8g N %.8g m)\n", L0, et.horizontal_tension, et.sag, el.horizontal_tension, el.sag, c.H,
           gal_catenary_sag(&c));
    /* the same discrete rod: to the statics tolerance; the continuous catenary: to the rod's
     * O(h^2) discretization (1.2e-7 on L0, amplified by EA / H on a taut span) */
    CHECK_REL(el.horizontal_tension, 42000, 1e-7);
    CHECK_REL(el.sag, et.sag, 1e-7);
    CHECK_REL(c.H, 42000, 1e-4);
    CHECK_REL(gal_catenary_sag(&c), el.sag, 1e-4);
    gal_equilibrium_clear(&et);
    gal_equilibrium_clear(&el);
}

/* Without gravity the span is a straight line under the given tension. */
static void test_no_gravity(void)
{
    gal_rod_params p = drake(100, 10, 20);
    p.gravity = 0;
    gal_equilibrium eq;
    CHECK(gal_statics_solve(&p, GAL_BY_TENSION, 5000, NULL, &eq) == GAL_OK, "%s", gal_error_message());
    CHECK_REL(eq.horizontal_tension, 5000, 1e-9);
    CHECK_NEAR(eq.sag, 0, 1e-9);
    gal_equilibrium_clear(&eq);
    CHECK(gal_statics_solve(&p, GAL_BY_SAG, 1.0, NULL, &eq) == GAL_EINPUT, "sag without gravity");
}

/* Eccentric ice: its weight twists the span. With the ice centre level with the axis (no pendulum
 * stiffness at zero twist) the moment per length is m_i g e and a clamped span twists at mid-span
 * by m_i g e L0^2 / (8 GJ) (a string under uniform load). */
static void test_eccentric_ice_twist(void)
{
    gal_rod_params p = drake(200, 0, 100);
    p.GJ = 3e4, p.ecc_mass = 0.6, p.ecc = 0.01, p.ecc_angle = 0; /* along the reference director (y) */
    p.mass += p.ecc_mass;
    gal_equilibrium eq;
    CHECK(gal_statics_solve(&p, GAL_BY_TENSION, 28000, NULL, &eq) == GAL_OK, "%s", gal_error_message());
    int nel = eq.rod->p.elements;
    double th = 0.5 * (eq.q[3 * eq.rod->nn + nel / 2 - 1] + eq.q[3 * eq.rod->nn + nel / 2]);
    double L0 = eq.unstretched_length, want = p.ecc_mass * p.gravity * p.ecc * L0 * L0 / (8 * p.GJ);
    printf("    (mid-span twist %.6g rad, string under uniform moment %.6g rad)\n", th, want);
    CHECK_REL(fabs(th), want, 2e-3); /* achieved 5.4e-4 at 100 elements */
    gal_equilibrium_clear(&eq);
}

int main(void)
{
    RUN(test_catenary_roundtrip);
    RUN(test_level_by_tension);
    RUN(test_level_by_sag);
    RUN(test_level_by_length);
    RUN(test_inclined_by_tension);
    RUN(test_inclined_by_sag);
    RUN(test_inclined_by_length);
    RUN(test_cable_no_bending);
    RUN(test_taut_by_length);
    RUN(test_no_gravity);
    RUN(test_eccentric_ice_twist);
    return CHECK_SUMMARY();
}
