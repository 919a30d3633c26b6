/* test_reduced.c: the reduced restoring force: Kirchhoff-Carrier cubic coefficients of a taut
 * string, agreement with the full static response, and what the condensation of the stretching
 * buys over a plain projection on the linear modes. */
#include "check.h"
#include "gallop.h"
#include "gallop/modes/modes.h"
#include "gallop/reduced/reduced.h"
#include "gallop/statics/statics.h"
#include "gallop/full/dynamics.h"
#include "gallop/reduced/rdyn.h"

/* A taut string: no gravity, no bending, no torsion. */
static void test_kirchhoff_carrier(void)
{
    double L = 100, T0 = 1e4, m = 1.0, EA = 1e7;
    gal_rod_params p = {.length = L, .elements = 100, .EA = EA, .EI = 0, .GJ = 1, .mass = m,
                        .polar_inertia = 1e-4, .gravity = 0, .torsion = 0, .twist_clamped = 1};
    gal_equilibrium eq;
    CHECK(gal_statics_solve(&p, GAL_BY_TENSION, T0, NULL, &eq) == GAL_OK, "%s", gal_error_message());
    gal_modes md;
    int want[GAL_FAMILY_COUNT] = {0, 3, 0, 0};
    CHECK(gal_modes_find(eq.rod, eq.q, want, 50, &md) == GAL_OK, "%s", gal_error_message());
    int sel[3], r = 0;
    for (int k = 0; k < md.n && r < 3; k++)
        if (md.mode[k].selected && md.mode[k].family == GAL_FAMILY_HORIZONTAL) sel[r++] = k;
    CHECK(r == 3, "three horizontal modes");
    gal_reduced_opts o;
    gal_reduced_default_opts(&o);
    o.amplitude_m = 0.5; /* the cubic (small-amplitude) coefficients: keep 5th-order terms small */
    gal_reduced *rm = gal_reduced_build(eq.rod, eq.q, &md, sel, 3, NULL, 0, &o);
    CHECK(rm != NULL, "%s", gal_error_message());
    if (!rm) return;
    /* f_i = c s^2 i^2 eta_i sum_j j^2 eta_j^2, c = EA pi^4 / (4 m L^4), s^2 = 2 / (m L) (the
     * amplitude of sin(i pi x / L) per unit mass-normalized coordinate); the string's length
     * between supports is L and its tension T0: use the stretched mass per length */
    double Ls = L, ms = m * eq.unstretched_length / Ls;
    double c = EA * pow(GAL_PI, 4) / (4 * ms * pow(Ls, 4)), s2 = 2 / (ms * Ls);
    double worst = 0;
    for (int mm = 0; mm < rm->n3; mm++) {
        int j = rm->m3[3 * mm], k = rm->m3[3 * mm + 1], l = rm->m3[3 * mm + 2];
        for (int i = 0; i < 3; i++) {
            /* expected coefficient of eta_j eta_k eta_l in f_i */
            double want_c = 0;
            int ni = i + 1;
            if (j == k && k == l && j == i) want_c = c * s2 * pow(ni, 4);
            else if (j == k && l == i && j != i) want_c = c * s2 * ni * ni * pow(j + 1, 2);  /* eta_j^2 eta_i, j < i */
            else if (k == l && j == i && k != i) want_c = c * s2 * ni * ni * pow(k + 1, 2);  /* eta_i eta_k^2, i < k */
            double got = rm->A[i * rm->n3 + mm];
            /* scale: the Kirchhoff-Carrier coefficients of the modes involved */
            int hi = l + 1 > ni ? l + 1 : ni;
            double ref = c * s2 * ni * ni * hi * hi;
            if (want_c != 0) {
                CHECK_REL(got, want_c, 1e-2);
                worst = fmax(worst, fabs(got - want_c) / want_c);
            } else {
                CHECK(fabs(got) < 1e-2 * ref, "coefficient (%d; %d %d %d) = %g should vanish (scale %g)", i, j, k, l, got, ref);
            }
        }
    }
    double qmax = 0;
    for (int mm = 0; mm < rm->n2 * 3; mm++) qmax = fmax(qmax, fabs(rm->B[mm]));
    CHECK(qmax < 1e-3 * c * s2 * 1.0, "a straight string has no quadratic terms: %g", qmax);
    /* the plain projection on the transverse modes (no axial relaxation) at the same amplitude:
     * its cubic coefficient of mode 1 is about 3/2 of Kirchhoff-Carrier's (non-uniform stretching) */
    double eta[3] = {rm->eta_ref[0], 0, 0}, f[3];
    double *wq = malloc(eq.rod->nq * sizeof(double)), *wg = malloc(eq.rod->nq * sizeof(double));
    gal_reduced_projected_force(rm, eq.rod, eq.q, eta, f, wq, wg);
    double a_proj = (f[0] - rm->omega2[0] * eta[0]) / pow(eta[0], 3), a_kc = c * s2;
    printf("    (worst relative error of the Kirchhoff-Carrier coefficients %.2e; %d load cases, "
           "fit residual %.1e, %.3f s; projection's cubic coefficient %.3f x Kirchhoff-Carrier)\n",
           worst, rm->load_cases, rm->fit_residual, rm->build_time_s, a_proj / a_kc);
    CHECK(a_proj > 1.3 * a_kc, "the projection on linear modes should be too stiff: %g vs %g", a_proj, a_kc);
    free(wq);
    free(wg);
    gal_reduced_free(rm);
    gal_modes_clear(&md);
    gal_equilibrium_clear(&eq);
}

