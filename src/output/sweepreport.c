/* sweepreport.c: sweep.csv and summary.json of `gallop sweep` (sweepreport.h), one output set:
 * a row per case, the grid, the totals, and per varied key where the vertical amplitude at the
 * first probe jumps (galloping_from), on each branch. */
#include "gallop/output/sweepreport.h"
#include "gallop/base/core.h"
#include "gallop/output/json.h"
#include "gallop/output/outset.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define AMP_FLOOR_M 1e-3 /* m: a peak-to-peak below a millimetre is no galloping, whatever its ratio */
#define JUMP_RATIO 5.0   /* a jump: the amplitude grows at least this much between neighbouring values */
#define MAX_FAILURES 50  /* failed cases named in summary.json */

static void csv_num(FILE *fp, double x)
{
    if (isfinite(x)) fprintf(fp, ",%.8g", x);
    else fputc(',', fp);
}

/* an explicit bundle's sub-conductors: per sub-conductor k, columns suffixed _s<k> after the rest */
static const char *const sub_cols[4] = {"vertical_pp_m", "horizontal_pp_m", "twist_pp_deg", "tension_max_n"};

static void sub_csv(FILE *fp, const gal_sweep_result *r, int nsub)
{
    for (int k = 0; k < nsub; k++) {
        double x[4] = {NAN, NAN, NAN, NAN};
        if (k < r->nsub)
            x[0] = r->sub_vertical_pp_m[k], x[1] = r->sub_horizontal_pp_m[k], x[2] = r->sub_twist_pp_deg[k],
            x[3] = r->sub_tension_max_n[k];
        for (int c = 0; c < 4; c++) csv_num(fp, x[c]);
    }
}

static void sweep_csv(FILE *fp, const gal_sweep_grid *g, const gal_sweep_result *rows)
{
    int nsub = 0;
    for (long r = 0; r < g->ncases; r++) nsub = rows[r].nsub > nsub ? rows[r].nsub : nsub;
    for (int k = 0; k < g->naxes; k++) fprintf(fp, "%s,", g->axis[k].key);
    fprintf(fp, "branch,vertical_pp_m,horizontal_pp_m,twist_pp_deg,frequency_hz,tension_max_n,onset_speed_m_s,"
            "valid,wall_time_s");
    for (int k = 0; k < nsub; k++)
        for (int c = 0; c < 4; c++) fprintf(fp, ",%s_s%d", sub_cols[c], k + 1);
    fputc('\n', fp);
    for (long u = 0; u < g->nunits; u++)
        for (int p = 0; p < g->unit_cases; p++) {
            gal_sweep_case c;
            gal_sweep_case_of(g, u, p, &c);
            const gal_sweep_result *r = rows + c.row;
            for (int k = 0; k < g->naxes; k++) fprintf(fp, "%s,", g->axis[k].value[c.idx[k]]);
            fputs(gal_sweep_branch_names[c.branch], fp);
            csv_num(fp, r->vertical_pp_m);
            csv_num(fp, r->horizontal_pp_m);
            csv_num(fp, r->twist_pp_deg);
            csv_num(fp, r->frequency_hz);
            csv_num(fp, r->tension_max_n);
            csv_num(fp, r->onset_speed_m_s);
            if (r->valid >= 0) fprintf(fp, ",%d", r->valid);
            else fputc(',', fp);
            fprintf(fp, ",%.3f", r->wall_time_s);
            sub_csv(fp, r, nsub);
            fputc('\n', fp);
        }
}

/* a value as a JSON number when it is one, else as the text given */
static void json_value(gal_json *j, const gal_sweep_axis *a, int i)
{
    if (isfinite(a->num[i])) gal_json_num(j, a->num[i]);
    else gal_json_str(j, a->value[i]);
}

/* The index on axis m of grid point p (axis 0 fastest). */
static int index_on(const gal_sweep_grid *g, long p, int m)
{
    for (int s = 0; s < m; s++) p /= g->axis[s].n;
    return (int)(p % g->axis[m].n);
}

/* The row of grid point `point` on branch b (the top of a chain is on the way up only). */
static long row_of(const gal_sweep_grid *g, long point, gal_sweep_branch b)
{
    if (!g->continuation) return point;
    long n0 = g->axis[0].n, i0 = point % n0, chain = point / n0;
    long pos = b == GAL_SWEEP_DOWN && i0 < n0 - 1 ? 2 * n0 - 2 - i0 : i0;
    return chain * g->unit_cases + pos;
}

/* Along axis k from grid point `base` (its index on k at 0): the index where the amplitude jumps
 * (the largest growth between neighbouring values, at least JUMP_RATIO), or -1. */
static int jump_along(const gal_sweep_grid *g, const gal_sweep_result *rows, int k, long base, long stride,
                      gal_sweep_branch b)
{
    int best = -1;
    double best_ratio = JUMP_RATIO;
    for (int i = 0; i + 1 < g->axis[k].n; i++) {
        double a0 = rows[row_of(g, base + i * stride, b)].vertical_pp_m;
        double a1 = rows[row_of(g, base + (i + 1) * stride, b)].vertical_pp_m;
        if (!isfinite(a0) || !isfinite(a1)) continue;
        double ratio = fmax(a1, AMP_FLOOR_M) / fmax(a0, AMP_FLOOR_M);
        if (ratio >= best_ratio) best_ratio = ratio, best = i + 1;
    }
    return best;
}

