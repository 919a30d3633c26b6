/* accuracy.c: what accuracy costs in time (issue 7): sweeps of the mesh (statics + modes against a
 * fine mesh, and the first out-of-plane frequency against string theory, f = 1/(2L) sqrt(H/m)),
 * of the reduced basis (against one full-model run), of the full model's time step and the reduced
 * model's tolerance, and of the physical effects; the cheapest setting within the tolerance. */
#include "gallop/analysis/accuracy.h"
#include "gallop/base/core.h"
#include "gallop/output/json.h"
#include "gallop/output/ofile.h"
#include "gallop/model/model.h"
#include "gallop/modes/modes.h"
#include "gallop/run/sim.h"
#include "gallop/analysis/measure.h"
#include "gallop/statics/statics.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const gal_acc_study_names[GAL_ACC_NSTUDY] = {"elements", "modes", "time_step", "tolerance", "effects"};

void gal_accuracy_default_opts(gal_acc_opts *o)
{
    o->tolerance = 0.01;
    o->studies = (1u << GAL_ACC_NSTUDY) - 1;
    o->repeats = 3;
    o->progress = 0;
}

void gal_accuracy_clear(gal_acc_result *r)
{
    free(r->row);
    memset(r, 0, sizeof *r);
}

static double relerr(double a, double b)
{
    if (!isfinite(a) || !isfinite(b)) return INFINITY;
    if (a == b) return 0;
    return fabs(a - b) / fmax(fabs(b), 1e-300);
}

static gal_acc_row *row_add(gal_acc_result *r, gal_acc_study s, const char *setting, const char *fmt, ...)
{
    if (r->n == r->cap) {
        int cap = r->cap ? 2 * r->cap : 32;
        gal_acc_row *p = realloc(r->row, (size_t)cap * sizeof *p);
        if (!p) return NULL;
        r->row = p, r->cap = cap;
    }
    gal_acc_row *w = r->row + r->n++;
    memset(w, 0, sizeof *w);
    w->study = s;
    snprintf(w->setting, sizeof w->setting, "%s", setting);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(w->value, sizeof w->value, fmt, ap);
    va_end(ap);
    w->err_frequency = w->err_amplitude = w->err_sag = w->err_tension = w->string_error = NAN;
    w->frequency_hz = w->amplitude_m = NAN;
    return w;
}

static void progress(const gal_acc_opts *o, const gal_acc_row *w)
{
    if (!o->progress) return;
    fprintf(stderr, "accuracy: %-9s %s = %-10s error %-10.3g wall %.3f s\n", gal_acc_study_names[w->study],
            w->setting, w->value, w->error, w->wall_time_s);
}

static void scene_want(const gal_scene *sc, int want[GAL_FAMILY_COUNT])
{
    want[GAL_FAMILY_VERTICAL] = sc->model.modes_vertical;
    want[GAL_FAMILY_HORIZONTAL] = sc->model.modes_horizontal;
    want[GAL_FAMILY_TORSIONAL] = sc->effect[GAL_FX_TORSION] ? sc->model.modes_torsional : 0;
    want[GAL_FAMILY_AXIAL] = 0;
}

/* frequency of the k-th mode (0-based, by frequency) of family f, among the selected ones or all */
static double family_hz(const gal_modes *md, int f, int k, int selected_only)
{
    for (int i = 0; i < md->n; i++)
        if ((int)md->mode[i].family == f && (!selected_only || md->mode[i].selected) && k-- == 0)
            return md->mode[i].frequency_hz;
    return NAN;
}

