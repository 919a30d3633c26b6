/* simreport.c: the files of a galloping run, each command's as one output set (outset.h):
 * trace.csv and summary.json of `gallop simulate` (the measures of analysis/measure.c),
 * compare.csv and summary.json of `gallop compare` (the figures of analysis/compare.c). */
#include "gallop/output/simreport.h"
#include "gallop/base/core.h"
#include "gallop/output/cigrereport.h"
#include "gallop/output/json.h"
#include "gallop/output/ofile.h"
#include "gallop/output/outset.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *const comp_names[4] = {"horizontal", "vertical", "along", "twist"};

static void json_measures(gal_json *j, const gal_sim_measures *m)
{
    gal_json_kv_num(j, "time_to_steady_s", m->time_to_steady_s);
    gal_json_kv_num(j, "rise_time_90_s", m->rise_time_s);
    gal_json_kv_num(j, "steady_from_s", m->steady_from_s);
    for (int c = 0; c < 4; c++) {
        gal_json_key(j, comp_names[c]);
        gal_json_obj_begin(j);
        const char *u = c == 3 ? "deg" : "m";
        char key[64];
        gal_json_kv_num(j, "frequency_hz", m->frequency_hz[c]);
        gal_json_kv_num(j, "dominant_frequency_hz", m->dominant_hz[c]);
        gal_json_kv_int(j, "harmonic", m->harmonic[c]);
        snprintf(key, sizeof key, "peak_to_peak_%s", u);
        gal_json_kv_num(j, key, m->peak_to_peak[c]);
        snprintf(key, sizeof key, "rms_%s", u);
        gal_json_kv_num(j, key, m->rms[c]);
        snprintf(key, sizeof key, "mean_%s", u);
        gal_json_kv_num(j, key, m->mean[c]);
        gal_json_obj_end(j);
    }
    gal_json_key(j, "orbit");
    gal_json_obj_begin(j);
    gal_json_kv_num(j, "major_semi_axis_m", m->orbit_major);
    gal_json_kv_num(j, "minor_semi_axis_m", m->orbit_minor);
    gal_json_kv_num(j, "tilt_deg", m->orbit_tilt_deg);
    gal_json_obj_end(j);
}

