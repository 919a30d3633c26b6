/* scene.c: scene files (DESIGN.md "Scene files"). The INI syntax is inih's, fed by a line reader
 * of ours that counts lines (Debian's inih has no INI_HANDLER_LINENO), so that every message
 * names FILE:LINE. Each value is converted and range-checked when it is read; conductor rows come
 * from a CSV table; defaults, cross-checks and effects follow; gal_scene_print writes it back. */
#define _XOPEN_SOURCE 700 /* realpath */
#include "gallop/scene/scene.h"
#include "gallop/loads/aero.h"
#include "gallop/base/core.h"

#include <ini.h>

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#define DEG (GAL_PI / 180.0) /* rad per degree */
#define VALMAX (GAL_PATH_MAX + 64)            /* longest value kept for messages */
#define FILEMAX (4L << 20)                    /* largest scene or table file read, bytes */

const char *const gal_effect_names[GAL_FX_COUNT] = {
    "gravity", "extension", "bending", "torsion", "ice_eccentricity", "aero_drag",
    "aero_lift", "aero_moment", "aero_damping", "turbulence", "damping"};

/* ---- the keys: one row per key of DESIGN.md's table ---- */

enum { T_NUM, T_INT, T_LONG, T_ENUM, T_NAME, T_PATH, T_DIR, T_FX, T_PROBES };

