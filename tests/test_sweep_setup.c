/* test_sweep_setup.c: a span's set-up reused by another model (forward.h: gal_stage_key,
 * gal_data_share; issue 13, a sweep over the wind): the key holds over the wind and the damping
 * ratio and changes with the span and the modes wanted; a data that borrows the equilibrium and
 * modes of another model's reaches the start exactly where its own pipeline does (the wind-dependent
 * start under the mean wind included), with its damping borrowed or built for its own ratio; a
 * share across keys is refused. The reduced model's own set-up (rom.h gal_rom_setup_alloc) made at
 * one wind and copied at another is the model computed alone there, bit for bit, and is not
 * changed by the runs it serves. */
#include "check.h"
#include "gallop.h"
#include "gallop/reduced/ecsw.h"
#include "reduced/hyper.h"

/* iced_gallop on a coarse mesh, with one more override (NULL: none) */
static gal_model *model_with(const char *extra)
{
    gal_scene *sc = malloc(sizeof *sc);
    const char *ov[4] = {"model.elements=24", "simulation.start=mean_wind", "simulation.duration=5", extra};
    int st = sc ? gal_scene_load(sc, "data/scenes/iced_gallop.ini", ov, extra ? 4 : 3, NULL) : GAL_ENOMEM;
    gal_model *m = st ? NULL : gal_model_alloc(sc, &st);
    CHECK(m != NULL, "model with %s: %s", extra ? extra : "-", gal_error_message());
    free(sc);
    return m;
}

static uint64_t key_of(const gal_model *m, gal_stage s)
{
    uint64_t k = 0;
    CHECK(gal_stage_key(m, s, &k) == GAL_OK, "%s", gal_error_message());
    return k;
}

static void test_keys(void)
{
    gal_model *a = model_with("wind.speed=4"), *b = model_with("wind.speed=12"), *c = model_with("span.length=210"),
              *d = model_with("model.modes_vertical=4"), *e = model_with("conductor.damping_ratio=0.01");
    if (!a || !b || !c || !d || !e) goto done;
    for (gal_stage s = GAL_STAGE_EQUILIBRIUM; s <= GAL_STAGE_MODES; s++) {
        CHECK(key_of(a, s) == key_of(b, s), "%s: the wind speed is not read", gal_stage_names[s]);
        CHECK(key_of(a, s) != key_of(c, s), "%s: the span length is read", gal_stage_names[s]);
        CHECK(key_of(a, s) == key_of(e, s), "%s: the damping ratio is not in the key", gal_stage_names[s]);
    }
    CHECK(key_of(a, GAL_STAGE_EQUILIBRIUM) == key_of(d, GAL_STAGE_EQUILIBRIUM), "the equilibrium ignores the modes");
    CHECK(key_of(a, GAL_STAGE_MODES) != key_of(d, GAL_STAGE_MODES), "the modes wanted are read by the modes");
    uint64_t k;
    CHECK(gal_stage_key(a, GAL_STAGE_WIND, &k) == GAL_EINPUT, "no key for the wind stage");
done:
    gal_model_free(a), gal_model_free(b), gal_model_free(c), gal_model_free(d), gal_model_free(e);
}

/* The damping of two data projected on the first modes of the first, bit for bit. */
static int same_damping(const gal_data *x, const gal_data *y)
{
    double P[4], Q[4];
    if (gal_damping_project(x->damping, x->md.shape, 2, P) || gal_damping_project(y->damping, x->md.shape, 2, Q))
        return 0;
    return !memcmp(P, Q, sizeof P);
}

