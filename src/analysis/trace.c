/* trace.c: reading a sampled trace from a CSV file (header of column names, time column, uniform
 * step), with a message naming the file, line and column for every defect. */
#include "gallop/base/core.h"
#include "gallop/analysis/spectrum.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* Fields of one line split at commas, in place; returns the count (may exceed cap). */
static size_t split(char *s, char **f, size_t cap)
{
    size_t k = 0;
    for (char *p = s;;) {
        char *c = strchr(p, ',');
        if (k < cap) f[k] = p;
        k++;
        if (!c) break;
        *c = '\0';
        p = c + 1;
    }
    return k;
}

static char *trim(char *s)
{
    while (isspace((unsigned char)*s)) s++;
    size_t n = strlen(s);
    while (n > 0 && isspace((unsigned char)s[n - 1])) s[--n] = '\0';
    return s;
}

/* 1 when s is a whole number (strtod consumes it all), the value in *v. */
static int parse_num(const char *s, double *v)
{
    char *end;
    if (!*s) return 0;
    errno = 0;
    *v = strtod(s, &end);
    return *end == '\0';
}

static int is_time_name(const char *s)
{
    return !strcasecmp(s, "time") || !strcasecmp(s, "t") || !strcasecmp(s, "time_s");
}

gal_trace *gal_trace_free(gal_trace *tr)
{
    if (!tr) return NULL;
    if (tr->x)
        for (size_t c = 0; c < tr->ncol; c++) free(tr->x[c]);
    if (tr->names)
        for (size_t c = 0; c < tr->ncol; c++) free(tr->names[c]);
    free(tr->x);
    free(tr->names);
    free(tr->time_name);
    free(tr->t);
    free(tr);
    return NULL;
}

int gal_trace_column(const gal_trace *tr, const char *name)
{
    for (size_t c = 0; c < tr->ncol; c++)
        if (!strcmp(tr->names[c], name)) return (int)c;
    return -1;
}

/* ---- the reader ---- */

typedef struct {
    const char *path;
    FILE *fp;
    char *line;           /* getline buffer */
    size_t cap;
    char **hdr;           /* header names (copies), nf */
    char **f;             /* field pointers of the current line, nf */
    size_t nf;            /* fields per line, the time column included */
    double *rows;         /* row-major values, nrow x nf */
    size_t *lineno;       /* source line of each row */
    size_t nrow, rowcap;
} reader;

static void reader_done(reader *r)
{
    if (r->fp) fclose(r->fp);
    free(r->line);
    if (r->hdr)
        for (size_t i = 0; i < r->nf; i++) free(r->hdr[i]);
    free(r->hdr);
    free(r->f);
    free(r->rows);
    free(r->lineno);
}

/* Next line that is not blank and not a comment, trimmed; NULL at the end of the file. */
static char *next_line(reader *r, size_t *lineno)
{
    for (;;) {
        ssize_t len = getline(&r->line, &r->cap, r->fp);
        if (len < 0) return NULL;
        (*lineno)++;
        char *s = trim(r->line);
        if (*s && *s != '#') return s;
    }
}

static int read_header(reader *r, char *s, size_t lineno)
{
    size_t nf = 1;
    for (const char *c = s; *c; c++) nf += *c == ',';
    r->f = calloc(nf, sizeof *r->f);
    r->hdr = calloc(nf, sizeof *r->hdr);
    if (!r->f || !r->hdr) return gal_error(GAL_ENOMEM, "out of memory");
    split(s, r->f, nf);
    r->nf = nf;
    size_t numeric = 0;
    for (size_t i = 0; i < nf; i++) {
        char *name = trim(r->f[i]);
        double v;
        numeric += parse_num(name, &v);
        if (!*name)
            return gal_error(GAL_EINPUT, "%s:%zu: header: column %zu has an empty name", r->path,
                             lineno, i + 1);
        r->hdr[i] = strdup(name);
        if (!r->hdr[i]) return gal_error(GAL_ENOMEM, "out of memory");
        for (size_t j = 0; j < i; j++)
            if (!strcmp(r->hdr[j], name))
                return gal_error(GAL_EINPUT, "%s:%zu: header: column name '%s' appears twice",
                                 r->path, lineno, name);
    }
    if (numeric == nf)
        return gal_error(GAL_EINPUT,
                         "%s:%zu: no header line: the first line holds numbers; it must name the "
                         "columns (e.g. time,probe_y,probe_z)", r->path, lineno);
    if (nf < 2)
        return gal_error(GAL_EINPUT,
                         "%s:%zu: header names %zu column; a time column and at least one data "
                         "column are needed", r->path, lineno, nf);
    return GAL_OK;
}