/* A sagged span under a large static modal load (0.6 m at the largest entry by linear theory):
 * the condensed model's response against the full static solution, and the plain projection. */
static void test_condensation_matters(void)
{
    gal_rod_params p = {.length = 200, .elements = 80, .EA = 3e7, .EI = 20, .GJ = 150, .mass = 1.6,
                        .polar_inertia = 1.6e-4, .gravity = 9.80665, .torsion = 1, .twist_clamped = 1};
    gal_equilibrium eq;
    CHECK(gal_statics_solve(&p, GAL_BY_TENSION, 20000, NULL, &eq) == GAL_OK, "%s", gal_error_message());
    gal_modes md;
    int want[GAL_FAMILY_COUNT] = {2, 2, 1, 0};
    CHECK(gal_modes_find(eq.rod, eq.q, want, 200, &md) == GAL_OK, "%s", gal_error_message());
    int sel[8], r = 0;
    for (int k = 0; k < md.n; k++)
        if (md.mode[k].selected) sel[r++] = k;
    gal_reduced_opts o;
    gal_reduced_default_opts(&o);
    o.amplitude_m = 1.0;
    gal_reduced *rm = gal_reduced_build(eq.rod, eq.q, &md, sel, r, NULL, 0, &o);
    CHECK(rm != NULL, "%s", gal_error_message());
    if (!rm) return;
    for (int fam = 0; fam < 2; fam++) {
    /* the first vertical / horizontal mode pushed to ~1.5 m by a dead modal load */
    int ih = -1;
    for (int i = 0; i < r; i++)
        if (rm->family[i] == (gal_family)fam) { ih = i; break; }
    int n = eq.rod->ndof, nq = eq.rod->nq;
    double *mdiag = malloc(n * sizeof(double)), *fq = calloc(nq, sizeof(double)), *q = malloc(nq * sizeof(double));
    gal_rod_mass_diag(eq.rod, mdiag);
    double fmod = rm->omega2[ih] * 0.6 * rm->eta_ref[ih];
    memcpy(q, eq.q, nq * sizeof(double));
    for (int j = 0; j < n; j++) fq[eq.rod->free_q[j]] = mdiag[j] * rm->phi[(size_t)ih * n + j] * fmod;
    int it = 0;
    CHECK(gal_statics_solve_loaded(eq.rod, q, fq, 1e-6, 60, &it) == GAL_OK, "%s", gal_error_message());
    double eta_full = 0;
    for (int j = 0; j < n; j++) {
        int k = eq.rod->free_q[j];
        eta_full += rm->phi[(size_t)ih * n + j] * mdiag[j] * (q[k] - eq.q[k]);
    }
    /* reduced static responses: f(eta) = fmod e_ih by Newton in all r coordinates (a horizontal
     * swing lifts the span: the vertical modes respond too), for both reduced models */
    double *eta = calloc(r, sizeof(double)), *f = malloc(r * sizeof(double)), *fp = malloc(r * sizeof(double));
    double *wq = malloc(nq * sizeof(double)), *wg = malloc(nq * sizeof(double));
    double *J = malloc(r * r * sizeof(double)), res[2];
    for (int model = 0; model < 2; model++) {
        memset(eta, 0, r * sizeof(double));
        eta[ih] = fmod / rm->omega2[ih];
        for (int k = 0; k < 30; k++) {
            if (model == 0) gal_reduced_force(rm, eta, f);
            else gal_reduced_projected_force(rm, eq.rod, eq.q, eta, f, wq, wg);
            f[ih] -= fmod;
            for (int b = 0; b < r; b++) {
                double h = 1e-6 * rm->eta_ref[b], save = eta[b];
                eta[b] = save + h;
                if (model == 0) gal_reduced_force(rm, eta, fp);
                else gal_reduced_projected_force(rm, eq.rod, eq.q, eta, fp, wq, wg);
                fp[ih] -= fmod;
                eta[b] = save;
                for (int a = 0; a < r; a++) J[a * r + b] = (fp[a] - f[a]) / h;
            }
            /* Gaussian elimination with partial pivoting, J dx = -f */
            for (int c2 = 0; c2 < r; c2++) {
                int pv = c2;
                for (int a = c2 + 1; a < r; a++) if (fabs(J[a * r + c2]) > fabs(J[pv * r + c2])) pv = a;
                for (int b = 0; b < r; b++) { double t = J[c2 * r + b]; J[c2 * r + b] = J[pv * r + b]; J[pv * r + b] = t; }
                double t = f[c2]; f[c2] = f[pv]; f[pv] = t;
                for (int a = c2 + 1; a < r; a++) {
                    double fct = J[a * r + c2] / J[c2 * r + c2];
                    for (int b = c2; b < r; b++) J[a * r + b] -= fct * J[c2 * r + b];
                    f[a] -= fct * f[c2];
                }
            }
            for (int a = r - 1; a >= 0; a--) {
                double sacc = f[a];
                for (int b = a + 1; b < r; b++) sacc -= J[a * r + b] * fp[b];
                fp[a] = sacc / J[a * r + a];
            }
            for (int a = 0; a < r; a++) eta[a] -= fp[a];
        }
        res[model] = eta[ih];
    }
    double e_ic = res[0], e_pr = res[1];
    double e_lin = fmod / rm->omega2[ih];
    printf("    (%s, static modal response: full %.5g, condensed %.5g (%.2f%%), projected on linear modes "
           "%.5g (%.1f%%), linear %.5g)\n", gal_family_names[fam], eta_full, e_ic, 100 * (e_ic - eta_full) / eta_full, e_pr,
           100 * (e_pr - eta_full) / eta_full, e_lin);
    CHECK_REL(e_ic, eta_full, 1e-2);
    CHECK(fabs(e_pr - eta_full) > 2 * fabs(e_ic - eta_full), "the plain projection should be worse");
    free(mdiag); free(fq); free(q); free(eta); free(f); free(fp); free(wq); free(wg); free(J);
    }
    gal_reduced_free(rm);
    gal_modes_clear(&md);
    gal_equilibrium_clear(&eq);
}