enum {
    K_LENGTH, K_HDIFF, K_TENSION, K_SAG, K_ULENGTH, K_TWIST,
    K_CNAME, K_DIAM, K_MASS, K_EA, K_EI, K_GJ, K_CPOLAR, K_ZETA,
    K_IMASS, K_IECC, K_IPOLAR, K_ITABLE, K_IANGLE,
    K_SPEED, K_YAW, K_RHO, K_TURB, K_INTENS, K_COH, K_SEED,
    K_FX0, K_FXLAST = K_FX0 + GAL_FX_COUNT - 1,
    K_ELEM, K_MVERT, K_MHOR, K_MTOR, K_IDAMP, K_IDTW,
    K_DUR, K_DT, K_PROBES, K_RAMP, K_REVERSE, K_OUTDT, K_RHOINF, K_TOL, K_START,
    K_DIR, K_COUNT
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

static const char *const twist_names[] = {"clamped", "free", NULL};
static const char *const start_names[] = {"rest", "mean_wind", NULL};
static const char *const turb_names[] = {"none", "kaimal", "davenport", "von_karman", NULL};
static const char *const sections[] = {"span", "conductor", "ice", "wind", "effects",
                                       "model", "simulation", "output", NULL};

#define OFF(m) offsetof(gal_scene, m)
#define NUM(s, k, m, lo, lop, hi, hip, u) {s, k, T_NUM, OFF(m), lo, hi, lop, hip, 1.0, u, NULL}
#define INT(s, k, m, lo, hi) {s, k, T_INT, OFF(m), lo, hi, 0, 0, 1.0, "count", NULL}
#define FX(i) {"effects", NULL, T_FX, i, 0, 1, 0, 0, 1.0, "on | off", NULL}

static const keydef keys[K_COUNT] = {
    NUM("span", "length", span.length, 0, 1, 5000, 0, "m"),
    NUM("span", "height_difference", span.height_difference, -5000, 1, 5000, 1, "m"),
    NUM("span", "horizontal_tension", span.horizontal_tension, 0, 1, 5e6, 0, "N"),
    NUM("span", "sag", span.sag, 0, 1, 2500, 1, "m"),
    NUM("span", "unstretched_length", span.unstretched_length, 0, 1, 10000, 0, "m"),
    {"span", "end_twist", T_ENUM, 0, 0, 0, 0, 0, 1.0, "clamped | free", twist_names},
    {"conductor", "name", T_NAME, 0, 0, 0, 0, 0, 1.0, "a row of conductors.csv", NULL},
    NUM("conductor", "diameter", conductor.diameter, 0, 1, 0.2, 0, "m"),
    NUM("conductor", "mass_per_length", conductor.mass_per_length, 0, 1, 100, 0, "kg/m"),
    NUM("conductor", "axial_stiffness", conductor.axial_stiffness, 0, 1, 1e10, 0, "N"),
    NUM("conductor", "bending_stiffness", conductor.bending_stiffness, 0, 0, 1e6, 0, "N m^2"),
    NUM("conductor", "torsional_stiffness", conductor.torsional_stiffness, 0, 1, 1e6, 0, "N m^2/rad"),
    NUM("conductor", "polar_inertia", conductor.polar_inertia, 0, 1, 10, 0, "kg m^2/m"),
    NUM("conductor", "damping_ratio", conductor.damping_ratio, 0, 0, 1, 1, "-"),
    NUM("ice", "mass_per_length", ice.mass_per_length, 0, 1, 100, 0, "kg/m"),
    NUM("ice", "eccentricity", ice.eccentricity, -0.5, 0, 0.5, 0, "m"),
    NUM("ice", "polar_inertia", ice.polar_inertia, 0, 0, 10, 0, "kg m^2/m"),
    {"ice", "aero_table", T_PATH, 0, 0, 0, 0, 0, 1.0, "CSV alpha_deg,cd,cl,cm", NULL},
    {"ice", "attack_angle", T_NUM, OFF(ice.attack_angle), -180, 180, 0, 0, DEG,
     "deg, angle of attack of a horizontal wind normal to the span on the section at rest", NULL},
    NUM("wind", "speed", wind.speed, 0, 0, 80, 0, "m/s"),
    {"wind", "yaw", T_NUM, OFF(wind.yaw), 0, 180, 0, 0, DEG, "deg, 90 = normal to the span", NULL},
    NUM("wind", "air_density", wind.air_density, 0, 1, 5, 0, "kg/m^3"),
    {"wind", "turbulence", T_ENUM, 0, 0, 0, 0, 0, 1.0, "none | kaimal | davenport | von_karman",
     turb_names},
    NUM("wind", "intensity", wind.intensity, 0, 0, 1, 0, "-, sigma_u / U"),
    NUM("wind", "coherence_decay", wind.coherence_decay, 0, 1, 100, 0, "-, C in exp(-C f dx / U)"),
    {"wind", "seed", T_LONG, OFF(wind.seed), 0, 4294967295.0, 0, 0, 1.0, "integer", NULL},
    FX(0), FX(1), FX(2), FX(3), FX(4), FX(5), FX(6), FX(7), FX(8), FX(9), FX(10),
    INT("model", "elements", model.elements, 4, 200000),
    INT("model", "modes_vertical", model.modes_vertical, 0, 200),
    INT("model", "modes_horizontal", model.modes_horizontal, 0, 200),
    INT("model", "modes_torsional", model.modes_torsional, 0, 200),
    NUM("model", "identification_amplitude", model.identification_amplitude, 0, 0, 100, 0,
        "m, largest translation of the reduced model's identification; 0 = max(1 m, sag)"),
    {"model", "identification_twist", T_NUM, OFF(model.identification_twist), 0, 90, 1, 0, DEG,
     "deg, largest twist of the reduced model's identification", NULL},
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
    NUM("simulation", "tolerance", simulation.tolerance, 0, 1, 0.1, 0, "-, reduced model: relative error per step"),
    {"simulation", "start", T_ENUM, 0, 0, 0, 0, 0, 1.0,
     "rest | mean_wind (rest: the wind ramps in over wind_ramp; mean_wind: from the equilibrium under the mean wind)",
     start_names},
    {"output", "directory", T_DIR, 0, 0, 0, 0, 0, 1.0, "path", NULL},
};

static const char *key_name(int k)
{
    return keys[k].type == T_FX ? gal_effect_names[keys[k].off] : keys[k].key;
}

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

/* Printable, bounded copy of a value for a message. */
static const char *show(const char *v, char *out, size_t n)
{
    size_t i = 0;
    for (; v[i] && i + 4 < n && i < 80; i++)
        out[i] = (v[i] >= 0x20 && v[i] < 0x7f) ? v[i] : '?';
    if (v[i]) out[i++] = '.', out[i++] = '.', out[i++] = '.';
    out[i] = '\0';
    return out;
}

/* Record the first error: "FILE:LINE: " (line > 0), "--set: " (line < 0), "FILE: " (line 0),
 * then the message. Returns 0 so that an inih handler can return it. */
static int fail(pstate *ps, int status, int line, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
static int fail(pstate *ps, int status, int line, const char *fmt, ...)
{
    if (ps->status) return 0;
    int n;
    if (line > 0) n = snprintf(ps->msg, sizeof ps->msg, "%s:%d: ", ps->file, line);
    else if (line < 0) n = snprintf(ps->msg, sizeof ps->msg, "--set: ");
    else n = snprintf(ps->msg, sizeof ps->msg, "%s: ", ps->file);
    if (n < 0 || (size_t)n >= sizeof ps->msg) n = 0;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(ps->msg + n, sizeof ps->msg - (size_t)n, fmt, ap);
    va_end(ap);
    ps->status = status;
    ps->err_line = line;
    return 0;
}

/* Shortest of %.15g..%.17g that reads back exactly. */
static const char *fmt_num(double x, char *buf, size_t n)
{
    for (int p = 15; p <= 17; p++) {
        snprintf(buf, n, "%.*g", p, x);
        if (strtod(buf, NULL) == x) break;
    }
    return buf;
}

/* A decimal number, whole string, finite, representable. */
static int parse_num(const char *s, double *x)
{
    if (!*s) return 0;
    for (const char *p = s; *p; p++)
        if (!strchr("0123456789+-.eE", *p)) return 0;
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || *end || errno == ERANGE || !isfinite(v)) return 0;
    *x = v;
    return 1;
}

static int parse_long(const char *s, long *x)
{
    const char *p = s;
    if (*p == '+' || *p == '-') p++;
    if (!*p) return 0;
    for (; *p; p++)
        if (*p < '0' || *p > '9') return 0;
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (*end || errno == ERANGE) return 0;
    *x = v;
    return 1;
}

static int in_range(const keydef *k, double v)
{
    return (k->lo_open ? v > k->lo : v >= k->lo) && (k->hi_open ? v < k->hi : v <= k->hi);
}

/* "0 < length <= 5000 m" */
static const char *range_text(int kid, char *buf, size_t n)
{
    const keydef *k = &keys[kid];
    char lo[32], hi[32];
    fmt_num(k->lo, lo, sizeof lo);
    fmt_num(k->hi, hi, sizeof hi);
    snprintf(buf, n, "%s %s %s %s %s%s%s", lo, k->lo_open ? "<" : "<=", key_name(kid),
             k->hi_open ? "<" : "<=", hi, k->type == T_NUM ? " " : "",
             k->type == T_NUM ? k->unit : "");
    return buf;
}

static int find_section(const char *s)
{
    for (int i = 0; sections[i]; i++)
        if (!strcmp(s, sections[i])) return i;
    return -1;
}

static int find_key(const char *sec, const char *key)
{
    for (int k = 0; k < K_COUNT; k++)
        if (!strcmp(keys[k].sec, sec) && !strcmp(key_name(k), key)) return k;
    return -1;
}

/* "length, height_difference, ..." for a section */
static const char *key_list(const char *sec, char *buf, size_t n)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int k = 0; k < K_COUNT; k++) {
        if (strcmp(keys[k].sec, sec)) continue;
        int w = snprintf(buf + used, n - used, "%s%s", used ? ", " : "", key_name(k));
        if (w < 0 || (size_t)w >= n - used) break;
        used += (size_t)w;
    }
    return buf;
}

static const char *section_list(void)
{
    return "span, conductor, ice, wind, effects, model, simulation, output";
}

/* Text values: printable, no ';' (it would start a comment when printed back). */
static int text_ok(const char *v)
{
    if (!*v) return 0;
    for (const char *p = v; *p; p++)
        if ((unsigned char)*p < 0x20 || *p == 0x7f || *p == ';') return 0;
    return 1;
}