static void test_share(void)
{
    gal_model *a = model_with("wind.speed=4"), *b = model_with("wind.speed=12"), *z = model_with("conductor.damping_ratio=0.01"),
              *c = model_with("span.length=210");
    gal_data *da = a ? gal_data_alloc(a) : NULL, *db = b ? gal_data_alloc(b) : NULL, *own = b ? gal_data_alloc(b) : NULL;
    gal_data *dz = z ? gal_data_alloc(z) : NULL, *oz = z ? gal_data_alloc(z) : NULL, *dc = c ? gal_data_alloc(c) : NULL;
    if (!da || !db || !own || !dz || !oz || !dc) goto done;
    CHECK(gal_data_share(b, db, da, GAL_STAGE_MODES) == GAL_EINPUT, "the source must be forwarded to the modes");
    CHECK(gal_forward(a, da, GAL_STAGE_START) == GAL_OK, "%s", gal_error_message());
    /* over the wind: borrowed, and the start under the mean wind the data's own */
    CHECK(gal_data_share(b, db, da, GAL_STAGE_MODES) == GAL_OK, "%s", gal_error_message());
    CHECK(db->eq.rod == da->eq.rod && db->md.shape == da->md.shape && db->damping == da->damping &&
          db->borrowed == GAL_STAGE_MODES && db->damping_borrowed, "the equilibrium, modes and damping borrowed");
    CHECK(gal_forward(b, db, GAL_STAGE_REDUCED) == GAL_OK, "%s", gal_error_message());
    CHECK(gal_forward(b, own, GAL_STAGE_REDUCED) == GAL_OK, "%s", gal_error_message());
    int nq = own->eq.rod->nq;
    CHECK(!memcmp(db->q_start, own->q_start, (size_t)nq * sizeof(double)), "the start under 12 m/s, bit for bit");
    CHECK(memcmp(db->q_start, da->q_start, (size_t)nq * sizeof(double)), "... not the 4 m/s one");
    CHECK(db->mean_wind_iterations == own->mean_wind_iterations && db->basis == own->basis &&
          !memcmp(db->sel, own->sel, sizeof db->sel), "the same reduced stage");
    CHECK(db->md.n == own->md.n && db->md.n > 0 && db->md.mode[0].omega == own->md.mode[0].omega, "the same modes");
    CHECK(same_damping(db, own), "the same damping");
    /* another damping ratio: built for it */
    CHECK(gal_data_share(z, dz, da, GAL_STAGE_MODES) == GAL_OK, "%s", gal_error_message());
    CHECK(!dz->damping_borrowed && dz->damping != da->damping, "the damping built for 0.01");
    CHECK(gal_forward(z, oz, GAL_STAGE_MODES) == GAL_OK, "%s", gal_error_message());
    CHECK(same_damping(dz, oz) && !same_damping(dz, da), "... as its own pipeline builds it, not 0.003's");
    /* another span: refused */
    CHECK(gal_data_share(c, dc, da, GAL_STAGE_MODES) == GAL_EINPUT && dc->stage == GAL_STAGE_NONE &&
          dc->borrowed == GAL_STAGE_NONE, "another span refused: %s", gal_error_message());
    /* the equilibrium alone: the modes computed on it */
    gal_data *de = gal_data_alloc(b);
    CHECK(de && gal_data_share(b, de, da, GAL_STAGE_EQUILIBRIUM) == GAL_OK && de->stage == GAL_STAGE_EQUILIBRIUM,
          "the equilibrium alone: %s", gal_error_message());
    if (de) {
        CHECK(gal_forward(b, de, GAL_STAGE_MODES) == GAL_OK && de->md.shape != da->md.shape && de->md.n == da->md.n,
              "modes of its own on the borrowed equilibrium");
        gal_data_free(de);
    }
done:
    /* the borrowers freed first, then the source: no double free (the sanitizers) */
    gal_data_free(db), gal_data_free(own), gal_data_free(dz), gal_data_free(oz), gal_data_free(dc);
    gal_data_free(da);
    gal_model_free(a), gal_model_free(b), gal_model_free(z), gal_model_free(c);
}

/* The reduced model's options and loads of data d, as the reduced integrator takes them. */
static void rom_opts_of(const gal_data *d, gal_rom_opts *o, gal_force *F)
{
    gal_rom_default_opts(o);
    o->damping = d->damping;
    memset(F, 0, sizeof *F);
    if (d->loads.table) F->eval = gal_loads_full, F->element = gal_loads_element, F->ctx = (void *)&d->loads;
}

/* Whether two models are the same, bit for bit: basis, reduced matrices, samples and state. */
static int same_rom(const gal_rom *a, const gal_rom *b)
{
    int n = a->ndof, r = a->r;
    if (r != b->r || a->nmodes != b->nmodes || memcmp(a->V, b->V, (size_t)n * r * sizeof(double)) ||
        memcmp(a->Cr, b->Cr, (size_t)r * r * sizeof(double)) || memcmp(a->K0r, b->K0r, (size_t)r * r * sizeof(double)) ||
        memcmp(a->x, b->x, (size_t)r * sizeof(double)) || memcmp(a->v, b->v, (size_t)r * sizeof(double)) ||
        memcmp(a->fi, b->fi, (size_t)r * sizeof(double)) || memcmp(a->fe, b->fe, (size_t)r * sizeof(double)) ||
        a->fscale != b->fscale || a->ufloor != b->ufloor || !a->hyper != !b->hyper)
        return 0;
    if (!a->hyper) return 1;
    for (int s = 0; s < 2; s++) {
        const gal_rom_hyper_set *x = &a->hyper->set[s], *y = &b->hyper->set[s];
        if (x->n != y->n || memcmp(x->elem, y->elem, (size_t)x->n * sizeof(int)) ||
            memcmp(x->w, y->w, (size_t)x->n * sizeof(double)) || x->fit_error != y->fit_error)
            return 0;
    }
    gal_rom_hyper_info p, q;
    gal_rom_hyper_get_info(a, &p), gal_rom_hyper_get_info(b, &q);
    return !memcmp(a->hyper->fc, b->hyper->fc, (size_t)r * sizeof(double)) && a->hyper->Uc == b->hyper->Uc &&
           p.train_element_evals == q.train_element_evals && p.train_full_evals == q.train_full_evals &&
           p.load_elements == q.load_elements && p.snapshots == q.snapshots;
}