/* Free vibration started by a modal velocity: the reduced model against the full model (mid-span
 * vertical amplitude and period), and at small amplitude the modal frequency. */
static void free_vibration_vs_full(gal_family fam, double swing)
{
    gal_rod_params p = {.length = 200, .elements = 60, .EA = 3e7, .EI = 20, .GJ = 150, .mass = 1.6,
                        .polar_inertia = 1.6e-4, .gravity = 9.80665, .torsion = 1, .twist_clamped = 1};
    gal_equilibrium eq;
    CHECK(gal_statics_solve(&p, GAL_BY_TENSION, 20000, NULL, &eq) == GAL_OK, "%s", gal_error_message());
    gal_modes md;
    int want[GAL_FAMILY_COUNT] = {3, 2, 1, 0};
    CHECK(gal_modes_find(eq.rod, eq.q, want, 200, &md) == GAL_OK, "%s", gal_error_message());
    int sel[8], r = 0;
    for (int k = 0; k < md.n; k++)
        if (md.mode[k].selected) sel[r++] = k;
    int mid = eq.rod->nn / 2, oq = 3 * mid + (fam == GAL_FAMILY_HORIZONTAL ? 1 : 2);
    gal_obs obs[1] = {{{oq, -1}, {1.0, 0.0}}};
    gal_reduced_opts o;
    gal_reduced_default_opts(&o);
    o.amplitude_m = 2.0;
    gal_reduced *rm = gal_reduced_build(eq.rod, eq.q, &md, sel, r, obs, 1, &o);
    CHECK(rm != NULL, "%s", gal_error_message());
    if (!rm) return;
    int iv = 0; /* first symmetric mode of the family */
    while (rm->family[iv] != fam || md.mode[rm->mode_index[iv]].symmetry != GAL_SYM_SYMMETRIC) iv++;

    double T = 2 * GAL_PI / sqrt(rm->omega2[iv]);
    for (int large = 0; large < 2; large++) {
        double vel = (large ? swing : 1e-3) * sqrt(rm->omega2[iv]) * rm->eta_ref[iv] * 0.5; /* ~1 m swing */
        gal_rdyn *rd = gal_rdyn_alloc(rm, eq.rod, eq.q, NULL, NULL, 32, 1e-9, T / 50, -1);
        rd->y[r + iv] = vel;
        gal_dyn_opts dop;
        gal_dyn_default_opts(&dop);
        dop.h = T / 100;
        double *v0 = calloc(eq.rod->nq, sizeof(double));
        for (int j = 0; j < md.ndof; j++) v0[eq.rod->free_q[j]] = rm->phi[(size_t)iv * md.ndof + j] * vel;
        gal_dyn *fd = gal_dyn_alloc(eq.rod, eq.q, v0, &dop, NULL);
        double zr_min = 1e9, zr_max = -1e9, zf_min = 1e9, zf_max = -1e9, prev_r = 0, prev_f = 0;
        double first_r = -1, last_r = -1, first_f = -1, last_f = -1;
        int nr = 0, nf = 0;
        for (int s = 1; s <= 10 * 100; s++) {
            double t = s * dop.h, zr;
            gal_rdyn_advance(rd, t);
            gal_reduced_observe(rm, rd->y, &zr);
            if (gal_dyn_step(fd) != GAL_OK) { CHECK(0, "full: %s", gal_error_message()); break; }
            double zf = fd->q[oq] - eq.q[oq];
            zr_min = fmin(zr_min, zr), zr_max = fmax(zr_max, zr), zf_min = fmin(zf_min, zf), zf_max = fmax(zf_max, zf);
            if (prev_r < 0 && zr >= 0) { double tc = t - dop.h * zr / (zr - prev_r); if (first_r < 0) first_r = tc; else nr++; last_r = tc; }
            if (prev_f < 0 && zf >= 0) { double tc = t - dop.h * zf / (zf - prev_f); if (first_f < 0) first_f = tc; else nf++; last_f = tc; }
            prev_r = zr, prev_f = zf;
        }
        double Tr = (last_r - first_r) / nr, Tf = (last_f - first_f) / nf;
        printf("    (%s %s: mid-span p-p full %.4g m, reduced %.4g m; period full %.5f s, reduced %.5f s, "
               "modal %.5f s)\n", gal_family_names[fam], large ? "large" : "small", zf_max - zf_min, zr_max - zr_min, Tf, Tr, T);
        if (!large) CHECK_REL(Tr, T, 1e-4);
        CHECK_REL(zr_max - zr_min, zf_max - zf_min, large ? 0.03 : 0.01);
        CHECK_REL(Tr, Tf, large ? 0.01 : 0.005);
        free(v0);
        gal_dyn_free(fd);
        gal_rdyn_free(rd);
    }
    gal_reduced_free(rm);
    gal_modes_clear(&md);
    gal_equilibrium_clear(&eq);
}

