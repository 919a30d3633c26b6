/* integrator_full.c: the full model as a galloping run's integrator (integrator.h):
 * generalized-alpha on the whole rod from the start state, a fixed step that divides the output
 * interval, the aerodynamic loads at the element centres. */
#include "gallop/run/integrator.h"
#include "gallop/base/core.h"
#include "gallop/full/dynamics.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "run/probes.h"

typedef struct {
    gal_dyn *dyn;
    const gal_rod *rod;
    const double *q_eq;
    int np;
    gal_probe pa[GAL_MAX_PROBES];
    double *u;               /* nq: displacement from the equilibrium */
} full_state;

static void full_free(void *state)
{
    full_state *s = state;
    if (!s) return;
    gal_dyn_free(s->dyn);
    free(s->u);
    free(s);
}

static int full_alloc(const gal_model *m, const gal_data *d, const gal_run_opts *o, double dt_out, double fhi,
                      void **state)
{
    *state = NULL;
    full_state *s = calloc(1, sizeof *s);
    const gal_rod *rod = d->eq.rod;
    if (!s || !(s->u = calloc((size_t)rod->nq, sizeof(double)))) {
        full_free(s);
        return gal_error(GAL_ENOMEM, "simulate: out of memory");
    }
    s->rod = rod, s->q_eq = d->eq.q, s->np = m->nprobe;
    for (int k = 0; k < m->nprobe; k++) s->pa[k] = gal_probe_locate(rod, m->probe[k]);
    gal_dyn_opts go;
    gal_dyn_default_opts(&go);
    double h = o->time_step;
    if (!(h > 0)) h = fmin(dt_out, 1.0 / (40 * fhi));
    int sub = (int)ceil(dt_out / h - 1e-9);
    go.h = dt_out / sub;
    go.rho_inf = o->rho_inf;
    if (o->newton_tol > 0) go.newton_tol = o->newton_tol;
    go.damping = d->damping;
    gal_force F = {0};
    if (d->loads.table) F.eval = gal_loads_full, F.ctx = (void *)&d->loads; /* read only */
    s->dyn = gal_dyn_alloc(rod, d->q_start, d->v_start, &go, &F);
    if (!s->dyn) {
        full_free(s);
        return GAL_EFAIL;
    }
    *state = s;
    return GAL_OK;
}

/* Whole steps up to t_out: the output interval is a whole number of them. */
static int full_advance(void *state, double t_out, double t_end)
{
    full_state *s = state;
    (void)t_end;
    long n = (long)floor(t_out / s->dyn->o.h + 0.5);
    int st = GAL_OK;
    while (s->dyn->steps < n && !st) st = gal_dyn_step(s->dyn);
    return st;
}

static void full_observe(void *state, double *probes, double tension[2])
{
    full_state *s = state;
    const gal_rod *rod = s->rod;
    const double *q = s->dyn->q;
    for (int k = 0; k < rod->nq; k++) s->u[k] = q[k] - s->q_eq[k];
    gal_probe_sample(rod, s->pa, s->np, s->u, probes);
    tension[0] = gal_probe_tension(rod, q, 0);
    tension[1] = gal_probe_tension(rod, q, rod->p.elements - 1);
}

static void full_counters(const void *state, gal_run_counters *c)
{
    const full_state *s = state;
    const gal_dyn *d = s->dyn;
    memset(c, 0, sizeof *c);
    c->time_step_s = d->o.h;
    c->steps = d->steps, c->newton_iterations = d->newton_iterations;
    c->factorizations = d->factorizations, c->force_evaluations = d->force_evaluations;
    c->rejected_steps = d->rejected_steps;
}

static void full_state_of(const void *state, double *q, double *v)
{
    const full_state *s = state;
    memcpy(q, s->dyn->q, (size_t)s->rod->nq * sizeof(double));
    memcpy(v, s->dyn->v, (size_t)s->rod->nq * sizeof(double));
}

const gal_integrator_type gal_integrator_full = {
    "full", GAL_MODEL_FULL, GAL_STAGE_START, full_alloc, full_advance, full_observe, full_counters, full_free,
    full_state_of, NULL,
};
