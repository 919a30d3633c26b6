/* sweep_case.c: one case of a sweep (sweep.h): the scene run as `gallop simulate` runs it (the
 * pipeline to the start, gal_run with the full or the scene's reduced integrator), or continued
 * from a given state (gal_data_start_from); the measures at the first probe; the coupled onset
 * about the mean-wind equilibrium as `gallop stability` finds it (analysis/onset.h), once per
 * span and process; the equilibrium and modes kept from case to case while their key holds
 * (gal_sweep_setup_cache), and with them the reduced model's own wind-independent set-up
 * (gal_data.rom_setup). An explicit bundle runs its full model and its coupled onset (bundle_dyn.h),
 * with each sub-conductor's measures. */
#include "gallop/run/sweep.h"
#include "gallop/analysis/measure.h"
#include "gallop/analysis/onset.h"
#include "gallop/bundle/bundle_dyn.h"
#include "gallop/run/onset_scene.h"
#include "gallop/base/core.h"
#include "gallop/output/record.h"
#include "gallop/run/sim.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* The scene less what the onset analysis ignores (the wind speed, [simulation]), hashed with its
 * aero table's bytes: the cache's key. */
static int onset_key(const gal_scene *sc, uint64_t *key)
{
    gal_scene *c = malloc(sizeof *c);
    if (!c) return gal_error(GAL_ENOMEM, "sweep: out of memory");
    *c = *sc;
    c->wind.speed = 0;
    memset(&c->simulation, 0, sizeof c->simulation);
    uint64_t h = 0, t = 0;
    long bytes = 0;
    int st = gal_record_scene_hash(c, &h);
    free(c);
    if (!st) st = gal_record_file_hash(sc->ice.aero_table, &t, &bytes);
    *key = gal_record_fnv1a64(&t, sizeof t, h);
    return st;
}

/* The onset kept in cache->dir: 1 found (*speed), 0 not. */
static int disk_get(const gal_sweep_onset_cache *cache, uint64_t key, double *speed)
{
    char path[GAL_PATH_MAX + 40];
    snprintf(path, sizeof path, "%s/onset-%016" PRIx64, cache->dir, key);
    FILE *fp = fopen(path, "r");
    int ok = fp && fscanf(fp, "%lf", speed) == 1;
    if (fp) fclose(fp);
    return ok;
}

/* ... written whole or not at all (another process may read it at any time) */
static void disk_put(const gal_sweep_onset_cache *cache, uint64_t key, double speed)
{
    char path[GAL_PATH_MAX + 40], tmp[GAL_PATH_MAX + 64];
    snprintf(path, sizeof path, "%s/onset-%016" PRIx64, cache->dir, key);
    snprintf(tmp, sizeof tmp, "%s.tmp.%ld", path, (long)getpid());
    FILE *fp = fopen(tmp, "w");
    if (!fp) return;
    int ok = fprintf(fp, "%.17g\n", speed) > 0;
    if (fclose(fp) != 0 || !ok || rename(tmp, path) != 0) remove(tmp);
}

/* The coupled onset of the span (NaN: stable over the [stability] range), as `gallop stability`. */
static int onset_compute(const gal_scene *sc, double *speed)
{
    gal_onset O;
    int st = gal_sweep_explicit_bundle(sc) ? gal_bundle_scene_onset(sc, &O) : gal_scene_onset(sc, &O);
    if (!st) *speed = O.onset_speed, gal_onset_clear(&O);
    return st;
}

/* The onset from the cache (memory, then the files), else computed and kept. */
static int onset_of(const gal_scene *sc, gal_sweep_onset_cache *cache, double *speed)
{
    uint64_t key = 0;
    int st = cache ? onset_key(sc, &key) : GAL_OK;
    if (st) return st;
    if (!cache) return onset_compute(sc, speed);
    for (int i = 0; i < cache->n; i++)
        if (cache->key[i] == key) {
            *speed = cache->speed[i];
            return GAL_OK;
        }
    if (!(cache->dir && disk_get(cache, key, speed))) {
        if ((st = onset_compute(sc, speed))) return st;
        if (cache->dir) disk_put(cache, key, *speed);
    }
    cache->key[cache->next] = key, cache->speed[cache->next] = *speed;
    cache->next = (cache->next + 1) % GAL_SWEEP_ONSET_CACHE;
    if (cache->n < GAL_SWEEP_ONSET_CACHE) cache->n++;
    return GAL_OK;
}

