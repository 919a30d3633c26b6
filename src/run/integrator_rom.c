/* integrator_rom.c: the recomputed reduced model (reduced/rom.h) as a galloping run's integrator
 * (integrator.h), the only reduced model: the basis built from the reduced stage's modes (none at or
 * near 0 Hz) and their modal
 * derivatives about the equilibrium, fixed generalized-alpha steps, the probes and the support
 * tensions from the reconstructed rod, and the self-check (gal_rom_residual) every second of
 * simulated time (less often past ~250 elements: gal_rom_check_interval keeps the checks' cost
 * within a share of the steps') against model.residual_tolerance: past it the basis grows (rom_adapt.h: the
 * residual's correction direction and the next mode of the family whose residual is largest, the
 * model rebuilt and run again from the run's start to the failing check's time, then on; logged in
 * summary.json basis_growths);
 * when it cannot grow any more the run stops (model.on_invalid = stop) or goes on marked invalid
 * (warn). At every output the reconstructed conductor must also stay taut (gal_rom_taut_share at
 * least GAL_ROM_SLACK_SHARE): a slack conductor is outside the basis, which no growth mends, and
 * the run stops or goes on marked invalid the same way. */
#include "gallop/run/integrator.h"
#include "gallop/base/core.h"
#include "gallop/reduced/rom_adapt.h"
#include "gallop/reduced/rom_turb.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CHECK_INTERVAL 1.0 /* s of simulated time between self-checks (at least; gal_rom_check_interval) */

static const char *const family_keys[GAL_FAMILY_COUNT] = {"modes_vertical", "modes_horizontal", "modes_torsional",
                                                          "modes_vertical"};

typedef struct {
    gal_rom *rom;
    gal_rom_adapt adapt;
    double *du;             /* ndof: the last check's correction direction */
    int basis_start;
    const gal_model *m;
    double next_check, tol;
    int warn, checks, valid;
    double residual_max;
    char why[256];          /* why the run is not valid, when not by its residual */
    gal_rom_check worst;
    int setup_reused;       /* the wind-independent set-up was the data's (an earlier run's) */
    double setup_time_s;    /* s: that set-up's wall time when this run made it */
    double *turb;           /* the turbulent wind's load shapes (rom_turb.h), or NULL */
    gal_rom_redo redo;      /* the samples a growth's replay observed, until the next rewrite */
} rom_state;

static void rom_free(void *state)
{
    rom_state *s = state;
    if (!s) return;
    gal_rom_free(s->rom);
    gal_rom_adapt_clear(&s->adapt);
    free(s->du);
    free(s->turb);
    gal_rom_redo_clear(&s->redo);
    free(s);
}

/* The replayed samples over the record's (integrator.h rewrite). */
static void rom_rewrite(void *state, long i, double *trace, double *tension)
{
    rom_state *s = state;
    gal_rom_redo_apply(&s->redo, i, trace, tension);
}

/* The data's wind-independent set-up of the reduced model into ro->setup: made now (and kept by
 * the data) when it has none, else an earlier run's (s->setup_reused). */
static int setup_of(const gal_data *d, gal_rom_opts *ro, rom_state *s)
{
    gal_rom_setup_slot *slot = d->rom_setup;
    if (!slot || ro->manifold) return GAL_OK;
    s->setup_reused = slot->rom != NULL;
    if (!slot->rom) {
        double t0 = gal_wall_time();
        slot->rom = gal_rom_setup_alloc(d->eq.rod, d->eq.q, &d->md, d->sel, d->basis, ro);
        if (!slot->rom) return GAL_EFAIL;
        s->setup_time_s = slot->time_s = gal_wall_time() - t0;
    }
    ro->setup = slot->rom;
    return GAL_OK;
}

