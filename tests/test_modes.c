/* test_modes.c: natural frequencies against cable theory (Irvine & Caughey 1974; Irvine, Cable
 * Structures, 1981): out-of-plane, in-plane antisymmetric and symmetric (lambda^2 below, at and
 * above 4 pi^2), torsional string modes at 100 elements with small EI; the error falls with mesh
 * refinement at second order. The tolerances are a margin over what the discretization allows:
 * a string of N lumped masses has w_n = (2N c / L) sin(n pi / 2N), a relative error of
 * -(n pi / N)^2 / 24, which is what the rod shows for the out-of-plane and torsional modes; the
 * in-plane modes add the shallow-cable theory's own O((sag/L)^2) error, 8 (d/L)^2 = 7e-4 here. */
#include <string.h>

#include "check.h"
#include "gallop.h"
#include "gallop/modes/modes.h"
#include "gallop/statics/statics.h"
#include "modes/modes_impl.h"

#define L 100.0
#define H 20000.0
#define M 1.5
#define G 9.80665

/* Relative error a lumped n-th string mode of wave number n may carry at nel elements (x1.5). */
static double string_tol(int n, int nel)
{
    double k = n * GAL_PI / nel;
    return 1.5 * k * k / 24 + 2e-5;
}

/* The shallow-cable theory's own error on the in-plane modes: 8 (sag/L)^2 (sag of this span). */
#define INPLANE_THEORY (8 * pow(M * G * L / (8 * H), 2)) /* sag / L = m g L / 8 H */

static gal_rod_params span(int nel, double EA)
{
    gal_rod_params p = {.length = L, .elements = nel, .EA = EA, .EI = 1e-2, .GJ = 100,
                        .mass = M, .polar_inertia = 1e-4, .gravity = G, .torsion = 1,
                        .twist_clamped = 1};
    return p;
}

/* First symmetric in-plane root: tan(x) = x - (4/lambda^2) x^3, x = w_bar/2 in (pi/2, 3pi/2). */
static double irvine_symmetric(double lam2)
{
    double lo = GAL_PI / 2 + 1e-12, hi = 1.5 * GAL_PI - 1e-12;
    for (int it = 0; it < 200; it++) {
        double x = 0.5 * (lo + hi), f = tan(x) - x + 4.0 / lam2 * x * x * x;
        if (f > 0) hi = x; else lo = x;
    }
    return lo + hi; /* w_bar = 2 x */
}

typedef struct {
    gal_equilibrium eq;
    gal_modes md;
} solved;

static int solve(solved *s, int nel, double EA, const int want[GAL_FAMILY_COUNT])
{
    gal_rod_params p = span(nel, EA);
    int st = gal_statics_solve(&p, GAL_BY_TENSION, H, NULL, &s->eq);
    CHECK(st == GAL_OK, "statics: %s", gal_error_message());
    if (st) return st;
    st = gal_modes_find(s->eq.rod, s->eq.q, want, 400, &s->md);
    CHECK(st == GAL_OK, "modes: %s", gal_error_message());
    return st;
}

static void release(solved *s)
{
    gal_modes_clear(&s->md);
    gal_equilibrium_clear(&s->eq);
}

/* k-th mode (1-based) of a family and symmetry (GAL_SYM_NONE: any) */
static double freq(const gal_modes *md, gal_family f, gal_symmetry sy, int k)
{
    for (int i = 0; i < md->n; i++)
        if (md->mode[i].family == f && (sy == GAL_SYM_NONE || md->mode[i].symmetry == sy) && --k == 0)
            return md->mode[i].frequency_hz;
    return NAN;
}

