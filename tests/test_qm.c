/* test_qm.c: the quadratic manifold's inertia (qm.h): the reduced mass M(x) and the convective
 * term against P(x)^T M (P a + Theta(v, v)) formed over the full dofs, the kinetic energy
 * |P v|_M^2 / 2, and the step's inertia term (momentum form with a discrete gradient) whose work
 * over x1 - x0 is exactly T1 - T0; the static vectors: the static response to a mean load in the
 * manifold's linear span, M-orthonormal to the modes. */
#include "check.h"
#include "gallop.h"
#include "gallop/modes/modes.h"
#include "gallop/reduced/rom.h"
#include "gallop/statics/statics.h"
#include "reduced/qm.h"
#include "base/chol.h"

static const gal_rod_params sagged = {.length = 150, .elements = 24, .EA = 3e7, .EI = 30, .GJ = 200, .mass = 1.6,
                                      .polar_inertia = 1.6e-4, .gravity = 9.80665, .torsion = 1, .twist_clamped = 1};

typedef struct {
    gal_equilibrium eq;
    gal_modes md;
    int sel[16], r;
    gal_rom *m;
} span;

static int make_loaded(span *s, const double *mean_load, int static_vectors)
{
    memset(s, 0, sizeof *s);
    int want[GAL_FAMILY_COUNT] = {3, 2, 1, 0};
    if (gal_statics_solve(&sagged, GAL_BY_SAG, 4.0, NULL, &s->eq) || gal_modes_find(s->eq.rod, s->eq.q, want, 60, &s->md)) {
        CHECK(0, "%s", gal_error_message());
        return 1;
    }
    for (int k = 0; k < s->md.n && s->r < 16; k++)
        if (s->md.mode[k].selected) s->sel[s->r++] = k;
    gal_rom_opts o;
    gal_rom_default_opts(&o);
    o.manifold = 1, o.hyper = 0, o.mean_load = mean_load, o.static_vectors = static_vectors;
    s->m = gal_rom_alloc(s->eq.rod, s->eq.q, &s->md, s->sel, s->r, &o, NULL);
    CHECK(s->m != NULL && s->m->qm && s->m->qm->inertia, "%s", gal_error_message());
    return s->m == NULL;
}

static int make(span *s) { return make_loaded(s, NULL, 0); }

static void clear(span *s)
{
    gal_rom_free(s->m);
    gal_modes_clear(&s->md);
    gal_equilibrium_clear(&s->eq);
}

/* states of about a metre at mid-span: mode k's coordinate ~ sqrt(m L) / (k + 1) */
static void state(const gal_rom *m, double scale, int seed, double *x)
{
    for (int k = 0; k < m->r; k++) x[k] = scale * sqrt(sagged.mass * sagged.length) * sin(1.7 * (k + 1) + seed) / (k + 1);
}

static void test_mass_and_convective(void)
{
    span s;
    if (make(&s)) return;
    gal_rom *m = s.m;
    int n = m->ndof, r = m->r;
    double x[16], v[16], a[16], fin[16], ref[16], *P = malloc((size_t)n * r * sizeof(double));
    double *up = malloc(n * sizeof(double)), *um = malloc(n * sizeof(double)), *u0 = malloc(n * sizeof(double));
    double *y = malloc(n * sizeof(double)), *My = malloc(n * sizeof(double)), *xs = malloc(r * sizeof(double));
    state(m, 1.0, 0, x), state(m, 2.0, 1, v), state(m, 0.5, 2, a);
    gal_rom_qm_inertia(m, x, v, a, fin, NULL);
    memcpy(P, gal_rom_qm_basis(m, x), (size_t)n * r * sizeof(double));
    /* Theta(v, v) = d^2/ds^2 u(x + s v), exact by second differences (u is quadratic) */
    for (int k = 0; k < r; k++) xs[k] = x[k] + v[k];
    gal_rom_qm_displacement(m, xs, NULL, up, NULL);
    for (int k = 0; k < r; k++) xs[k] = x[k] - v[k];
    gal_rom_qm_displacement(m, xs, NULL, um, NULL);
    gal_rom_qm_displacement(m, x, NULL, u0, NULL);
    double T = 0;
    for (int d = 0; d < n; d++) {
        double pa = 0, pv = 0;
        for (int k = 0; k < r; k++) pa += P[(size_t)k * n + d] * a[k], pv += P[(size_t)k * n + d] * v[k];
        y[d] = pa + (up[d] - 2 * u0[d] + um[d]);
        u0[d] = pv;
    }
    gal_rod_mass_mult(m->rod, y, My);
    double err = 0, mx = 0;
    for (int k = 0; k < r; k++) {
        ref[k] = 0;
        for (int d = 0; d < n; d++) ref[k] += P[(size_t)k * n + d] * My[d];
        err = fmax(err, fabs(fin[k] - ref[k])), mx = fmax(mx, fabs(ref[k]));
    }
    printf("    (M(x) a + c(x, v) against P^T M (P a + Theta(v, v)): %.1e of %.2g)\n", err / mx, mx);
    CHECK(err <= 1e-9 * mx, "inertia %g of %g", err, mx);
    gal_rod_mass_mult(m->rod, u0, My);
    for (int d = 0; d < n; d++) T += 0.5 * u0[d] * My[d];
    CHECK_REL(gal_rom_qm_kinetic(m, x, v), T, 1e-10);
    /* the iteration matrix's inertia is M(x) = P^T M P */
    double J[256] = {0};
    gal_rom_qm_iteration(m, x, v, 1, 0, J);
    err = 0, mx = 0;
    for (int j = 0; j < r; j++) {
        gal_rod_mass_mult(m->rod, P + (size_t)j * n, My);
        for (int i = 0; i < r; i++) {
            double s = 0;
            for (int d = 0; d < n; d++) s += P[(size_t)i * n + d] * My[d];
            err = fmax(err, fabs(J[i * r + j] - s)), mx = fmax(mx, fabs(s));
        }
    }
    CHECK(err <= 1e-10 * mx, "M(x) = P^T M P: %g of %g", err, mx);
    free(P), free(up), free(um), free(u0), free(y), free(My), free(xs);
    clear(&s);
}

