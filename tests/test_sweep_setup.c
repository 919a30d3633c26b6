/* test_sweep_setup.c: a span's set-up reused by another model (forward.h: gal_stage_key,
 * gal_data_share; issue 13, a sweep over the wind): the key holds over the wind and the damping
 * ratio and changes with the span and the modes wanted; a data that borrows the equilibrium and
 * modes of another model's reaches the start exactly where its own pipeline does (the wind-dependent
 * start under the mean wind included), with its damping borrowed or built for its own ratio; a
 * share across keys is refused. */
#include "check.h"
#include "gallop.h"

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

int main(void)
{
    RUN(test_keys);
    RUN(test_share);
    return CHECK_SUMMARY();
}
