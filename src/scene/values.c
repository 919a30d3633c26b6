/* values.c: one key = value of a scene: the value parsed (numbers, integers, names, paths, on/off,
 * probe lists), range-checked against the key table, stored in SI units. */
#define _XOPEN_SOURCE 700 /* realpath */
#include "scene_impl.h"
#include "gallop/loads/aero.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
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

int scn_apply(pstate *ps, int k, const char *v, int line)
{
    gal_scene *sc = ps->sc;
    const keydef *kd = &scn_keys[k];
    const char *kn = scn_key_name(k);
    char sv[128], rt[160];
    scn_show(v, sv, sizeof sv);

    switch (kd->type) {
    case T_NUM: {
        double x;
        if (!scn_parse_num(v, &x))
            return scn_fail(ps, GAL_EINPUT, line, "[%s] %s = %s: not a number; allowed: %s", kd->sec,
                        kn, sv, scn_range_text(k, rt, sizeof rt));
        if (!scn_in_range(kd, x))
            return scn_fail(ps, GAL_EINPUT, line, "[%s] %s = %s: out of range; allowed: %s", kd->sec,
                        kn, sv, scn_range_text(k, rt, sizeof rt));
        *(double *)((char *)sc + kd->off) = x * kd->scale;
        break;
    }
    case T_INT:
    case T_LONG: {
        long x;
        if (!parse_long(v, &x))
            return scn_fail(ps, GAL_EINPUT, line, "[%s] %s = %s: not an integer; allowed: %s",
                        kd->sec, kn, sv, scn_range_text(k, rt, sizeof rt));
        if (!scn_in_range(kd, (double)x))
            return scn_fail(ps, GAL_EINPUT, line, "[%s] %s = %s: out of range; allowed: %s", kd->sec,
                        kn, sv, scn_range_text(k, rt, sizeof rt));
        if (kd->type == T_INT) *(int *)((char *)sc + kd->off) = (int)x;
        else sc->wind.seed = x;
        break;
    }
    case T_ENUM: {
        int i = 0;
        while (kd->names[i] && strcasecmp(v, kd->names[i])) i++;
        if (!kd->names[i])
            return scn_fail(ps, GAL_EINPUT, line, "[%s] %s = %s: unknown value; allowed: %s", kd->sec,
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
        if (!scn_text_ok(v) || strchr(v, ',') || strlen(v) >= sizeof sc->conductor.name)
            return scn_fail(ps, GAL_EINPUT, line,
                        "[%s] %s = %s: not a conductor name; allowed: 1 to %zu printable "
                        "characters without ',' or ';'",
                        kd->sec, kn, sv, sizeof sc->conductor.name - 1);
        strcpy(sc->conductor.name, v);
        break;
    case T_DIR:
        if (!scn_text_ok(v) || strlen(v) >= sizeof sc->output.directory)
            return scn_fail(ps, GAL_EINPUT, line,
                        "[%s] %s = %s: not a usable path; allowed: 1 to %d printable characters "
                        "without ';'",
                        kd->sec, kn, sv, GAL_PATH_MAX - 1);
        strcpy(sc->output.directory, v);
        break;
    case T_PATH: {
        /* relative to the scene's directory (file) or to the current directory (--set) */
        char joined[2 * GAL_PATH_MAX + 2], real[PATH_MAX];
        if (!scn_text_ok(v) || strlen(v) >= GAL_PATH_MAX)
            return scn_fail(ps, GAL_EINPUT, line,
                        "[%s] %s = %s: not a usable path; allowed: 1 to %d printable characters "
                        "without ';'",
                        kd->sec, kn, sv, GAL_PATH_MAX - 1);
        if (v[0] == '/' || line < 0) snprintf(joined, sizeof joined, "%s", v);
        else snprintf(joined, sizeof joined, "%s/%s", ps->dir, v);
        if (access(joined, R_OK) != 0 || !realpath(joined, real))
            return scn_fail(ps, GAL_EINPUT, line,
                        "[%s] %s = %s: cannot read %s: %s; allowed: a readable CSV file (a "
                        "relative path is taken from the scene's directory)",
                        kd->sec, kn, sv, scn_show(joined, rt, sizeof rt), strerror(errno));
        if (!scn_text_ok(real) || strlen(real) >= sizeof sc->ice.aero_table)
            return scn_fail(ps, GAL_EINPUT, line,
                        "[%s] %s = %s: resolved path too long or unprintable; allowed: at most "
                        "%d printable characters",
                        kd->sec, kn, sv, GAL_PATH_MAX - 1);
        struct stat fst;
        if (stat(real, &fst) != 0 || !S_ISREG(fst.st_mode))
            return scn_fail(ps, GAL_EINPUT, line,
                        "[%s] %s = %s: %s is not a regular file; allowed: a readable CSV file",
                        kd->sec, kn, sv, scn_show(real, rt, sizeof rt));
        /* read it now, whatever the command: a bad table is bad input before any output */
        gal_aero_table *tab = NULL;
        int tst = gal_aero_table_read(real, &tab);
        gal_aero_table_free(tab);
        if (tst != GAL_OK)
            return scn_fail(ps, tst == GAL_ENOMEM ? GAL_ENOMEM : GAL_EINPUT, line,
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
            return scn_fail(ps, GAL_EINPUT, line,
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
                return scn_fail(ps, GAL_EINPUT, line, "[%s] %s = %s: too many probes; allowed: %s",
                            kd->sec, kn, sv, al);
            if (n == 0 || n >= sizeof item)
                return scn_fail(ps, GAL_EINPUT, line, "[%s] %s = %s: empty or bad item; allowed: %s",
                            kd->sec, kn, sv, al);
            memcpy(item, s, n);
            item[n] = '\0';
            if (!scn_parse_num(item, &p[np]))
                return scn_fail(ps, GAL_EINPUT, line, "[%s] %s = %s: '%s' is not a number; allowed: %s",
                            kd->sec, kn, sv, item, al);
            if (!(p[np] > 0 && p[np] < 1))
                return scn_fail(ps, GAL_EINPUT, line, "[%s] %s = %s: %s is out of range; allowed: %s",
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
