/* sim_fixture.h: a scene read with its overrides and set up for gal_run (gal_sim_setup_init), the
 * start of the tests that run a shipped or tests/rom/ scene; include after check.h. 0 when both
 * succeed; otherwise a failed CHECK naming the scene and the library's message, and -1. */
#ifndef GALLOP_TESTS_SIM_FIXTURE_H
#define GALLOP_TESTS_SIM_FIXTURE_H

#include "gallop/base/error.h"
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

#endif
