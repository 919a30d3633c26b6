/* scene_impl.h: what the files of the scene reader share (src/scene/): the key table, the parse
 * state, and the scn_* functions they call each other by. Not a public header. */
#ifndef GALLOP_SCENE_IMPL_H
#define GALLOP_SCENE_IMPL_H

#include "gallop/base/core.h"
#include "gallop/scene/scene.h"

#include <stddef.h>

#define DEG (GAL_PI / 180.0) /* rad per degree */
#define VALMAX (GAL_PATH_MAX + 64)            /* longest value kept for messages */
#define FILEMAX (4L << 20)                    /* largest scene or table file read, bytes */

/* ---- the keys: one row per key of DESIGN.md's table (keys.c) ---- */

enum { T_NUM, T_INT, T_LONG, T_ENUM, T_NAME, T_PATH, T_DIR, T_FX, T_PROBES, T_PAIRS, T_SPOS };

enum {
    K_LENGTH, K_HDIFF, K_TENSION, K_SAG, K_ULENGTH, K_TWIST, K_RTSFRAC, K_TEMP,
    K_STEMP, K_STENSION, K_SSAG,
    K_CNAME, K_DIAM, K_MASS, K_EA, K_EI, K_GJ, K_CPOLAR, K_ZETA, K_CRTS, K_CALPHA, K_CMOD,
    K_IMASS, K_IECC, K_IPOLAR, K_ITABLE, K_IANGLE, K_ITHICK, K_IDENS, K_ISHAPE,
    K_SPEED, K_YAW, K_RHO, K_TURB, K_INTENS, K_COH, K_SEED,
    K_HEIGHT, K_TERRAIN, K_Z0, K_VB, K_LSCALE, K_VTURB, K_VCOH, K_VINTENS, K_VLSCALE,
    K_FX0, K_FXLAST = K_FX0 + GAL_FX_COUNT - 1,
    K_ELEM, K_MVERT, K_MHOR, K_MTOR, K_REDUCED, K_RESTOL, K_ONINV,
    K_DUR, K_DT, K_PROBES, K_RAMP, K_REVERSE, K_OUTDT, K_RHOINF, K_NEWTONTOL, K_START,
    K_SPMIN, K_SPMAX, K_SPSTEP,
    K_DIR, K_NEIGHBOURS,
    K_BSUB, K_BSEP, K_BSPACERS, K_BSPOS, K_BORIENT, K_BSMASS, K_BSINERTIA, K_BWAKE, K_BSSTIFF, K_BMODEL, K_COUNT
};

typedef struct {
    const char *sec, *key;
    int type;
    size_t off;           /* T_NUM, T_INT: offset of the field; T_FX: effect index */
    double lo, hi;        /* allowed range (file units) */
    int lo_open, hi_open; /* 1: that bound is excluded */
    double scale;         /* SI value = file value * scale */
    const char *unit;     /* unit in the file, printed as a comment */
    const char *const *names; /* T_ENUM: the values, NULL-terminated */
} keydef;

extern const keydef scn_keys[K_COUNT];
extern const char *const scn_twist_names[];
extern const char *const scn_start_names[];
extern const char *const scn_reduced_names[];
extern const char *const scn_on_invalid_names[];
extern const char *const scn_turb_names[];
extern const char *const scn_terrain_names[];
extern const char *const scn_onoff_names[];
extern const char *const scn_bundle_model_names[];

const char *scn_key_name(int k);
/* A key that no longer applies: why (what removed it) and what replaced it, else NULL. */
const char *scn_retired_key(const char *sec, const char *key);
int scn_find_section(const char *s);
int scn_find_key(const char *sec, const char *key);
/* "length, height_difference, ..." for a section */
const char *scn_key_list(const char *sec, char *buf, size_t n);
const char *scn_section_list(void);
int scn_is_spec(int k);

/* ---- parse state ---- */

typedef struct {
    gal_scene *sc;
    const char *file;         /* the scene file, for messages */
    char dir[GAL_PATH_MAX];   /* its directory */
    int given[K_COUNT];       /* 0 not given; > 0 its line; -1 from --set */
    char raw[K_COUNT][VALMAX];/* the value as given, for later messages */
    int fx[GAL_FX_COUNT];     /* -1 not given, 0 off, 1 on */
    int seen[K_COUNT];        /* line of the key in the file (duplicates) */
    int over[K_COUNT];        /* a --set gives this key: the file's value is not used */
    int status, err_line;     /* first error: status (0 none) and its line */
    char msg[2048];
    /* the reader */
    const char *buf;
    size_t len, pos;
    int line;
} pstate;

/* ---- values (values.c) ---- */

/* Printable, bounded copy of a value for a message. */
const char *scn_show(const char *v, char *out, size_t n);
/* Shortest of %.15g..%.17g that reads back exactly. */
const char *scn_fmt_num(double x, char *buf, size_t n);
/* A decimal number, whole string, finite, representable. */
int scn_parse_num(const char *s, double *x);
int scn_in_range(const keydef *k, double v);
/* "0 < length <= 5000 m" */
const char *scn_range_text(int kid, char *buf, size_t n);
/* Text values: printable, no ';' (it would start a comment when printed back). */
int scn_text_ok(const char *v);
char *scn_trim(char *s);
/* One key = value: convert, check, store. 1 done, 0 failed (ps->status set). */
int scn_apply(pstate *ps, int k, const char *v, int line);

/* ---- the reader (reader.c) ---- */

/* Record the first error: "FILE:LINE: " (line > 0), "--set: " (line < 0), "FILE: " (line 0),
 * then the message. Returns 0 so that an inih handler can return it. */
int scn_fail(pstate *ps, int status, int line, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
/* The whole of a small file; NULL with errno set. Appends a '\0'. */
char *scn_slurp(const char *path, size_t *len);

/* ---- the conductor table (conductors.c) ---- */

/* Find the scene's conductor.name in the CSV table `csv` and fill the conductor keys the scene
 * did not give. 1 done, 0 failed. */
int scn_load_conductor(pstate *ps, const char *csv);
/* The table conductor.name refers to: given, $GALLOP_DATA/conductors.csv,
 * ./data/conductors.csv, or <scene dir>/../conductors.csv. */
void scn_conductor_table(const pstate *ps, const char *given, char *out, size_t n);

/* ---- after all keys (finish.c) ---- */

/* The table row, required keys, cross-checks, defaults, effects. 1 done, 0 failed. */
int scn_finish(pstate *ps, const char *csv_given);
/* An error about key k as it was given (file line or --set): "[section] key = value: ...". */
int scn_kfail(pstate *ps, int k, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
/* "[section] key" */
const char *scn_sec_key(int k, char *buf, size_t n);

/* ---- the standards' inputs (standards.c) ---- */

/* Ice from a mass or from a thickness and density; a shape names a shipped table. */
int scn_ice(pstate *ps);
/* Wind from height and terrain (EN 1991-1-4): speed, intensity, length scale where not given. */
int scn_wind_profile(pstate *ps);

#endif
