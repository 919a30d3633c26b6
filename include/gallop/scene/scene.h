/* scene.h: a resolved scene (DESIGN.md "Scene files"): every key of every section, in SI units
 * (angles converted to radians), defaults applied, validated. Read from an INI file with inih. */
#ifndef GALLOP_SCENE_H
#define GALLOP_SCENE_H

#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

#define GAL_PATH_MAX 1024
#define GAL_MAX_PROBES 16
#define GAL_MAX_SPACER_POSITIONS 64 /* [bundle] spacer_positions */
#define GAL_BUNDLE_MIN_SUBSPAN 0.005 /* shortest sub-span of spacer_positions, fraction of the span */
#define GAL_SPACER_STIFFNESS_MIN 100.0 /* N/m, [bundle] spacer_stiffness: the softest flexible spacer */
#define GAL_SPACER_STIFFNESS_MAX 1e9   /* N/m, the stiffest (stiffer: use 0, rigid) */
#define GAL_MAX_NEIGHBOURS 8

/* How the equilibrium is specified: exactly one of these ([span] horizontal_tension, sag,
 * unstretched_length, tension_rts, or a [stringing] condition). TENSION_RTS and STRINGING are
 * turned into TENSION or LENGTH by gal_stringing_spec (gallop/model/stringing.h). */
typedef enum {
    GAL_SPEC_TENSION, GAL_SPEC_SAG, GAL_SPEC_LENGTH, GAL_SPEC_TENSION_RTS, GAL_SPEC_STRINGING
} gal_span_spec;

/* EN 1991-1-4 Table 4.1 terrain categories; GAL_TERRAIN_NONE: no terrain given. */
typedef enum {
    GAL_TERRAIN_NONE = -1, GAL_TERRAIN_0, GAL_TERRAIN_I, GAL_TERRAIN_II, GAL_TERRAIN_III,
    GAL_TERRAIN_IV
} gal_terrain;

typedef enum { GAL_TWIST_CLAMPED, GAL_TWIST_FREE } gal_end_twist;

typedef enum {
    GAL_TURB_NONE, GAL_TURB_KAIMAL, GAL_TURB_DAVENPORT, GAL_TURB_VON_KARMAN, GAL_TURB_EN1991
} gal_turbulence;

/* Physical effects that a scene switches on or off ([effects]). */
typedef enum {
    GAL_FX_GRAVITY, GAL_FX_EXTENSION, GAL_FX_BENDING, GAL_FX_TORSION, GAL_FX_ICE_ECCENTRICITY,
    GAL_FX_AERO_DRAG, GAL_FX_AERO_LIFT, GAL_FX_AERO_MOMENT, GAL_FX_AERO_DAMPING,
    GAL_FX_TURBULENCE, GAL_FX_DAMPING, GAL_FX_COUNT
} gal_effect;