static int is_spec(int k) { return k == K_TENSION || k == K_SAG || k == K_ULENGTH; }

/* ---- one key = value: convert, check, store ---- */

static int apply(pstate *ps, int k, const char *v, int line)
{
    gal_scene *sc = ps->sc;
    const keydef *kd = &keys[k];
    const char *kn = key_name(k);
    char sv[128], rt[160];
    show(v, sv, sizeof sv);

    switch (kd->type) {
    case T_NUM: {
        double x;
        if (!parse_num(v, &x))
            return fail(ps, GAL_EINPUT, line, "[%s] %s = %s: not a number; allowed: %s", kd->sec,
                        kn, sv, range_text(k, rt, sizeof rt));
        if (!in_range(kd, x))
            return fail(ps, GAL_EINPUT, line, "[%s] %s = %s: out of range; allowed: %s", kd->sec,
                        kn, sv, range_text(k, rt, sizeof rt));
        *(double *)((char *)sc + kd->off) = x * kd->scale;
        break;
    }
    case T_INT:
    case T_LONG: {
        long x;
        if (!parse_long(v, &x))
            return fail(ps, GAL_EINPUT, line, "[%s] %s = %s: not an integer; allowed: %s",
                        kd->sec, kn, sv, range_text(k, rt, sizeof rt));
        if (!in_range(kd, (double)x))
            return fail(ps, GAL_EINPUT, line, "[%s] %s = %s: out of range; allowed: %s", kd->sec,
                        kn, sv, range_text(k, rt, sizeof rt));
        if (kd->type == T_INT) *(int *)((char *)sc + kd->off) = (int)x;
        else sc->wind.seed = x;
        break;
    }
    case T_ENUM: {
        int i = 0;
        while (kd->names[i] && strcasecmp(v, kd->names[i])) i++;
        if (!kd->names[i])
            return fail(ps, GAL_EINPUT, line, "[%s] %s = %s: unknown value; allowed: %s", kd->sec,
                        kn, sv, kd->unit);
        if (k == K_TWIST) sc->span.end_twist = i ? GAL_TWIST_FREE : GAL_TWIST_CLAMPED;
        else if (k == K_START) sc->simulation.start_mean_wind = i;
        else
            sc->wind.turbulence = i == 1 ? GAL_TURB_KAIMAL
                                  : i == 2 ? GAL_TURB_DAVENPORT
                                  : i == 3 ? GAL_TURB_VON_KARMAN
                                           : GAL_TURB_NONE;
        break;
    }
    case T_NAME:
        if (!text_ok(v) || strchr(v, ',') || strlen(v) >= sizeof sc->conductor.name)
            return fail(ps, GAL_EINPUT, line,
                        "[%s] %s = %s: not a conductor name; allowed: 1 to %zu printable "
                        "characters without ',' or ';'",
                        kd->sec, kn, sv, sizeof sc->conductor.name - 1);
        strcpy(sc->conductor.name, v);
        break;
    case T_DIR:
        if (!text_ok(v) || strlen(v) >= sizeof sc->output.directory)
            return fail(ps, GAL_EINPUT, line,
                        "[%s] %s = %s: not a usable path; allowed: 1 to %d printable characters "
                        "without ';'",
                        kd->sec, kn, sv, GAL_PATH_MAX - 1);
        strcpy(sc->output.directory, v);
        break;
    case T_PATH: {
        /* relative to the scene's directory (file) or to the current directory (--set) */
        char joined[2 * GAL_PATH_MAX + 2], real[PATH_MAX];
        if (!text_ok(v) || strlen(v) >= GAL_PATH_MAX)
            return fail(ps, GAL_EINPUT, line,
                        "[%s] %s = %s: not a usable path; allowed: 1 to %d printable characters "
                        "without ';'",
                        kd->sec, kn, sv, GAL_PATH_MAX - 1);
        if (v[0] == '/' || line < 0) snprintf(joined, sizeof joined, "%s", v);
        else snprintf(joined, sizeof joined, "%s/%s", ps->dir, v);
        if (access(joined, R_OK) != 0 || !realpath(joined, real))
            return fail(ps, GAL_EINPUT, line,
                        "[%s] %s = %s: cannot read %s: %s; allowed: a readable CSV file (a "
                        "relative path is taken from the scene's directory)",
                        kd->sec, kn, sv, show(joined, rt, sizeof rt), strerror(errno));
        if (!text_ok(real) || strlen(real) >= sizeof sc->ice.aero_table)
            return fail(ps, GAL_EINPUT, line,
                        "[%s] %s = %s: resolved path too long or unprintable; allowed: at most "
                        "%d printable characters",
                        kd->sec, kn, sv, GAL_PATH_MAX - 1);
        struct stat fst;
        if (stat(real, &fst) != 0 || !S_ISREG(fst.st_mode))
            return fail(ps, GAL_EINPUT, line,
                        "[%s] %s = %s: %s is not a regular file; allowed: a readable CSV file",
                        kd->sec, kn, sv, show(real, rt, sizeof rt));
        /* read it now, whatever the command: a bad table is bad input before any output */
        gal_aero_table *tab = NULL;
        int tst = gal_aero_table_read(real, &tab);
        gal_aero_table_free(tab);
        if (tst != GAL_OK)
            return fail(ps, tst == GAL_ENOMEM ? GAL_ENOMEM : GAL_EINPUT, line,
                        "[%s] %s = %s: %s; allowed: a CSV table '# source: ...', "
                        "'alpha_deg,cd,cl,cm', rows of 4 finite numbers, angles increasing over "
                        "one period",
                        kd->sec, kn, sv, gal_error_message());
        strcpy(sc->ice.aero_table, real);
        break;
    }
    case T_FX: {
        static const char *const on[] = {"on", "true", "yes", "1"};
        static const char *const off[] = {"off", "false", "no", "0"};
        int val = -1;
        for (int i = 0; i < 4; i++) {
            if (!strcasecmp(v, on[i])) val = 1;
            if (!strcasecmp(v, off[i])) val = 0;
        }
        if (val < 0)
            return fail(ps, GAL_EINPUT, line,
                        "[%s] %s = %s: not on or off; allowed: on, off (or true/false, yes/no, 1/0)",
                        kd->sec, kn, sv);
        ps->fx[kd->off] = val;
        break;
    }
    case T_PROBES: {
        double p[GAL_MAX_PROBES];
        int np = 0;
        const char *s = v;
        const char *allowed = "a comma list of 1 to %d fractions of the span, each 0 < p < 1";
        char al[128];
        snprintf(al, sizeof al, allowed, GAL_MAX_PROBES);
        for (;;) {
            const char *c = strchr(s, ',');
            size_t n = c ? (size_t)(c - s) : strlen(s);
            char item[64];
            while (n && (*s == ' ' || *s == '\t')) s++, n--;
            while (n && (s[n - 1] == ' ' || s[n - 1] == '\t')) n--;
            if (np == GAL_MAX_PROBES)
                return fail(ps, GAL_EINPUT, line, "[%s] %s = %s: too many probes; allowed: %s",
                            kd->sec, kn, sv, al);
            if (n == 0 || n >= sizeof item)
                return fail(ps, GAL_EINPUT, line, "[%s] %s = %s: empty or bad item; allowed: %s",
                            kd->sec, kn, sv, al);
            memcpy(item, s, n);
            item[n] = '\0';
            if (!parse_num(item, &p[np]))
                return fail(ps, GAL_EINPUT, line, "[%s] %s = %s: '%s' is not a number; allowed: %s",
                            kd->sec, kn, sv, item, al);
            if (!(p[np] > 0 && p[np] < 1))
                return fail(ps, GAL_EINPUT, line, "[%s] %s = %s: %s is out of range; allowed: %s",
                            kd->sec, kn, sv, item, al);
            np++;
            if (!c) break;
            s = c + 1;
        }
        memcpy(sc->simulation.probes, p, sizeof p[0] * (size_t)np);
        sc->simulation.nprobes = np;
        break;
    }
    }
    ps->given[k] = line;
    snprintf(ps->raw[k], VALMAX, "%s", v);
    return 1;
}