static int read_row(reader *r, char *s, size_t lineno)
{
    size_t k = split(s, r->f, r->nf);
    if (k != r->nf)
        return gal_error(GAL_EINPUT, "%s:%zu: %zu fields, the header has %zu", r->path, lineno, k,
                         r->nf);
    if (r->nrow == r->rowcap) {
        size_t nc = r->rowcap ? 2 * r->rowcap : 1024;
        double *rows = realloc(r->rows, nc * r->nf * sizeof *rows);
        if (!rows) return gal_error(GAL_ENOMEM, "out of memory reading %s", r->path);
        r->rows = rows;
        size_t *ln = realloc(r->lineno, nc * sizeof *ln);
        if (!ln) return gal_error(GAL_ENOMEM, "out of memory reading %s", r->path);
        r->lineno = ln;
        r->rowcap = nc;
    }
    double *row = r->rows + r->nrow * r->nf;
    for (size_t i = 0; i < r->nf; i++) {
        char *v = trim(r->f[i]);
        if (!*v)
            return gal_error(GAL_EINPUT, "%s:%zu: column '%s' is empty", r->path, lineno,
                             r->hdr[i]);
        if (!parse_num(v, &row[i]))
            return gal_error(GAL_EINPUT, "%s:%zu: column '%s': '%.40s' is not a number", r->path,
                             lineno, r->hdr[i], v);
        if (!isfinite(row[i]))
            return gal_error(GAL_EINPUT, "%s:%zu: column '%s': value '%.40s' is NaN or Inf",
                             r->path, lineno, r->hdr[i], v);
    }
    r->lineno[r->nrow++] = lineno;
    return GAL_OK;
}

/* Build the trace from the rows and check the time axis. */
static int build(reader *r, gal_trace **out)
{
    size_t n = r->nrow, nf = r->nf, it = 0;
    for (size_t i = 0; i < nf; i++)
        if (is_time_name(r->hdr[i])) {
            it = i;
            break;
        }
    if (n < GAL_TRACE_MIN_SAMPLES)
        return gal_error(GAL_EINPUT, "%s: %zu samples, at least %d needed", r->path, n,
                         GAL_TRACE_MIN_SAMPLES);
    /* time: strictly increasing and uniform */
    double dmin = INFINITY, dmax = -INFINITY;
    size_t lmin = 0, lmax = 0;
    for (size_t k = 0; k + 1 < n; k++) {
        double t0 = r->rows[k * nf + it], t1 = r->rows[(k + 1) * nf + it], d = t1 - t0;
        if (!(d > 0))
            return gal_error(GAL_EINPUT,
                             "%s:%zu: time %s = %.17g is not after %.17g on line %zu "
                             "(time must increase)", r->path, r->lineno[k + 1], r->hdr[it], t1,
                             t0, r->lineno[k]);
        if (d < dmin) dmin = d, lmin = r->lineno[k + 1];
        if (d > dmax) dmax = d, lmax = r->lineno[k + 1];
    }
    double dt = (r->rows[(n - 1) * nf + it] - r->rows[it]) / (double)(n - 1);
    if ((dmax - dmin) > GAL_TRACE_DT_SPREAD * dt)
        return gal_error(GAL_EINPUT,
                         "%s: sampling is not uniform: time step from %.9g s (line %zu) to %.9g s "
                         "(line %zu), relative spread %.3g > %g; resample the trace to a uniform "
                         "step", r->path, dmin, lmin, dmax, lmax, (dmax - dmin) / dt,
                         GAL_TRACE_DT_SPREAD);
    gal_trace *tr = calloc(1, sizeof *tr);
    if (!tr) return gal_error(GAL_ENOMEM, "out of memory");
    tr->n = n;
    tr->ncol = nf - 1;
    tr->dt = dt;
    tr->t = malloc(n * sizeof *tr->t);
    tr->x = calloc(tr->ncol, sizeof *tr->x);
    tr->names = calloc(tr->ncol, sizeof *tr->names);
    tr->time_name = strdup(r->hdr[it]);
    int ok = tr->t && tr->x && tr->names && tr->time_name;
    for (size_t i = 0, c = 0; ok && i < nf; i++) {
        if (i == it) continue;
        tr->x[c] = malloc(n * sizeof *tr->x[c]);
        tr->names[c] = strdup(r->hdr[i]);
        ok = tr->x[c] && tr->names[c];
        for (size_t k = 0; ok && k < n; k++) tr->x[c][k] = r->rows[k * nf + i];
        c++;
    }
    if (!ok) {
        gal_trace_free(tr);
        return gal_error(GAL_ENOMEM, "out of memory reading %s", r->path);
    }
    for (size_t k = 0; k < n; k++) tr->t[k] = r->rows[k * nf + it];
    *out = tr;
    return GAL_OK;
}

int gal_trace_read(const char *path, gal_trace **trace)
{
    *trace = NULL;
    reader r = {0};
    r.path = path;
    r.fp = fopen(path, "r");
    if (!r.fp) return gal_error(GAL_EIO, "%s: cannot open: %s", path, strerror(errno));
    size_t lineno = 0;
    int st = GAL_OK;
    char *s = next_line(&r, &lineno);
    if (!s && ferror(r.fp)) st = gal_error(GAL_EIO, "%s: cannot read: %s", path, strerror(errno));
    else if (!s) st = gal_error(GAL_EINPUT, "%s: no header line (the file has no data)", path);
    if (!st) st = read_header(&r, s, lineno);
    while (!st && (s = next_line(&r, &lineno))) st = read_row(&r, s, lineno);
    if (!st && ferror(r.fp)) st = gal_error(GAL_EIO, "%s: read error", path);
    if (!st) st = build(&r, trace);
    reader_done(&r);
    return st;
}
