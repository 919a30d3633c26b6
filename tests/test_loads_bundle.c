/* test_loads_bundle.c: an equivalent bundle's section load (src/loads/bundle_section.c): at rest
 * n times one sub-conductor's (the old n rho load), the sum over the sub-conductors at their own
 * relative wind by hand (a twisted, moving section with the twist rate from the rod's velocity),
 * the torsional aerodynamic damping of a drag-only section against its closed form by central
 * differences, the leeward sub-conductors and the wake factor, and the model's configuration
 * (equivalent: on; explicit and a single conductor: off). */
#include "check.h"
#include "gallop.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define NEL 10

/* A straight taut rod along x (100 m, NEL elements, torsion on), its configuration with twist. */
static gal_rod *straight_rod(double *q)
{
    gal_rod_params p = {.length = 100, .elements = NEL, .unstretched_length = 100, .EA = 3e7, .EI = 30,
                        .GJ = 200, .mass = 2, .polar_inertia = 1e-3, .torsion = 1, .twist_clamped = 1};
    int nn = NEL + 1;
    for (int i = 0; i < nn; i++) q[3 * i] = 10.0 * i, q[3 * i + 1] = q[3 * i + 2] = 0;
    for (int j = 0; j < NEL; j++) q[3 * nn + j] = 0;
    return gal_rod_alloc(&p, q);
}

/* A smooth table (per degree: 5-degree rows) with lift slope and moment. */
static gal_aero_table *smooth_table(void)
{
    double a[72], cd[72], cl[72], cm[72];
    for (int k = 0; k < 72; k++) {
        a[k] = -180 + 5 * k;
        double r = a[k] * M_PI / 180;
        cd[k] = 1.1 + 0.2 * cos(2 * r), cl[k] = -0.5 * sin(2 * r) + 0.1 * sin(r), cm[k] = 0.05 * sin(r + 0.4);
    }
    return gal_aero_table_make("smooth", "test", 72, a, cd, cl, cm);
}

static gal_loads base_loads(const gal_aero_table *t, const gal_rod *rod)
{
    gal_loads L = {.table = t, .flags = GAL_AERO_ALL, .aero_damping = 1, .rho = 1.25, .diam = 0.03,
                   .attack_angle = 0.3, .speed = 9, .dir = {0, 1, 0}, .rod = rod};
    return L;
}

/* At rest (no velocity, any twist) a bundle without shielding carries n times one sub-conductor's
 * load and moment: the old equivalent load at n rho. */
static void test_rest_is_n_times(void)
{
    gal_aero_table *t = smooth_table();
    double q[3 * (NEL + 1) + NEL], v[3 * (NEL + 1) + NEL] = {0};
    gal_rod *rod = straight_rod(q);
    CHECK(t && rod, "%s", gal_error_message());
    if (!t || !rod) { gal_aero_table_free(t); gal_rod_free(rod); return; }
    for (int j = 0; j < NEL; j++) q[3 * (NEL + 1) + j] = 0.05 * j - 0.2;
    for (int n = 2; n <= 8; n++) {
        gal_loads Ls = base_loads(t, rod), Lb = Ls;
        Ls.rho = 1.25 * n;
        gal_loads_bundle_set(&Lb, n, 0.3, 0.4, 1.25, 1.0);
        CHECK(Lb.bundle.n == n, "%d sub-conductors set", n);
        for (int j = 0; j < NEL; j++) {
            double fs[7], fb[7];
            CHECK(gal_loads_element(&Ls, 1.0, q, v, j, fs) == GAL_OK && gal_loads_element(&Lb, 1.0, q, v, j, fb) == GAL_OK, "load");
            for (int k = 0; k < 7; k++) CHECK_NEAR(fb[k], fs[k], 1e-12 * (1 + fabs(fs[k])));
        }
    }
    gal_aero_table_free(t);
    gal_rod_free(rod);
}

/* The bundle's element load against each sub-conductor's by hand: gal_aero_load at the relative
 * wind U dir - (v + spin e3 x p_k), p_k turned with the twist, the reference turned by the attack
 * angle, summed as force and moment about the centroid. */
