/* stability.c: Den Hartog's criterion and the galloping onset speed of a vertical mode, swept over
 * the angle of attack (stability.h). */
#include "gallop/analysis/stability.h"
#include "gallop/base/core.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define DEG (GAL_PI / 180)

double gal_stability_onset(const gal_aero_table *t, double alpha, double mass, double zeta, double omega,
                           double rho, double diam)
{
    double H = gal_aero_den_hartog(t, alpha);
    if (!(H < 0)) return INFINITY;
    return -4.0 * mass * zeta * omega / (rho * diam * H);
}

double gal_stability_nigol_onset(double dcm, double inertia, double omega, double zeta, double rho, double diam)
{
    if (!(dcm < 0)) return INFINITY;
    return 4.0 * inertia * omega * zeta / (rho * diam * diam * GAL_NIGOL_ARM * diam * -dcm);
}

void gal_stability_scene_params(const gal_scene *sc, gal_stability_params *p)
{
    p->mass = sc->conductor.mass_per_length + sc->ice.mass_per_length;
    /* the structural damping the runs use: none when the damping effect is off */
    p->zeta = sc->effect[GAL_FX_DAMPING] ? sc->conductor.damping_ratio : 0.0;
    p->rho = sc->wind.air_density;
    p->diam = sc->conductor.diameter;
    p->attack_angle = sc->ice.attack_angle;
    p->nmodes = 0;
    p->omega = NULL;
}

/* Runs of consecutive grid angles where H < 0. */
static void unstable_ranges(gal_stability *S)
{
    S->nranges = 0;
    for (int i = 0; i < GAL_STABILITY_NALPHA; i++) {
        if (!(S->r[i].h < 0)) continue;
        int e = i;
        while (e + 1 < GAL_STABILITY_NALPHA && S->r[e + 1].h < 0) e++;
        S->range[S->nranges][0] = S->r[i].alpha_deg;
        S->range[S->nranges][1] = S->r[e].alpha_deg;
        S->nranges++;
        i = e;
    }
}

gal_stability *gal_stability_sweep(const gal_aero_table *t, const gal_stability_params *p)
{
    if (p->nmodes < 0 || p->nmodes > GAL_STABILITY_MAX_MODES || (p->nmodes > 0 && !p->omega)) {
        gal_error(GAL_EINPUT, "stability: %d vertical modes; allowed: 0 to %d", p->nmodes, GAL_STABILITY_MAX_MODES);
        return NULL;
    }
    gal_stability *S = calloc(1, sizeof *S);
    int w = p->nmodes > 0 ? p->nmodes : 1;
    double *onset = S ? malloc((size_t)GAL_STABILITY_NALPHA * w * sizeof *onset) : NULL;
    if (!onset) {
        free(S);
        gal_error(GAL_ENOMEM, "out of memory");
        return NULL;
    }
    S->t = t;
    S->p = *p;
    if (p->nmodes > 0) memcpy(S->omega, p->omega, (size_t)p->nmodes * sizeof *S->omega);
    S->p.omega = S->omega;
    S->onset = onset;
    const double m = p->mass, zeta = p->zeta, rho = p->rho, diam = p->diam;
    S->h_rest = gal_aero_den_hartog(t, p->attack_angle);
    for (int k = 0; k < p->nmodes; k++)
        S->onset_rest[k] = gal_stability_onset(t, p->attack_angle, m, zeta, S->omega[k], rho, diam);
    for (int i = 0; i < GAL_STABILITY_NALPHA; i++) {
        gal_stability_row *r = S->r + i;
        double dc[3], a;
        r->alpha_deg = -180 + i;
        a = r->alpha_deg * DEG;
        gal_aero_eval(t, a, r->c, dc);
        r->dcl = dc[1];
        r->h = gal_aero_den_hartog(t, a);
        r->onset = onset + (size_t)i * w;
        for (int k = 0; k < p->nmodes; k++) r->onset[k] = gal_stability_onset(t, a, m, zeta, S->omega[k], rho, diam);
        if (r->h < S->r[S->imin].h) S->imin = i;
    }
    unstable_ranges(S);
    return S;
}

gal_stability *gal_stability_free(gal_stability *S)
{
    if (S) free(S->onset);
    free(S);
    return NULL;
}
