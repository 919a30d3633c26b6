/* standards.c: the scene's inputs as line engineers give them: ice as a radial thickness of an
 * equivalent uniform sleeve (IEC 60826 / EN 50341-1 practice) of a density, its shape naming a
 * shipped aerodynamic table; wind from the conductor's height and the terrain (EN 1991-1-4, as
 * used by EN 50341-1: gallop/scene/terrain.h). Each resolved value can be overridden by the
 * scene's own key (wind.speed, wind.intensity, wind.length_scale, ice.polar_inertia). */
#define _XOPEN_SOURCE 700 /* realpath */
#include "scene_impl.h"
#include "gallop/scene/terrain.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* Two keys that exclude each other: "[s] a (line n) and [s] b (line m) given". */
static int both(pstate *ps, int a, int b, const char *allowed)
{
    char ka[64], kb[64], wa[32], wb[32];
    int last = (ps->given[a] < 0 || (ps->given[b] > 0 && ps->given[b] < ps->given[a])) ? a : b;
    if (ps->given[a] > 0) snprintf(wa, sizeof wa, "line %d", ps->given[a]);
    else snprintf(wa, sizeof wa, "--set");
    if (ps->given[b] > 0) snprintf(wb, sizeof wb, "line %d", ps->given[b]);
    else snprintf(wb, sizeof wb, "--set");
    return scn_kfail(ps, last, "%s (%s) and %s (%s) given; allowed: %s",
                     scn_sec_key(a, ka, sizeof ka), wa, scn_sec_key(b, kb, sizeof kb), wb, allowed);
}

/* ice.shape: data/aero/<shape>.csv in $GALLOP_DATA, ./data, or <scene dir>/.. */
static int ice_shape(pstate *ps)
{
    gal_scene *sc = ps->sc;
    const char *env = getenv("GALLOP_DATA");
    char path[2 * GAL_PATH_MAX + 128], real[PATH_MAX];
    if (env && *env) snprintf(path, sizeof path, "%s/aero/%s.csv", env, sc->ice.shape);
    else if (access("data/aero", R_OK) == 0) snprintf(path, sizeof path, "data/aero/%s.csv", sc->ice.shape);
    else snprintf(path, sizeof path, "%s/../aero/%s.csv", ps->dir, sc->ice.shape);
    if (access(path, R_OK) != 0 || !realpath(path, real) || strlen(real) >= sizeof sc->ice.aero_table)
        return scn_kfail(ps, K_ISHAPE, "no such table %s; allowed: the name of a table of data/aero "
                         "(e.g. iced_d_shape), or [ice] aero_table = a file", path);
    strcpy(sc->ice.aero_table, real);
    sc->ice.aero_table_line = ps->given[K_ISHAPE];
    snprintf(sc->ice.aero_table_given, sizeof sc->ice.aero_table_given, "%s", sc->ice.shape);
    return 1;
}

int scn_ice(pstate *ps)
{
    gal_scene *sc = ps->sc;
    if (ps->given[K_IMASS] && ps->given[K_ITHICK])
        return both(ps, K_IMASS, K_ITHICK, "one of them (the mass, or a thickness and density)");
    if (ps->given[K_ISHAPE] && ps->given[K_ITABLE])
        return both(ps, K_ISHAPE, K_ITABLE, "one of them (a shipped table by name, or a file)");
    if (ps->given[K_IDENS] && ps->given[K_IMASS])
        return both(ps, K_IMASS, K_IDENS, "a density only with a thickness");
    sc->ice.present = ps->given[K_IMASS] || ps->given[K_ITHICK];
    static const int needs_ice[] = {K_IECC, K_IPOLAR, K_ITABLE, K_IANGLE, K_IDENS, K_ISHAPE};
    if (!sc->ice.present) {
        for (size_t i = 0; i < sizeof needs_ice / sizeof needs_ice[0]; i++)
            if (ps->given[needs_ice[i]])
                return scn_kfail(ps, needs_ice[i], "ice without a mass; allowed: together with "
                                 "[ice] mass_per_length or thickness");
        return 1;
    }
    double r = sc->conductor.diameter / 2, e = sc->ice.eccentricity;
    if (ps->given[K_ITHICK]) {
        /* a uniform sleeve of radial thickness t: m = rho pi ((r + t)^2 - r^2), its polar
         * inertia about the axis m ((r + t)^2 + r^2) / 2, the eccentricity's m e^2 added */
        double t = sc->ice.thickness, R = r + t;
        sc->ice.diameter = 2 * R;
        sc->ice.mass_per_length = sc->ice.density * GAL_PI * (R * R - r * r);
        if (!ps->given[K_IPOLAR])
            sc->ice.polar_inertia = sc->ice.mass_per_length * (0.5 * (R * R + r * r) + e * e);
    } else if (!ps->given[K_IPOLAR]) {
        /* the ice mass at the eccentricity plus a thin ring on the conductor surface */
        sc->ice.polar_inertia = sc->ice.mass_per_length * (r * r + e * e);
    }
    return ps->given[K_ISHAPE] ? ice_shape(ps) : 1;
}

