/* sim.c: a galloping run of the explicit bundle (bundle_dyn.h, gal_bundle_simulate): statics and
 * modes, the output interval and time step as the single rod's full model, modal damping, the
 * loads on every sub-conductor, then the steps to each output time and the probes of every
 * sub-conductor and of the bundle's centroid there. */
#include "gallop/bundle/bundle_dyn.h"
#include "gallop/bundle/bundle_rom.h"
#include "gallop/base/core.h"
#include "gallop/loads/windfield.h"
#include "gallop/model/damping.h"
#include "gallop/model/model.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "run/probes.h"

void gal_bundle_sim_result_clear(gal_bundle_sim_result *res)
{
    gal_sim_result_clear(&res->c);
    free(res->sub), free(res->tension);
    memset(res, 0, sizeof *res);
}

int gal_bundle_sim_sub(const gal_bundle_sim_result *res, int r, gal_sim_result *out)
{
    const gal_sim_result *c = &res->c;
    size_t np4 = 4 * (size_t)c->nprobe;
    *out = *c;
    out->trace = malloc((size_t)c->nsamples * np4 * sizeof(double));
    out->tension = malloc((size_t)c->nsamples * 2 * sizeof(double));
    if (!out->trace || !out->tension) {
        free(out->trace), free(out->tension);
        out->trace = out->tension = NULL;
        return gal_error(GAL_ENOMEM, "simulate: out of memory");
    }
    for (long i = 0; i < c->nsamples; i++) {
        memcpy(out->trace + i * np4, res->sub + ((size_t)i * res->n + r) * np4, np4 * sizeof(double));
        memcpy(out->tension + 2 * i, res->tension + ((size_t)i * res->n + r) * 2, 2 * sizeof(double));
    }
    return GAL_OK;
}

typedef struct {
    gal_bundle *b;
    gal_modes md;
    gal_bundle_loads bl;
    gal_bundle_dyn *dyn;
    gal_damping *damping;
    gal_bundle_rom *rom;     /* the reduced run's integrator (bundle_rom.h), or NULL */
    double *u, *wind_u;
    gal_probe pa[GAL_BUNDLE_MAX][GAL_MAX_PROBES];
} run_ws;

static void ws_clear(run_ws *w)
{
    gal_bundle_dyn_free(w->dyn);
    gal_damping_free(w->damping);
    gal_bundle_rom_free(w->rom);
    gal_bundle_loads_clear(&w->bl);
    gal_modes_clear(&w->md);
    gal_bundle_free(w->b);
    free(w->u), free(w->wind_u);
}

/* The output interval and the step, as run/sim.c and run/integrator_full.c choose them. */
static int sampling(const gal_model *m, const gal_modes *md, const gal_run_opts *o, double *dt_out, double *h)
{
    double fhi = 0;
    for (int k = 0; k < md->n; k++)
        if (md->mode[k].selected) fhi = fmax(fhi, md->mode[k].frequency_hz);
    double dt = o->output_interval;
    if (!(dt > 0)) dt = fmin(0.05, 1.0 / (10 * fhi));
    else if (dt > 0.25 / fhi)
        return gal_error(GAL_EINPUT, "%s: [simulation] output_interval = %g s cannot resolve the highest selected "
                         "mode (%.4g Hz); allowed: 0 (chosen) or up to %.4g s, a quarter of its period", m->sc.path,
                         dt, fhi, 0.25 / fhi);
    double hh = o->time_step > 0 ? o->time_step : fmin(dt, 1.0 / (40 * fhi));
    int sub = (int)ceil(dt / hh - 1e-9);
    *dt_out = dt, *h = dt / sub;
    return GAL_OK;
}

/* The result's arrays. */
static int result_alloc(const gal_model *m, const gal_run_opts *o, double dt, int n, gal_bundle_sim_result *res)
{
    gal_sim_result *c = &res->c;
    c->kind = GAL_MODEL_FULL, c->nprobe = m->nprobe, c->dt_out = dt;
    memcpy(c->probe, m->probe, sizeof c->probe);
    long ns;
    int st = gal_scene_sample_count(&m->sc, o->duration, dt, GAL_SCENE_MIN_SAMPLES, &ns);
    if (st) return st;
    size_t np4 = 4 * (size_t)m->nprobe;
    c->nsamples = ns, res->n = n;
    c->time = malloc((size_t)ns * sizeof(double));
    c->trace = calloc((size_t)ns * np4, sizeof(double));
    c->tension = calloc((size_t)ns * 2, sizeof(double));
    res->sub = calloc((size_t)ns * n * np4, sizeof(double));
    res->tension = calloc((size_t)ns * n * 2, sizeof(double));
    if (!c->time || !c->trace || !c->tension || !res->sub || !res->tension)
        return gal_error(GAL_ENOMEM, "simulate: out of memory for %ld samples", ns);
    for (long i = 0; i < ns; i++) c->time[i] = i * dt;
    return GAL_OK;
}

