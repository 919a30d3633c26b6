/* stability.c: Den Hartog's criterion and the galloping onset speed of a vertical mode. */
#include "gallop/analysis/stability.h"

#include <math.h>

double gal_stability_onset(const gal_aero_table *t, double alpha, double mass, double zeta, double omega,
                           double rho, double diam)
{
    double H = gal_aero_den_hartog(t, alpha);
    if (!(H < 0)) return INFINITY;
    return -4.0 * mass * zeta * omega / (rho * diam * H);
}
