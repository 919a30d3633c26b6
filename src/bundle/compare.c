/* compare.c: the output files of `gallop compare` on the explicit bundle (bundle_rom.h; README
 * "Bundles"): both runs' centroid, each family at its headline probe (analysis/compare.h: where the
 * full run's centroid moves most), under the single rod's compare.csv names, then every
 * sub-conductor's at the same probes suffixed _s<k> with its support tensions; summary.json with
 * the single rod's figures for the centroid and, per sub-conductor, both runs' measures as the
 * single rod's (gal_compare_measure: the centroid's window and headline probes) and their errors. */
#include "gallop/bundle/bundle_rom.h"
#include "gallop/base/core.h"
#include "gallop/analysis/compare.h"
#include "gallop/analysis/measure.h"
#include "gallop/output/outset.h"
#include "gallop/output/simreport.h"
#include "bundle_impl.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static double relerr(double a, double b)
{
    return fabs(a - b) / fmax(fabs(b), 1e-300);
}

static void csv_header(FILE *fp, int n)
{
    fprintf(fp, "time_s,full_vertical_m,reduced_vertical_m,full_horizontal_m,reduced_horizontal_m,full_twist_deg,"
                "reduced_twist_deg");
    for (int r = 1; r <= n; r++)
        fprintf(fp, ",full_vertical_m_s%d,reduced_vertical_m_s%d,full_horizontal_m_s%d,reduced_horizontal_m_s%d,"
                    "full_twist_deg_s%d,reduced_twist_deg_s%d,full_tension_left_n_s%d,reduced_tension_left_n_s%d,"
                    "full_tension_right_n_s%d,reduced_tension_right_n_s%d", r, r, r, r, r, r, r, r, r, r);
    fputc('\n', fp);
}

static int write_csv(gal_outset *o, const gal_bundle_sim_result *F, const gal_bundle_sim_result *R,
                     const gal_compare_figures *c)
{
    FILE *fp = gal_outset_open(o, "compare.csv");
    if (!fp) return GAL_EIO;
    int n = F->n, kv = 4 * c->headline[GAL_CMP_VERTICAL] + 1, kh = 4 * c->headline[GAL_CMP_HORIZONTAL];
    int kt = 4 * c->headline[GAL_CMP_TWIST] + 3;
    size_t np4 = 4 * (size_t)F->c.nprobe;
    csv_header(fp, n);
    long ns = F->c.nsamples < R->c.nsamples ? F->c.nsamples : R->c.nsamples;
    for (long i = 0; i < ns; i++) {
        const double *a = F->c.trace + i * np4, *b = R->c.trace + i * np4;
        fprintf(fp, "%.9g,%.8g,%.8g,%.8g,%.8g,%.8g,%.8g", F->c.time[i], a[kv], b[kv], a[kh], b[kh], a[kt], b[kt]);
        for (int r = 0; r < n; r++) {
            const double *sa = F->sub + ((size_t)i * n + r) * np4, *sb = R->sub + ((size_t)i * n + r) * np4;
            const double *ta = F->tension + ((size_t)i * n + r) * 2, *tb = R->tension + ((size_t)i * n + r) * 2;
            fprintf(fp, ",%.8g,%.8g,%.8g,%.8g,%.8g,%.8g,%.8g,%.8g,%.8g,%.8g", sa[kv], sb[kv], sa[kh], sb[kh], sa[kt],
                    sb[kt], ta[0], tb[0], ta[1], tb[1]);
        }
        fputc('\n', fp);
    }
    return gal_outset_close(o, fp);
}

static void json_measures(gal_json *j, const gal_sim_measures *m)
{
    gal_json_kv_num(j, "frequency_hz", m->frequency_hz[1]);
    gal_json_kv_num(j, "vertical_peak_to_peak_m", m->peak_to_peak[1]);
    gal_json_kv_num(j, "horizontal_peak_to_peak_m", m->peak_to_peak[0]);
    gal_json_kv_num(j, "twist_peak_to_peak_deg", m->peak_to_peak[3]);
    gal_json_kv_num(j, "tension_min_n", m->tension_min);
    gal_json_kv_num(j, "tension_max_n", m->tension_max);
}

static void json_errors(gal_json *j, const gal_sim_measures *f, const gal_sim_measures *r)
{
    gal_json_key(j, "errors");
    gal_json_obj_begin(j);
    gal_json_kv_num(j, "frequency", relerr(r->frequency_hz[1], f->frequency_hz[1]));
    gal_json_kv_num(j, "vertical", relerr(r->peak_to_peak[1], f->peak_to_peak[1]));
    gal_json_kv_num(j, "horizontal", relerr(r->peak_to_peak[0], f->peak_to_peak[0]));
    gal_json_kv_num(j, "twist", relerr(r->peak_to_peak[3], f->peak_to_peak[3]));
    gal_json_kv_num(j, "tension_max", relerr(r->tension_max, f->tension_max));
    gal_json_obj_end(j);
}