static void test_sum_by_hand(void)
{
    gal_aero_table *t = smooth_table();
    int nn = NEL + 1, nq = 3 * nn + NEL;
    double q[3 * (NEL + 1) + NEL], v[3 * (NEL + 1) + NEL];
    gal_rod *rod = straight_rod(q);
    if (!t || !rod) { CHECK(0, "%s", gal_error_message()); gal_aero_table_free(t); gal_rod_free(rod); return; }
    for (int k = 0; k < nq; k++) v[k] = 0.7 * sin(1.3 * k + 0.2);
    for (int i = 1; i < nn - 1; i++) q[3 * i + 2] += 0.3 * sin(0.9 * i), q[3 * i + 1] += 0.2 * cos(0.7 * i);
    for (int j = 0; j < NEL; j++) q[3 * nn + j] = 0.4 * sin(0.6 * j);
    gal_loads L = base_loads(t, rod);
    gal_loads_bundle_set(&L, 4, 0.3232, 0.25, 1.25, 1.0);
    double err = 0, mx = 0;
    for (int j = 0; j < NEL; j++) {
        double g[7], tg[3], d1[3], e2[3], da[3], F[3] = {0, 0, 0}, M = 0, ca = cos(0.3), sa = sin(0.3);
        CHECK(gal_loads_element(&L, 2.0, q, v, j, g) == GAL_OK, "load");
        gal_rod_material_frame(rod, q, j, tg, d1);
        gal_cross3(tg, d1, e2);
        for (int k = 0; k < 3; k++) da[k] = ca * d1[k] - sa * e2[k];
        double spin = v[3 * nn + j];
        for (int s = 0; s < 4; s++) {
            double a = 0.25 + M_PI * s / 2, p[3], w[3], f[3], m, pf[3];
            for (int k = 0; k < 3; k++) {
                p[k] = 0.3232 * (cos(a) * d1[k] + sin(a) * e2[k]);
                double u = 0.5 * (v[3 * j + k] + v[3 * (j + 1) + k]) + spin * 0.3232 * (cos(a) * e2[k] - sin(a) * d1[k]);
                w[k] = 9 * L.dir[k] - u;
            }
            gal_aero_load(t, tg, da, w, 1.25, 0.03, GAL_AERO_ALL, f, &m);
            gal_cross3(p, f, pf);
            for (int k = 0; k < 3; k++) F[k] += f[k];
            M += m + gal_dot3(pf, tg);
        }
        double l0 = rod->l0[j];
        for (int k = 0; k < 3; k++) {
            err = fmax(err, fmax(fabs(g[k] - 0.5 * l0 * F[k]), fabs(g[3 + k] - 0.5 * l0 * F[k])));
            mx = fmax(mx, fabs(0.5 * l0 * F[k]));
        }
        err = fmax(err, fabs(g[6] - l0 * M) / 0.3232);
    }
    CHECK(mx > 0 && err <= 1e-12 * mx, "element loads against the sum by hand: %g of %g", err, mx);
    gal_aero_table_free(t);
    gal_rod_free(rod);
}

/* Drag only, constant C_D, wind along d1: the twist rate's moment is -(rho d / 2) U C_D
 * (sum a_k^2 + 2 sum c_k^2) per rad/s (a_k, c_k the offsets along and across the wind), the
 * torsional aerodynamic damping the single load at the centroid lacks (dm/dspin = 0 there). */
static void test_torsional_damping(void)
{
    double a[4] = {-180, -90, 0, 90}, cd[4] = {1.2, 1.2, 1.2, 1.2}, z[4] = {0, 0, 0, 0};
    gal_aero_table *t = gal_aero_table_make("flat", "test", 4, a, cd, z, z);
    int nn = NEL + 1, nq = 3 * nn + NEL;
    double q[3 * (NEL + 1) + NEL], v[3 * (NEL + 1) + NEL] = {0};
    gal_rod *rod = straight_rod(q);
    if (!t || !rod) { CHECK(0, "%s", gal_error_message()); gal_aero_table_free(t); gal_rod_free(rod); return; }
    for (int n = 1; n <= 4; n++) {
        gal_loads L = {.table = t, .flags = GAL_AERO_DRAG, .aero_damping = 1, .rho = 1.25 * n, .diam = 0.03,
                       .speed = 10, .dir = {0, 1, 0}, .rod = rod};
        double R = 0.4, o = 0.3, want = 0;
        gal_loads_bundle_set(&L, n, R, o, 1.25, 1.0);
        for (int k = 0; k < n && n > 1; k++) {
            double ak = R * cos(o + 2 * M_PI * k / n), ck = R * sin(o + 2 * M_PI * k / n);
            want -= 0.5 * 1.25 * 0.03 * 10 * 1.2 * (ak * ak + 2 * ck * ck);
        }
        int j = 3;
        double h = 1e-4, gp[7], gm[7];
        v[3 * nn + j] = h;
        gal_loads_element(&L, 0, q, v, j, gp);
        v[3 * nn + j] = -h;
        gal_loads_element(&L, 0, q, v, j, gm);
        v[3 * nn + j] = 0;
        double got = (gp[6] - gm[6]) / (2 * h) / rod->l0[j];
        if (n == 1) CHECK(got == 0, "a single conductor: no torsional damping from the twist rate: %g", got);
        else CHECK_REL(got, want, 1e-7);
    }
    (void)nq;
    gal_aero_table_free(t);
    gal_rod_free(rod);
}