/* ---- inih callbacks ---- */

static int handler(void *user, const char *section, const char *name, const char *value)
{
    pstate *ps = user;
    char sv[128], sn[128], ss[128], list[512];
    if (ps->status) return 1; /* already failed: the reader stops at the next line */
    show(value, sv, sizeof sv);
    show(name, sn, sizeof sn);
    show(section, ss, sizeof ss);
    if (!*section)
        return fail(ps, GAL_EINPUT, ps->line,
                    "%s = %s: key outside any section; allowed: keys after a [section] line", sn,
                    sv);
    if (find_section(section) < 0)
        return fail(ps, GAL_EINPUT, ps->line, "[%s]: unknown section; allowed: %s", ss,
                    section_list());
    int k = find_key(section, name);
    if (k < 0)
        return fail(ps, GAL_EINPUT, ps->line, "[%s] %s = %s: unknown key; allowed: %s", ss, sn,
                    sv, key_list(section, list, sizeof list));
    if (ps->seen[k])
        return fail(ps, GAL_EINPUT, ps->line,
                    "[%s] %s = %s: duplicate key (first given at line %d); allowed: each key once",
                    ss, sn, sv, ps->seen[k]);
    ps->seen[k] = ps->line;
    if (ps->over[k]) return 1; /* replaced by a --set: not even checked */
    return apply(ps, k, value, ps->line);
}

/* A section header line (starts with '['): check its name here, since inih only reports keys. */
static void check_section(pstate *ps, const char *s)
{
    const char *e = strchr(s, ']');
    char name[64], sv[128];
    if (!e) return; /* inih reports it as malformed */
    size_t n = (size_t)(e - s - 1);
    const char *t = e + 1;
    while (*t == ' ' || *t == '\t' || *t == '\r') t++;
    if (*t && *t != '\n' && *t != ';' && *t != '#') {
        fail(ps, GAL_EINPUT, ps->line, "%s: text after the section header; allowed: [section] "
             "and an optional comment", show(s, sv, sizeof sv));
        return;
    }
    if (n >= sizeof name) n = sizeof name - 1;
    memcpy(name, s + 1, n);
    name[n] = '\0';
    if (find_section(name) < 0)
        fail(ps, GAL_EINPUT, ps->line, "[%s]: unknown section; allowed: %s",
             show(name, sv, sizeof sv), section_list());
}

/* fgets-like reader over the file in memory: one line per call (so inih's line count is ours),
 * leading blanks removed (inih would take an indented line for a continuation of the previous
 * value), no NUL bytes, no line longer than inih's buffer. */