/* "galloping_from": per key, per line along it (the other keys fixed, "at") and branch */
static void json_galloping(gal_json *j, const gal_sweep_grid *g, const gal_sweep_result *rows)
{
    gal_json_key(j, "galloping_from");
    gal_json_obj_begin(j);
    for (int k = 0; k < g->naxes; k++) {
        long stride = 1;
        for (int m = 0; m < k; m++) stride *= g->axis[m].n;
        gal_json_key(j, g->axis[k].key);
        gal_json_arr_begin(j);
        for (long p = 0; p < g->npoints; p++) {
            if ((p / stride) % g->axis[k].n) continue; /* the lines start where axis k is at its first value */
            for (int b = 0; b < 3; b++) {
                if ((b == GAL_SWEEP_NONE) == (g->continuation != 0)) continue;
                gal_json_obj_begin(j);
                gal_json_key(j, "at");
                gal_json_obj_begin(j);
                for (int m = 0; m < g->naxes; m++) {
                    if (m == k) continue;
                    gal_json_key(j, g->axis[m].key);
                    json_value(j, &g->axis[m], index_on(g, p, m));
                }
                gal_json_obj_end(j);
                gal_json_kv_str(j, "branch", gal_sweep_branch_names[b]);
                int i = jump_along(g, rows, k, p, stride, (gal_sweep_branch)b);
                gal_json_key(j, "galloping_from");
                if (i >= 0) json_value(j, &g->axis[k], i);
                else gal_json_num(j, NAN);
                gal_json_obj_end(j);
            }
        }
        gal_json_arr_end(j);
    }
    gal_json_obj_end(j);
}

static void json_grid(gal_json *j, const gal_sweep_grid *g)
{
    gal_json_key(j, "grid");
    gal_json_arr_begin(j);
    for (int k = 0; k < g->naxes; k++) {
        gal_json_obj_begin(j);
        gal_json_kv_str(j, "key", g->axis[k].key);
        gal_json_key(j, "values");
        gal_json_arr_begin(j);
        for (int i = 0; i < g->axis[k].n; i++) json_value(j, &g->axis[k], i);
        gal_json_arr_end(j);
        gal_json_obj_end(j);
    }
    gal_json_arr_end(j);
}

static void json_summary(gal_json *j, const gal_scene *sc, const gal_sweep_grid *g, const gal_sweep_result *rows,
                         const gal_sweep_totals *t)
{
    gal_json_kv_str(j, "command", "sweep");
    gal_json_kv_str(j, "scene", sc->path);
    gal_json_kv_str(j, "model", t->model);
    gal_json_key(j, "continuation");
    gal_json_bool(j, g->continuation);
    json_grid(j, g);
    gal_json_kv_int(j, "cases", g->ncases);
    gal_json_kv_int(j, "computed", t->computed);
    gal_json_kv_int(j, "resumed", t->resumed);
    gal_json_kv_int(j, "failed", t->failed);
    gal_json_kv_int(j, "ranks", t->ranks);
    gal_json_kv_num(j, "wall_time_s", t->wall_time_s);
    gal_json_kv_num(j, "case_time_s", t->case_time_s);
    gal_json_kv_num(j, "cases_per_hour_per_rank",
                    t->computed > 0 && t->wall_time_s > 0 ? 3600.0 * t->computed / t->wall_time_s / t->ranks : NAN);
    gal_json_kv_int(j, "setups_computed", t->setups_computed); /* equilibrium and modes (run/sweep.h) */
    gal_json_kv_int(j, "setups_reused", t->setups_reused);
    gal_json_kv_int(j, "damping_computed", t->damping_computed);
    gal_json_kv_num(j, "setup_time_s", t->setup_time_s);
    gal_json_kv_int(j, "reduced_setups_computed", t->reduced_setups_computed); /* gal_data.rom_setup */
    gal_json_kv_int(j, "reduced_setups_reused", t->reduced_setups_reused);
    gal_json_key(j, "failures");
    gal_json_arr_begin(j);
    for (long r = 0, n = 0; r < g->ncases && n < MAX_FAILURES; r++)
        if (rows[r].status) {
            gal_json_obj_begin(j);
            gal_json_kv_int(j, "row", r + 1);
            gal_json_kv_str(j, "message", rows[r].message);
            gal_json_obj_end(j);
            n++;
        }
    gal_json_arr_end(j);
    json_galloping(j, g, rows);
    gal_json_key(j, "sweep_csv");
    gal_json_obj_begin(j);
    gal_json_kv_str(j, "holds", "per case: the varied keys as given, branch (up, down: --continuation), at the "
                    "first probe the steady peak-to-peak vertical and horizontal displacements (m) and twist (deg), "
                    "the vertical frequency (Hz), the largest support tension over the steady window (N), the "
                    "coupled onset speed (m/s; empty: no aero table or stable over [stability]), valid (the reduced "
                    "model's self-check; empty: not checked), the case's wall time (s); a failed case's figures "
                    "are empty (summary.json: failures)");
    gal_json_obj_end(j);
}

int gal_sweep_write(const char *dir, const gal_scene *sc, const gal_sweep_grid *g, const gal_sweep_result *rows,
                    const gal_sweep_totals *t)
{
    gal_outset *o = NULL;
    int st = gal_outset_begin(&o, dir, "sweep");
    if (!st) st = gal_outset_scene(o, sc);
    FILE *fp = st ? NULL : gal_outset_open(o, "sweep.csv");
    if (!st && !fp) st = GAL_EIO;
    if (fp) {
        sweep_csv(fp, g, rows);
        st = gal_outset_close(o, fp);
    }
    gal_json *j = st ? NULL : gal_outset_summary(o);
    if (!st && !j) st = GAL_EIO;
    if (j) {
        json_summary(j, sc, g, rows, t);
        st = gal_outset_commit(o);
    }
    gal_outset_free(o);
    return st;
}