/* the figures of one run, as an object's members */
static void json_run(gal_json *j, const gal_sim_result *r, const gal_sim_measures *mid)
{
    gal_json_kv_str(j, "model", r->kind == GAL_MODEL_FULL ? "full" : "reduced");
    gal_json_kv_num(j, "wall_time_s", r->wall_time_s);
    gal_json_kv_num(j, "build_time_s", r->build_time_s);
    double dur = r->time[r->nsamples - 1];
    gal_json_kv_num(j, "wall_time_per_simulated_s", dur > 0 ? r->wall_time_s / dur : NAN);
    gal_json_kv_num(j, "frequency_hz", mid->frequency_hz[1]);
    gal_json_kv_num(j, "dominant_frequency_hz", mid->dominant_hz[1]);
    gal_json_kv_int(j, "harmonic", mid->harmonic[1]);
    gal_json_key(j, "amplitude_m");
    gal_json_obj_begin(j);
    gal_json_kv_num(j, "vertical", mid->peak_to_peak[1]);
    gal_json_kv_num(j, "horizontal", mid->peak_to_peak[0]);
    gal_json_obj_end(j);
    gal_json_kv_num(j, "twist_amplitude_deg", mid->peak_to_peak[3]);
    gal_json_kv_num(j, "time_to_steady_s", mid->time_to_steady_s);
    gal_json_kv_num(j, "rise_time_90_s", mid->rise_time_s);
    /* the support tensions: tension_*_n are the whole run's (measure.h) */
    gal_json_kv_num(j, "tension_min_n", mid->tension_min);
    gal_json_kv_num(j, "tension_max_n", mid->tension_max);
    gal_json_kv_num(j, "tension_min_run_n", mid->tension_min);
    gal_json_kv_num(j, "tension_max_run_n", mid->tension_max);
    gal_json_kv_num(j, "tension_min_steady_n", mid->tension_min_steady);
    gal_json_kv_num(j, "tension_max_steady_n", mid->tension_max_steady);
    gal_json_key(j, "counters");
    gal_json_obj_begin(j);
    gal_json_kv_int(j, "steps", r->steps);
    gal_json_kv_int(j, "rejected_steps", r->rejected_steps);
    gal_json_kv_int(j, "newton_iterations", r->newton_iterations);
    gal_json_kv_int(j, "factorizations", r->factorizations);
    gal_json_kv_int(j, "force_evaluations", r->force_evaluations);
    gal_json_kv_num(j, "time_step_s", r->time_step_s);
    gal_json_kv_int(j, "basis_modes", r->basis);
    gal_json_obj_end(j);
    if (r->checked) {
        /* the reduced model's self-check */
        gal_json_kv_num(j, "residual_max", r->residual_max);
        gal_json_key(j, "valid");
        gal_json_bool(j, r->valid);
        gal_json_kv_int(j, "basis_start", r->basis_start);
        gal_json_kv_int(j, "basis", r->basis);
        gal_json_key(j, "basis_growths"); /* rom_adapt.h: when and what the adaptation added */
        gal_json_arr_begin(j);
        for (int k = 0; k < r->growths; k++) {
            const gal_rom_event *e = &r->growth[k];
            gal_json_obj_begin(j);
            gal_json_kv_num(j, "time_s", e->t_s);
            gal_json_kv_num(j, "residual", e->residual);
            gal_json_kv_str(j, "family", gal_family_names[e->family]);
            gal_json_kv_int(j, "basis_before", e->basis_before);
            gal_json_kv_int(j, "basis_after", e->basis_after);
            /* the mode by its frequency: the adaptation may have computed more modes than modes.csv lists */
            if (e->mode_added >= 0) gal_json_kv_num(j, "mode_added_hz", e->mode_added_hz);
            gal_json_kv_int(j, "corrections_added", e->corrections);
            gal_json_obj_end(j);
        }
        gal_json_arr_end(j);
    }
}

static int write_summary(gal_outset *o, const gal_scene *sc, const gal_sim_result *r, gal_sim_measures *mid_out)
{
    gal_json *j = gal_outset_summary(o);
    if (!j) return GAL_EIO;
    gal_json_kv_str(j, "command", "simulate");
    gal_json_kv_str(j, "scene", sc->path);
    gal_json_kv_num(j, "duration_s", r->time[r->nsamples - 1]);
    gal_json_kv_num(j, "output_interval_s", r->dt_out);
    /* what trace.csv holds (the CSV itself starts with its header line) */
    gal_json_key(j, "trace_csv");
    gal_json_obj_begin(j);
    gal_json_kv_str(j, "model", r->kind == GAL_MODEL_FULL ? "full" : "reduced");
    gal_json_kv_str(j, "holds", "time_s; per probe p<a> (a: fraction of the span) the displacements from the "
                    "equilibrium, horizontal (y, downwind), vertical (z, up), along (x), m, and the twist, deg; "
                    "the support tensions, N");
    gal_json_obj_end(j);
    if (sc->bundle.subconductors > 1) { /* the traces and tensions are the bundle's */
        gal_json_key(j, "bundle");
        gal_json_obj_begin(j);
        gal_json_kv_num(j, "subconductors", sc->bundle.subconductors);
        gal_json_kv_num(j, "radius_m", sc->bundle.radius);
        gal_json_kv_str(j, "model", "equivalent");
        gal_json_kv_str(j, "holds", "probes: the bundle's centre and twist; tensions: the bundle's, the sum "
                        "over its sub-conductors (the equivalent model does not split it: each carries "
                        "1/subconductors of it)");
        gal_json_obj_end(j);
    }
    int mid = gal_sim_mid_probe(r), st;
    gal_sim_measures m[GAL_MAX_PROBES]; /* each probe measured once (the mid-span one is the run's too) */
    for (int k = 0; k < r->nprobe; k++)
        if ((st = gal_sim_measure(r, k, -1, m + k))) return st;
    json_run(j, r, m + mid);
    if (mid_out) *mid_out = m[mid];
    double from[GAL_MAX_PROBES];
    gal_json_key(j, "probes");
    gal_json_arr_begin(j);
    for (int k = 0; k < r->nprobe; k++) {
        gal_json_obj_begin(j);
        gal_json_kv_num(j, "position", r->probe[k]);
        json_measures(j, m + k);
        from[k] = m[k].steady_from_s;
        if ((st = gal_cigre_json_probe(j, sc, r, k, from[k]))) return st;   /* ellipse, clearances */
        gal_json_obj_end(j);
    }
    gal_json_arr_end(j);
    /* the rated strength of the scene's conductor (0: unknown, its ratio left out) */
    /* the tensions of a bundle are the bundle's: set them against its sub-conductors' strength */
    double rts = sc->conductor.rated_strength > 0 ? sc->conductor.rated_strength * sc->bundle.subconductors
                                                  : NAN;
    return gal_cigre_json_run(j, sc, r, from, rts);
}

