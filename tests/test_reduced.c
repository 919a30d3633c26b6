/* test_reduced.c: the reduced model (reduced/rom.h, the only one since issue 13) held to what the
 * identified model's tests asserted: the Kirchhoff-Carrier coefficients of a taut string (every
 * cubic coefficient of three modes, no quadratic ones) with the stretching relaxed on the modal
 * derivatives, and the linear modes alone too stiff; the static response to a large modal load
 * against the full rod's; the reduced force against the exact condensed force at random states of
 * five modes, to the order the method promises; free vibration against the full model, vertical and
 * horizontal, small and large; the full model's modal damping at every selected mode. The
 * projection's own tests evaluate every element (o.hyper = 0: the sampled, weighted model is held
 * to its own fit in test_ecsw.c); free vibration and damping run the default model (sampled,
 * weighted elements, the kept Newton tangent), the one every reduced run uses. */
#include "check.h"
#include "gallop.h"
#include "gallop/full/dynamics.h"
#include "gallop/modes/modes.h"
#include "gallop/reduced/rom.h"
#include "gallop/statics/statics.h"

typedef struct {
    gal_equilibrium eq;
    gal_modes md;
    int sel[16], r;
} span;

static int make_span(span *s, const gal_rod_params *p, double tension, const int want[GAL_FAMILY_COUNT])
{
    memset(s, 0, sizeof *s);
    if (gal_statics_solve(p, GAL_BY_TENSION, tension, NULL, &s->eq) ||
        gal_modes_find(s->eq.rod, s->eq.q, want, 200, &s->md)) {
        CHECK(0, "%s", gal_error_message());
        return 1;
    }
    for (int k = 0; k < s->md.n && s->r < 16; k++)
        if (s->md.mode[k].selected) s->sel[s->r++] = k;
    return 0;
}

/* The options of the projection's tests: every element (the Galerkin projection exactly, what they
 * assert; test_ecsw.c holds the sampled, weighted one to its own figures) and a fresh Newton
 * tangent each step. */
static void exact_opts(gal_rom_opts *o)
{
    gal_rom_default_opts(o);
    o->hyper = 0;
    o->reuse_tangent = 0;
}

static void free_span(span *s)
{
    gal_modes_clear(&s->md);
    gal_equilibrium_clear(&s->eq);
}

/* a 200 m sagged span at 20 kN with every family */
static const gal_rod_params sagged = {.length = 200, .elements = 60, .EA = 3e7, .EI = 20, .GJ = 150, .mass = 1.6,
                                      .polar_inertia = 1.6e-4, .gravity = 9.80665, .torsion = 1, .twist_clamped = 1};

/* Solve A x = b (n x n, row-major, destroyed) by Gaussian elimination with partial pivoting. */
static void gauss(double *A, double *b, int n)
{
    for (int k = 0; k < n; k++) {
        int p = k;
        for (int i = k + 1; i < n; i++)
            if (fabs(A[i * n + k]) > fabs(A[p * n + k])) p = i;
        for (int j = 0; j < n; j++) { double t = A[k * n + j]; A[k * n + j] = A[p * n + j]; A[p * n + j] = t; }
        double t = b[k]; b[k] = b[p]; b[p] = t;
        for (int i = k + 1; i < n; i++) {
            double l = A[i * n + k] / A[k * n + k];
            for (int j = k; j < n; j++) A[i * n + j] -= l * A[k * n + j];
            b[i] -= l * b[k];
        }
    }
    for (int k = n - 1; k >= 0; k--) {
        for (int j = k + 1; j < n; j++) b[k] -= A[k * n + j] * b[j];
        b[k] /= A[k * n + k];
    }
}

/* The condensed force on the modes: x[0..nm) held at eta, the modal-derivative coordinates relaxed
 * (their reduced force zero) by Newton on the reduced tangent; f[0..nm) the force on the modes. */