/* Sample i: each sub-conductor's probes and support tensions, the centroid's translation and the
 * bundle's rotation about it (the mean over the sub-conductors of the angle their offset from the
 * centroid turned by, in the section's plane), the tensions summed. */
static void observe(run_ws *w, const gal_model *m, gal_bundle_sim_result *res, long i)
{
    const gal_bundle *b = w->b;
    int n = b->n, np = m->nprobe, nq = b->rod[0]->nq, nel = b->rod[0]->p.elements;
    double *row = res->c.trace + (size_t)i * 4 * np, *sub = res->sub + (size_t)i * n * 4 * np;
    double *ten = res->tension + (size_t)i * n * 2, *tc = res->c.tension + 2 * i;
    tc[0] = tc[1] = 0;
    for (int r = 0; r < n; r++) {
        const double *q = (w->rom ? w->rom->s : w->dyn->s) + (size_t)r * nq, *qe = b->state + (size_t)r * nq;
        for (int k = 0; k < nq; k++) w->u[k] = q[k] - qe[k];
        gal_probe_sample(b->rod[r], w->pa[r], np, w->u, sub + (size_t)r * 4 * np);
        ten[2 * r] = gal_probe_tension(b->rod[r], q, 0), ten[2 * r + 1] = gal_probe_tension(b->rod[r], q, nel - 1);
        tc[0] += ten[2 * r], tc[1] += ten[2 * r + 1];
    }
    for (int p = 0; p < np; p++) {
        double c[3] = {0, 0, 0}, ang = 0;
        for (int r = 0; r < n; r++)
            for (int k = 0; k < 3; k++) c[k] += sub[(size_t)r * 4 * np + 4 * p + k] / n;
        for (int r = 0; r < n; r++) {
            const double *d = sub + (size_t)r * 4 * np + 4 * p; /* horizontal (y), vertical (z) */
            double oy = b->off[r][1], oz = b->off[r][2], py = oy + d[0] - c[0], pz = oz + d[1] - c[1];
            ang += atan2(oy * pz - oz * py, oy * py + oz * pz) / n;
        }
        row[4 * p] = c[0], row[4 * p + 1] = c[1], row[4 * p + 2] = c[2], row[4 * p + 3] = ang * 180 / GAL_PI;
    }
}

/* The bundle, its loads and its integrator at the start of the run. */
static int start(run_ws *w, const gal_model *m, const gal_run_opts *o, double h,
                 gal_bundle_sim_result *res)
{
    gal_bundle *b = w->b;
    const gal_scene *sc = &m->sc;
    gal_bundle_dyn_opts go;
    gal_bundle_dyn_default_opts(&go);
    go.h = h, go.rho_inf = o->rho_inf;
    if (o->newton_tol > 0) go.newton_tol = o->newton_tol; /* simulation.newton_tolerance */
    if (!(w->damping = gal_bundle_damping_modal(b, m->damping_ratio, 0))) return gal_error_status();
    go.damping = w->damping; /* the scene's ratio at every bundle mode of the band, as the single rod's */
    res->damping_modes = w->damping->nb, res->damping_band_hz = w->damping->band_hz;
    res->wake_factor = sc->bundle.wake_factor;
    gal_bundle_force F = {NULL, NULL};
    if (m->loads.table) {
        gal_loads base = m->loads;
        int st;
        if (m->turbulence && (st = gal_windfield_sample(sc, &base, &w->wind_u))) return st;
        if ((st = gal_bundle_loads_init(&w->bl, b, &base, sc->wind.air_density, sc->bundle.wake_factor))) return st;
        memcpy(res->leeward, w->bl.leeward, sizeof res->leeward);
        F.eval = gal_bundle_loads_eval, F.ctx = &w->bl;
    }
    for (int r = 0; r < b->n; r++)
        for (int k = 0; k < m->nprobe; k++) w->pa[r][k] = gal_probe_locate(b->rod[r], m->probe[k]);
    if (!(w->u = malloc((size_t)b->rod[0]->nq * sizeof(double)))) return gal_error(GAL_ENOMEM, "out of memory");
    if (res->c.kind == GAL_MODEL_REDUCED) {
        gal_bundle_rom_opts ro;
        gal_bundle_rom_default_opts(&ro);
        ro.h = go.h, ro.rho_inf = go.rho_inf, ro.damping = go.damping; /* the full model's modal damping */
        if (o->newton_tol > 0) ro.newton_tol = o->newton_tol;
        gal_bundle_loads mean;
        if (F.eval) gal_bundle_rom_mean_loads(&w->bl, &mean), ro.mean_loads = &mean;
        w->rom = gal_bundle_rom_alloc(b, &w->md, &ro, &F);
        return w->rom ? GAL_OK : GAL_EFAIL;
    }
    w->dyn = gal_bundle_dyn_alloc(b, NULL, NULL, &go, &F);
    return w->dyn ? GAL_OK : GAL_EFAIL;
}