static double median(double *v, int n)
{
    for (int i = 1; i < n; i++)
        for (int j = i; j > 0 && v[j] < v[j - 1]; j--) {
            double t = v[j];
            v[j] = v[j - 1], v[j - 1] = t;
        }
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* ======================================================================================
 * elements: statics + modes, the figures of a mesh */

typedef struct {
    gal_equilibrium eq;
    gal_modes md;
    int have_eq, have_md;
    double t_statics, t_total; /* s */
} mesh_run;

static void mesh_clear(mesh_run *m)
{
    if (m->have_md) gal_modes_clear(&m->md);
    if (m->have_eq) gal_equilibrium_clear(&m->eq);
    m->have_eq = m->have_md = 0;
}

static int mesh_solve(const gal_scene *sc, mesh_run *m)
{
    memset(m, 0, sizeof *m);
    gal_rod_params p;
    gal_statics_spec spec;
    double value;
    int want[GAL_FAMILY_COUNT];
    scene_want(sc, want);
    double t0 = gal_wall_time();
    int st = gal_model_rod_params(sc, &p, &spec, &value);
    if (st) return st;
    if ((st = gal_statics_solve(&p, spec, value, NULL, &m->eq)))
        return gal_error(st, "%d elements: no equilibrium: %s", sc->model.elements, gal_error_message());
    m->have_eq = 1;
    m->t_statics = gal_wall_time() - t0;
    if ((st = gal_modes_find(m->eq.rod, m->eq.q, want, 1000, &m->md)))
        return gal_error(st, "%d elements: modes: %s", sc->model.elements, gal_error_message());
    m->have_md = 1;
    m->t_total = gal_wall_time() - t0;
    return GAL_OK;
}

/* statics + modes timed: the median of `repeats` runs when one takes under a second */
static int mesh_timed(const gal_scene *sc, int repeats, mesh_run *m)
{
    int st = mesh_solve(sc, m);
    if (st || m->t_total >= 1.0 || repeats <= 1) return st;
    double tt[16], ts[16];
    int n = repeats > 16 ? 16 : repeats;
    tt[0] = m->t_total, ts[0] = m->t_statics;
    for (int i = 1; i < n; i++) {
        mesh_run x;
        st = mesh_solve(sc, &x);
        tt[i] = x.t_total, ts[i] = x.t_statics;
        mesh_clear(&x);
        if (st) return st;
    }
    m->t_total = median(tt, n);
    m->t_statics = median(ts, n);
    return GAL_OK;
}

/* first out-of-plane frequency of a level span under gravity by string theory, Hz (NaN: n/a) */
static double string_hz(const gal_scene *sc, double H)
{
    if (sc->span.height_difference != 0 || !sc->effect[GAL_FX_GRAVITY]) return NAN;
    double m = sc->conductor.mass_per_length + (sc->ice.present ? sc->ice.mass_per_length : 0);
    return sqrt(H / m) / (2 * sc->span.length);
}

static int study_elements(const gal_scene *sc, const gal_acc_opts *o, gal_acc_result *r)
{
    static const int list[] = {10, 20, 50, 100, 200, 400, 800};
    int own = sc->model.elements, v[16], nv = 0;
    int cap = 4 * own > 100 ? 4 * own : 100;  /* meshes far finer than the user's are not swept */
    for (size_t i = 0; i < sizeof list / sizeof list[0]; i++)
        if (list[i] <= cap) v[nv++] = list[i];
    int in = 0;
    for (int i = 0; i < nv; i++) in |= v[i] == own;
    if (!in) {  /* the scene's own mesh, in order */
        int i = nv++;
        while (i > 0 && v[i - 1] > own) v[i] = v[i - 1], i--;
        v[i] = own;
    }
    int nref = 4 * v[nv - 1] > 1600 ? 4 * v[nv - 1] : 1600;

    gal_scene s = *sc;
    s.model.elements = nref;
    mesh_run ref;
    int st = mesh_timed(&s, 1, &ref);
    if (st) { mesh_clear(&ref); return gal_error(st, "elements: the reference mesh: %s", gal_error_message()); }
    double fs = string_hz(sc, ref.eq.horizontal_tension);
    r->string_hz = fs;
    int want[GAL_FAMILY_COUNT];
    scene_want(sc, want);
    for (int i = 0; i <= nv && !st; i++) {
        int isref = i == nv;
        gal_acc_row *w = row_add(r, GAL_ACC_ELEMENTS, "model.elements", "%d", isref ? nref : v[i]);
        if (!w) { st = gal_error(GAL_ENOMEM, "out of memory"); break; }
        mesh_run m, *pm = &ref;
        if (!isref) {
            s.model.elements = v[i];
            if (mesh_timed(&s, o->repeats, &m)) {
                if (o->progress) fprintf(stderr, "accuracy: %d elements failed: %s\n", v[i], gal_error_message());
                snprintf(w->failed, sizeof w->failed, "%s", gal_error_message());
                mesh_clear(&m);
                w->error = INFINITY;
                progress(o, w);
                continue;
            }
            pm = &m;
        }
        double ef = 0;
        for (int f = 0; f < 3; f++)
            for (int k = 0; k < want[f]; k++) {
                double a = family_hz(&pm->md, f, k, 1), b = family_hz(&ref.md, f, k, 1);
                if (isfinite(b)) ef = fmax(ef, relerr(a, b));
            }
        w->err_frequency = ef;
        w->err_sag = relerr(pm->eq.sag, ref.eq.sag);
        w->err_tension = relerr(pm->eq.horizontal_tension, ref.eq.horizontal_tension);
        w->error = fmax(ef, fmax(w->err_sag, w->err_tension));
        w->wall_time_s = pm->t_total;
        w->build_time_s = pm->t_statics;
        w->reference = isref;
        w->frequency_hz = family_hz(&pm->md, GAL_FAMILY_HORIZONTAL, 0, 0);
        w->string_error = relerr(w->frequency_hz, fs);
        if (!isfinite(fs)) w->string_error = NAN;
        if (!isref) mesh_clear(&m);
        progress(o, w);
    }
    mesh_clear(&ref);
    return st;
}

/* ======================================================================================
 * dynamic studies: one run and its measures at mid-span */

typedef struct {
    double pp, hz;        /* vertical peak-to-peak (m) and dominant frequency (Hz) at mid-span */
    double from;          /* steady window start, s */
    double wall, build;   /* s */
} dyn_out;

static int dyn_measure(const gal_sim_result *res, double from, dyn_out *d)
{
    gal_sim_measures m;
    int st = gal_sim_measure(res, gal_sim_mid_probe(res), from, &m);
    if (st) return st;
    d->pp = m.peak_to_peak[1], d->hz = m.frequency_hz[1], d->from = m.steady_from_s;
    d->wall = res->wall_time_s, d->build = res->build_time_s;
    if (!isfinite(d->pp) || !isfinite(d->hz)) return gal_error(GAL_EFAIL, "the mid-span vertical measures are not finite");
    return GAL_OK;
}

/* set up the scene, run one model, measure (from < 0: detect the steady window) */
static int dyn_once(const gal_scene *sc, gal_model_kind kind, double from, dyn_out *d)
{
    gal_sim_setup s;
    gal_sim_result res;
    memset(&res, 0, sizeof res);
    int st = gal_sim_setup_init(&s, sc, kind == GAL_MODEL_REDUCED);
    if (!st) st = gal_sim_run(&s, kind, &res);
    if (!st) st = dyn_measure(&res, from, d);
    gal_sim_result_clear(&res);
    gal_sim_setup_clear(&s);
    return st;
}

static void dyn_fill(gal_acc_row *w, const dyn_out *d, const dyn_out *ref)
{
    w->err_amplitude = relerr(d->pp, ref->pp);
    w->err_frequency = relerr(d->hz, ref->hz);
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

/* highest selected mode frequency of the scene (Hz), from its own statics and modes */
static int scene_fhi(const gal_scene *sc, double *fhi)
{
    mesh_run m;
    int st = mesh_solve(sc, &m);
    *fhi = 0;
    if (!st)
        for (int i = 0; i < m.md.n; i++)
            if (m.md.mode[i].selected) *fhi = fmax(*fhi, m.md.mode[i].frequency_hz);
    mesh_clear(&m);
    if (!st && !(*fhi > 0)) st = gal_error(GAL_EFAIL, "no selected mode with a positive frequency");
    return st;
}

typedef struct { int v, h, t; } basis;

static int study_modes(const gal_scene *sc, const gal_acc_opts *o, gal_acc_result *r)
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
    int st = dyn_once(sc, GAL_MODEL_FULL, -1, &ref);
    if (st) return gal_error(st, "modes: the full-model reference run: %s", gal_error_message());
    S->steady_from_s = ref.from;
    gal_acc_row *w = row_add(r, GAL_ACC_MODES, "model", "full");
    if (!w) return gal_error(GAL_ENOMEM, "out of memory");
    dyn_fill(w, &ref, &ref);
    w->reference = 1;
    progress(o, w);
    gal_scene s = *sc;
    for (int i = 0; i < nb; i++) {
        s.model.modes_vertical = b[i].v, s.model.modes_horizontal = b[i].h;
        if (tors) s.model.modes_torsional = b[i].t;
        if (!(w = row_add(r, GAL_ACC_MODES, "model.modes", "%d/%d/%d", b[i].v, b[i].h, b[i].t)))
            return gal_error(GAL_ENOMEM, "out of memory");
        dyn_out d;
        if (dyn_once(&s, GAL_MODEL_REDUCED, ref.from, &d)) dyn_failed(o, w);
        else dyn_fill(w, &d, &ref);
        progress(o, w);
    }
    return GAL_OK;
}

/* a sweep of one setting on one shared set-up: full-model time steps or reduced tolerances */
static int study_sweep(const gal_scene *sc, const gal_acc_opts *o, gal_acc_result *r, gal_acc_study which,
                       double T)
{
    gal_acc_summary *S = &r->study[which];
    gal_scene s = *sc;
    int full = which == GAL_ACC_TIME_STEP;
    static const int div[] = {10, 20, 40, 80, 160};               /* T / div */
    static const double tol[] = {1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-11};
    int nv = full ? 5 : 7;
    if (full) s.simulation.output_interval = T / 10;  /* every step divides the sampling interval */
    S->output_interval_s = s.simulation.output_interval;
    gal_sim_setup su;
    int st = gal_sim_setup_init(&su, &s, 1);
    if (st) { gal_sim_setup_clear(&su); return gal_error(st, "%s: set-up: %s", gal_acc_study_names[which], gal_error_message()); }
    dyn_out d[8];
    int ok[8], ref = -1;
    char why[8][256];
    /* from the finest setting down: the finest that runs is the reference (the requested one
     * unless it fails, which the summary then says), measured first for its steady window */
    for (int i = nv - 1; i >= 0; i--) {
        if (full) s.simulation.time_step = T / div[i];
        else s.simulation.tolerance = tol[i];
        gal_sim_result res;
        ok[i] = !gal_sim_run(&su, full ? GAL_MODEL_FULL : GAL_MODEL_REDUCED, &res) &&
                !dyn_measure(&res, ref < 0 ? -1 : d[ref].from, &d[i]);
        gal_sim_result_clear(&res);
        if (!ok[i]) {
            snprintf(why[i], sizeof why[i], "%s", gal_error_message());
            if (o->progress) fprintf(stderr, "accuracy: %s run %d failed: %s\n", gal_acc_study_names[which], i, gal_error_message());
            if (i == nv - 1)
                snprintf(S->note, sizeof S->note, "the requested reference %s = %.3g failed (%s); the finest setting "
                         "that ran is the reference", full ? "simulation.time_step" : "simulation.tolerance",
                         full ? T / div[i] : tol[i], gal_error_message());
            continue;
        }
        if (ref < 0) ref = i, S->steady_from_s = d[i].from;
        if (o->progress) fprintf(stderr, "accuracy: %-9s %d of %d runs done\n", gal_acc_study_names[which], nv - i, nv);
    }
    if (ref < 0) {
        gal_sim_setup_clear(&su);
        return gal_error(GAL_EFAIL, "%s: no run succeeded: %s", gal_acc_study_names[which], gal_error_message());
    }
    gal_sim_setup_clear(&su);
    for (int i = 0; i < nv; i++) {
        gal_acc_row *w = full ? row_add(r, which, "simulation.time_step", "%.6g", T / div[i])
                              : row_add(r, which, "simulation.tolerance", "%.0e", tol[i]);
        if (!w) return gal_error(GAL_ENOMEM, "out of memory");
        if (ok[i]) dyn_fill(w, &d[i], &d[ref]);
        else w->error = INFINITY, snprintf(w->failed, sizeof w->failed, "%s", why[i]);
        w->reference = i == ref;
        progress(o, w);
    }
    return GAL_OK;
}

static int study_effects(const gal_scene *sc, const gal_acc_opts *o, gal_acc_result *r)
{
    gal_acc_summary *S = &r->study[GAL_ACC_EFFECTS];
    static const gal_effect fx[] = {GAL_FX_TORSION, GAL_FX_BENDING, GAL_FX_AERO_MOMENT, GAL_FX_AERO_DAMPING,
                                    GAL_FX_TURBULENCE, GAL_FX_DAMPING};
    dyn_out ref;
    int st = dyn_once(sc, GAL_MODEL_REDUCED, -1, &ref);
    if (st) return gal_error(st, "effects: the reference run (all effects on): %s", gal_error_message());
    S->steady_from_s = ref.from;
    gal_acc_row *w = row_add(r, GAL_ACC_EFFECTS, "effects", "all_on");
    if (!w) return gal_error(GAL_ENOMEM, "out of memory");
    dyn_fill(w, &ref, &ref);
    w->reference = 1;
    progress(o, w);
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
        if (!(w = row_add(r, GAL_ACC_EFFECTS, key, "off"))) return gal_error(GAL_ENOMEM, "out of memory");
        dyn_out d;
        if (dyn_once(&s, GAL_MODEL_REDUCED, ref.from, &d)) dyn_failed(o, w);
        else dyn_fill(w, &d, &ref);
        progress(o, w);
    }
    return GAL_OK;
}

