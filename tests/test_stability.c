/* test_stability.c: Den Hartog's criterion swept over the angle of attack (analysis/stability.c)
 * against closed forms: a section with C_D = d and C_L = +-a sin(alpha) has H = d +- a cos(alpha)
 * (per rad), unstable where cos(alpha) < -d/a (or > d/a), lowest H = d - a, and onset speeds
 * U_c = -4 m zeta w / (rho D H). */
#include "check.h"
#include "gallop.h"
#include "gallop/analysis/stability.h"
#include "gallop/scene/scene.h"

#define DEG (GAL_PI / 180.0)
#define SPAN_M 2.228      /* kg/m */
#define SPAN_ZETA 0.003
#define SPAN_RHO 1.225    /* kg/m^3 */
#define SPAN_D 0.02814    /* m */

/* C_D = cd, C_L = a sin(alpha), C_M = 0 on a 2-deg grid */
static gal_aero_table *sine_table(double cd, double a)
{
    double al[180], d[180], l[180], m[180];
    for (int i = 0; i < 180; i++) al[i] = -180 + 2 * i, d[i] = cd, l[i] = a * sin(al[i] * DEG), m[i] = 0;
    return gal_aero_table_make("sine lift", "closed form for the test", 180, al, d, l, m);
}

static void span(gal_stability_params *p, const double *omega, int n, double attack_deg)
{
    p->mass = SPAN_M, p->zeta = SPAN_ZETA, p->rho = SPAN_RHO, p->diam = SPAN_D;
    p->attack_angle = attack_deg * DEG;
    p->nmodes = n, p->omega = omega;
}

static double onset_exact(double omega, double H)
{
    return H < 0 ? -4 * SPAN_M * SPAN_ZETA * omega / (SPAN_RHO * SPAN_D * H) : INFINITY;
}

/* H = 1 + 2.5 cos(alpha): unstable for |alpha| > acos(-0.4) = 113.58 deg, i.e. [-180, -114] and
 * [114, 180] on the grid; lowest H = -1.5 at +-180 deg. */
static void test_sine_lift_two_ranges(void)
{
    gal_aero_table *t = sine_table(1.0, 2.5);
    double omega[2] = {2 * GAL_PI * 0.5, 2 * GAL_PI * 1.1};
    gal_stability_params p;
    span(&p, omega, 2, 150);
    gal_stability *S = gal_stability_sweep(t, &p);
    CHECK(S != NULL, "%s", gal_error_message());
    if (!S) { gal_aero_table_free(t); return; }
    double worst = 0;
    for (int i = 0; i < GAL_STABILITY_NALPHA; i++) {
        double a = S->r[i].alpha_deg * DEG, H = 1 + 2.5 * cos(a);
        CHECK(S->r[i].alpha_deg == -180 + i, "grid angle %g at row %d", S->r[i].alpha_deg, i);
        worst = fmax(worst, fabs(S->r[i].h - H));
        worst = fmax(worst, fabs(S->r[i].dcl - 2.5 * cos(a)));
        worst = fmax(worst, fabs(S->r[i].c[1] - 2.5 * sin(a)) + fabs(S->r[i].c[0] - 1));
        for (int k = 0; k < 2; k++) {
            double u = onset_exact(omega[k], H);
            if (isinf(u)) CHECK(isinf(S->r[i].onset[k]), "alpha %g: stable, onset %g", S->r[i].alpha_deg, S->r[i].onset[k]);
            else CHECK_REL(S->r[i].onset[k], u, 2e-3);
        }
    }
    CHECK(worst < 1e-3, "largest error of H, dC_L/dalpha, C_L, C_D against the closed form: %g", worst);
    CHECK(S->nranges == 2, "%d unstable ranges, want 2", S->nranges);
    if (S->nranges == 2) {
        CHECK(S->range[0][0] == -180 && S->range[0][1] == -114, "[%g, %g]", S->range[0][0], S->range[0][1]);
        CHECK(S->range[1][0] == 114 && S->range[1][1] == 180, "[%g, %g]", S->range[1][0], S->range[1][1]);
    }
    CHECK_NEAR(S->r[S->imin].h, -1.5, 1e-4);
    CHECK(fabs(S->r[S->imin].alpha_deg) == 180, "lowest H at %g deg", S->r[S->imin].alpha_deg);
    double H150 = 1 + 2.5 * cos(150 * DEG);
    CHECK_NEAR(S->h_rest, H150, 1e-3);
    CHECK_REL(S->onset_rest[1], onset_exact(omega[1], H150), 2e-3);
    CHECK_REL(S->onset_rest[0], gal_stability_onset(t, 150 * DEG, SPAN_M, SPAN_ZETA, omega[0], SPAN_RHO, SPAN_D), 1e-14);
    gal_stability_free(S);
    gal_aero_table_free(t);
}

