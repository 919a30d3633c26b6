/* stability.h: Den Hartog's galloping criterion over the angle of attack (issue 4):
 * H(alpha) = dC_L/dalpha + C_D (per radian); where H < 0 a vertical mode of circular frequency w,
 * damping ratio zeta, mass m per length gallops above the onset speed
 *   U_c = -4 m zeta w / (rho d H(alpha))
 * (the wind speed at which the aerodynamic damping 1/2 rho U d H cancels the structural one).
 *
 * gal_stability_sweep evaluates the criterion and the onset speed of every mode on the grid
 * alpha = -180, -179, ..., 180 deg, finds the unstable ranges (runs of grid angles with H < 0)
 * and the lowest H; gal_stability_free releases the result. */
#ifndef GALLOP_STABILITY_H
#define GALLOP_STABILITY_H

#include "gallop/loads/aero.h"
#include "gallop/scene/scene.h"

#define GAL_STABILITY_NALPHA 361     /* -180 .. 180 deg in 1-deg steps */
#define GAL_STABILITY_MAX_MODES 64   /* vertical modes */

#ifdef __cplusplus
extern "C" {
#endif

/* Onset speed (m/s) for one mode at one angle; +INFINITY where H >= 0 (stable at any speed). */
double gal_stability_onset(const gal_aero_table *t, double alpha_rad, double mass, double zeta,
                           double omega, double rho, double diam);

/* Nigol's torsional criterion (Nigol & Buchan 1981, "Conductor galloping, Part II: torsional
 * mechanism", IEEE Trans. PAS-100(2), 708-720; summarized in CIGRE TB 322, 2007, "State of the art
 * of conductor galloping", ch. 2): the section's rotation theta' changes the angle of attack by
 * -R theta'/U (R a lever arm of the section), so the moment 1/2 rho U^2 d^2 C_M(alpha) gives the
 * torsional motion the damping 1/2 rho U d^2 R dC_M/dalpha; a torsional mode of polar inertia I
 * (kg m^2/m), circular frequency w and structural ratio zeta gallops torsionally where the total
 * ratio zeta + rho U d^2 R dC_M/dalpha / (4 I w) < 0, i.e. when dC_M/dalpha < 0 above
 *   U_N = 4 I w zeta / (rho d^2 R (-dC_M/dalpha)).
 * R = GAL_NIGOL_ARM d (the conductor's radius). +INFINITY where dC_M/dalpha >= 0. Note the
 * quasi-steady loads of the dynamic models use the velocity of the section's centre only (no R
 * theta' term), so this mechanism is the classic column's, not the coupled analysis's. */
#define GAL_NIGOL_ARM 0.5
double gal_stability_nigol_onset(double dcm, double inertia, double omega, double zeta, double rho, double diam);

/* What the criterion needs of the span. */
typedef struct gal_stability_params {
    double mass;          /* kg/m, conductor and ice */
    double zeta;          /* structural damping ratio of the vertical modes, - */
    double rho;           /* air density, kg/m^3 */
    double diam;          /* conductor diameter, m */
    double attack_angle;  /* of the section at rest, rad */
    int nmodes;           /* vertical modes, 0 .. GAL_STABILITY_MAX_MODES */
    const double *omega;  /* their circular frequencies, rad/s */
} gal_stability_params;

/* The span figures of a scene (omega left NULL, nmodes 0): mass = conductor + ice, zeta = the
 * conductor's damping ratio when the damping effect is on (else 0), the wind's air density, the
 * conductor's diameter, the ice's attack angle. */
void gal_stability_scene_params(const gal_scene *sc, gal_stability_params *p);

typedef struct gal_stability_row {
    double alpha_deg;     /* deg */
    double c[3];          /* C_D, C_L, C_M */
    double dcl;           /* dC_L/dalpha, per rad */
    double h;             /* Den Hartog H, per rad */
    double *onset;        /* m/s per mode; +INFINITY where H >= 0 */
} gal_stability_row;

typedef struct gal_stability {
    const gal_aero_table *t;
    gal_stability_params p;                      /* omega points at omega[] below */
    double omega[GAL_STABILITY_MAX_MODES];       /* rad/s */
    gal_stability_row r[GAL_STABILITY_NALPHA];
    double *onset;                               /* owned: NALPHA x max(nmodes, 1) */
    int imin;                                    /* row of the lowest H (the first one) */
    double h_rest;                               /* H at the attack angle, per rad */
    double onset_rest[GAL_STABILITY_MAX_MODES];  /* m/s per mode at the attack angle */
    int nranges;                                 /* runs of grid angles with H < 0 */
    double range[(GAL_STABILITY_NALPHA + 1) / 2][2]; /* [from, to] deg, both ends H < 0 */
} gal_stability;

/* The sweep; NULL with a message on bad parameters or out of memory. */
gal_stability *gal_stability_sweep(const gal_aero_table *t, const gal_stability_params *p);
/* Accepts NULL; returns NULL. */
gal_stability *gal_stability_free(gal_stability *S);

#ifdef __cplusplus
}
#endif

#endif
