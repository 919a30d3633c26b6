/* onset_scene.h: the coupled galloping onset of a scene's span (analysis/onset.h) through the
 * pipeline: its model, the equilibrium, modes, damping and loads the runs apply (run/forward.h), the
 * scene's [stability] speeds. `gallop stability` and `gallop sweep` share it. */
#ifndef GALLOP_ONSET_SCENE_H
#define GALLOP_ONSET_SCENE_H

#include "gallop/analysis/onset.h"
#include "gallop/scene/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The onset analysis of the resolved scene into *O (gal_onset_clear it); a status with a message on
 * failure. */
int gal_scene_onset(const gal_scene *sc, gal_onset *O);

#ifdef __cplusplus
}
#endif

#endif
