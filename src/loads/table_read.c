/* table_read.c: the reader of aerodynamic coefficient tables (CSV: "# source:" lines, the header
 * alpha_deg,cd,cl,cm and rows of 4 numbers; include/gallop/loads/aero.h), with messages that name
 * the file, line, column, value and allowed range. */
#define _POSIX_C_SOURCE 200809L
#include "aero_impl.h"
#include "gallop/base/core.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_ROWS 1000000

typedef struct {
    int rows, cap;
    double *v[4];  /* alpha_deg, cd, cl, cm */
    int *line;
    int *col;      /* 4 per row */
    char *source;
    size_t srclen;
} reader;

static void reader_free(reader *r)
{
    for (int i = 0; i < 4; i++) free(r->v[i]);
    free(r->line);
    free(r->col);
    free(r->source);
}

static int reader_grow(reader *r)
{
    if (r->rows < r->cap) return 0;
    int cap = r->cap ? 2 * r->cap : 64;
    for (int i = 0; i < 4; i++) {
        double *p = realloc(r->v[i], cap * sizeof(double));
        if (!p) return -1;
        r->v[i] = p;
    }
    int *l = realloc(r->line, cap * sizeof(int));
    if (!l) return -1;
    r->line = l;
    int *c = realloc(r->col, 4 * cap * sizeof(int));
    if (!c) return -1;
    r->col = c;
    r->cap = cap;
    return 0;
}

static int add_source(reader *r, const char *s)
{
    size_t n = strlen(s);
    char *p = realloc(r->source, r->srclen + n + 3);
    if (!p) return -1;
    r->source = p;
    if (r->srclen) memcpy(p + r->srclen, "; ", 2), r->srclen += 2;
    memcpy(p + r->srclen, s, n + 1);
    r->srclen += n;
    return 0;
}

static const char *skip_space(const char *s)
{
    while (*s == ' ' || *s == '\t') s++;
    return s;
}

/* Is the line (leading space skipped) the header "alpha_deg,cd,cl,cm" (spaces allowed)? */
static int is_header(const char *s)
{
    static const char *const want[4] = {"alpha_deg", "cd", "cl", "cm"};
    for (int i = 0; i < 4; i++) {
        s = skip_space(s);
        size_t n = strlen(want[i]);
        if (strncmp(s, want[i], n) != 0) return 0;
        s = skip_space(s + n);
        if (i < 3) {
            if (*s != ',') return 0;
            s++;
        }
    }
    return *s == '\0';
}

gal_aero_table *gal_aero_table_load(const char *path)
{
    gal_aero_table *t = NULL;
    gal_aero_table_read(path, &t);
    return t;
}

/* A "# ..." line: a "# source:" line before the header adds to the table's source. */
static int comment_line(const char *path, int lineno, const char *buf, const char *s, reader *r,
                        int header)
{
    const char *c = skip_space(s + 1);
    if (header || strncmp(c, "source:", 7) != 0) return GAL_OK;
    c = skip_space(c + 7);
    if (*c == '\0')
        return gal_error(GAL_EINPUT, "%s:%d:%d: empty '# source:' line: say where the numbers come "
                         "from", path, lineno, (int)(c - buf) + 1);
    if (add_source(r, c))
        return gal_error(GAL_ENOMEM, "%s: out of memory reading the aerodynamic table", path);
    return GAL_OK;
}

/* The header line, after the "# source:" lines. */
static int header_line(const char *path, int lineno, const char *buf, const char *s,
                       const reader *r)
{
    if (!is_header(s))
        return gal_error(GAL_EINPUT, "%s:%d:%d: expected the header line 'alpha_deg,cd,cl,cm' "
                         "(after the '# source:' comment lines)", path, lineno, (int)(s - buf) + 1);
    if (!r->source)
        return gal_error(GAL_EINPUT, "%s:%d:1: no '# source:' comment line before the header: every "
                         "table must say where its numbers come from", path, lineno);
    return GAL_OK;
}

