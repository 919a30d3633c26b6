/* stringing.h: the way a scene fixes the span's equilibrium, as one of the statics'
 * specifications (tension, sag or unstretched length). [span] tension_rts gives the horizontal
 * tension tension_rts * rated_strength. A [stringing] condition (horizontal tension H1 or sag at
 * the reference temperature T1, bare conductor) is carried to the load case (span.temperature T2,
 * ice) by the sag-tension change of state through the unstretched length L0:
 *   1. the bare conductor (weight w1 = m g) at T1 with H1 (or the sag) is the elastic catenary
 *      (Irvine 1981; gallop/statics/catenary.h): its unstretched length L0(T1);
 *   2. L0(T2) = L0(T1) (1 + alpha (T2 - T1))   (thermal strain of the unstretched length);
 *   3. the load case is solved by unstretched length L0(T2) under its own weight (ice included),
 *      the elastic strain following from the tension.
 * For a level span this is the classic state-change equation, which the parabolic cable
 * approximates as the cubic (e.g. Kiessling et al., Overhead Power Lines, 2003, Sect. 14.3)
 *   H2^2 (H2 - H1 + EA w1^2 L^2 / (24 H1^2) + EA alpha (T2 - T1)) = EA w2^2 L^2 / 24. */
#ifndef GALLOP_STRINGING_H
#define GALLOP_STRINGING_H

#include "gallop/scene/scene.h"
#include "gallop/statics/statics.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The statics' specification of the scene's equilibrium and its value (N, m or m). With gravity
 * off a [stringing] condition by sag has no solution (GAL_EINPUT). `gravity` is the acceleration
 * the model uses (m/s^2; 0 when [effects] gravity = off). */
int gal_stringing_spec(const gal_scene *sc, double gravity, gal_statics_spec *spec, double *value);

/* The unstretched length (m) at the load case's temperature from a stringing condition: the bare
 * conductor's elastic catenary at the reference temperature, then its thermal strain. */
int gal_stringing_length(const gal_scene *sc, double gravity, double *L0);

#ifdef __cplusplus
}
#endif

#endif
