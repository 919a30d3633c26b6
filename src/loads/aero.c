/* aero.c: aerodynamic coefficient tables (CSV, periodic cubic splines) and the quasi-steady load
 * per unit length on a conductor section with its derivative (paper Eq. 10; DESIGN.md
 * "Aerodynamics"; the angle and sign convention is stated in include/gallop/aero.h). */
#define _POSIX_C_SOURCE 200809L
#include "gallop/loads/aero.h"
#include "gallop/base/core.h"
#include "gallop/base/vec3.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_interp.h>

#define DEG (GAL_PI / 180.0)
#define CLOSE_TOL 1e-9      /* periodic closure: last row = first row + 360 within this */
#define MIN_STEP_DEG 1e-6   /* two angles closer than this are treated as duplicates */
#define MAX_ALPHA_DEG 720.0 /* |alpha_deg| allowed */
#define MAX_ROWS 1000000


static const char *const coef_name[3] = {"cd", "cl", "cm"};

/* ------------------------------------------------------------------------------------------ */
/* building a table from rows                                                                  */
/* ------------------------------------------------------------------------------------------ */

static char *dupstr(const char *s)
{
    size_t n = strlen(s) + 1;
    char *p = malloc(n);
    if (p) memcpy(p, s, n);
    return p;
}

gal_aero_table *gal_aero_table_free(gal_aero_table *t)
{
    if (!t) return NULL;
    for (int i = 0; i < 3; i++) {
        if (t->spline[i]) gsl_interp_free(t->spline[i]);
        free(t->c[i]);
    }
    free(t->alpha);
    free(t->path);
    free(t->source);
    free(t);
    return NULL;
}

/* Where a row came from, for messages: "file:line" (line[r] > 0) or "name: row r". */
static void where(char *buf, size_t sz, const char *name, const int *line, int r)
{
    if (line) snprintf(buf, sz, "%s:%d", name, line[r]);
    else snprintf(buf, sz, "%s: row %d", name, r + 1);
}

/* Validate rows (alpha in degrees) and build the splines. `line` (may be NULL) gives the file
 * line of each row for messages; `col` (may be NULL) the column where each of the 4 fields
 * starts, row-major. */