static void json_run(gal_json *j, const char *key, const gal_bundle_sim_result *b, const gal_sim_measures *m)
{
    const gal_sim_result *r = &b->c;
    gal_json_key(j, key);
    gal_json_obj_begin(j);
    gal_json_kv_str(j, "model", r->kind == GAL_MODEL_REDUCED ? "reduced" : "full");
    gal_json_kv_num(j, "setup_time_s", b->setup_time_s);
    gal_json_kv_num(j, "wall_time_s", r->wall_time_s);
    gal_json_kv_num(j, "wall_time_per_simulated_s", r->wall_time_s / r->time[r->nsamples - 1]);
    json_measures(j, m);
    gal_json_kv_int(j, "steps", r->steps);
    gal_json_kv_int(j, "newton_iterations", r->newton_iterations);
    if (r->checked) {
        gal_json_kv_int(j, "basis", r->basis);
        gal_json_kv_num(j, "build_time_s", r->build_time_s);
        gal_json_kv_num(j, "residual_max", r->residual_max);
        gal_json_key(j, "valid");
        gal_json_bool(j, r->valid);
    }
    gal_json_obj_end(j);
}

/* Per sub-conductor: both runs' measures over the centroid's window, each family at the centroid's
 * headline probe (gal_compare_measure, as the centroid's record). */
static int json_subs(gal_json *j, const gal_bundle_sim_result *F, const gal_bundle_sim_result *R,
                     const gal_compare_figures *c)
{
    int st = GAL_OK;
    gal_compare_ref h;
    memset(&h, 0, sizeof h);
    h.from = c->full.steady_from_s;
    for (int f = 0; f < GAL_CMP_FAMILIES; f++) h.headline[f] = c->headline[f], h.position[f] = F->c.probe[c->headline[f]];
    gal_json_key(j, "subconductors");
    gal_json_arr_begin(j);
    for (int r = 0; r < F->n && !st; r++) {
        gal_sim_result sf, sr;
        gal_sim_measures mf, mr;
        memset(&sf, 0, sizeof sf), memset(&sr, 0, sizeof sr);
        st = gal_bundle_sim_sub(F, r, &sf);
        if (!st) st = gal_bundle_sim_sub(R, r, &sr);
        if (!st) st = gal_compare_measure(&sf, &h, &mf);
        if (!st) st = gal_compare_measure(&sr, &h, &mr);
        if (!st) {
            gal_json_obj_begin(j);
            gal_json_kv_int(j, "sub", r + 1);
            gal_json_key(j, "full");
            gal_json_obj_begin(j), json_measures(j, &mf), gal_json_obj_end(j);
            gal_json_key(j, "reduced");
            gal_json_obj_begin(j), json_measures(j, &mr), gal_json_obj_end(j);
            json_errors(j, &mf, &mr);
            gal_json_obj_end(j);
        }
        free(sf.trace), free(sf.tension), free(sr.trace), free(sr.tension);
    }
    gal_json_arr_end(j);
    return st;
}

static int write_summary(gal_outset *o, const gal_scene *sc, const gal_bundle_sim_result *F,
                         const gal_bundle_sim_result *R, const gal_sim_measures *mf, const gal_sim_measures *mr,
                         const gal_compare_figures *c)
{
    gal_json *j = gal_outset_summary(o);
    if (!j) return GAL_EIO;
    gal_json_kv_str(j, "command", "compare");
    gal_json_kv_str(j, "scene", sc->path);
    gal_json_kv_num(j, "duration_s", F->c.time[F->c.nsamples - 1]);
    gal_json_kv_num(j, "steady_from_s", mf->steady_from_s);
    gal_json_key(j, "bundle");
    gal_json_obj_begin(j);
    gal_json_kv_int(j, "subconductors", F->n);
    gal_json_kv_str(j, "model", "explicit");
    gal_json_kv_int(j, "dofs", F->ndof);
    gal_json_kv_str(j, "centroid", "full and reduced: the bundle's centroid at the mid probe (its rotation in twist)");
    gal_json_obj_end(j);
    json_run(j, "full", F, mf);
    json_run(j, "reduced", R, mr);
    gal_compare_figures_json(j, c);
    return json_subs(j, F, R, c);
}

int gal_bundle_write_compare(const char *dir, const gal_scene *sc, const gal_bundle_sim_result *full,
                             const gal_bundle_sim_result *red, gal_compare_figures *out)
{
    gal_compare_figures c; /* analysis/compare.c: every probe, each family's headline where it moves most */
    int st = gal_compare_runs(&full->c, &red->c, -1, &c);
    if (st) return st;
    const gal_sim_measures *mf = &c.full, *mr = &c.reduced;
    if (out) *out = c;
    gal_outset *o;
    st = gal_outset_begin(&o, dir, "compare");
    if (!st) st = gal_outset_scene(o, sc);
    if (!st) st = write_csv(o, full, red, &c);
    if (!st) st = write_summary(o, sc, full, red, mf, mr, &c);
    if (!st) st = gal_outset_commit(o);
    gal_outset_free(o);
    return st;
}
