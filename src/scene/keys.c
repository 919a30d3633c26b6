/* keys.c: the scene keys, one row per key of DESIGN.md's table ("Scene files"): section, name,
 * type, allowed range, unit; the effect names; looking keys and sections up by name. */
#include "scene_impl.h"

#include <stddef.h>
#include <stdio.h>
#include <string.h>

const char *const gal_effect_names[GAL_FX_COUNT] = {
    "gravity", "extension", "bending", "torsion", "ice_eccentricity", "aero_drag",
    "aero_lift", "aero_moment", "aero_damping", "turbulence", "damping"};

const char *const scn_twist_names[] = {"clamped", "free", NULL};
const char *const scn_start_names[] = {"rest", "mean_wind", NULL};
const char *const scn_reduced_names[] = {"recomputed", NULL};
const char *const scn_on_invalid_names[] = {"stop", "warn", NULL};
const char *const scn_turb_names[] = {"none", "kaimal", "davenport", "von_karman", "en1991",
                                      NULL};
const char *const scn_terrain_names[] = {"0", "I", "II", "III", "IV", NULL};
const char *const scn_onoff_names[] = {"off", "on", NULL};
const char *const scn_bundle_model_names[] = {"equivalent", "explicit", NULL};
static const char *const sections[] = {"span", "stringing", "conductor", "ice", "wind",
                                       "effects", "model", "simulation", "stability", "output",
                                       "bundle", NULL};

#define OFF(m) offsetof(gal_scene, m)
#define NUM(s, k, m, lo, lop, hi, hip, u) {s, k, T_NUM, OFF(m), lo, hi, lop, hip, 1.0, u, NULL}
#define INT(s, k, m, lo, hi) {s, k, T_INT, OFF(m), lo, hi, 0, 0, 1.0, "count", NULL}
#define FX(i) {"effects", NULL, T_FX, i, 0, 1, 0, 0, 1.0, "on | off", NULL}

