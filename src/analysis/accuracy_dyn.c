/* accuracy_dyn.c: the dynamic studies of `gallop accuracy` (issue 7): the reduced basis against
 * one full-model run, the full model's time step, the physical effects; each setting is one run
 * measured as `gallop compare` measures (compare.h: at the reference's headline probe). */
#include "gallop/analysis/accuracy.h"
#include "analysis/accuracy_int.h"
#include "gallop/base/core.h"
#include "gallop/analysis/compare.h"
#include "gallop/analysis/measure.h"
#include "gallop/run/sim.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* ======================================================================================
 * dynamic studies: one run and its measures as `gallop compare` takes them (compare.h): over the
 * reference's window, at the probe where the reference moves most vertically */

typedef struct {
    double pp, hz;        /* vertical peak-to-peak (m) and fundamental frequency (Hz) at the headline probe */
    double from;          /* steady window start, s */
    double wall, build;   /* s */
} dyn_out;

/* res measured against the reference *h; detect: res is the reference, *h is set from it */
static int dyn_measure(const gal_sim_result *res, gal_compare_ref *h, int detect, dyn_out *d)
{
    gal_sim_measures m;
    int st = detect ? gal_compare_reference(res, -1, h) : GAL_OK;
    if (!st) st = gal_compare_measure(res, h, &m);
    if (st) return st;
    d->pp = m.peak_to_peak[1], d->hz = m.frequency_hz[1], d->from = h->from;
    d->wall = res->wall_time_s, d->build = res->build_time_s;
    if (!isfinite(d->pp) || !isfinite(d->hz)) return gal_error(GAL_EFAIL, "the vertical measures are not finite");
    return GAL_OK;
}

/* set up the scene, run one model, measure (detect: the reference run, which sets *h) */
static int dyn_once(const gal_scene *sc, gal_model_kind kind, gal_compare_ref *h, int detect, dyn_out *d)
{
    gal_sim_setup s;
    gal_sim_result res;
    memset(&res, 0, sizeof res);
    int st = gal_sim_setup_init(&s, sc, kind == GAL_MODEL_REDUCED);
    if (!st) st = gal_sim_run(&s, kind, &res);
    if (!st) st = dyn_measure(&res, h, detect, d);
    gal_sim_result_clear(&res);
    gal_sim_setup_clear(&s);
    return st;
}

static void dyn_fill(gal_acc_row *w, const dyn_out *d, const dyn_out *ref)
{
    w->err_amplitude = gal_acc_relerr(d->pp, ref->pp);
    w->err_frequency = gal_acc_relerr(d->hz, ref->hz);
    w->error = fmax(w->err_amplitude, w->err_frequency);
    w->wall_time_s = d->wall;
    w->build_time_s = d->build;
    w->amplitude_m = d->pp;
    w->frequency_hz = d->hz;
}

static void dyn_failed(const gal_acc_opts *o, gal_acc_row *w)
{
    if (o->progress) fprintf(stderr, "accuracy: %s = %s failed: %s\n", w->setting, w->value, gal_error_message());
    snprintf(w->failed, sizeof w->failed, "%s", gal_error_message());
    w->error = INFINITY;
}

typedef struct { int v, h, t; } basis;

