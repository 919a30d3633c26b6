/* specreport.c: the outputs of `gallop spectrum` (specreport.h): psd.csv (one-sided PSD, each
 * column named with its unit squared per Hz), summary.json and the table on stdout. */
#include "gallop/output/specreport.h"
#include "gallop/base/core.h"
#include "gallop/output/json.h"
#include "gallop/output/outset.h"

#include <math.h>
#include <string.h>

static void fmt(char *buf, size_t n, double v)
{
    if (isfinite(v)) snprintf(buf, n, "%.6g", v);
    else snprintf(buf, n, "none");
}

/* The psd.csv column of a trace column: its unit squared per Hz. A name ending in a unit suffix
 * (_m, _deg, _n, _rad) gets that unit's "<u>2_per_hz" (p0.5_vertical_m -> p0.5_vertical_m2_per_hz);
 * any other name "_psd" (mid_y -> mid_y_psd: the column's unit squared per Hz). */
static void psd_name(FILE *fp, const char *name)
{
    static const char *const units[] = {"_m", "_deg", "_n", "_rad"};
    size_t ln = strlen(name);
    for (size_t u = 0; u < sizeof units / sizeof units[0]; u++) {
        size_t lu = strlen(units[u]);
        if (ln > lu && !strcmp(name + ln - lu, units[u])) {
            fprintf(fp, ",%s2_per_hz", name);
            return;
        }
    }
    fprintf(fp, ",%s_psd", name);
}

static int write_psd(gal_outset *o, const gal_trace *tr, const gal_trace_spectrum *s)
{
    FILE *fp = gal_outset_open(o, "psd.csv");
    if (!fp) return GAL_EIO;
    fprintf(fp, "frequency_hz");
    for (size_t c = 0; c < s->nsel; c++) psd_name(fp, tr->names[s->sel[c]]);
    fputc('\n', fp);
    for (size_t k = 0; k < s->nf; k++) {
        fprintf(fp, "%.10g", (double)k * s->df);
        for (size_t c = 0; c < s->nsel; c++) fprintf(fp, ",%.10g", s->psd[c * s->nf + k]);
        fputc('\n', fp);
    }
    return gal_outset_close(o, fp);
}

static void json_orbit(gal_json *j, const gal_trace *tr, const gal_trace_pair *p)
{
    gal_json_kv_str(j, "y", tr->names[p->y]);
    gal_json_kv_str(j, "z", tr->names[p->z]);
    gal_json_kv_num(j, "major_semi_axis", p->orbit.major);
    gal_json_kv_num(j, "minor_semi_axis", p->orbit.minor);
    gal_json_kv_num(j, "tilt_deg", p->orbit.tilt_deg);
}

static void json_column(gal_json *j, const gal_measures *m, double tss)
{
    gal_json_obj_begin(j);
    gal_json_kv_num(j, "frequency_hz", m->frequency);
    gal_json_kv_num(j, "fundamental_hz", m->fundamental);
    gal_json_kv_int(j, "harmonic", m->harmonic);
    gal_json_key(j, "peaks_hz");
    gal_json_arr_begin(j);
    for (size_t q = 0; q < m->npeaks; q++) gal_json_num(j, m->peaks[q].frequency);
    gal_json_arr_end(j);
    gal_json_key(j, "peak_amplitudes");
    gal_json_arr_begin(j);
    for (size_t q = 0; q < m->npeaks; q++) gal_json_num(j, m->peaks[q].amplitude);
    gal_json_arr_end(j);
    gal_json_kv_num(j, "amplitude", m->amplitude);
    gal_json_kv_num(j, "amplitude_pp", m->peak_to_peak);
    gal_json_kv_num(j, "rms", m->rms);
    gal_json_kv_num(j, "mean", m->mean);
    gal_json_kv_num(j, "time_to_steady_s", tss);
    gal_json_obj_end(j);
}

