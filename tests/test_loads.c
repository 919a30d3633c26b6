/* test_loads.c: the loads of a span in wind: static blow-out against atan(F_D / (m g)), the
 * linearized aerodynamic damping of a vertical mode against Den Hartog's (dC_L/dalpha + C_D),
 * the wind's ramp, reversal and interpolation of the turbulence field. */
#include "check.h"
#include "gallop.h"
#include "gallop/loads/loads.h"
#include "gallop/modes/modes.h"
#include "gallop/statics/statics.h"

static gal_rod_params drake(void)
{
    gal_rod_params p = {.length = 300, .elements = 60, .EA = 2.9e7, .EI = 28, .GJ = 160, .mass = 1.628,
                        .polar_inertia = 1.6e-4, .gravity = 9.80665, .torsion = 1, .twist_clamped = 1};
    return p;
}

/* C_D constant, C_L = slope sin(alpha), tabulated every 5 degrees (the periodic spline then has
 * dC_L/dalpha(0) = slope to 1e-5) */
static gal_aero_table *constant_table(double cd, double cl_slope)
{
    double a[73], c[73], l[73], z[73];
    for (int k = 0; k < 73; k++) {
        a[k] = -180 + 5.0 * k;
        c[k] = cd, l[k] = cl_slope * sin(a[k] * GAL_PI / 180), z[k] = 0;
    }
    return gal_aero_table_make("test", "made up", 73, a, c, l, z);
}

static void test_blowout_angle(void)
{
    gal_rod_params p = drake();
    gal_equilibrium eq;
    CHECK(gal_statics_solve(&p, GAL_BY_TENSION, 28000, NULL, &eq) == GAL_OK, "%s", gal_error_message());
    gal_aero_table *t = constant_table(1.0, 0);
    gal_loads L = {.table = t, .flags = GAL_AERO_DRAG, .rho = 1.225, .diam = 0.0281, .speed = 25,
                   .dir = {0, 1, 0}, .rod = eq.rod};
    int it = 0;
    CHECK(gal_loads_static(eq.rod, eq.q, &L, 1e-6, 50, &it) == GAL_OK, "%s", gal_error_message());
    int mid = eq.rod->nn / 2;
    double y = eq.q[3 * mid + 1], z = eq.q[3 * mid + 2];
    double phi = atan2(y, -z) * 180 / GAL_PI;
    double FD = 0.5 * 1.225 * 25 * 25 * 0.0281 * 1.0, W = p.mass * p.gravity;
    double want = atan(FD / W) * 180 / GAL_PI;
    printf("    (blow-out at mid-span %.3f deg vs atan(F_D / m g) = %.3f deg, %d Newton iterations)\n", phi, want, it);
    CHECK_REL(phi, want, 1e-2);
    gal_aero_table_free(t);
    gal_equilibrium_clear(&eq);
}

/* The modal aerodynamic damping of the first vertical mode in a horizontal wind normal to the span:
 * c = 1/2 rho U d (dC_L/dalpha + C_D) int phi_n^2 ds (phi_n: the mode across the conductor in its plane), by differences of the loads in the modal
 * velocity. */