/* At random states inside the identification range the polynomial restoring force equals the
 * exact condensed force of the full rod to the order the fit promises: it is identified from
 * states with up to three modes active, so at random states of three active modes it is within 1%
 * of the force scale w_i^2 eta_ref_i; with all five modes active the four- and five-mode products
 * it lacks are reported. A sagged span with every family in the basis. */
static void test_reduced_force_at_random_states(void)
{
    gal_rod_params p = {.length = 200, .elements = 60, .EA = 3e7, .EI = 20, .GJ = 150, .mass = 1.6,
                        .polar_inertia = 1.6e-4, .gravity = 9.80665, .torsion = 1, .twist_clamped = 1};
    gal_equilibrium eq;
    CHECK(gal_statics_solve(&p, GAL_BY_TENSION, 20000, NULL, &eq) == GAL_OK, "%s", gal_error_message());
    gal_modes md;
    int want[GAL_FAMILY_COUNT] = {2, 2, 1, 0};
    CHECK(gal_modes_find(eq.rod, eq.q, want, 200, &md) == GAL_OK, "%s", gal_error_message());
    int sel[8], r = 0;
    for (int k = 0; k < md.n; k++)
        if (md.mode[k].selected) sel[r++] = k;
    gal_reduced *rm = gal_reduced_build(eq.rod, eq.q, &md, sel, r, NULL, 0, NULL);
    CHECK(rm != NULL, "%s", gal_error_message());
    if (!rm) return;
    unsigned seed = 12345;
    double worst = 0, lin = 0, worst_all = 0;
    for (int t = 0; t < 30; t++) {
        double eta[8], fp[8], fc[8];
        int all = t >= 20; /* the last ten: every mode active */
        for (int i = 0; i < r; i++) {
            seed = seed * 1103515245u + 12345u;
            eta[i] = (((seed >> 8) & 0xffff) / 32768.0 - 1.0) * 0.5 * rm->eta_ref[i]; /* within half the range */
        }
        if (!all) { /* keep three of the modes */
            int keep[3] = {t % r, (t / r + t + 1) % r, (t + 2 + t / 2) % r};
            for (int i = 0; i < r; i++)
                if (i != keep[0] && i != keep[1] && i != keep[2]) eta[i] = 0;
        }
        gal_reduced_force(rm, eta, fp);
        if (gal_reduced_condensed_force(rm, eq.rod, eq.q, eta, fc) != GAL_OK) { CHECK(0, "%s", gal_error_message()); break; }
        for (int i = 0; i < r; i++) {
            double scale = rm->omega2[i] * rm->eta_ref[i], e = fabs(fp[i] - fc[i]) / scale;
            if (all) worst_all = fmax(worst_all, e);
            else worst = fmax(worst, e);
            lin = fmax(lin, fabs(rm->omega2[i] * eta[i] - fc[i]) / scale); /* what linear modes alone miss */
        }
    }
    printf("    (random states, polynomial against condensed force: worst %.2e of the force scale with three "
           "modes active, %.2e with all five; the nonlinear part itself up to %.2e)\n", worst, worst_all, lin);
    CHECK(worst < 1e-2, "reduced force off the condensed one by %g of the scale", worst);
    CHECK(lin > 10 * worst, "the test must exercise the nonlinearity: %g vs %g", lin, worst);
    gal_reduced_free(rm);
    gal_modes_clear(&md);
    gal_equilibrium_clear(&eq);
}

