/* test_rom.c: the recomputed reduced model (rom.h): Kirchhoff-Carrier coefficient of a taut string
 * from the modes and modal derivatives, the full model's damping at every mode, reduced forces and
 * tangent against the projected full ones, energy over 1000 periods, symmetry kept, and one short
 * span of tests/rom/ against the full model. */
#include "check.h"
#include "gallop.h"
#include "gallop/modes/modes.h"
#include "gallop/output/simreport.h"
#include "gallop/reduced/rom.h"
#include "gallop/reduced/rom_sim.h"
#include "gallop/statics/statics.h"

typedef struct {
    gal_equilibrium eq;
    gal_modes md;
    int sel[16], r;
} span;

static int make_span(span *s, const gal_rod_params *p, gal_statics_spec spec, double value, const int want[GAL_FAMILY_COUNT])
{
    memset(s, 0, sizeof *s);
    if (gal_statics_solve(p, spec, value, NULL, &s->eq) || gal_modes_find(s->eq.rod, s->eq.q, want, 60, &s->md)) {
        CHECK(0, "%s", gal_error_message());
        return 1;
    }
    for (int k = 0; k < s->md.n && s->r < 16; k++)
        if (s->md.mode[k].selected) s->sel[s->r++] = k;
    return 0;
}

static void free_span(span *s)
{
    gal_modes_clear(&s->md);
    gal_equilibrium_clear(&s->eq);
}

/* Taut string: holding the first mode at eta with the modal-derivative coordinates relaxed
 * (their reduced force zero), f_1 = w^2 eta + k eta^3 with Kirchhoff-Carrier's k = EA pi^4 /
 * (2 m^2 L^5) (the quasi-static stretching); the first mode alone is much stiffer. */
static void test_kirchhoff_carrier(void)
{
    double L = 100, T0 = 1e4, mass = 1.0, EA = 1e7;
    gal_rod_params p = {.length = L, .elements = 60, .EA = EA, .EI = 0, .GJ = 1, .mass = mass,
                        .polar_inertia = 1e-4, .gravity = 0, .torsion = 0, .twist_clamped = 1};
    span s;
    int want[GAL_FAMILY_COUNT] = {0, 1, 0, 0};
    if (make_span(&s, &p, GAL_BY_TENSION, T0, want)) return;
    gal_rom *m = gal_rom_alloc(s.eq.rod, s.eq.q, &s.md, s.sel, 1, NULL, NULL);
    CHECK(m != NULL, "%s", gal_error_message());
    if (!m) { free_span(&s); return; }
    int r = m->r;
    CHECK(r >= 2, "a modal derivative joins the basis (r = %d)", r);
    double ms = mass * s.eq.unstretched_length / L, kc = EA * pow(GAL_PI, 4) / (2 * ms * ms * pow(L, 5));
    double eta = 0.5 * sqrt(ms * L / 2); /* 0.5 m at mid-span */
    double x[8] = {eta}, f[8], fp[8], J[64];
    for (int it = 0; it < 20; it++) { /* Newton on x[1..r-1]: f[1..r-1] = 0 */
        CHECK(gal_rom_internal_force(m, x, f) == GAL_OK, "%s", gal_error_message());
        double rn = 0;
        for (int i = 1; i < r; i++) rn = fmax(rn, fabs(f[i]));
        if (rn < 1e-9 * fabs(f[0])) break;
        for (int j = 1; j < r; j++) {
            double hj = 1e-6 * eta;
            x[j] += hj;
            gal_rom_internal_force(m, x, fp);
            x[j] -= hj;
            for (int i = 1; i < r; i++) J[(i - 1) * (r - 1) + j - 1] = (fp[i] - f[i]) / hj;
        }
        /* Gauss elimination on the (r-1) x (r-1) system */
        int n1 = r - 1;
        double b[8];
        for (int i = 0; i < n1; i++) b[i] = -f[i + 1];
        for (int k = 0; k < n1; k++)
            for (int i = k + 1; i < n1; i++) {
                double l = J[i * n1 + k] / J[k * n1 + k];
                for (int j = k; j < n1; j++) J[i * n1 + j] -= l * J[k * n1 + j];
                b[i] -= l * b[k];
            }
        for (int k = n1 - 1; k >= 0; k--) {
            for (int j = k + 1; j < n1; j++) b[k] -= J[k * n1 + j] * b[j];
            x[k + 1] += b[k] / J[k * n1 + k];
        }
    }
    double k_rel = (f[0] - m->omega2[0] * eta) / pow(eta, 3);
    double xl[8] = {eta}, fl[8];
    gal_rom_internal_force(m, xl, fl);
    double k_lin = (fl[0] - m->omega2[0] * eta) / pow(eta, 3);
    printf("    (cubic coefficient: relaxed on the modal derivative %.4f x Kirchhoff-Carrier, mode alone %.3f x)\n",
           k_rel / kc, k_lin / kc);
    CHECK_REL(k_rel, kc, 2e-2);
    CHECK(k_lin > 1.3 * kc, "the linear mode alone should be too stiff: %g vs %g", k_lin, kc);
    gal_rom_free(m);
    free_span(&s);
}

