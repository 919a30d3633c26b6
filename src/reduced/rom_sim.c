/* rom_sim.c: a run of a scene by the recomputed reduced model on the full model's set-up: the same
 * sampling, time step, Rayleigh damping, loads and probes as gal_sim_run, with the residual
 * self-check every check_interval seconds. */
#include "gallop/reduced/rom_sim.h"
#include "gallop/base/core.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void gal_rom_sim_default_opts(gal_rom_sim_opts *o)
{
    o->derivatives = 1;
    o->h = 0;
    o->check_interval = 1.0;
    o->check_from = 0;
}

/* One sample row (horizontal, vertical, along, twist per probe) and the support tensions. */
static void sample(const gal_rom *m, const gal_sim_result *res, long i)
{
    gal_rom_observe(m, res->nprobe, res->probe, res->trace + (size_t)i * 4 * res->nprobe, res->tension + 2 * i);
}

static int run_loop(gal_rom *m, const gal_rom_sim_opts *o, gal_sim_result *res, int sub, gal_rom_sim_info *info)
{
    double next_check = o->check_from;
    for (long i = 0; i < res->nsamples; i++) {
        if (i > 0)
            for (int k = 0; k < sub; k++) {
                int st = gal_rom_step(m);
                if (st) return st;
            }
        sample(m, res, i);
        if (o->check_interval > 0 && m->t >= next_check - 1e-9) {
            gal_rom_check chk;
            int st = gal_rom_residual(m, &chk);
            if (st) return st;
            info->checks++;
            info->residual_max = fmax(info->residual_max, chk.max);
            for (int f = 0; f < GAL_FAMILY_COUNT; f++) info->residual_family[f] = fmax(info->residual_family[f], chk.rel[f]);
            next_check += o->check_interval;
        }
    }
    return GAL_OK;
}

int gal_rom_sim_run(gal_sim_setup *s, const gal_rom_sim_opts *o, gal_sim_result *res, gal_rom_sim_info *info)
{
    const gal_scene *sc = s->sc;
    const gal_data *d = s->data;
    const gal_rod *rod = d->eq.rod;
    const gal_modes *md = &d->md;
    gal_rom_sim_opts od;
    if (!o) gal_rom_sim_default_opts(&od), o = &od;
    memset(res, 0, sizeof *res);
    memset(info, 0, sizeof *info);
    res->kind = GAL_MODEL_REDUCED;
    res->nprobe = sc->simulation.nprobes;
    memcpy(res->probe, sc->simulation.probes, sizeof res->probe);
    int sel[64], r = 0;
    double fhi = 0;
    for (int k = 0; k < md->n && r < 64; k++)
        if (md->mode[k].selected) {
            sel[r++] = k;
            fhi = fmax(fhi, md->mode[k].frequency_hz);
        }
    double dt_out = sc->simulation.output_interval;
    if (!(dt_out > 0)) dt_out = fmin(0.05, 1.0 / (10 * fhi));
    double h = o->h > 0 ? o->h : sc->simulation.time_step;
    if (!(h > 0)) h = fmin(dt_out, 1.0 / (40 * fhi));
    int sub = (int)ceil(dt_out / h - 1e-9);
    res->dt_out = dt_out;
    long ns;
    int sst = gal_scene_sample_count(sc, sc->simulation.duration, dt_out, 1, &ns); /* bounded */
    if (sst) return sst;
    res->nsamples = ns;
    res->time = malloc((size_t)ns * sizeof(double));
    res->trace = calloc((size_t)ns * 4 * res->nprobe, sizeof(double));
    res->tension = calloc((size_t)ns * 2, sizeof(double));
    if (!res->time || !res->trace || !res->tension) return gal_error(GAL_ENOMEM, "reduced run: out of memory");
    for (long i = 0; i < ns; i++) res->time[i] = i * dt_out;
    double tb = gal_wall_time();
    gal_rom_opts ro;
    gal_rom_default_opts(&ro);
    ro.derivatives = o->derivatives;
    ro.h = dt_out / sub;
    ro.rho_inf = sc->simulation.rho_inf;
    ro.damping = d->damping; /* the structural damping of the pipeline */
    gal_force F = {0};
    if (d->loads.table) F.eval = gal_loads_full, F.element = gal_loads_element, F.ctx = (void *)&d->loads; /* read only */
    gal_rom *m = gal_rom_alloc(rod, d->eq.q, md, sel, r, &ro, &F);
    if (!m) return GAL_EFAIL;
    int st = gal_rom_start(m, 0.0, d->q_start, NULL);
    info->build_time_s = res->build_time_s = gal_wall_time() - tb;
    info->basis = res->basis = m->r;
    double t0 = gal_wall_time();
    if (!st) st = run_loop(m, o, res, sub, info);
    res->wall_time_s = gal_wall_time() - t0;
    res->steps = m->steps, res->newton_iterations = m->newton_iterations;
    res->force_evaluations = m->force_evaluations, res->factorizations = m->tangents;
    res->time_step_s = ro.h;
    gal_rom_free(m);
    return st;
}