static char *reader(char *str, int num, void *stream)
{
    pstate *ps = stream;
    if (ps->status || ps->pos >= ps->len) return NULL;
    const char *s = ps->buf + ps->pos;
    size_t rem = ps->len - ps->pos;
    const char *nl = memchr(s, '\n', rem);
    size_t n = nl ? (size_t)(nl - s) : rem, i = 0;
    ps->pos += n + (nl ? 1 : 0);
    ps->line++;
    if (memchr(s, '\0', n)) {
        fail(ps, GAL_EINPUT, ps->line,
             "malformed line: contains a NUL byte; allowed: text lines [section], key = value, "
             "or a comment");
        return NULL;
    }
    if (ps->line == 1 && n >= 3 && !memcmp(s, "\xEF\xBB\xBF", 3)) i = 3; /* UTF-8 BOM */
    while (i < n && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r' || s[i] == '\v' || s[i] == '\f'))
        i++;
    if (n - i + 2 > (size_t)num) {
        fail(ps, GAL_EINPUT, ps->line, "malformed line: %zu characters long; allowed: at most %d",
             n - i, num - 2);
        return NULL;
    }
    memcpy(str, s + i, n - i);
    str[n - i] = '\n';
    str[n - i + 1] = '\0';
    if (str[0] == '[') check_section(ps, str);
    return str;
}

/* ---- the conductor table ---- */

static const char *const csv_cols[] = {
    "name", "diameter_m", "mass_per_length_kg_m", "axial_stiffness_n", "bending_stiffness_n_m2",
    "torsional_stiffness_n_m2_rad", "polar_inertia_kg_m2_m", "source"};
static const int csv_keys[7] = {-1, K_DIAM, K_MASS, K_EA, K_EI, K_GJ, K_CPOLAR};

/* The whole of a small file; NULL with errno set. Appends a '\0'. */
static char *slurp(const char *path, size_t *len)
{
    FILE *fp = fopen(path, "rb");
    if (!fp) return NULL;
    size_t cap = 4096, n = 0;
    char *buf = malloc(cap);
    while (buf) {
        if (n + 1 >= cap) {
            if (cap >= (size_t)FILEMAX) {
                free(buf), buf = NULL, errno = EFBIG;
                break;
            }
            char *nb = realloc(buf, cap * 2);
            if (!nb) {
                free(buf), buf = NULL, errno = ENOMEM;
                break;
            }
            buf = nb, cap *= 2;
        }
        size_t r = fread(buf + n, 1, cap - 1 - n, fp);
        n += r;
        if (r == 0) {
            if (ferror(fp)) {
                int e = errno ? errno : EIO;
                free(buf), buf = NULL, errno = e;
            }
            break;
        }
    }
    fclose(fp);
    if (buf) buf[n] = '\0', *len = n;
    return buf;
}

static char *trim(char *s)
{
    while (*s == ' ' || *s == '\t') s++;
    size_t n = strlen(s);
    while (n && (s[n - 1] == ' ' || s[n - 1] == '\t' || s[n - 1] == '\r')) s[--n] = '\0';
    return s;
}

/* Find `want` in the CSV table `csv` and fill the conductor keys the scene did not give. Every
 * row is checked, so that a broken table is found whichever row is asked for. */
static int load_conductor(pstate *ps, const char *csv)
{
    gal_scene *sc = ps->sc;
    int nl = ps->given[K_CNAME];
    char sv[128], sc_[128], list[512] = "";
    size_t len, listn = 0;
    char *buf = slurp(csv, &len);
    show(sc->conductor.name, sv, sizeof sv);
    show(csv, sc_, sizeof sc_);
    if (!buf)
        return fail(ps, errno == ENOMEM ? GAL_ENOMEM : GAL_EIO, nl,
                    "[conductor] name = %s: cannot read the conductor table %s: %s; allowed: a "
                    "readable CSV file (GALLOP_DATA names its directory)",
                    sv, sc_, strerror(errno));
    if (memchr(buf, '\0', len)) {
        free(buf);
        ps->file = csv;
        return fail(ps, GAL_EINPUT, 0, "contains a NUL byte; allowed: a text CSV file");
    }
    int line = 0, header = 0, found = 0;
    double row[7] = {0};
    char *start = len >= 3 && !memcmp(buf, "\xEF\xBB\xBF", 3) ? buf + 3 : buf; /* UTF-8 BOM */
    for (char *l = start, *next; l; l = next) {
        next = strchr(l, '\n');
        if (next) *next++ = '\0';
        line++;
        char *t = trim(l);
        if (!*t || *t == '#') continue;
        /* split into 8 fields: the 7 first commas, the source is the rest */
        char *f[8];
        int nf = 0;
        f[nf++] = t;
        for (char *p = t; *p && nf < 8; p++)
            if (*p == ',') *p = '\0', f[nf++] = p + 1;
        for (int i = 0; i < nf; i++) f[i] = trim(f[i]);
        if (!header) {
            int ok = nf == 8;
            for (int i = 0; ok && i < 8; i++) ok = !strcmp(f[i], csv_cols[i]);
            if (!ok) {
                free(buf);
                ps->file = csv;
                return fail(ps, GAL_EINPUT, line,
                            "not the conductor table header; allowed: name,diameter_m,"
                            "mass_per_length_kg_m,axial_stiffness_n,bending_stiffness_n_m2,"
                            "torsional_stiffness_n_m2_rad,polar_inertia_kg_m2_m,source");
            }
            header = 1;
            continue;
        }
        char sn[128], sf[128], rt[160];
        show(f[0], sn, sizeof sn);
        if (nf != 8 || !*f[0]) {
            free(buf);
            ps->file = csv;
            return fail(ps, GAL_EINPUT, line,
                        "row %s: %d fields; allowed: 8 fields, the first a non-empty name", sn, nf);
        }
        double v[7];
        for (int i = 1; i < 7; i++) {
            int k = csv_keys[i];
            int isnum = parse_num(f[i], &v[i]);
            if (!isnum || !in_range(&keys[k], v[i])) {
                show(f[i], sf, sizeof sf);
                free(buf);
                ps->file = csv;
                return fail(ps, GAL_EINPUT, line, "row %s: %s = %s: %s; allowed: %s", sn,
                            csv_cols[i], sf, isnum ? "out of range" : "not a number",
                            range_text(k, rt, sizeof rt));
            }
        }
        int w = snprintf(list + listn, sizeof list - listn, "%s%s", listn ? ", " : "", sn);
        if (w > 0 && (size_t)w < sizeof list - listn) listn += (size_t)w;
        if (!strcasecmp(f[0], sc->conductor.name)) {
            if (found) {
                free(buf);
                ps->file = csv;
                return fail(ps, GAL_EINPUT, line, "row %s: a second row of this name (first at "
                            "line %d); allowed: one row per name", sn, found);
            }
            found = line;
            memcpy(row, v, sizeof v);
            if (text_ok(f[0]) && strlen(f[0]) < sizeof sc->conductor.name)
                strcpy(sc->conductor.name, f[0]); /* the table's spelling */
        }
    }
    free(buf);
    if (!header) {
        ps->file = csv;
        return fail(ps, GAL_EINPUT, line, "no header line; allowed: a CSV table with the header "
                    "name,diameter_m,...,source");
    }
    if (!found)
        return fail(ps, GAL_EINPUT, nl, "[conductor] name = %s: not in %s; allowed: %s", sv, sc_,
                    listn ? list : "(the table has no rows)");
    for (int i = 1; i < 7; i++) {
        int k = csv_keys[i];
        if (!ps->given[k]) *(double *)((char *)sc + keys[k].off) = row[i];
    }
    return 1;
}

/* The table conductor.name refers to: given, $GALLOP_DATA/conductors.csv,
 * ./data/conductors.csv, or <scene dir>/../conductors.csv. */
static void conductor_table(const pstate *ps, const char *given, char *out, size_t n)
{
    const char *env = getenv("GALLOP_DATA");
    if (given) snprintf(out, n, "%s", given);
    else if (env && *env) snprintf(out, n, "%s/conductors.csv", env);
    else if (access("data/conductors.csv", R_OK) == 0) snprintf(out, n, "data/conductors.csv");
    else snprintf(out, n, "%s/../conductors.csv", ps->dir);
}

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

/* An error about key k as it was given (file line or --set). */
#define KFAIL(k, what, ...)                                                                     \
    fail(ps, GAL_EINPUT, ps->given[k], "[%s] %s = %s: " what, keys[k].sec, key_name(k),         \
         show(ps->raw[k], sv, sizeof sv), __VA_ARGS__)

static int finish(pstate *ps, const char *csv_given)
{
    gal_scene *sc = ps->sc;
    char sv[128], rt[160];

    if (ps->given[K_CNAME]) {
        char csv[2 * GAL_PATH_MAX + 32];
        conductor_table(ps, csv_given, csv, sizeof csv);
        if (!load_conductor(ps, csv)) return 0;
    }

    /* required keys */
    if (!ps->given[K_LENGTH])
        return fail(ps, GAL_EINPUT, 0, "[span] length: missing; allowed: %s (required)",
                    range_text(K_LENGTH, rt, sizeof rt));
    int nspec = !!ps->given[K_TENSION] + !!ps->given[K_SAG] + !!ps->given[K_ULENGTH];
    if (nspec == 0)
        return fail(ps, GAL_EINPUT, 0, "[span] horizontal_tension / sag / unstretched_length: "
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
                             key_name(k), where);
            if (w > 0 && (size_t)w < sizeof list - used) used += (size_t)w;
            /* report at the one given last: a --set, else the highest line */
            if (last < 0 || (ps->given[last] > 0 && (ps->given[k] < 0 || ps->given[k] > ps->given[last])))
                last = k;
        }
        return KFAIL(last, "%s given; allowed: exactly one of horizontal_tension, sag, "
                     "unstretched_length", list);
    }
    sc->span.spec = ps->given[K_TENSION] ? GAL_SPEC_TENSION
                    : ps->given[K_SAG]   ? GAL_SPEC_SAG
                                         : GAL_SPEC_LENGTH;
    static const int required[] = {K_DIAM, K_MASS, K_EA, K_EI, K_GJ};
    for (size_t i = 0; i < sizeof required / sizeof required[0]; i++) {
        int k = required[i];
        if (!ps->given[k] && !ps->given[K_CNAME])
            return fail(ps, GAL_EINPUT, 0, "[conductor] %s: missing; allowed: %s (required: "
                        "give it, or name a row of the conductor table)", key_name(k),
                        range_text(k, rt, sizeof rt));
    }

    /* cross-checks of the span */
    double L = sc->span.length, h = sc->span.height_difference;
    double chord = sqrt(L * L + h * h);
    if (ps->given[K_HDIFF] && !(fabs(h) < L))
        return KFAIL(K_HDIFF, "steeper than 45 degrees; allowed: |height_difference| < length "
                     "(%g m)", L);
    if (sc->span.spec == GAL_SPEC_SAG && !(sc->span.sag < L / 2))
        return KFAIL(K_SAG, "too deep; allowed: 0 < sag < length / 2 (%g m)", L / 2);
    if (sc->span.spec == GAL_SPEC_LENGTH &&
        !(sc->span.unstretched_length > chord && sc->span.unstretched_length <= 2 * chord))
        return KFAIL(K_ULENGTH, "out of range; allowed: chord < unstretched_length <= 2 chord, "
                     "chord = sqrt(length^2 + height_difference^2) = %.6g m", chord);

    /* conductor and ice defaults */
    if (!ps->given[K_CPOLAR] && !ps->given[K_CNAME]) /* a table row has its own */
        sc->conductor.polar_inertia =
            sc->conductor.mass_per_length * sc->conductor.diameter * sc->conductor.diameter / 8;
    sc->ice.present = ps->given[K_IMASS] != 0;
    if (!sc->ice.present) {
        for (int k = K_IECC; k <= K_IANGLE; k++)
            if (ps->given[k])
                return KFAIL(k, "ice without a mass; allowed: together with [ice] "
                             "mass_per_length%s", "");
    } else if (!ps->given[K_IPOLAR]) {
        /* the ice mass at the eccentricity plus a thin ring on the conductor surface */
        double r = sc->conductor.diameter / 2, e = sc->ice.eccentricity;
        sc->ice.polar_inertia = sc->ice.mass_per_length * (r * r + e * e);
    }

    /* wind and simulation */
    if (sc->wind.turbulence != GAL_TURB_NONE && !(sc->wind.speed > 0))
        return KFAIL(K_TURB, "turbulence needs a mean wind; allowed: none, or [wind] speed > 0%s",
                     "");
    if (sc->simulation.time_step > sc->simulation.duration)
        return KFAIL(K_DT, "longer than the duration; allowed: 0 <= time_step <= duration (%g s)",
                     sc->simulation.duration);
    if (!sc->output.directory[0])
        snprintf(sc->output.directory, sizeof sc->output.directory, "out/%s", sc->name);

    /* effects: on where the scene has the data; an explicit "on" without it is an error */
    for (int i = 0; i < GAL_FX_COUNT; i++) {
        const char *miss = fx_missing(sc, i);
        if (ps->fx[i] == 1 && miss)
            return KFAIL(K_FX0 + i, "the scene lacks its data: %s; allowed: off, or give the data",
                         miss);
        sc->effect[i] = ps->fx[i] >= 0 ? ps->fx[i] : !miss;
    }
    return 1;
}