/* ======================================================================================
 * the choice and what it buys */

static void choose(gal_acc_result *r, gal_acc_study s)
{
    gal_acc_summary *S = &r->study[s];
    S->reference = S->chosen = -1;
    int best = -1; /* the most accurate non-reference row, for the message when none meets */
    for (int i = 0; i < r->n; i++) {
        gal_acc_row *w = r->row + i;
        if (w->study != s) continue;
        if (w->reference) { S->reference = i; continue; }
        if (best < 0 || w->error < r->row[best].error) best = i;
        if (w->error <= r->tolerance && (S->chosen < 0 || w->wall_time_s < r->row[S->chosen].wall_time_s))
            S->chosen = i;
    }
    if (S->chosen >= 0) r->row[S->chosen].chosen = 1;
    const gal_acc_row *ref = S->reference >= 0 ? r->row + S->reference : NULL;
    const gal_acc_row *c = S->chosen >= 0 ? r->row + S->chosen : NULL;
    if (!ref) { snprintf(S->buys, sizeof S->buys, "no reference"); return; }
    if (!c) {
        if (s == GAL_ACC_EFFECTS)
            snprintf(S->buys, sizeof S->buys, "every effect switched off changes the mid-span galloping measures by more "
                     "than %.3g%%: keep them all on", 100 * r->tolerance);
        else if (best >= 0)
            snprintf(S->buys, sizeof S->buys, "no setting meets the tolerance of %.3g%%: the best, %s = %s, is off by "
                     "%.3g%%; use the reference (%s = %s, %.3g s) or finer", 100 * r->tolerance, r->row[best].setting,
                     r->row[best].value, 100 * r->row[best].error, ref->setting, ref->value, ref->wall_time_s);
        else snprintf(S->buys, sizeof S->buys, "no setting besides the reference");
        return;
    }
    double ratio = c->wall_time_s > 0 ? ref->wall_time_s / c->wall_time_s : INFINITY;
    switch (s) {
    case GAL_ACC_ELEMENTS:
        snprintf(S->buys, sizeof S->buys, "%s elements: statics + modes in %.3g s, %.3gx faster than the %s-element "
                 "reference (%.3g s), with mode frequencies, sag and tension within %.3g%%", c->value, c->wall_time_s,
                 ratio, ref->value, ref->wall_time_s, 100 * c->error);
        break;
    case GAL_ACC_MODES:
        snprintf(S->buys, sizeof S->buys, "a reduced basis of %s (vertical/horizontal/torsional) modes integrates in "
                 "%.3g s (plus %.3g s of identification), %.3gx faster than the full model (%.3g s), with the mid-span "
                 "vertical amplitude and frequency within %.3g%%", c->value, c->wall_time_s, c->build_time_s, ratio,
                 ref->wall_time_s, 100 * c->error);
        break;
    case GAL_ACC_TIME_STEP:
        snprintf(S->buys, sizeof S->buys, "a full-model time step of %s s runs in %.3g s, %.3gx faster than %s s "
                 "(%.3g s), with the mid-span vertical amplitude and frequency within %.3g%%", c->value,
                 c->wall_time_s, ratio, ref->value, ref->wall_time_s, 100 * c->error);
        break;
    case GAL_ACC_TOLERANCE:
        snprintf(S->buys, sizeof S->buys, "a reduced-model tolerance of %s runs in %.3g s, %.3gx faster than %s "
                 "(%.3g s), with the mid-span vertical amplitude and frequency within %.3g%%", c->value,
                 c->wall_time_s, ratio, ref->value, ref->wall_time_s, 100 * c->error);
        break;
    default:
        snprintf(S->buys, sizeof S->buys, "%s = off changes the mid-span vertical amplitude and frequency by %.3g%% "
                 "only and runs in %.3g s against %.3g s with every effect on", c->setting, 100 * c->error,
                 c->wall_time_s, ref->wall_time_s);
        break;
    }
}