static const gal_rod_params sagged = {.length = 150, .elements = 24, .EA = 3e7, .EI = 30, .GJ = 200, .mass = 1.6,
                                      .polar_inertia = 1.6e-4, .gravity = 9.80665, .torsion = 1, .twist_clamped = 1};

/* Damping is the full model's at every mode: Phi^T (a M + b K0) Phi = a I + b diag(w^2); reduced
 * force equals the projected full gradient (exactly) and the reduced tangent its derivative. */
static void test_damping_forces_tangent(void)
{
    span s;
    int want[GAL_FAMILY_COUNT] = {3, 2, 1, 0};
    if (make_span(&s, &sagged, GAL_BY_SAG, 4.0, want)) return;
    gal_rom_opts o;
    gal_rom_default_opts(&o);
    double ra = 0.05, rb = 0.002;
    gal_damping *C = gal_damping_rayleigh_alloc(s.eq.rod, s.eq.q, ra, rb);
    o.damping = C;
    o.hyper = 0; /* every element: the Galerkin projection exactly (test_ecsw.c: the sampled one) */
    gal_rom *m = gal_rom_alloc(s.eq.rod, s.eq.q, &s.md, s.sel, s.r, &o, NULL);
    CHECK(m != NULL, "%s", gal_error_message());
    if (!m) { gal_damping_free(C); free_span(&s); return; }
    int r = m->r, nm = m->nmodes, n = m->ndof, nq = m->nq;
    for (int i = 0; i < nm; i++)
        for (int j = 0; j < nm; j++) {
            double want_c = i == j ? ra + rb * m->omega2[i] : 0;
            CHECK_NEAR(m->Cr[i * r + j], want_c, 1e-7 * (ra + rb * m->omega2[nm - 1]));
        }
    /* a large state: 1 m of each mode's largest entry plus modal-derivative content */
    double *x = calloc(r, sizeof(double)), *f = malloc(r * sizeof(double)), *fp = malloc(r * sizeof(double));
    double *fm = malloc(r * sizeof(double)), *g = malloc(nq * sizeof(double)), *q = malloc(nq * sizeof(double));
    double *Kr = malloc((size_t)r * r * sizeof(double)), *w = malloc(n * sizeof(double));
    for (int k = 0; k < r; k++) x[k] = (k < nm ? 1.0 : 0.1) * sqrt(sagged.mass * sagged.length) / (k + 1);
    CHECK(gal_rom_internal_force(m, x, f) == GAL_OK, "%s", gal_error_message());
    memcpy(m->x, x, r * sizeof(double));
    gal_rom_reconstruct(m, q, NULL);
    gal_csc *K = gal_csc_clone(s.eq.rod->K);
    gal_rod_eval(s.eq.rod, q, NULL, g, K);
    double fmax_ = 0, err = 0;
    for (int k = 0; k < r; k++) {
        double pr = 0;
        for (int d = 0; d < n; d++) pr += m->V[(size_t)k * n + d] * g[s.eq.rod->free_q[d]];
        err = fmax(err, fabs(pr - f[k])), fmax_ = fmax(fmax_, fabs(f[k]));
    }
    CHECK(err <= 1e-12 * fmax_, "reduced force = V^T grad U at the reconstructed state: %g of %g", err, fmax_);
    /* tangent: central differences of the reduced force, O(h^2) */
    gal_rom_project_tangent(m, K, Kr, w);
    double terr = 0, tmax = 0;
    for (int j = 0; j < r; j++) {
        double hj = 1e-4 * fabs(x[0]);
        x[j] += hj, gal_rom_internal_force(m, x, fp);
        x[j] -= 2 * hj, gal_rom_internal_force(m, x, fm);
        x[j] += hj;
        for (int i = 0; i < r; i++) {
            double fd = (fp[i] - fm[i]) / (2 * hj);
            terr = fmax(terr, fabs(fd - Kr[i * r + j])), tmax = fmax(tmax, fabs(Kr[i * r + j]));
        }
    }
    printf("    (basis %d = %d modes + %d modal derivatives; tangent vs differences %.1e relative)\n", r, nm, r - nm,
           terr / tmax);
    CHECK(terr <= 1e-6 * tmax, "reduced tangent vs central differences: %g of %g", terr, tmax);
    gal_csc_free(K);
    free(x); free(f); free(fp); free(fm); free(g); free(q); free(Kr); free(w);
    gal_rom_free(m);
    gal_damping_free(C);
    free_span(&s);
}

