/* table.c: aerodynamic coefficient tables (DESIGN.md "Aerodynamics"; the file format and the
 * angle convention are stated in include/gallop/loads/aero.h): the checks of the rows, the
 * periodic closure, the periodic cubic splines (GSL) and their evaluation. */
#include "aero_impl.h"
#include "gallop/base/core.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_interp.h>

#define DEG (GAL_PI / 180.0)
#define CLOSE_TOL 1e-9      /* periodic closure: last row = first row + 360 within this */
#define MIN_STEP_DEG 1e-6   /* two angles closer than this are treated as duplicates */
#define MAX_ALPHA_DEG 720.0 /* |alpha_deg| allowed */
#define FINE 64             /* interpolant checked at this many points per interval between rows */

const char *const gal_aero_coef_name[3] = {"cd", "cl", "cm"};

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
    free(t->poly);
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

/* The rows: every value finite and in range, the angles strictly increasing. */
static int check_rows(const char *name, int rows, const double *adeg, const double *const cv[3],
                      const int *line, const int *col)
{
    char at[1200];
    for (int r = 0; r < rows; r++) {
        where(at, sizeof at, name, line, r);
        if (!isfinite(adeg[r]) || fabs(adeg[r]) > MAX_ALPHA_DEG)
            return gal_error(GAL_EINPUT, "%s:%d: alpha_deg = %g out of range: finite, within [-%g, %g]",
                             at, col ? col[4 * r] : 1, adeg[r], MAX_ALPHA_DEG, MAX_ALPHA_DEG);
        for (int i = 0; i < 3; i++)
            if (!isfinite(cv[i][r]) || fabs(cv[i][r]) > GAL_AERO_MAX_COEF)
                return gal_error(GAL_EINPUT, "%s:%d: %s = %g out of range: finite, within [-%g, %g]",
                                 at, col ? col[4 * r + 1 + i] : 2 + i, gal_aero_coef_name[i],
                                 cv[i][r], GAL_AERO_MAX_COEF, GAL_AERO_MAX_COEF);
        if (r > 0 && !(adeg[r] > adeg[r - 1] + MIN_STEP_DEG))
            return gal_error(GAL_EINPUT, "%s:%d: alpha_deg = %.17g %s the previous row's %.17g: angles "
                             "must be strictly increasing (steps > %g deg)", at,
                             col ? col[4 * r] : 1, adeg[r],
                             fabs(adeg[r] - adeg[r - 1]) <= MIN_STEP_DEG ? "duplicates" : "is below",
                             adeg[r - 1], MIN_STEP_DEG);
    }
    if (rows < 4)
        return gal_error(GAL_EINPUT, "%s: %d data rows, at least 4 angles are needed", name, rows);
    return GAL_OK;
}

/* The period: the closure row is given (the rows span 360 deg: *given = 1) or added (span < 360). */
static int check_period(const char *name, int rows, const double *adeg, const double *const cv[3],
                        const int *line, const int *col, int *given)
{
    char at[1200];
    double span = adeg[rows - 1] - adeg[0];
    *given = 0;
    where(at, sizeof at, name, line, rows - 1);
    if (span > 360.0 + CLOSE_TOL)
        return gal_error(GAL_EINPUT, "%s:%d: alpha_deg = %g: the rows span %g deg, more than one "
                         "period (allowed: less than 360, or exactly 360 with the last row equal to "
                         "the first)", at, col ? col[4 * (rows - 1)] : 1, adeg[rows - 1], span);
    if (span < 360.0 - CLOSE_TOL) return GAL_OK;
    *given = 1;
    for (int i = 0; i < 3; i++)
        if (fabs(cv[i][rows - 1] - cv[i][0]) > CLOSE_TOL)
            return gal_error(GAL_EINPUT, "%s:%d: %s = %.17g at alpha_first + 360 must equal the "
                             "first row's %.17g (periodic closure, within %g)", at,
                             col ? col[4 * (rows - 1) + 1 + i] : 2 + i, gal_aero_coef_name[i],
                             cv[i][rows - 1], cv[i][0], CLOSE_TOL);
    if (rows - 1 < 4)
        return gal_error(GAL_EINPUT, "%s: %d distinct angles (the last row closes the period), at "
                         "least 4 are needed", name, rows - 1);
    return GAL_OK;
}

/* Interval i of the spline: i such that alpha[i] <= x < alpha[i + 1] (n - 2 at the last node), as
 * GSL's bisection finds it (gsl_interp_bsearch over the whole table). */
