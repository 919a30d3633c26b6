/* stability.h: Den Hartog's galloping criterion over the angle of attack (issue 4):
 * H(alpha) = dC_L/dalpha + C_D (per radian); where H < 0 a vertical mode of circular frequency w,
 * damping ratio zeta, mass m per length gallops above the onset speed
 *   U_c = -4 m zeta w / (rho d H(alpha))
 * (the wind speed at which the aerodynamic damping 1/2 rho U d H cancels the structural one). */
#ifndef GALLOP_STABILITY_H
#define GALLOP_STABILITY_H

#include "gallop/loads/aero.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Onset speed (m/s) for one mode at one angle; +INFINITY where H >= 0 (stable at any speed). */
double gal_stability_onset(const gal_aero_table *t, double alpha_rad, double mass, double zeta,
                           double omega, double rho, double diam);

#ifdef __cplusplus
}
#endif

#endif