static void test_den_hartog_damping(void)
{
    gal_rod_params p = drake();
    p.elements = 100;
    gal_equilibrium eq;
    CHECK(gal_statics_solve(&p, GAL_BY_TENSION, 28000, NULL, &eq) == GAL_OK, "%s", gal_error_message());
    gal_modes md;
    int want[GAL_FAMILY_COUNT] = {1, 0, 0, 0};
    CHECK(gal_modes_find(eq.rod, eq.q, want, 100, &md) == GAL_OK, "%s", gal_error_message());
    int k = 0;
    while (!md.mode[k].selected) k++;
    const double *phi = md.shape + (size_t)k * md.ndof;
    double slope = -3.0, cd = 1.2; /* C_L = slope sin(alpha): dC_L/dalpha(0) = slope */
    gal_aero_table *t = constant_table(cd, slope);
    double U = 8, rho = 1.225, d = 0.0281;
    gal_loads L = {.table = t, .flags = GAL_AERO_DRAG | GAL_AERO_LIFT, .aero_damping = 1, .rho = rho,
                   .diam = d, .speed = U, .dir = {0, 1, 0}, .rod = eq.rod};
    int nq = eq.rod->nq;
    double *v = calloc(nq, sizeof(double)), *fp = calloc(nq, sizeof(double)), *fm = calloc(nq, sizeof(double));
    double dv = 1e-4, c = 0, iz = 0;
    for (int j = 0; j < md.ndof; j++) v[eq.rod->free_q[j]] = dv * phi[j];
    gal_loads_full(&L, 0, eq.q, v, fp);
    for (int j = 0; j < md.ndof; j++) v[eq.rod->free_q[j]] = -dv * phi[j];
    gal_loads_full(&L, 0, eq.q, v, fm);
    for (int j = 0; j < md.ndof; j++) {
        int q = eq.rod->free_q[j];
        c -= phi[j] * (fp[q] - fm[q]) / (2 * dv);
    }
    /* int phi_n^2 ds: phi_n the component along the lift direction t x y (the in-plane normal),
     * lumped at the nodes (length = node mass / m) */
    for (int i = 1; i < eq.rod->nn - 1; i++) {
        double t[3], ph[3];
        for (int a = 0; a < 3; a++) t[a] = eq.q[3 * (i + 1) + a] - eq.q[3 * (i - 1) + a];
        double nt = sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
        for (int a = 0; a < 3; a++) ph[a] = phi[eq.rod->dof[3 * i + a]];
        double pn = (-t[2] * ph[0] + t[0] * ph[2]) / nt; /* (t x y) . phi */
        iz += pn * pn * eq.rod->node_mass[i] / p.mass;
    }
    double cdh = 0.5 * rho * U * d * (slope + cd) * iz;
    printf("    (modal aerodynamic damping %.6g 1/s vs Den Hartog %.6g 1/s; damping ratio %.4f)\n", c, cdh,
           c / (2 * md.mode[k].omega));
    CHECK_REL(c, cdh, 1e-2);
    CHECK(c < 0, "C_L' + C_D < 0 must give negative damping");
    free(v); free(fp); free(fm);
    gal_aero_table_free(t);
    gal_modes_clear(&md);
    gal_equilibrium_clear(&eq);
}

static void test_wind_ramp_reverse_field(void)
{
    double u[2 * 3] = {0, 1, 2, 10, 11, 12}; /* two times, three points */
    gal_loads L = {.speed = 10, .dir = {0, 1, 0}, .ramp_time = 4, .nx = 3, .nt = 2, .x0 = 0, .dx = 100,
                   .dt = 1, .u = u};
    double w[3];
    gal_loads_wind(&L, 2.0, 50, w); /* half ramp: mean 5, fluctuation at t = 2 wraps to t = 0: 0.5 */
    CHECK_NEAR(w[1], 0.5 * (10 + 0.5), 1e-12);
    gal_loads_wind(&L, 4.5, 150, w); /* after the ramp; t mod 1 = 0.5, x = 150: (1.5 + 11.5)/2 */
    CHECK_NEAR(w[1], 10 + 0.5 * (1.5 + 11.5), 1e-12);
    L.reverse_time = 5;
    gal_loads_wind(&L, 6.0, 0, w);
    CHECK(w[1] < 0, "reversed wind: %g", w[1]);
    CHECK_NEAR(w[0], 0, 1e-15);
}

/* An effect that is off is not in the lists; the lists follow the fields (a copy with the
 * turbulence dropped has no turbulence term). */
static void test_term_lists(void)
{
    double u[6] = {0};
    gal_loads L = {.flags = GAL_AERO_DRAG | GAL_AERO_MOMENT, .speed = 10, .aero_damping = 1};
    gal_loads_list ls;
    gal_loads_list_make(&L, &ls);
    CHECK(ls.nwind == 2 && ls.wind[0] == &gal_loads_term_mean_wind &&
          ls.wind[1] == &gal_loads_term_aero_damping, "mean wind, aero damping: %d terms", ls.nwind);
    CHECK(ls.nsection == 2 && ls.section[0] == &gal_aero_term_drag &&
          ls.section[1] == &gal_aero_term_moment, "drag, moment: %d terms", ls.nsection);
    L.u = u, L.nx = 3, L.nt = 2, L.aero_damping = 0, L.flags = GAL_AERO_ALL;
    gal_loads_list_make(&L, &ls);
    CHECK(ls.nwind == 2 && ls.wind[1] == &gal_loads_term_turbulence, "turbulence");
    CHECK(ls.nsection == 3 && strcmp(ls.section[1]->name, "aero_lift") == 0, "all three");
    gal_loads Ls = L;
    Ls.u = NULL, Ls.nt = 0;
    gal_loads_list_make(&Ls, &ls);
    CHECK(ls.nwind == 1 && ls.wind[0] == &gal_loads_term_mean_wind, "turbulence dropped");
    gal_loads none = {.dir = {0, 1, 0}};
    gal_loads_list_make(&none, &ls);
    CHECK(ls.nwind == 0 && ls.nsection == 0, "no wind, no loads: %d, %d", ls.nwind, ls.nsection);
}