typedef struct gal_scene {
    char path[GAL_PATH_MAX];      /* the scene file */
    char name[256];               /* scene name: file name without directory and .ini */

    struct {
        double length;            /* m, horizontal distance between supports, > 0 */
        double height_difference; /* m, right support minus left */
        gal_span_spec spec;       /* which one of the three below was given */
        double horizontal_tension;/* N (spec TENSION) */
        double sag;               /* m, mid-span below the chord (spec SAG) */
        double unstretched_length;/* m (spec LENGTH) */
        double tension_rts;       /* -, horizontal tension over conductor.rated_strength, in the
                                   * load case (spec TENSION_RTS) */
        double temperature;       /* deg C, conductor temperature of the load case (used by a
                                   * [stringing] condition); default: the stringing temperature */
        gal_end_twist end_twist;
    } span;

    struct {                      /* the sag-tension change of state's reference ([stringing]) */
        int present;              /* a stringing condition was given (spec STRINGING) */
        int by_sag;               /* 0: horizontal_tension given, 1: sag given */
        double temperature;       /* deg C, reference (stringing) temperature */
        double horizontal_tension;/* N, bare conductor at that temperature */
        double sag;               /* m, mid-span below the chord, bare, at that temperature */
    } stringing;

    struct {
        char name[128];           /* row of data/conductors.csv, or "" */
        double diameter;          /* m */
        double mass_per_length;   /* kg/m */
        double axial_stiffness;   /* N (EA) */
        double bending_stiffness; /* N m^2 (EI, both axes) */
        double torsional_stiffness; /* N m^2/rad (GJ) */
        double polar_inertia;     /* kg m^2/m (I_theta); default: the table row, else m d^2/8 */
        double damping_ratio;     /* -, modal, all modes */
        double rated_strength;    /* N, rated tensile strength (RTS); 0 = unknown */
        double thermal_expansion; /* 1/K, coefficient of linear expansion; 0 = unknown */
        double final_modulus;     /* Pa, final modulus of the stranded conductor (table; the
                                   * rod uses axial_stiffness); 0 = unknown */
    } conductor;

    struct {
        int present;              /* an [ice] section with a mass or a thickness was given */
        double thickness;         /* m, radial thickness of an equivalent uniform ice sleeve;
                                   * 0 = not given (the mass is given) */
        double density;           /* kg/m^3, of that ice (glaze 900 by default) */
        double diameter;          /* m, iced diameter: conductor.diameter + 2 thickness (0 when
                                   * the ice is given by its mass) */
        char shape[64];           /* the shipped table named by ice.shape, or "" */
        double mass_per_length;   /* kg/m */
        double eccentricity;      /* m, offset of the ice mass centre from the axis */
        double polar_inertia;     /* kg m^2/m, about the conductor axis; default
                                     mass_per_length (diameter^2/4 + eccentricity^2) */
        char aero_table[GAL_PATH_MAX]; /* CSV alpha_deg,cd,cl,cm, resolved path, or ""; the scene
                                   * only checks that it is a readable file: gal_model_aero_table
                                   * (gallop/model/tables.h) reads it */
        int aero_table_line;      /* where aero_table was given: its line in the scene file, -1 a
                                   * --set, 0 not given (for messages about the table) */
        char aero_table_given[128]; /* aero_table as given, printable and shortened, for messages */
        double attack_angle;      /* rad (scene: deg): the section's angle of attack at rest for a
                                   * horizontal wind normal to the span (orientation of the ice) */
    } ice;

    struct {
        double speed;             /* m/s, mean */
        double yaw;               /* rad (scene: deg, 90 = normal to the span) */
        double air_density;       /* kg/m^3 */
        gal_turbulence turbulence;
        double intensity;         /* -, turbulence intensity sigma_u / U */
        double coherence_decay;   /* -, C in exp(-C f dx / U) */
        long seed;
        /* the standards' wind (EN 1991-1-4 as used by EN 50341-1): */
        double height;            /* m, conductor height above ground; 0 = not given (10 m) */
        gal_terrain terrain;      /* roughness category, or GAL_TERRAIN_NONE */
        double roughness_length;  /* m, z0 (the terrain's, or given); 0 = none */
        double min_height;        /* m, z_min of the terrain (z0 given: 1 m) */
        double basic_speed;       /* m/s, v_b (10 m, category II, 10 min); 0 = not given */
        double length_scale;      /* m, turbulence length scale; 0 = the spectrum's default */
        int vertical_turbulence;  /* 1: a vertical component w is generated as well */
        double vertical_coherence_decay; /* -, C_w in exp(-C_w f dx / U); default C of u */
        double vertical_intensity;       /* -, sigma_w / U; default 0.5 intensity (IEC 61400-1) */
        double vertical_length_scale;    /* m, L_w; 0 = the spectrum's (gallop/loads/wind.h) */
    } wind;

    struct {                      /* [bundle]: a phase of several sub-conductors held by spacers;
                                   * each sub-conductor is [conductor] (with its [ice]) and the
                                   * [span] tension and sag are one sub-conductor's */
        int subconductors;        /* 1 (no bundle), 2, 3, 4, 6 or 8 */
        double separation;        /* m, between adjacent sub-conductors on the bundle circle */
        double radius;            /* m, of the bundle circle (from separation; 0 for one) */
        int spacers;              /* count, evenly spaced along the span (or spacer_positions') */
        int nspacer_positions;    /* 0: the spacers are evenly spaced */
        double spacer_positions[GAL_MAX_SPACER_POSITIONS]; /* fractions of the span, increasing */
        double orientation;       /* rad (scene: deg), of the first sub-conductor from horizontal */
        double spacer_mass;       /* kg, of one spacer */
        double spacer_inertia;    /* kg m^2, of one spacer about the bundle axis */
        double wake_factor;       /* -, explicit model: leeward sub-conductors' dynamic pressure factor */
        double spacer_stiffness;  /* N/m, explicit model: a spacer arm's at its clamp; 0: rigid */
        int explicit_model;       /* 1: one rod per sub-conductor; 0: one equivalent rod */
        int model_line;           /* the scene line of [bundle] model (-1: --set, 0: not given) */
    } bundle;

    int effect[GAL_FX_COUNT];     /* 1 on, 0 off */

    struct {
        int elements;             /* count, >= 4 */
        int modes_vertical, modes_horizontal, modes_torsional; /* count per family, >= 0 */
        /* the reduced model (reduced/rom.h, the only one: model.reduced = recomputed) */
        double residual_tolerance;/* -, its self-check's largest relative residual */
        int on_invalid_warn;      /* 1: a run past the tolerance finishes with valid: false */
    } model;

    struct {
        double duration;          /* s */
        double time_step;         /* s; 0 = chosen by gallop */
        int nprobes;
        double probes[GAL_MAX_PROBES]; /* fractions of the span, in (0, 1) */
        double wind_ramp;         /* s: the mean wind rises from 0 over this time */
        double wind_reverse_time; /* s: the wind reverses at this time; 0 = never */
        double output_interval;   /* s; 0 = chosen */
        double rho_inf;           /* -, full model's numerical dissipation (1 = none) */
        double newton_tolerance;  /* -, both models' Newton: residual over the step's force scale */
        int start_mean_wind;      /* 0: from rest, the wind ramped in; 1: from the equilibrium under
                                   * the mean wind, the wind at full speed from the start */
    } simulation;

    struct {
        double speed_min, speed_max, speed_step; /* m/s: the wind speeds of `gallop stability` */
    } stability;

    struct {
        char directory[GAL_PATH_MAX]; /* default out/<scene name> */
        int nneighbours;          /* neighbouring phases (at rest) for the clearances, 0 to 8 */
        double neighbour[GAL_MAX_NEIGHBOURS][2]; /* m: their offsets y (horizontal, downwind), z
                                   * (up) from this conductor's equilibrium at the same point */
    } output;
} gal_scene;