/* z0 and z_min: from the terrain category, or z0 given (no z_min) */
static int roughness(pstate *ps, double *z0, double *zmin)
{
    gal_scene *sc = ps->sc;
    if (ps->given[K_TERRAIN] && ps->given[K_Z0])
        return both(ps, K_TERRAIN, K_Z0, "one of them (a category, or z0 directly)");
    if (ps->given[K_TERRAIN]) {
        gal_terrain_category(sc->wind.terrain, z0, zmin);
        sc->wind.roughness_length = *z0;
        sc->wind.min_height = *zmin;
    } else {
        *z0 = sc->wind.roughness_length;
        *zmin = sc->wind.min_height = 0;
    }
    return 1;
}

/* the vertical component's keys only with it on, and it only with a turbulent field */
static int vertical(pstate *ps)
{
    gal_scene *sc = ps->sc;
    char kb[64];
    static const int needs[] = {K_VCOH, K_VINTENS, K_VLSCALE};
    if (!sc->wind.vertical_turbulence) {
        for (size_t i = 0; i < sizeof needs / sizeof needs[0]; i++)
            if (ps->given[needs[i]])
                return scn_kfail(ps, needs[i], "only with [wind] vertical_turbulence = on; allowed: "
                                 "not given");
        return 1;
    }
    if (sc->wind.turbulence == GAL_TURB_NONE)
        return scn_kfail(ps, K_VTURB, "no turbulent wind field; allowed: on only together with %s "
                         "(kaimal, davenport, von_karman, en1991)", scn_sec_key(K_TURB, kb, sizeof kb));
    return 1;
}

/* after the along-wind values are resolved: the vertical ones not given follow them (C_w = C,
 * sigma_w = 0.5 sigma_u: IEC 61400-1 ed. 3 Annex C, Table C.1) */
static int vertical_defaults(pstate *ps)
{
    gal_scene *sc = ps->sc;
    if (!ps->given[K_VCOH]) sc->wind.vertical_coherence_decay = sc->wind.coherence_decay;
    if (!ps->given[K_VINTENS]) sc->wind.vertical_intensity = 0.5 * sc->wind.intensity;
    return 1;
}

int scn_wind_profile(pstate *ps)
{
    gal_scene *sc = ps->sc;
    int terrain = ps->given[K_TERRAIN] || ps->given[K_Z0];
    char kb[64];
    if (ps->given[K_VB] && ps->given[K_SPEED])
        return both(ps, K_SPEED, K_VB, "one of them (the mean speed at the conductor, or the "
                    "basic speed with height and terrain)");
    if ((terrain || ps->given[K_VB]) && !ps->given[K_HEIGHT])
        return scn_kfail(ps, terrain ? (ps->given[K_TERRAIN] ? K_TERRAIN : K_Z0) : K_VB,
                         "no conductor height; allowed: together with %s",
                         scn_sec_key(K_HEIGHT, kb, sizeof kb));
    if (ps->given[K_VB] && !terrain)
        return scn_kfail(ps, K_VB, "no terrain; allowed: together with [wind] terrain or "
                         "roughness_length");
    if (!vertical(ps)) return 0;
    if (!terrain) return vertical_defaults(ps);
    double z0, zmin, cr, iv, L;
    if (!roughness(ps, &z0, &zmin)) return 0;
    if (gal_terrain_profile(z0, zmin, sc->wind.height, &cr, &iv, &L) != GAL_OK)
        return scn_kfail(ps, K_HEIGHT, "not above the roughness length z0 = %g m; allowed: "
                         "height > z0", z0);
    if (ps->given[K_VB]) sc->wind.speed = cr * sc->wind.basic_speed;  /* v_m = c_r v_b */
    if (!ps->given[K_INTENS]) sc->wind.intensity = fmin(iv, 1.0);      /* I_v = 1 / ln(z/z0) */
    if (!ps->given[K_LSCALE] && sc->wind.turbulence == GAL_TURB_EN1991)
        sc->wind.length_scale = L;                                     /* Annex B, Eq. B.1 */
    return vertical_defaults(ps);
}
