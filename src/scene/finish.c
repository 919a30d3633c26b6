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

int scn_kfail(pstate *ps, int k, const char *fmt, ...)
{
    char what[2048], sv[128];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return scn_fail(ps, GAL_EINPUT, ps->given[k], "[%s] %s = %s: %s", scn_keys[k].sec,
                    scn_key_name(k), scn_show(ps->raw[k], sv, sizeof sv), what);
}

/* "[section] key" of a key, for messages that name several */
const char *scn_sec_key(int k, char *buf, size_t n)
{
    snprintf(buf, n, "[%s] %s", scn_keys[k].sec, scn_key_name(k));
    return buf;
}

#define SPEC_ALLOWED "exactly one of [span] horizontal_tension, sag, unstretched_length, " \
                     "tension_rts, or a [stringing] horizontal_tension or sag"

/* Exactly one way of fixing the equilibrium: [span] horizontal_tension, sag, unstretched_length,
 * tension_rts, or a [stringing] condition (its horizontal_tension or its sag). */
static int span_spec(pstate *ps)
{
    static const int keys[] = {K_TENSION, K_SAG, K_ULENGTH, K_RTSFRAC, K_STENSION, K_SSAG};
    int nspec = 0, last = -1;
    char list[512] = "", kb[64];
    size_t used = 0;
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++) {
        int k = keys[i];
        if (!ps->given[k]) continue;
        nspec++;
        char where[32];
        if (ps->given[k] > 0) snprintf(where, sizeof where, "line %d", ps->given[k]);
        else snprintf(where, sizeof where, "--set");
        int w = snprintf(list + used, sizeof list - used, "%s%s (%s)", used ? " and " : "",
                         k == K_STENSION || k == K_SSAG ? scn_sec_key(k, kb, sizeof kb)
                                                        : scn_key_name(k), where);
        if (w > 0 && (size_t)w < sizeof list - used) used += (size_t)w;
        /* report at the one given last: a --set, else the highest line */
        if (last < 0 || (ps->given[last] > 0 && (ps->given[k] < 0 || ps->given[k] > ps->given[last])))
            last = k;
    }
    if (nspec == 0)
        return scn_fail(ps, GAL_EINPUT, 0, "[span] horizontal_tension / sag / unstretched_length / "
                        "tension_rts / [stringing]: none given; allowed: " SPEC_ALLOWED);
    if (nspec > 1) return scn_kfail(ps, last, "%s given; allowed: " SPEC_ALLOWED, list);
    gal_scene *sc = ps->sc;
    sc->span.spec = ps->given[K_TENSION]   ? GAL_SPEC_TENSION
                    : ps->given[K_SAG]     ? GAL_SPEC_SAG
                    : ps->given[K_ULENGTH] ? GAL_SPEC_LENGTH
                    : ps->given[K_RTSFRAC] ? GAL_SPEC_TENSION_RTS
                                           : GAL_SPEC_STRINGING;
    sc->stringing.present = sc->span.spec == GAL_SPEC_STRINGING;
    sc->stringing.by_sag = ps->given[K_SSAG] != 0;
    return 1;
}

/* The stringing condition and the load case's temperature; tension_rts needs a rated strength.
 * Run after the conductor row is read. */
static int stringing_checks(pstate *ps)
{
    gal_scene *sc = ps->sc;
    char kb[64];
    if (sc->span.spec == GAL_SPEC_TENSION_RTS && !(sc->conductor.rated_strength > 0))
        return scn_kfail(ps, K_RTSFRAC, "the conductor has no rated strength; allowed: give "
                     "[conductor] rated_strength, or a conductor row that has one");
    if (sc->span.spec == GAL_SPEC_TENSION_RTS)
        sc->span.horizontal_tension = sc->span.tension_rts * sc->conductor.rated_strength;
    if (!sc->stringing.present) {
        if (ps->given[K_STEMP] && !ps->over[K_STENSION])
            return scn_kfail(ps, K_STEMP, "a stringing temperature without a stringing condition; "
                         "allowed: together with [stringing] horizontal_tension or sag");
        if (!ps->given[K_TEMP]) sc->span.temperature = 0;
        return 1;
    }
    int k = sc->stringing.by_sag ? K_SSAG : K_STENSION;
    if (!ps->given[K_STEMP])
        return scn_kfail(ps, k, "no stringing temperature; allowed: together with %s",
                     scn_sec_key(K_STEMP, kb, sizeof kb));
    if (sc->stringing.by_sag && !(sc->stringing.sag < sc->span.length / 2))
        return scn_kfail(ps, K_SSAG, "too deep; allowed: 0 < sag < length / 2 (%g m)",
                     sc->span.length / 2);
    if (!ps->given[K_TEMP]) sc->span.temperature = sc->stringing.temperature;
    if (sc->span.temperature != sc->stringing.temperature && !(sc->conductor.thermal_expansion > 0))
        return scn_kfail(ps, K_TEMP, "the conductor has no thermal expansion coefficient; allowed: "
                     "give [conductor] thermal_expansion, or the stringing temperature");
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
        return scn_kfail(ps, K_HDIFF, "steeper than 45 degrees; allowed: |height_difference| < length "
                     "(%g m)", L);
    if (sc->span.spec == GAL_SPEC_SAG && !(sc->span.sag < L / 2))
        return scn_kfail(ps, K_SAG, "too deep; allowed: 0 < sag < length / 2 (%g m)", L / 2);
    if (sc->span.spec == GAL_SPEC_LENGTH &&
        !(sc->span.unstretched_length >= chord / 1.01 && sc->span.unstretched_length <= 2 * chord))
        return scn_kfail(ps, K_ULENGTH, "out of range; allowed: chord / 1.01 <= unstretched_length <= 2 "
                     "chord (shorter stretches the conductor beyond 1 %%, past its breaking strain), "
                     "chord = sqrt(length^2 + height_difference^2) = %.6g m", chord);
    return 1;
}