const keydef scn_keys[K_COUNT] = {
    NUM("span", "length", span.length, 0, 1, 5000, 0, "m"),
    NUM("span", "height_difference", span.height_difference, -5000, 1, 5000, 1, "m"),
    NUM("span", "horizontal_tension", span.horizontal_tension, 0, 1, 5e6, 0, "N"),
    NUM("span", "sag", span.sag, 0, 1, 2500, 1, "m"),
    NUM("span", "unstretched_length", span.unstretched_length, 0, 1, 10000, 0, "m"),
    {"span", "end_twist", T_ENUM, 0, 0, 0, 0, 0, 1.0, "clamped | free", scn_twist_names},
    NUM("span", "tension_rts", span.tension_rts, 0, 1, 1, 1,
        "-, horizontal tension over the rated strength, in the load case"),
    NUM("span", "temperature", span.temperature, -273.15, 1, 1000, 0,
        "deg C, conductor temperature of the load case"),
    NUM("stringing", "temperature", stringing.temperature, -273.15, 1, 1000, 0,
        "deg C, reference temperature of the stringing condition"),
    NUM("stringing", "horizontal_tension", stringing.horizontal_tension, 0, 1, 5e6, 0,
        "N, bare conductor at the stringing temperature"),
    NUM("stringing", "sag", stringing.sag, 0, 1, 2500, 1,
        "m, mid-span below the chord, bare conductor at the stringing temperature"),
    {"conductor", "name", T_NAME, 0, 0, 0, 0, 0, 1.0, "a row of conductors.csv", NULL},
    NUM("conductor", "diameter", conductor.diameter, 0, 1, 0.2, 0, "m"),
    NUM("conductor", "mass_per_length", conductor.mass_per_length, 0, 1, 100, 0, "kg/m"),
    NUM("conductor", "axial_stiffness", conductor.axial_stiffness, 0, 1, 1e10, 0, "N"),
    NUM("conductor", "bending_stiffness", conductor.bending_stiffness, 0, 0, 1e6, 0, "N m^2"),
    NUM("conductor", "torsional_stiffness", conductor.torsional_stiffness, 0, 1, 1e6, 0, "N m^2/rad"),
    NUM("conductor", "polar_inertia", conductor.polar_inertia, 0, 1, 10, 0, "kg m^2/m"),
    NUM("conductor", "damping_ratio", conductor.damping_ratio, 0, 0, 1, 1, "-"),
    NUM("conductor", "rated_strength", conductor.rated_strength, 0, 1, 1e7, 0,
        "N, rated tensile strength (RTS)"),
    NUM("conductor", "thermal_expansion", conductor.thermal_expansion, 0, 1, 1e-4, 0,
        "1/K, coefficient of linear expansion"),
    NUM("conductor", "final_modulus", conductor.final_modulus, 0, 1, 1e12, 0,
        "Pa, final modulus (informational: the rod uses axial_stiffness)"),
    NUM("ice", "mass_per_length", ice.mass_per_length, 0, 1, 100, 0, "kg/m"),
    NUM("ice", "eccentricity", ice.eccentricity, -0.5, 0, 0.5, 0, "m"),
    NUM("ice", "polar_inertia", ice.polar_inertia, 0, 0, 10, 0, "kg m^2/m"),
    {"ice", "aero_table", T_PATH, 0, 0, 0, 0, 0, 1.0, "CSV alpha_deg,cd,cl,cm", NULL},
    {"ice", "attack_angle", T_NUM, OFF(ice.attack_angle), -180, 180, 0, 0, DEG,
     "deg, angle of attack of a horizontal wind normal to the span on the section at rest", NULL},
    NUM("ice", "thickness", ice.thickness, 0, 1, 0.5, 0,
        "m, radial thickness of an equivalent uniform ice sleeve"),
    NUM("ice", "density", ice.density, 0, 1, 1000, 0, "kg/m^3, of the ice (glaze 900)"),
    {"ice", "shape", T_NAME, 0, 0, 0, 0, 0, 1.0, "a table of data/aero (file name without .csv)",
     NULL},
    NUM("wind", "speed", wind.speed, 0, 0, 80, 0, "m/s"),
    {"wind", "yaw", T_NUM, OFF(wind.yaw), 0, 180, 0, 0, DEG, "deg, 90 = normal to the span", NULL},
    NUM("wind", "air_density", wind.air_density, 0, 1, 5, 0, "kg/m^3"),
    {"wind", "turbulence", T_ENUM, 0, 0, 0, 0, 0, 1.0, "none | kaimal | davenport | von_karman | en1991",
     scn_turb_names},
    NUM("wind", "intensity", wind.intensity, 0, 0, 1, 0, "-, sigma_u / U"),
    NUM("wind", "coherence_decay", wind.coherence_decay, 0, 1, 100, 0, "-, C in exp(-C f dx / U)"),
    {"wind", "seed", T_LONG, OFF(wind.seed), 0, 4294967295.0, 0, 0, 1.0, "integer", NULL},
    NUM("wind", "height", wind.height, 0, 1, 200, 0, "m, conductor height above ground"),
    {"wind", "terrain", T_ENUM, OFF(wind.terrain), 0, 0, 0, 0, 1.0,
     "0 | I | II | III | IV (EN 1991-1-4 Table 4.1)", scn_terrain_names},
    NUM("wind", "roughness_length", wind.roughness_length, 0, 1, 10, 0, "m, z0"),
    NUM("wind", "basic_speed", wind.basic_speed, 0, 1, 80, 0,
        "m/s, v_b: 10 min mean at 10 m in terrain II"),
    NUM("wind", "length_scale", wind.length_scale, 0, 1, 10000, 0,
        "m, turbulence length scale of the spectrum"),
    {"wind", "vertical_turbulence", T_ENUM, OFF(wind.vertical_turbulence), 0, 0, 0, 0, 1.0,
     "off | on", scn_onoff_names},
    NUM("wind", "vertical_coherence_decay", wind.vertical_coherence_decay, 0, 1, 100, 0,
        "-, C_w in exp(-C_w f dx / U) of the vertical component"),
    NUM("wind", "vertical_intensity", wind.vertical_intensity, 0, 0, 1, 0,
        "-, sigma_w / U of the vertical component"),
    NUM("wind", "vertical_length_scale", wind.vertical_length_scale, 0, 1, 10000, 0,
        "m, length scale L_w of the vertical component's spectrum"),
    FX(0), FX(1), FX(2), FX(3), FX(4), FX(5), FX(6), FX(7), FX(8), FX(9), FX(10),
    INT("model", "elements", model.elements, 4, 200000),
    INT("model", "modes_vertical", model.modes_vertical, 0, 200),
    INT("model", "modes_horizontal", model.modes_horizontal, 0, 200),
    INT("model", "modes_torsional", model.modes_torsional, 0, 200),
    {"model", "reduced", T_ENUM, 0, 0, 0, 0, 0, 1.0,
     "recomputed (the only reduced model: modes and modal derivatives, the rod's own forces at the "
     "reconstructed state, self-checked)", scn_reduced_names},
    NUM("model", "residual_tolerance", model.residual_tolerance, 0, 1, 10, 0,
        "-, reduced model: largest relative residual of its self-check (0.1: amplitudes within ~5%)"),
    {"model", "on_invalid", T_ENUM, 0, 0, 0, 0, 0, 1.0,
     "stop | warn (what a reduced run does when its residual passes residual_tolerance)",
     scn_on_invalid_names},
    NUM("simulation", "duration", simulation.duration, 0, 1, 1e6, 0, "s"),
    NUM("simulation", "time_step", simulation.time_step, 0, 0, 1000, 0, "s, 0 = chosen by gallop"),
    {"simulation", "probes", T_PROBES, 0, 0, 1, 1, 1, 1.0, "fractions of the span, comma list",
     NULL},
    NUM("simulation", "wind_ramp", simulation.wind_ramp, 0, 0, 1e4, 0, "s, the mean wind rises from 0 over this time"),
    NUM("simulation", "wind_reverse_time", simulation.wind_reverse_time, 0, 0, 1e6, 0,
        "s, the wind reverses its direction at this time; 0 = never"),
    NUM("simulation", "output_interval", simulation.output_interval, 0, 0, 10, 0, "s, trace sampling; 0 = chosen"),
    NUM("simulation", "rho_inf", simulation.rho_inf, 0, 0, 1, 0,
        "-, full model: spectral radius at infinite frequency (1 = no numerical dissipation)"),
    NUM("simulation", "newton_tolerance", simulation.newton_tolerance, 1e-14, 0, 1e-2, 0,
        "-, both models' implicit step: Newton's largest residual over the step's force scale"),
    {"simulation", "start", T_ENUM, 0, 0, 0, 0, 0, 1.0,
     "rest | mean_wind (rest: the wind ramps in over wind_ramp; mean_wind: from the equilibrium under the mean wind)",
     scn_start_names},
    NUM("stability", "speed_min", stability.speed_min, 0, 0, 80, 0, "m/s, lowest wind speed of `gallop stability`"),
    NUM("stability", "speed_max", stability.speed_max, 0, 1, 80, 0, "m/s, highest wind speed"),
    NUM("stability", "speed_step", stability.speed_step, 0.001, 0, 80, 0, "m/s, step of the wind speeds"),
    {"output", "directory", T_DIR, 0, 0, 0, 0, 0, 1.0, "path", NULL},
    {"output", "neighbour_phases", T_PAIRS, 0, -1000, 1000, 0, 0, 1.0,
     "m, y1, z1, y2, z2, ...: neighbouring phases at rest, offsets (horizontal downwind, up) from this "
     "conductor's equilibrium; the galloping ellipse's clearance to each is reported", NULL},
    INT("bundle", "subconductors", bundle.subconductors, 1, 8),
    NUM("bundle", "separation", bundle.separation, 0, 1, 2, 0,
        "m, between adjacent sub-conductors on the bundle circle"),
    INT("bundle", "spacers", bundle.spacers, 0, 1000),
    {"bundle", "spacer_positions", T_SPOS, 0, 0, 1, 1, 1, 1.0,
     "fractions of the span, comma list, increasing (in place of spacers)", NULL},
    {"bundle", "orientation", T_NUM, OFF(bundle.orientation), -180, 180, 0, 0, DEG,
     "deg, of the first sub-conductor on the bundle circle from the horizontal", NULL},
    NUM("bundle", "spacer_mass", bundle.spacer_mass, 0, 0, 1000, 0, "kg, of one spacer"),
    NUM("bundle", "spacer_inertia", bundle.spacer_inertia, 0, 0, 1000, 0,
        "kg m^2, of one spacer about the bundle axis"),
    NUM("bundle", "wake_factor", bundle.wake_factor, 0, 0, 1, 0,
        "-, explicit model: the dynamic pressure of a leeward sub-conductor (in another's wake, at rest) "
        "over the free stream's (1: no shielding)"),
    NUM("bundle", "spacer_stiffness", bundle.spacer_stiffness, 0, 0, GAL_SPACER_STIFFNESS_MAX, 0,
        "N/m, explicit model: a spacer arm's stiffness at its clamp (0: rigid spacers; flexible: at "
        "least 100)"),
    {"bundle", "model", T_ENUM, 0, 0, 0, 0, 0, 1.0,
     "equivalent | explicit (equivalent: one rod with the bundle's mass, inertia and tension-given "
     "torsional stiffness; explicit: one rod per sub-conductor, joined by the spacers)",
     scn_bundle_model_names},
};