int gal_accuracy_run(const gal_scene *sc, const gal_acc_opts *opts, gal_acc_result *r)
{
    memset(r, 0, sizeof *r);
    gal_acc_opts o;
    if (opts) o = *opts;
    else gal_accuracy_default_opts(&o);
    for (int s = 0; s < GAL_ACC_NSTUDY; s++) r->study[s].reference = r->study[s].chosen = -1;
    r->string_hz = NAN;
    if (!(o.tolerance > 0 && o.tolerance < 1))
        return gal_error(GAL_EINPUT, "accuracy: tolerance %g; allowed: 0 < tolerance < 1", o.tolerance);
    if (!(o.studies & ((1u << GAL_ACC_NSTUDY) - 1)))
        return gal_error(GAL_EINPUT, "accuracy: no study selected");
    r->tolerance = o.tolerance;
    double t0 = gal_wall_time();
    int st = GAL_OK;
    double fhi = 0;
    unsigned dyn = (1u << GAL_ACC_MODES) | (1u << GAL_ACC_TIME_STEP) | (1u << GAL_ACC_TOLERANCE) | (1u << GAL_ACC_EFFECTS);
    /* the dynamic studies share the sampling of the scene's own run */
    gal_scene s = *sc;
    if (o.studies & dyn) {
        if ((st = scene_fhi(sc, &fhi))) return gal_error(st, "accuracy: %s: %s", sc->path, gal_error_message());
        if (!(s.simulation.output_interval > 0)) s.simulation.output_interval = fmin(0.05, 1.0 / (10 * fhi));
    }
    for (int k = 0; k < GAL_ACC_NSTUDY && !st; k++) {
        if (!(o.studies & (1u << k))) continue;
        r->study[k].ran = 1;
        r->study[k].steady_from_s = NAN;
        r->study[k].output_interval_s = (dyn & (1u << k)) ? s.simulation.output_interval : NAN;
        if (o.progress) fprintf(stderr, "accuracy: study %s\n", gal_acc_study_names[k]);
        switch ((gal_acc_study)k) {
        case GAL_ACC_ELEMENTS: st = study_elements(sc, &o, r); break;
        case GAL_ACC_MODES: st = study_modes(&s, &o, r); break;
        case GAL_ACC_TIME_STEP: st = study_sweep(&s, &o, r, GAL_ACC_TIME_STEP, 1.0 / fhi); break;
        case GAL_ACC_TOLERANCE: st = study_sweep(&s, &o, r, GAL_ACC_TOLERANCE, 1.0 / fhi); break;
        default: st = study_effects(&s, &o, r); break;
        }
        if (!st) choose(r, (gal_acc_study)k);
    }
    r->wall_time_s = gal_wall_time() - t0;
    return st;
}