static void test_free_vibration_reduced_vs_full(void)
{
    free_vibration_vs_full(GAL_FAMILY_VERTICAL, 1.0);
    free_vibration_vs_full(GAL_FAMILY_HORIZONTAL, 2.0);
}

/* A 200 m span at 20 kN with `nel` elements, its modes (want per family) and the identified
 * reduced model on the selected ones (one observation: mid-span vertical). */
typedef struct {
    gal_equilibrium eq;
    gal_modes md;
    int sel[8], r;
    gal_reduced *rm;
} small_rom;

static int small_rom_build(small_rom *s, int nel, const int want[GAL_FAMILY_COUNT])
{
    gal_rod_params p = {.length = 200, .elements = nel, .EA = 3e7, .EI = 20, .GJ = 150, .mass = 1.6,
                        .polar_inertia = 1.6e-4, .gravity = 9.80665, .torsion = 1, .twist_clamped = 1};
    memset(s, 0, sizeof *s);
    CHECK(gal_statics_solve(&p, GAL_BY_TENSION, 20000, NULL, &s->eq) == GAL_OK, "%s", gal_error_message());
    CHECK(gal_modes_find(s->eq.rod, s->eq.q, want, 200, &s->md) == GAL_OK, "%s", gal_error_message());
    for (int k = 0; k < s->md.n && s->r < 8; k++)
        if (s->md.mode[k].selected) s->sel[s->r++] = k;
    int mid = s->eq.rod->nn / 2;
    gal_obs obs[1] = {{{3 * mid + 2, -1}, {1.0, 0.0}}};
    gal_reduced_opts o;
    gal_reduced_default_opts(&o);
    s->rm = gal_reduced_build(s->eq.rod, s->eq.q, &s->md, s->sel, s->r, obs, 1, &o);
    CHECK(s->rm != NULL, "%s", gal_error_message());
    return s->rm ? GAL_OK : GAL_EFAIL;
}