static int condensed(gal_rom *m, const double *eta, double *x, double *f)
{
    int r = m->r, nm = m->nmodes, n1 = r - nm, n = m->ndof;
    double *q = malloc(m->nq * sizeof(double)), *g = malloc(m->nq * sizeof(double));
    double *Kr = malloc((size_t)r * r * sizeof(double)), *A = malloc((size_t)r * r * sizeof(double));
    double *w = malloc(n * sizeof(double)), b[64];
    gal_csc *K = gal_csc_clone(m->rod->K);
    memset(x, 0, r * sizeof(double)); /* the modal derivatives relaxed from zero */
    memcpy(x, eta, nm * sizeof(double));
    int st = GAL_EFAIL;
    for (int it = 0; it < 30; it++) {
        if (gal_rom_internal_force(m, x, f)) break;
        double rn = 0, sc = 0;
        for (int i = 0; i < nm; i++) sc = fmax(sc, fabs(f[i]));
        for (int i = nm; i < r; i++) rn = fmax(rn, fabs(f[i]));
        if (rn <= 1e-10 * sc || n1 == 0) { st = GAL_OK; break; }
        memcpy(m->x, x, r * sizeof(double));
        gal_rom_reconstruct(m, q, NULL);
        gal_rod_eval(m->rod, q, NULL, g, K);
        gal_rom_project_tangent(m, K, Kr, w);
        for (int i = 0; i < n1; i++) {
            b[i] = -f[nm + i];
            for (int j = 0; j < n1; j++) A[i * n1 + j] = Kr[(nm + i) * r + nm + j];
        }
        gauss(A, b, n1);
        for (int i = 0; i < n1; i++) x[nm + i] += b[i];
    }
    gal_csc_free(K);
    free(q); free(g); free(Kr); free(A); free(w);
    return st;
}

/* A taut string (no gravity, bending or torsion), three horizontal modes: the condensed force is
 * f_i = w_i^2 eta_i + c s^2 i^2 eta_i sum_j j^2 eta_j^2, c = EA pi^4 / (4 m L^4), s^2 = 2 / (m L)
 * (Kirchhoff-Carrier: the amplitude of sin(i pi x / L) per unit mass-normalized coordinate is s):
 * the coefficients of eta_i^3 and eta_i eta_j^2 in f_i, every other cubic coefficient zero, no
 * quadratic term (a straight string); the linear modes alone (no modal derivatives) ~1.5 times too
 * stiff (the stretching is uniform only once the axial motion relaxes). Coefficients by central
 * differences at 0.5 m and Richardson's extrapolation against the fifth-order terms. */
static double cubic_c(gal_rom *m, int i, int j, int k, double a, double *x, double *f)
{
    /* the coefficient of eta_j eta_k^2 in f_i (j == k: eta_j^3), odd in eta_j and even in eta_k */
    double eta[3], s = 0;
    for (int sj = -1; sj <= 1; sj += 2)
        for (int sk = (j == k ? 1 : -1); sk <= 1; sk += 2) {
            memset(eta, 0, sizeof eta);
            eta[j] += sj * a;
            eta[k] += (j == k ? 0 : sk * a);
            if (condensed(m, eta, x, f)) return NAN;
            double lin = m->omega2[i] * eta[i];
            s += sj * (f[i] - lin);
        }
    if (j != k) { /* minus the part without eta_k: f_i(a e_j) - f_i(-a e_j) */
        for (int sj = -1; sj <= 1; sj += 2) {
            memset(eta, 0, sizeof eta);
            eta[j] = sj * a;
            if (condensed(m, eta, x, f)) return NAN;
            s -= 2 * sj * (f[i] - m->omega2[i] * eta[i]);
        }
        return s / (4 * a * a * a);
    }
    return s / (2 * a * a * a);
}