static void test_out_of_plane_and_antisymmetric(void)
{
    solved s;
    int want[GAL_FAMILY_COUNT] = {4, 4, 0, 0};
    if (solve(&s, 100, 1e8, want)) return;
    double f1 = sqrt(H / M) / (2 * L);
    for (int n = 1; n <= 4; n++) {
        double fh = freq(&s.md, GAL_FAMILY_HORIZONTAL, GAL_SYM_NONE, n);
        CHECK_REL(fh, n * f1, string_tol(n, 100));
        gal_symmetry sy = n % 2 ? GAL_SYM_SYMMETRIC : GAL_SYM_ANTISYMMETRIC;
        int k = 0;
        for (int i = 0; i < s.md.n; i++)
            if (s.md.mode[i].family == GAL_FAMILY_HORIZONTAL && ++k == n)
                CHECK(s.md.mode[i].symmetry == sy, "horizontal mode %d symmetry %d", n, s.md.mode[i].symmetry);
    }
    for (int n = 1; n <= 2; n++) {
        double fa = freq(&s.md, GAL_FAMILY_VERTICAL, GAL_SYM_ANTISYMMETRIC, n);
        CHECK_REL(fa, 2 * n * f1, string_tol(2 * n, 100) + INPLANE_THEORY);
    }
    printf("    (f1 %.5f Hz: horizontal %.5f %.5f, antisymmetric vertical %.5f)\n", f1,
           freq(&s.md, GAL_FAMILY_HORIZONTAL, GAL_SYM_NONE, 1), freq(&s.md, GAL_FAMILY_HORIZONTAL, GAL_SYM_NONE, 2),
           freq(&s.md, GAL_FAMILY_VERTICAL, GAL_SYM_ANTISYMMETRIC, 1));
    release(&s);
}

/* lambda^2 = (m g L / H)^2 L / (H Le / EA); choose EA for a target lambda^2 */
static void check_symmetric(double lam2_target)
{
    double d = M * G * L * L / (8 * H), Le = L * (1 + 8 * (d / L) * (d / L));
    double EA = lam2_target * H * Le / (pow(M * G * L / H, 2) * L);
    solved s;
    int want[GAL_FAMILY_COUNT] = {3, 1, 0, 0};
    if (solve(&s, 100, EA, want)) return;
    double dd = s.eq.sag, Le2 = L * (1 + 8 * (dd / L) * (dd / L)), Hh = s.eq.horizontal_tension;
    double lam2 = pow(M * G * L / Hh, 2) * L / (Hh * Le2 / EA);
    double fs = irvine_symmetric(lam2) * sqrt(Hh / M) / (2 * GAL_PI * L);
    double fa = 2 * sqrt(Hh / M) / (2 * L);
    /* at the crossover the first symmetric and antisymmetric modes coincide; compare the pair */
    double got = freq(&s.md, GAL_FAMILY_VERTICAL, GAL_SYM_SYMMETRIC, 1);
    if (fabs(lam2 - 4 * GAL_PI * GAL_PI) < 1) {
        double v1 = freq(&s.md, GAL_FAMILY_VERTICAL, GAL_SYM_NONE, 1), v2 = freq(&s.md, GAL_FAMILY_VERTICAL, GAL_SYM_NONE, 2);
        CHECK_REL(v1, fs, 1e-3);
        CHECK_REL(v2, fa, string_tol(2, 100) + INPLANE_THEORY);
        /* and the labels: of the nearly coincident pair, the one called symmetric is Irvine's
         * symmetric mode and the one called antisymmetric the string's */
        CHECK_REL(got, fs, 1e-3);
        CHECK_REL(freq(&s.md, GAL_FAMILY_VERTICAL, GAL_SYM_ANTISYMMETRIC, 1), fa, string_tol(2, 100) + INPLANE_THEORY);
        int pair[2], np = 0;
        for (int i = 0; i < s.md.n && np < 2; i++)
            if (s.md.mode[i].family == GAL_FAMILY_VERTICAL) pair[np++] = i;
        CHECK(np == 2 && s.md.mode[pair[0]].symmetry != s.md.mode[pair[1]].symmetry &&
              s.md.mode[pair[0]].symmetry != GAL_SYM_NONE && s.md.mode[pair[1]].symmetry != GAL_SYM_NONE,
              "the crossover pair's labels");
    } else {
        CHECK_REL(got, fs, 1e-3); /* achieved 3.5e-4 .. 5.3e-4 over the three lambda^2 */
    }
    printf("    (lambda^2 %.2f: symmetric %.5f Hz vs Irvine %.5f, error %.3f%%)\n", lam2, got, fs,
           100 * (got - fs) / fs);
    release(&s);
}

