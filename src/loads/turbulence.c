/* turbulence.c: the turbulence of a scene in one place (DESIGN.md "Wind"): the parameters of its
 * along-wind field (the spectral-representation generator of wind.c) from the scene's [wind],
 * [span] and [simulation], the field sampled on the loads' grid, and the term of the relative
 * wind that interpolates it bilinearly in time and span position, ramped in with the mean wind. */
#include "gallop/loads/windfield.h"
#include "gallop/loads/loads.h"
#include "gallop/base/core.h"

#include <math.h>
#include <stdlib.h>

int gal_windfield_params(const gal_scene *sc, gal_wind_params *p)
{
    gal_wind_params_default(p);
    if (sc->wind.turbulence == GAL_TURB_NONE)
        return gal_error(GAL_EINPUT, "%s: [wind] turbulence = none: the scene has no turbulent wind field; "
                         "allowed: kaimal, davenport, von_karman", sc->path);
    p->speed = sc->wind.speed;
    p->intensity = sc->wind.intensity;
    p->spectrum = (gal_wind_spectrum)sc->wind.turbulence; /* same values (wind.h) */
    p->coherence_decay = sc->wind.coherence_decay;
    if (sc->wind.height > 0) p->height = sc->wind.height;          /* else the default 10 m */
    p->length_scale = sc->wind.length_scale;                       /* 0: the spectrum's own */
    p->points = GAL_WINDFIELD_POINTS;
    p->spacing = sc->span.length / (GAL_WINDFIELD_POINTS - 1);
    p->time_step = GAL_WINDFIELD_TIME_STEP;
    p->duration = sc->simulation.duration + GAL_WINDFIELD_EXTRA_TIME;
    p->seed = (unsigned long)sc->wind.seed;
    return GAL_OK;
}

int gal_windfield_sample(const gal_scene *sc, gal_loads *L, double **u)
{
    *u = NULL;
    gal_wind_params wp;
    int st = gal_windfield_params(sc, &wp); /* the same field as `gallop wind` */
    if (st) return st;
    gal_wind *w = gal_wind_alloc(&wp);
    if (!w) return gal_error(GAL_EINPUT, "%s: [wind]: %s", sc->path, gal_error_message());
    st = gal_wind_generate(w);
    if (st) { gal_wind_free(w); return st; }
    int nx = gal_wind_points(w), nt = gal_wind_samples(w);
    *u = malloc((size_t)nx * nt * sizeof(double));
    if (!*u) { gal_wind_free(w); return gal_error(GAL_ENOMEM, "out of memory for the wind field"); }
    for (int k = 0; k < nt; k++)
        for (int j = 0; j < nx; j++) (*u)[(size_t)k * nx + j] = gal_wind_u(w, j, k);
    L->u = *u, L->nx = nx, L->nt = nt, L->x0 = 0, L->dx = gal_wind_spacing(w), L->dt = gal_wind_time_step(w);
    gal_wind_free(w);
    return GAL_OK;
}

/* the along-wind fluctuation u(t, x), bilinear in (t, x); the field repeats after its duration */
static double turbulence(const gal_loads *L, double t, double x, double ramp)
{
    double ft = t / L->dt, period = (double)(L->nt - 1);
    ft = fmod(ft, period);
    if (ft < 0) ft += period;
    int k = (int)ft;
    if (k >= L->nt - 1) k = L->nt - 2;
    double a = ft - k;
    double fx = L->nx > 1 ? (x - L->x0) / L->dx : 0;
    if (fx < 0) fx = 0;
    if (fx > L->nx - 1) fx = L->nx - 1;
    int j = (int)fx;
    if (j >= L->nx - 1) j = L->nx > 1 ? L->nx - 2 : 0;
    double b = L->nx > 1 ? fx - j : 0;
    const double *u0 = L->u + (size_t)k * L->nx, *u1 = u0 + L->nx;
    int j1 = L->nx > 1 ? j + 1 : j;
    double u = (1 - a) * ((1 - b) * u0[j] + b * u0[j1]) + a * ((1 - b) * u1[j] + b * u1[j1]);
    return ramp * u;
}

const gal_loads_term gal_loads_term_turbulence = {"turbulence", turbulence, NULL};
