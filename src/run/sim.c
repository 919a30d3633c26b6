/* sim.c: galloping runs of a model by either integrator in one loop (sim.h; issues 5, 6). */
#include "gallop/run/sim.h"
#include "gallop/base/core.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

void gal_sim_result_clear(gal_sim_result *res)
{
    free(res->time);
    free(res->trace);
    free(res->tension);
    memset(res, 0, sizeof *res);
}

void gal_run_opts_from_scene(const gal_scene *sc, gal_run_opts *o)
{
    memset(o, 0, sizeof *o);
    o->duration = sc->simulation.duration;
    o->time_step = sc->simulation.time_step;
    o->output_interval = sc->simulation.output_interval;
    o->rho_inf = sc->simulation.rho_inf;
    o->newton_tol = sc->simulation.newton_tolerance;
}

/* The output interval: chosen from the highest selected mode fhi (Hz), or the scene's when it
 * resolves that mode. */
static int sampling(const gal_model *m, const gal_data *d, const gal_run_opts *o, double *dt_out, double *fhi)
{
    *fhi = 0;
    for (int k = 0; k < d->md.n; k++)
        if (d->md.mode[k].selected) *fhi = fmax(*fhi, d->md.mode[k].frequency_hz);
    double dt = o->output_interval;
    if (!(dt > 0)) dt = fmin(0.05, 1.0 / (10 * *fhi));
    else if (dt > 0.25 / *fhi)
        /* the samples must resolve what the model carries, or the spectra alias */
        return gal_error(GAL_EINPUT, "%s: [simulation] output_interval = %g s cannot resolve the highest "
                         "selected mode (%.4g Hz); allowed: 0 (chosen) or up to %.4g s, a quarter of its period",
                         m->sc.path, dt, *fhi, 0.25 / *fhi);
    *dt_out = dt;
    return GAL_OK;
}

/* The result's arrays and the sample times. */
static int result_alloc(const gal_model *m, const gal_integrator_type *T, const gal_run_opts *o, double dt_out,
                        gal_sim_result *res)
{
    res->kind = T->kind;
    res->nprobe = m->nprobe;
    memcpy(res->probe, m->probe, sizeof res->probe);
    res->dt_out = dt_out;
    long ns; /* bounded: no cast overflow */
    int st = gal_scene_sample_count(&m->sc, o->duration, dt_out, 1, &ns);
    if (st) return st;
    res->nsamples = ns;
    res->time = malloc((size_t)ns * sizeof(double));
    res->trace = calloc((size_t)ns * 4 * m->nprobe, sizeof(double));
    res->tension = calloc((size_t)ns * 2, sizeof(double));
    if (!res->time || !res->trace || !res->tension)
        return gal_error(GAL_ENOMEM, "simulate: out of memory for %ld samples", ns);
    for (long i = 0; i < ns; i++) res->time[i] = i * dt_out;
    return GAL_OK;
}

/* The loop of every run: the integrator brought to each output time and observed there. */
static int integrate(const gal_integrator_type *T, void *state, gal_sim_result *res)
{
    long ns = res->nsamples;
    int np = res->nprobe, st = GAL_OK, tty = isatty(2);
    for (long i = 0; i < ns && !st; i++) {
        if ((st = T->advance(state, res->time[i], res->time[ns - 1]))) break;
        T->observe(state, res->trace + (size_t)i * 4 * np, res->tension + 2 * i);
        if (T->rewrite) T->rewrite(state, i, res->trace, res->tension);
        if (tty && i % 200 == 0) fprintf(stderr, "\r%s model: t = %.1f of %.1f s", T->name, res->time[i], res->time[ns - 1]);
    }
    if (tty) fprintf(stderr, "\n");
    return st;
}