static gal_aero_table *build(const char *name, const char *source, int rows, const double *adeg,
                             const double *cd, const double *cl, const double *cm, const int *line,
                             const int *col, int *status)
{
    *status = GAL_EINPUT;
    char at[1200];
    const double *cv[3] = {cd, cl, cm};
    if (!source || !source[0]) {
        gal_error(GAL_EINPUT, "%s: no '# source:' comment line: every table must say where its "
                  "numbers come from", name);
        return NULL;
    }
    for (int r = 0; r < rows; r++) {
        where(at, sizeof at, name, line, r);
        if (!isfinite(adeg[r]) || fabs(adeg[r]) > MAX_ALPHA_DEG) {
            gal_error(GAL_EINPUT, "%s:%d: alpha_deg = %g out of range: finite, within [-%g, %g]",
                      at, col ? col[4 * r] : 1, adeg[r], MAX_ALPHA_DEG, MAX_ALPHA_DEG);
            return NULL;
        }
        for (int i = 0; i < 3; i++)
            if (!isfinite(cv[i][r]) || fabs(cv[i][r]) > GAL_AERO_MAX_COEF) {
                gal_error(GAL_EINPUT, "%s:%d: %s = %g out of range: finite, within [-%g, %g]", at,
                          col ? col[4 * r + 1 + i] : 2 + i, coef_name[i], cv[i][r],
                          GAL_AERO_MAX_COEF, GAL_AERO_MAX_COEF);
                return NULL;
            }
        if (r > 0 && !(adeg[r] > adeg[r - 1] + MIN_STEP_DEG)) {
            gal_error(GAL_EINPUT, "%s:%d: alpha_deg = %.17g %s the previous row's %.17g: angles must "
                      "be strictly increasing (steps > %g deg)", at, col ? col[4 * r] : 1, adeg[r],
                      fabs(adeg[r] - adeg[r - 1]) <= MIN_STEP_DEG ? "duplicates" : "is below",
                      adeg[r - 1], MIN_STEP_DEG);
            return NULL;
        }
    }
    if (rows < 4) {
        gal_error(GAL_EINPUT, "%s: %d data rows, at least 4 angles are needed", name, rows);
        return NULL;
    }
    /* ---- period: the closure row is given (span 360) or added (span < 360) ---- */
    double span = adeg[rows - 1] - adeg[0];
    int given = 0;
    where(at, sizeof at, name, line, rows - 1);
    if (span > 360.0 + CLOSE_TOL) {
        gal_error(GAL_EINPUT, "%s:%d: alpha_deg = %g: the rows span %g deg, more than one period "
                  "(allowed: less than 360, or exactly 360 with the last row equal to the first)",
                  at, col ? col[4 * (rows - 1)] : 1, adeg[rows - 1], span);
        return NULL;
    }
    if (span >= 360.0 - CLOSE_TOL) {
        given = 1;
        for (int i = 0; i < 3; i++)
            if (fabs(cv[i][rows - 1] - cv[i][0]) > CLOSE_TOL) {
                gal_error(GAL_EINPUT, "%s:%d: %s = %.17g at alpha_first + 360 must equal the first "
                          "row's %.17g (periodic closure, within %g)", at,
                          col ? col[4 * (rows - 1) + 1 + i] : 2 + i, coef_name[i], cv[i][rows - 1],
                          cv[i][0], CLOSE_TOL);
                return NULL;
            }
        if (rows - 1 < 4) {
            gal_error(GAL_EINPUT, "%s: %d distinct angles (the last row closes the period), at "
                      "least 4 are needed", name, rows - 1);
            return NULL;
        }
    }
    int nd = given ? rows - 1 : rows; /* distinct angles */
    int n = nd + 1;                   /* nodes with the closure */

    gal_aero_table *t = calloc(1, sizeof *t);
    if (!t) goto nomem;
    t->n = n;
    t->path = dupstr(name);
    t->source = dupstr(source);
    t->alpha = malloc(n * sizeof(double));
    if (!t->path || !t->source || !t->alpha) goto nomem;
    for (int k = 0; k < nd; k++) t->alpha[k] = adeg[k] * DEG;
    t->alpha[nd] = t->alpha[0] + 2.0 * GAL_PI;
    *status = GAL_EINPUT;
    for (int i = 0; i < 3; i++) {
        t->c[i] = malloc(n * sizeof(double));
        if (!t->c[i]) goto nomem;
        for (int k = 0; k < nd; k++) t->c[i][k] = cv[i][k];
        t->c[i][nd] = cv[i][0]; /* exact closure for the periodic spline */
        gsl_interp *s = gsl_interp_alloc(gsl_interp_cspline_periodic, n);
        if (!s) goto nomem;
        t->spline[i] = s;
        if (gsl_interp_init(s, t->alpha, t->c[i], n) != 0) {
            gal_error(GAL_EINPUT, "%s: the periodic spline of %s could not be built", name,
                      coef_name[i]);
            return gal_aero_table_free(t);
        }
    }
    *status = GAL_OK;
    return t;
nomem:
    *status = gal_error(GAL_ENOMEM, "%s: out of memory building the aerodynamic table", name);
    return gal_aero_table_free(t);
}

gal_aero_table *gal_aero_table_make(const char *name, const char *source, int n,
                                    const double *alpha_deg, const double *cd, const double *cl,
                                    const double *cm)
{
    if (!name) name = "(table)";
    if (!alpha_deg || !cd || !cl || !cm || n < 0) {
        gal_error(GAL_EINPUT, "%s: missing arrays", name);
        return NULL;
    }
    int st;
    return build(name, source, n, alpha_deg, cd, cl, cm, NULL, NULL, &st);
}

