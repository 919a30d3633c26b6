/* test_rom_k0.c: the reduced model's set-up on the statics' K0 and its factorization (statics.h
 * gal_equilibrium.k0, rom.h gal_rom_opts.k0): the statics keep a copy of their stability check's
 * factor that the modes' own factorization of K - sigma M does not touch, and the model built on
 * it is the model computed afresh bit for bit (basis, V^T K0 V, both samples and their weights,
 * the state after a short run). A tangent of another configuration is not taken; one at the same
 * configuration is taken (a doctored one moves the basis: the hand-over is used, not ignored).
 * With the twist free the check's factor is shifted: none is kept. */
#include "check.h"
#include "gallop.h"
#include "base/chol.h"
#include "reduced/hyper.h"

/* drake_200_level_dshape (a clamped twist, the loads of its D-shaped ice) on a coarse mesh */
static gal_model *model_with(const char *extra)
{
    gal_scene *sc = malloc(sizeof *sc);
    const char *ov[3] = {"model.elements=40", "simulation.duration=2", extra};
    int st = sc ? gal_scene_load(sc, "tests/rom/drake_200_level_dshape.ini", ov, extra ? 3 : 2, NULL) : GAL_ENOMEM;
    gal_model *m = st ? NULL : gal_model_alloc(sc, &st);
    CHECK(m != NULL, "%s", gal_error_message());
    free(sc);
    return m;
}

static gal_rom *build(const gal_data *d, const gal_tangent *k0)
{
    gal_rom_opts o;
    gal_rom_default_opts(&o);
    o.h = 0.01, o.damping = d->damping, o.k0 = k0;
    gal_force F = {.eval = gal_loads_full, .ctx = (void *)&d->loads, .element = gal_loads_element};
    gal_rom *m = gal_rom_alloc(d->eq.rod, d->eq.q, &d->md, d->sel, d->basis, &o, &F);
    CHECK(m != NULL, "%s", gal_error_message());
    return m;
}

/* 1 when a and b are the same model to the last bit (and, with run, after 0.5 s in the wind from rest) */
static int same_model(gal_rom *a, gal_rom *b, int run)
{
    int r = a->r, n = a->ndof, same = a->r == b->r && !memcmp(a->V, b->V, (size_t)n * r * sizeof(double)) &&
                                      !memcmp(a->K0r, b->K0r, (size_t)r * r * sizeof(double));
    for (int s = 0; s < 2 && same; s++) {
        const gal_rom_hyper_set *x = &a->hyper->set[s], *y = &b->hyper->set[s];
        same = x->n == y->n && !memcmp(x->elem, y->elem, (size_t)x->n * sizeof(int)) &&
               !memcmp(x->w, y->w, (size_t)x->n * sizeof(double));
    }
    if (!same || !run) return same;
    CHECK(gal_rom_start(a, 0, a->q_eq, NULL) == GAL_OK && gal_rom_start(b, 0, b->q_eq, NULL) == GAL_OK, "%s", gal_error_message());
    CHECK(gal_rom_advance(a, 0.5) == GAL_OK && gal_rom_advance(b, 0.5) == GAL_OK, "%s", gal_error_message());
    double big = 0;
    for (int k = 0; k < r; k++) big = fmax(big, fabs(a->x[k]));
    CHECK(big > 1e-3, "the span moves in the wind (largest coordinate %g)", big);
    return !memcmp(a->x, b->x, (size_t)r * sizeof(double)) && !memcmp(a->v, b->v, (size_t)r * sizeof(double));
}

static void test_same_model(void)
{
    gal_model *m = model_with(NULL);
    gal_data *d = m ? gal_data_alloc(m) : NULL;
    if (!d || gal_forward(m, d, GAL_STAGE_REDUCED)) {
        CHECK(0, "%s", gal_error_message());
        goto done;
    }
    const gal_tangent *k0 = d->eq.k0;
    CHECK(k0 != NULL && k0->chol && k0->chol->L, "the statics keep K0's factor (clamped twist)");
    if (!k0) goto done;
    /* the modes factorized K - sigma M in the statics' own analysis since: the copy is K0's */
    CHECK(d->md.factorizations > 0, "the modes factorized (%ld)", d->md.factorizations);
    gal_rom *a = build(d, NULL), *b = build(d, k0);
    if (a && b) CHECK(same_model(a, b, 1), "the model on the statics' K0 is the model computed afresh, bit for bit");
    gal_rom_free(a), gal_rom_free(b);

    /* a tangent of the same configuration with other values is taken (the basis moves) ... */
    gal_tangent *t = gal_tangent_copy(k0->K, k0->chol, k0->q, k0->nq, k0->L0);
    CHECK(t != NULL, "%s", gal_error_message());
    if (!t) goto done;
    for (int k = 0; k < t->K->nnz; k++) t->K->val[k] *= 1.5;
    CHECK(gal_chol_factor(t->chol, t->K, 0, NULL) == GAL_OK, "%s", gal_error_message());
    a = build(d, NULL), b = build(d, t);
    if (a && b) CHECK(!same_model(a, b, 0), "a tangent at q_eq is taken");
    gal_rom_free(b);
    /* ... one of another configuration or unstretched length is not */
    t->q[3 * (d->eq.rod->nn / 2) + 2] += 1e-9;
    b = build(d, t);
    if (a && b) CHECK(same_model(a, b, 0), "a tangent at another configuration is not taken");
    gal_rom_free(b);
    t->q[3 * (d->eq.rod->nn / 2) + 2] = d->eq.q[3 * (d->eq.rod->nn / 2) + 2];
    t->L0 *= 1 + 1e-12;
    b = build(d, t);
    if (a && b) CHECK(same_model(a, b, 0), "a tangent of another unstretched length is not taken");
    gal_rom_free(a), gal_rom_free(b);
    gal_tangent_free(t);
done:
    gal_data_free(d);
    gal_model_free(m);
}

/* The twist free at the ends: the check factorized K plus a tiny shift, not K0: nothing kept. */
static void test_free_twist(void)
{
    gal_model *m = model_with("span.end_twist=free");
    gal_data *d = m ? gal_data_alloc(m) : NULL;
    if (!d || gal_forward(m, d, GAL_STAGE_EQUILIBRIUM)) {
        CHECK(0, "%s", gal_error_message());
    } else {
        CHECK(d->eq.tangent != NULL, "the modes' tangent is handed over");
        CHECK(d->eq.k0 == NULL, "no factor of K0 kept from a shifted factorization");
    }
    gal_data_free(d);
    gal_model_free(m);
}

int main(void)
{
    RUN(test_same_model);
    RUN(test_free_twist);
    return CHECK_SUMMARY();
}
