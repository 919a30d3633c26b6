/* test_statics.c: the elastic catenary, and the rod's equilibrium against it (H and sag within
 * 0.1% for small EI), for every way of specifying a span, level and inclined. */
#include "check.h"
#include "gallop.h"
#include "gallop/statics/catenary.h"
#include "gallop/statics/statics.h"
#include "gallop/modes/modes.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

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

/* The sag iteration ends on a bracket as narrow as the doubles allow: every sag of a fine sweep
 * converges and is reproduced (a fixed absolute width on log H once left some sags unsolved). */
static void test_sag_sweep(void)
{
    int failed = 0;
    double worst = 0;
    for (int k = 0; k <= 400; k++) {
        double sag = 2 + 0.0125 * k;
        gal_catenary c = {.L = 300, .h = 0, .w = 1.9 * 9.80665, .EA = 3.3e7};
        if (gal_catenary_solve(&c, 1, sag) != GAL_OK) { failed++; continue; }
        worst = fmax(worst, fabs(gal_catenary_sag(&c) - sag) / sag);
    }
    CHECK(failed == 0, "%d of 401 sags did not converge", failed);
    CHECK(worst < 1e-9, "sag reproduced to %g", worst);
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

/* theta(L0) of GJ theta'' = -w sin(theta), theta(0) = 0, theta'(0) = p (RK4): the twist of a
 * string in torsion with the inverted pendulum of eccentric ice on top (U = w cos theta). */
static double shoot(double p, double k2, double L0, double *mid)
{
    int n = 20000;
    double h = L0 / n, th = 0, dth = p;
    for (int i = 0; i < n; i++) {
        double k1a = dth, k1b = -k2 * sin(th);
        double k2a = dth + 0.5 * h * k1b, k2b = -k2 * sin(th + 0.5 * h * k1a);
        double k3a = dth + 0.5 * h * k2b, k3b = -k2 * sin(th + 0.5 * h * k2a);
        double k4a = dth + h * k3b, k4b = -k2 * sin(th + h * k3a);
        th += h / 6 * (k1a + 2 * k2a + 2 * k3a + k4a);
        dth += h / 6 * (k1b + 2 * k2b + 2 * k3b + k4b);
        if (i == n / 2 - 1) *mid = th;
    }
    return th;
}

/* Eccentric ice on top of a Falcon span (issue 14): an inverted pendulum. Weak (4 mm) the span
 * stays untwisted and stable; strong (20 and 50 mm) the untwisted equilibrium is unstable and
 * statics finds the twisted one the ice weight turns the span to (the mid-span twist of the
 * shooting solution of GJ theta'' = -m_i g e sin theta), where every mode has a positive
 * frequency; at the untwisted, unstable equilibrium the modes report lost stability instead of
 * a 0 Hz mode. */
static void check_ice_on_top(double e)
{
    gal_rod_params p = {.length = 200, .elements = 80, .EA = 6.88e7, .EI = 74.8, .GJ = 389,
                        .mass = 3.040 + 0.6, .polar_inertia = 5.851e-4 + 0.6 * (0.0196 * 0.0196 + e * e),
                        .gravity = 9.80665, .torsion = 1, .twist_clamped = 1, .ecc_mass = 0.6, .ecc = e,
                        .ecc_angle = GAL_PI / 2}; /* the ice centre straight above the axis */
    gal_equilibrium eq;
    int st = gal_statics_solve(&p, GAL_BY_TENSION, 40000, NULL, &eq);
    CHECK(st == GAL_OK, "e %g: %s", e, gal_error_message());
    if (st) return;
    int nn = eq.rod->nn, nel = p.elements;
    double th = 0.5 * (eq.q[3 * nn + nel / 2 - 1] + eq.q[3 * nn + nel / 2]);
    double k2 = p.ecc_mass * p.gravity * e / p.GJ, L0 = eq.unstretched_length, want = 0, mid = 0;
    if (k2 * L0 * L0 > GAL_PI * GAL_PI) { /* unstable untwisted: bisect on theta'(0) */
        double lo = 1e-6, hi = 4 * sqrt(k2);
        for (int it = 0; it < 100; it++) {
            double m = 0.5 * (lo + hi);
            if (shoot(m, k2, L0, &mid) < 0) lo = m; else hi = m;
        }
        shoot(lo, k2, L0, &want);
    }
    printf("    (e %g m: twisted %d, mid-span twist %.6g rad, shooting %.6g rad)\n", e, eq.twisted, th, want);
    CHECK(eq.twisted == (want != 0), "e %g: twisted %d", e, eq.twisted);
    CHECK_NEAR(fabs(th), want, 2e-3 * fmax(want, 1e-3));
    gal_modes md;
    int want_t[GAL_FAMILY_COUNT] = {1, 1, 2, 0};
    CHECK(gal_modes_find(eq.rod, eq.q, want_t, 200, &md) == GAL_OK, "modes: %s", gal_error_message());
    for (int k = 0; k < md.n; k++)
        CHECK(md.mode[k].frequency_hz > 0.2, "e %g: mode %d at %g Hz", e, k + 1, md.mode[k].frequency_hz);
    gal_modes_clear(&md);
    if (want != 0) { /* the untwisted equilibrium: lost stability, said so */
        double *q0 = malloc((size_t)eq.rod->nq * sizeof(double));
        memcpy(q0, eq.q, (size_t)eq.rod->nq * sizeof(double));
        for (int j = 0; j < nel; j++) q0[3 * nn + j] = 0;
        gal_rod_params p0 = eq.rod->p;
        gal_rod *r0 = gal_rod_alloc(&p0, q0);
        CHECK(gal_modes_solve(r0, q0, 10, &md) == GAL_EFAIL && strstr(gal_error_message(), "lost stability"),
              "modes at the untwisted equilibrium: %s", gal_error_message());
        gal_rod_free(r0);
        free(q0);
    }
    gal_equilibrium_clear(&eq);
}

static void test_ice_on_top(void)
{
    check_ice_on_top(0.004);
    check_ice_on_top(0.02);
    check_ice_on_top(0.05);
}

int main(void)
{
    RUN(test_catenary_roundtrip);
    RUN(test_sag_sweep);
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
    RUN(test_ice_on_top);
    return CHECK_SUMMARY();
}