/* ---- the public functions ---- */

static void defaults(gal_scene *sc)
{
    memset(sc, 0, sizeof *sc);
    sc->span.end_twist = GAL_TWIST_CLAMPED;
    sc->wind.yaw = 90 * DEG;
    sc->wind.air_density = 1.225;
    sc->wind.turbulence = GAL_TURB_NONE;
    sc->wind.intensity = 0.1;
    sc->wind.coherence_decay = 10;
    sc->wind.seed = 1;
    sc->model.elements = 100;
    sc->model.modes_vertical = 3;
    sc->model.modes_horizontal = 2;
    sc->model.modes_torsional = 2;
    sc->simulation.duration = 60;
    sc->simulation.time_step = 0;
    sc->simulation.wind_ramp = 10;
    sc->simulation.wind_reverse_time = 0;
    sc->simulation.output_interval = 0;
    sc->simulation.rho_inf = 0.9;
    sc->simulation.tolerance = 1e-6;
    sc->model.identification_amplitude = 0;
    sc->model.identification_twist = 30 * DEG;
    sc->simulation.nprobes = 1;
    sc->simulation.probes[0] = 0.5;
}

/* The key a --set names, or -1 (apply_override then says what is wrong). */
static int override_key(const char *o)
{
    char buf[256];
    const char *eq = strchr(o, '=');
    if (!eq || (size_t)(eq - o) >= sizeof buf) return -1;
    memcpy(buf, o, (size_t)(eq - o));
    buf[eq - o] = '\0';
    char *dot = strchr(buf, '.');
    if (!dot) return -1;
    *dot = '\0';
    return find_key(trim(buf), trim(dot + 1));
}

