/* finish.c: a scene after all its keys: the conductor table row, required keys, cross-checks of
 * the span, defaults of conductor and ice, wind and simulation checks, effects. */
#include "scene_impl.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* ---- after all keys: the table row, required keys, cross-checks, defaults, effects ---- */

static const char *fx_missing(const gal_scene *sc, int fx)
{
    switch (fx) {
    case GAL_FX_BENDING:
        return sc->conductor.bending_stiffness > 0 ? NULL : "[conductor] bending_stiffness is 0";
    case GAL_FX_ICE_ECCENTRICITY:
        return !sc->ice.present            ? "the scene has no ice ([ice] mass_per_length)"
               : sc->ice.eccentricity == 0 ? "[ice] eccentricity is 0"
                                           : NULL;
    case GAL_FX_AERO_DRAG:
    case GAL_FX_AERO_LIFT:
    case GAL_FX_AERO_MOMENT:
    case GAL_FX_AERO_DAMPING: return sc->wind.speed > 0 ? NULL : "[wind] speed is 0";
    case GAL_FX_TURBULENCE:
        return sc->wind.turbulence != GAL_TURB_NONE ? NULL : "[wind] turbulence is none";
    case GAL_FX_DAMPING:
        return sc->conductor.damping_ratio > 0 ? NULL : "[conductor] damping_ratio is 0";
    default: return NULL;
    }
}