/* Free vibration (no damping, no wind) of the first symmetric vertical mode at a large amplitude
 * on a level span without eccentric ice: the energy drifts less than 1e-3 of the motion's over
 * 1000 periods, and the motion stays symmetric (antisymmetric part at round-off). */
static void test_energy_and_symmetry(void)
{
    span s;
    int want[GAL_FAMILY_COUNT] = {2, 1, 0, 0};
    gal_rod_params p = sagged;
    p.elements = 16, p.torsion = 0;
    if (make_span(&s, &p, GAL_BY_SAG, 4.0, want)) return;
    gal_rom_opts o;
    gal_rom_default_opts(&o);
    int k1 = -1;
    for (int k = 0; k < s.r; k++)
        if (k1 < 0 && s.md.mode[s.sel[k]].family == GAL_FAMILY_VERTICAL && s.md.mode[s.sel[k]].symmetry == GAL_SYM_SYMMETRIC) k1 = k;
    CHECK(k1 >= 0, "a symmetric vertical mode");
    if (k1 < 0) { free_span(&s); return; }
    double w1 = s.md.mode[s.sel[k1]].omega;
    o.h = 2 * GAL_PI / w1 / 32;
    gal_rom *m = gal_rom_alloc(s.eq.rod, s.eq.q, &s.md, s.sel, s.r, &o, NULL);
    CHECK(m != NULL, "%s", gal_error_message());
    if (!m) { free_span(&s); return; }
    double U0 = gal_rom_energy(m);
    m->x[k1] = 0.15 * sqrt(p.mass * p.length); /* about 0.2 m at mid-span, a twentieth of the sag (at
                                                * 0.7 m the drift is 7e-3: not yet an energy-conserving scheme) */
    /* start from the reconstructed full state (gal_rom_start projects it) */
    int nq = m->nq, nn = s.eq.rod->nn;
    double *q = malloc(nq * sizeof(double));
    gal_rom_reconstruct(m, q, NULL);
    CHECK(gal_rom_start(m, 0, q, NULL) == GAL_OK, "%s", gal_error_message());
    double E0 = gal_rom_energy(m), drift = 0, asym = 0, sym = 0;
    for (int per = 0; per < 1000; per++) {
        if (gal_rom_advance(m, (per + 1) * 2 * GAL_PI / w1)) { CHECK(0, "%s", gal_error_message()); break; }
        if (per % 50 == 49) drift = fmax(drift, fabs(gal_rom_energy(m) - E0));
        gal_rom_reconstruct(m, q, NULL);
        for (int i = 0; i < nn / 2; i++) {
            int j = nn - 1 - i;
            double a = (q[3 * i + 2] - s.eq.q[3 * i + 2]) - (q[3 * j + 2] - s.eq.q[3 * j + 2]);
            asym = fmax(asym, fabs(a) + fabs(q[3 * i + 1]) + fabs(q[3 * j + 1]));
            sym = fmax(sym, fabs(q[3 * i + 2] - s.eq.q[3 * i + 2]));
        }
    }
    printf("    (1000 periods, %ld steps: energy drift %.2e of the motion's energy; antisymmetric part %.1e of %.2f m)\n",
           m->steps, drift / (E0 - U0), asym, sym);
    /* the 1e-3: the discrete-gradient step conserves T + U to Newton's tolerance (it was
     * 3.5e-3 with the trapezoidal forces) */
    CHECK(drift < 1e-3 * (E0 - U0), "energy drift %g of %g", drift, E0 - U0);
    CHECK(asym < 1e-9 * sym, "antisymmetric part %g of %g", asym, sym);
    free(q);
    gal_rom_free(m);
    free_span(&s);
}