/* Decimals of the time stamps: at least 6, and enough that consecutive samples dt_out apart
 * never print alike (a hundredth of the interval resolved). */
static int time_decimals(double dt_out)
{
    int d = 6;
    while (d < 17 && !(dt_out * pow(10.0, d) >= 100.0)) d++;
    return d;
}

/* the trace of a run, one line per sample */
static void trace_csv(FILE *fp, const gal_sim_result *res)
{
    fprintf(fp, "time_s");
    for (int k = 0; k < res->nprobe; k++) {
        double a = res->probe[k];
        fprintf(fp, ",p%g_horizontal_m,p%g_vertical_m,p%g_along_m,p%g_twist_deg", a, a, a, a);
    }
    fprintf(fp, ",tension_left_n,tension_right_n\n");
    int td = time_decimals(res->dt_out);
    for (long i = 0; i < res->nsamples; i++) {
        fprintf(fp, "%.*f", td, res->time[i]);
        for (int c = 0; c < 4 * res->nprobe; c++) fprintf(fp, ",%.8g", res->trace[(size_t)i * 4 * res->nprobe + c]);
        fprintf(fp, ",%.8g,%.8g\n", res->tension[2 * i], res->tension[2 * i + 1]);
    }
}

int gal_sim_write(const char *dir, const gal_scene *sc, const gal_sim_result *r)
{
    return gal_sim_write_measured(dir, sc, r, NULL);
}

int gal_sim_write_measured(const char *dir, const gal_scene *sc, const gal_sim_result *r, gal_sim_measures *mid)
{
    gal_outset *o;
    int st = gal_outset_begin(&o, dir, "simulate");
    if (!st) st = gal_outset_scene(o, sc);
    FILE *fp = st ? NULL : gal_outset_open(o, "trace.csv");
    if (!st && !fp) st = GAL_EIO;
    if (fp) trace_csv(fp, r), st = gal_outset_close(o, fp);
    if (!st) st = write_summary(o, sc, r, mid);
    if (!st) st = gal_outset_commit(o);
    gal_outset_free(o);
    return st;
}

int gal_sim_write_trace(const char *path, const gal_sim_result *res)
{
    gal_ofile f;
    int st = gal_ofile_open(&f, path);
    if (st) return st;
    trace_csv(f.fp, res);
    return gal_ofile_close(&f, 1);
}

/* compare.csv: the headline columns (each family at its headline probe, compare.h), then every
 * probe's under the trace's names p<a>_..., prefixed full_ and reduced_ */
