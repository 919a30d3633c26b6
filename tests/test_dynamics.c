/* test_dynamics.c: the full model's time integration: small free vibration at the modal frequency
 * with energy conserved (no numerical dissipation), large free vibration bounded, eccentric ice,
 * second-order convergence as the step is refined down to 1e-5 s. */
#include "check.h"
#include "gallop.h"
#include "gallop/full/dynamics.h"
#include "gallop/modes/modes.h"
#include "gallop/statics/statics.h"

static int eccentric; /* the next spans carry eccentric ice */

static gal_rod_params span(int nel)
{
    gal_rod_params p = {.length = 100, .elements = nel, .EA = 1e8, .EI = 1e-2, .GJ = 100, .mass = 1.5,
                        .polar_inertia = 1e-4, .gravity = 9.80665, .torsion = 1, .twist_clamped = 1};
    if (eccentric) {
        p.ecc_mass = 0.5, p.ecc = 0.01, p.ecc_angle = 2.5, p.mass += 0.5;
        p.polar_inertia += 0.5 * (0.014 * 0.014 + 0.01 * 0.01);
    }
    return p;
}

typedef struct {
    double period, energy_drift, emax_rel;
    int finite;
} run_result;

/* Start from the equilibrium displaced along mode k (amplitude amp at its largest entry) and run
 * `periods` periods with n_per steps each; measure the period at the largest entry from upward
 * zero crossings, and the energy. */
static run_result free_vibration(int fam, double amp, double periods, int n_per, double rho, int by_velocity)
{
    run_result res = {0};
    gal_rod_params p = span(30);
    gal_equilibrium eq;
    gal_modes md;
    int want[GAL_FAMILY_COUNT] = {0};
    want[fam] = 1;
    CHECK(gal_statics_solve(&p, GAL_BY_TENSION, 20000, NULL, &eq) == GAL_OK, "%s", gal_error_message());
    CHECK(gal_modes_find(eq.rod, eq.q, want, 200, &md) == GAL_OK, "%s", gal_error_message());
    int k = 0;
    while (!md.mode[k].selected) k++;
    const double *phi = md.shape + (size_t)k * md.ndof;
    int jmax = 0;
    for (int j = 0; j < md.ndof; j++)
        if (fabs(phi[j]) > fabs(phi[jmax])) jmax = j;
    double *q0 = malloc(eq.rod->nq * sizeof(double));
    memcpy(q0, eq.q, eq.rod->nq * sizeof(double));
    double T = 1.0 / md.mode[k].frequency_hz;
    double *v0 = calloc(eq.rod->nq, sizeof(double));
    /* a modal displacement, or a modal velocity (no initial stretch: the way to start a large motion) */
    for (int j = 0; j < md.ndof; j++) {
        if (by_velocity) v0[eq.rod->free_q[j]] = 2 * GAL_PI / T * amp * phi[j] / fabs(phi[jmax]);
        else q0[eq.rod->free_q[j]] += amp * phi[j] / fabs(phi[jmax]);
    }
    gal_dyn_opts o;
    gal_dyn_default_opts(&o);
    o.h = T / n_per;
    o.rho_inf = rho;
    gal_dyn *d = gal_dyn_alloc(eq.rod, q0, v0, &o, NULL);
    CHECK(d != NULL, "%s", gal_error_message());
    if (!d) return res;
    int kq = eq.rod->free_q[jmax];
    double prev = d->q[kq] - eq.q[kq], first = -1, last = -1, emax = 0;
    int crossings = 0;
    res.finite = 1;
    long nsteps = (long)(periods * n_per);
    for (long s = 0; s < nsteps; s++) {
        if (gal_dyn_step(d) != GAL_OK) { res.finite = 0; CHECK(0, "step: %s", gal_error_message()); break; }
        double cur = d->q[kq] - eq.q[kq];
        if (!by_velocity && prev < 0 && cur >= 0) {
            double tc = d->t - o.h * cur / (cur - prev);
            if (first < 0) first = tc;
            else crossings++;
            last = tc;
        }
        prev = cur;
        double e = gal_dyn_energy(d);
        if (!isfinite(e)) { res.finite = 0; break; }
        emax = fmax(emax, e - d->energy0);
    }
    /* energy about the equilibrium: E - E_eq, relative to the initial excitation energy */
    double Ueq;
    gal_rod_eval(eq.rod, eq.q, &Ueq, NULL, NULL);
    double Eexc = d->energy0 - Ueq;
    res.period = crossings > 0 ? (last - first) / crossings / T : NAN;
    res.energy_drift = (gal_dyn_energy(d) - d->energy0) / Eexc;
    res.emax_rel = emax / Eexc;
    gal_dyn_free(d);
    free(q0);
    free(v0);
    gal_modes_clear(&md);
    gal_equilibrium_clear(&eq);
    return res;
}

