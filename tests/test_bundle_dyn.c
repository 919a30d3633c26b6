/* test_bundle_dyn.c: the explicit bundle's dynamics (src/bundle/dynamics.c, loads.c): energy
 * conserved without damping and wind (rho_inf = 1) for twin and quad bundles started in a torsional
 * and a vertical mode at once; damping takes energy out; free vertical vibration of the bundle at
 * its first vertical mode's frequency, which is a single sub-conductor's at the same tension; the
 * wake factor on the leeward sub-conductors only; simulation.newton_tolerance read by the run (a
 * looser one takes fewer Newton iterations, the default's run unchanged bit for bit). */
#include "check.h"
#include "gallop.h"
#include "gallop/model/model.h"
#include "gallop/scene/scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *const scene = "tests/bundle/drake_twin.ini";
#ifndef AT
#define AT 40.0
#define AV 60.0
#endif

/* The bundle of the scene with the overrides, at its equilibrium, and its modes. */
static gal_bundle *bundle(const char *const *ov, int n, gal_modes *md, gal_scene *sc)
{
    const char *all[16] = {"bundle.model=explicit", "model.elements=48", "bundle.spacers=5"};
    for (int i = 0; i < n; i++) all[3 + i] = ov[i];
    int st = gal_scene_load(sc, scene, all, 3 + n, NULL);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (st) return NULL;
    gal_model *m = gal_model_alloc(sc, &st);
    gal_bundle *b = NULL;
    if (m) st = gal_bundle_solve_model(m, &b, md);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    gal_model_free(m);
    return b;
}

static int first_of(const gal_modes *md, gal_family f)
{
    for (int k = 0; k < md->n; k++)
        if (md->mode[k].family == f) return k;
    return -1;
}

/* Energy drift over 200 steps from v0 = a1 phi_tors + a2 phi_vert (rad/s of modal amplitude). */
static double drift(const char *sub, double alpha, double *loss)
{
    gal_scene sc;
    gal_modes md;
    const char *ov[1] = {sub};
    gal_bundle *b = bundle(ov, 1, &md, &sc);
    if (!b) return INFINITY;
    int kt = first_of(&md, GAL_FAMILY_TORSIONAL), kv = first_of(&md, GAL_FAMILY_VERTICAL);
    CHECK(kt >= 0 && kv >= 0, "%s: torsional and vertical modes found", sub);
    double *v0 = calloc((size_t)b->ndof, sizeof(double));
    for (int j = 0; j < b->ndof; j++)
        v0[j] = AT * md.shape[(size_t)kt * b->ndof + j] + AV * md.shape[(size_t)kv * b->ndof + j];
    gal_bundle_dyn_opts o;
    gal_bundle_dyn_default_opts(&o);
    o.h = 0.005, o.alpha = alpha;
    gal_bundle_dyn *d = gal_bundle_dyn_alloc(b, NULL, v0, &o, NULL);
    CHECK(d != NULL, "%s", gal_error_message());
    double e0 = d ? d->energy0 : 0, kin = 0, emax = 0;
    gal_bundle_eval(b, NULL, NULL, 0); /* the map at the equilibrium */
    double *mv = malloc((size_t)b->ndof * sizeof(double)), *w = malloc((size_t)2 * b->rod[0]->nq * sizeof(double));
    gal_bundle_mass_mult(b, b->state, v0, mv, w);
    for (int j = 0; j < b->ndof; j++) kin += 0.5 * v0[j] * mv[j];
    for (int s = 0; d && s < 200; s++) {
        int st = gal_bundle_dyn_step(d);
        CHECK(st == GAL_OK, "%s", gal_error_message());
        if (st) break;
        emax = fmax(emax, fabs(gal_bundle_dyn_energy(d) - e0));
    }
    *loss = d ? (e0 - gal_bundle_dyn_energy(d)) / kin : 0;
    gal_bundle_dyn_free(d);
    free(v0), free(mv), free(w);
    gal_modes_clear(&md);
    gal_bundle_free(b);
    return emax / kin;
}

static void test_energy(void)
{
    const char *subs[2] = {"bundle.subconductors=2", "bundle.subconductors=4"};
    for (int i = 0; i < 2; i++) {
        double loss, e = drift(subs[i], 0, &loss);
        printf("  %s: energy drift %.3g of the kinetic energy over 1 s\n", subs[i], e);
        CHECK(e < 2e-3, "%s: energy conserved: drift %.3g of the kinetic energy", subs[i], e);
        double e2 = drift(subs[i], 0.5, &loss);
        (void)e2;
        CHECK(loss > 0.2, "%s: damping alpha = 0.5/s takes energy out: %.3g of it in 1 s", subs[i], loss);
    }
}

