/* accreport_front.c: the front study's outputs (issue 20): front.csv (every configuration, its
 * errors per measure, wall time, on the front, chosen), the "front" object of summary.json (the
 * reference, its levels and estimated error, the front, the tolerance's check, the effects) and
 * the table on stdout. */
#include "output/accreport_int.h"
#include "gallop/base/core.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static void csv_num(FILE *fp, double v)
{
    if (isnan(v)) fprintf(fp, "nan");
    else if (isinf(v)) fprintf(fp, "inf");
    else fprintf(fp, "%.6g", v);
}

/* the Newton tolerance a point ran at (its own, else the scene's) */
static double point_tol(const gal_acc_front *F, const gal_acc_point *p)
{
    return p->c.newton_tol > 0 ? p->c.newton_tol : F->base_newton_tol;
}

static void csv_point(FILE *fp, const gal_acc_front *F, const gal_acc_point *p, int chosen)
{
    const gal_acc_config *c = &p->c;
    fprintf(fp, "%s,%s,%s,%d,", p->label, p->group, c->reduced ? "reduced" : "full", c->elements);
    if (c->reduced) fprintf(fp, "%d/%d/%d", c->modes[0], c->modes[1], c->modes[2]);
    fprintf(fp, ",%.6g,%s", c->time_step, c->effect_off >= 0 ? gal_effect_names[c->effect_off] : "");
    for (int k = 0; k < GAL_ACC_NMEAS; k++) fputc(',', fp), csv_num(fp, p->err[k]);
    fputc(',', fp), csv_num(fp, p->error);
    fprintf(fp, ",%.6g,%d,%d,%.6g,%ld\n", p->wall_time_s, p->on_front, chosen, point_tol(F, p), p->newton_iterations);
}

int gal_acc_front_csv(gal_outset *o, const gal_acc_result *r)
{
    const gal_acc_front *F = &r->front;
    FILE *fp = gal_outset_open(o, "front.csv");
    if (!fp) return GAL_EIO;
    fprintf(fp, "label,group,model,elements,modes,time_step_s,effect_off");
    for (int k = 0; k < GAL_ACC_NMEAS; k++) fprintf(fp, ",error_%s", gal_acc_measure_names[k]);
    fprintf(fp, ",error,wall_time_s,on_front,chosen,newton_tolerance,newton_iterations\n");
    for (int i = 0; i < F->n; i++) csv_point(fp, F, F->pt + i, i == F->chosen);
    return gal_outset_close(o, fp);
}

static void json_point(gal_json *j, const gal_acc_front *F, const gal_acc_point *p)
{
    gal_json_obj_begin(j);
    gal_json_kv_str(j, "label", p->label);
    gal_json_kv_str(j, "group", p->group);
    gal_json_kv_num(j, "error", p->error);
    gal_json_kv_num(j, "wall_time_s", p->wall_time_s);
    gal_json_kv_num(j, "newton_tolerance", point_tol(F, p));
    gal_json_kv_int(j, "newton_iterations", p->newton_iterations);
    gal_json_key(j, "errors");
    gal_json_obj_begin(j);
    for (int k = 0; k < GAL_ACC_NMEAS; k++) gal_json_kv_num(j, gal_acc_measure_names[k], p->err[k]);
    gal_json_obj_end(j);
    gal_json_key(j, "values");
    gal_json_obj_begin(j);
    for (int k = 0; k < GAL_ACC_NMEAS; k++) gal_json_kv_num(j, gal_acc_measure_names[k], p->value[k]);
    gal_json_obj_end(j);
    if (p->predicted) {
        gal_json_kv_num(j, "predicted_error", p->predicted_error);
        gal_json_kv_num(j, "predicted_wall_time_s", p->predicted_time_s);
    }
    gal_json_kv_int(j, "on_front", p->on_front);
    if (p->failed[0]) gal_json_kv_str(j, "failed", p->failed);
    gal_json_obj_end(j);
}

static void json_reference(gal_json *j, const gal_acc_front *F)
{
    gal_json_obj_begin(j);
    gal_json_kv_int(j, "levels", F->levels);
    gal_json_kv_int(j, "converged", F->converged);
    if (F->levels > 0) {
        gal_json_kv_int(j, "elements", F->ref_elements[F->levels - 1]);
        gal_json_kv_num(j, "time_step_s", F->ref_time_step[F->levels - 1]);
    }
    static const char *const what[5] = {"values", "estimated_error", "discretization_error", "last_change",
                                        "observed_order"};
    const double *arr[5] = {F->ref_value, F->ref_error, F->ref_disc_error, F->ref_change, F->order};
    for (int a = 0; a < 5; a++) {
        gal_json_key(j, what[a]);
        gal_json_obj_begin(j);
        for (int k = 0; k < GAL_ACC_NMEAS; k++)
            if (F->scored[k] || a == 0) gal_json_kv_num(j, gal_acc_measure_names[k], arr[a][k]);
        gal_json_obj_end(j);
    }
    double worst = 0;
    for (int k = 0; k < GAL_ACC_NMEAS; k++)
        if (F->scored[k] && isfinite(F->ref_error[k])) worst = fmax(worst, F->ref_error[k]);
    gal_json_kv_num(j, "worst_estimated_error", F->levels > 1 ? worst : NAN);
    gal_json_key(j, "scored");
    gal_json_arr_begin(j);
    for (int k = 0; k < GAL_ACC_NMEAS; k++)
        if (F->scored[k]) gal_json_str(j, gal_acc_measure_names[k]);
    gal_json_arr_end(j);
    if (F->ref_note[0]) gal_json_kv_str(j, "note", F->ref_note);
    gal_json_obj_end(j);
}