static int write_compare_csv(gal_outset *o, const gal_sim_result *full, const gal_sim_result *red,
                             const gal_compare_figures *c)
{
    FILE *fp = gal_outset_open(o, "compare.csv");
    if (!fp) return GAL_EIO;
    static const int comp[3] = {1, 0, 3};
    static const char *const name[3] = {"vertical_m", "horizontal_m", "twist_deg"};
    int wf = 4 * full->nprobe, wr = 4 * red->nprobe, td = time_decimals(full->dt_out);
    fprintf(fp, "time_s,full_vertical_m,reduced_vertical_m,full_horizontal_m,reduced_horizontal_m,"
                "full_twist_deg,reduced_twist_deg");
    for (int k = 0; k < c->nprobe; k++)
        for (int f = 0; f < 3; f++)
            fprintf(fp, ",full_p%g_%s,reduced_p%g_%s", full->probe[k], name[f], full->probe[k], name[f]);
    fputc('\n', fp);
    long n = full->nsamples < red->nsamples ? full->nsamples : red->nsamples;
    for (long i = 0; i < n; i++) {
        const double *a = full->trace + (size_t)i * wf, *b = red->trace + (size_t)i * wr;
        fprintf(fp, "%.*f", td, full->time[i]);
        for (int f = 0; f < 3; f++) {
            int k = 4 * c->headline[f] + comp[f];
            fprintf(fp, ",%.8g,%.8g", a[k], b[k]);
        }
        for (int k = 0; k < c->nprobe; k++)
            for (int f = 0; f < 3; f++) fprintf(fp, ",%.8g,%.8g", a[4 * k + comp[f]], b[4 * k + comp[f]]);
        fputc('\n', fp);
    }
    return gal_outset_close(o, fp);
}

/* one run's measures at one probe, as an object's members */
static void json_probe_run(gal_json *j, const char *key, const gal_sim_measures *m)
{
    gal_json_key(j, key);
    gal_json_obj_begin(j);
    gal_json_kv_num(j, "frequency_hz", m->frequency_hz[1]);
    gal_json_kv_num(j, "dominant_frequency_hz", m->dominant_hz[1]);
    gal_json_kv_int(j, "harmonic", m->harmonic[1]);
    gal_json_kv_num(j, "vertical_peak_to_peak_m", m->peak_to_peak[1]);
    gal_json_kv_num(j, "horizontal_peak_to_peak_m", m->peak_to_peak[0]);
    gal_json_kv_num(j, "twist_peak_to_peak_deg", m->peak_to_peak[3]);
    gal_json_obj_end(j);
}