/* The short span of tests/rom/ against the full model on the same wind and window. */
static void test_short_span_against_full(void)
{
    gal_scene sc;
    if (gal_scene_load(&sc, "tests/rom/condor_150_taut_dshape.ini", NULL, 0, "data/conductors.csv")) {
        CHECK(0, "%s", gal_error_message());
        return;
    }
    gal_sim_setup s;
    CHECK(gal_sim_setup_init(&s, &sc, 1) == GAL_OK, "%s", gal_error_message());
    gal_sim_result rf, rr;
    gal_rom_sim_info info;
    CHECK(gal_sim_run(&s, GAL_MODEL_FULL, &rf) == GAL_OK, "%s", gal_error_message());
    CHECK(gal_rom_sim_run(&s, NULL, &rr, &info) == GAL_OK, "%s", gal_error_message());
    gal_compare_ref h; /* measured as `gallop compare` measures */
    gal_sim_measures mf, mr;
    CHECK(gal_compare_reference(&rf, -1, &h) == GAL_OK && gal_compare_measure(&rf, &h, &mf) == GAL_OK &&
          gal_compare_measure(&rr, &h, &mr) == GAL_OK, "%s", gal_error_message());
    printf("    (f %.4f / %.4f Hz, vertical %.3f / %.3f m, horizontal %.3f / %.3f m, twist %.2f / %.2f deg, "
           "T %.0f / %.0f N; residual %.3f; basis %d)\n", mr.frequency_hz[1], mf.frequency_hz[1], mr.peak_to_peak[1],
           mf.peak_to_peak[1], mr.peak_to_peak[0], mf.peak_to_peak[0], mr.peak_to_peak[3], mf.peak_to_peak[3],
           mr.tension_max, mf.tension_max, info.residual_max, info.basis);
    CHECK_REL(mr.frequency_hz[1], mf.frequency_hz[1], 1e-2);
    CHECK_REL(mr.peak_to_peak[1], mf.peak_to_peak[1], 5e-2);
    CHECK_NEAR(mr.peak_to_peak[0], mf.peak_to_peak[0], fmax(5e-2 * mf.peak_to_peak[0], 2e-2 * mf.peak_to_peak[1]));
    CHECK_NEAR(mr.peak_to_peak[3], mf.peak_to_peak[3], fmax(5e-2 * mf.peak_to_peak[3], 3.0));
    CHECK_REL(mr.tension_max, mf.tension_max, 5e-2);
    CHECK(info.checks > 10 && info.residual_max < 0.1, "residual %g over %d checks", info.residual_max, info.checks);
    gal_sim_result_clear(&rf);
    gal_sim_result_clear(&rr);
    gal_sim_setup_clear(&s);
}

/* A step whose Newton cannot converge (one iteration allowed, the modal derivatives unrelaxed at
 * 1 m) is retried in halves GAL_ROM_HALVINGS deep, then fails naming them, the state unchanged. */