static int interval(const gal_aero_table *t, double x)
{
    int lo = 0, hi = t->n - 1;
    while (hi > lo + 1) {
        int i = (hi + lo) / 2;
        if (t->alpha[i] > x) hi = i;
        else lo = i;
    }
    return lo;
}

/* The cubic of coefficient k at x in interval i: value and slope, in GSL's cspline evaluation's
 * operations (y_lo + delx (b + delx (c + delx d)), b + delx (2 c + 3 d delx)). */
static void cubic(const gal_aero_table *t, int i, int k, double x, double *y, double *dy)
{
    const double *p = t->poly + 4 * (3 * i + k);
    double delx = x - t->alpha[i];
    *y = p[0] + delx * (p[1] + delx * (p[2] + delx * p[3]));
    if (dy) *dy = p[1] + delx * (2.0 * p[2] + 3.0 * p[3] * delx);
}

/* t->poly: each interval's cubic, formed once as GSL's periodic cubic spline forms it at every
 * evaluation (b = dy/dx - dx (c_{i+1} + 2 c_i)/3, c = c_i, d = (c_{i+1} - c_i)/(3 dx), c_i half the
 * second derivative at node i, c_{n-1} = c_0 by periodicity): the same numbers without the
 * three divisions and the call per coefficient. Kept only when it gives GSL's values and slopes
 * bit for bit at every node and at 7 points inside every interval; else left NULL (GSL evaluates).
 * Out of memory: left NULL as well. */
static void poly_build(gal_aero_table *t)
{
    int n = t->n;
    double *cc = malloc((size_t)n * sizeof(double));
    if (!cc || !(t->poly = malloc((size_t)12 * (n - 1) * sizeof(double)))) {
        free(cc);
        return;
    }
    int ok = 1;
    for (int k = 0; k < 3 && ok; k++) {
        for (int i = 0; i + 1 < n; i++) cc[i] = 0.5 * gsl_interp_eval_deriv2(t->spline[k], t->alpha, t->c[k], t->alpha[i], NULL);
        cc[n - 1] = cc[0];
        for (int i = 0; i + 1 < n; i++) {
            double dx = t->alpha[i + 1] - t->alpha[i], dy = t->c[k][i + 1] - t->c[k][i], *p = t->poly + 4 * (3 * i + k);
            p[0] = t->c[k][i];
            p[1] = (dy / dx) - dx * (cc[i + 1] + 2.0 * cc[i]) / 3.0;
            p[2] = cc[i];
            p[3] = (cc[i + 1] - cc[i]) / (3.0 * dx);
        }
    }
    for (int i = 0; i + 1 < n && ok; i++)
        for (int s = 0; s <= 8 && ok; s++) { /* the node, 7 points inside, the next node */
            double x = s == 8 ? t->alpha[i + 1] : t->alpha[i] + s * (t->alpha[i + 1] - t->alpha[i]) / 8;
            int j = interval(t, x);
            for (int k = 0; k < 3 && ok; k++) {
                double y, dy;
                cubic(t, j, k, x, &y, &dy);
                ok = y == gsl_interp_eval(t->spline[k], t->alpha, t->c[k], x, NULL) &&
                     dy == gsl_interp_eval_deriv(t->spline[k], t->alpha, t->c[k], x, NULL);
            }
        }
    free(cc);
    if (!ok) free(t->poly), t->poly = NULL;
}

/* The table over nd distinct angles plus the closure alpha[0] + 2 pi, with its periodic splines. */
static gal_aero_table *splines(const char *name, const char *source, int nd, const double *adeg,
                               const double *const cv[3], int *status)
{
    int n = nd + 1; /* nodes with the closure */
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
                      gal_aero_coef_name[i]);
            return gal_aero_table_free(t);
        }
    }
    poly_build(t);
    *status = GAL_OK;
    return t;
nomem:
    *status = gal_error(GAL_ENOMEM, "%s: out of memory building the aerodynamic table", name);
    return gal_aero_table_free(t);
}

/* The interpolant between rows: on FINE points per interval, every coefficient within the rows'
 * bound GAL_AERO_MAX_COEF and every slope within GAL_AERO_MAX_SLOPE (aero.h); else the message
 * names the two rows of the interval where the bound is exceeded most (an overshooting periodic
 * spline rings over the whole period, worst next to the rows too close for their values).
 * Interval k runs from row k to row k + 1 (the last to the closure: the first row, or the
 * closure row when given). */