/* The point load is the sum of its terms: aerodynamic damping is the load in the wind minus the
 * velocity; each section term's derivative against central differences of its own load. */
static void test_point_load_terms(void)
{
    gal_aero_table *t = gal_aero_table_load("data/aero/iced_d_shape.csv");
    CHECK(t != NULL, "%s", gal_error_message());
    if (!t) return;
    double u[2 * 3] = {0, 1, 2, -1, 0.5, 3};
    gal_loads L = {.table = t, .flags = GAL_AERO_ALL, .aero_damping = 1, .rho = 1.25, .diam = 0.03,
                   .attack_angle = 0.2, .speed = 12, .dir = {0, 1, 0}, .ramp_time = 2, .nx = 3,
                   .nt = 2, .dx = 50, .dt = 1, .u = u};
    double r[3] = {0}, rd[3] = {0.1, -0.4, 0.7}, tan[3] = {1, 0.05, -0.1}, d1[3] = {0, 1, 0.2};
    double f0[3], m0, f2[3], m2, w[3];
    CHECK(gal_loads_point(&L, 1.3, 60, r, rd, tan, d1, f0, &m0) == GAL_OK, "point");
    /* damping: the load without it, in the wind minus the velocity */
    gal_loads_wind(&L, 1.3, 60, w);
    for (int k = 0; k < 3; k++) w[k] -= rd[k];
    double c = cos(0.2), s = sin(0.2), b[3], d[3];
    b[0] = tan[1] * d1[2] - tan[2] * d1[1], b[1] = tan[2] * d1[0] - tan[0] * d1[2], b[2] = tan[0] * d1[1] - tan[1] * d1[0];
    for (int k = 0; k < 3; k++) d[k] = c * d1[k] - s * b[k];
    gal_aero_load(t, tan, d, w, 1.25, 0.03, GAL_AERO_ALL, f2, &m2);
    for (int k = 0; k < 3; k++) CHECK_NEAR(f0[k], f2[k], 1e-12 * (1 + fabs(f2[k])));
    CHECK_NEAR(m0, m2, 1e-12 * (1 + fabs(m2)));
    /* each section term alone: its derivative against differences of its own load */
    const gal_aero_term *all[3] = {&gal_aero_term_drag, &gal_aero_term_lift, &gal_aero_term_moment};
    for (int k = 0; k < 3; k++) {
        double f[3], m, df[9], dm[3], err = 0, big = 0;
        gal_aero_load_terms(t, tan, d1, w, 1.25, 0.03, all + k, 1, f, &m, df, dm);
        for (int j = 0; j < 3; j++) {
            double wp[3] = {w[0], w[1], w[2]}, wm[3] = {w[0], w[1], w[2]}, fp[3], fm[3], mp, mm, h = 1e-6;
            wp[j] += h, wm[j] -= h;
            gal_aero_load_terms(t, tan, d1, wp, 1.25, 0.03, all + k, 1, fp, &mp, NULL, NULL);
            gal_aero_load_terms(t, tan, d1, wm, 1.25, 0.03, all + k, 1, fm, &mm, NULL, NULL);
            for (int i = 0; i < 3; i++) {
                err = fmax(err, fabs((fp[i] - fm[i]) / (2 * h) - df[3 * i + j]));
                big = fmax(big, fabs(df[3 * i + j]));
            }
            err = fmax(err, fabs((mp - mm) / (2 * h) - dm[j]));
            big = fmax(big, fabs(dm[j]));
        }
        CHECK(big > 0 && err <= 1e-6 * big, "%s: derivative error %g of %g", all[k]->name, err, big);
        printf("    (%s: derivative error %.2g of %.2g)\n", all[k]->name, err, big);
    }
    gal_aero_table_free(t);
}

int main(void)
{
    RUN(test_blowout_angle);
    RUN(test_den_hartog_damping);
    RUN(test_wind_ramp_reverse_field);
    RUN(test_term_lists);
    RUN(test_point_load_terms);
    return CHECK_SUMMARY();
}
