/* sim.c: galloping runs of a scene by the full or the reduced model, sharing equilibrium, modes,
 * loads and wind (issues 5, 6). */
#include "gallop/run/sim.h"
#include "gallop/base/core.h"
#include "gallop/full/dynamics.h"
#include "gallop/model/model.h"
#include "gallop/model/tables.h"
#include "gallop/reduced/rdyn.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "gallop/loads/windfield.h"

void gal_sim_result_clear(gal_sim_result *res)
{
    free(res->time);
    free(res->trace);
    free(res->tension);
    memset(res, 0, sizeof *res);
}

void gal_sim_setup_clear(gal_sim_setup *s)
{
    gal_equilibrium_clear(&s->eq);
    if (s->have_modes) gal_modes_clear(&s->md);
    gal_aero_table_free(s->table);
    free(s->wind_u);
    free(s->q_start);
    memset(s, 0, sizeof *s);
}

/* Rayleigh coefficients giving the damping ratio zeta at w1 and w2: zeta = a/(2w) + b w/2. */
static void rayleigh(double zeta, double w1, double w2, double *a, double *b)
{
    if (zeta <= 0) { *a = *b = 0; return; }
    if (!(w2 > w1 * 1.0001)) w2 = 3 * w1;
    *a = 2 * zeta * w1 * w2 / (w1 + w2);
    *b = 2 * zeta / (w1 + w2);
}

/* The along-wind turbulence on 65 points along the span (or one point under full coherence), at
 * 20 Hz or finer, for the run's duration: the same field for both models. */
static int wind_field(gal_sim_setup *s)
{
    return gal_windfield_sample(s->sc, &s->loads, &s->wind_u);
}

int gal_sim_setup_init(gal_sim_setup *s, const gal_scene *sc, int need_modes)
{
    double t0 = gal_wall_time();
    memset(s, 0, sizeof *s);
    s->sc = sc;
    gal_rod_params p;
    gal_statics_spec spec;
    double value;
    int st = gal_model_rod_params(sc, &p, &spec, &value);
    if (st) return st;
    if ((st = gal_statics_solve(&p, spec, value, NULL, &s->eq)))
        return gal_error(st, "%s: no equilibrium: %s", sc->path, gal_error_message());
    (void)need_modes;
    int want[GAL_FAMILY_COUNT] = {sc->model.modes_vertical, sc->model.modes_horizontal,
                                  sc->effect[GAL_FX_TORSION] ? sc->model.modes_torsional : 0, 0};
    if (want[0] + want[1] + want[2] == 0)
        return gal_error(GAL_EINPUT, "%s: [model] selects no modes: the reduced model and the damping need at least one", sc->path);
    if ((st = gal_modes_find(s->eq.rod, s->eq.q, want, 1000, &s->md)))
        return gal_error(st, "%s: modes: %s", sc->path, gal_error_message());
    s->have_modes = 1;

    /* loads: only what the scene asks for */
    gal_loads *L = &s->loads;
    L->rod = s->eq.rod;
    L->flags = (sc->effect[GAL_FX_AERO_DRAG] ? GAL_AERO_DRAG : 0u) | (sc->effect[GAL_FX_AERO_LIFT] ? GAL_AERO_LIFT : 0u) |
               (sc->effect[GAL_FX_AERO_MOMENT] && sc->effect[GAL_FX_TORSION] ? GAL_AERO_MOMENT : 0u);
    L->aero_damping = sc->effect[GAL_FX_AERO_DAMPING];
    L->rho = sc->wind.air_density;
    L->diam = sc->conductor.diameter;
    L->attack_angle = sc->ice.present ? sc->ice.attack_angle : 0.0;
    L->speed = sc->wind.speed;
    L->dir[0] = cos(sc->wind.yaw), L->dir[1] = sin(sc->wind.yaw), L->dir[2] = 0;
    L->ramp_time = sc->simulation.wind_ramp;
    L->reverse_time = sc->simulation.wind_reverse_time;
    if (L->flags && sc->wind.speed > 0) {
        if ((st = gal_model_aero_table(sc, &s->table))) return st; /* the scene's, or a bare conductor's */
        L->table = s->table;
    }
    if (L->table && sc->effect[GAL_FX_TURBULENCE]) {
        double tw = gal_wall_time();
        st = wind_field(s);
        if (st) return st;
        s->wind_time_s = gal_wall_time() - tw;
    }
    /* the start: the sagged equilibrium, or the equilibrium under the mean wind (then the wind
     * blows at full speed from t = 0) */
    s->q_start = malloc((size_t)s->eq.rod->nq * sizeof(double));
    if (!s->q_start) return gal_error(GAL_ENOMEM, "out of memory");
    memcpy(s->q_start, s->eq.q, (size_t)s->eq.rod->nq * sizeof(double));
    if (sc->simulation.start_mean_wind && L->table) {
        int it = 0;
        st = gal_loads_static(s->eq.rod, s->q_start, L, 1e-6 * fmax(s->eq.horizontal_tension, 1.0) / sc->model.elements, 100, &it);
        if (st) return gal_error(st, "%s: no equilibrium under the mean wind: %s", sc->path, gal_error_message());
        L->ramp_time = 0;
    }
    s->setup_time_s = gal_wall_time() - t0;
    return GAL_OK;
}