/* A data row: exactly 4 numbers separated by commas, appended to r. */
static int data_row(const char *path, int lineno, const char *buf, reader *r)
{
    if (r->rows >= MAX_ROWS)
        return gal_error(GAL_EINPUT, "%s:%d:1: more than %d rows", path, lineno, MAX_ROWS);
    if (reader_grow(r))
        return gal_error(GAL_ENOMEM, "%s: out of memory reading the aerodynamic table", path);
    const char *p = buf;
    for (int i = 0; i < 4; i++) {
        const char *name = i ? gal_aero_coef_name[i - 1] : "alpha_deg";
        p = skip_space(p);
        int column = (int)(p - buf) + 1;
        r->col[4 * r->rows + i] = column;
        if (*p == '\0' || *p == ',')
            return gal_error(GAL_EINPUT, "%s:%d:%d: missing value for column %d (%s): expected 4 "
                             "columns alpha_deg,cd,cl,cm", path, lineno, column, i + 1, name);
        char *end;
        errno = 0;
        double v = strtod(p, &end);
        const char *e = skip_space(end);
        if (end == p || (*e != ',' && *e != '\0'))
            return gal_error(GAL_EINPUT, "%s:%d:%d: column %d (%s) is not a number: a finite "
                             "decimal number is expected", path, lineno, column, i + 1, name);
        if (!isfinite(v))
            return gal_error(GAL_EINPUT, "%s:%d:%d: %s = %g is not finite", path, lineno, column,
                             name, v);
        r->v[i][r->rows] = v;
        if (i < 3 && *e != ',')
            return gal_error(GAL_EINPUT, "%s:%d:%d: only %d column%s: expected 4 columns "
                             "alpha_deg,cd,cl,cm", path, lineno, (int)(e - buf) + 1, i + 1,
                             i ? "s" : "");
        if (i == 3 && *e != '\0')
            return gal_error(GAL_EINPUT, "%s:%d:%d: extra column: expected 4 columns "
                             "alpha_deg,cd,cl,cm", path, lineno, (int)(e - buf) + 1);
        p = e + 1;
    }
    r->line[r->rows++] = lineno;
    return GAL_OK;
}

/* Read the lines of fp into r; *lineno: the last line read. */
static int read_lines(const char *path, FILE *fp, reader *r, int *lineno)
{
    char *buf = NULL;
    size_t cap = 0;
    ssize_t len;
    int header = 0, st = GAL_OK;
    while (st == GAL_OK && (len = getline(&buf, &cap, fp)) >= 0) {
        ++*lineno;
        if ((size_t)len != strlen(buf)) {
            st = gal_error(GAL_EINPUT, "%s:%d:%zu: NUL byte in the file (a CSV text file "
                           "alpha_deg,cd,cl,cm is expected)", path, *lineno, strlen(buf) + 1);
            break;
        }
        while (len > 0 && (buf[len - 1] == '\n' || buf[len - 1] == '\r')) buf[--len] = '\0';
        const char *s = skip_space(buf);
        if (*s == '\0') continue;
        if (*s == '#') st = comment_line(path, *lineno, buf, s, r, header);
        else if (!header) st = header_line(path, *lineno, buf, s, r), header = st == GAL_OK;
        else st = data_row(path, *lineno, buf, r);
    }
    free(buf);
    if (st) return st;
    if (ferror(fp)) return gal_error(GAL_EIO, "%s: read error", path);
    if (!header)
        return gal_error(GAL_EINPUT, "%s:%d: no header line 'alpha_deg,cd,cl,cm' (and no data)",
                         path, *lineno);
    return GAL_OK;
}

int gal_aero_table_read(const char *path, gal_aero_table **out)
{
    *out = NULL;
    if (!path) return gal_error(GAL_EINPUT, "aerodynamic table: no path");
    FILE *fp = fopen(path, "r");
    if (!fp)
        return gal_error(GAL_EIO, "%s: cannot open the aerodynamic table: %s", path,
                         strerror(errno));
    reader r = {0};
    int lineno = 0, st = read_lines(path, fp, &r, &lineno);
    if (st == GAL_OK)
        *out = gal_aero_table_build(path, r.source, r.rows, r.v[0], r.v[1], r.v[2], r.v[3], r.line,
                                    r.col, &st);
    fclose(fp);
    reader_free(&r);
    return st;
}