int gal_sweep_explicit_bundle(const gal_scene *sc)
{
    return sc->bundle.subconductors > 1 && sc->bundle.explicit_model;
}

/* An explicit bundle's run (full model, from rest): the centroid's measures at the first probe,
 * then each sub-conductor's over the centroid's steady window. */
static int run_bundle(const gal_scene *sc, gal_sweep_result *r)
{
    int st;
    gal_model *m = gal_model_alloc(sc, &st);
    gal_run_opts o;
    gal_run_opts_from_scene(sc, &o);
    gal_bundle_sim_result res;
    memset(&res, 0, sizeof res);
    if (!st) st = gal_bundle_simulate(m, &o, &res);
    gal_sim_measures mc, ms;
    if (!st) st = gal_sim_measure(&res.c, 0, -1, &mc);
    if (!st) {
        r->horizontal_pp_m = mc.peak_to_peak[0], r->vertical_pp_m = mc.peak_to_peak[1];
        r->twist_pp_deg = mc.peak_to_peak[3], r->frequency_hz = mc.frequency_hz[1];
        r->tension_max_n = mc.tension_max_steady;
        r->nsub = res.n < GAL_SWEEP_MAX_SUB ? res.n : GAL_SWEEP_MAX_SUB;
    }
    for (int k = 0; !st && k < r->nsub; k++) {
        gal_sim_result sr;
        st = gal_bundle_sim_sub(&res, k, &sr);
        if (!st) st = gal_sim_measure(&sr, 0, mc.steady_from_s, &ms);
        if (!st) {
            r->sub_horizontal_pp_m[k] = ms.peak_to_peak[0], r->sub_vertical_pp_m[k] = ms.peak_to_peak[1];
            r->sub_twist_pp_deg[k] = ms.peak_to_peak[3], r->sub_tension_max_n[k] = ms.tension_max_steady;
        }
        free(sr.trace), free(sr.tension);
    }
    gal_bundle_sim_result_clear(&res);
    gal_model_free(m);
    return st;
}

void gal_sweep_setup_cache_clear(gal_sweep_setup_cache *c)
{
    for (int i = 0; i < c->n; i++) {
        gal_data_free(c->d[i]);
        gal_model_free(c->m[i]);
    }
    memset(c, 0, sizeof *c);
}

/* The equilibrium and modes of d from the cache when it holds those of m's key (*reused: 1 with
 * the damping, 2 without; gal_sweep_result.setup_reused). */
static int setup_take(gal_sweep_setup_cache *c, const gal_model *m, gal_data *d, uint64_t *key, int *reused)
{
    *reused = 0;
    if (!c) return GAL_OK;
    int st = gal_stage_key(m, GAL_STAGE_MODES, key);
    for (int i = 0; !st && i < c->n; i++)
        if (c->key[i] == *key) {
            if ((st = gal_data_share(m, d, c->d[i], GAL_STAGE_MODES))) return st;
            *reused = d->damping_borrowed ? 1 : 2;
            return GAL_OK;
        }
    return st;
}

/* A case's model and data into the cache (in place of the oldest), or freed when the case
 * borrowed its set-up or failed before its modes. */
static void setup_keep(gal_sweep_setup_cache *c, gal_model *m, gal_data *d, uint64_t key, int reused)
{
    if (c && !reused && d && d->stage >= GAL_STAGE_MODES && d->borrowed == GAL_STAGE_NONE) {
        int i = c->next;
        if (i < c->n) gal_data_free(c->d[i]), gal_model_free(c->m[i]);
        else c->n++;
        c->m[i] = m, c->d[i] = d, c->key[i] = key;
        c->next = (i + 1) % GAL_SWEEP_SETUP_CACHE;
        return;
    }
    gal_data_free(d);
    gal_model_free(m);
}

/* The measures of a run into r. */
static void measures_of(const gal_sim_measures *ms, const gal_sim_result *res, gal_sweep_result *r)
{
    r->horizontal_pp_m = ms->peak_to_peak[0], r->vertical_pp_m = ms->peak_to_peak[1];
    r->twist_pp_deg = ms->peak_to_peak[3], r->frequency_hz = ms->frequency_hz[1];
    r->tension_max_n = ms->tension_max_steady;
    r->valid = res->checked ? res->valid : -1;
    r->residual_max = res->checked ? res->residual_max : NAN;
}

