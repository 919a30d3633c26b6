/* simwrite.c: the output files of `gallop simulate --model full` on the explicit bundle
 * (bundle_dyn.h; README "Bundles"): trace.csv with the bundle's centroid under the single rod's
 * column names, then every sub-conductor's probes and support tensions suffixed _s<k>; summary.json
 * with the run's counters and each probe's measures, the centroid's and each sub-conductor's. */
#include "gallop/bundle/bundle_dyn.h"
#include "gallop/base/core.h"
#include "gallop/analysis/measure.h"
#include "gallop/output/outset.h"
#include "bundle_impl.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const comp[4] = {"horizontal_m", "vertical_m", "along_m", "twist_deg"};

static void trace_csv(FILE *fp, const gal_bundle_sim_result *res)
{
    const gal_sim_result *c = &res->c;
    int np = c->nprobe, n = res->n;
    fprintf(fp, "time_s");
    for (int p = 0; p < np; p++)
        for (int k = 0; k < 4; k++) fprintf(fp, ",p%g_%s", c->probe[p], comp[k]);
    fprintf(fp, ",tension_left_n,tension_right_n");
    for (int r = 0; r < n; r++) {
        for (int p = 0; p < np; p++)
            for (int k = 0; k < 4; k++) fprintf(fp, ",p%g_%s_s%d", c->probe[p], comp[k], r + 1);
        fprintf(fp, ",tension_left_n_s%d,tension_right_n_s%d", r + 1, r + 1);
    }
    fputc('\n', fp);
    for (long i = 0; i < c->nsamples; i++) {
        fprintf(fp, "%.9f", c->time[i]);
        for (int k = 0; k < 4 * np; k++) fprintf(fp, ",%.8g", c->trace[(size_t)i * 4 * np + k]);
        fprintf(fp, ",%.8g,%.8g", c->tension[2 * i], c->tension[2 * i + 1]);
        for (int r = 0; r < n; r++) {
            const double *s = res->sub + ((size_t)i * n + r) * 4 * np;
            for (int k = 0; k < 4 * np; k++) fprintf(fp, ",%.8g", s[k]);
            fprintf(fp, ",%.8g,%.8g", res->tension[((size_t)i * n + r) * 2], res->tension[((size_t)i * n + r) * 2 + 1]);
        }
        fputc('\n', fp);
    }
}

static void json_measures(gal_json *j, const gal_sim_measures *m)
{
    gal_json_kv_num(j, "vertical_peak_to_peak_m", m->peak_to_peak[1]);
    gal_json_kv_num(j, "horizontal_peak_to_peak_m", m->peak_to_peak[0]);
    gal_json_kv_num(j, "twist_peak_to_peak_deg", m->peak_to_peak[3]);
    gal_json_kv_num(j, "vertical_frequency_hz", m->frequency_hz[1]);
    gal_json_kv_num(j, "time_to_steady_s", m->time_to_steady_s);
    gal_json_kv_num(j, "steady_from_s", m->steady_from_s);
    gal_json_kv_num(j, "tension_min_n", m->tension_min);
    gal_json_kv_num(j, "tension_max_n", m->tension_max);
}

/* Per probe: the centroid's measures, then each sub-conductor's over the same window. */
static int json_probes(gal_json *j, const gal_bundle_sim_result *res)
{
    const gal_sim_result *c = &res->c;
    gal_sim_result sr[GAL_BUNDLE_MAX];
    int st = GAL_OK, made = 0;
    for (; made < res->n && !st; made++) st = gal_bundle_sim_sub(res, made, &sr[made]);
    if (st) made--;
    gal_json_key(j, "probes");
    gal_json_arr_begin(j);
    for (int p = 0; p < c->nprobe && !st; p++) {
        gal_sim_measures mc, ms;
        if ((st = gal_sim_measure(c, p, -1, &mc))) break;
        gal_json_obj_begin(j);
        gal_json_kv_num(j, "position", c->probe[p]);
        gal_json_key(j, "centroid");
        gal_json_obj_begin(j);
        json_measures(j, &mc);
        gal_json_obj_end(j);
        gal_json_key(j, "subconductors");
        gal_json_arr_begin(j);
        for (int r = 0; r < res->n && !st; r++) {
            if ((st = gal_sim_measure(&sr[r], p, mc.steady_from_s, &ms))) break;
            gal_json_obj_begin(j);
            gal_json_kv_int(j, "sub", r + 1);
            json_measures(j, &ms);
            gal_json_obj_end(j);
        }
        gal_json_arr_end(j);
        gal_json_obj_end(j);
    }
    gal_json_arr_end(j);
    for (int r = 0; r < made; r++) free(sr[r].trace), free(sr[r].tension);
    return st;
}

