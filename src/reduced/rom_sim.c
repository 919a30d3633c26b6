/* rom_sim.c: a run of a scene by the recomputed reduced model on the full model's set-up: the same
 * sampling, time step, Rayleigh damping, loads and probes as gal_sim_run, with the residual
 * self-check every check_interval seconds and the adaptation (rom_adapt.h) past the tolerance; not
 * valid either where the conductor goes slack (rom.h: gal_rom_taut_share). */
#include "gallop/reduced/rom_sim.h"
#include "gallop/base/core.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void gal_rom_sim_default_opts(gal_rom_sim_opts *o)
{
    memset(o, 0, sizeof *o);
    o->derivatives = 1;
    o->manifold = -1;
    o->h = 0;
    o->check_interval = 1.0;
    o->check_from = 0;
    o->tolerance = -1; /* the scene's */
    o->policy = GAL_ROM_ADD_CORRECTION | GAL_ROM_ADD_MODE;
    o->relax = 1;
    o->replay = 1;
}

/* One sample row (horizontal, vertical, along, twist per probe) and the support tensions. */
static void sample(const gal_rom *m, const gal_sim_result *res, long i)
{
    gal_rom_observe(m, res->nprobe, res->probe, res->trace + (size_t)i * 4 * res->nprobe, res->tension + 2 * i);
}

/* The check at the state reached (sample i): past tol the basis grows (once per check); after a
 * growth run again from the start, the record before sample i is the grown model's, and the taut
 * share the least over it, as a run of the grown model from the start would give them. */
static int check(gal_rom_adapt *a, gal_rom **m, double tol, gal_rom_sim_info *info, double *du,
                 gal_sim_result *res, gal_rom_redo *redo, long i)
{
    gal_rom_check chk;
    int st = gal_rom_adapt_residual(a, *m, &chk, du);
    if (st) return st;
    info->checks++;
    if (tol > 0 && chk.max > tol) {
        st = gal_rom_adapt_grow(a, m, &chk, du);
        if (st == GAL_OK && a->q0 && gal_rom_redo_apply(redo, i, res->trace, res->tension) == i) {
            sample(*m, res, i);
            info->taut_share = fmin(redo->taut, gal_rom_taut_share(*m));
        }
        if (st == GAL_OK) return GAL_OK;
        if (st != GAL_ROM_ELIMIT) return st;
        info->valid = 0; /* it cannot grow: kept, marked invalid */
    }
    info->residual_max = fmax(info->residual_max, chk.max);
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) info->residual_family[f] = fmax(info->residual_family[f], chk.rel[f]);
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) info->cubic_family[f] = fmax(info->cubic_family[f], chk.cubic[f]);
    return GAL_OK;
}

static int run_loop(gal_rom_adapt *a, gal_rom **m, const gal_rom_sim_opts *o, double tol, gal_sim_result *res,
                    int sub, gal_rom_sim_info *info)
{
    double next_check = o->check_from;
    double *du = malloc((size_t)a->rod->ndof * sizeof(double));
    if (!du) return gal_error(GAL_ENOMEM, "reduced run: out of memory");
    gal_rom_redo redo;
    gal_rom_redo_init(&redo, res->nprobe, res->probe, 1);
    if (a->q0) a->replay_observe = gal_rom_redo_observe, a->replay_ctx = &redo, a->replay_dt = res->dt_out;
    int st = GAL_OK;
    for (long i = 0; i < res->nsamples && !st; i++) {
        for (int k = 0; k < sub && i > 0 && !st; k++) st = gal_rom_step(*m);
        if (st) break;
        sample(*m, res, i);
        info->taut_share = fmin(info->taut_share, gal_rom_taut_share(*m));
        if (o->check_interval > 0 && (*m)->t >= next_check - 1e-9) {
            st = check(a, m, tol, info, du, res, &redo, i);
            next_check += gal_rom_check_interval(*m, o->check_interval);
        }
    }
    free(du);
    gal_rom_redo_clear(&redo);
    a->replay_observe = NULL, a->replay_ctx = NULL;
    return st;
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
    if (o->manifold >= 0) ro.manifold = o->manifold;
    ro.h = dt_out / sub;
    ro.rho_inf = sc->simulation.rho_inf;
    ro.damping = d->damping; /* the structural damping of the pipeline */
    ro.extra = o->extra, ro.nextra = o->nextra;
    gal_force F = {0};
    if (d->loads.table) /* read only */
        F.eval = gal_loads_full, F.element = gal_loads_element, F.eval_framed = gal_loads_full_framed, F.ctx = (void *)&d->loads;
    double *fm = ro.manifold && d->loads.table ? calloc((size_t)rod->nq, sizeof(double)) : NULL; /* qm.h */
    if (fm && !gal_loads_mean(&d->loads, d->eq.q, fm)) ro.mean_load = fm, ro.static_vectors = 1;
    gal_rom_adapt a;
    gal_rom *m;
    int st = gal_rom_adapt_init(&a, &m, rod, d->eq.q, md, sel, r, &ro, &F);
    free(fm);
    if (st) { gal_rom_adapt_clear(&a); return st; }
    a.policy = o->policy, a.relax = o->relax;
    if (o->replay) gal_rom_adapt_replay_from(&a, d->q_start, d->v_start);
    st = gal_rom_start(m, 0.0, d->q_start, d->v_start);
    info->build_time_s = res->build_time_s = gal_wall_time() - tb;
    info->basis_start = m->r;
    info->valid = 1;
    info->taut_share = 1;
    double tol = o->tolerance < 0 ? sc->model.residual_tolerance : o->tolerance;
    double t0 = gal_wall_time();
    if (!st) st = run_loop(&a, &m, o, tol, res, sub, info);
    info->basis = res->basis = m->r;
    info->valid = (!(tol > 0) || info->residual_max <= tol) && info->taut_share >= GAL_ROM_SLACK_SHARE;
    info->nevents = a.nevents;
    memcpy(info->ev, a.ev, sizeof a.ev);
    gal_rom_adapt_clear(&a);
    res->wall_time_s = gal_wall_time() - t0;
    res->steps = m->steps, res->newton_iterations = m->newton_iterations;
    res->force_evaluations = m->force_evaluations, res->factorizations = m->tangents;
    res->time_step_s = ro.h;
    gal_rom_free(m);
    return st;
}
