/* sweep_grid.c: the grid of a sweep (sweep.h): `section.key=LIST` parsed, the product of the axes,
 * the cases of each unit of work (a case, or a chain up and down axis 0), and every value checked
 * by the scene reader before anything is computed. */
#include "gallop/run/sweep.h"
#include "gallop/base/core.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const gal_sweep_branch_names[3] = {"", "up", "down"};

#define LIST_FORMS "allowed: --vary section.key=v1,v2,... or section.key=start:stop:step (step != 0, towards stop)"

static int number(const char *s, double *v)
{
    char *end;
    errno = 0;
    *v = strtod(s, &end);
    return end != s && !*end && errno == 0 && isfinite(*v);
}

static int axis_alloc(gal_sweep_axis *a, const char *spec, long n)
{
    if (n < 1 || n > GAL_SWEEP_MAX_VALUES)
        return gal_error(GAL_EINPUT, "--vary %s: %ld values; allowed: 1 to %d per key", spec, n, GAL_SWEEP_MAX_VALUES);
    a->n = (int)n;
    a->value = calloc((size_t)n, sizeof *a->value);
    a->num = calloc((size_t)n, sizeof *a->num);
    if (!a->value || !a->num) return gal_error(GAL_ENOMEM, "--vary %s: out of memory", spec);
    return GAL_OK;
}

/* start:stop:step, the values start + i step up to stop (within a millionth of a step) */
static int parse_range(gal_sweep_axis *a, const char *spec, const char *list)
{
    char t[3][GAL_SWEEP_VALUE_MAX];
    double v[3];
    const char *p = list;
    for (int k = 0; k < 3; k++) {
        const char *e = k < 2 ? strchr(p, ':') : p + strlen(p);
        if (!e || e - p >= GAL_SWEEP_VALUE_MAX || (k == 2 && strchr(p, ':')))
            return gal_error(GAL_EINPUT, "--vary %s: not start:stop:step; " LIST_FORMS, spec);
        memcpy(t[k], p, (size_t)(e - p));
        t[k][e - p] = '\0';
        if (!number(t[k], &v[k]))
            return gal_error(GAL_EINPUT, "--vary %s: '%s' is not a number; " LIST_FORMS, spec, t[k]);
        p = e + 1;
    }
    double span = (v[1] - v[0]) / v[2];
    if (v[2] == 0 || !(span >= -1e-6) || !isfinite(span))
        return gal_error(GAL_EINPUT, "--vary %s: the step %g does not go from %g towards %g; " LIST_FORMS, spec, v[2],
                         v[0], v[1]);
    if (span + 1 > GAL_SWEEP_MAX_VALUES)
        return gal_error(GAL_EINPUT, "--vary %s: %.0f values; allowed: 1 to %d per key", spec, floor(span + 1e-6) + 1,
                         GAL_SWEEP_MAX_VALUES);
    long n = (long)floor(span + 1e-6) + 1;
    int st = axis_alloc(a, spec, n);
    for (long i = 0; !st && i < n; i++) {
        double x = v[0] + (double)i * v[2];
        if (fabs(x) < 1e-12 * fabs(v[2])) x = 0; /* no -0 or 1e-17 where the range crosses zero */
        a->num[i] = x;
        snprintf(a->value[i], GAL_SWEEP_VALUE_MAX, "%.10g", x);
    }
    return st;
}

/* v1,v2,...: each value kept as written */
static int parse_list(gal_sweep_axis *a, const char *spec, const char *list)
{
    long n = 1;
    for (const char *p = list; *p; p++) n += *p == ',';
    int st = axis_alloc(a, spec, n);
    const char *p = list;
    for (long i = 0; !st && i < n; i++) {
        const char *e = strchr(p, ',');
        if (!e) e = p + strlen(p);
        while (p < e && (*p == ' ' || *p == '\t')) p++;
        const char *f = e;
        while (f > p && (f[-1] == ' ' || f[-1] == '\t')) f--;
        if (f == p) return gal_error(GAL_EINPUT, "--vary %s: value %ld is empty; " LIST_FORMS, spec, i + 1);
        if (f - p >= GAL_SWEEP_VALUE_MAX)
            return gal_error(GAL_EINPUT, "--vary %s: value %ld is longer than %d characters", spec, i + 1,
                             GAL_SWEEP_VALUE_MAX - 1);
        memcpy(a->value[i], p, (size_t)(f - p));
        a->value[i][f - p] = '\0';
        if (!number(a->value[i], &a->num[i])) a->num[i] = NAN;
        p = e + 1;
    }
    return st;
}