/* H = 1 - 2.5 cos(alpha): one range about 0, [-66, 66] (acos(0.4) = 66.42 deg), lowest H at 0. */
static void test_sine_lift_one_range(void)
{
    gal_aero_table *t = sine_table(1.0, -2.5);
    double omega[1] = {2 * GAL_PI * 0.3};
    gal_stability_params p;
    span(&p, omega, 1, 0);
    gal_stability *S = gal_stability_sweep(t, &p);
    CHECK(S != NULL, "%s", gal_error_message());
    if (!S) { gal_aero_table_free(t); return; }
    CHECK(S->nranges == 1 && S->range[0][0] == -66 && S->range[0][1] == 66, "%d ranges, first [%g, %g]", S->nranges,
          S->range[0][0], S->range[0][1]);
    CHECK(S->r[S->imin].alpha_deg == 0, "lowest H at %g deg, want 0", S->r[S->imin].alpha_deg);
    CHECK_NEAR(S->r[S->imin].h, -1.5, 1e-4);
    CHECK_REL(S->r[S->imin].onset[0], onset_exact(omega[0], -1.5), 1e-4);
    CHECK_REL(S->onset_rest[0], onset_exact(omega[0], -1.5), 1e-4);
    gal_stability_free(S);
    gal_aero_table_free(t);
}

/* A circular cylinder: H = C_D > 0 everywhere, no range, every onset infinite. */
static void test_cylinder_stable(void)
{
    gal_aero_table *t = sine_table(1.2, 0);
    double omega[3] = {1, 2, 3};
    gal_stability_params p;
    span(&p, omega, 3, 20);
    gal_stability *S = gal_stability_sweep(t, &p);
    CHECK(S != NULL, "%s", gal_error_message());
    if (!S) { gal_aero_table_free(t); return; }
    CHECK(S->nranges == 0, "%d ranges", S->nranges);
    CHECK_NEAR(S->h_rest, 1.2, 1e-12);
    int finite = 0;
    for (int i = 0; i < GAL_STABILITY_NALPHA; i++)
        for (int k = 0; k < 3; k++) finite += isfinite(S->r[i].onset[k]);
    for (int k = 0; k < 3; k++) finite += isfinite(S->onset_rest[k]);
    CHECK(finite == 0, "%d finite onset speeds", finite);
    gal_stability_free(S);
    gal_aero_table_free(t);
}

/* No damping: the onset is 0 wherever H < 0; no modes: the criterion alone. */
static void test_no_damping_no_modes(void)
{
    gal_aero_table *t = sine_table(1.0, 2.5);
    double omega[1] = {3};
    gal_stability_params p;
    span(&p, omega, 1, 180);
    p.zeta = 0;
    gal_stability *S = gal_stability_sweep(t, &p);
    CHECK(S != NULL && S->onset_rest[0] == 0 && S->r[0].onset[0] == 0, "onset without damping");
    gal_stability_free(S);
    span(&p, NULL, 0, 180);
    S = gal_stability_sweep(t, &p);
    CHECK(S != NULL && S->nranges == 2, "no modes: the sweep still finds the ranges");
    gal_stability_free(S);
    gal_aero_table_free(t);
}