/* The first vertical frequency of one sub-conductor of the scene (the model's rod), Hz. */
static double single_vertical(const gal_scene *sc)
{
    int st;
    gal_model *m = gal_model_alloc(sc, &st);
    gal_rod_params p = m->rod[0].p;
    p.elements = gal_bundle_elements(p.elements, sc->bundle.spacers);
    gal_equilibrium eq;
    gal_modes md;
    int want[GAL_FAMILY_COUNT] = {1, 0, 0, 0};
    double f = 0;
    st = gal_statics_solve(&p, m->rod[0].spec, m->rod[0].spec_value, NULL, &eq);
    if (!st) st = gal_modes_find_eq(&eq, want, 40, &md);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (!st) f = md.mode[first_of(&md, GAL_FAMILY_VERTICAL)].frequency_hz, gal_modes_clear(&md);
    gal_equilibrium_clear(&eq);
    gal_model_free(m);
    return f;
}

/* Free vertical vibration from the first vertical mode's velocity: the frequency of the centroid's
 * motion at a quarter of the span from its upward zero crossings over 3 periods. */
static void free_vertical(const char *sub)
{
    gal_scene sc;
    gal_modes md;
    const char *ov[1] = {sub};
    gal_bundle *b = bundle(ov, 1, &md, &sc);
    if (!b) return;
    double fs = single_vertical(&sc);
    int kv = first_of(&md, GAL_FAMILY_VERTICAL), nq = b->rod[0]->nq, mid = b->nn / 4; /* a quarter: the antisymmetric mode has its node at mid-span */
    double *v0 = calloc((size_t)b->ndof, sizeof(double));
    for (int j = 0; j < b->ndof; j++) v0[j] = 3.0 * md.shape[(size_t)kv * b->ndof + j];
    gal_bundle_dyn_opts o;
    gal_bundle_dyn_default_opts(&o);
    o.h = 0.02;
    gal_bundle_dyn *d = gal_bundle_dyn_alloc(b, NULL, v0, &o, NULL);
    CHECK(d != NULL, "%s", gal_error_message());
    double prev = 0, tc[8];
    int nc = 0, steps = (int)(3.2 / (fs * o.h));
    for (int s = 0; d && s < steps && nc < 8; s++) {
        if (gal_bundle_dyn_step(d)) break;
        double z = 0;
        for (int r = 0; r < b->n; r++) z += (d->s[(size_t)r * nq + 3 * mid + 2] - b->state[(size_t)r * nq + 3 * mid + 2]) / b->n;
        if (s > 0 && prev < 0 && z >= 0) tc[nc++] = d->t - o.h * z / (z - prev);
        prev = z;
    }
    CHECK(nc >= 3, "%s: %d upward zero crossings", sub, nc);
    if (nc >= 3) {
        double f = (nc - 1) / (tc[nc - 1] - tc[0]);
        printf("  %s: free vertical vibration at %.6f Hz, one sub-conductor %.6f Hz (%+.4f%%), the bundle's first "
               "vertical mode %.6f Hz\n", sub, f, fs, 100 * (f / fs - 1), md.mode[kv].frequency_hz);
        CHECK_REL(f, fs, 1e-3);
    }
    gal_bundle_dyn_free(d);
    free(v0);
    gal_modes_clear(&md);
    gal_bundle_free(b);
}

static void test_free_vertical(void)
{
    free_vertical("bundle.subconductors=2");
    free_vertical("bundle.subconductors=4");
}

/* The wake factor on the leeward sub-conductors alone: a horizontal twin in a wind across the span
 * shields its downwind sub-conductor; a square quad its two downwind ones; a vertical twin none. */
static void test_wake(void)
{
    static const struct { const char *n, *orient; int lee[4]; } c[3] = {
        {"bundle.subconductors=2", "bundle.orientation=0", {1, 0}},
        {"bundle.subconductors=4", "bundle.orientation=45", {1, 0, 0, 1}},
        {"bundle.subconductors=2", "bundle.orientation=90", {0, 0}}};
    for (int i = 0; i < 3; i++) {
        gal_scene sc;
        gal_modes md;
        const char *ov[2] = {c[i].n, c[i].orient};
        gal_bundle *b = bundle(ov, 2, &md, &sc);
        if (!b) continue;
        gal_loads base;
        memset(&base, 0, sizeof base);
        base.dir[1] = 1, base.diam = 0.0281;
        gal_bundle_loads bl;
        CHECK(gal_bundle_loads_init(&bl, b, &base, 1.2, 0.6) == GAL_OK, "loads");
        for (int r = 0; r < b->n; r++) {
            CHECK(bl.leeward[r] == c[i].lee[r], "%s %s: sub-conductor %d leeward %d", c[i].n, c[i].orient, r + 1,
                  bl.leeward[r]);
            CHECK_REL(bl.L[r].rho, c[i].lee[r] ? 0.72 : 1.2, 1e-15);
        }
        gal_bundle_loads_clear(&bl);
        gal_modes_clear(&md);
        gal_bundle_free(b);
    }
}