/* "section.key=value" from the command line */
static int apply_override(pstate *ps, const char *o)
{
    char buf[VALMAX + 256], sv[128], list[512];
    if (strlen(o) >= sizeof buf)
        return fail(ps, GAL_EINPUT, -1, "%s: too long; allowed: at most %zu characters",
                    show(o, sv, sizeof sv), sizeof buf - 1);
    strcpy(buf, o);
    char *eq = strchr(buf, '=');
    char *dot = eq ? memchr(buf, '.', (size_t)(eq - buf)) : NULL;
    if (!eq || !dot)
        return fail(ps, GAL_EINPUT, -1, "%s: malformed override; allowed: section.key=value",
                    show(o, sv, sizeof sv));
    *eq = *dot = '\0';
    char *sec = trim(buf), *key = trim(dot + 1), *val = trim(eq + 1);
    char ss[64], sk[64];
    show(sec, ss, sizeof ss);
    show(key, sk, sizeof sk);
    if (find_section(sec) < 0)
        return fail(ps, GAL_EINPUT, -1, "[%s] %s = %s: unknown section; allowed: %s", ss, sk,
                    show(val, sv, sizeof sv), section_list());
    int k = find_key(sec, key);
    if (k < 0)
        return fail(ps, GAL_EINPUT, -1, "[%s] %s = %s: unknown key; allowed: %s", ss, sk,
                    show(val, sv, sizeof sv), key_list(sec, list, sizeof list));
    return apply(ps, k, val, -1);
}

int gal_scene_load(gal_scene *sc, const char *path, const char *const *overrides, int n,
                   const char *conductors_csv)
{
    if (!sc || !path) return gal_error(GAL_EINPUT, "gal_scene_load: no scene given");
    defaults(sc);
    if (!*path || strlen(path) >= sizeof sc->path)
        return gal_error(GAL_EINPUT, "%.64s...: scene path empty or too long; allowed: 1 to %d "
                         "characters", path, GAL_PATH_MAX - 1);
    pstate *ps = calloc(1, sizeof *ps);
    if (!ps) return gal_error(GAL_ENOMEM, "%s: out of memory", path);
    ps->sc = sc;
    ps->file = path;
    for (int i = 0; i < GAL_FX_COUNT; i++) ps->fx[i] = -1;
    strcpy(sc->path, path);

    /* name: the file name without directory and .ini; dir: the rest */
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    size_t bl = strlen(base);
    if (bl > 4 && !strcmp(base + bl - 4, ".ini")) bl -= 4;
    if (bl >= sizeof sc->name) bl = sizeof sc->name - 1;
    memcpy(sc->name, base, bl);
    sc->name[bl] = '\0';
    if (!slash) strcpy(ps->dir, ".");
    else if (slash == path) strcpy(ps->dir, "/");
    else snprintf(ps->dir, sizeof ps->dir, "%.*s", (int)(slash - path), path);

    int st = GAL_OK;
    size_t len = 0;
    char *buf = slurp(path, &len);
    if (!buf) {
        int e = errno;
        st = gal_error(e == ENOMEM ? GAL_ENOMEM : e == EFBIG ? GAL_EINPUT : GAL_EIO,
                       "%s: cannot read the scene: %s", path,
                       e == EFBIG ? "larger than 4 MiB" : strerror(e));
        free(ps);
        return st;
    }
    ps->buf = buf;
    ps->len = len;
    /* keys that a --set replaces; a --set of one of tension / sag / unstretched length replaces
     * the file's choice of specification */
    for (int i = 0; overrides && i < n; i++) {
        int k = overrides[i] ? override_key(overrides[i]) : -1;
        if (k < 0) continue;
        ps->over[k] = 1;
        if (is_spec(k)) ps->over[K_TENSION] = ps->over[K_SAG] = ps->over[K_ULENGTH] = 1;
    }
    int r = ini_parse_stream(reader, ps, handler, ps);
    if (r == -2) fail(ps, GAL_ENOMEM, 0, "out of memory");
    else if (r > 0 && (!ps->status || r < ps->err_line)) {
        /* inih's own complaint: a line that is neither [section], key = value nor a comment */
        const char *s = buf;
        for (int i = 1; i < r && s; i++) {
            s = memchr(s, '\n', len - (size_t)(s - buf));
            if (s) s++;
        }
        char text[128] = "";
        if (s) {
            size_t m = strcspn(s, "\n");
            char tmp[128];
            if (m >= sizeof tmp) m = sizeof tmp - 1;
            memcpy(tmp, s, m);
            tmp[m] = '\0';
            show(tmp, text, sizeof text);
        }
        ps->status = 0;
        fail(ps, GAL_EINPUT, r, "\"%s\": malformed line; allowed: [section], key = value, or a "
             "comment starting with ; or #", text);
    }
    for (int i = 0; !ps->status && overrides && i < n; i++)
        if (overrides[i]) apply_override(ps, overrides[i]);
    if (!ps->status) finish(ps, conductors_csv);
    if (ps->status) st = gal_error(ps->status, "%s", ps->msg);
    free(buf);
    free(ps);
    return st;
}