static int rom_alloc(const gal_model *m, const gal_data *d, const gal_run_opts *o, double dt_out, double fhi,
                     void **state)
{
    *state = NULL;
    int st;
    rom_state *s = calloc(1, sizeof *s);
    if (!s) return gal_error(GAL_ENOMEM, "simulate: out of memory");
    double h = o->time_step;
    if (!(h > 0)) h = fmin(dt_out, 1.0 / (40 * fhi));
    int sub = (int)ceil(dt_out / h - 1e-9);
    gal_rom_opts ro;
    gal_rom_default_opts(&ro);
    ro.h = dt_out / sub;
    ro.rho_inf = o->rho_inf;
    ro.scheme = o->rom_scheme;
    if (o->newton_tol > 0) ro.newton_tol = o->newton_tol;
    ro.damping = d->damping; /* the structural damping of the pipeline */
    ro.k0 = d->eq.k0;        /* the statics' K0 and its factorization */
    ro.hyper_check_interval = 0; /* the sample's check comes with the self-check (rom_advance) */
    gal_force F = {0};
    if (d->loads.table) /* read only */
        F.eval = gal_loads_full, F.element = gal_loads_element, F.eval_framed = gal_loads_full_framed, F.ctx = (void *)&d->loads;
    s->m = m;
    s->tol = m->sc.model.residual_tolerance;
    s->warn = m->sc.model.on_invalid_warn;
    s->valid = 1;
    if ((st = setup_of(d, &ro, s))) {
        rom_free(s);
        return st;
    }
    if (d->loads.u && ro.setup && /* a turbulent field: its load shapes up front */
        (st = gal_rom_turb_basis(ro.setup, &F, m->sc.simulation.duration, &s->turb, &ro.nextra))) {
        rom_free(s);
        return st;
    }
    ro.extra = s->turb;
    if ((st = gal_rom_adapt_init(&s->adapt, &s->rom, d->eq.rod, d->eq.q, &d->md, d->sel, d->basis, &ro, &F)) ||
        !(s->du = malloc((size_t)d->eq.rod->ndof * sizeof(double)))) {
        if (!st) st = gal_error(GAL_ENOMEM, "simulate: out of memory");
        rom_free(s);
        return st;
    }
    gal_rom_adapt_replay_from(&s->adapt, d->q_start, d->v_start);
    gal_rom_redo_init(&s->redo, s->m->nprobe, s->m->probe, 0);
    s->adapt.replay_observe = gal_rom_redo_observe, s->adapt.replay_ctx = &s->redo, s->adapt.replay_dt = dt_out;
    s->basis_start = s->rom->r;
    s->setup_reused = s->setup_reused && s->rom->setup_reused;
    if ((st = gal_rom_start(s->rom, 0.0, d->q_start, d->v_start))) {
        rom_free(s);
        return st;
    }
    *state = s;
    return GAL_OK;
}

/* The self-check at the state reached: past model.residual_tolerance the basis grows
 * (rom_adapt.h: the grown model run again from the start to this time) and the run goes on; when it cannot grow, GAL_EFAIL naming
 * what grew (model.on_invalid = stop) or the run goes on marked invalid (warn). */
static int self_check(rom_state *s)
{
    gal_rom_check chk;
    char why[256] = "";
    int st = gal_rom_adapt_residual(&s->adapt, s->rom, &chk, s->du);
    if (st) return st;
    s->checks++;
    if (chk.max > s->tol && s->valid) {
        st = gal_rom_adapt_grow(&s->adapt, &s->rom, &chk, s->du);
        if (st == GAL_OK) return GAL_OK;
        if (st != GAL_ROM_ELIMIT) return st;
        snprintf(why, sizeof why, "%s", gal_error_message());
    }
    if (chk.max > s->residual_max) s->residual_max = chk.max, s->worst = chk;
    if (chk.max <= s->tol || !s->valid) return GAL_OK;
    s->valid = 0;
    int f = 0;
    for (int k = 1; k < GAL_FAMILY_COUNT; k++)
        if (chk.rel[k] > chk.rel[f]) f = k;
    if (s->warn) return GAL_OK;
    return gal_error(GAL_EFAIL, "%s: the reduced model's residual grew to %.3g in the %s family at t = %.4g s, past "
                     "model.residual_tolerance = %.3g (amplitudes no longer within ~5%%), and it cannot adapt: %s; "
                     "select more modes (model.%s), run the full model (--model full), raise "
                     "model.residual_tolerance, or set model.on_invalid = warn to finish the run marked invalid", s->m->sc.path, chk.rel[f], gal_family_names[f], s->rom->t,
                     s->tol, why, family_keys[f]);
}

