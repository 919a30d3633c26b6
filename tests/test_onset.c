/* test_onset.c: the galloping onset of the coupled aeroelastic system (issue 15): Den Hartog's
 * closed form for one vertical mode with torsion off; the structural damping ratio of every mode at
 * zero wind; the aerodynamic matrices against differences of the full model's loads; convergence
 * with the basis; the issue's measurement (the full model's growth rates change sign at 3.19 m/s
 * on iced_gallop.ini with torsion off); and a coupled case whose full-model growth rates just
 * below and just above the predicted onset have opposite signs. */
#include "check.h"
#include "gallop.h"
#include "gallop/analysis/onset.h"
#include "gallop/analysis/stability.h"
#include "gallop/run/sim.h"

typedef struct {
    gal_scene sc;
    gal_sim_setup s;
    const gal_damping *C; /* the pipeline's (modal), or own */
    gal_damping *own;
    double mass;
} fixture;

/* The scene with overrides; damping: 0 the pipeline's, which the dynamic models apply (modal: the
 * scene's ratio at every mode of the band), 1 the Rayleigh fit they applied before issue 15 (zeta at
 * the lowest and highest selected modes). */
static int fixture_init(fixture *f, const char *const *ov, int n, int rayleigh)
{
    memset(f, 0, sizeof *f);
    int st = gal_scene_load(&f->sc, "data/scenes/iced_gallop.ini", ov, n, NULL);
    if (!st) st = gal_sim_setup_init(&f->s, &f->sc, 1);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (st) return st;
    const gal_modes *md = &f->s.data->md;
    double wmin = INFINITY, wmax = 0, zeta = f->sc.conductor.damping_ratio, a, b;
    for (int k = 0; k < md->n; k++)
        if (md->mode[k].selected) wmin = fmin(wmin, md->mode[k].omega), wmax = fmax(wmax, md->mode[k].omega);
    if (rayleigh) {
        gal_damping_rayleigh_fit(zeta, wmin, wmax, &a, &b);
        f->C = f->own = gal_damping_rayleigh_alloc(f->s.data->eq.rod, f->s.data->eq.q, a, b);
    } else f->C = f->s.data->damping;
    CHECK(f->C != NULL, "%s", gal_error_message());
    f->mass = f->sc.conductor.mass_per_length + f->sc.ice.mass_per_length;
    return f->C ? GAL_OK : GAL_EFAIL;
}

static void fixture_clear(fixture *f)
{
    gal_damping_free(f->own);
    gal_sim_setup_clear(&f->s);
}

static int analyse(fixture *f, gal_onset_opts *o, gal_onset *r)
{
    int st = gal_onset_analyse(f->s.data->eq.rod, f->s.data->eq.q, &f->s.data->loads, f->C, f->mass, o, r);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    return st;
}

/* Torsion off, one vertical mode in the basis: Den Hartog's U_c = -4 m zeta w / (rho d H) with the
 * applied modal damping, to 0.5%. */
static void test_den_hartog_one_vertical_mode(void)
{
    fixture f;
    const char *ov[] = {"effects.torsion=off"};
    if (fixture_init(&f, ov, 1, 0)) return;
    gal_onset_opts o;
    gal_onset_default_opts(&o);
    o.speed_min = 0, o.speed_max = 6, o.speed_step = 0.5, o.basis = 1, o.nmodes = 1;
    o.families = 1u << GAL_FAMILY_VERTICAL;
    gal_onset r;
    if (!analyse(&f, &o, &r)) {
        double w = 0;
        for (int k = 0; k < f.s.data->md.n && w == 0; k++)
            if (f.s.data->md.mode[k].family == GAL_FAMILY_VERTICAL) w = f.s.data->md.mode[k].omega;
        const gal_loads *L = &f.s.data->loads;
        double uc = gal_stability_onset(L->table, L->attack_angle, f.mass, 0.003, w, L->rho, L->diam);
        printf("    (onset %.5g m/s, Den Hartog %.5g m/s, mode %.4f Hz)\n", r.onset_speed, uc, r.onset_frequency_hz);
        CHECK_REL(r.onset_speed, uc, 5e-3);
        CHECK_REL(r.onset_frequency_hz, w / (2 * GAL_PI), 1e-3);
        CHECK(r.onset_share[0] > 0.99, "vertical share %.4f", r.onset_share[0]);
        gal_onset_clear(&r);
    }
    fixture_clear(&f);
}

/* At zero wind every followed mode has the structural damping ratio: zeta (modal), and the
 * Rayleigh ratio alpha/(2w) + beta w/2 of its frequency. */