/* ======================================================================================
 * output */

static void csv_num(FILE *fp, double v)
{
    if (isnan(v)) fprintf(fp, "nan");
    else if (isinf(v)) fprintf(fp, "inf");
    else fprintf(fp, "%.6g", v);
}

static void json_row(gal_json *j, const gal_acc_row *w)
{
    gal_json_obj_begin(j);
    gal_json_kv_str(j, "setting", w->setting);
    gal_json_kv_str(j, "value", w->value);
    gal_json_kv_num(j, "error", w->error);
    gal_json_kv_num(j, "wall_time_s", w->wall_time_s);
    gal_json_kv_num(j, "build_time_s", w->build_time_s);
    if (w->study == GAL_ACC_ELEMENTS) {
        gal_json_kv_num(j, "error_frequency", w->err_frequency);
        gal_json_kv_num(j, "error_sag", w->err_sag);
        gal_json_kv_num(j, "error_horizontal_tension", w->err_tension);
        gal_json_kv_num(j, "first_horizontal_hz", w->frequency_hz);
        gal_json_kv_num(j, "string_theory_error", w->string_error);
    } else {
        gal_json_kv_num(j, "error_amplitude", w->err_amplitude);
        gal_json_kv_num(j, "error_frequency", w->err_frequency);
        gal_json_kv_num(j, "vertical_peak_to_peak_m", w->amplitude_m);
        gal_json_kv_num(j, "vertical_frequency_hz", w->frequency_hz);
    }
    if (w->failed[0]) gal_json_kv_str(j, "failed", w->failed);
    gal_json_kv_int(j, "reference", w->reference);
    gal_json_kv_int(j, "chosen", w->chosen);
    gal_json_obj_end(j);
}

