/* values.c: one key = value of a scene: the value parsed (numbers, integers, names, paths, on/off,
 * probe lists), range-checked against the key table, stored in SI units. */
#define _XOPEN_SOURCE 700 /* realpath */
#include "scene_impl.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

/* Printable, bounded copy of a value for a message. */
const char *scn_show(const char *v, char *out, size_t n)
{
    size_t i = 0;
    for (; v[i] && i + 4 < n && i < 80; i++)
        out[i] = (v[i] >= 0x20 && v[i] < 0x7f) ? v[i] : '?';
    if (v[i]) out[i++] = '.', out[i++] = '.', out[i++] = '.';
    out[i] = '\0';
    return out;
}

/* Shortest of %.15g..%.17g that reads back exactly. */
const char *scn_fmt_num(double x, char *buf, size_t n)
{
    for (int p = 15; p <= 17; p++) {
        snprintf(buf, n, "%.*g", p, x);
        if (strtod(buf, NULL) == x) break;
    }
    return buf;
}

/* A decimal number, whole string, finite, representable. */
int scn_parse_num(const char *s, double *x)
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

int scn_in_range(const keydef *k, double v)
{
    return (k->lo_open ? v > k->lo : v >= k->lo) && (k->hi_open ? v < k->hi : v <= k->hi);
}

/* "0 < length <= 5000 m" */
const char *scn_range_text(int kid, char *buf, size_t n)
{
    const keydef *k = &scn_keys[kid];
    char lo[32], hi[32];
    scn_fmt_num(k->lo, lo, sizeof lo);
    scn_fmt_num(k->hi, hi, sizeof hi);
    snprintf(buf, n, "%s %s %s %s %s%s%s", lo, k->lo_open ? "<" : "<=", scn_key_name(kid),
             k->hi_open ? "<" : "<=", hi, k->type == T_NUM ? " " : "",
             k->type == T_NUM ? k->unit : "");
    return buf;
}

/* Text values: printable, no ';' (it would start a comment when printed back). */
int scn_text_ok(const char *v)
{
    if (!*v) return 0;
    for (const char *p = v; *p; p++)
        if ((unsigned char)*p < 0x20 || *p == 0x7f || *p == ';') return 0;
    return 1;
}

char *scn_trim(char *s)
{
    while (*s == ' ' || *s == '\t') s++;
    size_t n = strlen(s);
    while (n && (s[n - 1] == ' ' || s[n - 1] == '\t' || s[n - 1] == '\r')) s[--n] = '\0';
    return s;
}

/* ---- one key = value: convert, check, store ---- */

/* A value being applied: the key, the text, where it was given (file line, or -1 for --set). */
typedef struct {
    pstate *ps;
    int k, line;
    const char *v;
    char sv[128]; /* the value as shown in messages */
} kv;