static void test_zero_wind_structural_ratio(void)
{
    for (int ray = 0; ray < 2; ray++) {
        fixture f;
        if (fixture_init(&f, NULL, 0, ray)) return;
        gal_onset_opts o;
        gal_onset_default_opts(&o);
        o.speed_min = o.speed_max = 0;
        gal_onset r;
        if (!analyse(&f, &o, &r)) {
            double worst = 0;
            for (int k = 0; k < r.nmodes; k++) {
                double w = 2 * GAL_PI * r.m[k].frequency_hz, z = r.m[k].damping_ratio;
                /* lambda = -zeta w0 + i w0 sqrt(1 - zeta^2): w is the damped frequency */
                double w0 = w / sqrt(1 - z * z), want = ray ? f.C->alpha / (2 * w0) + f.C->beta * w0 / 2 : 0.003;
                worst = fmax(worst, fabs(z - want) / want);
            }
            printf("    (%s: %d modes, worst relative error %.2g)\n", ray ? "Rayleigh" : "modal", r.nmodes, worst);
            /* the basis modes are ARPACK's again at this configuration: round-off of its shapes */
            CHECK(worst < 1e-6, "%s damping: ratio off by %.3g", ray ? "Rayleigh" : "modal", worst);
            gal_onset_clear(&r);
        }
        fixture_clear(&f);
    }
}

/* The projected aerodynamic matrices against central differences of gal_loads_full along the
 * basis vectors (a different code path and step), on the twisted span at 12 m/s. */
static void test_aero_matrices(void)
{
    fixture f;
    const char *ov[] = {"model.elements=30", "wind.speed=12"};
    if (fixture_init(&f, ov, 2, 0)) return;
    gal_rod *rod = f.s.data->eq.rod;
    int nq = rod->nq, n = rod->ndof, nb = 8, it = 0;
    double *q = malloc(6 * (size_t)nq * sizeof(double)), *v = q + nq, *qp = v + nq, *fp = qp + nq, *fm = fp + nq;
    double *dv = fm + nq, Ka[64], Ca[64];
    gal_loads L = f.s.data->loads;
    L.ramp_time = 0; /* the mean wind at full speed */
    memcpy(q, f.s.data->eq.q, nq * sizeof(double));
    CHECK(gal_loads_static(rod, q, &L, 1e-4, 200, &it) == GAL_OK, "%s", gal_error_message());
    gal_modes md;
    CHECK(gal_modes_solve(rod, q, nb, &md) == GAL_OK, "%s", gal_error_message());
    CHECK(gal_onset_aero_matrices(rod, q, &L, md.shape, nb, Ka, Ca) == GAL_OK, "%s", gal_error_message());
    double errk = 0, errc = 0, sk = 0, sc = 0;
    for (int b = 0; b < nb; b++)
        for (int pass = 0; pass < 2; pass++) {
            double h = pass ? 1e-3 : 1e-4, *M = pass ? Ca : Ka;
            memset(dv, 0, nq * sizeof(double));
            gal_rod_scatter(rod, md.shape + (size_t)b * n, dv);
            for (int sgn = 0; sgn < 2; sgn++) {
                double s = sgn ? -h : h, *out = sgn ? fm : fp;
                for (int k = 0; k < nq; k++) qp[k] = q[k] + (pass ? 0 : s * dv[k]), v[k] = pass ? s * dv[k] : 0;
                memset(out, 0, nq * sizeof(double));
                gal_loads_full(&L, 0, qp, v, out);
            }
            for (int a = 0; a < nb; a++) {
                double d = 0;
                for (int j = 0; j < n; j++) d -= md.shape[(size_t)a * n + j] * (fp[rod->free_q[j]] - fm[rod->free_q[j]]) / (2 * h);
                double e = fabs(d - M[(size_t)b * nb + a]);
                if (pass) errc = fmax(errc, e), sc = fmax(sc, fabs(d));
                else errk = fmax(errk, e), sk = fmax(sk, fabs(d));
            }
        }
    printf("    (K_aero: max %.4g, error %.2g; C_aero: max %.4g, error %.2g)\n", sk, errk, sc, errc);
    CHECK(errk <= 1e-5 * sk, "aerodynamic stiffness off by %.3g of %.3g", errk, sk);
    CHECK(errc <= 1e-6 * sc, "aerodynamic damping off by %.3g of %.3g", errc, sc);
    gal_modes_clear(&md);
    free(q);
    fixture_clear(&f);
}

/* The onset converges with the basis: 20 and 40 natural modes agree (torsion on: the torsional
 * modes come in above the 10th). */
static void test_basis_convergence(void)
{
    fixture f;
    if (fixture_init(&f, NULL, 0, 0)) return;
    double u[3];
    int nbs[3] = {10, 20, 40};
    for (int k = 0; k < 3; k++) {
        gal_onset_opts o;
        gal_onset_default_opts(&o);
        o.speed_min = 2.5, o.speed_max = 4.5, o.speed_step = 0.25, o.basis = nbs[k];
        gal_onset r;
        u[k] = NAN;
        if (!analyse(&f, &o, &r)) u[k] = r.onset_speed, gal_onset_clear(&r);
    }
    printf("    (onset with 10, 20, 40 modes: %.5g, %.5g, %.5g m/s)\n", u[0], u[1], u[2]);
    CHECK_REL(u[1], u[2], 1e-4);
    fixture_clear(&f);
}

