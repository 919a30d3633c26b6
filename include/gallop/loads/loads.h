/* loads.h: the aerodynamic loads of a scene (paper Eq. 10; DESIGN.md "Aerodynamics", "Wind"):
 * quasi-steady drag, lift and moment per unit length from a coefficient table, in the relative
 * wind (wind minus conductor velocity when aero_damping is on), with the mean wind ramped in and
 * an along-wind turbulence field interpolated in space and time. Only the effects the scene asks
 * for are evaluated. The same point load serves the full model (at element centres) and the
 * reduced model (at quadrature points). */
#ifndef GALLOP_LOADS_H
#define GALLOP_LOADS_H

#include "gallop/loads/aero.h"
#include "gallop/full/dynamics.h"
#include "gallop/reduced/rdyn.h"
#include "gallop/rod/rod.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct gal_loads {
    const gal_aero_table *table;
    unsigned flags;          /* GAL_AERO_DRAG | GAL_AERO_LIFT | GAL_AERO_MOMENT */
    int aero_damping;        /* the conductor's velocity is in the relative wind */
    double rho;              /* kg/m^3 */
    double diam;             /* m */
    double attack_angle;     /* rad: added to the angle of attack (the section's orientation at rest) */
    double speed;            /* m/s, mean */
    double dir[3];           /* unit wind direction (horizontal; yaw from the span axis) */
    double ramp_time;        /* s: mean wind from 0 to speed by (1 - cos)/2 over this time */
    double reverse_time;     /* s: the wind reverses direction at this time (<= 0: never) */
    /* turbulence: along-wind fluctuation u(t, x) on a grid (nt x nx), or none */
    int nx, nt;
    double x0, dx, dt;       /* m, m, s */
    const double *u;         /* m/s, row-major by time: u[k * nx + j] */
    /* the rod, for the full model's callback */
    const gal_rod *rod;
} gal_loads;

/* Wind velocity at (t, x) (m/s, 3-vector). */
void gal_loads_wind(const gal_loads *L, double t, double x, double w[3]);
/* The point load (gal_pointload.eval signature). */
int gal_loads_point(void *ctx, double t, double x, const double r[3], const double rdot[3],
                    const double tan[3], const double d1[3], double f[3], double *m);
/* The full model's generalized forces (gal_force.eval signature): element-centre loads times the
 * unstretched element length, half to each node, moments to the twist. */
int gal_loads_full(void *ctx, double t, const double *q, const double *v, double *f);

/* Static equilibrium under the mean wind (drag, lift and moment of the mean flow, no motion): q
 * is updated in place (start: the no-wind equilibrium). */
int gal_loads_static(gal_rod *rod, double *q, const gal_loads *L, double force_tol, int max_iter, int *iterations);

#ifdef __cplusplus
}
#endif

#endif