static void test_kirchhoff_carrier(void)
{
    double L = 100, T0 = 1e4, mass = 1.0, EA = 1e7;
    gal_rod_params p = {.length = L, .elements = 60, .EA = EA, .EI = 0, .GJ = 1, .mass = mass,
                        .polar_inertia = 1e-4, .gravity = 0, .torsion = 0, .twist_clamped = 1};
    span s;
    int want[GAL_FAMILY_COUNT] = {0, 3, 0, 0};
    if (make_span(&s, &p, T0, want)) return;
    gal_rom_opts o;
    exact_opts(&o);
    gal_rom *m = gal_rom_alloc(s.eq.rod, s.eq.q, &s.md, s.sel, 3, &o, NULL);
    o.derivatives = 0;
    gal_rom *lin = gal_rom_alloc(s.eq.rod, s.eq.q, &s.md, s.sel, 3, &o, NULL);
    CHECK(m && lin && m->nmodes == 3, "%s", gal_error_message());
    if (!m || !lin) { gal_rom_free(m); gal_rom_free(lin); free_span(&s); return; }
    double ms = mass * s.eq.unstretched_length / L;
    double c = EA * pow(GAL_PI, 4) / (4 * ms * pow(L, 4)), s2 = 2 / (ms * L);
    double a = 0.5 * sqrt(ms * L / 2); /* 0.5 m at the largest entry */
    double x[64], f[64], worst = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++) {
                double ni = i + 1, nj = j + 1, nk = k + 1;
                double want_c = 0;
                if (j == i && k == i) want_c = c * s2 * pow(ni, 4);       /* eta_i^3 */
                else if (j == i) want_c = c * s2 * ni * ni * nk * nk;      /* eta_i eta_k^2 */
                double c1 = cubic_c(m, i, j, k, a, x, f), c2 = cubic_c(m, i, j, k, a / 2, x, f);
                double got = (4 * c2 - c1) / 3; /* Richardson: the a^2 (fifth-order) part removed */
                double ref = c * s2 * ni * ni * fmax(fmax(nj, nk), ni) * fmax(fmax(nj, nk), ni);
                if (want_c != 0) {
                    CHECK_REL(got, want_c, 1e-2);
                    worst = fmax(worst, fabs(got - want_c) / want_c);
                } else {
                    CHECK(fabs(got) < 1e-2 * ref, "coefficient (%d; %d %d^2) = %g should vanish (scale %g)", i, j, k,
                          got, ref);
                }
            }
    /* no quadratic term: the even part of f along each mode and the bilinear part of each pair */
    double qmax = 0, eta[3];
    for (int j = 0; j < 3; j++)
        for (int k = j; k < 3; k++) {
            double sum[3] = {0, 0, 0};
            for (int sj = -1; sj <= 1; sj += 2)
                for (int sk = -1; sk <= 1; sk += 2) {
                    memset(eta, 0, sizeof eta);
                    eta[j] += sj * a, eta[k] += (j == k ? 0 : sk * a);
                    condensed(m, eta, x, f);
                    for (int i = 0; i < 3; i++) sum[i] += (j == k ? 1 : sj * sk) * f[i];
                }
            for (int i = 0; i < 3; i++) qmax = fmax(qmax, fabs(sum[i]) / (4 * a * a));
        }
    CHECK(qmax < 1e-3 * c * s2 * a, "a straight string has no quadratic terms: %g", qmax);
    /* nor a coefficient of eta_1 eta_2 eta_3: the part odd in all three */
    double tri = 0;
    for (int i = 0; i < 3; i++) {
        double sum = 0;
        for (int sg = 0; sg < 8; sg++) {
            double e3[3] = {(sg & 1 ? -a : a), (sg & 2 ? -a : a), (sg & 4 ? -a : a)};
            condensed(m, e3, x, f);
            sum += e3[0] * e3[1] * e3[2] / (a * a * a) * f[i];
        }
        tri = fmax(tri, fabs(sum) / (8 * a * a * a) / (c * s2 * (i + 1) * (i + 1) * 9));
    }
    CHECK(tri < 1e-2, "the coefficient of eta_1 eta_2 eta_3 should vanish: %g of the scale", tri);
    /* the linear modes alone at the same amplitude */
    double xl[3] = {a, 0, 0}, fl[3];
    gal_rom_internal_force(lin, xl, fl);
    double a_proj = (fl[0] - lin->omega2[0] * a) / pow(a, 3), a_kc = c * s2;
    printf("    (basis %d = 3 modes + %d modal derivatives; worst relative error of the Kirchhoff-Carrier coefficients "
           "%.2e; linear modes alone: cubic coefficient %.3f x Kirchhoff-Carrier)\n", m->r, m->r - 3, worst, a_proj / a_kc);
    CHECK(a_proj > 1.3 * a_kc, "the projection on linear modes should be too stiff: %g vs %g", a_proj, a_kc);
    gal_rom_free(m);
    gal_rom_free(lin);
    free_span(&s);
}