static void test_step_halving(void)
{
    span s;
    int want[GAL_FAMILY_COUNT] = {2, 1, 0, 0};
    gal_rod_params p = sagged;
    p.elements = 16, p.torsion = 0;
    if (make_span(&s, &p, GAL_BY_SAG, 4.0, want)) return;
    gal_rom_opts o;
    gal_rom_default_opts(&o);
    o.h = 2 * GAL_PI / s.md.mode[s.sel[0]].omega / 4, o.max_newton = 1;
    gal_rom *m = gal_rom_alloc(s.eq.rod, s.eq.q, &s.md, s.sel, s.r, &o, NULL);
    CHECK(m != NULL, "%s", gal_error_message());
    if (!m) { free_span(&s); return; }
    m->x[0] = 0.8 * sqrt(p.mass * p.length);
    double *q = malloc(m->nq * sizeof(double));
    gal_rom_reconstruct(m, q, NULL);
    CHECK(gal_rom_start(m, 0, q, NULL) == GAL_OK, "%s", gal_error_message());
    double x0 = m->x[0];
    CHECK(gal_rom_step(m) == GAL_EFAIL, "a step of one Newton iteration should fail");
    CHECK(strstr(gal_error_message(), "step halvings") != NULL, "%s", gal_error_message());
    CHECK(m->halvings >= GAL_ROM_HALVINGS, "halvings %ld", m->halvings);
    CHECK(m->t == 0 && m->x[0] == x0 && m->steps == 0, "the state changed: t = %g", m->t);
    free(q);
    gal_rom_free(m);
    free_span(&s);
}


/* The quadratic manifold (o.manifold): on the taut string the first mode's coordinate alone
 * carries Kirchhoff-Carrier's cubic (the stretching rides on the manifold); its reduced force is
 * P(x)^T grad U at the reconstructed state (exactly, every element) and its tangent the force's
 * derivative; undamped and unloaded, the energy drifts less than 1e-3 over 1000 periods (with the
 * sampled elements). */
static void test_manifold(void)
{
    double L = 100, T0 = 1e4, mass = 1.0, EA = 1e7;
    gal_rod_params p = {.length = L, .elements = 60, .EA = EA, .EI = 0, .GJ = 1, .mass = mass,
                        .polar_inertia = 1e-4, .gravity = 0, .torsion = 0, .twist_clamped = 1};
    span s;
    int want[GAL_FAMILY_COUNT] = {0, 1, 0, 0};
    if (make_span(&s, &p, GAL_BY_TENSION, T0, want)) return;
    gal_rom_opts o;
    gal_rom_default_opts(&o);
    o.manifold = 1, o.hyper = 0;
    gal_rom *m = gal_rom_alloc(s.eq.rod, s.eq.q, &s.md, s.sel, 1, &o, NULL);
    CHECK(m != NULL && m->r == 1, "%s", gal_error_message());
    if (m) {
        double ms = mass * s.eq.unstretched_length / L, kc = EA * pow(GAL_PI, 4) / (2 * ms * ms * pow(L, 5));
        double eta = 0.5 * sqrt(ms * L / 2), f;
        CHECK(gal_rom_internal_force(m, &eta, &f) == GAL_OK, "%s", gal_error_message());
        double k = (f - m->omega2[0] * eta) / pow(eta, 3);
        printf("    (manifold: cubic coefficient %.4f x Kirchhoff-Carrier)\n", k / kc);
        CHECK_REL(k, kc, 2e-2);
        gal_rom_free(m);
    }
    free_span(&s);
    /* the sagged span with torsion: force and tangent */
    int want2[GAL_FAMILY_COUNT] = {3, 2, 1, 0};
    if (make_span(&s, &sagged, GAL_BY_SAG, 4.0, want2)) return;
    m = gal_rom_alloc(s.eq.rod, s.eq.q, &s.md, s.sel, s.r, &o, NULL);
    CHECK(m != NULL, "%s", gal_error_message());
    if (!m) { free_span(&s); return; }
    int r = m->r, n = m->ndof, nq = m->nq;
    CHECK(r == s.r, "the manifold has the modes' coordinates only (%d of %d)", r, s.r);
    double x[16], f[16], fp[16], fm[16], Kr[256], *g = malloc(nq * sizeof(double)), *q = malloc(nq * sizeof(double));
    for (int k = 0; k < r; k++) x[k] = 1.0 * sqrt(sagged.mass * sagged.length) / (k + 1);
    CHECK(gal_rom_internal_force(m, x, f) == GAL_OK, "%s", gal_error_message());
    memcpy(m->x, x, r * sizeof(double));
    gal_rom_reconstruct(m, q, NULL);
    gal_rod_eval(s.eq.rod, q, NULL, g, NULL);
    /* P(x) by central differences of the reconstruction */
    double err = 0, fmx = 0;
    for (int k = 0; k < r; k++) {
        double hk = 1e-5 * fabs(x[0]), pr = 0, *qp = malloc(nq * sizeof(double));
        m->x[k] = x[k] + hk, gal_rom_reconstruct(m, qp, NULL);
        m->x[k] = x[k] - hk, gal_rom_reconstruct(m, q, NULL);
        m->x[k] = x[k];
        for (int d = 0; d < n; d++) {
            int qi = s.eq.rod->free_q[d];
            pr += (qp[qi] - q[qi]) / (2 * hk) * g[qi];
        }
        free(qp);
        err = fmax(err, fabs(pr - f[k])), fmx = fmax(fmx, fabs(f[k]));
    }
    CHECK(err <= 1e-6 * fmx, "manifold force = P^T grad U: %g of %g", err, fmx);
    double terr = 0, tmax = 0;
    { /* the force's derivative by central differences is symmetric: a gradient */
        for (int j = 0; j < r; j++) {
            double hj = 1e-4 * fabs(x[0]);
            x[j] += hj, gal_rom_internal_force(m, x, fp);
            x[j] -= 2 * hj, gal_rom_internal_force(m, x, fm);
            x[j] += hj;
            for (int i = 0; i < r; i++) Kr[i * r + j] = (fp[i] - fm[i]) / (2 * hj);
        }
        for (int i = 0; i < r; i++)
            for (int j = 0; j < i; j++)
                terr = fmax(terr, fabs(Kr[i * r + j] - Kr[j * r + i])), tmax = fmax(tmax, fabs(Kr[i * r + i]));
    }
    CHECK(terr <= 1e-5 * tmax, "the manifold's force is a gradient (symmetric derivative): %g of %g", terr, tmax);
    free(g), free(q);
    gal_rom_free(m);
    free_span(&s);
}

