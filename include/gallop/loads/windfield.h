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

#define GAL_WINDFIELD_POINTS 65       /* most points `gallop wind` reports statistics at */
/* The field's points along the span are a property of the wind and the span, never of the mesh:
 * x_j = j dx, j = 0 .. ceil(span.length / dx), with
 *     dx = U / (C f_c)  clamped to [GAL_WINDFIELD_SPACING_MIN, GAL_WINDFIELD_SPACING_MAX],
 * the coherence length at f_c = GAL_WINDFIELD_FREQUENCY (coh(f_c, dx) = exp(-1)): galloping
 * is in the first vertical modes of a span, 0.1 to 0.5 Hz (CIGRE TB 322), so the field is resolved
 * below one coherence length at every frequency that drives it. A mesh samples the field by
 * linear interpolation in x between these points (turbulence.c): the field is the same at the
 * same point whatever the mesh (and, the random phases being drawn point by point from x = 0, the
 * same on the common part of two spans). Linear because the grid is below the coherence length:
 * the spatially integrated (modal) load, which is what excites the span, is then within
 * (dx / 2 Lc) coth(dx / 2 Lc) - 1 <= 8% of the continuous field's variance at f_c and < 1% at
 * the 0.02-0.1 Hz where a Kaimal spectrum holds most of its energy (Lc = U / (C f)). Between
 * the points the interpolated field's point variance at frequency f is lower, by
 * 1 - 2 a (1 - a) (1 - r), r = exp(-C f dx / U), a the fraction of the way (at f_c mid-way: 16%):
 * what the load over an element sees, not a point anemometer. */
#define GAL_WINDFIELD_FREQUENCY 0.5   /* Hz, f_c above */
#define GAL_WINDFIELD_SPACING_MIN 1.0 /* m */
#define GAL_WINDFIELD_SPACING_MAX 4.0 /* m */
#define GAL_WINDFIELD_TIME_STEP 0.05  /* s: 20 Hz */
#define GAL_WINDFIELD_EXTRA_TIME 1.0  /* s: the record outlasts the run by at least this much */
#define GAL_WINDFIELD_VERTICAL_SEED 2654435769UL /* added to wind.seed (mod 2^32) for w */

/* The spacing dx (m) of the field's points for this scene (above). */
double gal_windfield_spacing(const gal_scene *sc);

/* Fill p from the scene: mean speed, intensity, spectrum, coherence decay and seed of [wind];
 * points gal_windfield_spacing(sc) apart from x = 0 to span.length or just past it;
 * dt = GAL_WINDFIELD_TIME_STEP; duration = simulation.duration + GAL_WINDFIELD_EXTRA_TIME
 * rounded up to a sample count with no prime factor above 5 (a fast FFT: at most 8% longer); the
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