/* The bounds of the sizes computed from [simulation]'s doubles, checked when a scene is loaded
 * (exit 2 with the file, line, key and allowed range):
 *   output_interval: 0 (chosen) or >= GAL_SCENE_MIN_OUTPUT_INTERVAL, and at most
 *                    GAL_SCENE_MAX_SAMPLES samples over the duration;
 *   time_step:       0 (chosen) or >= GAL_SCENE_MIN_TIME_STEP, and at most GAL_SCENE_MAX_STEPS
 *                    steps over the duration;
 *   duration:        at least GAL_SCENE_MIN_SAMPLES samples at the output interval (the measures
 *                    need them); with output_interval = 0 this is checked by
 *                    gal_scene_sample_count once the interval is chosen, before the run. */
#define GAL_SCENE_MIN_OUTPUT_INTERVAL 1e-4 /* s */
#define GAL_SCENE_MIN_TIME_STEP 1e-6       /* s */
#define GAL_SCENE_MAX_SAMPLES 1000000L     /* trace samples of a run */
#define GAL_SCENE_MAX_STEPS 1000000000L    /* integration steps of a run */
#define GAL_SCENE_MIN_SAMPLES 64L          /* trace samples a run's measures need */

/* The number of trace samples of a run of `duration` s (the scene's, or a study's) sampled every
 * dt_out s (floor(duration / dt_out) + 1), into *ns; GAL_EINPUT naming sc's file, [simulation]
 * duration or output_interval and the allowed range when it is below min_samples
 * (GAL_SCENE_MIN_SAMPLES for a run that is measured) or above GAL_SCENE_MAX_SAMPLES (never a
 * cast overflow). */
int gal_scene_sample_count(const gal_scene *sc, double duration, double dt_out, long min_samples,
                           long *ns);

/* Effect names as written in scene files, indexed by gal_effect. */
extern const char *const gal_effect_names[GAL_FX_COUNT];

/* Read and validate a scene. `overrides` holds `n` strings "section.key=value" applied after
 * the file (as if they were in it, reported as "--set"): a key given by --set replaces the file's
 * value, which is then not checked; a --set of one of horizontal_tension / sag /
 * unstretched_length replaces the file's choice among them; a relative ice.aero_table given by
 * --set is taken from the current directory (from the scene's directory in the file).
 * `conductors_csv` is the table that conductor.name refers to (NULL: $GALLOP_DATA/conductors.csv
 * if GALLOP_DATA is set, else the installed data directory's (gallop/base/datadir.h) if it has
 * one, else data/conductors.csv if it exists in the current directory, else
 * conductors.csv in the parent of the scene's directory, since scenes live in data/scenes/).
 * The table is read only when conductor.name is given; the scene's conductor keys override its
 * row. An [ice] aero_table is resolved and must be a readable regular file; its contents are not
 * read here (the scene reader depends on the base alone): gal_model_aero_table reads and checks
 * it, with a message that names the scene file, the line and the key as those below.
 * Returns GAL_OK, or GAL_EINPUT / GAL_EIO (unreadable file) with a message
 * "FILE:LINE: [section] key = value: what is wrong; allowed: range" ("--set: ..." for overrides,
 * "FILE: ..." for a missing key). The ranges are listed in src/scene/keys.c (table `scn_keys`). */
int gal_scene_load(gal_scene *sc, const char *path, const char *const *overrides, int n,
                   const char *conductors_csv);

/* Print the resolved scene as INI (every key, with its unit in a comment). */
void gal_scene_print(const gal_scene *sc, FILE *fp);

#ifdef __cplusplus
}
#endif

#endif