/* The full rod's static response to the dead modal load M phi_i fmod (every dof relaxed): its
 * modal amplitudes phi^T M u of the selected modes into eta (r entries). */
static int full_static(const span *s, const gal_rom *m, const double *fmod, double *eta)
{
    const gal_rod *rod = s->eq.rod;
    int n = rod->ndof, nq = rod->nq, it = 0, nm = m->nmodes;
    double *mdiag = malloc(n * sizeof(double)), *fq = calloc(nq, sizeof(double)), *q = malloc(nq * sizeof(double));
    gal_rod_mass_diag(rod, mdiag);
    memcpy(q, s->eq.q, nq * sizeof(double));
    for (int j = 0; j < n; j++)
        for (int i = 0; i < nm; i++) fq[rod->free_q[j]] += mdiag[j] * m->V[(size_t)i * n + j] * fmod[i];
    int st = gal_statics_solve_loaded(rod, q, fq, 1e-6, 60, &it);
    for (int i = 0; i < nm; i++) {
        eta[i] = 0;
        for (int j = 0; j < n; j++) eta[i] += m->V[(size_t)i * n + j] * mdiag[j] * (q[rod->free_q[j]] - s->eq.q[rod->free_q[j]]);
    }
    free(mdiag); free(fq); free(q);
    return st;
}

/* The reduced static response to the same load: V^T grad U(q_eq + V x) = e_i fmod by Newton. */
static int reduced_static(gal_rom *m, const double *fmod, double *x)
{
    int r = m->r, nm = m->nmodes;
    double *f = malloc(r * sizeof(double)), *A = malloc((size_t)r * r * sizeof(double));
    double *q = malloc(m->nq * sizeof(double)), *g = malloc(m->nq * sizeof(double)), *w = malloc(m->ndof * sizeof(double));
    gal_csc *K = gal_csc_clone(m->rod->K);
    memset(x, 0, r * sizeof(double));
    for (int i = 0; i < nm; i++) x[i] = fmod[i] / m->omega2[i];
    int st = GAL_EFAIL;
    for (int it = 0; it < 40 && st; it++) {
        gal_rom_internal_force(m, x, f);
        double rn = 0, sc = 0;
        for (int i = 0; i < r; i++) {
            f[i] -= i < nm ? fmod[i] : 0;
            rn = fmax(rn, fabs(f[i])), sc = fmax(sc, i < nm ? fabs(fmod[i]) : 0);
        }
        if (rn <= 1e-10 * sc) st = GAL_OK;
        memcpy(m->x, x, r * sizeof(double));
        gal_rom_reconstruct(m, q, NULL);
        gal_rod_eval(m->rod, q, NULL, g, K);
        gal_rom_project_tangent(m, K, A, w);
        for (int i = 0; i < r; i++) f[i] = -f[i];
        gauss(A, f, r);
        for (int i = 0; i < r; i++) x[i] += f[i];
    }
    gal_csc_free(K);
    free(f); free(A); free(q); free(g); free(w);
    return st;
}

/* A sagged span under a large static modal load (0.6 m at the largest entry by linear theory) of
 * its first vertical, then its first horizontal mode: the reduced model's response within 1% of
 * the full rod's, the linear modes alone at least twice as far off. */