/* Probe at span fraction a: element e and weight xi along the unstretched length; edge-centre
 * twist interpolation e0, e1, w1. */
typedef struct {
    int e, e0, e1;
    double xi, w1;
} probe_at;

static probe_at probe_locate(const gal_rod *rod, double frac)
{
    probe_at pa;
    int nel = rod->p.elements;
    double s = frac * nel;
    pa.e = (int)s;
    if (pa.e > nel - 1) pa.e = nel - 1;
    pa.xi = s - pa.e;
    double se = s - 0.5;
    pa.e0 = (int)floor(se);
    pa.w1 = se - pa.e0;
    if (pa.e0 < 0) pa.e0 = 0, pa.w1 = 0;
    if (pa.e0 >= nel - 1) pa.e0 = nel - 1, pa.w1 = 0;
    pa.e1 = pa.e0 + 1 < nel ? pa.e0 + 1 : pa.e0;
    return pa;
}

/* record one sample: displacements of the probes from equilibrium (from configuration-sized u) */
static void sample(const gal_rod *rod, const probe_at *pa, int np, const double *u, double *row)
{
    int nn = rod->nn;
    for (int k = 0; k < np; k++) {
        const probe_at *a = pa + k;
        double d[3];
        for (int c = 0; c < 3; c++) d[c] = (1 - a->xi) * u[3 * a->e + c] + a->xi * u[3 * (a->e + 1) + c];
        double th = rod->p.torsion ? (1 - a->w1) * u[3 * nn + a->e0] + a->w1 * u[3 * nn + a->e1] : 0;
        row[4 * k + 0] = d[1];          /* horizontal (y) */
        row[4 * k + 1] = d[2];          /* vertical (z) */
        row[4 * k + 2] = d[0];          /* along (x) */
        row[4 * k + 3] = th * 180 / GAL_PI;
    }
}

static double element_tension(const gal_rod *rod, const double *q, int j)
{
    double e[3];
    for (int k = 0; k < 3; k++) e[k] = q[3 * (j + 1) + k] - q[3 * j + k];
    return rod->p.EA * (sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]) / rod->l0[j] - 1);
}