int gal_acc_study_modes(const gal_scene *sc, const gal_acc_opts *o, gal_acc_result *r)
{
    gal_acc_summary *S = &r->study[GAL_ACC_MODES];
    static const basis list[] = {{1, 1, 1}, {2, 1, 1}, {2, 2, 1}, {3, 2, 1}, {3, 2, 2}, {4, 3, 2}};
    int tors = sc->effect[GAL_FX_TORSION];
    basis b[8];
    int nb = 0;
    basis own = {sc->model.modes_vertical, sc->model.modes_horizontal, tors ? sc->model.modes_torsional : 0};
    for (int i = 0; i <= 6; i++) {
        basis x = i < 6 ? list[i] : own;
        if (!tors) x.t = 0;
        if (x.v + x.h + x.t == 0) continue;
        int dup = 0;
        for (int j = 0; j < nb; j++) dup |= b[j].v == x.v && b[j].h == x.h && b[j].t == x.t;
        if (dup) continue;
        int j = nb++;  /* in order of size */
        while (j > 0 && b[j - 1].v + b[j - 1].h + b[j - 1].t > x.v + x.h + x.t) b[j] = b[j - 1], j--;
        b[j] = x;
    }
    dyn_out ref;
    gal_compare_ref h;
    int st = dyn_once(sc, GAL_MODEL_FULL, &h, 1, &ref);
    if (st) return gal_error(st, "modes: the full-model reference run: %s", gal_error_message());
    S->steady_from_s = ref.from, S->probe = h.position[GAL_CMP_VERTICAL];
    gal_acc_row *w = gal_acc_row_add(r, GAL_ACC_MODES, "model", "full");
    if (!w) return gal_error(GAL_ENOMEM, "out of memory");
    dyn_fill(w, &ref, &ref);
    w->reference = 1;
    gal_acc_progress(o, w);
    gal_scene s = *sc;
    for (int i = 0; i < nb; i++) {
        s.model.modes_vertical = b[i].v, s.model.modes_horizontal = b[i].h;
        if (tors) s.model.modes_torsional = b[i].t;
        if (!(w = gal_acc_row_add(r, GAL_ACC_MODES, "model.modes", "%d/%d/%d", b[i].v, b[i].h, b[i].t)))
            return gal_error(GAL_ENOMEM, "out of memory");
        dyn_out d;
        if (dyn_once(&s, GAL_MODEL_REDUCED, &h, 0, &d)) dyn_failed(o, w);
        else dyn_fill(w, &d, &ref);
        gal_acc_progress(o, w);
    }
    return GAL_OK;
}

/* one setting of a swept key of the full model */
static void set_value(gal_scene *s, gal_acc_study which, double v)
{
    if (which == GAL_ACC_TIME_STEP) s->simulation.time_step = v;
    else s->simulation.newton_tolerance = v;
}

/* the full model's key (simulation.time_step or newton_tolerance) swept over val[0..nv-1] on one
 * shared set-up, the last value the reference */
static int full_sweep(gal_scene s, const gal_acc_opts *o, gal_acc_result *r, gal_acc_study which, const char *key,
                      const double *val, int nv)
{
    gal_acc_summary *S = &r->study[which];
    gal_sim_setup su;
    int st = gal_sim_setup_init(&su, &s, 1);
    if (st) { gal_sim_setup_clear(&su); return gal_error(st, "%s: set-up: %s", gal_acc_study_names[which], gal_error_message()); }
    dyn_out d[8];
    gal_compare_ref h;
    int ok[8], ref = -1;
    char why[8][256];
    /* from the finest setting down: the finest that runs is the reference (the requested one
     * unless it fails, which the summary then says), measured first for its steady window */
    for (int i = nv - 1; i >= 0; i--) {
        set_value(&s, which, val[i]);
        gal_sim_result res;
        ok[i] = !gal_sim_run(&su, GAL_MODEL_FULL, &res) &&
                !dyn_measure(&res, &h, ref < 0, &d[i]);
        gal_sim_result_clear(&res);
        if (!ok[i]) {
            snprintf(why[i], sizeof why[i], "%s", gal_error_message());
            if (o->progress) fprintf(stderr, "accuracy: %s run %d failed: %s\n", gal_acc_study_names[which], i, gal_error_message());
            if (i == nv - 1)
                snprintf(S->note, sizeof S->note, "the requested reference %s = %.3g failed (%s); "
                         "the finest setting that ran is the reference", key, val[i], gal_error_message());
            continue;
        }
        if (ref < 0) ref = i, S->steady_from_s = d[i].from, S->probe = h.position[GAL_CMP_VERTICAL];
        if (o->progress) fprintf(stderr, "accuracy: %-9s %d of %d runs done\n", gal_acc_study_names[which], nv - i, nv);
    }
    if (ref < 0) {
        gal_sim_setup_clear(&su);
        return gal_error(GAL_EFAIL, "%s: no run succeeded: %s", gal_acc_study_names[which], gal_error_message());
    }
    gal_sim_setup_clear(&su);
    for (int i = 0; i < nv; i++) {
        gal_acc_row *w = gal_acc_row_add(r, which, key, "%.6g", val[i]);
        if (!w) return gal_error(GAL_ENOMEM, "out of memory");
        if (ok[i]) dyn_fill(w, &d[i], &d[ref]);
        else w->error = INFINITY, snprintf(w->failed, sizeof w->failed, "%s", why[i]);
        w->reference = i == ref;
        gal_acc_progress(o, w);
    }
    return GAL_OK;
}