/* The run itself, its end state into q_end, v_end when given; the set-up from and into `setup`. */
static int run_case(const gal_scene *sc, gal_model_kind kind, const double *q0, const double *v0, int nq0,
                    gal_sweep_setup_cache *setup, gal_sweep_result *r, double **q_end, double **v_end, int *nq)
{
    int st;
    uint64_t key = 0;
    gal_model *m = gal_model_alloc(sc, &st);
    gal_data *d = m ? gal_data_alloc(m) : NULL;
    if (m && !d) st = GAL_ENOMEM;
    if (!st) st = setup_take(setup, m, d, &key, &r->setup_reused);
    if (!st) st = gal_forward(m, d, GAL_STAGE_START);
    const gal_integrator_type *T = NULL;
    if (!st) T = kind == GAL_MODEL_FULL ? &gal_integrator_full : &gal_integrator_reduced;
    if (!st && q0 && nq0 != d->eq.rod->nq)
        st = gal_error(GAL_EINPUT, "%s: --continuation: this case has %d unknowns, the one it continues %d: the "
                       "varied keys must keep the mesh ([model] elements, effects)", sc->path, d->eq.rod->nq, nq0);
    if (!st && q0) st = gal_data_start_from(m, d, q0, v0);
    gal_run_opts o;
    gal_run_opts_from_scene(sc, &o);
    if (!st) st = gal_run_check_measurable(m, d, &o);
    if (!st && q_end) {
        *nq = d->eq.rod->nq;
        *q_end = malloc((size_t)*nq * sizeof(double));
        *v_end = malloc((size_t)*nq * sizeof(double));
        if (!*q_end || !*v_end) st = gal_error(GAL_ENOMEM, "sweep: out of memory");
    }
    gal_sim_result res;
    memset(&res, 0, sizeof res);
    if (!st) st = gal_run_to_state(m, d, T, &o, &res, q_end ? *q_end : NULL, v_end ? *v_end : NULL);
    gal_sim_measures ms;
    if (!st) st = gal_sim_measure(&res, 0, -1, &ms);
    if (!st) measures_of(&ms, &res, r);
    for (int s = GAL_STAGE_EQUILIBRIUM; d && s <= GAL_STAGE_START; s++) r->setup_time_s += d->stage_time_s[s];
    r->setup_time_s += res.build_time_s;
    if (!st && kind == GAL_MODEL_REDUCED) r->rom_setup = res.setup_reused ? 2 : 1;
    gal_sim_result_clear(&res);
    setup_keep(setup, m, d, key, r->setup_reused);
    return st;
}

int gal_sweep_case_run(const gal_scene *sc, gal_model_kind kind, const double *q0, const double *v0, int nq0,
                       gal_sweep_onset_cache *cache, gal_sweep_setup_cache *setup, gal_sweep_result *r,
                       double **q_end, double **v_end, int *nq)
{
    double t0 = gal_wall_time();
    memset(r, 0, sizeof *r);
    r->vertical_pp_m = r->horizontal_pp_m = r->twist_pp_deg = r->frequency_hz = r->tension_max_n = NAN;
    r->onset_speed_m_s = r->residual_max = NAN;
    r->valid = -1;
    if (q_end) *q_end = *v_end = NULL;
    gal_error_clear();
    int st;
    if (gal_sweep_explicit_bundle(sc))
        st = q0 || q_end ? gal_error(GAL_EINPUT, "%s: --continuation with [bundle] model = explicit: the explicit "
                                     "bundle starts at rest; allowed: model = equivalent", sc->path)
                         : run_bundle(sc, r);
    else
        st = run_case(sc, kind, q0, v0, nq0, setup, r, q_end, v_end, nq);
    r->has_onset = sc->ice.present && sc->ice.aero_table[0];
    if (!st && r->has_onset) st = onset_of(sc, cache, &r->onset_speed_m_s);
    r->status = st;
    if (st) {
        snprintf(r->message, sizeof r->message, "%s", gal_error_message());
        if (q_end) {
            free(*q_end), free(*v_end);
            *q_end = *v_end = NULL;
        }
    }
    r->wall_time_s = gal_wall_time() - t0;
    return st == GAL_ENOMEM ? st : GAL_OK;
}