/* ------------------------------------------------------------------------------------------ */
/* reading the CSV file                                                                        */
/* ------------------------------------------------------------------------------------------ */

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
                               i ? coef_name[i - 1] : "alpha_deg");
                goto done;
            }
            char *end;
            errno = 0;
            double v = strtod(p, &end);
            const char *e = skip_space(end);
            if (end == p || (*e != ',' && *e != '\0')) {
                st = gal_error(GAL_EINPUT, "%s:%d:%d: column %d (%s) is not a number: a finite "
                               "decimal number is expected", path, lineno, column, i + 1,
                               i ? coef_name[i - 1] : "alpha_deg");
                goto done;
            }
            if (!isfinite(v)) {
                st = gal_error(GAL_EINPUT, "%s:%d:%d: %s = %g is not finite", path, lineno, column,
                               i ? coef_name[i - 1] : "alpha_deg", v);
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
    *out = build(path, r.source, r.rows, r.v[0], r.v[1], r.v[2], r.v[3], r.line, r.col, &st);
    goto done;
nomem:
    st = gal_error(GAL_ENOMEM, "%s: out of memory reading the aerodynamic table", path);
done:
    free(buf);
    fclose(fp);
    reader_free(&r);
    return st;
}

/* ------------------------------------------------------------------------------------------ */
/* evaluation                                                                                  */
/* ------------------------------------------------------------------------------------------ */

void gal_aero_eval(const gal_aero_table *t, double alpha, double c[3], double dc[3])
{
    if (!isfinite(alpha)) {
        for (int i = 0; i < 3; i++) {
            c[i] = NAN;
            if (dc) dc[i] = NAN;
        }
        return;
    }
    const double a0 = t->alpha[0], a1 = t->alpha[t->n - 1], P = 2.0 * GAL_PI;
    double x = alpha - a0;
    x -= P * floor(x / P);          /* x in [0, P) up to rounding */
    x += a0;
    if (x < a0) x = a0;
    if (x > a1) x = a1;             /* the spline's domain, exactly */
    for (int i = 0; i < 3; i++) {   /* NULL accelerator: the table stays const, thread-safe */
        c[i] = gsl_interp_eval(t->spline[i], t->alpha, t->c[i], x, NULL);
        if (dc) dc[i] = gsl_interp_eval_deriv(t->spline[i], t->alpha, t->c[i], x, NULL);
    }
}

double gal_aero_den_hartog(const gal_aero_table *t, double alpha)
{
    double c[3], dc[3];
    gal_aero_eval(t, alpha, c, dc);
    return dc[1] + c[0]; /* H = dC_L/dalpha + C_D */
}

/* ------------------------------------------------------------------------------------------ */
/* loads                                                                                       */
/* ------------------------------------------------------------------------------------------ */

static int finite3(const double a[3]) { return isfinite(a[0]) && isfinite(a[1]) && isfinite(a[2]); }

/* The section frame: e3 = unit tangent, e1 = unit part of d1 normal to it, e2 = e3 x e1. */
static int frame(const double tan[3], const double d1[3], double e1[3], double e2[3], double e3[3])
{
    if (!finite3(tan) || !finite3(d1))
        return gal_error(GAL_EINPUT, "aerodynamic load: non-finite tangent or reference direction");
    double nt = sqrt(gal_dot3(tan, tan));
    if (!(nt > 0)) return gal_error(GAL_EINPUT, "aerodynamic load: zero tangent");
    for (int i = 0; i < 3; i++) e3[i] = tan[i] / nt;
    double s = gal_dot3(d1, e3);
    for (int i = 0; i < 3; i++) e1[i] = d1[i] - s * e3[i]; /* e1 = (I - e3 e3^T) d1 */
    double n1 = sqrt(gal_dot3(e1, e1)), nd = sqrt(gal_dot3(d1, d1));
    if (!(n1 > 1e-12 * nd) || !(nd > 0))
        return gal_error(GAL_EINPUT, "aerodynamic load: reference direction d1 is zero or parallel "
                         "to the tangent");
    for (int i = 0; i < 3; i++) e1[i] /= n1;
    gal_cross3(e3, e1, e2);
    return GAL_OK;
}

double gal_aero_alpha(const double tan[3], const double d1[3], const double wrel[3])
{
    double e1[3], e2[3], e3[3];
    if (frame(tan, d1, e1, e2, e3) != GAL_OK || !finite3(wrel)) return 0.0;
    double x = gal_dot3(wrel, e1), y = gal_dot3(wrel, e2);
    if (x == 0.0 && y == 0.0) return 0.0;
    return atan2(y, x);
}

