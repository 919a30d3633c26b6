/* print.c: the resolved scene printed back as INI that gallop reads (every key, with its unit in a
 * comment, numbers with the digits that read back to the same value). */
#include "scene_impl.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- printing ---- */

static void put_num(FILE *fp, const char *key, double v, const char *unit)
{
    char b[40];
    fprintf(fp, "%s = %s ; %s\n", key, scn_fmt_num(v, b, sizeof b), unit);
}

/* A key in its file unit, with the digits that read back to the same SI value. */
static void put_key(FILE *fp, const gal_scene *sc, int k)
{
    const keydef *kd = &scn_keys[k];
    double v = *(const double *)((const char *)sc + kd->off);
    if (kd->scale == 1.0) {
        put_num(fp, kd->key, v, kd->unit);
        return;
    }
    char b[40];
    for (int p = 15; p <= 17; p++) {
        snprintf(b, sizeof b, "%.*g", p, v / kd->scale);
        if (strtod(b, NULL) * kd->scale == v) break;
    }
    fprintf(fp, "%s = %s ; %s\n", kd->key, b, kd->unit);
}

static const char *printable(const char *s, char *out, size_t n)
{
    size_t i = 0;
    for (; s[i] && i + 1 < n; i++) out[i] = (s[i] >= 0x20 && s[i] < 0x7f) ? s[i] : '?';
    out[i] = '\0';
    return out;
}

static void print_span_conductor_ice(const gal_scene *sc, FILE *fp)
{
    fprintf(fp, "\n[span]\n");
    put_key(fp, sc, K_LENGTH);
    put_key(fp, sc, K_HDIFF);
    if (sc->span.spec == GAL_SPEC_STRINGING)
        fprintf(fp, "; the equilibrium: the [stringing] condition below, carried to temperature\n");
    else
        put_key(fp, sc, sc->span.spec == GAL_SPEC_TENSION       ? K_TENSION
                        : sc->span.spec == GAL_SPEC_SAG         ? K_SAG
                        : sc->span.spec == GAL_SPEC_TENSION_RTS ? K_RTSFRAC
                                                                : K_ULENGTH);
    if (sc->span.spec == GAL_SPEC_TENSION_RTS)
        fprintf(fp, "; horizontal_tension = tension_rts * rated_strength = %.6g N\n",
                sc->span.horizontal_tension);
    put_key(fp, sc, K_TEMP);
    fprintf(fp, "end_twist = %s ; clamped | free\n",
            sc->span.end_twist == GAL_TWIST_FREE ? "free" : "clamped");

    fprintf(fp, "\n[stringing]\n");
    if (sc->stringing.present) {
        put_key(fp, sc, K_STEMP);
        put_key(fp, sc, sc->stringing.by_sag ? K_SSAG : K_STENSION);
    } else {
        fprintf(fp, "; no stringing condition\n");
    }

    fprintf(fp, "\n[conductor]\n");
    if (sc->conductor.name[0]) {
        fprintf(fp, "; a row of conductors.csv; the keys below override it\n");
        fprintf(fp, "name = %s\n", sc->conductor.name);
    }
    for (int k = K_DIAM; k <= K_ZETA; k++) put_key(fp, sc, k);
    for (int k = K_CRTS; k <= K_CMOD; k++) /* 0: not known, not printed (0 is out of range) */
        if (*(const double *)((const char *)sc + scn_keys[k].off) > 0) put_key(fp, sc, k);

    fprintf(fp, "\n[ice]\n");
    if (sc->ice.present) {
        if (sc->ice.thickness > 0) {
            put_key(fp, sc, K_ITHICK);
            put_key(fp, sc, K_IDENS);
            fprintf(fp, "; mass_per_length = %.6g kg/m, iced diameter = %.6g m (from the thickness)\n",
                    sc->ice.mass_per_length, sc->ice.diameter);
        } else {
            put_key(fp, sc, K_IMASS);
        }
        put_key(fp, sc, K_IECC);
        put_key(fp, sc, K_IPOLAR);
        if (sc->ice.shape[0]) {
            fprintf(fp, "; a table of data/aero: %s\n", sc->ice.aero_table);
            fprintf(fp, "shape = %s\n", sc->ice.shape);
        } else if (sc->ice.aero_table[0]) {
            fprintf(fp, "; CSV alpha_deg,cd,cl,cm\n");
            fprintf(fp, "aero_table = %s\n", sc->ice.aero_table);
        }
        put_key(fp, sc, K_IANGLE);
    } else {
        fprintf(fp, "; no ice\n");
    }
}

