/* windfield.c: a scene's turbulent wind field parameters (DESIGN.md "Wind"; windfield.h). */
#include "gallop/loads/windfield.h"

#include "gallop/base/core.h"

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
    p->points = GAL_WINDFIELD_POINTS;
    p->spacing = sc->span.length / (GAL_WINDFIELD_POINTS - 1);
    p->time_step = GAL_WINDFIELD_TIME_STEP;
    p->duration = sc->simulation.duration + GAL_WINDFIELD_EXTRA_TIME;
    p->seed = (unsigned long)sc->wind.seed;
    return GAL_OK;
}