int gal_aero_load_deriv(const gal_aero_table *t, const double tan[3], const double d1[3],
                        const double wrel[3], double rho, double diam, unsigned flags,
                        double f[3], double *m, double df[9], double dm[3])
{
    double e1[3], e2[3], e3[3];
    if (f) f[0] = f[1] = f[2] = 0.0;
    if (m) *m = 0.0;
    if (df) memset(df, 0, 9 * sizeof(double));
    if (dm) dm[0] = dm[1] = dm[2] = 0.0;
    int st = frame(tan, d1, e1, e2, e3);
    if (st) return st;
    if (!finite3(wrel) || !isfinite(rho) || !isfinite(diam) || rho < 0 || diam < 0)
        return gal_error(GAL_EINPUT, "aerodynamic load: relative wind, air density or diameter not "
                         "finite or negative (rho = %g, d = %g)", rho, diam);

    /* ---- normal part of the relative wind, its speed and direction ---- */
    double x = gal_dot3(wrel, e1), y = gal_dot3(wrel, e2);   /* wn = x e1 + y e2 */
    double V = hypot(x, y);
    if (!(V > 1e-100)) return GAL_OK;              /* no wind, no load; load ~ V^2: zero slope */
    double wh[3], lh[3];                            /* w^ and l^ = e3 x w^ */
    for (int i = 0; i < 3; i++) {
        wh[i] = (x * e1[i] + y * e2[i]) / V;
        lh[i] = (x * e2[i] - y * e1[i]) / V;
    }
    double alpha = atan2(y, x);
    double c[3], dc[3];
    gal_aero_eval(t, alpha, c, dc);
    double cd = (flags & GAL_AERO_DRAG) ? c[0] : 0.0, dcd = (flags & GAL_AERO_DRAG) ? dc[0] : 0.0;
    double cl = (flags & GAL_AERO_LIFT) ? c[1] : 0.0, dcl = (flags & GAL_AERO_LIFT) ? dc[1] : 0.0;
    double cm = (flags & GAL_AERO_MOMENT) ? c[2] : 0.0, dcm = (flags & GAL_AERO_MOMENT) ? dc[2] : 0.0;
    double q = 0.5 * rho * diam;                   /* f = q V^2 (C_D w^ + C_L l^) */

    double g[3];                                   /* C_D w^ + C_L l^ */
    for (int i = 0; i < 3; i++) g[i] = cd * wh[i] + cl * lh[i];
    if (f)
        for (int i = 0; i < 3; i++) f[i] = q * V * V * g[i];
    if (m) *m = q * diam * V * V * cm;

    if (df) {
        /* dV/dw = w^T, dalpha/dw = l^T / V, d(V w^)/dw = P = I - e3 e3^T, d(V l^)/dw = [e3]x:
         * df/dw = q V [ (C_D w^ + C_L l^) w^T + (C_D' w^ + C_L' l^) l^T + C_D P + C_L [e3]x ] */
        double h[3];
        for (int i = 0; i < 3; i++) h[i] = dcd * wh[i] + dcl * lh[i];
        double X[9] = {0, -e3[2], e3[1], e3[2], 0, -e3[0], -e3[1], e3[0], 0}; /* [e3]x */
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                double P = (i == j) - e3[i] * e3[j];
                df[3 * i + j] = q * V * (g[i] * wh[j] + h[i] * lh[j] + cd * P + cl * X[3 * i + j]);
            }
    }
    if (dm)
        for (int j = 0; j < 3; j++) /* dm/dw = q d V (2 C_M w^ + C_M' l^)^T */
            dm[j] = q * diam * V * (2.0 * cm * wh[j] + dcm * lh[j]);
    return GAL_OK;
}

int gal_aero_load(const gal_aero_table *t, const double tan[3], const double d1[3],
                  const double wrel[3], double rho, double diam, unsigned flags, double f[3],
                  double *m)
{
    return gal_aero_load_deriv(t, tan, d1, wrel, rho, diam, flags, f, m, NULL, NULL);
}
