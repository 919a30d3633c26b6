/* accreport.c: the outputs of `gallop accuracy` (DESIGN.md "Command line"): accuracy.csv,
 * summary.json and the table on stdout. */
#include "gallop/output/accreport.h"
#include "gallop/base/core.h"
#include "gallop/output/json.h"
#include "gallop/output/outset.h"
#include "output/accreport_int.h"

#include <math.h>
#include <stdio.h>

static void csv_num(FILE *fp, double v)
{
    if (isnan(v)) fprintf(fp, "nan");
    else if (isinf(v)) fprintf(fp, "inf");
    else fprintf(fp, "%.6g", v);
}

static void json_row(gal_json *j, const gal_acc_row *w)
{
    gal_json_obj_begin(j);
    gal_json_kv_str(j, "setting", w->setting);
    gal_json_kv_str(j, "value", w->value);
    gal_json_kv_num(j, "error", w->error);
    gal_json_kv_num(j, "wall_time_s", w->wall_time_s);
    gal_json_kv_num(j, "build_time_s", w->build_time_s);
    if (w->study == GAL_ACC_ELEMENTS) {
        gal_json_kv_num(j, "error_frequency", w->err_frequency);
        gal_json_kv_num(j, "error_sag", w->err_sag);
        gal_json_kv_num(j, "error_horizontal_tension", w->err_tension);
        gal_json_kv_num(j, "first_horizontal_hz", w->frequency_hz);
        gal_json_kv_num(j, "string_theory_error", w->string_error);
    } else {
        gal_json_kv_num(j, "error_amplitude", w->err_amplitude);
        gal_json_kv_num(j, "error_frequency", w->err_frequency);
        gal_json_kv_num(j, "vertical_peak_to_peak_m", w->amplitude_m);
        gal_json_kv_num(j, "vertical_frequency_hz", w->frequency_hz);
    }
    if (w->failed[0]) gal_json_kv_str(j, "failed", w->failed);
    gal_json_kv_int(j, "reference", w->reference);
    gal_json_kv_int(j, "chosen", w->chosen);
    gal_json_obj_end(j);
}

static int write_csv(gal_outset *o, const gal_acc_result *r)
{
    FILE *fp = gal_outset_open(o, "accuracy.csv");
    if (!fp) return GAL_EIO;
    fprintf(fp, "study,setting,value,error,wall_time_s,chosen\n");
    for (int i = 0; i < r->n; i++) {
        const gal_acc_row *w = r->row + i;
        fprintf(fp, "%s,%s,%s,", gal_acc_study_names[w->study], w->setting, w->value);
        csv_num(fp, w->error);
        fprintf(fp, ",%.6g,%d\n", w->wall_time_s, w->chosen);
    }
    /* the front study's points: setting = what they vary, value = the configuration (no spaces) */
    for (int i = 0; i < r->front.n; i++) {
        const gal_acc_point *p = r->front.pt + i;
        fprintf(fp, "front,%s,", p->group);
        for (const char *c = p->label; *c; c++) fputc(*c == ' ' ? '_' : *c, fp);
        fputc(',', fp);
        csv_num(fp, p->error);
        fprintf(fp, ",%.6g,%d\n", p->wall_time_s, i == r->front.chosen);
    }
    return gal_outset_close(o, fp);
}

/* one study: its reference, the chosen setting, what it buys, its rows */
static void json_study(gal_json *j, const gal_acc_result *r, int s)
{
    const gal_acc_summary *S = r->study + s;
    const gal_acc_row *ref = S->reference >= 0 ? r->row + S->reference : NULL;
    const gal_acc_row *c = S->chosen >= 0 ? r->row + S->chosen : NULL;
    gal_json_obj_begin(j);
    gal_json_key(j, "reference");
    gal_json_obj_begin(j);
    gal_json_kv_str(j, "setting", ref ? ref->setting : "");
    gal_json_kv_str(j, "value", ref ? ref->value : "");
    gal_json_kv_num(j, "wall_time_s", ref ? ref->wall_time_s : NAN);
    gal_json_obj_end(j);
    gal_json_key(j, "meets_tolerance");
    gal_json_bool(j, c != NULL);
    gal_json_key(j, "chosen");
    if (c) {
        gal_json_obj_begin(j);
        gal_json_kv_str(j, "setting", c->setting);
        gal_json_kv_str(j, "value", c->value);
        gal_json_kv_num(j, "error", c->error);
        gal_json_kv_num(j, "wall_time_s", c->wall_time_s);
        gal_json_kv_num(j, "build_time_s", c->build_time_s);
        gal_json_obj_end(j);
    } else {
        gal_json_num(j, NAN);
    }
    gal_json_kv_str(j, "buys", S->buys);
    if (S->note[0]) gal_json_kv_str(j, "note", S->note);
    if (isfinite(S->steady_from_s)) gal_json_kv_num(j, "steady_from_s", S->steady_from_s);
    if (isfinite(S->probe)) gal_json_kv_num(j, "probe", S->probe);
    if (isfinite(S->output_interval_s)) gal_json_kv_num(j, "output_interval_s", S->output_interval_s);
    gal_json_key(j, "rows");
    gal_json_arr_begin(j);
    for (int i = 0; i < r->n; i++)
        if ((int)r->row[i].study == s) json_row(j, r->row + i);
    gal_json_arr_end(j);
    gal_json_obj_end(j);
}

