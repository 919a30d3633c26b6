/* loads.h: the aerodynamic loads of a scene (paper Eq. 10; DESIGN.md "Aerodynamics", "Wind"):
 * quasi-steady drag, lift and moment per unit length from a coefficient table, in the relative
 * wind (wind minus conductor velocity when aero_damping is on), with the mean wind ramped in and
 * an along-wind turbulence field interpolated in space and time. The same point load serves the
 * full model (at element centres) and the reduced model (at quadrature points).
 *
 * Each effect is one term; gal_loads_list_make lists those that are on:
 *   the relative wind   mean_wind     src/loads/relwind.c     speed != 0 (ramp, reversal)
 *                       turbulence    src/loads/turbulence.c  a field u (nt > 1, nx > 0)
 *                       vertical_turbulence  turbulence.c     a field w on the same grid
 *                       aero_damping  src/loads/relwind.c     aero_damping (minus the velocity)
 *   the section load    aero_drag, aero_lift, aero_moment  src/loads/section.c  by flags
 * An equivalent bundle sums the section load over its sub-conductors (src/loads/bundle_section.c). */
#ifndef GALLOP_LOADS_H
#define GALLOP_LOADS_H

#include "gallop/loads/aero.h"
#include "gallop/model/force.h"
#include "gallop/rod/rod.h"

#ifdef __cplusplus
extern "C" {
#endif

struct gal_loads;

/* A term of the relative wind at a section, in one of three forms:
 *   speed:    its part of the along-wind speed (m/s) at time t (s) and span position x (m),
 *             before the wind's reversal; ramp is the mean wind's ramp factor at t (0..1);
 *   relative: a change of the relative wind w (m/s) of a section moving at rdot (m/s);
 *   vertical: its part of the vertical wind speed (m/s, up: +z) at t and x (not reversed). */
typedef struct gal_loads_term {
    const char *name;   /* "mean_wind", or the scene's effect: "turbulence", "aero_damping" */
    double (*speed)(const struct gal_loads *L, double t, double x, double ramp);
    void (*relative)(const struct gal_loads *L, const double rdot[3], double w[3]);
    double (*vertical)(const struct gal_loads *L, double t, double x, double ramp);
} gal_loads_term;
extern const gal_loads_term gal_loads_term_mean_wind, gal_loads_term_turbulence,
    gal_loads_term_vertical_turbulence, gal_loads_term_aero_damping;

/* An equivalent bundle carried as one rod (src/loads/bundle_section.c): at each section the loads
 * of its n sub-conductors, each at its offset from the centroid (turned with the section's twist),
 * at its own relative wind (the centroid's velocity plus the twist rate times tan x offset), its
 * own air density (the wake factor on a leeward one), summed about the centroid. */
#define GAL_LOADS_MAX_SUB 8
typedef struct gal_loads_bundle {
    int n;                              /* sub-conductors; 0: a single conductor (the section's load) */
    double off[GAL_LOADS_MAX_SUB][2];   /* m: offsets along the section's d1 and d2 = tan x d1 (at
                                         * rest: horizontal across the span and up) */
    double rho[GAL_LOADS_MAX_SUB];      /* kg/m^3: each one's air density */
    int leeward[GAL_LOADS_MAX_SUB];     /* 1: in another's wake at rest (its rho times wake_factor) */
} gal_loads_bundle;

typedef struct gal_loads {
    const gal_aero_table *table;
    unsigned flags;          /* GAL_AERO_DRAG | GAL_AERO_LIFT | GAL_AERO_MOMENT */
    int aero_damping;        /* the conductor's velocity is in the relative wind */
    double rho;              /* kg/m^3; times the sub-conductors of a bundle carried as one rod */
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
    const double *w;         /* m/s, the vertical fluctuation on the same grid, or NULL: none */
    /* the rod, for the full model's callback */
    const gal_rod *rod;
    gal_loads_bundle bundle; /* n > 1: an equivalent bundle's sub-conductors (gal_loads_bundle_set) */
} gal_loads;

/* Make L an equivalent bundle's: n (2..GAL_LOADS_MAX_SUB) sub-conductors on the circle of `radius`
 * (m), the first at `orientation` (rad from the horizontal, the explicit model's placing), each at
 * air_density (kg/m^3) times wake_factor (0..1) when leeward: downwind of another (along L->dir's
 * component across the span) and within one diameter L->diam of its line, at rest (set L->dir and
 * L->diam first). L->rho stays as it is (n times the air density: what the single-rod onset
 * criteria read). n < 2 clears it. */
void gal_loads_bundle_set(gal_loads *L, int n, double radius, double orientation, double air_density,
                          double wake_factor);

/* The terms that are on, in order. Made from the fields of a gal_loads at each evaluation (a few
 * tests; gal_loads_full makes it once for all elements): gal_loads is a value that callers copy
 * and change (statics under the mean wind drops the turbulence, the onset sweep sets the speed),
 * so a list kept inside it could go stale. */
typedef struct gal_loads_list {
    const gal_loads_term *wind[4];      /* the relative wind's terms */
    int nwind;
    const gal_aero_term *section[3];    /* the section load's terms */
    int nsection;
} gal_loads_list;
void gal_loads_list_make(const gal_loads *L, gal_loads_list *list);
/* The mean wind's ramp factor at t: (1 - cos(pi t / ramp_time))/2 during the ramp, else 1. */
double gal_loads_ramp(const gal_loads *L, double t);

/* Wind velocity at (t, x) (m/s, 3-vector). */
void gal_loads_wind(const gal_loads *L, double t, double x, double w[3]);
/* The point load (gal_pointload.eval signature). */
int gal_loads_point(void *ctx, double t, double x, const double r[3], const double rdot[3],
                    const double tan[3], const double d1[3], double f[3], double *m);
/* The full model's generalized forces (gal_force.eval signature): element-centre loads times the
 * unstretched element length, half to each node, moments to the twist. An equivalent bundle's
 * (L->bundle.n > 1) are its sub-conductors' summed about the centroid, each moving with the
 * element's twist rate v[3 nn + j] (gal_loads_point has no twist rate: it takes it as 0). */
int gal_loads_full(void *ctx, double t, const double *q, const double *v, double *f);
/* gal_loads_full with the rod's edge frames at q given (gal_force.eval_framed; frames from
 * gal_rod_eval_frames at the same q): the same numbers, without computing them again. */
int gal_loads_full_framed(void *ctx, double t, const double *q, const double *v, const double *frames, double *f);

/* The share of element j alone (gal_force.element signature): f[0..2] and f[3..5] on its two
 * nodes, f[6] on its twist; gal_loads_full adds these over the elements. */
int gal_loads_element(void *ctx, double t, const double *q, const double *v, int j, double f[7]);

/* The mean wind's load at rest at q, after the ramp, without turbulence (gal_loads_full's
 * generalized forces, added to f): what gal_loads_static balances. */
int gal_loads_mean(const gal_loads *L, const double *q, double *f);

/* Static equilibrium under the mean wind (drag, lift and moment of the mean flow, no motion): q
 * is updated in place (start: the no-wind equilibrium). */
int gal_loads_static(const gal_rod *rod, double *q, const gal_loads *L, double force_tol, int max_iter, int *iterations);

#ifdef __cplusplus
}
#endif

#endif