/* Keys that no longer apply, refused (exit 2, FILE:LINE): why, and what replaced them. */
#define REDUCED_REPLACEMENT                                                                                       \
    "the reduced model recomputes its coupling from the rod at the current state (no fitted range) and checks " \
    "itself: remove the line; what replaced it: model.residual_tolerance (its self-check's largest residual), "  \
    "model.on_invalid = stop | warn, and the basis keys model.modes_vertical, model.modes_horizontal, "           \
    "model.modes_torsional"
static const struct {
    const char *sec, *key, *why;
} retired[] = {
    {"model", "identification_amplitude",
     "the identified reduced model whose fit it ranged was removed (issue 13); " REDUCED_REPLACEMENT},
    {"model", "identification_twist",
     "the identified reduced model whose fit it ranged was removed (issue 13); " REDUCED_REPLACEMENT},
    {"simulation", "tolerance",
     "the adaptive reduced integrator whose error per step it set was removed (issue 13): both models take "
     "fixed steps; remove the line; what replaced it: simulation.time_step (s, the step of both models; its "
     "error against a converged reference is measured by gallop accuracy's front study)"},
};

const char *scn_retired_key(const char *sec, const char *key)
{
    for (size_t i = 0; i < sizeof retired / sizeof retired[0]; i++)
        if (!strcmp(sec, retired[i].sec) && !strcmp(key, retired[i].key)) return retired[i].why;
    return NULL;
}