static void small_rom_clear(small_rom *s)
{
    gal_reduced_free(s->rm);
    gal_modes_clear(&s->md);
    gal_equilibrium_clear(&s->eq);
}

/* issue 14: the reduced model's damping is the structural damping projected on its
 * mass-normalized modes; for Rayleigh damping alpha M + beta K that is, in closed form,
 * alpha + beta omega^2 on the diagonal (not omega) and zero off it. */
static void test_rayleigh_projection(void)
{
    small_rom s;
    int want[GAL_FAMILY_COUNT] = {3, 2, 1, 0};
    small_rom_build(&s, 40, want);
    gal_equilibrium eq = s.eq;
    gal_modes md = s.md;
    gal_reduced *rm = s.rm;
    const int *sel = s.sel;
    int r = s.r;
    double a = 0.07, b = 0.003;
    gal_damping *c = gal_damping_rayleigh_alloc(eq.rod, eq.q, a, b);
    gal_rdyn *rd = rm && c ? gal_rdyn_alloc(rm, eq.rod, eq.q, c, NULL, 32, 1e-9, 0.01, -1) : NULL;
    CHECK(rd != NULL, "set-up: %s", gal_error_message());
    if (rd)
        for (int i = 0; i < r; i++)
            for (int j = 0; j < r; j++) {
                double want_ij = i == j ? a + b * md.mode[sel[i]].omega * md.mode[sel[i]].omega : 0.0;
                CHECK_NEAR(rd->damp[(size_t)j * r + i], want_ij, 1e-6 * (a + b * md.mode[sel[r - 1]].omega * md.mode[sel[r - 1]].omega));
            }
    gal_damping_free(c);
    gal_rdyn_free(rd);
    small_rom_clear(&s);
}