static void test_bad_params(void)
{
    gal_aero_table *t = sine_table(1.0, 2.5);
    double omega[GAL_STABILITY_MAX_MODES + 1] = {0};
    gal_stability_params p;
    span(&p, omega, GAL_STABILITY_MAX_MODES + 1, 0);
    CHECK(gal_stability_sweep(t, &p) == NULL, "65 modes must be refused");
    CHECK(strstr(gal_error_message(), "allowed: 0 to 64") != NULL, "message: %s", gal_error_message());
    span(&p, omega, -1, 0);
    CHECK(gal_stability_sweep(t, &p) == NULL, "-1 modes must be refused");
    CHECK(gal_stability_free(NULL) == NULL, "free(NULL)");
    gal_aero_table_free(t);
}

/* The span figures of a scene: conductor + ice mass, damping only with the damping effect on. */
static void test_scene_params(void)
{
    gal_scene sc;
    const char *sets[] = {"effects.damping=off"};
    int st = gal_scene_load(&sc, "data/scenes/iced_gallop.ini", NULL, 0, NULL);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (st) return;
    gal_stability_params p;
    gal_stability_scene_params(&sc, &p);
    CHECK_NEAR(p.mass, sc.conductor.mass_per_length + sc.ice.mass_per_length, 0);
    CHECK(p.zeta == sc.conductor.damping_ratio && p.zeta > 0, "zeta %g", p.zeta);
    CHECK(p.rho == sc.wind.air_density && p.diam == sc.conductor.diameter, "rho, d");
    CHECK(p.attack_angle == sc.ice.attack_angle && p.nmodes == 0, "attack angle, modes");
    st = gal_scene_load(&sc, "data/scenes/iced_gallop.ini", sets, 1, NULL);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    gal_stability_scene_params(&sc, &p);
    CHECK(p.zeta == 0, "damping off: zeta %g", p.zeta);
}

/* Nigol's torsional onset: the total torsional damping ratio zeta + rho U d^2 R C_M' / (4 I w)
 * vanishes there (R = d/2), by hand: C_M' = -0.5, I = 1e-3 kg m^2/m, 1 Hz, zeta = 0.01,
 * rho = 1.2, d = 0.03: U_N = 4e-3 (2 pi) 0.01 / (1.2 9e-4 0.015 0.5) = 31.03 m/s; none for
 * C_M' >= 0; it scales with zeta and 1/|C_M'|. */
static void test_nigol(void)
{
    double w = 2 * GAL_PI, u = gal_stability_nigol_onset(-0.5, 1e-3, w, 0.01, 1.2, 0.03);
    CHECK_REL(u, 4e-3 * w * 0.01 / (1.2 * 9e-4 * 0.015 * 0.5), 1e-12);
    CHECK_NEAR(u, 31.03, 0.01);
    CHECK_NEAR(0.01 + 1.2 * u * 9e-4 * 0.015 * -0.5 / (4 * 1e-3 * w), 0, 1e-12);
    CHECK(isinf(gal_stability_nigol_onset(0.0, 1e-3, w, 0.01, 1.2, 0.03)), "dC_M/dalpha = 0: stable");
    CHECK(isinf(gal_stability_nigol_onset(0.2, 1e-3, w, 0.01, 1.2, 0.03)), "dC_M/dalpha > 0: stable");
    CHECK_REL(gal_stability_nigol_onset(-1.0, 1e-3, w, 0.02, 1.2, 0.03), u, 1e-12);
}

int main(void)
{
    RUN(test_nigol);
    RUN(test_sine_lift_two_ranges);
    RUN(test_sine_lift_one_range);
    RUN(test_cylinder_stable);
    RUN(test_no_damping_no_modes);
    RUN(test_bad_params);
    RUN(test_scene_params);
    return CHECK_SUMMARY();
}