static void test_static_response(void)
{
    span s;
    int want[GAL_FAMILY_COUNT] = {2, 2, 1, 0};
    if (make_span(&s, &sagged, 20000, want)) return;
    gal_rom_opts o;
    exact_opts(&o);
    gal_rom *m = gal_rom_alloc(s.eq.rod, s.eq.q, &s.md, s.sel, s.r, &o, NULL);
    o.derivatives = 0;
    gal_rom *lin = gal_rom_alloc(s.eq.rod, s.eq.q, &s.md, s.sel, s.r, &o, NULL);
    CHECK(m && lin, "%s", gal_error_message());
    if (!m || !lin) { gal_rom_free(m); gal_rom_free(lin); free_span(&s); return; }
    double scale = sqrt(sagged.mass * sagged.length / 2); /* ~1 m at the largest entry per unit coordinate */
    for (int fam = 0; fam < 2; fam++) {
        int ih = -1;
        for (int i = 0; i < s.r && ih < 0; i++)
            if (s.md.mode[s.sel[i]].family == (gal_family)fam) ih = i;
        double fmod[16] = {0}, eta[16], x[64], xl[16];
        fmod[ih] = m->omega2[ih] * 0.6 * scale;
        CHECK(full_static(&s, m, fmod, eta) == GAL_OK, "full: %s", gal_error_message());
        CHECK(reduced_static(m, fmod, x) == GAL_OK, "reduced: Newton did not converge");
        CHECK(reduced_static(lin, fmod, xl) == GAL_OK, "linear modes: Newton did not converge");
        printf("    (%s, static modal response: full %.5g, reduced %.5g (%.2f%%), linear modes alone %.5g (%.1f%%), "
               "linear theory %.5g)\n", gal_family_names[fam], eta[ih], x[ih], 100 * (x[ih] - eta[ih]) / eta[ih], xl[ih],
               100 * (xl[ih] - eta[ih]) / eta[ih], fmod[ih] / m->omega2[ih]);
        CHECK_REL(x[ih], eta[ih], 1e-2);
        CHECK(fabs(xl[ih] - eta[ih]) > 2 * fabs(x[ih] - eta[ih]), "the linear modes alone should be worse");
    }
    gal_rom_free(m);
    gal_rom_free(lin);
    free_span(&s);
}

/* At random states of all five modes (within 0.5 m, or 0.5 rad for the torsional one, at the largest
 * entry by linear theory) the reduced force with
 * the modal derivatives relaxed equals the exact condensed force of the full rod: the full rod
 * under the dead modal loads lambda (every dof relaxed) sits at modal amplitudes eta with
 * condensed force lambda. The modal derivatives make the condensation exact to third order, so
 * the error relative to the force falls at least fourfold when the amplitude halves, and is
 * within 1% of the force scale w_i^2 eta_ref at the larger amplitude; the nonlinear part itself
 * is far larger. */
