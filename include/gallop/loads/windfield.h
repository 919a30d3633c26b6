/* windfield.h: the turbulent wind field of a scene (DESIGN.md "Wind"; src/loads/turbulence.c):
 * the parameters of the spectral-representation generator (wind.h) that a scene's [wind], [span]
 * and [simulation] sections call for, in one place, so that `gallop simulate`, `gallop compare`
 * and `gallop wind` make the same field from the same scene; and that field on the loads' grid. */
#ifndef GALLOP_WINDFIELD_H
#define GALLOP_WINDFIELD_H

#include "gallop/scene/scene.h"
#include "gallop/loads/wind.h"

#ifdef __cplusplus
extern "C" {
#endif

struct gal_loads;

#define GAL_WINDFIELD_POINTS 65       /* points along the span, supports included */
#define GAL_WINDFIELD_TIME_STEP 0.05  /* s: 20 Hz */
#define GAL_WINDFIELD_EXTRA_TIME 1.0  /* s: the record outlasts the run by this much */

/* Fill p from the scene: mean speed, intensity, spectrum, coherence decay and seed of [wind];
 * GAL_WINDFIELD_POINTS points spaced span.length / (GAL_WINDFIELD_POINTS - 1) apart;
 * dt = GAL_WINDFIELD_TIME_STEP; duration = simulation.duration + GAL_WINDFIELD_EXTRA_TIME; the
 * other fields take gal_wind_params_default's values. The parameters are not validated here
 * (gal_wind_alloc does it). GAL_EINPUT with a message when [wind] turbulence is none. */
int gal_windfield_params(const gal_scene *sc, gal_wind_params *p);

/* Generate the scene's field and point L's turbulence grid (u, nx, nt, x0, dx, dt) at it; the
 * caller owns *u (free). The turbulence term is then in L's list (gal_loads_list_make). */
int gal_windfield_sample(const gal_scene *sc, struct gal_loads *L, double **u);

#ifdef __cplusplus
}
#endif

#endif