/* Conductor and ice defaults (the ice: standards.c). */
static int conductor_and_ice(pstate *ps)
{
    gal_scene *sc = ps->sc;
    if (!ps->given[K_CPOLAR] && !ps->given[K_CNAME]) /* a table row has its own */
        sc->conductor.polar_inertia =
            sc->conductor.mass_per_length * sc->conductor.diameter * sc->conductor.diameter / 8;
    return scn_ice(ps);
}

/* The sizes computed from [simulation]'s doubles (scene.h): samples and steps within bounds. */
static int sim_sizes(pstate *ps)
{
    const gal_scene *sc = ps->sc;
    double T = sc->simulation.duration, dto = sc->simulation.output_interval, h = sc->simulation.time_step;
    if (dto > 0 && dto < GAL_SCENE_MIN_OUTPUT_INTERVAL)
        return scn_kfail(ps, K_OUTDT, "too small; allowed: 0 (chosen) or %g <= output_interval <= 10 s",
                     GAL_SCENE_MIN_OUTPUT_INTERVAL);
    if (dto > 0 && T / dto > (double)GAL_SCENE_MAX_SAMPLES)
        return scn_kfail(ps, K_OUTDT, "%.3g samples over the duration (%g s); allowed: 0 (chosen) or "
                     "output_interval >= duration / %ld = %g s", T / dto, T, GAL_SCENE_MAX_SAMPLES,
                     T / (double)GAL_SCENE_MAX_SAMPLES);
    if (dto > 0 && T / dto + 1e-9 < (double)(GAL_SCENE_MIN_SAMPLES - 1))
        return scn_kfail(ps, K_DUR, "too short to measure: %ld samples at output_interval = %g s; allowed: "
                     "duration >= %g s (%ld samples)", (long)floor(T / dto + 1e-9) + 1, dto,
                     (GAL_SCENE_MIN_SAMPLES - 1) * dto, GAL_SCENE_MIN_SAMPLES);
    if (h > 0 && h < GAL_SCENE_MIN_TIME_STEP)
        return scn_kfail(ps, K_DT, "too small; allowed: 0 (chosen) or %g <= time_step <= duration s",
                     GAL_SCENE_MIN_TIME_STEP);
    if (h > 0 && T / h > (double)GAL_SCENE_MAX_STEPS)
        return scn_kfail(ps, K_DT, "%.3g steps over the duration (%g s); allowed: 0 (chosen) or "
                     "time_step >= duration / %ld = %g s", T / h, T, GAL_SCENE_MAX_STEPS,
                     T / (double)GAL_SCENE_MAX_STEPS);
    return 1;
}

int gal_scene_sample_count(const gal_scene *sc, double duration, double dt_out, long min_samples, long *ns)
{
    double T = duration, n = floor(T / dt_out + 1e-9) + 1;
    *ns = 0;
    if (!(dt_out > 0) || !(n <= (double)GAL_SCENE_MAX_SAMPLES))
        return gal_error(GAL_EINPUT, "%s: [simulation] output_interval = %g s: %.3g samples over the "
                         "duration (%g s); allowed: at most %ld samples", sc->path, dt_out, n, T,
                         GAL_SCENE_MAX_SAMPLES);
    if (n < (double)min_samples)
        return gal_error(GAL_EINPUT, "%s: [simulation] duration = %g s: too short to measure: %.0f "
                         "samples at the output interval %g s; allowed: duration >= %g s (%ld "
                         "samples)", sc->path, T, n, dt_out, (double)(min_samples - 1) * dt_out, min_samples);
    *ns = (long)n;
    return GAL_OK;
}

/* Wind and simulation checks, the output directory, the effects: on where the scene has the
 * data; an explicit "on" without it is an error. */