int gal_sweep_axis_parse(gal_sweep_axis *a, const char *spec)
{
    memset(a, 0, sizeof *a);
    const char *eq = strchr(spec, '='), *dot = strchr(spec, '.');
    if (!eq || !dot || dot > eq || dot == spec || dot + 1 == eq || !eq[1])
        return gal_error(GAL_EINPUT, "--vary %s: not section.key=LIST; " LIST_FORMS, spec);
    if (eq - spec >= GAL_SWEEP_KEY_MAX)
        return gal_error(GAL_EINPUT, "--vary %s: the key is longer than %d characters", spec, GAL_SWEEP_KEY_MAX - 1);
    memcpy(a->key, spec, (size_t)(eq - spec));
    a->key[eq - spec] = '\0';
    const char *list = eq + 1;
    /* a range has two colons and no comma; anything else is a list (a value may hold a colon) */
    const char *c1 = strchr(list, ':');
    if (c1 && strchr(c1 + 1, ':') && !strchr(list, ',')) return parse_range(a, spec, list);
    return parse_list(a, spec, list);
}

void gal_sweep_grid_clear(gal_sweep_grid *g)
{
    for (int k = 0; k < GAL_SWEEP_MAX_AXES; k++) {
        free(g->axis[k].value);
        free(g->axis[k].num);
    }
    memset(g, 0, sizeof *g);
}

int gal_sweep_grid_init(gal_sweep_grid *g, int continuation)
{
    if (g->naxes < 1 || g->naxes > GAL_SWEEP_MAX_AXES)
        return gal_error(GAL_EINPUT, "sweep: %d keys varied; allowed: 1 to %d --vary options", g->naxes,
                         GAL_SWEEP_MAX_AXES);
    double np = 1;
    for (int k = 0; k < g->naxes; k++) {
        for (int j = 0; j < k; j++)
            if (!strcmp(g->axis[j].key, g->axis[k].key))
                return gal_error(GAL_EINPUT, "--vary %s given twice; allowed: each key once", g->axis[k].key);
        np *= g->axis[k].n;
    }
    int n0 = g->axis[0].n;
    double nc = continuation ? np / n0 * (2.0 * n0 - 1) : np;
    if (nc > GAL_SWEEP_MAX_CASES)
        return gal_error(GAL_EINPUT, "sweep: %.0f cases; allowed: at most %ld (split the sweep)", nc, GAL_SWEEP_MAX_CASES);
    g->continuation = continuation;
    g->npoints = (long)np;
    g->unit_cases = continuation ? 2L * n0 - 1 : 1;
    g->nunits = continuation ? g->npoints / n0 : g->npoints;
    g->ncases = g->nunits * g->unit_cases;
    return GAL_OK;
}

void gal_sweep_case_of(const gal_sweep_grid *g, long unit, int pos, gal_sweep_case *c)
{
    memset(c, 0, sizeof *c);
    c->unit = unit, c->pos = pos;
    c->row = unit * g->unit_cases + pos;
    int n0 = g->axis[0].n;
    if (g->continuation) {
        /* the chain's point on axes 1.., then axis 0 up and back down */
        c->point = unit * n0 + (pos < n0 ? pos : 2 * n0 - 2 - pos);
        c->branch = pos < n0 ? GAL_SWEEP_UP : GAL_SWEEP_DOWN;
    } else {
        c->point = unit;
        c->branch = GAL_SWEEP_NONE;
    }
    long p = c->point;
    for (int k = 0; k < g->naxes; k++) {
        c->idx[k] = (int)(p % g->axis[k].n);
        p /= g->axis[k].n;
    }
}

int gal_sweep_case_sets(const gal_sweep_grid *g, const gal_sweep_case *c, const char *const *user, int nuser,
                        char (*buf)[GAL_SWEEP_KEY_MAX + GAL_SWEEP_VALUE_MAX], const char **sets)
{
    int n = 0;
    for (int i = 0; i < nuser; i++) sets[n++] = user[i];
    for (int k = 0; k < g->naxes; k++) {
        snprintf(buf[k], sizeof buf[k], "%s=%s", g->axis[k].key, g->axis[k].value[c->idx[k]]);
        sets[n++] = buf[k];
    }
    return n;
}

int gal_sweep_grid_check(const gal_sweep_grid *g, const char *scene_path, const char *const *user, int nuser)
{
    const char **sets = malloc((size_t)(nuser + 1) * sizeof *sets);
    gal_scene *sc = malloc(sizeof *sc);
    char one[GAL_SWEEP_KEY_MAX + GAL_SWEEP_VALUE_MAX];
    int st = sets && sc ? GAL_OK : gal_error(GAL_ENOMEM, "sweep: out of memory");
    for (int i = 0; sets && i < nuser; i++) sets[i] = user[i];
    /* each value alone over the scene and the user's settings: the reader names what is wrong */
    for (int k = 0; !st && k < g->naxes; k++)
        for (int i = 0; !st && i < g->axis[k].n; i++) {
            snprintf(one, sizeof one, "%s=%s", g->axis[k].key, g->axis[k].value[i]);
            sets[nuser] = one;
            if ((st = gal_scene_load(sc, scene_path, sets, nuser + 1, NULL)))
                st = gal_error(st, "--vary %s: %s", one, gal_error_message());
        }
    free(sets);
    free(sc);
    return st;
}