/* An error about key k as it was given (file line or --set): "[section] key = value: ...". */
static int kfail(pstate *ps, int k, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
static int kfail(pstate *ps, int k, const char *fmt, ...)
{
    char what[2048], sv[128];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return scn_fail(ps, GAL_EINPUT, ps->given[k], "[%s] %s = %s: %s", scn_keys[k].sec,
                    scn_key_name(k), scn_show(ps->raw[k], sv, sizeof sv), what);
}

/* Exactly one of horizontal_tension, sag, unstretched_length: the span's specification. */
static int span_spec(pstate *ps)
{
    int nspec = !!ps->given[K_TENSION] + !!ps->given[K_SAG] + !!ps->given[K_ULENGTH];
    if (nspec == 0)
        return scn_fail(ps, GAL_EINPUT, 0, "[span] horizontal_tension / sag / unstretched_length: "
                        "none given; allowed: exactly one of them");
    if (nspec > 1) {
        int last = -1;
        char list[256] = "";
        size_t used = 0;
        for (int k = K_TENSION; k <= K_ULENGTH; k++) {
            if (!ps->given[k]) continue;
            char where[32];
            if (ps->given[k] > 0) snprintf(where, sizeof where, "line %d", ps->given[k]);
            else snprintf(where, sizeof where, "--set");
            int w = snprintf(list + used, sizeof list - used, "%s%s (%s)", used ? " and " : "",
                             scn_key_name(k), where);
            if (w > 0 && (size_t)w < sizeof list - used) used += (size_t)w;
            /* report at the one given last: a --set, else the highest line */
            if (last < 0 || (ps->given[last] > 0 && (ps->given[k] < 0 || ps->given[k] > ps->given[last])))
                last = k;
        }
        return kfail(ps, last, "%s given; allowed: exactly one of horizontal_tension, sag, "
                     "unstretched_length", list);
    }
    ps->sc->span.spec = ps->given[K_TENSION] ? GAL_SPEC_TENSION
                        : ps->given[K_SAG]   ? GAL_SPEC_SAG
                                             : GAL_SPEC_LENGTH;
    return 1;
}

/* The keys without a default: the span's length and specification, the conductor's properties
 * (unless a table row gives them). */
static int required_keys(pstate *ps)
{
    char rt[160];
    if (!ps->given[K_LENGTH])
        return scn_fail(ps, GAL_EINPUT, 0, "[span] length: missing; allowed: %s (required)",
                        scn_range_text(K_LENGTH, rt, sizeof rt));
    if (!span_spec(ps)) return 0;
    static const int required[] = {K_DIAM, K_MASS, K_EA, K_EI, K_GJ};
    for (size_t i = 0; i < sizeof required / sizeof required[0]; i++) {
        int k = required[i];
        if (!ps->given[k] && !ps->given[K_CNAME])
            return scn_fail(ps, GAL_EINPUT, 0, "[conductor] %s: missing; allowed: %s (required: "
                            "give it, or name a row of the conductor table)", scn_key_name(k),
                            scn_range_text(k, rt, sizeof rt));
    }
    return 1;
}

/* Cross-checks of the span: incline, sag, unstretched length against the chord. */
static int span_checks(pstate *ps)
{
    const gal_scene *sc = ps->sc;
    double L = sc->span.length, h = sc->span.height_difference;
    double chord = sqrt(L * L + h * h);
    if (ps->given[K_HDIFF] && !(fabs(h) < L))
        return kfail(ps, K_HDIFF, "steeper than 45 degrees; allowed: |height_difference| < length "
                     "(%g m)", L);
    if (sc->span.spec == GAL_SPEC_SAG && !(sc->span.sag < L / 2))
        return kfail(ps, K_SAG, "too deep; allowed: 0 < sag < length / 2 (%g m)", L / 2);
    if (sc->span.spec == GAL_SPEC_LENGTH &&
        !(sc->span.unstretched_length > chord && sc->span.unstretched_length <= 2 * chord))
        return kfail(ps, K_ULENGTH, "out of range; allowed: chord < unstretched_length <= 2 chord, "
                     "chord = sqrt(length^2 + height_difference^2) = %.6g m", chord);
    return 1;
}

/* Conductor and ice defaults; ice keys need an ice mass. */
static int conductor_and_ice(pstate *ps)
{
    gal_scene *sc = ps->sc;
    if (!ps->given[K_CPOLAR] && !ps->given[K_CNAME]) /* a table row has its own */
        sc->conductor.polar_inertia =
            sc->conductor.mass_per_length * sc->conductor.diameter * sc->conductor.diameter / 8;
    sc->ice.present = ps->given[K_IMASS] != 0;
    if (!sc->ice.present) {
        for (int k = K_IECC; k <= K_IANGLE; k++)
            if (ps->given[k])
                return kfail(ps, k, "ice without a mass; allowed: together with [ice] "
                             "mass_per_length");
    } else if (!ps->given[K_IPOLAR]) {
        /* the ice mass at the eccentricity plus a thin ring on the conductor surface */
        double r = sc->conductor.diameter / 2, e = sc->ice.eccentricity;
        sc->ice.polar_inertia = sc->ice.mass_per_length * (r * r + e * e);
    }
    return 1;
}

/* Wind and simulation checks, the output directory, the effects: on where the scene has the
 * data; an explicit "on" without it is an error. */
static int wind_and_effects(pstate *ps)
{
    gal_scene *sc = ps->sc;
    if (sc->wind.turbulence != GAL_TURB_NONE && !(sc->wind.speed > 0))
        return kfail(ps, K_TURB, "turbulence needs a mean wind; allowed: none, or [wind] speed > 0");
    if (sc->simulation.time_step > sc->simulation.duration)
        return kfail(ps, K_DT, "longer than the duration; allowed: 0 <= time_step <= duration "
                     "(%g s)", sc->simulation.duration);
    if (!sc->output.directory[0])
        snprintf(sc->output.directory, sizeof sc->output.directory, "out/%s", sc->name);
    for (int i = 0; i < GAL_FX_COUNT; i++) {
        const char *miss = fx_missing(sc, i);
        if (ps->fx[i] == 1 && miss)
            return kfail(ps, K_FX0 + i, "the scene lacks its data: %s; allowed: off, or give the "
                         "data", miss);
        sc->effect[i] = ps->fx[i] >= 0 ? ps->fx[i] : !miss;
    }
    return 1;
}

int scn_finish(pstate *ps, const char *csv_given)
{
    if (ps->given[K_CNAME]) {
        char csv[2 * GAL_PATH_MAX + 32];
        scn_conductor_table(ps, csv_given, csv, sizeof csv);
        if (!scn_load_conductor(ps, csv)) return 0;
    }
    return required_keys(ps) && span_checks(ps) && conductor_and_ice(ps) && wind_and_effects(ps);
}