/* Leeward sub-conductors (the explicit model's rule) and the wake factor on their air density. */
static void test_leeward(void)
{
    gal_loads L = {.diam = 0.03, .dir = {0, 1, 0}};
    gal_loads_bundle_set(&L, 2, 0.2285, 0, 1.25, 0.5); /* horizontal twin, wind +y: the first downwind */
    CHECK(L.bundle.leeward[0] == 1 && L.bundle.leeward[1] == 0, "twin: %d %d", L.bundle.leeward[0], L.bundle.leeward[1]);
    CHECK_NEAR(L.bundle.rho[0], 0.625, 1e-15);
    CHECK_NEAR(L.bundle.rho[1], 1.25, 1e-15);
    L.dir[1] = -1;
    gal_loads_bundle_set(&L, 2, 0.2285, 0, 1.25, 0.5);
    CHECK(L.bundle.leeward[0] == 0 && L.bundle.leeward[1] == 1, "twin, wind -y: %d %d", L.bundle.leeward[0], L.bundle.leeward[1]);
    gal_loads_bundle_set(&L, 2, 0.2285, M_PI / 2, 1.25, 0.5); /* vertical twin: none */
    CHECK(!L.bundle.leeward[0] && !L.bundle.leeward[1], "vertical twin");
    L.dir[1] = 1;
    gal_loads_bundle_set(&L, 4, 0.3232, M_PI / 4, 1.25, 0.5); /* a square: the two downwind */
    int nl = 0;
    for (int k = 0; k < 4; k++) {
        nl += L.bundle.leeward[k];
        CHECK(L.bundle.leeward[k] == (L.bundle.off[k][0] > 0), "quad %d", k);
    }
    CHECK(nl == 2, "quad: %d leeward", nl);
    gal_loads_bundle_set(&L, 1, 0.3, 0, 1.25, 0.5);
    CHECK(L.bundle.n == 0, "one: none");
}

/* The model: an equivalent bundle's loads sum its sub-conductors (the explicit model's placing),
 * the explicit model's and a single conductor's do not. */
static void test_model(void)
{
    const char *sets[3][2] = {{NULL, NULL}, {"bundle.model=explicit", NULL}, {NULL, NULL}};
    const char *scene[3] = {"data/scenes/quad_bundle_gallop.ini", "data/scenes/quad_bundle_gallop.ini",
                            "data/scenes/iced_gallop.ini"};
    int want[3] = {4, 0, 0};
    for (int c = 0; c < 3; c++) {
        gal_scene sc;
        const char *kv[2];
        int nkv = 0;
        for (int k = 0; k < 2; k++)
            if (sets[c][k]) kv[nkv++] = sets[c][k];
        if (gal_scene_load(&sc, scene[c], kv, nkv, "data/conductors.csv")) {
            CHECK(0, "%d: %s", c, gal_error_message());
            continue;
        }
        gal_model *m = gal_model_alloc(&sc, NULL);
        CHECK(m != NULL, "%s", gal_error_message());
        if (!m) continue;
        CHECK(m->loads.bundle.n == want[c], "case %d: %d sub-conductors in the loads", c, m->loads.bundle.n);
        if (c == 0) {
            double R = sc.bundle.radius, o = sc.bundle.orientation;
            for (int k = 0; k < 4; k++) {
                CHECK_NEAR(m->loads.bundle.off[k][0], R * cos(o + M_PI * k / 2), 1e-15);
                CHECK_NEAR(m->loads.bundle.off[k][1], R * sin(o + M_PI * k / 2), 1e-15);
                CHECK_NEAR(m->loads.bundle.rho[k], sc.wind.air_density, 1e-15);
            }
        }
        gal_model_free(m);
    }
}

int main(void)
{
    RUN(test_rest_is_n_times);
    RUN(test_sum_by_hand);
    RUN(test_torsional_damping);
    RUN(test_leeward);
    RUN(test_model);
    return CHECK_SUMMARY();
}