int gal_accuracy_write(const char *dir, const gal_scene *sc, const gal_acc_result *r)
{
    int st = gal_mkdirs(dir);
    if (st) return st;
    char *pc = gal_path_join(dir, "accuracy.csv"), *pj = gal_path_join(dir, "summary.json");
    if (!pc || !pj) { free(pc); free(pj); return gal_error(GAL_ENOMEM, "out of memory"); }
    gal_ofile f;
    if (!(st = gal_ofile_open(&f, pc))) {
        fprintf(f.fp, "study,setting,value,error,wall_time_s,chosen\n");
        for (int i = 0; i < r->n; i++) {
            const gal_acc_row *w = r->row + i;
            fprintf(f.fp, "%s,%s,%s,", gal_acc_study_names[w->study], w->setting, w->value);
            csv_num(f.fp, w->error);
            fprintf(f.fp, ",%.6g,%d\n", w->wall_time_s, w->chosen);
        }
        st = gal_ofile_close(&f, 1);
    }
    if (!st && !(st = gal_ofile_open(&f, pj))) {
        gal_json j;
        gal_json_begin(&j, f.fp);
        gal_json_kv_str(&j, "scene", sc->path);
        gal_json_kv_num(&j, "tolerance", r->tolerance);
        gal_json_kv_num(&j, "wall_time_s", r->wall_time_s);
        gal_json_key(&j, "string_theory");
        gal_json_obj_begin(&j);
        gal_json_kv_str(&j, "applies", isfinite(r->string_hz) ? "level span with gravity: f_1 = 1/(2L) sqrt(H/m)"
                                                              : "no (inclined span, gravity off, or elements study not run)");
        gal_json_kv_num(&j, "first_horizontal_hz", r->string_hz);
        gal_json_obj_end(&j);
        gal_json_key(&j, "studies");
        gal_json_obj_begin(&j);
        for (int s = 0; s < GAL_ACC_NSTUDY; s++) {
            const gal_acc_summary *S = r->study + s;
            if (!S->ran) continue;
            gal_json_key(&j, gal_acc_study_names[s]);
            gal_json_obj_begin(&j);
            const gal_acc_row *ref = S->reference >= 0 ? r->row + S->reference : NULL;
            const gal_acc_row *c = S->chosen >= 0 ? r->row + S->chosen : NULL;
            gal_json_key(&j, "reference");
            gal_json_obj_begin(&j);
            gal_json_kv_str(&j, "setting", ref ? ref->setting : "");
            gal_json_kv_str(&j, "value", ref ? ref->value : "");
            gal_json_kv_num(&j, "wall_time_s", ref ? ref->wall_time_s : NAN);
            gal_json_obj_end(&j);
            gal_json_key(&j, "meets_tolerance");
            gal_json_bool(&j, c != NULL);
            gal_json_key(&j, "chosen");
            if (c) {
                gal_json_obj_begin(&j);
                gal_json_kv_str(&j, "setting", c->setting);
                gal_json_kv_str(&j, "value", c->value);
                gal_json_kv_num(&j, "error", c->error);
                gal_json_kv_num(&j, "wall_time_s", c->wall_time_s);
                gal_json_kv_num(&j, "build_time_s", c->build_time_s);
                gal_json_obj_end(&j);
            } else {
                gal_json_num(&j, NAN);
            }
            gal_json_kv_str(&j, "buys", S->buys);
            if (S->note[0]) gal_json_kv_str(&j, "note", S->note);
            if (isfinite(S->steady_from_s)) gal_json_kv_num(&j, "steady_from_s", S->steady_from_s);
            if (isfinite(S->output_interval_s)) gal_json_kv_num(&j, "output_interval_s", S->output_interval_s);
            gal_json_key(&j, "rows");
            gal_json_arr_begin(&j);
            for (int i = 0; i < r->n; i++)
                if ((int)r->row[i].study == s) json_row(&j, r->row + i);
            gal_json_arr_end(&j);
            gal_json_obj_end(&j);
        }
        gal_json_obj_end(&j);
        gal_json_end(&j);
        st = gal_ofile_close(&f, !ferror(f.fp));
    }
    free(pc);
    free(pj);
    return st;
}

