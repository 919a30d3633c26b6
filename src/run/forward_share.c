/* forward_share.c: the set-up of one model's data reused by another's (forward.h): the key of
 * what the equilibrium and modes stages read, and the stages borrowed from a data of the same key
 * (a sweep over the wind finds its span's equilibrium and modes once, and the reduced model's own
 * set-up on them: gal_data.rom_setup). */
#include "gallop/run/forward.h"
#include "gallop/base/core.h"
#include "gallop/reduced/rom.h"

#include <stdlib.h>
#include <string.h>

/* The rod's parameters, hashed field by field (no padding bytes); a field added to gal_rod_params
 * must be added here too, or two rods that differ in it would share their equilibrium. */
_Static_assert(sizeof(gal_rod_params) == 176, "gal_rod_params changed: add its new field to the stage key "
               "(src/run/forward_share.c)");

typedef struct {
    uint64_t h;
} hasher;

static void put(hasher *k, const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n; i++) k->h = (k->h ^ b[i]) * 0x100000001b3ULL; /* FNV-1a */
}
static void put_d(hasher *k, double x) { put(k, &x, sizeof x); }
static void put_i(hasher *k, int x) { put(k, &x, sizeof x); }

static void put_rod(hasher *k, const gal_rod_params *p)
{
    const double d[] = {p->length, p->height_difference, p->unstretched_length, p->EA, p->EI, p->GJ, p->mass,
                        p->polar_inertia, p->gravity, p->ecc_mass, p->ecc, p->ecc_angle, p->bundle_radius2,
                        p->bundle_field_k, p->bundle_field_inertia, p->bundle_field_dir[0][0],
                        p->bundle_field_dir[0][1], p->bundle_field_dir[1][0], p->bundle_field_dir[1][1]};
    for (size_t i = 0; i < sizeof d / sizeof d[0]; i++) put_d(k, d[i]);
    put_i(k, p->elements), put_i(k, p->torsion), put_i(k, p->twist_clamped), put_i(k, p->bundle_fields);
}

int gal_stage_key(const gal_model *m, gal_stage s, uint64_t *key)
{
    if (s != GAL_STAGE_EQUILIBRIUM && s != GAL_STAGE_MODES)
        return gal_error(GAL_EINPUT, "stage key: stage %d; allowed: equilibrium (%d), modes (%d)", (int)s,
                         GAL_STAGE_EQUILIBRIUM, GAL_STAGE_MODES);
    hasher k = {0xcbf29ce484222325ULL};
    put_i(&k, m->nrods), put_i(&k, m->ncouplings);
    for (int i = 0; i < m->nrods; i++) {
        put_rod(&k, &m->rod[i].p);
        put_i(&k, (int)m->rod[i].spec), put_d(&k, m->rod[i].spec_value);
    }
    put_d(&k, m->statics.force_tol), put_i(&k, m->statics.max_newton), put_i(&k, m->statics.max_length_iter);
    if (s >= GAL_STAGE_MODES) {
        for (int f = 0; f < GAL_FAMILY_COUNT; f++) put_i(&k, m->want[f]);
        put_i(&k, m->max_modes);
    }
    *key = k.h;
    return GAL_OK;
}

int gal_data_share(const gal_model *m, gal_data *d, const gal_data *from, gal_stage upto)
{
    uint64_t a = 0, b = 0;
    int st = gal_stage_key(m, upto, &a);
    if (!st) st = gal_stage_key(from->model, upto, &b);
    if (st) return st;
    if (d->model != m || d->stage != GAL_STAGE_NONE || from->stage < GAL_STAGE_MODES || a != b)
        return gal_error(GAL_EINPUT, "%s: the set-up of %s cannot be shared (another key, or the data already "
                         "forwarded)", m->sc.path, from->model->sc.path);
    d->eq = from->eq;
    d->eq.tangent = NULL; /* the modes stage's, taken over there */
    d->borrowed = GAL_STAGE_EQUILIBRIUM;
    d->stage = GAL_STAGE_EQUILIBRIUM;
    if (upto < GAL_STAGE_MODES) return GAL_OK;
    d->md = from->md;
    gal_rom_free(d->rom_setup->rom); /* none yet: d is not forwarded */
    free(d->rom_setup);
    d->rom_setup = from->rom_setup; /* the reduced set-up on these modes */
    d->borrowed = GAL_STAGE_MODES;
    if (m->damping_ratio == from->model->damping_ratio) {
        d->damping = from->damping;
        d->damping_borrowed = 1;
    } else {
        double t0 = gal_wall_time();
        d->damping = gal_damping_modal_alloc(d->eq.rod, d->eq.q, m->damping_ratio, GAL_DAMPING_BAND_HZ);
        d->stage_time_s[GAL_STAGE_MODES] = gal_wall_time() - t0;
        if (!d->damping) return gal_error(GAL_EFAIL, "%s: %s", m->sc.path, gal_error_message());
    }
    d->stage = GAL_STAGE_MODES;
    return GAL_OK;
}
