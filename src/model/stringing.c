/* stringing.c: the scene's way of fixing the equilibrium as a statics specification; the
 * sag-tension change of state from a [stringing] condition through the unstretched length
 * (gallop/model/stringing.h states the equations). */
#include "gallop/model/stringing.h"
#include "gallop/base/core.h"
#include "gallop/statics/catenary.h"

int gal_stringing_length(const gal_scene *sc, double gravity, double *L0)
{
    if (!sc->stringing.present)
        return gal_error(GAL_EINPUT, "%s: no [stringing] condition", sc->path);
    gal_catenary c = {.L = sc->span.length, .h = sc->span.height_difference,
                      .w = sc->conductor.mass_per_length * gravity, /* bare conductor */
                      .EA = sc->conductor.axial_stiffness};
    int by_sag = sc->stringing.by_sag;
    int st = gal_catenary_solve(&c, by_sag ? 1 : 0,
                                by_sag ? sc->stringing.sag : sc->stringing.horizontal_tension);
    if (st != GAL_OK)
        return gal_error(st, "%s: [stringing] %s = %g: %s", sc->path,
                         by_sag ? "sag" : "horizontal_tension",
                         by_sag ? sc->stringing.sag : sc->stringing.horizontal_tension,
                         gal_error_message());
    double dT = sc->span.temperature - sc->stringing.temperature;
    *L0 = c.L0 * (1.0 + sc->conductor.thermal_expansion * dT); /* L0(T2) = L0(T1)(1 + alpha dT) */
    return GAL_OK;
}

int gal_stringing_spec(const gal_scene *sc, double gravity, gal_statics_spec *spec, double *value)
{
    switch (sc->span.spec) {
    case GAL_SPEC_TENSION: *spec = GAL_BY_TENSION, *value = sc->span.horizontal_tension; break;
    case GAL_SPEC_SAG: *spec = GAL_BY_SAG, *value = sc->span.sag; break;
    case GAL_SPEC_LENGTH: *spec = GAL_BY_LENGTH, *value = sc->span.unstretched_length; break;
    case GAL_SPEC_TENSION_RTS:
        *spec = GAL_BY_TENSION, *value = sc->span.tension_rts * sc->conductor.rated_strength;
        break;
    case GAL_SPEC_STRINGING:
        *spec = GAL_BY_LENGTH;
        return gal_stringing_length(sc, gravity, value);
    default: return gal_error(GAL_EINPUT, "%s: unknown span specification %d", sc->path, (int)sc->span.spec);
    }
    return GAL_OK;
}