static void test_small_vibration_frequency_and_energy(void)
{
    for (int fam = 0; fam < 3; fam++) {
        run_result r = free_vibration(fam, 1e-3, 100, 40, 1.0, 0);
        printf("    (%s: period / modal period %.5f, energy drift %.2e, max deviation %.2e of the "
               "excitation energy)\n", gal_family_names[fam], r.period, r.energy_drift, r.emax_rel);
        CHECK(r.finite, "finite");
        CHECK_NEAR(r.period, 1.0, 5e-3);
        CHECK(fabs(r.energy_drift) < 1e-3 && fabs(r.emax_rel) < 1e-3, "energy %g %g", r.energy_drift, r.emax_rel);
    }
}

/* Large motion, started by a modal velocity: the mid-span swings by about the sag (0.9 m) or
 * twice it out of plane; the energy stays bounded (no growth) and finite. */
static void test_large_vibration_bounded(void)
{
    run_result r = free_vibration(GAL_FAMILY_VERTICAL, 0.9, 30, 80, 1.0, 1);
    printf("    (large vertical, rho_inf 1: energy drift %.2e, max excess %.2e of the initial energy)\n",
           r.energy_drift, r.emax_rel);
    CHECK(r.finite, "finite");
    CHECK(fabs(r.energy_drift) < 1e-2 && r.emax_rel < 1e-2, "energy drift %g, max excess %g", r.energy_drift, r.emax_rel);
    run_result r2 = free_vibration(GAL_FAMILY_HORIZONTAL, 2.0, 30, 80, 0.8, 1);
    printf("    (large horizontal, rho_inf 0.8: energy drift %.2e, max excess %.2e)\n", r2.energy_drift, r2.emax_rel);
    CHECK(r2.finite, "finite");
    CHECK(r2.emax_rel <= 1e-3, "a dissipative method must not gain energy: %g", r2.emax_rel);
}

/* Eccentric ice couples twist and translation in the mass matrix: the modes mix the families, and
 * the full model still conserves energy. */
static void test_eccentric_ice_coupling(void)
{
    eccentric = 1;
    gal_rod_params p = span(30);
    gal_equilibrium eq;
    gal_modes md;
    int want[GAL_FAMILY_COUNT] = {1, 1, 1, 0};
    CHECK(gal_statics_solve(&p, GAL_BY_TENSION, 20000, NULL, &eq) == GAL_OK, "%s", gal_error_message());
    CHECK(gal_modes_find(eq.rod, eq.q, want, 200, &md) == GAL_OK, "%s", gal_error_message());
    double mix = 0;
    for (int k = 0; k < md.n; k++)
        if (md.mode[k].family == GAL_FAMILY_TORSIONAL) mix = fmax(mix, md.mode[k].share[GAL_FAMILY_VERTICAL] + md.mode[k].share[GAL_FAMILY_HORIZONTAL]);
    printf("    (eccentric ice: the torsional mode carries %.2g of its kinetic energy in translation)\n", mix);
    CHECK(mix > 1e-4, "eccentric ice must couple twist and translation");
    gal_modes_clear(&md);
    gal_equilibrium_clear(&eq);
    for (int fam = 0; fam < 3; fam++) {
        run_result r = free_vibration(fam, 1e-3, 30, 40, 1.0, 0);
        printf("    (eccentric ice, %s: energy drift %.2e)\n", gal_family_names[fam], r.energy_drift);
        CHECK(r.finite && fabs(r.energy_drift) < 1e-3, "energy %g", r.energy_drift);
    }
    eccentric = 0;
}

/* The modal coordinate at t_end of a free vibration started by the velocity of mode k, step h. */
static double refine_run(const gal_equilibrium *eq, const gal_modes *md, int k, double h, double t_end)
{
    const gal_rod *rod = eq->rod;
    int n = rod->ndof, nq = rod->nq;
    const double *phi = md->shape + (size_t)k * n;
    double *v0 = calloc(nq, sizeof(double)), *mphi = malloc(n * sizeof(double)), big = 0;
    for (int j = 0; j < n; j++) big = fmax(big, fabs(phi[j]));
    for (int j = 0; j < n; j++) v0[rod->free_q[j]] = md->mode[k].omega * 1e-3 * phi[j] / big; /* 1 mm */
    gal_rod_mass_mult(rod, phi, mphi);
    gal_dyn_opts o;
    gal_dyn_default_opts(&o);
    o.h = h;
    gal_dyn *d = gal_dyn_alloc(rod, eq->q, v0, &o, NULL);
    CHECK(d != NULL, "%s", gal_error_message());
    double eta = NAN;
    long ns = (long)floor(t_end / h + 0.5), s = 0;
    while (d && s < ns && gal_dyn_step(d) == GAL_OK) s++;
    CHECK(d && s == ns, "h = %g s: %s", h, gal_error_message());
    if (d && s == ns) {
        eta = 0;
        for (int j = 0; j < n; j++) eta += mphi[j] * (d->q[rod->free_q[j]] - eq->q[rod->free_q[j]]);
    }
    gal_dyn_free(d);
    free(v0);
    free(mphi);
    return eta;
}

