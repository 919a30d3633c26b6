/* test_hard.c: hard cases of the statics and modes (issue 8): taut and slack spans, a steep
 * incline, a nearly inextensible and a bending-free conductor, tiny and huge torsional stiffness,
 * a very fine mesh, a stiff short rod far from the catenary. Each must converge and agree with
 * what it should, or fail with a reason. */
#include "check.h"
#include "gallop.h"
#include "gallop/modes/modes.h"
#include "gallop/statics/statics.h"

static gal_rod_params drake(void)
{
    gal_rod_params p = {.length = 300, .height_difference = 0, .elements = 100, .EA = 2.9e7, .EI = 28,
                        .GJ = 160, .mass = 1.628, .polar_inertia = 1.6e-4, .gravity = 9.80665,
                        .torsion = 1, .twist_clamped = 1};
    return p;
}

/* statics by `spec`, then against the catenary, then 10 modes all finite and positive */
static void run_case(const char *name, gal_rod_params p, gal_statics_spec spec, double value, double tol)
{
    gal_equilibrium eq;
    int st = gal_statics_solve(&p, spec, value, NULL, &eq);
    CHECK(st == GAL_OK, "%s: statics: %s", name, gal_error_message());
    if (st) return;
    CHECK_REL(eq.horizontal_tension, eq.cat.H, tol);
    CHECK_REL(eq.sag, gal_catenary_sag(&eq.cat), tol);
    gal_modes md;
    st = gal_modes_solve(eq.rod, eq.q, 10, &md);
    CHECK(st == GAL_OK, "%s: modes: %s", name, gal_error_message());
    if (!st) {
        /* free twist ends leave one rigid rotation about the axis: a torsional mode at 0 Hz */
        int k0 = 0;
        if (p.torsion && !p.twist_clamped) {
            CHECK(md.mode[0].family == GAL_FAMILY_TORSIONAL && md.mode[0].frequency_hz < 1e-3,
                  "%s: rigid rotation: %s at %g Hz", name, gal_family_names[md.mode[0].family], md.mode[0].frequency_hz);
            k0 = 1;
        }
        for (int k = k0; k < md.n; k++)
            CHECK(isfinite(md.mode[k].frequency_hz) && md.mode[k].frequency_hz > 0, "%s: mode %d: %g Hz", name,
                  k + 1, md.mode[k].frequency_hz);
        printf("    (%s: H %.6g N, sag %.5g m, %d Newton, %d load steps, f1 %.4f Hz, %.1f ms)\n", name,
               eq.horizontal_tension, eq.sag, eq.newton_iterations, eq.load_steps, md.mode[k0].frequency_hz,
               1e3 * (eq.wall_time_s + md.wall_time_s));
        gal_modes_clear(&md);
    }
    gal_equilibrium_clear(&eq);
}

static void test_taut_span(void) { run_case("taut, sag 0.5%", drake(), GAL_BY_SAG, 1.5, 1e-3); }
static void test_slack_span(void) { run_case("slack, sag 12%", drake(), GAL_BY_SAG, 36, 1e-3); }
static void test_steep_incline(void)
{
    gal_rod_params p = drake();
    p.height_difference = 100;
    run_case("inclined h = L/3", p, GAL_BY_TENSION, 28000, 1e-3);
    p.height_difference = -100;
    run_case("declined h = -L/3", p, GAL_BY_SAG, 10, 1e-3);
}
static void test_nearly_inextensible(void)
{
    gal_rod_params p = drake();
    p.EA = 1e10;
    run_case("EA 1e10", p, GAL_BY_TENSION, 28000, 1e-3);
}
static void test_no_bending(void)
{
    gal_rod_params p = drake();
    p.EI = 0;
    run_case("EI 0", p, GAL_BY_TENSION, 28000, 1e-3);
}
static void test_torsion_extremes(void)
{
    gal_rod_params p = drake();
    p.GJ = 1;
    run_case("GJ 1", p, GAL_BY_TENSION, 28000, 1e-3);
    p.GJ = 1e5;
    run_case("GJ 1e5", p, GAL_BY_TENSION, 28000, 1e-3);
    p.twist_clamped = 0;
    run_case("GJ 1e5, free twist", p, GAL_BY_TENSION, 28000, 1e-3);
}
static void test_fine_mesh(void)
{
    gal_rod_params p = drake();
    p.elements = 10000;
    run_case("10000 elements", p, GAL_BY_TENSION, 28000, 1e-3);
}
/* A short, stiff rod whose bending carries a good part of its weight: far from the catenary. */
static void test_stiff_short_rod(void)
{
    gal_rod_params p = drake();
    p.length = 10, p.EI = 2e4, p.elements = 40;
    gal_equilibrium eq;
    int st = gal_statics_solve(&p, GAL_BY_TENSION, 200, NULL, &eq);
    CHECK(st == GAL_OK, "statics: %s", gal_error_message());
    if (st) return;
    /* bending carries load: the sag is below the cable's */
    printf("    (stiff rod: sag %.4g m vs cable %.4g m, %d Newton, %d load steps)\n", eq.sag,
           gal_catenary_sag(&eq.cat), eq.newton_iterations, eq.load_steps);
    CHECK(eq.sag < gal_catenary_sag(&eq.cat), "bending must reduce the sag");
    CHECK_REL(eq.horizontal_tension, 200, 1e-8);
    gal_equilibrium_clear(&eq);
}

/* No equilibrium: a clear failure, not a crash. */
static void test_impossible_spans(void)
{
    gal_rod_params p = drake();
    gal_equilibrium eq;
    CHECK(gal_statics_solve(&p, GAL_BY_SAG, 200, NULL, &eq) == GAL_EINPUT, "sag beyond half the span");
    p.gravity = 0;
    CHECK(gal_statics_solve(&p, GAL_BY_LENGTH, 400, NULL, &eq) == GAL_EINPUT, "slack without gravity");
    CHECK(strstr(gal_error_message(), "unstretched_length") != NULL, "message names the key: %s", gal_error_message());
}

int main(void)
{
    RUN(test_taut_span);
    RUN(test_slack_span);
    RUN(test_steep_incline);
    RUN(test_nearly_inextensible);
    RUN(test_no_bending);
    RUN(test_torsion_extremes);
    RUN(test_fine_mesh);
    RUN(test_stiff_short_rod);
    RUN(test_impossible_spans);
    return CHECK_SUMMARY();
}