int gal_sim_run(gal_sim_setup *s, gal_model_kind kind, gal_sim_result *res)
{
    const gal_scene *sc = s->sc;
    const gal_rod *rod = s->eq.rod;
    memset(res, 0, sizeof *res);
    res->kind = kind;
    res->nprobe = sc->simulation.nprobes;
    memcpy(res->probe, sc->simulation.probes, sizeof res->probe);
    int np = res->nprobe, nq = rod->nq, st = GAL_OK;
    probe_at pa[GAL_MAX_PROBES];
    for (int k = 0; k < np; k++) pa[k] = probe_locate(rod, res->probe[k]);

    /* output sampling and the time step */
    const gal_modes *md = &s->md;
    double fhi = 0, wmin = INFINITY, wmax = 0;
    for (int k = 0; k < md->n; k++)
        if (md->mode[k].selected) {
            fhi = fmax(fhi, md->mode[k].frequency_hz);
            if (md->mode[k].omega > 0) wmin = fmin(wmin, md->mode[k].omega);
            wmax = fmax(wmax, md->mode[k].omega);
        }
    double dt_out = sc->simulation.output_interval;
    if (!(dt_out > 0)) dt_out = fmin(0.05, 1.0 / (10 * fhi));
    else if (dt_out > 0.25 / fhi) {
        /* the samples must resolve what the model carries, or the spectra alias */
        free(res->time);
        res->time = NULL;
        return gal_error(GAL_EINPUT, "%s: [simulation] output_interval = %g s cannot resolve the highest "
                         "selected mode (%.4g Hz); allowed: 0 (chosen) or up to %.4g s, a quarter of its period",
                         sc->path, dt_out, fhi, 0.25 / fhi);
    }
    res->dt_out = dt_out;
    long ns = (long)floor(sc->simulation.duration / dt_out + 1e-9) + 1;
    res->nsamples = ns;
    res->time = malloc((size_t)ns * sizeof(double));
    res->trace = calloc((size_t)ns * 4 * np, sizeof(double));
    res->tension = calloc((size_t)ns * 2, sizeof(double));
    double *u = calloc((size_t)nq, sizeof(double));
    if (!res->time || !res->trace || !res->tension || !u) {
        free(u);
        return gal_error(GAL_ENOMEM, "simulate: out of memory for %ld samples", ns);
    }
    double ra, rb;
    rayleigh(sc->effect[GAL_FX_DAMPING] ? sc->conductor.damping_ratio : 0, wmin, wmax, &ra, &rb);
    double t0 = gal_wall_time();
    for (long i = 0; i < ns; i++) res->time[i] = i * dt_out;

    if (kind == GAL_MODEL_FULL) {
        gal_dyn_opts o;
        gal_dyn_default_opts(&o);
        double h = sc->simulation.time_step;
        if (!(h > 0)) h = fmin(dt_out, 1.0 / (40 * fhi));
        int sub = (int)ceil(dt_out / h - 1e-9);
        o.h = dt_out / sub;
        o.rho_inf = sc->simulation.rho_inf;
        o.rayleigh_mass = ra, o.rayleigh_stiffness = rb;
        gal_force F = {0};
        if (s->loads.table) F.eval = gal_loads_full, F.ctx = &s->loads;
        gal_dyn *d = gal_dyn_alloc(rod, s->q_start, NULL, &o, &F);
        if (!d) { free(u); return GAL_EFAIL; }
        res->time_step_s = o.h;
        for (long i = 0; i < ns && !st; i++) {
            if (i > 0)
                for (int k = 0; k < sub && !st; k++) st = gal_dyn_step(d);
            for (int k = 0; k < nq; k++) u[k] = d->q[k] - s->eq.q[k];
            sample(rod, pa, np, u, res->trace + (size_t)i * 4 * np);
            res->tension[2 * i] = element_tension(rod, d->q, 0);
            res->tension[2 * i + 1] = element_tension(rod, d->q, rod->p.elements - 1);
            if (isatty(2) && i % 200 == 0) fprintf(stderr, "\rfull model: t = %.1f of %.1f s", res->time[i], res->time[ns - 1]);
        }
        if (isatty(2)) fprintf(stderr, "\n");
        res->steps = d->steps, res->newton_iterations = d->newton_iterations;
        res->factorizations = d->factorizations, res->force_evaluations = d->force_evaluations;
        res->rejected_steps = d->rejected_steps;
        gal_dyn_free(d);
    } else {
        double tb = gal_wall_time();
        int sel[64], r = 0;
        for (int k = 0; k < md->n && r < 64; k++)
            if (md->mode[k].selected) sel[r++] = k;
        /* observed: the loads' quadrature points (7 each), the probes (4 each: horizontal,
         * vertical, along, twist) and the support elements' inner nodes (3 each) */
        /* (the loads' kinematics from the expansion, gal_rdyn_quadrature_obs, changed the galloping
         * amplitudes of data/scenes/iced_gallop.ini by 0.2% at three times the cost: the loads use
         * the linear modes at the points) */
        int nqp = 16, no = 0; /* 2-point Gauss on 8 segments: the selected modes are smooth on them */
        gal_obs obs[4 * GAL_MAX_PROBES + 6];
        int po = no;
        for (int k = 0; k < np; k++) {
            const probe_at *a = pa + k;
            for (int c = 0; c < 3; c++) obs[no + c] = (gal_obs){{3 * a->e + c, 3 * (a->e + 1) + c}, {1 - a->xi, a->xi}};
            /* sample() wants horizontal (y), vertical (z), along (x) */
            gal_obs tmp = obs[no];
            obs[no] = obs[no + 1], obs[no + 1] = obs[no + 2], obs[no + 2] = tmp;
            obs[no + 3] = rod->p.torsion ? (gal_obs){{3 * rod->nn + a->e0, 3 * rod->nn + a->e1}, {1 - a->w1, a->w1}}
                                         : (gal_obs){{-1, -1}, {0, 0}};
            no += 4;
        }
        int so = no;
        for (int c = 0; c < 3; c++) obs[no++] = (gal_obs){{3 + c, -1}, {1, 0}};
        for (int c = 0; c < 3; c++) obs[no++] = (gal_obs){{3 * (rod->nn - 2) + c, -1}, {1, 0}};
        gal_reduced_opts ro;
        gal_reduced_default_opts(&ro);
        ro.amplitude_m = sc->model.identification_amplitude > 0 ? sc->model.identification_amplitude
                                                                 : fmax(1.0, s->eq.sag);
        ro.amplitude_rad = sc->model.identification_twist;
        gal_reduced *rm = gal_reduced_build(rod, s->eq.q, md, sel, r, obs, no, &ro);
        if (!rm) { free(u); return gal_error(GAL_EFAIL, "simulate: reduced model: %s", gal_error_message()); }
        res->build_time_s = gal_wall_time() - tb;
        res->basis = r, res->load_cases = rm->load_cases;
        gal_pointload pl = {0};
        if (s->loads.table) pl.eval = gal_loads_point, pl.ctx = &s->loads;
        gal_rdyn *d = gal_rdyn_alloc(rm, rod, s->eq.q, ra, rb, &pl, nqp, sc->simulation.tolerance, dt_out / 4, -1);
        if (d && sc->simulation.start_mean_wind) {
            /* the start in the modes: eta = Phi^T M (q_start - q_eq) */
            int n = rod->ndof;
            double *du = malloc((size_t)2 * n * sizeof(double));
            if (du) {
                for (int j = 0; j < n; j++) du[j] = s->q_start[rod->free_q[j]] - s->eq.q[rod->free_q[j]];
                gal_rod_mass_mult(rod, du, du + n);
                for (int i = 0; i < r; i++) {
                    double e = 0;
                    for (int j = 0; j < n; j++) e += rm->phi[(size_t)i * n + j] * du[n + j];
                    d->y[i] = e;
                }
                free(du);
            }
        }
        double *ov = malloc((size_t)no * sizeof(double)), *ys = malloc((size_t)2 * r * sizeof(double));
        if (!d || !ov || !ys) { free(ov); free(ys); gal_rdyn_free(d); gal_reduced_free(rm); free(u); return GAL_ENOMEM; }
        t0 = gal_wall_time();
        for (long i = 0; i < ns && !st; i++) {
            /* natural steps; the samples between them by Hermite interpolation */
            st = gal_rdyn_sample(d, res->time[i], res->time[ns - 1], ys);
            if (st) break;
            gal_reduced_observe(rm, ys, ov);
            double *row = res->trace + (size_t)i * 4 * np;
            for (int k = 0; k < np; k++) {
                for (int c = 0; c < 3; c++) row[4 * k + c] = ov[po + 4 * k + c];
                row[4 * k + 3] = ov[po + 4 * k + 3] * 180 / GAL_PI;
            }
            /* support tensions from the recovered inner nodes */
            memcpy(u, s->eq.q, (size_t)nq * sizeof(double));
            for (int c = 0; c < 3; c++) u[3 + c] += ov[so + c], u[3 * (rod->nn - 2) + c] += ov[so + 3 + c];
            res->tension[2 * i] = element_tension(rod, u, 0);
            res->tension[2 * i + 1] = element_tension(rod, u, rod->p.elements - 1);
        }
        gal_rdyn_counts(d, &res->steps, &res->rejected_steps);
        res->force_evaluations = d->rhs_evaluations;
        res->time_step_s = res->steps > 0 ? sc->simulation.duration / res->steps : 0;
        free(ov);
        free(ys);
        gal_rdyn_free(d);
        gal_reduced_free(rm);
    }
    res->wall_time_s = gal_wall_time() - t0;
    free(u);
    return st;
}
