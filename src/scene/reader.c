/* reader.c: scene files (DESIGN.md "Scene files"). The INI syntax is inih's, fed by a line reader
 * of ours that counts lines (Debian's inih has no INI_HANDLER_LINENO), so that every message
 * names FILE:LINE; --set overrides are applied after the file. */
#include "scene_impl.h"

#include <ini.h>

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Record the first error: "FILE:LINE: " (line > 0), "--set: " (line < 0), "FILE: " (line 0),
 * then the message. Returns 0 so that an inih handler can return it. */
int scn_fail(pstate *ps, int status, int line, const char *fmt, ...)
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

/* ---- inih callbacks ---- */

static int handler(void *user, const char *section, const char *name, const char *value)
{
    pstate *ps = user;
    char sv[128], sn[128], ss[128], list[512];
    if (ps->status) return 1; /* already failed: the reader stops at the next line */
    scn_show(value, sv, sizeof sv);
    scn_show(name, sn, sizeof sn);
    scn_show(section, ss, sizeof ss);
    if (!*section)
        return scn_fail(ps, GAL_EINPUT, ps->line,
                    "%s = %s: key outside any section; allowed: keys after a [section] line", sn,
                    sv);
    if (scn_find_section(section) < 0)
        return scn_fail(ps, GAL_EINPUT, ps->line, "[%s]: unknown section; allowed: %s", ss,
                    scn_section_list());
    int k = scn_find_key(section, name);
    const char *why = k < 0 ? scn_retired_key(section, name) : NULL;
    if (why)
        return scn_fail(ps, GAL_EINPUT, ps->line, "[%s] %s = %s: no longer a key: %s", ss, sn, sv, why);
    if (k < 0)
        return scn_fail(ps, GAL_EINPUT, ps->line, "[%s] %s = %s: unknown key; allowed: %s", ss, sn,
                    sv, scn_key_list(section, list, sizeof list));
    if (ps->seen[k])
        return scn_fail(ps, GAL_EINPUT, ps->line,
                    "[%s] %s = %s: duplicate key (first given at line %d); allowed: each key once",
                    ss, sn, sv, ps->seen[k]);
    ps->seen[k] = ps->line;
    if (ps->over[k]) return 1; /* replaced by a --set: not even checked */
    return scn_apply(ps, k, value, ps->line);
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
        scn_fail(ps, GAL_EINPUT, ps->line, "%s: text after the section header; allowed: [section] "
             "and an optional comment", scn_show(s, sv, sizeof sv));
        return;
    }
    if (n >= sizeof name) n = sizeof name - 1;
    memcpy(name, s + 1, n);
    name[n] = '\0';
    if (scn_find_section(name) < 0)
        scn_fail(ps, GAL_EINPUT, ps->line, "[%s]: unknown section; allowed: %s",
             scn_show(name, sv, sizeof sv), scn_section_list());
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
        scn_fail(ps, GAL_EINPUT, ps->line,
             "malformed line: contains a NUL byte; allowed: text lines [section], key = value, "
             "or a comment");
        return NULL;
    }
    if (ps->line == 1 && n >= 3 && !memcmp(s, "\xEF\xBB\xBF", 3)) i = 3; /* UTF-8 BOM */
    while (i < n && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r' || s[i] == '\v' || s[i] == '\f'))
        i++;
    if (n - i + 2 > (size_t)num) {
        scn_fail(ps, GAL_EINPUT, ps->line, "malformed line: %zu characters long; allowed: at most %d",
             n - i, num - 2);
        return NULL;
    }
    memcpy(str, s + i, n - i);
    str[n - i] = '\n';
    str[n - i + 1] = '\0';
    if (str[0] == '[') check_section(ps, str);
    return str;
}

/* The whole of a small file; NULL with errno set. Appends a '\0'. */
char *scn_slurp(const char *path, size_t *len)
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
    sc->wind.terrain = GAL_TERRAIN_NONE;
    sc->ice.density = 900; /* glaze */
    sc->bundle.subconductors = 1;
    sc->bundle.wake_factor = 1;
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
    sc->simulation.newton_tolerance = 1e-8;
    sc->stability.speed_min = 0.5; /* analysis/onset.h's GAL_ONSET_SPEED_MIN, _MAX, _STEP */
    sc->stability.speed_max = 20;
    sc->stability.speed_step = 0.25;
    sc->model.residual_tolerance = 0.1;
    sc->model.on_invalid_warn = 0;
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
    return scn_find_key(scn_trim(buf), scn_trim(dot + 1));
}