static int integrate(run_ws *w, const gal_model *m, gal_bundle_sim_result *res)
{
    gal_sim_result *c = &res->c;
    long ns = c->nsamples;
    int st = GAL_OK, tty = isatty(2);
    double next_check = 0;
    for (long i = 0; i < ns && !st; i++) {
        if (w->rom) { /* checked every simulated second and at the end (as the single rod's) */
            long nsteps = (long)floor(c->time[i] / w->rom->o.h + 0.5);
            while (w->rom->steps < nsteps && !st) st = gal_bundle_rom_step(w->rom);
            if (!st && (w->rom->t >= next_check - 1e-9 || i == ns - 1)) {
                st = gal_bundle_rom_selfcheck(w->rom, m->sc.model.residual_tolerance, m->sc.model.on_invalid_warn,
                                              m->sc.path);
                while (next_check <= w->rom->t + 1e-9) next_check += 1.0;
            }
        } else {
            long nsteps = (long)floor(c->time[i] / w->dyn->o.h + 0.5);
            while (w->dyn->steps < nsteps && !st) st = gal_bundle_dyn_step(w->dyn);
        }
        if (st) break;
        if (w->rom) gal_bundle_rom_sync(w->rom);
        observe(w, m, res, i);
        if (tty && i % 200 == 0) fprintf(stderr, "\rexplicit bundle (%s): t = %.1f of %.1f s", w->rom ? "reduced" : "full", c->time[i],
                                         c->time[ns - 1]);
    }
    if (tty) fprintf(stderr, "\n");
    return st;
}

static int simulate(const gal_model *m, const gal_run_opts *o, gal_model_kind kind, gal_bundle_sim_result *res)
{
    memset(res, 0, sizeof *res);
    if (m->start_mean_wind)
        return gal_error(GAL_EINPUT, "%s: [simulation] start = mean_wind with [bundle] model = explicit: the "
                         "explicit bundle starts at rest (allowed: start = rest, the wind ramped in over wind_ramp)",
                         m->sc.path);
    run_ws w;
    memset(&w, 0, sizeof w);
    double t0 = gal_wall_time(), dt = 0, h = 0;
    int st = gal_bundle_solve_model(m, &w.b, &w.md);
    if (!st) st = sampling(m, &w.md, o, &dt, &h);
    if (!st) st = result_alloc(m, o, dt, w.b->n, res);
    res->c.kind = kind;
    double t1 = gal_wall_time();
    res->setup_time_s = t1 - t0;
    if (!st) st = start(&w, m, o, h, res);
    if (!st) st = integrate(&w, m, res);
    if (w.dyn) {
        gal_sim_result *c = &res->c;
        c->time_step_s = h, c->steps = w.dyn->steps, c->newton_iterations = w.dyn->newton_iterations;
        c->factorizations = w.dyn->factorizations, c->force_evaluations = w.dyn->force_evaluations;
        c->rejected_steps = w.dyn->rejected_steps;
    }
    if (w.rom) {
        gal_sim_result *c = &res->c;
        gal_bundle_rom *r = w.rom;
        c->time_step_s = h, c->steps = r->steps, c->newton_iterations = r->newton_iterations;
        c->factorizations = r->tangents, c->force_evaluations = r->force_evaluations;
        c->rejected_steps = r->rejected_steps, c->basis = c->basis_start = r->r, c->build_time_s = r->build_time_s;
        c->checked = r->checks > 0, c->residual_max = r->residual_max, c->valid = r->valid;
    }
    if (w.b) res->ndof = w.b->ndof;
    res->c.wall_time_s = gal_wall_time() - t1;
    ws_clear(&w);
    return st;
}

int gal_bundle_simulate(const gal_model *m, const gal_run_opts *o, gal_bundle_sim_result *res)
{
    return simulate(m, o, GAL_MODEL_FULL, res);
}

int gal_bundle_simulate_reduced(const gal_model *m, const gal_run_opts *o, gal_bundle_sim_result *res)
{
    int st = simulate(m, o, GAL_MODEL_REDUCED, res);
    if (!st && !res->c.checked) /* never a reduced result it has not checked */
        st = gal_error(GAL_EFAIL, "%s: the explicit bundle's reduced run: its self-check did not run", m->sc.path);
    return st;
}