static void test_rom_setup(void)
{
    gal_model *a = model_with("wind.speed=4"), *b = model_with("wind.speed=12");
    gal_data *da = a ? gal_data_alloc(a) : NULL, *db = b ? gal_data_alloc(b) : NULL;
    gal_rom *S = NULL, *alone = NULL, *copy = NULL, *other = NULL, *at4 = NULL;
    double *V0 = NULL;
    if (!da || !db) goto done;
    CHECK(gal_forward(a, da, GAL_STAGE_REDUCED) == GAL_OK, "%s", gal_error_message());
    CHECK(gal_data_share(b, db, da, GAL_STAGE_MODES) == GAL_OK && gal_forward(b, db, GAL_STAGE_REDUCED) == GAL_OK,
          "%s", gal_error_message());
    CHECK(db->rom_setup == da->rom_setup, "the reduced set-up's holder borrowed with the modes");
    gal_rom_opts oa, ob;
    gal_force Fa, Fb;
    rom_opts_of(da, &oa, &Fa), rom_opts_of(db, &ob, &Fb);
    const gal_rod *rod = da->eq.rod;
    S = gal_rom_setup_alloc(rod, da->eq.q, &da->md, da->sel, da->basis, &oa);
    CHECK(S != NULL && S->hyper && S->hyper->set[1].n == 0, "a set-up with the rod's sample, no loads': %s",
          gal_error_message());
    if (!S) goto done;
    int n = rod->ndof, r = S->r;
    gal_rom_hyper_info i0, i1;
    gal_rom_hyper_get_info(S, &i0);
    V0 = malloc((size_t)n * r * sizeof(double));
    if (!V0) goto done;
    memcpy(V0, S->V, (size_t)n * r * sizeof(double));
    /* at 12 m/s, on the set-up made at 4 m/s: the model computed there alone */
    alone = gal_rom_alloc(rod, db->eq.q, &db->md, db->sel, db->basis, &ob, &Fb);
    ob.setup = S;
    copy = gal_rom_alloc(rod, db->eq.q, &db->md, db->sel, db->basis, &ob, &Fb);
    CHECK(alone && copy && !alone->setup_reused && copy->setup_reused && copy->chol0 == S->chol0,
          "the copy reads the set-up's factorization: %s", gal_error_message());
    if (!alone || !copy) goto done;
    CHECK(same_rom(alone, copy), "on the set-up: the model computed alone, bit for bit");
    CHECK(alone->hyper->loads && copy->hyper->set[1].n > 0, "the loads' sample the wind's own");
    oa.setup = S;
    at4 = gal_rom_alloc(rod, da->eq.q, &da->md, da->sel, da->basis, &oa, &Fa);
    CHECK(at4 && at4->setup_reused && at4->hyper->set[0].n == copy->hyper->set[0].n &&
          !memcmp(at4->hyper->set[0].w, copy->hyper->set[0].w, (size_t)copy->hyper->set[0].n * sizeof(double)),
          "the rod's sample does not depend on the wind");
    /* a run with re-samplings at every check (a tight tolerance): the same states, the set-up intact */
    alone->o.hyper_check_tol = copy->o.hyper_check_tol = 1e-9;
    alone->o.hyper_check_interval = copy->o.hyper_check_interval = 0.5;
    int sa = gal_rom_start(alone, 0, db->q_start, NULL), sc = gal_rom_start(copy, 0, db->q_start, NULL);
    if (!sa) sa = gal_rom_advance(alone, 2.0);
    if (!sc) sc = gal_rom_advance(copy, 2.0);
    CHECK(!sa && !sc, "2 s: %s", gal_error_message());
    CHECK(alone->hyper->refits > 0 && alone->hyper->refits == copy->hyper->refits, "re-sampled %d times",
          alone->hyper->refits);
    CHECK(same_rom(alone, copy), "after 2 s and re-samplings: the same state, bit for bit");
    gal_rom_hyper_get_info(S, &i1);
    CHECK(!memcmp(V0, S->V, (size_t)n * r * sizeof(double)) && S->r == r && i1.elements == i0.elements &&
          i1.snapshots == i0.snapshots && i1.refits == 0 && S->hyper->set[1].n == 0, "the set-up unchanged by the runs");
    /* other modes: the set-up is not used */
    other = db->basis > 1 ? gal_rom_alloc(rod, db->eq.q, &db->md, db->sel, db->basis - 1, &ob, &Fb) : NULL;
    CHECK(db->basis > 1 && other && !other->setup_reused, "a set-up of other modes is not used");
done:
    gal_rom_free(other), gal_rom_free(at4), gal_rom_free(copy), gal_rom_free(alone), gal_rom_free(S);
    free(V0);
    gal_data_free(db), gal_data_free(da);
    gal_model_free(a), gal_model_free(b);
}

int main(void)
{
    RUN(test_keys);
    RUN(test_share);
    RUN(test_rom_setup);
    return CHECK_SUMMARY();
}