/* "section.key=value" from the command line */
static int apply_override(pstate *ps, const char *o)
{
    char buf[VALMAX + 256], sv[128], list[512];
    if (strlen(o) >= sizeof buf)
        return scn_fail(ps, GAL_EINPUT, -1, "%s: too long; allowed: at most %zu characters",
                    scn_show(o, sv, sizeof sv), sizeof buf - 1);
    strcpy(buf, o);
    char *eq = strchr(buf, '=');
    char *dot = eq ? memchr(buf, '.', (size_t)(eq - buf)) : NULL;
    if (!eq || !dot)
        return scn_fail(ps, GAL_EINPUT, -1, "%s: malformed override; allowed: section.key=value",
                    scn_show(o, sv, sizeof sv));
    *eq = *dot = '\0';
    char *sec = scn_trim(buf), *key = scn_trim(dot + 1), *val = scn_trim(eq + 1);
    char ss[64], sk[64];
    scn_show(sec, ss, sizeof ss);
    scn_show(key, sk, sizeof sk);
    if (scn_find_section(sec) < 0)
        return scn_fail(ps, GAL_EINPUT, -1, "[%s] %s = %s: unknown section; allowed: %s", ss, sk,
                    scn_show(val, sv, sizeof sv), scn_section_list());
    int k = scn_find_key(sec, key);
    const char *why = k < 0 ? scn_retired_key(sec, key) : NULL;
    if (why)
        return scn_fail(ps, GAL_EINPUT, -1, "[%s] %s = %s: no longer a key: %s", ss, sk,
                        scn_show(val, sv, sizeof sv), why);
    if (k < 0)
        return scn_fail(ps, GAL_EINPUT, -1, "[%s] %s = %s: unknown key; allowed: %s", ss, sk,
                    scn_show(val, sv, sizeof sv), scn_key_list(sec, list, sizeof list));
    return scn_apply(ps, k, val, -1);
}

/* sc->name: the file name without directory and .ini; ps->dir: the rest. */
static void name_and_dir(gal_scene *sc, pstate *ps, const char *path)
{
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
}

/* inih's own complaint about line r: neither [section], key = value nor a comment. */
static void malformed_line(pstate *ps, int r)
{
    const char *buf = ps->buf, *s = buf;
    for (int i = 1; i < r && s; i++) {
        s = memchr(s, '\n', ps->len - (size_t)(s - buf));
        if (s) s++;
    }
    char text[128] = "";
    if (s) {
        size_t m = strcspn(s, "\n");
        char tmp[128];
        if (m >= sizeof tmp) m = sizeof tmp - 1;
        memcpy(tmp, s, m);
        tmp[m] = '\0';
        scn_show(tmp, text, sizeof text);
    }
    ps->status = 0;
    scn_fail(ps, GAL_EINPUT, r, "\"%s\": malformed line; allowed: [section], key = value, or a "
             "comment starting with ; or #", text);
}

/* The file in ps->buf, then the overrides, then the checks after all keys. */
static void parse(pstate *ps, const char *const *overrides, int n, const char *conductors_csv)
{
    /* keys that a --set replaces; a --set of one of tension / sag / unstretched length replaces
     * the file's choice of specification */
    for (int i = 0; overrides && i < n; i++) {
        int k = overrides[i] ? override_key(overrides[i]) : -1;
        if (k < 0) continue;
        ps->over[k] = 1;
        if (scn_is_spec(k))
            for (int j = 0; j < K_COUNT; j++)
                if (scn_is_spec(j)) ps->over[j] = 1;
    }
    int r = ini_parse_stream(reader, ps, handler, ps);
    if (r == -2) scn_fail(ps, GAL_ENOMEM, 0, "out of memory");
    else if (r > 0 && (!ps->status || r < ps->err_line)) malformed_line(ps, r);
    for (int i = 0; !ps->status && overrides && i < n; i++)
        if (overrides[i]) apply_override(ps, overrides[i]);
    if (!ps->status) scn_finish(ps, conductors_csv);
}

int gal_scene_load(gal_scene *sc, const char *path, const char *const *overrides, int n,
                   const char *conductors_csv)
{
    if (!sc || !path) return gal_error(GAL_EINPUT, "gal_scene_load: no scene given");
    gal_gsl_errors_install(); /* GSL errors as gallop errors, never an abort */
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
    name_and_dir(sc, ps, path);

    int st = GAL_OK;
    size_t len = 0;
    char *buf = scn_slurp(path, &len);
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
    parse(ps, overrides, n, conductors_csv);
    if (ps->status) st = gal_error(ps->status, "%s", ps->msg);
    free(buf);
    free(ps);
    return st;
}
