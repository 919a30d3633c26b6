/* test_rom_orbit.c: a growth's correction is taken over the orbit (rom_adapt.h:
 * GAL_ROM_ORBIT_SAMPLES), so the grown basis does not depend on the instant the check trips.
 * The case: data/scenes/iced_gallop.ini at 80 elements, galloping; the same first growth made at
 * two instants a fraction of a period apart (as round-off moves a trip: BENCHMARKS.md, issue 13,
 * "The fine-mesh twist depends on the instant of a late growth"): with orbit_vectors = 1 and 2
 * the grown bases are nearly the same. (The whole residual direction at one instant, a growth's
 * correction before main's family-alone one, was orthogonal between the two.) */
#include "check.h"
#include "sim_fixture.h"
#include "gallop.h"
#include "gallop/reduced/rom_adapt.h"

/* The basis grown at time t (in place, its first growth: the correction alone, orbit_vectors ov)
 * into V (n x r, malloc'd), the start basis's size into r0; the grown size, or -1. The growth
 * starts the new model from the old one's state at the check (not where the sampling ended) and
 * counts the sampling's steps. */
static int grown_at(const gal_sim_setup *s, double t, int ov, double **V, int *r0)
{
    const gal_data *d = s->data;
    const gal_rod *rod = d->eq.rod;
    int sel[64], ns = 0, r = -1;
    double fhi = 0;
    for (int k = 0; k < d->md.n && ns < 64; k++)
        if (d->md.mode[k].selected) sel[ns++] = k, fhi = fmax(fhi, d->md.mode[k].frequency_hz);
    gal_rom_opts o;
    gal_rom_default_opts(&o);
    o.h = 1 / (40 * fhi), o.damping = d->damping;
    gal_force F = {0};
    F.eval = gal_loads_full, F.element = gal_loads_element, F.ctx = (void *)&d->loads; /* read only */
    gal_rom_adapt a;
    gal_rom *m;
    double *du = malloc((size_t)rod->ndof * sizeof(double));
    gal_rom_check chk;
    double *q = malloc(2 * (size_t)rod->nq * sizeof(double)), *q1 = q + rod->nq;
    int st = gal_rom_adapt_init(&a, &m, rod, d->eq.q, &d->md, sel, ns, &o, &F);
    a.orbit_vectors = ov, a.relax = 0;
    if (!st) *r0 = m->r, st = gal_rom_start(m, 0.0, d->q_start, d->v_start);
    if (!st) st = gal_rom_advance(m, t);
    if (!st) st = gal_rom_adapt_residual(&a, m, &chk, du);
    double tc = m->t; /* the check's instant (the last step past t) */
    long steps = m->steps;
    if (!st) gal_rom_reconstruct(m, q, NULL), st = gal_rom_adapt_grow(&a, &m, &chk, du);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (!st && (*V = malloc((size_t)m->r * m->ndof * sizeof(double)))) {
        r = m->r;
        memcpy(*V, m->V, (size_t)r * m->ndof * sizeof(double));
        CHECK(a.nevents == 1 && a.ev[0].corrections >= 1 && a.ev[0].mode_added < 0 && m->t == tc,
              "one growth by corrections alone at %g s: %d, %d, mode %d, t %g", t, a.nevents, a.ev[0].corrections,
              a.ev[0].mode_added, m->t);
    }
    if (!st) {
        gal_rom_reconstruct(m, q1, NULL);
        double e = 0, sc = 0;
        for (int k = 0; k < rod->nq; k++) e = fmax(e, fabs(q1[k] - q[k])), sc = fmax(sc, fabs(q[k]));
        CHECK(e <= 1e-10 * sc, "the state moved by %g of %g at the growth", e, sc);
        CHECK(m->steps == steps + a.orbit_steps && (a.orbit_steps > 0) == (ov > 0), "steps %ld: %ld + %ld sampling",
              m->steps, steps, a.orbit_steps);
    }
    free(du);
    free(q);
    gal_rom_free(m);
    gal_rom_adapt_clear(&a);
    return r;
}

/* The part of span V2 outside span V1 (both M-orthonormal, r columns): r - |V1^T M V2|_F^2. */
static double outside(const gal_rod *rod, const double *V1, const double *V2, int r)
{
    int n = rod->ndof;
    double *Mv = malloc((size_t)n * sizeof(double)), out = r;
    for (int j = 0; j < r; j++) {
        gal_rod_mass_mult(rod, V2 + (size_t)j * n, Mv);
        for (int i = 0; i < r; i++) {
            double p = 0;
            for (int d = 0; d < n; d++) p += V1[(size_t)i * n + d] * Mv[d];
            out -= p * p;
        }
    }
    free(Mv);
    return out;
}

static void test_orbit(void)
{
    gal_scene sc;
    const char *ov[] = {"simulation.duration=400"};
    gal_sim_setup s;
    if (sim_fixture(&sc, &s, "data/scenes/iced_gallop.ini", ov, 1)) return;
    double f1 = INFINITY;
    for (int k = 0; k < s.data->md.n; k++)
        if (s.data->md.mode[k].selected) f1 = fmin(f1, s.data->md.mode[k].frequency_hz);
    double t1 = 300, t2 = 300 + 0.4 / f1, diff[3] = {0};
    for (int vectors = 0; vectors <= 2; vectors++) {
        double *V1 = NULL, *V2 = NULL;
        int r0 = 0, r1 = grown_at(&s, t1, vectors, &V1, &r0), r2 = grown_at(&s, t2, vectors, &V2, &r0);
        CHECK(r1 > r0 && r1 == r2, "bases of %d and %d", r1, r2);
        if (r1 > r0 && r1 == r2) {
            diff[vectors] = outside(s.data->eq.rod, V1, V2, r1) / (r1 - r0); /* the start basis is shared */
            printf("    iced_gallop, 80 elements, orbit_vectors %d: the bases grown at %.2f s and %.2f s (0.4 period "
                   "later) differ by %.4f of each of the %d vectors added (1: orthogonal)\n", vectors, t1, t2,
                   diff[vectors], r1 - r0);
        }
        free(V1), free(V2);
    }
    /* the orbit's directions do not depend on the instant (the instant's family correction, ov 0,
     * is printed: 0.0037 here; the whole residual direction, before main's family-alone
     * correction, read 0.9994) */
    CHECK(diff[1] <= 0.1 && diff[2] <= 0.1, "the orbit's differ by %g (1 vector), %g (2)", diff[1], diff[2]);
    gal_sim_setup_clear(&s);
}

int main(void)
{
    RUN(test_orbit);
    return CHECK_SUMMARY();
}