static void test_symmetric_below_crossover(void) { check_symmetric(4.0); }
static void test_symmetric_at_crossover(void) { check_symmetric(4 * GAL_PI * GAL_PI); }
static void test_symmetric_above_crossover(void) { check_symmetric(400.0); }

static void test_torsional_string(void)
{
    solved s;
    int want[GAL_FAMILY_COUNT] = {0, 0, 3, 0};
    if (solve(&s, 100, 1e8, want)) return;
    double L0 = s.eq.unstretched_length;
    for (int n = 1; n <= 3; n++) {
        double ft = n * sqrt(100 / 1e-4) / (2 * L0);
        CHECK_REL(freq(&s.md, GAL_FAMILY_TORSIONAL, GAL_SYM_NONE, n), ft, string_tol(n, 100));
    }
    printf("    (torsional %.5f Hz vs %.5f)\n", freq(&s.md, GAL_FAMILY_TORSIONAL, GAL_SYM_NONE, 1),
           sqrt(100 / 1e-4) / (2 * L0));
    release(&s);
}

/* Mass-normalized, M-orthogonal shapes. */
static void test_mass_normalized(void)
{
    solved s;
    int want[GAL_FAMILY_COUNT] = {2, 2, 1, 0};
    if (solve(&s, 40, 1e8, want)) return;
    int n = s.md.ndof;
    double *mdiag = malloc(n * sizeof(double));
    gal_rod_mass_diag(s.eq.rod, mdiag);
    double worst = 0;
    for (int a = 0; a < s.md.n; a++)
        for (int b = a; b < s.md.n; b++) {
            double m = 0;
            for (int j = 0; j < n; j++) m += s.md.shape[a * n + j] * mdiag[j] * s.md.shape[b * n + j];
            worst = fmax(worst, fabs(m - (a == b)));
        }
    CHECK(worst < 1e-9, "phi^T M phi - I: %g", worst);
    free(mdiag);
    release(&s);
}

/* Refinement: the error of the 3rd out-of-plane mode falls as h^2. */
static void test_convergence_order(void)
{
    double err[3];
    int nels[3] = {25, 50, 100};
    for (int k = 0; k < 3; k++) {
        solved s;
        int want[GAL_FAMILY_COUNT] = {0, 3, 0, 0};
        if (solve(&s, nels[k], 1e8, want)) return;
        double exact = 3 * sqrt(s.eq.horizontal_tension / M) / (2 * L);
        err[k] = fabs(freq(&s.md, GAL_FAMILY_HORIZONTAL, GAL_SYM_NONE, 3) - exact) / exact;
        release(&s);
    }
    double p1 = log2(err[0] / err[1]), p2 = log2(err[1] / err[2]);
    printf("    (3rd out-of-plane errors %.2e %.2e %.2e: orders %.2f %.2f)\n", err[0], err[1], err[2], p1, p2);
    CHECK(p1 > 1.7 && p2 > 1.5, "order %g %g", p1, p2);
}

/* The modes a search by family selects (torsional ones by a shift at each estimate, computing a
 * window of a few modes) against every mode from the bottom: the same frequency, family and shape
 * (M-inner product 1 up to sign) at the rank the inertia of K - sigma M gave (gal_mode.index). On a
 * 300 m Drake span (torsional modes far above the flexural ones: the shifts are used), with
 * eccentric ice (twist coupled to the motion through M and K: from the bottom) and with a soft
 * twist (torsional modes among the flexural ones, as on a bundle: foreseen, one run). */