/* With x1 = x0 + h (v0 + v1) / 2 (the trapezoidal update), f1 . (x1 - x0) = T(x1, v1) - T(x0, v0). */
static void test_step_work(void)
{
    span s;
    if (make(&s)) return;
    gal_rom *m = s.m;
    int r = m->r;
    double h = 0.05, dx = 0;
    state(m, 1.0, 3, m->x), state(m, 2.0, 4, m->v), state(m, 1.0, 5, m->a), state(m, 2.5, 6, m->v1);
    for (int k = 0; k < r; k++) m->x1[k] = m->x[k] + 0.5 * h * (m->v[k] + m->v1[k]), m->a1[k] = m->a[k];
    gal_rom_qm_begin(m);
    gal_rom_qm_end(m, h);
    double T0 = gal_rom_qm_kinetic(m, m->x, m->v), T1 = gal_rom_qm_kinetic(m, m->x1, m->v1), w = 0;
    for (int k = 0; k < r; k++) w += m->qm->f1[k] * (m->x1[k] - m->x[k]), dx = fmax(dx, fabs(m->x1[k] - m->x[k]));
    printf("    (step work %.10g J, T1 - T0 %.10g J)\n", w, T1 - T0);
    CHECK(fabs(w - (T1 - T0)) <= 1e-10 * fmax(T0, T1), "work %g against %g", w, T1 - T0);
    CHECK(fabs(T1 - T0) > 1e-3 * T0, "a step that changes T (%g %g)", T0, T1);
    clear(&s);
}

/* A mean load (out-of-plane drag, in-plane lift, twist moment: uneven along the span) whose static
 * response K0^-1 F, and with static_vectors = 2 each part's, lies in the span of V to round-off;
 * the added columns M-orthonormal to the modes and to each other. */
static void test_static_vectors(void)
{
    for (int sv = 1; sv <= 2; sv++) {
        span s0;
        if (make(&s0)) return;
        int nsel = s0.r, nq = s0.m->nq, n = s0.m->ndof, nn = s0.m->rod->nn;
        clear(&s0);
        double *F = calloc(nq, sizeof(double)), *f = calloc(nq, sizeof(double)), *b = malloc(n * sizeof(double));
        double *u = malloc(n * sizeof(double)), *Mu = malloc(n * sizeof(double));
        for (int i = 0; i < nn; i++) F[3 * i + 1] = 8.0 + 3 * sin(0.3 * i), F[3 * i + 2] = 2.0 * cos(0.2 * i);
        for (int j = 0; 3 * nn + j < nq; j++) F[3 * nn + j] = 0.4 + 0.1 * j;
        span s;
        if (make_loaded(&s, F, sv)) return;
        gal_rom *m = s.m;
        CHECK(m->r == nsel + (sv == 2 ? 3 : 1) && m->nmodes == m->r && m->qm->nstatic == m->r - nsel,
              "basis %d (modes %d, static %d)", m->r, nsel, m->qm->nstatic);
        for (int p = 0; p < (sv == 2 ? 3 : 1); p++) {
            for (int k = 0; k < nq; k++) f[k] = sv == 1 || (p == 2 ? k >= 3 * nn : k < 3 * nn && (k % 3 == 1) == (p == 0)) ? F[k] : 0;
            gal_rod_gather(m->rod, f, b);
            gal_chol_solve(m->chol0, b, u);
            gal_rod_mass_mult(m->rod, u, Mu);
            double n0 = 0, n1 = 0;
            for (int d = 0; d < n; d++) n0 += u[d] * Mu[d];
            for (int k = 0; k < m->r; k++) { /* u less its M-projection on V */
                double c = 0;
                for (int d = 0; d < n; d++) c += m->V[(size_t)k * n + d] * Mu[d];
                for (int d = 0; d < n; d++) u[d] -= c * m->V[(size_t)k * n + d];
            }
            gal_rod_mass_mult(m->rod, u, Mu);
            for (int d = 0; d < n; d++) n1 += u[d] * Mu[d];
            printf("    (static vectors %d, part %d: %.3g of the response outside V)\n", sv, p, sqrt(n1 / n0));
            CHECK(n1 <= 1e-20 * n0, "the static response outside V: %g of %g", sqrt(n1), sqrt(n0));
        }
        double orth = 0;
        for (int k = nsel; k < m->r; k++) {
            gal_rod_mass_mult(m->rod, m->V + (size_t)k * n, Mu);
            for (int j = 0; j <= k; j++) {
                double c = 0;
                for (int d = 0; d < n; d++) c += m->V[(size_t)j * n + d] * Mu[d];
                orth = fmax(orth, fabs(c - (j == k)));
            }
        }
        CHECK(orth <= 1e-10, "V^T M V - I on the static vectors: %g", orth);
        free(F), free(f), free(b), free(u), free(Mu);
        clear(&s);
    }
}

int main(void)
{
    RUN(test_mass_and_convective);
    RUN(test_step_work);
    RUN(test_static_vectors);
    return CHECK_SUMMARY();
}