/* headline_probes and probes (the per-probe figures) */
static void json_compare_probes(gal_json *j, const gal_compare_figures *c)
{
    static const char *const fam[GAL_CMP_FAMILIES] = {"vertical", "horizontal", "twist"};
    gal_json_key(j, "full_window"); /* the reference's steadiness over the window (compare.h) */
    gal_json_obj_begin(j);
    gal_json_kv_num(j, "vertical_peak_to_peak_first_half_m", c->window_pp_first);
    gal_json_kv_num(j, "vertical_peak_to_peak_second_half_m", c->window_pp_second);
    gal_json_kv_num(j, "drift", c->window_drift);
    gal_json_kv_num(j, "horizontal_peak_to_peak_first_half_m", c->family_first[GAL_CMP_HORIZONTAL]);
    gal_json_kv_num(j, "horizontal_peak_to_peak_second_half_m", c->family_second[GAL_CMP_HORIZONTAL]);
    gal_json_kv_num(j, "horizontal_drift", c->family_drift[GAL_CMP_HORIZONTAL]);
    gal_json_kv_num(j, "twist_peak_to_peak_first_half_deg", c->family_first[GAL_CMP_TWIST]);
    gal_json_kv_num(j, "twist_peak_to_peak_second_half_deg", c->family_second[GAL_CMP_TWIST]);
    gal_json_kv_num(j, "twist_drift", c->family_drift[GAL_CMP_TWIST]);
    gal_json_key(j, "steady");
    gal_json_bool(j, c->full_steady);
    gal_json_kv_num(j, "from_s", c->full.steady_from_s);
    gal_json_kv_num(j, "automatic_from_s", c->window_first_from_s);
    gal_json_key(j, "moved");
    gal_json_bool(j, c->window_moved);
    gal_json_obj_end(j);
    gal_json_key(j, "headline_probes");
    gal_json_obj_begin(j);
    for (int f = 0; f < GAL_CMP_FAMILIES; f++) gal_json_kv_num(j, fam[f], c->probe[c->headline[f]].position);
    gal_json_obj_end(j);
    gal_json_key(j, "probes");
    gal_json_arr_begin(j);
    for (int k = 0; k < c->nprobe; k++) {
        const gal_compare_probe *p = c->probe + k;
        gal_json_obj_begin(j);
        gal_json_kv_num(j, "position", p->position);
        json_probe_run(j, "full", &p->full);
        json_probe_run(j, "reduced", &p->reduced);
        gal_json_kv_num(j, "frequency_error", p->frequency_error);
        gal_json_key(j, "amplitude_errors");
        gal_json_obj_begin(j);
        for (int f = 0; f < GAL_CMP_FAMILIES; f++) gal_json_kv_num(j, fam[f], p->err[f]);
        gal_json_obj_end(j);
        gal_json_obj_end(j);
    }
    gal_json_arr_end(j);
}

void gal_compare_figures_json(gal_json *j, const gal_compare_figures *c)
{
    gal_json_kv_num(j, "frequency_error", c->frequency_error);
    gal_json_kv_num(j, "amplitude_error", c->amplitude_error);
    gal_json_key(j, "amplitude_errors");
    gal_json_obj_begin(j);
    gal_json_kv_num(j, "vertical", c->err_vertical);
    gal_json_kv_num(j, "horizontal", c->err_horizontal);
    gal_json_kv_num(j, "twist", c->err_twist);
    gal_json_obj_end(j);
    gal_json_kv_num(j, "speedup", c->speedup);
    json_compare_probes(j, c);
}

static int write_compare_summary(gal_outset *o, const gal_scene *sc, const gal_sim_result *full,
                                 const gal_sim_result *red, const gal_compare_figures *c)
{
    gal_json *j = gal_outset_summary(o);
    if (!j) return GAL_EIO;
    gal_json_kv_str(j, "command", "compare");
    gal_json_kv_str(j, "scene", sc->path);
    gal_json_kv_num(j, "duration_s", full->time[full->nsamples - 1]);
    gal_json_kv_num(j, "steady_from_s", c->full.steady_from_s);
    gal_json_key(j, "full");
    gal_json_obj_begin(j);
    json_run(j, full, &c->full);
    gal_json_obj_end(j);
    gal_json_key(j, "reduced");
    gal_json_obj_begin(j);
    json_run(j, red, &c->reduced);
    gal_json_obj_end(j);
    gal_compare_figures_json(j, c);
    return GAL_OK;
}

int gal_sim_write_compare(const char *dir, const gal_scene *sc, const gal_sim_result *full,
                          const gal_sim_result *red, gal_compare_figures *out)
{
    gal_compare_figures c;
    int st = gal_compare_runs(full, red, -1, &c);
    if (st) return st;
    if (out) *out = c;
    gal_outset *o;
    st = gal_outset_begin(&o, dir, "compare");
    if (!st) st = gal_outset_scene(o, sc);
    if (!st) st = write_compare_csv(o, full, red, &c);
    if (!st) st = write_compare_summary(o, sc, full, red, &c);
    if (!st) st = gal_outset_commit(o);
    gal_outset_free(o);
    return st;
}