void gal_acc_front_json(gal_json *j, const gal_acc_result *r)
{
    const gal_acc_front *F = &r->front;
    gal_json_obj_begin(j);
    gal_json_kv_num(j, "tolerance", r->tolerance);
    gal_json_kv_num(j, "output_interval_s", F->output_interval_s);
    gal_json_kv_num(j, "steady_from_s", F->steady_from_s);
    gal_json_key(j, "headline_probes");
    gal_json_obj_begin(j);
    gal_json_kv_num(j, "vertical", F->probe[0]);
    gal_json_kv_num(j, "horizontal", F->probe[1]);
    gal_json_kv_num(j, "twist", F->probe[2]);
    gal_json_obj_end(j);
    gal_json_kv_int(j, "base_elements", F->base_elements);
    gal_json_kv_num(j, "base_time_step_s", F->base_time_step_s);
    gal_json_kv_num(j, "base_newton_tolerance", F->base_newton_tol);
    gal_json_kv_int(j, "seeds", F->nseeds);
    gal_json_key(j, "reference");
    json_reference(j, F);
    gal_json_key(j, "chosen");
    if (F->chosen >= 0) json_point(j, F, F->pt + F->chosen);
    else gal_json_num(j, NAN);
    gal_json_key(j, "check");
    if (F->checked) json_point(j, F, &F->check);
    else gal_json_num(j, NAN);
    gal_json_kv_str(j, "effects", F->effects);
    if (F->note[0]) gal_json_kv_str(j, "note", F->note);
    gal_json_key(j, "front");
    gal_json_arr_begin(j);
    for (int i = 0; i < F->n; i++)
        if (F->pt[i].on_front) gal_json_str(j, F->pt[i].label);
    gal_json_arr_end(j);
    gal_json_key(j, "points");
    gal_json_arr_begin(j);
    for (int i = 0; i < F->n; i++) json_point(j, F, F->pt + i);
    gal_json_arr_end(j);
    gal_json_obj_end(j);
}

void gal_acc_front_print(FILE *fp, const gal_acc_result *r)
{
    const gal_acc_front *F = &r->front;
    fprintf(fp, "%-52s %-9s %8s %8s %8s %8s %8s %8s %9s %9s %8s\n", "configuration", "group", "freq %", "vert %",
            "horiz %", "twist %", "tens %", "steady %", "worst %", "wall s", "newton");
    for (int i = 0; i < F->n; i++) {
        const gal_acc_point *p = F->pt + i;
        fprintf(fp, "%-52s %-9s", p->label, strcmp(p->group, "newton_tolerance") ? p->group : "newton");
        for (int k = 0; k < GAL_ACC_NMEAS; k++) fprintf(fp, " %8.3g", 100 * p->err[k]);
        fprintf(fp, " %9.3g %9.3g %8ld %s%s\n", 100 * p->error, p->wall_time_s, p->newton_iterations,
                p->on_front ? "front" : "",
                i == F->chosen ? " <- chosen" : p->failed[0] ? " (failed: see summary.json)" : "");
    }
    fprintf(fp, "\nreference: %d levels, finest %d elements and step %.4g s, %s; estimated error:",
            F->levels, F->levels ? F->ref_elements[F->levels - 1] : 0,
            F->levels ? F->ref_time_step[F->levels - 1] : NAN, F->converged ? "converged" : "NOT converged");
    for (int k = 0; k < GAL_ACC_NMEAS; k++)
        if (F->scored[k]) {
            fprintf(fp, " %s %.2g%%", gal_acc_measure_names[k], 100 * F->ref_error[k]);
            if (isfinite(F->order[k]) && k != GAL_ACC_M_STEADY) fprintf(fp, " (order %.2g)", F->order[k]);
        }
    fprintf(fp, "\n");
    if (F->ref_note[0]) fprintf(fp, "reference note: %s\n", F->ref_note);
    if (F->chosen >= 0 && F->checked)
        fprintf(fp, "tolerance %.3g%%: %s; its check run reached an error of %.3g%% in %.3g s\n", 100 * r->tolerance,
                F->pt[F->chosen].label, 100 * F->check.error, F->check.wall_time_s);
    else fprintf(fp, "tolerance %.3g%%: no configuration meets it\n", 100 * r->tolerance);
    if (F->effects[0]) fprintf(fp, "effects: %s\n", F->effects);
    if (F->note[0]) fprintf(fp, "note: %s\n", F->note);
}