void gal_accuracy_print(FILE *fp, const gal_acc_result *r)
{
    fprintf(fp, "%-10s %-22s %-10s %12s %12s %12s  %s\n", "study", "setting", "value", "error %", "wall s", "build s", "");
    for (int i = 0; i < r->n; i++) {
        const gal_acc_row *w = r->row + i;
        fprintf(fp, "%-10s %-22s %-10s %12.4g %12.4g %12.4g  %s\n", gal_acc_study_names[w->study], w->setting,
                w->value, 100 * w->error, w->wall_time_s, w->build_time_s,
                w->chosen ? "<- chosen" : w->reference ? "(reference)" : w->failed[0] ? "(failed: see summary.json)" : "");
    }
    fprintf(fp, "\ntolerance %.3g%%\n", 100 * r->tolerance);
    for (int s = 0; s < GAL_ACC_NSTUDY; s++)
        if (r->study[s].ran) {
            fprintf(fp, "%-10s %s\n", gal_acc_study_names[s], r->study[s].buys);
            if (r->study[s].note[0]) fprintf(fp, "%-10s note: %s\n", "", r->study[s].note);
        }
    if (isfinite(r->string_hz))
        fprintf(fp, "string theory: first out-of-plane frequency %.6g Hz (errors of each mesh in summary.json)\n",
                r->string_hz);
    fprintf(fp, "total wall time %.3g s\n", r->wall_time_s);
}