static int check_interpolant(const gal_aero_table *t, const char *name, int rows, const int *line,
                             int given)
{
    double worst = 1, wv = 0, wx = 0;
    int wk = -1, wi = 0, wslope = 0;
    for (int k = 0; k + 1 < t->n; k++) {
        double h = t->alpha[k + 1] - t->alpha[k];
        for (int j = 0; j <= FINE; j++) {
            double x = j == FINE ? t->alpha[k + 1] : t->alpha[k] + h * j / FINE;
            for (int i = 0; i < 3; i++) {
                double v[2] = {gsl_interp_eval(t->spline[i], t->alpha, t->c[i], x, NULL),
                               gsl_interp_eval_deriv(t->spline[i], t->alpha, t->c[i], x, NULL)};
                for (int d = 0; d < 2; d++) {
                    double r = fabs(v[d]) / (d ? GAL_AERO_MAX_SLOPE : GAL_AERO_MAX_COEF);
                    if (!isfinite(r)) r = INFINITY;
                    if (r > worst) worst = r, wv = v[d], wx = x, wk = k, wi = i, wslope = d;
                }
            }
        }
    }
    if (wk < 0) return GAL_OK;
    char a0[1200], a1[1200];
    int r1 = wk + 1 < t->n - 1 ? wk + 1 : (given ? rows - 1 : 0);
    where(a0, sizeof a0, name, line, wk);
    where(a1, sizeof a1, name, line, r1);
    const char *c = gal_aero_coef_name[wi];
    return gal_error(GAL_EINPUT, "%s and %s: between these rows (alpha_deg %.9g to %.9g) the periodic "
                     "spline of %s reaches %s%s = %.3g%s at alpha_deg = %.9g; allowed between rows as "
                     "at them: |%s| <= %g, |d%s/dalpha| <= %g per rad; the rows are too close for "
                     "their values (the spline overshoots): space the angles or smooth the data",
                     a0, a1, t->alpha[wk] / DEG, t->alpha[wk + 1] / DEG, c, wslope ? "d" : "", c,
                     wv, wslope ? "/dalpha" : "", wx / DEG, c, GAL_AERO_MAX_COEF, c, GAL_AERO_MAX_SLOPE);
}

gal_aero_table *gal_aero_table_build(const char *name, const char *source, int rows,
                                     const double *adeg, const double *cd, const double *cl,
                                     const double *cm, const int *line, const int *col, int *status)
{
    const double *const cv[3] = {cd, cl, cm};
    int given;
    *status = GAL_EINPUT;
    gal_gsl_errors_install(); /* GSL errors as gallop errors, never an abort */
    if (!source || !source[0]) {
        gal_error(GAL_EINPUT, "%s: no '# source:' comment line: every table must say where its "
                  "numbers come from", name);
        return NULL;
    }
    if (check_rows(name, rows, adeg, cv, line, col) != GAL_OK ||
        check_period(name, rows, adeg, cv, line, col, &given) != GAL_OK)
        return NULL;
    gal_aero_table *t = splines(name, source, given ? rows - 1 : rows, adeg, cv, status);
    if (t && check_interpolant(t, name, rows, line, given) != GAL_OK) {
        *status = GAL_EINPUT;
        return gal_aero_table_free(t);
    }
    return t;
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
    return gal_aero_table_build(name, source, n, alpha_deg, cd, cl, cm, NULL, NULL, &st);
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
    /* the three splines share their nodes: one interval search (a local accelerator: the table
     * stays const and thread-safe), found as the NULL accelerator's bisection finds it, so the
     * values are the same numbers; each interval's cubic formed once (poly_build) */
    if (t->poly) {
        int j = interval(t, x);
        for (int i = 0; i < 3; i++) cubic(t, j, i, x, c + i, dc ? dc + i : NULL);
        return;
    }
    gsl_interp_accel acc = {0, 0, 0};
    for (int i = 0; i < 3; i++) {
        c[i] = gsl_interp_eval(t->spline[i], t->alpha, t->c[i], x, &acc);
        if (dc) dc[i] = gsl_interp_eval_deriv(t->spline[i], t->alpha, t->c[i], x, &acc);
    }
}

double gal_aero_den_hartog(const gal_aero_table *t, double alpha)
{
    double c[3], dc[3];
    gal_aero_eval(t, alpha, c, dc);
    return dc[1] + c[0]; /* H = dC_L/dalpha + C_D */
}