const char *scn_key_name(int k)
{
    return scn_keys[k].type == T_FX ? gal_effect_names[scn_keys[k].off] : scn_keys[k].key;
}

int scn_find_section(const char *s)
{
    for (int i = 0; sections[i]; i++)
        if (!strcmp(s, sections[i])) return i;
    return -1;
}

int scn_find_key(const char *sec, const char *key)
{
    for (int k = 0; k < K_COUNT; k++)
        if (!strcmp(scn_keys[k].sec, sec) && !strcmp(scn_key_name(k), key)) return k;
    return -1;
}

/* "length, height_difference, ..." for a section */
const char *scn_key_list(const char *sec, char *buf, size_t n)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int k = 0; k < K_COUNT; k++) {
        if (strcmp(scn_keys[k].sec, sec)) continue;
        int w = snprintf(buf + used, n - used, "%s%s", used ? ", " : "", scn_key_name(k));
        if (w < 0 || (size_t)w >= n - used) break;
        used += (size_t)w;
    }
    return buf;
}

const char *scn_section_list(void)
{
    return "span, stringing, conductor, ice, wind, effects, model, simulation, stability, output, bundle";
}

/* the keys that fix the equilibrium: exactly one of them (the stringing section counts once) */
int scn_is_spec(int k)
{
    return k == K_TENSION || k == K_SAG || k == K_ULENGTH || k == K_RTSFRAC || k == K_STENSION ||
           k == K_SSAG;
}
