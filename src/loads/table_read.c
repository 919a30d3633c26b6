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

int gal_aero_table_read(const char *path, gal_aero_table **out)
{
    *out = NULL;
    if (!path) return gal_error(GAL_EINPUT, "aerodynamic table: no path");
    FILE *fp = fopen(path, "r");
    if (!fp)
        return gal_error(GAL_EIO, "%s: cannot open the aerodynamic table: %s", path,
                         strerror(errno));
    reader r = {0};
    char *buf = NULL;
    size_t cap = 0;
    ssize_t len;
    int lineno = 0, header = 0, st = GAL_OK;

    while ((len = getline(&buf, &cap, fp)) >= 0) {
        lineno++;
        if ((size_t)len != strlen(buf)) {
            st = gal_error(GAL_EINPUT, "%s:%d:%zu: NUL byte in the file (a CSV text file "
                           "alpha_deg,cd,cl,cm is expected)", path, lineno, strlen(buf) + 1);
            goto done;
        }
        while (len > 0 && (buf[len - 1] == '\n' || buf[len - 1] == '\r')) buf[--len] = '\0';
        const char *s = skip_space(buf);
        if (*s == '\0') continue;
        if (*s == '#') {
            const char *c = skip_space(s + 1);
            if (!header && strncmp(c, "source:", 7) == 0) {
                c = skip_space(c + 7);
                if (*c == '\0') {
                    st = gal_error(GAL_EINPUT, "%s:%d:%d: empty '# source:' line: say where the "
                                   "numbers come from", path, lineno, (int)(c - buf) + 1);
                    goto done;
                }
                if (add_source(&r, c)) goto nomem;
            }
            continue;
        }
        if (!header) {
            if (!is_header(s)) {
                st = gal_error(GAL_EINPUT, "%s:%d:%d: expected the header line "
                               "'alpha_deg,cd,cl,cm' (after the '# source:' comment lines)",
                               path, lineno, (int)(s - buf) + 1);
                goto done;
            }
            if (!r.source) {
                st = gal_error(GAL_EINPUT, "%s:%d:1: no '# source:' comment line before the "
                               "header: every table must say where its numbers come from",
                               path, lineno);
                goto done;
            }
            header = 1;
            continue;
        }
        /* ---- a data row: exactly 4 numbers separated by commas ---- */
        if (r.rows >= MAX_ROWS) {
            st = gal_error(GAL_EINPUT, "%s:%d:1: more than %d rows", path, lineno, MAX_ROWS);
            goto done;
        }
        if (reader_grow(&r)) goto nomem;
        const char *p = buf;
        for (int i = 0; i < 4; i++) {
            p = skip_space(p);
            int column = (int)(p - buf) + 1;
            r.col[4 * r.rows + i] = column;
            if (*p == '\0' || *p == ',') {
                st = gal_error(GAL_EINPUT, "%s:%d:%d: missing value for column %d (%s): expected "
                               "4 columns alpha_deg,cd,cl,cm", path, lineno, column, i + 1,
                               i ? gal_aero_coef_name[i - 1] : "alpha_deg");
                goto done;
            }
            char *end;
            errno = 0;
            double v = strtod(p, &end);
            const char *e = skip_space(end);
            if (end == p || (*e != ',' && *e != '\0')) {
                st = gal_error(GAL_EINPUT, "%s:%d:%d: column %d (%s) is not a number: a finite "
                               "decimal number is expected", path, lineno, column, i + 1,
                               i ? gal_aero_coef_name[i - 1] : "alpha_deg");
                goto done;
            }
            if (!isfinite(v)) {
                st = gal_error(GAL_EINPUT, "%s:%d:%d: %s = %g is not finite", path, lineno, column,
                               i ? gal_aero_coef_name[i - 1] : "alpha_deg", v);
                goto done;
            }
            r.v[i][r.rows] = v;
            if (i < 3) {
                if (*e != ',') {
                    st = gal_error(GAL_EINPUT, "%s:%d:%d: only %d column%s: expected 4 columns "
                                   "alpha_deg,cd,cl,cm", path, lineno, (int)(e - buf) + 1, i + 1,
                                   i ? "s" : "");
                    goto done;
                }
                p = e + 1;
            } else if (*e != '\0') {
                st = gal_error(GAL_EINPUT, "%s:%d:%d: extra column: expected 4 columns "
                               "alpha_deg,cd,cl,cm", path, lineno, (int)(e - buf) + 1);
                goto done;
            }
        }
        r.line[r.rows++] = lineno;
    }
    if (ferror(fp)) {
        st = gal_error(GAL_EIO, "%s: read error", path);
        goto done;
    }
    if (!header) {
        st = gal_error(GAL_EINPUT, "%s:%d: no header line 'alpha_deg,cd,cl,cm' (and no data)",
                       path, lineno);
        goto done;
    }
    *out = gal_aero_table_build(path, r.source, r.rows, r.v[0], r.v[1], r.v[2], r.v[3], r.line, r.col, &st);
    goto done;
nomem:
    st = gal_error(GAL_ENOMEM, "%s: out of memory reading the aerodynamic table", path);
done:
    free(buf);
    fclose(fp);
    reader_free(&r);
    return st;
}