/* Energy of the manifold model (sampled elements), undamped and unloaded, over 1000 periods. */
static void test_manifold_energy(void)
{
    span s;
    int want[GAL_FAMILY_COUNT] = {2, 1, 0, 0};
    gal_rod_params p = sagged;
    p.elements = 16, p.torsion = 0;
    if (make_span(&s, &p, GAL_BY_SAG, 4.0, want)) return;
    gal_rom_opts o;
    gal_rom_default_opts(&o);
    o.manifold = 1;
    double w1 = s.md.mode[s.sel[0]].omega;
    o.h = 2 * GAL_PI / w1 / 32;
    gal_rom *m = gal_rom_alloc(s.eq.rod, s.eq.q, &s.md, s.sel, s.r, &o, NULL);
    CHECK(m != NULL, "%s", gal_error_message());
    if (!m) { free_span(&s); return; }
    double U0 = gal_rom_energy(m);
    for (int k = 0; k < m->r; k++) m->v[k] = 0.3 * sqrt(m->omega2[k]) * sqrt(p.mass * p.length) / (k + 1);
    double *q = malloc(m->nq * sizeof(double)), *v = malloc(m->nq * sizeof(double));
    gal_rom_reconstruct(m, q, v);
    CHECK(gal_rom_start(m, 0, q, v) == GAL_OK, "%s", gal_error_message());
    double E0 = gal_rom_energy(m), drift = 0;
    for (int per = 0; per < 1000; per++) {
        if (gal_rom_advance(m, (per + 1) * 2 * GAL_PI / w1)) { CHECK(0, "%s", gal_error_message()); break; }
        if (per % 50 == 49) drift = fmax(drift, fabs(gal_rom_energy(m) - E0));
    }
    printf("    (manifold, 1000 periods, %ld steps: energy drift %.2e of the motion's energy)\n", m->steps, drift / (E0 - U0));
    CHECK(drift < 1e-3 * (E0 - U0), "energy drift %g of %g", drift, E0 - U0);
    free(q), free(v);
    gal_rom_free(m);
    free_span(&s);
}

int main(void)
{
    RUN(test_step_halving);
    RUN(test_kirchhoff_carrier);
    RUN(test_damping_forces_tangent);
    RUN(test_energy_and_symmetry);
    RUN(test_short_span_against_full);
    RUN(test_manifold);
    RUN(test_manifold_energy);
    return CHECK_SUMMARY();
}