/* A load along y growing linearly along the span, f_y = x / 100 N/m (a uniform one would not do:
 * its quadrature errors telescope to the fixed supports): the reduced model's quadrature. */
static int ramp_y(void *ctx, double t, double x, const double r[3], const double rdot[3], const double tan[3],
                  const double d1[3], double f[3], double *m)
{
    (void)ctx, (void)t, (void)x, (void)rdot, (void)tan, (void)d1;
    f[0] = 0, f[1] = r[0] / 100, f[2] = 0, *m = 0;
    return GAL_OK;
}

/* The reduced loads' quadrature (2 Gauss points per segment): with one segment per element the
 * mode shapes and x are linear on each element, their product quadratic, which 2-point Gauss
 * integrates exactly: sum_q w_q phi_i(s_q) f(s_q) = sum_e l0 (phi_a (2 x_a + x_b) + phi_b (x_a +
 * 2 x_b)) / 600 over the elements (nodes a, b). */
static void test_load_quadrature_exact(void)
{
    small_rom s;
    int want[GAL_FAMILY_COUNT] = {2, 3, 0, 0};
    small_rom_build(&s, 20, want);
    gal_equilibrium eq = s.eq;
    const gal_rod *rod = eq.rod;
    gal_reduced *rm = s.rm;
    int r = s.r;
    gal_pointload pl = {ramp_y, NULL}, none = {0};
    int nqp = 2 * rod->p.elements;
    gal_rdyn *a = rm ? gal_rdyn_alloc(rm, rod, eq.q, NULL, &pl, nqp, 1e-9, 0.01, -1) : NULL;
    gal_rdyn *b = rm ? gal_rdyn_alloc(rm, rod, eq.q, NULL, &none, nqp, 1e-9, 0.01, -1) : NULL;
    CHECK(a && b, "set-up: %s", gal_error_message());
    if (a && b) {
        double ya[16] = {0}, yb[16] = {0};
        a->sys.function(0, a->y, ya, a);
        b->sys.function(0, b->y, yb, b);
        int n = rod->ndof;
        double worst = 0, scale = 0;
        for (int i = 0; i < r; i++) {
            double want_i = 0;
            for (int e = 0; e < rod->p.elements; e++) {
                int da = rod->dof[3 * e + 1], db = rod->dof[3 * (e + 1) + 1];
                double pa = da >= 0 ? rm->phi[(size_t)i * n + da] : 0, pb = db >= 0 ? rm->phi[(size_t)i * n + db] : 0;
                double xa = eq.q[3 * e], xb = eq.q[3 * (e + 1)];
                want_i += rod->l0[e] * (pa * (2 * xa + xb) + pb * (xa + 2 * xb)) / 600;
            }
            double got = ya[r + i] - yb[r + i];
            worst = fmax(worst, fabs(got - want_i));
            scale = fmax(scale, fabs(want_i));
        }
        printf("    (generalized ramp load: worst error %.2e of %.3g)\n", worst, scale);
        CHECK(worst <= 1e-9 * scale, "quadrature error %g of %g", worst, scale);
    }
    gal_rdyn_free(a);
    gal_rdyn_free(b);
    small_rom_clear(&s);
}

int main(void)
{
    RUN(test_kirchhoff_carrier);
    RUN(test_condensation_matters);
    RUN(test_reduced_force_at_random_states);
    RUN(test_free_vibration_reduced_vs_full);
    RUN(test_rayleigh_projection);
    RUN(test_load_quadrature_exact);
    return CHECK_SUMMARY();
}
