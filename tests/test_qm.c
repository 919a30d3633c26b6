/* test_qm.c: the quadratic manifold's inertia (qm.h): the reduced mass M(x) and the convective
 * term against P(x)^T M (P a + Theta(v, v)) formed over the full dofs, the kinetic energy
 * |P v|_M^2 / 2, and the step's inertia term (momentum form with a discrete gradient) whose work
 * over x1 - x0 is exactly T1 - T0. */
#include "check.h"
#include "gallop.h"
#include "gallop/modes/modes.h"
#include "gallop/reduced/rom.h"
#include "gallop/statics/statics.h"
#include "reduced/qm.h"

static const gal_rod_params sagged = {.length = 150, .elements = 24, .EA = 3e7, .EI = 30, .GJ = 200, .mass = 1.6,
                                      .polar_inertia = 1.6e-4, .gravity = 9.80665, .torsion = 1, .twist_clamped = 1};

typedef struct {
    gal_equilibrium eq;
    gal_modes md;
    int sel[16], r;
    gal_rom *m;
} span;

static int make(span *s)
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
    o.manifold = 1, o.hyper = 0;
    s->m = gal_rom_alloc(s->eq.rod, s->eq.q, &s->md, s->sel, s->r, &o, NULL);
    CHECK(s->m != NULL && s->m->qm && s->m->qm->inertia, "%s", gal_error_message());
    return s->m == NULL;
}

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

int main(void)
{
    RUN(test_mass_and_convective);
    RUN(test_step_work);
    return CHECK_SUMMARY();
}
