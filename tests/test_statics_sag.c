/* test_statics_sag.c: spans given by their sag on fine meshes (issue 13): the outer iteration on
 * the unstretched length must meet the sag to 1e-10 of itself at 400-1000 elements, level and
 * inclined. Before the fix the inner Newton's force test could not see the small changes of L0 the
 * iteration asked for (they move the forces by less than its round-off floor, which grows with
 * the elements), so the sag read never moved and the iteration stopped after 30 steps. */
#include "check.h"
#include "gallop.h"
#include "gallop/statics/statics.h"

/* a bare ACSR conductor of data/conductors.csv: EA, EI, GJ, mass, polar inertia */
static gal_rod_params conductor(double EA, double EI, double GJ, double mass, double inertia)
{
    gal_rod_params p = {.EA = EA, .EI = EI, .GJ = GJ, .mass = mass, .polar_inertia = inertia,
                        .gravity = 9.80665, .torsion = 1, .twist_clamped = 1};
    return p;
}

static gal_rod_params falcon(void) { return conductor(6.88e7, 74.8, 389, 3.040, 5.851e-4); }
static gal_rod_params cardinal(void) { return conductor(4.15e7, 32.7, 233, 1.829, 2.110e-4); }
static gal_rod_params drake(void) { return conductor(3.73e7, 44.1, 200, 1.628, 1.611e-4); }

/* solve by sag; the sag met to 1e-10 of itself (the tolerance of solve_length), in a few outer
 * iterations (1-2 measured on the spans of tests/rom/ at 100-1000 elements) */
static void run_case(const char *name, gal_rod_params p, double L, double h, double sag, int elements)
{
    p.length = L, p.height_difference = h, p.elements = elements;
    gal_equilibrium eq;
    int st = gal_statics_solve(&p, GAL_BY_SAG, sag, NULL, &eq);
    CHECK(st == GAL_OK, "%s, %d elements: %s", name, elements, gal_error_message());
    if (st) return;
    CHECK_NEAR(eq.sag, sag, 1e-10 * sag);
    CHECK_NEAR(gal_rod_sag(eq.rod, eq.q), sag, 1e-10 * sag);
    CHECK(eq.length_iterations <= 4, "%s, %d elements: %d length iterations", name, elements, eq.length_iterations);
    printf("    (%s, %d elements: sag - target %.2g m, %d length iterations, %d Newton)\n", name, elements,
           eq.sag - sag, eq.length_iterations, eq.newton_iterations);
    gal_equilibrium_clear(&eq);
}

static void test_taut_inclined_400(void) { run_case("Falcon 400 m, 80 m rise, sag 6 m", falcon(), 400, 80, 6, 400); }
static void test_taut_level_400(void) { run_case("Cardinal 500 m level, sag 5 m", cardinal(), 500, 0, 5, 400); }
static void test_declined_600(void) { run_case("Cardinal 500 m, 60 m fall, sag 8 m", cardinal(), 500, -60, 8, 600); }
static void test_level_1000(void) { run_case("Drake 300 m level, sag 3 m", drake(), 300, 0, 3, 1000); }

int main(void)
{
    printf("test_statics_sag\n");
    RUN(test_taut_inclined_400);
    RUN(test_taut_level_400);
    RUN(test_declined_600);
    RUN(test_level_1000);
    return CHECK_SUMMARY();
}
