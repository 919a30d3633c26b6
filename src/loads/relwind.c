/* relwind.c: the terms of the relative wind at a section other than turbulence (DESIGN.md "Wind"):
 * the mean wind, ramped in by (1 - cos)/2, and the aerodynamic damping, the conductor's own
 * velocity taken from the wind (the relative wind is wind minus conductor velocity). */
#include "gallop/loads/loads.h"
#include "gallop/base/core.h"

#include <math.h>

double gal_loads_ramp(const gal_loads *L, double t)
{
    return (L->ramp_time > 0 && t < L->ramp_time) ? 0.5 * (1 - cos(GAL_PI * t / L->ramp_time)) : 1.0;
}

/* the mean wind: speed times the ramp */
static double mean_wind(const gal_loads *L, double t, double x, double ramp)
{
    (void)t, (void)x;
    return L->speed * ramp;
}

/* aerodynamic damping: w = wind - rdot */
static void aero_damping(const gal_loads *L, const double rdot[3], double w[3])
{
    (void)L;
    for (int k = 0; k < 3; k++) w[k] -= rdot[k];
}

const gal_loads_term gal_loads_term_mean_wind = {"mean_wind", mean_wind, NULL, NULL};
const gal_loads_term gal_loads_term_aero_damping = {"aero_damping", NULL, aero_damping, NULL};