/* height, terrain, basic speed (the mean speed then a comment), length scale, vertical component */
static void print_wind_standards(const gal_scene *sc, FILE *fp)
{
    if (sc->wind.height > 0) put_key(fp, sc, K_HEIGHT);
    int t = sc->wind.terrain;
    if (t >= GAL_TERRAIN_0 && t <= GAL_TERRAIN_IV) {
        fprintf(fp, "terrain = %s ; %s\n", scn_terrain_names[t], scn_keys[K_TERRAIN].unit);
        fprintf(fp, "; z0 = %g m, z_min = %g m (EN 1991-1-4 Table 4.1)\n",
                sc->wind.roughness_length, sc->wind.min_height);
    } else if (sc->wind.roughness_length > 0) {
        put_key(fp, sc, K_Z0);
    }
    if (sc->wind.basic_speed > 0) put_key(fp, sc, K_VB);
    if (sc->wind.length_scale > 0) put_key(fp, sc, K_LSCALE);
    fprintf(fp, "vertical_turbulence = %s ; off | on\n", sc->wind.vertical_turbulence ? "on" : "off");
    if (!sc->wind.vertical_turbulence) return;
    put_key(fp, sc, K_VINTENS);
    put_key(fp, sc, K_VCOH);
    if (sc->wind.vertical_length_scale > 0) put_key(fp, sc, K_VLSCALE);
}

static void print_wind_effects(const gal_scene *sc, FILE *fp)
{
    fprintf(fp, "\n[wind]\n");
    if (sc->wind.basic_speed > 0) /* the mean speed follows from it */
        fprintf(fp, "; speed = %.6g m/s: v_m = c_r(height) basic_speed\n", sc->wind.speed);
    else
        put_key(fp, sc, K_SPEED);
    put_key(fp, sc, K_YAW); /* degrees that read back to the same radians */
    put_key(fp, sc, K_RHO);
    int t = sc->wind.turbulence;
    fprintf(fp, "turbulence = %s ; %s\n", scn_turb_names[t >= 0 && t <= 4 ? t : 0], scn_keys[K_TURB].unit);
    put_key(fp, sc, K_INTENS);
    put_key(fp, sc, K_COH);
    fprintf(fp, "seed = %ld ; integer\n", sc->wind.seed);
    print_wind_standards(sc, fp);

    fprintf(fp, "\n[effects]\n");
    for (int i = 0; i < GAL_FX_COUNT; i++)
        fprintf(fp, "%s = %s\n", gal_effect_names[i], sc->effect[i] ? "on" : "off");
}