static void test_force_at_random_states(void)
{
    span s;
    int want[GAL_FAMILY_COUNT] = {2, 2, 1, 0};
    if (make_span(&s, &sagged, 20000, want)) return;
    gal_rom_opts o;
    exact_opts(&o);
    gal_rom *m = gal_rom_alloc(s.eq.rod, s.eq.q, &s.md, s.sel, s.r, &o, NULL);
    CHECK(m != NULL, "%s", gal_error_message());
    if (!m) { free_span(&s); return; }
    int nm = m->nmodes, n = m->ndof;
    double unit[16]; /* the coordinate of 1 m (1 rad for a torsional mode) at the mode's largest entry */
    for (int i = 0; i < nm; i++) {
        double big = 0;
        for (int d = 0; d < n; d++) big = fmax(big, fabs(m->V[(size_t)i * n + d]));
        unit[i] = 1 / big;
    }
    unsigned seed = 12345;
    double err[2] = {0, 0}, nonlin = 0;
    for (int t = 0; t < 6; t++) {
        double dir[16];
        for (int i = 0; i < nm; i++) {
            seed = seed * 1103515245u + 12345u;
            dir[i] = (((seed >> 8) & 0xffff) / 32768.0 - 1.0);
        }
        for (int half = 0; half < 2; half++) {
            double amp = half ? 0.25 : 0.5, lam[16], eta[16], x[64], f[64], fs = 0;
            for (int i = 0; i < nm; i++) lam[i] = m->omega2[i] * amp * unit[i] * dir[i], fs = fmax(fs, fabs(lam[i]));
            if (full_static(&s, m, lam, eta) || condensed(m, eta, x, f)) { CHECK(0, "%s", gal_error_message()); break; }
            for (int i = 0; i < nm; i++) {
                err[half] = fmax(err[half], fabs(f[i] - lam[i]) / fs);
                if (!half) nonlin = fmax(nonlin, fabs(m->omega2[i] * eta[i] - lam[i]) / fs);
            }
        }
    }
    printf("    (random states of %d modes: reduced against condensed force %.2e of the force at 0.5 m, %.2e at "
           "0.25 m; the nonlinear part itself %.2e)\n", nm, err[0], err[1], nonlin);
    CHECK(err[0] < 1e-2, "reduced force off the condensed one by %g", err[0]);
    CHECK(err[1] < err[0] / 4, "the error should fall at least fourfold: %g then %g", err[0], err[1]);
    CHECK(nonlin > 10 * err[0], "the test must exercise the nonlinearity: %g vs %g", nonlin, err[0]);
    gal_rom_free(m);
    free_span(&s);
}

/* Free vibration started by a modal velocity of the first symmetric mode of a family: the reduced
 * model against the full model (mid-span amplitude and period) and at small amplitude the modal
 * period. The reduced step is a 400th of the period (its period error (w h)^2/12 = 2e-5). */
static void free_vibration_vs_full(gal_family fam, double swing)
{
    span s;
    int want[GAL_FAMILY_COUNT] = {3, 2, 1, 0};
    if (make_span(&s, &sagged, 20000, want)) return;
    int iv = 0;
    while (s.md.mode[s.sel[iv]].family != fam || s.md.mode[s.sel[iv]].symmetry != GAL_SYM_SYMMETRIC) iv++;
    double w = s.md.mode[s.sel[iv]].omega, T = 2 * GAL_PI / w, scale = sqrt(sagged.mass * sagged.length / 2);
    int mid = s.eq.rod->nn / 2, oq = 3 * mid + (fam == GAL_FAMILY_HORIZONTAL ? 1 : 2), n = s.md.ndof;
    gal_rom_opts o;
    gal_rom_default_opts(&o); /* the model of every reduced run: sampled, weighted, kept tangent */
    o.h = T / 400;
    for (int large = 0; large < 2; large++) {
        double vel = (large ? swing : 1e-3) * w * scale * 0.5;
        gal_rom *m = gal_rom_alloc(s.eq.rod, s.eq.q, &s.md, s.sel, s.r, &o, NULL);
        gal_dyn_opts dop;
        gal_dyn_default_opts(&dop);
        dop.h = T / 100;
        double *v0 = calloc(s.eq.rod->nq, sizeof(double));
        for (int j = 0; j < n; j++) v0[s.eq.rod->free_q[j]] = s.md.shape[(size_t)s.sel[iv] * n + j] * vel;
        gal_dyn *fd = gal_dyn_alloc(s.eq.rod, s.eq.q, v0, &dop, NULL);
        CHECK(m && fd && gal_rom_start(m, 0, s.eq.q, v0) == GAL_OK, "%s", gal_error_message());
        if (!m || !fd) { gal_rom_free(m); gal_dyn_free(fd); free(v0); break; }
        double zr_min = 1e9, zr_max = -1e9, zf_min = 1e9, zf_max = -1e9, prev_r = 0, prev_f = 0;
        double first_r = -1, last_r = -1, first_f = -1, last_f = -1;
        int nr = 0, nf = 0;
        for (int k = 1; k <= 10 * 100; k++) {
            double t = k * dop.h;
            if (gal_rom_advance(m, t) || gal_dyn_step(fd)) { CHECK(0, "%s", gal_error_message()); break; }
            double zr = gal_rom_entry(m, oq, 0) - s.eq.q[oq], zf = fd->q[oq] - s.eq.q[oq];
            zr_min = fmin(zr_min, zr), zr_max = fmax(zr_max, zr), zf_min = fmin(zf_min, zf), zf_max = fmax(zf_max, zf);
            if (prev_r < 0 && zr >= 0) { double tc = t - dop.h * zr / (zr - prev_r); if (first_r < 0) first_r = tc; else nr++; last_r = tc; }
            if (prev_f < 0 && zf >= 0) { double tc = t - dop.h * zf / (zf - prev_f); if (first_f < 0) first_f = tc; else nf++; last_f = tc; }
            prev_r = zr, prev_f = zf;
        }
        double Tr = (last_r - first_r) / nr, Tf = (last_f - first_f) / nf;
        printf("    (%s %s: mid-span p-p full %.4g m, reduced %.4g m; period full %.5f s, reduced %.5f s, modal %.5f s)\n",
               gal_family_names[fam], large ? "large" : "small", zf_max - zf_min, zr_max - zr_min, Tf, Tr, T);
        if (!large) CHECK_REL(Tr, T, 1e-4);
        CHECK_REL(zr_max - zr_min, zf_max - zf_min, large ? 0.03 : 0.01);
        CHECK_REL(Tr, Tf, large ? 0.01 : 0.005);
        free(v0);
        gal_dyn_free(fd);
        gal_rom_free(m);
    }
    free_span(&s);
}