/* The issue's measurement: iced_gallop.ini with torsion off, the damping the full model applied
 * before issue 15 (Rayleigh over the selected modes): the full model's growth rates change sign at 3.19 m/s
 * (`gallop stability`, with the nominal ratio, said 3.58). */
static void test_issue_measurement(void)
{
    fixture f;
    const char *ov[] = {"effects.torsion=off"};
    if (fixture_init(&f, ov, 1, 1)) return;
    gal_onset_opts o;
    gal_onset_default_opts(&o);
    o.speed_min = 0, o.speed_max = 6;
    gal_onset r;
    if (!analyse(&f, &o, &r)) {
        printf("    (onset %.4g m/s, %.4f Hz; Den Hartog with the applied ratio %.4g: %.4g m/s)\n", r.onset_speed,
               r.onset_frequency_hz, r.sp[0].zeta_vertical, r.sp[0].den_hartog_onset);
        CHECK_NEAR(r.onset_speed, 3.19, 0.01);
        CHECK_REL(r.onset_speed, r.sp[0].den_hartog_onset, 5e-3);
        gal_onset_clear(&r);
    }
    fixture_clear(&f);
}

/* Growth rate (1/s) of the vertical motion at the quarter-span probe of a full-model run: the
 * slope of the log of the window maxima over the second half of the run. */
static double growth_rate(const gal_sim_result *r)
{
    int k = 1, np = r->nprobe; /* probes 0.5, 0.25: the quarter span sees the antisymmetric modes */
    long n0 = r->nsamples / 3, win = (long)(10.0 / r->dt_out);
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int m = 0;
    for (long a = n0; a + win <= r->nsamples; a += win, m++) {
        double mx = 0, mean = 0;
        for (long i = a; i < a + win; i++) mean += r->trace[(size_t)i * 4 * np + 4 * k + 1] / win;
        for (long i = a; i < a + win; i++) mx = fmax(mx, fabs(r->trace[(size_t)i * 4 * np + 4 * k + 1] - mean));
        double t = r->time[a + win / 2], y = log(mx);
        sx += t, sy += y, sxx += t * t, sxy += t * y;
    }
    return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

/* A coupled case (torsion on, the damping the full model applies): the full model's growth rates
 * just below and just above the predicted onset have opposite signs. */
static void test_full_model_across_onset(void)
{
    const char *ov[] = {"model.elements=40", "simulation.duration=150", NULL};
    fixture f;
    if (fixture_init(&f, ov, 2, 0)) return;
    gal_onset_opts o;
    gal_onset_default_opts(&o);
    o.speed_min = 2, o.speed_max = 5, o.speed_step = 0.25;
    gal_onset r;
    double uc = NAN;
    if (!analyse(&f, &o, &r)) uc = r.onset_speed, gal_onset_clear(&r);
    fixture_clear(&f);
    CHECK(isfinite(uc), "no onset predicted below 5 m/s");
    if (!isfinite(uc)) return;
    double g[2];
    char sp[64];
    for (int k = 0; k < 2; k++) {
        snprintf(sp, sizeof sp, "wind.speed=%.6g", uc * (k ? 1.1 : 0.9));
        ov[2] = sp;
        gal_scene sc;
        gal_sim_setup s;
        gal_sim_result res;
        g[k] = NAN;
        if (gal_scene_load(&sc, "data/scenes/iced_gallop.ini", ov, 3, NULL) || gal_sim_setup_init(&s, &sc, 1)) {
            CHECK(0, "%s", gal_error_message());
            return;
        }
        CHECK(gal_sim_run(&s, GAL_MODEL_FULL, &res) == GAL_OK, "%s", gal_error_message());
        if (res.nsamples) g[k] = growth_rate(&res);
        gal_sim_result_clear(&res);
        gal_sim_setup_clear(&s);
    }
    printf("    (predicted onset %.4g m/s; full-model growth rate %.3g 1/s at %.4g m/s, %.3g 1/s at %.4g m/s)\n", uc,
           g[0], 0.9 * uc, g[1], 1.1 * uc);
    CHECK(g[0] < 0 && g[1] > 0, "growth rates %.3g below and %.3g above the onset", g[0], g[1]);
}

int main(void)
{
    RUN(test_den_hartog_one_vertical_mode);
    RUN(test_zero_wind_structural_ratio);
    RUN(test_aero_matrices);
    RUN(test_basis_convergence);
    RUN(test_issue_measurement);
    RUN(test_full_model_across_onset);
    return CHECK_SUMMARY();
}