static void print_model_simulation_output(const gal_scene *sc, FILE *fp)
{
    char nb[40];
    fprintf(fp, "\n[model]\n");
    fprintf(fp, "elements = %d ; count\n", sc->model.elements);
    fprintf(fp, "modes_vertical = %d ; count\n", sc->model.modes_vertical);
    fprintf(fp, "modes_horizontal = %d ; count\n", sc->model.modes_horizontal);
    fprintf(fp, "modes_torsional = %d ; count\n", sc->model.modes_torsional);
    fprintf(fp, "reduced = %s ; %s\n", scn_reduced_names[0], scn_keys[K_REDUCED].unit);
    put_key(fp, sc, K_RESTOL);
    fprintf(fp, "on_invalid = %s ; stop | warn\n", scn_on_invalid_names[sc->model.on_invalid_warn ? 1 : 0]);

    fprintf(fp, "\n[simulation]\n");
    put_key(fp, sc, K_DUR);
    put_key(fp, sc, K_DT);
    fprintf(fp, "probes = ");
    for (int i = 0; i < sc->simulation.nprobes && i < GAL_MAX_PROBES; i++)
        fprintf(fp, "%s%s", i ? ", " : "", scn_fmt_num(sc->simulation.probes[i], nb, sizeof nb));
    fprintf(fp, " ; %s\n", scn_keys[K_PROBES].unit);
    put_key(fp, sc, K_RAMP);
    put_key(fp, sc, K_REVERSE);
    put_key(fp, sc, K_OUTDT);
    put_key(fp, sc, K_RHOINF);
    put_key(fp, sc, K_NEWTONTOL);
    fprintf(fp, "start = %s ; rest | mean_wind\n", scn_start_names[sc->simulation.start_mean_wind ? 1 : 0]);

    fprintf(fp, "\n[stability]\n");
    put_key(fp, sc, K_SPMIN);
    put_key(fp, sc, K_SPMAX);
    put_key(fp, sc, K_SPSTEP);

    fprintf(fp, "\n[output]\n");
    fprintf(fp, "; path\n");
    fprintf(fp, "directory = %s\n", sc->output.directory);
    if (sc->output.nneighbours > 0) {
        char nb[64];
        fprintf(fp, "; %s\nneighbour_phases = ", scn_keys[K_NEIGHBOURS].unit);
        for (int i = 0; i < sc->output.nneighbours; i++)
            for (int c = 0; c < 2; c++)
                fprintf(fp, "%s%s", i + c ? ", " : "", scn_fmt_num(sc->output.neighbour[i][c], nb, sizeof nb));
        fputc('\n', fp);
    }
}

/* [bundle], only for a bundle (its keys are refused with one sub-conductor). */
static void print_bundle(const gal_scene *sc, FILE *fp)
{
    if (sc->bundle.subconductors <= 1) return;
    fprintf(fp, "\n[bundle]\n");
    fprintf(fp, "subconductors = %d ; count\n", sc->bundle.subconductors);
    put_key(fp, sc, K_BSEP);
    if (sc->bundle.nspacer_positions) {
        fprintf(fp, "spacer_positions = ");
        for (int i = 0; i < sc->bundle.nspacer_positions; i++)
            fprintf(fp, "%s%.15g", i ? ", " : "", sc->bundle.spacer_positions[i]);
        fprintf(fp, " ; fractions of the span\n");
    } else {
        fprintf(fp, "spacers = %d ; count\n", sc->bundle.spacers);
    }
    put_key(fp, sc, K_BORIENT);
    put_key(fp, sc, K_BSMASS);
    put_key(fp, sc, K_BSINERTIA);
    if (sc->bundle.explicit_model) put_key(fp, sc, K_BWAKE); /* the explicit model's alone */
    if (sc->bundle.spacer_stiffness > 0) put_key(fp, sc, K_BSSTIFF); /* flexible spacers alone */
    fprintf(fp, "model = %s ; equivalent | explicit\n",
            scn_bundle_model_names[sc->bundle.explicit_model ? 1 : 0]);
    fprintf(fp, "; radius of the bundle circle: %.6g m\n", sc->bundle.radius);
}

void gal_scene_print(const gal_scene *sc, FILE *fp)
{
    char b[GAL_PATH_MAX];
    fprintf(fp, "# gallop scene \"%s\", resolved from %s\n", printable(sc->name, b, 256),
            printable(sc->path, b + 256, sizeof b - 256));
    fprintf(fp, "# every key with its value in use; units in the comments (SI, angles in deg)\n");
    print_span_conductor_ice(sc, fp);
    print_wind_effects(sc, fp);
    print_model_simulation_output(sc, fp);
    print_bundle(sc, fp);
}