int gal_run_check_measurable(const gal_model *m, gal_data *d, const gal_run_opts *o)
{
    double dt_out, fhi;
    long ns;
    int st = gal_forward(m, d, GAL_STAGE_MODES);
    if (!st) st = sampling(m, d, o, &dt_out, &fhi);
    if (!st) st = gal_scene_sample_count(&m->sc, o->duration, dt_out, GAL_SCENE_MIN_SAMPLES, &ns);
    return st;
}

int gal_run(const gal_model *m, gal_data *d, const gal_integrator_type *T, const gal_run_opts *o,
            gal_sim_result *res)
{
    return gal_run_to_state(m, d, T, o, res, NULL, NULL);
}

int gal_run_to_state(const gal_model *m, gal_data *d, const gal_integrator_type *T, const gal_run_opts *o,
                     gal_sim_result *res, double *q_end, double *v_end)
{
    memset(res, 0, sizeof *res);
    res->kind = T->kind;
    if ((q_end || v_end) && !T->state)
        return gal_error(GAL_EINPUT, "%s: the %s integrator cannot give its final state", m->sc.path,
                         T->name);
    double dt_out = 0, fhi = 0;
    int st = gal_forward(m, d, GAL_STAGE_MODES);
    if (!st) st = sampling(m, d, o, &dt_out, &fhi);
    if (!st) st = gal_forward(m, d, T->needs);
    if (!st) st = result_alloc(m, T, o, dt_out, res);
    if (st) return st;
    double t0 = gal_wall_time();
    void *state;
    if ((st = T->alloc(m, d, o, dt_out, fhi, &state))) return st;
    st = integrate(T, state, res);
    if (!st && q_end && v_end) T->state(state, q_end, v_end);
    gal_run_counters c;
    T->counters(state, &c);
    T->free(state);
    res->wall_time_s = gal_wall_time() - t0;
    res->time_step_s = c.time_step_s;
    res->steps = c.steps, res->newton_iterations = c.newton_iterations, res->factorizations = c.factorizations;
    res->force_evaluations = c.force_evaluations, res->rejected_steps = c.rejected_steps;
    res->basis = c.basis, res->build_time_s = c.build_time_s, res->setup_reused = c.setup_reused;
    res->checked = c.checked, res->residual_max = c.residual_max, res->valid = c.valid;
    memcpy(res->invalid_why, c.invalid_why, sizeof c.invalid_why);
    res->basis_start = c.basis_start, res->growths = c.growths;
    memcpy(res->growth, c.growth, sizeof c.growth);
    if (!st && T->kind == GAL_MODEL_REDUCED && !res->checked) /* never a reduced result it has not checked */
        st = gal_error(GAL_EFAIL, "%s: the reduced run's self-check did not run: its result is not checked",
                       m->sc.path);
    return st;
}

/* ---- a scene's set-up, for runs whose controls change between them ---- */

void gal_sim_setup_clear(gal_sim_setup *s)
{
    gal_data_free(s->data);
    gal_model_free(s->model);
    memset(s, 0, sizeof *s);
}

int gal_sim_setup_init(gal_sim_setup *s, const gal_scene *sc, int need_modes)
{
    (void)need_modes;
    double t0 = gal_wall_time();
    memset(s, 0, sizeof *s);
    s->sc = sc;
    int st;
    if (!(s->model = gal_model_alloc(sc, &st))) return st;
    if (!(s->data = gal_data_alloc(s->model))) return GAL_ENOMEM;
    st = gal_forward(s->model, s->data, GAL_STAGE_START);
    s->setup_time_s = gal_wall_time() - t0;
    return st;
}

int gal_sim_run(gal_sim_setup *s, gal_model_kind kind, gal_sim_result *res)
{
    gal_run_opts o;
    gal_run_opts_from_scene(s->sc, &o);
    int st = gal_run_check_measurable(s->model, s->data, &o);
    if (st) {
        memset(res, 0, sizeof *res);
        return st;
    }
    return gal_run(s->model, s->data, kind == GAL_MODEL_FULL ? &gal_integrator_full : &gal_integrator_reduced,
                   &o, res);
}