static void test_free_vibration_vs_full(void)
{
    free_vibration_vs_full(GAL_FAMILY_VERTICAL, 1.0);
    free_vibration_vs_full(GAL_FAMILY_HORIZONTAL, 2.0);
}

/* The damping the pipeline builds (modal over the band: every mode below 5 Hz has the ratio zeta)
 * projected on the reduced basis is the full model's at every selected mode: 2 zeta w_i on the
 * diagonal (not 2 zeta w_i^2 nor zeta w_i), nothing between two modes. */
static void test_modal_damping_every_mode(void)
{
    span s;
    int want[GAL_FAMILY_COUNT] = {3, 2, 2, 0};
    if (make_span(&s, &sagged, 20000, want)) return;
    double zeta = 0.03;
    gal_damping *C = gal_damping_modal_alloc(s.eq.rod, s.eq.q, zeta, GAL_DAMPING_BAND_HZ);
    gal_rom_opts o;
    gal_rom_default_opts(&o); /* sampled, weighted: Cr is projected on the basis all the same */
    o.damping = C;
    gal_rom *m = C ? gal_rom_alloc(s.eq.rod, s.eq.q, &s.md, s.sel, s.r, &o, NULL) : NULL;
    CHECK(m != NULL, "%s", gal_error_message());
    if (m) {
        int r = m->r, nm = m->nmodes;
        double cmax = 2 * zeta * sqrt(m->omega2[nm - 1]);
        for (int i = 0; i < nm; i++)
            for (int j = 0; j < nm; j++)
                CHECK_NEAR(m->Cr[i * r + j], i == j ? 2 * zeta * sqrt(m->omega2[i]) : 0.0, 1e-6 * cmax);
    }
    gal_rom_free(m);
    gal_damping_free(C);
    free_span(&s);
}

int main(void)
{
    RUN(test_kirchhoff_carrier);
    RUN(test_static_response);
    RUN(test_force_at_random_states);
    RUN(test_free_vibration_vs_full);
    RUN(test_modal_damping_every_mode);
    return CHECK_SUMMARY();
}