static void check_against_bottom(const gal_rod_params *p, const int want[GAL_FAMILY_COUNT], int expect)
{
    gal_equilibrium eq;
    gal_modes md, all;
    CHECK(gal_statics_solve(p, GAL_BY_TENSION, 28000, NULL, &eq) == GAL_OK, "statics: %s", gal_error_message());
    CHECK(gal_modes_find(eq.rod, eq.q, want, 400, &md) == GAL_OK, "find: %s", gal_error_message());
    int top = 0, nsel = 0;
    for (int k = 0; k < md.n; k++) {
        if (md.mode[k].index > top) top = md.mode[k].index;
        CHECK(k == 0 || md.mode[k].index > md.mode[k - 1].index, "ranks in order at %d", k);
    }
    CHECK(gal_modes_solve(eq.rod, eq.q, top + 2, &all) == GAL_OK, "all: %s", gal_error_message());
    if (expect == 1) /* by shifts: fewer modes than their ranks */
        CHECK(md.n < top && md.factorizations > 1, "computed %d of %d modes in %ld factorizations", md.n, top,
              md.factorizations);
    if (expect == 2) /* the torsional modes among the lowest, foreseen: one run */
        CHECK(md.factorizations == 1, "%ld factorizations", md.factorizations);
    int n = md.ndof;
    double *mphi = malloc((size_t)n * sizeof(double));
    for (int k = 0; k < md.n; k++) {
        if (!md.mode[k].selected) continue;
        nsel++;
        const gal_mode *a = md.mode + k, *b = all.mode + a->index - 1;
        CHECK_REL(a->frequency_hz, b->frequency_hz, 1e-9);
        CHECK(a->family == b->family, "mode %d: family %d vs %d", a->index, a->family, b->family);
        gal_rod_mass_mult(eq.rod, all.shape + (size_t)(a->index - 1) * n, mphi);
        double ip = 0;
        for (int j = 0; j < n; j++) ip += md.shape[(size_t)k * n + j] * mphi[j];
        CHECK(fabs(fabs(ip) - 1) < 1e-6, "mode %d: <phi, M phi_ref> = %.9f", a->index, ip);
    }
    int partners = 0; /* the torsional partners selected beyond the number asked (gal_modes_select) */
    for (int k = 0; k < md.n; k++) partners += md.mode[k].partner != 0;
    CHECK(nsel == want[0] + want[1] + want[2] + partners, "selected %d, %d partners", nsel, partners);
    CHECK(expect == 2 || partners == 0, "%d partners with the twist far above", partners);
    printf("    (%d modes computed for ranks up to %d, %ld factorizations, %ld operator applications, %d partners)\n",
           md.n, top, md.factorizations, md.op_applications, partners);
    free(mphi);
    gal_modes_clear(&md);
    gal_modes_clear(&all);
    gal_equilibrium_clear(&eq);
}

static void test_family_shifts(void)
{
    gal_rod_params p = {.length = 300, .elements = 200, .EA = 2.9e7, .EI = 28, .GJ = 160, .mass = 1.628,
                        .polar_inertia = 1.6e-4, .gravity = G, .torsion = 1, .twist_clamped = 1};
    int want[GAL_FAMILY_COUNT] = {3, 2, 2, 0};
    check_against_bottom(&p, want, 1);
    int want3[GAL_FAMILY_COUNT] = {1, 0, 3, 0};
    check_against_bottom(&p, want3, 1);
    p.ecc_mass = 0.6, p.ecc = 0.02, p.ecc_angle = GAL_PI / 2, p.mass += 0.6; /* ice at the side */
    check_against_bottom(&p, want, 0);
    p.GJ = 2, p.ecc_mass = 0, p.mass -= 0.6; /* soft twist: the torsional modes among the lowest */
    check_against_bottom(&p, want, 2);
}

/* 1 when a and b hold the same modes to the last bit (frequencies, ranks, families, shapes). */
static int same_modes(const gal_modes *a, const gal_modes *b)
{
    if (a->n != b->n || a->ndof != b->ndof) return 0;
    for (int k = 0; k < a->n; k++)
        if (a->mode[k].omega != b->mode[k].omega || a->mode[k].index != b->mode[k].index ||
            a->mode[k].family != b->mode[k].family || a->mode[k].selected != b->mode[k].selected)
            return 0;
    return !memcmp(a->shape, b->shape, (size_t)a->n * a->ndof * sizeof(double));
}

/* The modes about an equilibrium taking over the statics' tangent and analysis (gal_modes_find_eq,
 * gal_modes_solve_eq) are those computed from scratch, to the last bit: clamped and free twist,
 * eccentric ice; the handed tangent is released; with the configuration moved after the statics
 * it is not taken (the modes are those of the configuration moved). */