static int wind_and_effects(pstate *ps)
{
    gal_scene *sc = ps->sc;
    if (sc->wind.turbulence != GAL_TURB_NONE && !(sc->wind.speed > 0))
        return scn_kfail(ps, K_TURB, "turbulence needs a mean wind; allowed: none, or [wind] speed > 0");
    if (sc->simulation.time_step > sc->simulation.duration)
        return scn_kfail(ps, K_DT, "longer than the duration; allowed: 0 <= time_step <= duration "
                     "(%g s)", sc->simulation.duration);
    if (!(sc->stability.speed_max >= sc->stability.speed_min))
        return scn_kfail(ps, K_SPMAX, "below speed_min (%g m/s); allowed: speed_min <= speed_max",
                     sc->stability.speed_min);
    if ((sc->stability.speed_max - sc->stability.speed_min) / sc->stability.speed_step > 2000)
        return scn_kfail(ps, K_SPSTEP, "gives more than 2000 speeds from %g to %g m/s; allowed: speed_step >= "
                     "(speed_max - speed_min) / 2000", sc->stability.speed_min, sc->stability.speed_max);
    if (!sc->output.directory[0])
        snprintf(sc->output.directory, sizeof sc->output.directory, "out/%s", sc->name);
    for (int i = 0; i < GAL_FX_COUNT; i++) {
        const char *miss = fx_missing(sc, i);
        if (ps->fx[i] == 1 && miss)
            return scn_kfail(ps, K_FX0 + i, "the scene lacks its data: %s; allowed: off, or give the "
                         "data", miss);
        sc->effect[i] = ps->fx[i] >= 0 ? ps->fx[i] : !miss;
    }
    return 1;
}

/* [bundle]: the counts a bundle comes in, a separation for more than one, the circle's radius. */
static int bundle_checks(pstate *ps)
{
    gal_scene *sc = ps->sc;
    int n = sc->bundle.subconductors;
    if (!(n == 1 || n == 2 || n == 3 || n == 4 || n == 6 || n == 8))
        return scn_kfail(ps, K_BSUB, "not a bundle's count; allowed: 1, 2, 3, 4, 6 or 8");
    if (n == 1) {
        for (int k = K_BSEP; k <= K_BMODEL; k++)
            if (ps->given[k])
                return scn_kfail(ps, k, "a key of a bundle, but [bundle] subconductors is 1; allowed: "
                             "subconductors = 2, 3, 4, 6 or 8 with it, or leave it out");
        return 1;
    }
    if (!ps->given[K_BSEP])
        return scn_kfail(ps, K_BSUB, "a bundle of %d needs [bundle] separation (m, between adjacent "
                     "sub-conductors; allowed: 0 < separation <= 2)", n);
    if (ps->given[K_BSPOS] && ps->given[K_BSPACERS])
        return scn_kfail(ps, K_BSPOS, "given with [bundle] spacers; allowed: one of the two (spacers: a "
                         "count, evenly spaced; spacer_positions: where each is)");
    const double *sp = sc->bundle.spacer_positions, gap = GAL_BUNDLE_MIN_SUBSPAN;
    for (int i = 0; i <= sc->bundle.nspacer_positions && ps->given[K_BSPOS]; i++) {
        double a = i ? sp[i - 1] : 0, b = i < sc->bundle.nspacer_positions ? sp[i] : 1;
        if (b - a < gap)
            return scn_kfail(ps, K_BSPOS, "a sub-span of %g of the span between %g and %g (0 and 1: the "
                             "supports); allowed: sub-spans of at least %g of the span", b - a, a, b, gap);
    }
    sc->bundle.model_line = ps->given[K_BMODEL]; /* for the commands that refuse explicit */
    double ks = sc->bundle.spacer_stiffness;
    if (ks > 0 && ks < GAL_SPACER_STIFFNESS_MIN)
        return scn_kfail(ps, K_BSSTIFF, "%g N/m; allowed: 0 (rigid spacers) or %g to %g N/m", ks,
                         GAL_SPACER_STIFFNESS_MIN, GAL_SPACER_STIFFNESS_MAX);
    if (ks > 0 && !sc->bundle.explicit_model)
        return scn_kfail(ps, K_BSSTIFF, "flexible spacers with [bundle] model = equivalent (one rod: its "
                         "spacers are rigid); allowed: model = explicit, or spacer_stiffness = 0");
    if (!sc->effect[GAL_FX_TORSION])
        return scn_kfail(ps, K_BSUB, "a bundle with [effects] torsion = off: its twist is what the "
                     "bundle changes; allowed: torsion = on, or subconductors = 1");
    if (!(sc->bundle.separation > sc->conductor.diameter))
        return scn_kfail(ps, K_BSEP, "not more than a sub-conductor's diameter (%g m): they would touch; "
                         "allowed: %g < separation <= 2 m", sc->conductor.diameter, sc->conductor.diameter);
    sc->bundle.radius = sc->bundle.separation / (2 * sin(GAL_PI / n));
    return 1;
}

int scn_finish(pstate *ps, const char *csv_given)
{
    if (ps->given[K_CNAME]) {
        char csv[2 * GAL_PATH_MAX + 32];
        scn_conductor_table(ps, csv_given, csv, sizeof csv);
        if (!scn_load_conductor(ps, csv)) return 0;
    }
    return required_keys(ps) && span_checks(ps) && stringing_checks(ps) && conductor_and_ice(ps) &&
           scn_wind_profile(ps) && wind_and_effects(ps) && sim_sizes(ps) && bundle_checks(ps);
}
