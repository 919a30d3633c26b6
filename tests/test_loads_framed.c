/* test_loads_framed.c: the loads given the rod's edge frames (gal_loads_full_framed, from
 * gal_rod_eval_frames at the same configuration) are gal_loads_full's bit for bit, and the rod's
 * evaluation that hands them out is gal_rod_eval's: with and without the twist, for a single
 * conductor and an equivalent bundle, at the equilibrium and at perturbed states in motion; and
 * the reduced model whose training hands the rod's frames to the loads (gal_force.eval_framed,
 * above 128 elements where the fits' targets are whole-rod evaluations) is the model trained
 * without, bit for bit (basis, both samples and their weights). */
#include "check.h"
#include "gallop.h"
#include "reduced/hyper.h"

static double unif(unsigned long long *s)
{
    *s ^= *s >> 12, *s ^= *s << 25, *s ^= *s >> 27;
    return ((*s * 2685821657736338717ULL) >> 11) * (1.0 / 9007199254740992.0);
}

static gal_model *model_of(const char *path, const char *elements, const char *extra)
{
    gal_scene *sc = malloc(sizeof *sc);
    const char *ov[3] = {elements, "simulation.duration=2", extra};
    int st = sc ? gal_scene_load(sc, path, ov, extra ? 3 : 2, NULL) : GAL_ENOMEM;
    gal_model *m = st ? NULL : gal_model_alloc(sc, &st);
    CHECK(m != NULL, "%s: %s", path, gal_error_message());
    free(sc);
    return m;
}

/* the entries of a and b (n) that differ (NaN counts) */
static int differ(const double *a, const double *b, int n)
{
    int bad = 0;
    for (int k = 0; k < n; k++) bad += !(a[k] == b[k]);
    return bad;
}

static void check_scene(const char *path, const char *extra)
{
    gal_model *m = model_of(path, "model.elements=60", extra);
    gal_data *d = m ? gal_data_alloc(m) : NULL;
    if (!d || gal_forward(m, d, GAL_STAGE_WIND)) {
        CHECK(0, "%s: %s", path, gal_error_message());
        gal_data_free(d), gal_model_free(m);
        return;
    }
    const gal_rod *rod = d->eq.rod;
    int nq = rod->nq, nel = rod->p.elements, bad = 0;
    double *q = malloc(nq * sizeof(double)), *v = calloc(nq, sizeof(double)), *g = malloc(nq * sizeof(double));
    double *gf = malloc(nq * sizeof(double)), *f = malloc(nq * sizeof(double)), *ff = malloc(nq * sizeof(double));
    double *fr = malloc(6 * nel * sizeof(double)), U, Uf, big = 0;
    unsigned long long seed = 77;
    for (int s = 0; s < 4; s++) { /* the equilibrium at rest, then 0.1 m / 0.1 rad .. 0.3 m / 0.3 rad, moving */
        memcpy(q, d->eq.q, nq * sizeof(double));
        for (int k = 0; k < nq && s; k++)
            if (rod->dof[k] >= 0) q[k] += 0.1 * s * (2 * unif(&seed) - 1), v[k] = 3 * (2 * unif(&seed) - 1);
        for (int k = 0; k < 6 * nel; k++) fr[k] = NAN;
        CHECK(gal_rod_eval(rod, q, &U, g, NULL) == GAL_OK && gal_rod_eval_frames(rod, q, &Uf, gf, NULL, fr) == GAL_OK, "%s",
              gal_error_message());
        bad += differ(g, gf, nq) + !(U == Uf);
        memset(f, 0, nq * sizeof(double)), memset(ff, 0, nq * sizeof(double));
        CHECK(gal_loads_full((void *)&d->loads, 20.0 + s, q, v, f) == GAL_OK, "%s", gal_error_message());
        CHECK(gal_loads_full_framed((void *)&d->loads, 20.0 + s, q, v, fr, ff) == GAL_OK, "%s", gal_error_message());
        bad += differ(f, ff, nq);
        for (int k = 0; k < nq; k++) big = fmax(big, fabs(f[k]));
    }
    CHECK(big > 0, "%s: the loads are not zero", path);
    CHECK(bad == 0, "%s%s%s: %d entries of the framed rod / loads differ from the separate evaluations", path,
          extra ? " " : "", extra ? extra : "", bad);
    printf("    (%s%s%s: torsion %d, %d sub-conductors: gradient and loads bit for bit)\n", path, extra ? " " : "",
           extra ? extra : "", rod->p.torsion, d->loads.bundle.n);
    free(q), free(v), free(g), free(gf), free(f), free(ff), free(fr);
    gal_data_free(d), gal_model_free(m);
}

static void test_full_framed(void)
{
    check_scene("tests/rom/drake_200_level_dshape.ini", NULL);
    check_scene("tests/rom/drake_200_level_dshape.ini", "effects.torsion=off");
    check_scene("data/scenes/quad_bundle_gallop.ini", NULL);
    check_scene("tests/rom/falcon_400_incline80.ini", NULL);
}

static gal_rom *build(const gal_data *d, int framed)
{
    gal_rom_opts o;
    gal_rom_default_opts(&o);
    o.h = 0.01, o.damping = d->damping, o.k0 = d->eq.k0;
    gal_force F = {.eval = gal_loads_full, .ctx = (void *)&d->loads, .element = gal_loads_element,
                   .eval_framed = framed ? gal_loads_full_framed : NULL};
    gal_rom *m = gal_rom_alloc(d->eq.rod, d->eq.q, &d->md, d->sel, d->basis, &o, &F);
    CHECK(m != NULL, "%s", gal_error_message());
    return m;
}

static void test_training_framed(void)
{
    gal_model *m = model_of("tests/rom/drake_200_level_dshape.ini", "model.elements=150", NULL);
    gal_data *d = m ? gal_data_alloc(m) : NULL;
    if (!d || gal_forward(m, d, GAL_STAGE_REDUCED)) {
        CHECK(0, "%s", gal_error_message());
        gal_data_free(d), gal_model_free(m);
        return;
    }
    gal_rom *a = build(d, 0), *b = build(d, 1);
    if (a && b) {
        int r = a->r, n = a->ndof, same = a->r == b->r && !memcmp(a->V, b->V, (size_t)n * r * sizeof(double));
        CHECK(a->hyper && a->hyper->train_full_evals == 2 * a->hyper->ns, "whole-rod targets: %ld evaluations",
              a->hyper ? a->hyper->train_full_evals : -1L);
        for (int s = 0; s < 2 && same; s++) {
            const gal_rom_hyper_set *x = &a->hyper->set[s], *y = &b->hyper->set[s];
            same = x->n == y->n && !memcmp(x->elem, y->elem, (size_t)x->n * sizeof(int)) &&
                   !memcmp(x->w, y->w, (size_t)x->n * sizeof(double)) && x->fit_error == y->fit_error;
        }
        CHECK(same, "the model trained on the handed-over frames is the model trained without, bit for bit");
        printf("    (150 elements: %d + %d sampled elements, fit errors %.3g / %.3g, the same)\n", a->hyper->set[0].n,
               a->hyper->set[1].n, a->hyper->set[0].fit_error, a->hyper->set[1].fit_error);
    }
    gal_rom_free(a), gal_rom_free(b);
    gal_data_free(d), gal_model_free(m);
}

int main(void)
{
    RUN(test_full_framed);
    RUN(test_training_framed);
    return CHECK_SUMMARY();
}