/* The galloping quad of data/scenes/quad_bundle_gallop.ini, explicit, 12 s (42 elements asked), at the
 * Newton tolerance tol (0: the scene's default): its counters and trace. */
static gal_bundle_sim_result gallop_run(double tol)
{
    const char *ov[3] = {"bundle.model=explicit", "model.elements=42", "simulation.duration=12"};
    gal_scene sc;
    gal_bundle_sim_result res;
    memset(&res, 0, sizeof res);
    int st = gal_scene_load(&sc, "data/scenes/quad_bundle_gallop.ini", ov, 3, NULL);
    gal_model *m = st ? NULL : gal_model_alloc(&sc, &st);
    gal_run_opts o;
    gal_run_opts_from_scene(&sc, &o);
    if (tol > 0) o.newton_tol = tol;
    if (!st) st = gal_bundle_simulate(m, &o, &res);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    gal_model_free(m);
    return res;
}

static void test_newton_tolerance(void)
{
    gal_bundle_sim_result r0 = gallop_run(0), r8 = gallop_run(1e-8), r4 = gallop_run(1e-4);
    long n = r0.c.nsamples * 4 * r0.c.nprobe;
    CHECK(r8.c.nsamples == r0.c.nsamples && r4.c.nsamples == r0.c.nsamples, "samples");
    CHECK(r8.c.newton_iterations == r0.c.newton_iterations, "1e-8 is the default: %ld against %ld iterations",
          r8.c.newton_iterations, r0.c.newton_iterations);
    int same = r8.c.nsamples == r0.c.nsamples && r0.c.trace && r8.c.trace &&
               !memcmp(r0.c.trace, r8.c.trace, (size_t)n * sizeof(double));
    CHECK(same, "1e-8: the default's trace bit for bit");
    printf("  Newton iterations: tolerance 1e-8 %ld, 1e-4 %ld (%ld steps)\n", r0.c.newton_iterations,
           r4.c.newton_iterations, r0.c.steps);
    CHECK(r4.c.newton_iterations < 0.85 * r0.c.newton_iterations, "1e-4: fewer Newton iterations: %ld against %ld",
          r4.c.newton_iterations, r0.c.newton_iterations);
    double dmax = 0, zmax = 0;
    for (long i = 0; r4.c.nsamples == r0.c.nsamples && i < n; i++)
        dmax = fmax(dmax, fabs(r4.c.trace[i] - r0.c.trace[i])), zmax = fmax(zmax, fabs(r0.c.trace[i]));
    printf("  1e-4 against 1e-8: largest trace difference %.3g of the largest entry\n", dmax / zmax);
    CHECK(zmax > 0 && dmax < 1e-2 * zmax, "1e-4: the same motion (%.3g of %.3g)", dmax, zmax);
    gal_bundle_sim_result_clear(&r0), gal_bundle_sim_result_clear(&r8), gal_bundle_sim_result_clear(&r4);
}

/* The explicit onset's convergence in the basis (src/bundle/onset.c): the twin of
 * quad_bundle_gallop.ini (42 elements asked) at 10, the default GAL_ONSET_BASIS and 60 modes. */
static void test_onset_basis(void)
{
    const char *ov[3] = {"bundle.model=explicit", "bundle.subconductors=2", "model.elements=42"};
    gal_scene sc;
    int st = gal_scene_load(&sc, "data/scenes/quad_bundle_gallop.ini", ov, 3, NULL);
    gal_model *m = st ? NULL : gal_model_alloc(&sc, &st);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (st) return;
    int basis[3] = {10, GAL_ONSET_BASIS, 60};
    double u[3] = {NAN, NAN, NAN};
    for (int i = 0; i < 3; i++) {
        gal_onset_opts o;
        gal_onset_default_opts(&o);
        o.speed_min = 2.0, o.speed_max = 3.5, o.speed_step = 0.05, o.basis = basis[i];
        gal_onset O;
        st = gal_bundle_onset(m, &o, &O);
        CHECK(st == GAL_OK, "basis %d: %s", basis[i], gal_error_message());
        if (st) continue;
        u[i] = O.onset_speed;
        gal_onset_clear(&O);
    }
    printf("  twin onset: %.6f m/s (10 modes), %.6f (%d, the default), %.6f (60)\n", u[0], u[1], GAL_ONSET_BASIS, u[2]);
    CHECK(u[1] > 2.0 && u[1] < 3.5, "the twin gallops from %.4g m/s", u[1]);
    CHECK_REL(u[1], u[2], 1e-4);  /* the default converged: 2e-5 at 80 elements, quad and twin (README) */
    CHECK_REL(u[0], u[2], 1e-3);
    gal_model_free(m);
}

int main(void)
{
    RUN(test_onset_basis);
    RUN(test_newton_tolerance);
    RUN(test_energy);
    RUN(test_free_vertical);
    RUN(test_wake);
    return CHECK_SUMMARY();
}