/* Refining the step, the way to check convergence (issue 14): the same free vibration at h = 1e-3,
 * 1e-4 and 1e-5 s (the 12th mode, 3.4 Hz, for 0.2 s) converges at the method's second order: the differences to
 * the finest shrink 100-fold per decade (the convergence test has a round-off floor for the
 * inertia term, which grows as 1/h^2). */
static void test_step_refinement(void)
{
    gal_rod_params p = span(30);
    gal_equilibrium eq;
    gal_modes md;
    CHECK(gal_statics_solve(&p, GAL_BY_TENSION, 20000, NULL, &eq) == GAL_OK, "%s", gal_error_message());
    CHECK(gal_modes_solve(eq.rod, eq.q, 12, &md) == GAL_OK, "%s", gal_error_message());
    int k = md.n - 1; /* the highest of them, ~3.4 Hz */
    double e[3], hs[3] = {1e-3, 1e-4, 1e-5};
    for (int i = 0; i < 3; i++) e[i] = refine_run(&eq, &md, k, hs[i], 0.2);
    double d0 = fabs(e[0] - e[2]), d1 = fabs(e[1] - e[2]), order = log10(d0 / d1);
    printf("    (mode %d, %.3f Hz: eta at 0.2 s %.10g, %.10g, %.10g; differences to h = 1e-5 s %.3g, %.3g: "
           "order %.3f)\n", k + 1, md.mode[k].frequency_hz, e[0], e[1], e[2], d0, d1, order);
    CHECK(fabs(order - 2) < 0.1, "order %g, not 2", order);
    gal_modes_clear(&md);
    gal_equilibrium_clear(&eq);
}

/* issue 14: the sign of the ice's mass coupling, from the kinetic energy of the ice centre: it
 * moves at xdot + e thetadot (t x c); with the nodes moving along t x c, a positive twist rate
 * adds to its speed, a negative one subtracts: 1/2 v^T M v is larger for thetadot > 0, by
 * 2 m_i e |xdot| |thetadot| l0 (both nodes' halves of the edge). */
static void test_eccentric_ice_mass_sign(void)
{
    eccentric = 1;
    gal_rod_params p = span(30);
    eccentric = 0;
    gal_equilibrium eq;
    CHECK(gal_statics_solve(&p, GAL_BY_TENSION, 20000, NULL, &eq) == GAL_OK, "%s", gal_error_message());
    const gal_rod *rod = eq.rod;
    CHECK(rod->ecc_c != NULL, "no eccentric ice");
    if (!rod->ecc_c) { gal_equilibrium_clear(&eq); return; }
    int n = rod->ndof, j = rod->p.elements / 2;
    double *v = calloc((size_t)n, sizeof(double)), *y = calloc((size_t)n, sizeof(double)), T[2], g[3];
    const double *t = rod->tbar + 3 * j, *c = rod->ecc_c + 3 * j;
    g[0] = t[1] * c[2] - t[2] * c[1], g[1] = t[2] * c[0] - t[0] * c[2], g[2] = t[0] * c[1] - t[1] * c[0];
    for (int sgn = 0; sgn < 2; sgn++) {
        memset(v, 0, (size_t)n * sizeof(double));
        for (int node = j; node <= j + 1; node++)
            for (int k = 0; k < 3; k++)
                if (rod->dof[3 * node + k] >= 0) v[rod->dof[3 * node + k]] = g[k];
        v[rod->dof[3 * rod->nn + j]] = sgn ? -1.0 : 1.0;
        gal_rod_mass_mult(rod, v, y);
        T[sgn] = 0;
        for (int d = 0; d < n; d++) T[sgn] += 0.5 * v[d] * y[d];
    }
    double want = 2 * p.ecc_mass * p.ecc * rod->l0[j];
    CHECK_REL(T[0] - T[1], want, 1e-9);
    free(v);
    free(y);
    gal_equilibrium_clear(&eq);
}

int main(void)
{
    RUN(test_small_vibration_frequency_and_energy);
    RUN(test_large_vibration_bounded);
    RUN(test_eccentric_ice_coupling);
    RUN(test_step_refinement);
    RUN(test_eccentric_ice_mass_sign);
    return CHECK_SUMMARY();
}
