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
#define GAL_WINDFIELD_VERTICAL_SEED 2654435769UL /* added to wind.seed (mod 2^32) for w */

/* Fill p from the scene: mean speed, intensity, spectrum, coherence decay and seed of [wind];
 * GAL_WINDFIELD_POINTS points spaced span.length / (GAL_WINDFIELD_POINTS - 1) apart;
 * dt = GAL_WINDFIELD_TIME_STEP; duration = simulation.duration + GAL_WINDFIELD_EXTRA_TIME; the
 * other fields take gal_wind_params_default's values. The parameters are not validated here
 * (gal_wind_alloc does it). GAL_EINPUT with a message when [wind] turbulence is none. */
int gal_windfield_params(const gal_scene *sc, gal_wind_params *p);

/* The vertical component's parameters ([wind] vertical_turbulence = on): those of the along-wind
 * field with component = GAL_WIND_VERTICAL, intensity = wind.vertical_intensity (sigma_w / U),
 * length_scale = wind.vertical_length_scale (0: the spectrum's L_w, wind.h), coherence decay =
 * wind.vertical_coherence_decay and the seed wind.seed + GAL_WINDFIELD_VERTICAL_SEED (mod 2^32).
 * GAL_EINPUT when the scene has no turbulence or vertical_turbulence is off. */
int gal_windfield_params_vertical(const gal_scene *sc, gal_wind_params *p);

/* Generate the scene's field and point L's turbulence grid (u, nx, nt, x0, dx, dt) at it, and
 * with vertical_turbulence on the w field on the same grid (L->w, in the same allocation after
 * u); the caller owns *u (free). The turbulence terms are then in L's list
 * (gal_loads_list_make). An effect that is off costs nothing: no w field, no w term. */
int gal_windfield_sample(const gal_scene *sc, struct gal_loads *L, double **u);

#ifdef __cplusplus
}
#endif

#endif