static void test_handover(void)
{
    gal_rod_params p = {.length = 300, .elements = 150, .EA = 2.9e7, .EI = 28, .GJ = 160, .mass = 1.628,
                        .polar_inertia = 1.6e-4, .gravity = G, .torsion = 1, .twist_clamped = 1};
    int want[GAL_FAMILY_COUNT] = {3, 2, 2, 0};
    for (int v = 0; v < 4; v++) {
        if (v == 1) p.twist_clamped = 0;
        if (v == 2) p.twist_clamped = 1, p.ecc_mass = 0.6, p.ecc = 0.02, p.ecc_angle = GAL_PI / 2, p.mass += 0.6;
        gal_equilibrium eq;
        gal_modes a, b, c, d;
        CHECK(gal_statics_solve(&p, GAL_BY_TENSION, 28000, NULL, &eq) == GAL_OK, "statics: %s", gal_error_message());
        CHECK(eq.tangent != NULL, "case %d: the statics hand over their tangent", v);
        if (v == 3) eq.q[3 * (eq.rod->nn / 2) + 2] += 1e-3; /* moved: the tangent no longer fits */
        { /* taken (values and analysis leave the tangent) exactly when it fits */
            gal_tangent *t = eq.tangent;
            gal_csc *K = gal_csc_clone(t->K);
            memcpy(K->val, t->K->val, (size_t)K->nnz * sizeof(double));
            gal_chol *ch = gal_chol_alloc(K);
            gal_tangent *t2 = gal_tangent_alloc(&K, &ch, t->q, t->nq, t->L0);
            gal_modes_ctx ctx;
            CHECK(t2 && gal_modes_ctx_init(&ctx, eq.rod, eq.q, t2) == GAL_OK, "ctx: %s", gal_error_message());
            CHECK((t2->chol == NULL) == (v != 3), "case %d: the tangent %s", v, v != 3 ? "taken" : "left");
            gal_modes_ctx_clear(&ctx);
            gal_tangent_free(t2);
        }
        CHECK(gal_modes_find(eq.rod, eq.q, want, 400, &a) == GAL_OK, "find: %s", gal_error_message());
        CHECK(gal_modes_solve(eq.rod, eq.q, 9, &c) == GAL_OK, "solve: %s", gal_error_message());
        CHECK(gal_modes_find_eq(&eq, want, 400, &b) == GAL_OK, "find_eq: %s", gal_error_message());
        CHECK(eq.tangent == NULL, "case %d: the tangent is released", v);
        CHECK(same_modes(&a, &b), "case %d: find_eq gives find's modes to the last bit", v);
        CHECK(gal_modes_solve_eq(&eq, 9, &d) == GAL_OK, "solve_eq: %s", gal_error_message());
        CHECK(same_modes(&c, &d), "case %d: solve_eq (no tangent left) gives solve's modes", v);
        gal_modes_clear(&a); gal_modes_clear(&b); gal_modes_clear(&c); gal_modes_clear(&d);
        gal_equilibrium_clear(&eq);
    }
    gal_equilibrium eq;
    gal_modes a, b;
    p.ecc_mass = 0, p.mass -= 0.6;
    CHECK(gal_statics_solve(&p, GAL_BY_TENSION, 28000, NULL, &eq) == GAL_OK, "statics: %s", gal_error_message());
    CHECK(gal_modes_solve(eq.rod, eq.q, 9, &a) == GAL_OK, "solve: %s", gal_error_message());
    CHECK(gal_modes_solve_eq(&eq, 9, &b) == GAL_OK, "solve_eq: %s", gal_error_message());
    CHECK(same_modes(&a, &b), "solve_eq with the tangent gives solve's modes to the last bit");
    gal_modes_clear(&a); gal_modes_clear(&b);
    gal_equilibrium_clear(&eq);
}

int main(void)
{
    RUN(test_handover);
    RUN(test_family_shifts);
    RUN(test_out_of_plane_and_antisymmetric);
    RUN(test_symmetric_below_crossover);
    RUN(test_symmetric_at_crossover);
    RUN(test_symmetric_above_crossover);
    RUN(test_torsional_string);
    RUN(test_mass_normalized);
    RUN(test_convergence_order);
    return CHECK_SUMMARY();
}