static int write_summary(gal_outset *o, const gal_scene *sc, const gal_bundle_sim_result *res)
{
    const gal_sim_result *c = &res->c;
    gal_json *j = gal_outset_summary(o);
    if (!j) return GAL_EIO;
    gal_json_kv_str(j, "command", "simulate");
    gal_json_kv_str(j, "scene", sc->path);
    gal_json_kv_num(j, "duration_s", c->time[c->nsamples - 1]);
    gal_json_kv_num(j, "output_interval_s", c->dt_out);
    gal_json_key(j, "trace_csv");
    gal_json_obj_begin(j);
    gal_json_kv_str(j, "model", c->kind == GAL_MODEL_REDUCED ? "reduced" : "full");
    gal_json_kv_str(j, "holds", "time_s; per probe p<a> the bundle's centroid: displacements from the equilibrium "
                    "(horizontal y downwind, vertical z up, along x, m; the mean of the sub-conductors') and the "
                    "bundle's rotation about it in the twist column, deg; the support tensions summed over the "
                    "sub-conductors, N; then per sub-conductor k the same columns suffixed _s<k> (its own "
                    "displacements and twist, its support tensions)");
    gal_json_obj_end(j);
    gal_json_key(j, "bundle");
    gal_json_obj_begin(j);
    gal_json_kv_int(j, "subconductors", res->n);
    gal_json_kv_num(j, "radius_m", sc->bundle.radius);
    gal_json_kv_str(j, "model", "explicit");
    gal_json_kv_num(j, "wake_factor", res->wake_factor);
    gal_json_key(j, "leeward");
    gal_json_arr_begin(j);
    for (int r = 0; r < res->n; r++)
        if (res->leeward[r]) gal_json_int(j, r + 1);
    gal_json_arr_end(j);
    gal_json_kv_int(j, "dofs", res->ndof);
    gal_json_kv_str(j, "damping", res->damping_modes > 0 ? "modal" : res->alpha > 0 || res->beta > 0 ? "rayleigh" : "none");
    gal_json_kv_int(j, "damping_modes", res->damping_modes);
    gal_json_kv_num(j, "damping_band_hz", res->damping_band_hz);
    gal_json_kv_num(j, "rayleigh_alpha_per_s", res->alpha);
    gal_json_kv_num(j, "rayleigh_beta_s", res->beta);
    gal_json_obj_end(j);
    gal_json_kv_num(j, "setup_time_s", res->setup_time_s);
    gal_json_kv_num(j, "wall_time_s", c->wall_time_s);
    gal_json_kv_num(j, "time_step_s", c->time_step_s);
    gal_json_kv_int(j, "steps", c->steps);
    gal_json_kv_int(j, "newton_iterations", c->newton_iterations);
    gal_json_kv_int(j, "factorizations", c->factorizations);
    gal_json_kv_int(j, "rejected_steps", c->rejected_steps);
    if (c->checked) { /* the reduced model's self-check (bundle_rom.h) */
        gal_json_kv_int(j, "basis", c->basis);
        gal_json_kv_num(j, "build_time_s", c->build_time_s);
        gal_json_kv_num(j, "residual_max", c->residual_max);
        gal_json_key(j, "valid");
        gal_json_bool(j, c->valid);
    }
    return json_probes(j, res);
}

int gal_bundle_sim_write(const char *dir, const gal_scene *sc, const gal_bundle_sim_result *res)
{
    gal_outset *o;
    int st = gal_outset_begin(&o, dir, "simulate");
    if (!st) st = gal_outset_scene(o, sc);
    FILE *fp = st ? NULL : gal_outset_open(o, "trace.csv");
    if (!st && !fp) st = GAL_EIO;
    if (fp) trace_csv(fp, res), st = gal_outset_close(o, fp);
    if (!st) st = write_summary(o, sc, res);
    if (!st) st = gal_outset_commit(o);
    gal_outset_free(o);
    return st;
}