static int write_summary(gal_outset *o, const char *path, const gal_trace *tr, const gal_trace_spectrum *s,
                         double wall)
{
    gal_json *j = gal_outset_summary(o);
    if (!j) return GAL_EIO;
    gal_json_kv_str(j, "trace", path);
    gal_json_kv_str(j, "time_column", tr->time_name);
    gal_json_kv_int(j, "samples", (long)tr->n);
    gal_json_kv_num(j, "dt_s", tr->dt);
    gal_json_kv_num(j, "steady_from_s", tr->t[s->i0]);
    gal_json_kv_str(j, "steady_from_rule", s->auto_from ? "auto" : "option --from");
    gal_json_kv_int(j, "steady_samples", (long)(tr->n - s->i0));
    gal_json_kv_int(j, "segment", (long)s->nseg);
    gal_json_kv_int(j, "segments", (long)s->nsegments);
    gal_json_kv_num(j, "frequency_resolution_hz", s->df);
    gal_json_key(j, "columns");
    gal_json_obj_begin(j);
    for (size_t c = 0; c < s->nsel; c++) {
        gal_json_key(j, tr->names[s->sel[c]]);
        json_column(j, &s->m[c], s->tss[c]);
    }
    gal_json_obj_end(j);
    if (s->npairs > 0) {
        gal_json_key(j, "orbit");
        gal_json_obj_begin(j);
        json_orbit(j, tr, &s->pairs[0]);
        gal_json_obj_end(j);
    }
    gal_json_key(j, "orbits");
    gal_json_arr_begin(j);
    for (size_t q = 0; q < s->npairs; q++) {
        gal_json_obj_begin(j);
        json_orbit(j, tr, &s->pairs[q]);
        gal_json_obj_end(j);
    }
    gal_json_arr_end(j);
    gal_json_kv_num(j, "wall_time_s", wall);
    return GAL_OK;
}

int gal_trace_spectrum_write(const char *dir, const char *trace_path, const gal_trace *tr,
                             const gal_trace_spectrum *s, double wall_time_s)
{
    gal_outset *o;
    int st = gal_outset_begin(&o, dir, "spectrum");
    if (!st) st = gal_outset_input(o, "trace_hash", trace_path); /* no scene: the trace's bytes */
    if (!st) st = write_psd(o, tr, s);
    if (!st) st = write_summary(o, trace_path, tr, s, wall_time_s);
    if (!st) st = gal_outset_commit(o);
    gal_outset_free(o);
    return st;
}

void gal_trace_spectrum_print(FILE *fp, const char *path, const gal_trace *tr, const gal_trace_spectrum *s)
{
    fprintf(fp, "trace %s: %zu samples, dt %.6g s, steady part from %.6g s (%s), Welch %zu x %zu "
                "samples, df %.6g Hz\n", path, tr->n, tr->dt, tr->t[s->i0], s->auto_from ? "auto" : "--from",
            s->nsegments, s->nseg, s->df);
    fprintf(fp, "%-20s %12s %12s %12s %12s %12s %12s %12s\n", "column", "mean", "rms", "peak-to-peak", "f1 [Hz]",
            "f2 [Hz]", "t_steady [s]", "f0 [Hz]");
    for (size_t c = 0; c < s->nsel; c++) {
        const gal_measures *m = &s->m[c];
        char b[7][32];
        fmt(b[0], 32, m->mean);
        fmt(b[1], 32, m->rms);
        fmt(b[2], 32, m->peak_to_peak);
        fmt(b[3], 32, m->npeaks > 0 ? m->peaks[0].frequency : NAN);
        fmt(b[4], 32, m->npeaks > 1 ? m->peaks[1].frequency : NAN);
        fmt(b[5], 32, s->tss[c]);
        fmt(b[6], 32, m->fundamental);
        fprintf(fp, "%-20s %12s %12s %12s %12s %12s %12s %12s\n", tr->names[s->sel[c]], b[0], b[1], b[2], b[3], b[4],
                b[5], b[6]);
    }
    for (size_t q = 0; q < s->npairs; q++)
        fprintf(fp, "orbit %s,%s: semi-axes %.6g and %.6g, tilt %.4g deg\n", tr->names[s->pairs[q].y],
                tr->names[s->pairs[q].z], s->pairs[q].orbit.major, s->pairs[q].orbit.minor,
                s->pairs[q].orbit.tilt_deg);
}