/* the full model's time step, T/10 .. T/160 */
int gal_acc_study_time_step(const gal_scene *sc, const gal_acc_opts *o, gal_acc_result *r, double T)
{
    gal_scene s = *sc;
    static const int div[] = {10, 20, 40, 80, 160};               /* T / div */
    double val[5];
    for (int i = 0; i < 5; i++) val[i] = T / div[i];
    s.simulation.output_interval = T / 10;  /* every step divides the sampling interval */
    r->study[GAL_ACC_TIME_STEP].output_interval_s = s.simulation.output_interval;
    return full_sweep(s, o, r, GAL_ACC_TIME_STEP, "simulation.time_step", val, 5);
}

/* the full model's Newton tolerance, 1e-3 .. 1e-10 (the reference), at the scene's step */
int gal_acc_study_newton_tol(const gal_scene *sc, const gal_acc_opts *o, gal_acc_result *r)
{
    static const double val[] = {1e-3, 1e-4, 1e-6, 1e-8, 1e-10};
    return full_sweep(*sc, o, r, GAL_ACC_NEWTON_TOL, "simulation.newton_tolerance", val, 5);
}

int gal_acc_study_effects(const gal_scene *sc, const gal_acc_opts *o, gal_acc_result *r)
{
    gal_acc_summary *S = &r->study[GAL_ACC_EFFECTS];
    static const gal_effect fx[] = {GAL_FX_TORSION, GAL_FX_BENDING, GAL_FX_AERO_MOMENT, GAL_FX_AERO_DAMPING,
                                    GAL_FX_TURBULENCE, GAL_FX_DAMPING};
    dyn_out ref;
    gal_compare_ref h;
    int st = dyn_once(sc, GAL_MODEL_REDUCED, &h, 1, &ref);
    if (st) return gal_error(st, "effects: the reference run (all effects on): %s", gal_error_message());
    S->steady_from_s = ref.from, S->probe = h.position[GAL_CMP_VERTICAL];
    gal_acc_row *w = gal_acc_row_add(r, GAL_ACC_EFFECTS, "effects", "all_on");
    if (!w) return gal_error(GAL_ENOMEM, "out of memory");
    dyn_fill(w, &ref, &ref);
    w->reference = 1;
    gal_acc_progress(o, w);
    for (size_t i = 0; i < sizeof fx / sizeof fx[0]; i++) {
        gal_effect e = fx[i];
        if (!sc->effect[e]) continue;
        /* only effects that do something in this scene */
        if (e == GAL_FX_AERO_MOMENT && !sc->effect[GAL_FX_TORSION]) continue;
        if (e == GAL_FX_TURBULENCE && sc->wind.turbulence == GAL_TURB_NONE) continue;
        if (e == GAL_FX_DAMPING && !(sc->conductor.damping_ratio > 0)) continue;
        gal_scene s = *sc;
        s.effect[e] = 0;
        char key[48];
        snprintf(key, sizeof key, "effects.%s", gal_effect_names[e]);
        if (!(w = gal_acc_row_add(r, GAL_ACC_EFFECTS, key, "off"))) return gal_error(GAL_ENOMEM, "out of memory");
        dyn_out d;
        if (dyn_once(&s, GAL_MODEL_REDUCED, &h, 0, &d)) dyn_failed(o, w);
        else dyn_fill(w, &d, &ref);
        gal_acc_progress(o, w);
    }
    return GAL_OK;
}