/* "[section] key = value: " then the message; returns 0 (scn_fail). */
static int bad(kv *a, int status, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
static int bad(kv *a, int status, const char *fmt, ...)
{
    char what[2048];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return scn_fail(a->ps, status, a->line, "[%s] %s = %s: %s", scn_keys[a->k].sec,
                    scn_key_name(a->k), a->sv, what);
}

static int apply_num(kv *a)
{
    const keydef *kd = &scn_keys[a->k];
    char rt[160];
    double x;
    if (!scn_parse_num(a->v, &x))
        return bad(a, GAL_EINPUT, "not a number; allowed: %s", scn_range_text(a->k, rt, sizeof rt));
    if (!scn_in_range(kd, x))
        return bad(a, GAL_EINPUT, "out of range; allowed: %s", scn_range_text(a->k, rt, sizeof rt));
    *(double *)((char *)a->ps->sc + kd->off) = x * kd->scale;
    return 1;
}

static int apply_int(kv *a)
{
    const keydef *kd = &scn_keys[a->k];
    char rt[160];
    long x;
    if (!parse_long(a->v, &x))
        return bad(a, GAL_EINPUT, "not an integer; allowed: %s", scn_range_text(a->k, rt, sizeof rt));
    if (!scn_in_range(kd, (double)x))
        return bad(a, GAL_EINPUT, "out of range; allowed: %s", scn_range_text(a->k, rt, sizeof rt));
    if (kd->type == T_INT) *(int *)((char *)a->ps->sc + kd->off) = (int)x;
    else a->ps->sc->wind.seed = x;
    return 1;
}

static int apply_enum(kv *a)
{
    const keydef *kd = &scn_keys[a->k];
    gal_scene *sc = a->ps->sc;
    int i = 0;
    while (kd->names[i] && strcasecmp(a->v, kd->names[i])) i++;
    if (!kd->names[i] && a->k == K_REDUCED && !strcasecmp(a->v, "identified"))
        return bad(a, GAL_EINPUT, "the identified reduced model (a polynomial fitted once over a fixed range) was "
                   "removed (issue 13); allowed: recomputed, the reduced model, whose self-check "
                   "model.residual_tolerance and model.on_invalid control (or leave the key out)");
    if (!kd->names[i]) return bad(a, GAL_EINPUT, "unknown value; allowed: %s", kd->unit);
    if (a->k == K_TWIST) sc->span.end_twist = i ? GAL_TWIST_FREE : GAL_TWIST_CLAMPED;
    else if (a->k == K_START) sc->simulation.start_mean_wind = i;
    else if (a->k == K_TERRAIN) sc->wind.terrain = (gal_terrain)i;
    else if (a->k == K_VTURB) sc->wind.vertical_turbulence = i;
    else if (a->k == K_REDUCED) (void)i; /* one value: recomputed */
    else if (a->k == K_ONINV) sc->model.on_invalid_warn = i;
    else if (a->k == K_BMODEL) sc->bundle.explicit_model = i;
    else
        sc->wind.turbulence = i == 1 ? GAL_TURB_KAIMAL
                              : i == 2 ? GAL_TURB_DAVENPORT
                              : i == 3 ? GAL_TURB_VON_KARMAN
                              : i == 4 ? GAL_TURB_EN1991
                                       : GAL_TURB_NONE;
    return 1;
}

/* conductor.name (T_NAME) and output.directory (T_DIR): text kept as given */
static int apply_text(kv *a)
{
    gal_scene *sc = a->ps->sc;
    const char *v = a->v;
    if (a->k == K_ISHAPE) {
        if (!scn_text_ok(v) || strpbrk(v, ",/") || strlen(v) >= sizeof sc->ice.shape)
            return bad(a, GAL_EINPUT, "not a table name; allowed: 1 to %zu printable characters "
                       "without ',', '/' or ';'", sizeof sc->ice.shape - 1);
        strcpy(sc->ice.shape, v);
        return 1;
    }
    if (scn_keys[a->k].type == T_NAME) {
        if (!scn_text_ok(v) || strchr(v, ',') || strlen(v) >= sizeof sc->conductor.name)
            return bad(a, GAL_EINPUT, "not a conductor name; allowed: 1 to %zu printable "
                       "characters without ',' or ';'", sizeof sc->conductor.name - 1);
        strcpy(sc->conductor.name, v);
        return 1;
    }
    if (!scn_text_ok(v) || strlen(v) >= sizeof sc->output.directory)
        return bad(a, GAL_EINPUT, "not a usable path; allowed: 1 to %d printable characters "
                   "without ';'", GAL_PATH_MAX - 1);
    strcpy(sc->output.directory, v);
    return 1;
}

/* ice.aero_table: relative to the scene's directory (file) or to the current directory (--set),
 * resolved, a readable regular file */
static int apply_path(kv *a)
{
    gal_scene *sc = a->ps->sc;
    const char *v = a->v;
    char joined[2 * GAL_PATH_MAX + 2], real[PATH_MAX], rt[160];
    if (!scn_text_ok(v) || strlen(v) >= GAL_PATH_MAX)
        return bad(a, GAL_EINPUT, "not a usable path; allowed: 1 to %d printable characters "
                   "without ';'", GAL_PATH_MAX - 1);
    if (v[0] == '/' || a->line < 0) snprintf(joined, sizeof joined, "%s", v);
    else snprintf(joined, sizeof joined, "%s/%s", a->ps->dir, v);
    if (access(joined, R_OK) != 0 || !realpath(joined, real))
        return bad(a, GAL_EINPUT, "cannot read %s: %s; allowed: a readable CSV file (a relative "
                   "path is taken from the scene's directory)",
                   scn_show(joined, rt, sizeof rt), strerror(errno));
    if (!scn_text_ok(real) || strlen(real) >= sizeof sc->ice.aero_table)
        return bad(a, GAL_EINPUT, "resolved path too long or unprintable; allowed: at most %d "
                   "printable characters", GAL_PATH_MAX - 1);
    struct stat fst;
    if (stat(real, &fst) != 0 || !S_ISREG(fst.st_mode))
        return bad(a, GAL_EINPUT, "%s is not a regular file; allowed: a readable CSV file",
                   scn_show(real, rt, sizeof rt));
    /* its contents are read by the model (gal_model_aero_table), which names this line */
    strcpy(sc->ice.aero_table, real);
    sc->ice.aero_table_line = a->line;
    snprintf(sc->ice.aero_table_given, sizeof sc->ice.aero_table_given, "%s", a->sv);
    return 1;
}

static int apply_fx(kv *a)
{
    static const char *const on[] = {"on", "true", "yes", "1"};
    static const char *const off[] = {"off", "false", "no", "0"};
    int val = -1;
    for (int i = 0; i < 4; i++) {
        if (!strcasecmp(a->v, on[i])) val = 1;
        if (!strcasecmp(a->v, off[i])) val = 0;
    }
    if (val < 0)
        return bad(a, GAL_EINPUT, "not on or off; allowed: on, off (or true/false, yes/no, 1/0)");
    a->ps->fx[scn_keys[a->k].off] = val;
    return 1;
}

/* output.neighbour_phases: "y1, z1, y2, z2, ...", m, an even count of numbers in the key's range */
static int apply_pairs(kv *a)
{
    double p[2 * GAL_MAX_NEIGHBOURS];
    int np = 0;
    char buf[VALMAX], al[160];
    snprintf(al, sizeof al, "y1, z1, y2, z2, ...: 1 to %d pairs of offsets in m, each in [%g, %g]",
             GAL_MAX_NEIGHBOURS, scn_keys[a->k].lo, scn_keys[a->k].hi);
    snprintf(buf, sizeof buf, "%s", a->v);
    for (char *save = NULL, *t = strtok_r(buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        while (*t == ' ' || *t == '\t') t++;
        size_t n = strlen(t);
        while (n && (t[n - 1] == ' ' || t[n - 1] == '\t')) t[--n] = '\0';
        if (np == 2 * GAL_MAX_NEIGHBOURS) return bad(a, GAL_EINPUT, "too many numbers; allowed: %s", al);
        if (!scn_parse_num(t, &p[np])) return bad(a, GAL_EINPUT, "'%s' is not a number; allowed: %s", t, al);
        if (!(p[np] >= scn_keys[a->k].lo && p[np] <= scn_keys[a->k].hi))
            return bad(a, GAL_EINPUT, "%s is out of range; allowed: %s", t, al);
        np++;
    }
    if (np == 0 || np % 2) return bad(a, GAL_EINPUT, "%d numbers; allowed: %s", np, al);
    memcpy(a->ps->sc->output.neighbour, p, sizeof p[0] * (size_t)np);
    a->ps->sc->output.nneighbours = np / 2;
    return 1;
}

/* The next item of the comma list at *s into item (blanks around it trimmed); *s moves past it, to
 * NULL after the last. Returns 0 for an empty item or one longer than cap - 1. */
static int list_next(const char **s, char *item, size_t cap)
{
    const char *b = *s, *c = strchr(b, ',');
    size_t n = c ? (size_t)(c - b) : strlen(b);
    *s = c ? c + 1 : NULL;
    while (n && (*b == ' ' || *b == '\t')) b++, n--;
    while (n && (b[n - 1] == ' ' || b[n - 1] == '\t')) n--;
    if (n == 0 || n >= cap) return 0;
    memcpy(item, b, n);
    item[n] = '\0';
    return 1;
}

/* item as a fraction of the span, 0 < x < 1 (note: said after "out of range"); 0 with the message. */
static int fraction_item(kv *a, const char *item, double *x, const char *note, const char *al)
{
    if (!scn_parse_num(item, x)) return bad(a, GAL_EINPUT, "'%s' is not a number; allowed: %s", item, al);
    if (!(*x > 0 && *x < 1)) return bad(a, GAL_EINPUT, "%s is out of range%s; allowed: %s", item, note, al);
    return 1;
}

/* "0.25, 0.5": 1 to GAL_MAX_PROBES fractions of the span */
static int apply_probes(kv *a)
{
    double p[GAL_MAX_PROBES];
    int np = 0;
    const char *s = a->v;
    char al[128];
    snprintf(al, sizeof al, "a comma list of 1 to %d fractions of the span, each 0 < p < 1",
             GAL_MAX_PROBES);
    while (s) {
        char item[64];
        if (np == GAL_MAX_PROBES) return bad(a, GAL_EINPUT, "too many probes; allowed: %s", al);
        if (!list_next(&s, item, sizeof item)) return bad(a, GAL_EINPUT, "empty or bad item; allowed: %s", al);
        if (!fraction_item(a, item, &p[np], "", al)) return 0;
        /* the trace names its columns p<%g of the probe>_...: those must not repeat */
        char me[32], other[32];
        snprintf(me, sizeof me, "%g", p[np]);
        for (int j = 0; j < np; j++) {
            snprintf(other, sizeof other, "%g", p[j]);
            if (!strcmp(me, other))
                return bad(a, GAL_EINPUT, "probe %d (%s) repeats probe %d (%s): the trace's column "
                           "names would repeat; allowed: distinct probes (in their first 6 digits)",
                           np + 1, item, j + 1, other);
        }
        np++;
    }
    memcpy(a->ps->sc->simulation.probes, p, sizeof p[0] * (size_t)np);
    a->ps->sc->simulation.nprobes = np;
    return 1;
}

/* [bundle] spacer_positions: fractions of the span, strictly increasing, in (0, 1); the count
 * becomes [bundle] spacers (finish.c refuses both keys together). */
static int apply_spacer_positions(kv *a)
{
    double *p = a->ps->sc->bundle.spacer_positions;
    int np = 0;
    const char *s = a->v;
    char al[160];
    snprintf(al, sizeof al, "a comma list of 1 to %d fractions of the span, each 0 < p < 1, increasing",
             GAL_MAX_SPACER_POSITIONS);
    while (s) {
        char item[64];
        if (np == GAL_MAX_SPACER_POSITIONS) return bad(a, GAL_EINPUT, "too many positions; allowed: %s", al);
        if (!list_next(&s, item, sizeof item)) return bad(a, GAL_EINPUT, "empty or bad item; allowed: %s", al);
        if (!fraction_item(a, item, &p[np], " (0 and 1 are the supports)", al)) return 0;
        if (np > 0 && !(p[np] > p[np - 1]))
            return bad(a, GAL_EINPUT, "position %d (%s) not after position %d (%g); allowed: %s", np + 1,
                       item, np, p[np - 1], al);
        np++;
    }
    a->ps->sc->bundle.nspacer_positions = np;
    a->ps->sc->bundle.spacers = np;
    return 1;
}

int scn_apply(pstate *ps, int k, const char *v, int line)
{
    kv a = {.ps = ps, .k = k, .line = line, .v = v};
    scn_show(v, a.sv, sizeof a.sv);
    int ok = 0;
    switch (scn_keys[k].type) {
    case T_NUM: ok = apply_num(&a); break;
    case T_INT:
    case T_LONG: ok = apply_int(&a); break;
    case T_ENUM: ok = apply_enum(&a); break;
    case T_NAME:
    case T_DIR: ok = apply_text(&a); break;
    case T_PATH: ok = apply_path(&a); break;
    case T_FX: ok = apply_fx(&a); break;
    case T_PROBES: ok = apply_probes(&a); break;
    case T_PAIRS: ok = apply_pairs(&a); break;
    case T_SPOS: ok = apply_spacer_positions(&a); break;
    }
    if (!ok) return 0;
    ps->given[k] = line;
    snprintf(ps->raw[k], VALMAX, "%s", v);
    return 1;
}