/* The conductor at the state reached still taut (rom.h: gal_rom_taut_share), else the run is not
 * valid: GAL_EFAIL saying so (model.on_invalid = stop), or marked (warn). */
static int taut_check(rom_state *s)
{
    double share = gal_rom_taut_share(s->rom);
    if (share >= GAL_ROM_SLACK_SHARE || !s->valid) return GAL_OK;
    s->valid = 0;
    snprintf(s->why, sizeof s->why, "the reduced conductor went slack at t = %.4g s (a support tension %.3g of its "
             "static value, below %.2g): the reduced basis, built about the taut equilibrium, does not carry a slack "
             "conductor (amplitudes and tensions no longer within ~5%%)", s->rom->t, share, GAL_ROM_SLACK_SHARE);
    if (s->warn) return GAL_OK;
    return gal_error(GAL_EFAIL, "%s: %s; run the full model (--model full), or set model.on_invalid = warn to finish "
                     "the run marked invalid", s->m->sc.path, s->why);
}

/* The state at t_out, checked every CHECK_INTERVAL and at the end of the run (t_end). */
static int rom_advance(void *state, double t_out, double t_end)
{
    rom_state *s = state;
    int st = gal_rom_advance(s->rom, t_out);
    if (st) {
        char why[256];
        snprintf(why, sizeof why, "%s", gal_error_message());
        return gal_error(st, "reduced model (basis %d): %s", s->rom->r, why);
    }
    if ((st = taut_check(s))) return st;
    if (s->rom->t >= s->next_check - 1e-9 || t_out >= t_end) {
        /* the sample's check on the self-check's schedule (not at the start), at its state: the
         * self-check takes the whole rod's gradient and loads from it */
        if (s->next_check > 0 && s->rom->t >= s->next_check - 1e-9 && (st = gal_rom_sample_check(s->rom))) {
            char why[256];
            snprintf(why, sizeof why, "%s", gal_error_message());
            return gal_error(st, "reduced model (basis %d): %s", s->rom->r, why);
        }
        st = self_check(s);
        double dt = gal_rom_check_interval(s->rom, CHECK_INTERVAL); /* longer on fine meshes */
        while (s->next_check <= s->rom->t + 1e-9) s->next_check += dt;
    }
    return st;
}

static void rom_observe(void *state, double *probes, double tension[2])
{
    rom_state *s = state;
    gal_rom_observe(s->rom, s->m->nprobe, s->m->probe, probes, tension);
}

static void rom_counters(const void *state, gal_run_counters *c)
{
    const rom_state *s = state;
    const gal_rom *r = s->rom;
    memset(c, 0, sizeof *c);
    c->time_step_s = r->o.h;
    c->steps = r->steps, c->newton_iterations = r->newton_iterations, c->factorizations = r->tangents;
    c->force_evaluations = r->force_evaluations;
    c->basis = r->r;
    c->build_time_s = r->build_time_s + s->setup_time_s;
    c->setup_reused = s->setup_reused;
    c->checked = s->checks > 0, c->residual_max = s->residual_max, c->valid = s->valid;
    snprintf(c->invalid_why, sizeof c->invalid_why, "%s", s->why);
    c->basis_start = s->basis_start, c->growths = s->adapt.nevents;
    memcpy(c->growth, s->adapt.ev, sizeof s->adapt.ev);
}

static void rom_state_of(const void *state, double *q, double *v)
{
    const rom_state *s = state;
    gal_rom_reconstruct(s->rom, q, v);
}

const gal_integrator_type gal_integrator_reduced = {
    "reduced", GAL_MODEL_REDUCED, GAL_STAGE_REDUCED, rom_alloc, rom_advance, rom_observe, rom_counters, rom_free,
    rom_state_of, rom_rewrite,
};
