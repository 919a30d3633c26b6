/* model.h: from a resolved scene to the discretized span: rod parameters with only the effects
 * the scene calls for (bending off: EI = 0; torsion off: no twist unknowns; gravity off: g = 0),
 * and the way its equilibrium is specified. */
#ifndef GALLOP_MODEL_H
#define GALLOP_MODEL_H

#include "gallop/rod/rod.h"
#include "gallop/scene/scene.h"
#include "gallop/statics/statics.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GAL_GRAVITY 9.80665 /* m/s^2, standard gravity */

/* GAL_EINPUT when the scene asks for something the model cannot represent (with the key). */
int gal_model_rod_params(const gal_scene *sc, gal_rod_params *p, gal_statics_spec *spec, double *value);

#ifdef __cplusplus
}
#endif

#endif
