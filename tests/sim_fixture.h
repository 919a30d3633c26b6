/* sim_fixture.h: a scene read with its overrides and set up for gal_run (gal_sim_setup_init), the
 * start of the tests that run a shipped or tests/rom/ scene, and its reduced model started
 * (rom_fixture); include after check.h. 0 when both
 * succeed; otherwise a failed CHECK naming the scene and the library's message, and -1. */
#ifndef GALLOP_TESTS_SIM_FIXTURE_H
#define GALLOP_TESTS_SIM_FIXTURE_H

#include "gallop/base/error.h"
#include "gallop/loads/loads.h"
#include "gallop/reduced/rom.h"
#include "gallop/reduced/rom_adapt.h"
#include "gallop/run/forward.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"

static int sim_fixture(gal_scene *sc, gal_sim_setup *s, const char *path, const char **ov, int nov)
{
    if (gal_scene_load(sc, path, ov, nov, "data/conductors.csv") || gal_sim_setup_init(s, sc, 1)) {
        CHECK(0, "%s: %s", path, gal_error_message());
        return -1;
    }
    return 0;
}

/* sim_fixture's scene carried through the pipeline to the reduced model's stage (gal_forward to
 * GAL_STAGE_REDUCED: equilibrium, modes, selection, damping); its data, or NULL after a failed
 * CHECK (the set-up cleared). */
static inline gal_data *forward_fixture(gal_scene *sc, gal_sim_setup *s, const char *path, const char **ov, int nov)
{
    if (sim_fixture(sc, s, path, ov, nov)) return NULL;
    if (gal_forward(s->model, s->data, GAL_STAGE_REDUCED)) {
        CHECK(0, "%s: %s", path, gal_error_message());
        gal_sim_setup_clear(s);
        return NULL;
    }
    return s->data;
}

/* The reduced model of a set-up scene (gal_forward to GAL_STAGE_REDUCED) with the options *ro, its
 * damping the scene's, under the scene's loads, started from the scene's start state; NULL after a
 * failed CHECK naming the library's message. */
static inline gal_rom *rom_fixture(gal_sim_setup *s, gal_rom_opts *ro)
{
    gal_data *d = s->data;
    if (gal_forward(s->model, d, GAL_STAGE_REDUCED)) {
        CHECK(0, "%s", gal_error_message());
        return NULL;
    }
    ro->damping = d->damping;
    gal_force F = {gal_loads_full, (void *)&d->loads, gal_loads_element, gal_loads_full_framed};
    gal_rom *m = gal_rom_alloc(d->eq.rod, d->eq.q, &d->md, d->sel, d->basis, ro, &F);
    if (m && gal_rom_start(m, 0, d->q_start, d->v_start)) gal_rom_free(m), m = NULL;
    CHECK(m != NULL, "%s", gal_error_message());
    return m;
}

/* The adaptation (rom_adapt.h) of a set-up scene's data d at a step of 0.01 s, its damping the
 * scene's, under the scene's loads, relaxation off (every trip grows at once): *ro and *F, which it
 * keeps, filled here; gal_rom_adapt_init's status (the caller checks it). */
static inline int adapt_fixture(gal_data *d, gal_rom_opts *ro, gal_force *F, gal_rom_adapt *a, gal_rom **m)
{
    gal_rom_default_opts(ro);
    ro->h = 0.01, ro->damping = d->damping;
    *F = (gal_force){gal_loads_full, (void *)&d->loads, gal_loads_element, gal_loads_full_framed};
    int st = gal_rom_adapt_init(a, m, d->eq.rod, d->eq.q, &d->md, d->sel, d->basis, ro, F);
    if (!st) a->relax = 0;
    return st;
}

#endif