/* ---- printing ---- */

static void put_num(FILE *fp, const char *key, double v, const char *unit)
{
    char b[40];
    fprintf(fp, "%s = %s ; %s\n", key, fmt_num(v, b, sizeof b), unit);
}

/* A key in its file unit, with the digits that read back to the same SI value. */
static void put_key(FILE *fp, const gal_scene *sc, int k)
{
    const keydef *kd = &keys[k];
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

void gal_scene_print(const gal_scene *sc, FILE *fp)
{
    char b[GAL_PATH_MAX], nb[40];
    fprintf(fp, "# gallop scene \"%s\", resolved from %s\n", printable(sc->name, b, 256),
            printable(sc->path, b + 256, sizeof b - 256));
    fprintf(fp, "# every key with its value in use; units in the comments (SI, angles in deg)\n");

    fprintf(fp, "\n[span]\n");
    put_key(fp, sc, K_LENGTH);
    put_key(fp, sc, K_HDIFF);
    put_key(fp, sc, sc->span.spec == GAL_SPEC_TENSION ? K_TENSION
                    : sc->span.spec == GAL_SPEC_SAG   ? K_SAG
                                                      : K_ULENGTH);
    fprintf(fp, "end_twist = %s ; clamped | free\n",
            sc->span.end_twist == GAL_TWIST_FREE ? "free" : "clamped");

    fprintf(fp, "\n[conductor]\n");
    if (sc->conductor.name[0]) {
        fprintf(fp, "; a row of conductors.csv; the keys below override it\n");
        fprintf(fp, "name = %s\n", sc->conductor.name);
    }
    for (int k = K_DIAM; k <= K_ZETA; k++) put_key(fp, sc, k);

    fprintf(fp, "\n[ice]\n");
    if (sc->ice.present) {
        for (int k = K_IMASS; k <= K_IPOLAR; k++) put_key(fp, sc, k);
        if (sc->ice.aero_table[0]) {
            fprintf(fp, "; CSV alpha_deg,cd,cl,cm\n");
            fprintf(fp, "aero_table = %s\n", sc->ice.aero_table);
        }
        put_key(fp, sc, K_IANGLE);
    } else {
        fprintf(fp, "; no ice\n");
    }

    fprintf(fp, "\n[wind]\n");
    put_key(fp, sc, K_SPEED);
    /* degrees that read back to the same radians */
    for (int p = 15; p <= 17; p++) {
        snprintf(nb, sizeof nb, "%.*g", p, sc->wind.yaw / DEG);
        if (strtod(nb, NULL) * DEG == sc->wind.yaw) break;
    }
    fprintf(fp, "yaw = %s ; %s\n", nb, keys[K_YAW].unit);
    put_key(fp, sc, K_RHO);
    int t = sc->wind.turbulence;
    fprintf(fp, "turbulence = %s ; %s\n", turb_names[t >= 0 && t <= 3 ? t : 0], keys[K_TURB].unit);
    put_key(fp, sc, K_INTENS);
    put_key(fp, sc, K_COH);
    fprintf(fp, "seed = %ld ; integer\n", sc->wind.seed);

    fprintf(fp, "\n[effects]\n");
    for (int i = 0; i < GAL_FX_COUNT; i++)
        fprintf(fp, "%s = %s\n", gal_effect_names[i], sc->effect[i] ? "on" : "off");

    fprintf(fp, "\n[model]\n");
    fprintf(fp, "elements = %d ; count\n", sc->model.elements);
    fprintf(fp, "modes_vertical = %d ; count\n", sc->model.modes_vertical);
    fprintf(fp, "modes_horizontal = %d ; count\n", sc->model.modes_horizontal);
    fprintf(fp, "modes_torsional = %d ; count\n", sc->model.modes_torsional);
    put_key(fp, sc, K_IDAMP);
    put_key(fp, sc, K_IDTW);

    fprintf(fp, "\n[simulation]\n");
    put_key(fp, sc, K_DUR);
    put_key(fp, sc, K_DT);
    fprintf(fp, "probes = ");
    for (int i = 0; i < sc->simulation.nprobes && i < GAL_MAX_PROBES; i++)
        fprintf(fp, "%s%s", i ? ", " : "", fmt_num(sc->simulation.probes[i], nb, sizeof nb));
    fprintf(fp, " ; %s\n", keys[K_PROBES].unit);
    put_key(fp, sc, K_RAMP);
    put_key(fp, sc, K_REVERSE);
    put_key(fp, sc, K_OUTDT);
    put_key(fp, sc, K_RHOINF);
    put_key(fp, sc, K_TOL);
    fprintf(fp, "start = %s ; rest | mean_wind\n", start_names[sc->simulation.start_mean_wind ? 1 : 0]);

    fprintf(fp, "\n[output]\n");
    fprintf(fp, "; path\n");
    fprintf(fp, "directory = %s\n", sc->output.directory);
}
