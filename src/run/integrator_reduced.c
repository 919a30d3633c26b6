/* integrator_reduced.c: the reduced model as a galloping run's integrator (integrator.h): the
 * modal equations from the start state projected on the basis, natural adaptive steps and Hermite
 * interpolation at the output times, the probes and the support elements recovered by the
 * model's expansion. */
#include "gallop/run/integrator.h"
#include "gallop/base/core.h"
#include "gallop/reduced/rdyn.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "run/probes.h"

#define NQP 16 /* load quadrature: 2-point Gauss on 8 segments (the selected modes are smooth on them) */

typedef struct {
    gal_rdyn *dyn;
    const gal_reduced *rm;
    const gal_data *d;
    int np;
    double duration;         /* s */
    double *ys, *ov;         /* 2r: the state at the output time; nobs: the observations there */
    double *q;               /* nq: scratch configuration for the support tensions */
} reduced_state;

static void reduced_free(void *state)
{
    reduced_state *s = state;
    if (!s) return;
    gal_rdyn_free(s->dyn);
    free(s->ys); free(s->ov); free(s->q);
    free(s);
}

/* The start in the modes: eta = Phi^T M (q_start - q_eq). */
static void project_start(const gal_data *d, double *eta)
{
    const gal_rod *rod = d->eq.rod;
    const gal_reduced *rm = d->rm;
    int n = rod->ndof, r = rm->r;
    double *du = malloc((size_t)2 * n * sizeof(double));
    if (!du) return;
    for (int j = 0; j < n; j++) du[j] = d->q_start[rod->free_q[j]] - d->eq.q[rod->free_q[j]];
    gal_rod_mass_mult(rod, du, du + n);
    for (int i = 0; i < r; i++) {
        double e = 0;
        for (int j = 0; j < n; j++) e += rm->phi[(size_t)i * n + j] * du[n + j];
        eta[i] = e;
    }
    free(du);
}

static int reduced_alloc(const gal_model *m, const gal_data *d, const gal_run_opts *o, double dt_out, double fhi,
                         void **state)
{
    (void)fhi;
    *state = NULL;
    reduced_state *s = calloc(1, sizeof *s);
    if (!s) return gal_error(GAL_ENOMEM, "simulate: out of memory");
    const gal_rod *rod = d->eq.rod;
    s->rm = d->rm, s->d = d, s->np = m->nprobe, s->duration = o->duration;
    gal_pointload pl = {0};
    if (d->loads.table) pl.eval = gal_loads_point, pl.ctx = (void *)&d->loads; /* read only */
    s->dyn = gal_rdyn_alloc(d->rm, rod, d->eq.q, d->damping, &pl, NQP, o->tolerance, dt_out / 4, -1);
    if (s->dyn && m->start_mean_wind) project_start(d, s->dyn->y);
    s->ys = malloc((size_t)2 * d->rm->r * sizeof(double));
    s->ov = malloc((size_t)d->rm->nobs * sizeof(double));
    s->q = malloc((size_t)rod->nq * sizeof(double));
    if (!s->dyn || !s->ys || !s->ov || !s->q) {
        reduced_free(s);
        return GAL_ENOMEM;
    }
    *state = s;
    return GAL_OK;
}

static int reduced_advance(void *state, double t_out, double t_end)
{
    reduced_state *s = state;
    int st = gal_rdyn_sample(s->dyn, t_out, t_end, s->ys);
    if (!st) gal_reduced_observe(s->rm, s->ys, s->ov);
    return st;
}

static void reduced_observe(void *state, double *probes, double tension[2])
{
    reduced_state *s = state;
    const gal_data *d = s->d;
    const gal_rod *rod = d->eq.rod;
    const double *po = s->ov + d->obs_probe, *so = s->ov + d->obs_support;
    for (int k = 0; k < s->np; k++) {
        for (int c = 0; c < 3; c++) probes[4 * k + c] = po[4 * k + c];
        probes[4 * k + 3] = po[4 * k + 3] * 180 / GAL_PI;
    }
    /* support tensions from the recovered inner nodes */
    memcpy(s->q, d->eq.q, (size_t)rod->nq * sizeof(double));
    for (int c = 0; c < 3; c++) s->q[3 + c] += so[c], s->q[3 * (rod->nn - 2) + c] += so[3 + c];
    tension[0] = gal_probe_tension(rod, s->q, 0);
    tension[1] = gal_probe_tension(rod, s->q, rod->p.elements - 1);
}

static void reduced_counters(const void *state, gal_run_counters *c)
{
    const reduced_state *s = state;
    memset(c, 0, sizeof *c);
    gal_rdyn_counts(s->dyn, &c->steps, &c->rejected_steps);
    c->force_evaluations = s->dyn->rhs_evaluations;
    c->time_step_s = c->steps > 0 ? s->duration / c->steps : 0;
    c->basis = s->rm->r;
    c->load_cases = s->rm->load_cases;
    c->build_time_s = s->rm->build_time_s;
}

const gal_integrator_type gal_integrator_reduced = {
    "reduced", GAL_MODEL_REDUCED, GAL_STAGE_REDUCED, reduced_alloc, reduced_advance, reduced_observe,
    reduced_counters, reduced_free, NULL,
};