static int write_summary(gal_outset *o, const gal_scene *sc, const gal_acc_result *r)
{
    gal_json *j = gal_outset_summary(o);
    if (!j) return GAL_EIO;
    gal_json_kv_str(j, "scene", sc->path);
    gal_json_kv_num(j, "tolerance", r->tolerance);
    gal_json_kv_num(j, "wall_time_s", r->wall_time_s);
    gal_json_key(j, "string_theory");
    gal_json_obj_begin(j);
    gal_json_kv_str(j, "applies", isfinite(r->string_hz) ? "level span with gravity: f_1 = 1/(2L) sqrt(H/m)"
                                                        : "no (inclined span, gravity off, or elements study not run)");
    gal_json_kv_num(j, "first_horizontal_hz", r->string_hz);
    gal_json_obj_end(j);
    gal_json_key(j, "studies");
    gal_json_obj_begin(j);
    for (int s = 0; s < GAL_ACC_NSTUDY; s++) {
        if (!r->study[s].ran || s == GAL_ACC_FRONT) continue;
        gal_json_key(j, gal_acc_study_names[s]);
        json_study(j, r, s);
    }
    gal_json_obj_end(j);
    if (r->study[GAL_ACC_FRONT].ran) {
        gal_json_key(j, "front");
        gal_acc_front_json(j, r);
    }
    return GAL_OK;
}

int gal_accuracy_write(const char *dir, const gal_scene *sc, const gal_acc_result *r)
{
    gal_outset *o;
    int st = gal_outset_begin(&o, dir, "accuracy");
    if (!st) st = gal_outset_scene(o, sc);
    if (!st) st = write_csv(o, r);
    if (!st && r->study[GAL_ACC_FRONT].ran) st = gal_acc_front_csv(o, r);
    if (!st) st = write_summary(o, sc, r);
    if (!st) st = gal_outset_commit(o);
    gal_outset_free(o);
    return st;
}

void gal_accuracy_print(FILE *fp, const gal_acc_result *r)
{
    if (r->study[GAL_ACC_FRONT].ran) gal_acc_front_print(fp, r);
    if (r->n == 0) {
        fprintf(fp, "total wall time %.3g s\n", r->wall_time_s);
        return;
    }
    fprintf(fp, "%-10s %-22s %-10s %12s %12s %12s  %s\n", "study", "setting", "value", "error %", "wall s", "build s", "");
    for (int i = 0; i < r->n; i++) {
        const gal_acc_row *w = r->row + i;
        fprintf(fp, "%-10s %-22s %-10s %12.4g %12.4g %12.4g  %s\n", gal_acc_study_names[w->study], w->setting,
                w->value, 100 * w->error, w->wall_time_s, w->build_time_s,
                w->chosen ? "<- chosen" : w->reference ? "(reference)" : w->failed[0] ? "(failed: see summary.json)" : "");
    }
    fprintf(fp, "\ntolerance %.3g%%\n", 100 * r->tolerance);
    for (int s = 0; s < GAL_ACC_NSTUDY; s++)
        if (r->study[s].ran && s != GAL_ACC_FRONT) {
            fprintf(fp, "%-10s %s\n", gal_acc_study_names[s], r->study[s].buys);
            if (r->study[s].note[0]) fprintf(fp, "%-10s note: %s\n", "", r->study[s].note);
        }
    if (isfinite(r->string_hz))
        fprintf(fp, "string theory: first out-of-plane frequency %.6g Hz (errors of each mesh in summary.json)\n",
                r->string_hz);
    fprintf(fp, "total wall time %.3g s\n", r->wall_time_s);
}
