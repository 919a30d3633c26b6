/* accuracy.c: what accuracy costs in time (issue 7): the sweep of the studies, the mesh study
 * (statics + modes against a fine mesh, and the first out-of-plane frequency against string
 * theory, f = 1/(2L) sqrt(H/m)) and the cheapest setting within the tolerance; the dynamic
 * studies are in accuracy_dyn.c. */
#include "gallop/analysis/accuracy.h"
#include "analysis/accuracy_int.h"
#include "gallop/base/core.h"
#include "gallop/model/model.h"
#include "gallop/modes/modes.h"
#include "gallop/run/forward.h"
#include "gallop/statics/statics.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const gal_acc_study_names[GAL_ACC_NSTUDY] = {"elements",         "modes", "time_step", "effects",
                                                            "newton_tolerance", "front"};

void gal_accuracy_default_opts(gal_acc_opts *o)
{
    o->tolerance = 0.01;
    o->studies = 1u << GAL_ACC_FRONT;
    o->repeats = 3;
    o->progress = 0;
    o->budget_s = 0;
    o->seeds = 3;
    o->max_levels = 3;
}

void gal_accuracy_clear(gal_acc_result *r)
{
    free(r->row);
    free(r->front.pt);
    memset(r, 0, sizeof *r);
}

double gal_acc_relerr(double a, double b)
{
    if (!isfinite(a) || !isfinite(b)) return INFINITY;
    if (a == b) return 0;
    return fabs(a - b) / fmax(fabs(b), 1e-300);
}

gal_acc_row *gal_acc_row_add(gal_acc_result *r, gal_acc_study s, const char *setting, const char *fmt, ...)
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

void gal_acc_progress(const gal_acc_opts *o, const gal_acc_row *w)
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
    gal_model *model;
    gal_data *data;            /* the pipeline to the modes */
    const gal_equilibrium *eq; /* its equilibrium and modes */
    const gal_modes *md;
    double t_statics, t_total; /* s */
} mesh_run;

static void mesh_clear(mesh_run *m)
{
    gal_data_free(m->data);
    gal_model_free(m->model);
    memset(m, 0, sizeof *m);
}

static int mesh_solve(const gal_scene *sc, mesh_run *m)
{
    memset(m, 0, sizeof *m);
    double t0 = gal_wall_time();
    int st;
    if (!(m->model = gal_model_alloc(sc, &st))) return st;
    if (!(m->data = gal_data_alloc(m->model))) return GAL_ENOMEM;
    if ((st = gal_forward(m->model, m->data, GAL_STAGE_EQUILIBRIUM)))
        return gal_error(st, "%d elements: %s", sc->model.elements, gal_error_message());
    m->t_statics = gal_wall_time() - t0;
    if ((st = gal_forward(m->model, m->data, GAL_STAGE_MODES)))
        return gal_error(st, "%d elements: %s", sc->model.elements, gal_error_message());
    m->eq = &m->data->eq, m->md = &m->data->md;
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
    double fs = string_hz(sc, ref.eq->horizontal_tension);
    r->string_hz = fs;
    int want[GAL_FAMILY_COUNT];
    scene_want(sc, want);
    for (int i = 0; i <= nv && !st; i++) {
        int isref = i == nv;
        gal_acc_row *w = gal_acc_row_add(r, GAL_ACC_ELEMENTS, "model.elements", "%d", isref ? nref : v[i]);
        if (!w) { st = gal_error(GAL_ENOMEM, "out of memory"); break; }
        mesh_run m, *pm = &ref;
        if (!isref) {
            s.model.elements = v[i];
            if (mesh_timed(&s, o->repeats, &m)) {
                if (o->progress) fprintf(stderr, "accuracy: %d elements failed: %s\n", v[i], gal_error_message());
                snprintf(w->failed, sizeof w->failed, "%s", gal_error_message());
                mesh_clear(&m);
                w->error = INFINITY;
                gal_acc_progress(o, w);
                continue;
            }
            pm = &m;
        }
        double ef = 0;
        for (int f = 0; f < 3; f++)
            for (int k = 0; k < want[f]; k++) {
                double a = family_hz(pm->md, f, k, 1), b = family_hz(ref.md, f, k, 1);
                if (isfinite(b)) ef = fmax(ef, gal_acc_relerr(a, b));
            }
        w->err_frequency = ef;
        w->err_sag = gal_acc_relerr(pm->eq->sag, ref.eq->sag);
        w->err_tension = gal_acc_relerr(pm->eq->horizontal_tension, ref.eq->horizontal_tension);
        w->error = fmax(ef, fmax(w->err_sag, w->err_tension));
        w->wall_time_s = pm->t_total;
        w->build_time_s = pm->t_statics;
        w->reference = isref;
        w->frequency_hz = family_hz(pm->md, GAL_FAMILY_HORIZONTAL, 0, 0);
        w->string_error = gal_acc_relerr(w->frequency_hz, fs);
        if (!isfinite(fs)) w->string_error = NAN;
        if (!isref) mesh_clear(&m);
        gal_acc_progress(o, w);
    }
    mesh_clear(&ref);
    return st;
}

/* highest selected mode frequency of the scene (Hz), from its own statics and modes */
static int scene_fhi(const gal_scene *sc, double *fhi)
{
    mesh_run m;
    int st = mesh_solve(sc, &m);
    *fhi = 0;
    if (!st)
        for (int i = 0; i < m.md->n; i++)
            if (m.md->mode[i].selected) *fhi = fmax(*fhi, m.md->mode[i].frequency_hz);
    mesh_clear(&m);
    if (!st && !(*fhi > 0)) st = gal_error(GAL_EFAIL, "no selected mode with a positive frequency");
    return st;
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
            snprintf(S->buys, sizeof S->buys, "every effect switched off changes the galloping measures by more "
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
                 "%.3g s (plus %.3g s of its own set-up), %.3gx faster than the full model (%.3g s), with the "
                 "vertical amplitude and frequency within %.3g%%", c->value, c->wall_time_s, c->build_time_s, ratio,
                 ref->wall_time_s, 100 * c->error);
        break;
    case GAL_ACC_TIME_STEP:
        snprintf(S->buys, sizeof S->buys, "a full-model time step of %s s runs in %.3g s, %.3gx faster than %s s "
                 "(%.3g s), with the vertical amplitude and frequency within %.3g%%", c->value,
                 c->wall_time_s, ratio, ref->value, ref->wall_time_s, 100 * c->error);
        break;
    case GAL_ACC_NEWTON_TOL:
        snprintf(S->buys, sizeof S->buys, "a full-model Newton tolerance of %s runs in %.3g s, %.3gx faster than %s "
                 "(%.3g s), with the vertical amplitude and frequency within %.3g%%", c->value,
                 c->wall_time_s, ratio, ref->value, ref->wall_time_s, 100 * c->error);
        break;
    default:
        snprintf(S->buys, sizeof S->buys, "%s = off changes the vertical amplitude and frequency by %.3g%% "
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
    if (!(o.budget_s >= 0) || o.seeds < 1 || o.seeds > 64 || o.max_levels < 1 || o.max_levels > 8)
        return gal_error(GAL_EINPUT, "accuracy: budget %g s, seeds %d, levels %d; allowed: budget >= 0, 1 <= seeds "
                         "<= 64, 1 <= levels <= 8", o.budget_s, o.seeds, o.max_levels);
    if (!(o.studies & ((1u << GAL_ACC_NSTUDY) - 1)))
        return gal_error(GAL_EINPUT, "accuracy: no study selected");
    r->tolerance = o.tolerance;
    double t0 = gal_wall_time();
    int st = GAL_OK;
    double fhi = 0;
    r->front.chosen = -1;
    unsigned dyn = (1u << GAL_ACC_MODES) | (1u << GAL_ACC_TIME_STEP) | (1u << GAL_ACC_EFFECTS) |
                   (1u << GAL_ACC_NEWTON_TOL);
    /* (the front study finds its own sampling) */
    /* the dynamic studies share the sampling of the scene's own run */
    gal_scene s = *sc;
    if (o.studies & dyn) {
        if ((st = scene_fhi(sc, &fhi))) return gal_error(st, "accuracy: %s: %s", sc->path, gal_error_message());
        if (!(s.simulation.output_interval > 0)) s.simulation.output_interval = fmin(0.05, 1.0 / (10 * fhi));
    }
    for (int k = 0; k < GAL_ACC_NSTUDY && !st; k++) {
        if (!(o.studies & (1u << k))) continue;
        r->study[k].ran = 1;
        r->study[k].steady_from_s = r->study[k].probe = NAN;
        r->study[k].output_interval_s = (dyn & (1u << k)) ? s.simulation.output_interval : NAN;
        if (o.progress) fprintf(stderr, "accuracy: study %s\n", gal_acc_study_names[k]);
        switch ((gal_acc_study)k) {
        case GAL_ACC_ELEMENTS: st = study_elements(sc, &o, r); break;
        case GAL_ACC_MODES: st = gal_acc_study_modes(&s, &o, r); break;
        case GAL_ACC_TIME_STEP: st = gal_acc_study_time_step(&s, &o, r, 1.0 / fhi); break;
        case GAL_ACC_NEWTON_TOL: st = gal_acc_study_newton_tol(&s, &o, r); break;
        case GAL_ACC_FRONT: st = gal_acc_study_front(sc, &o, r); break;
        default: st = gal_acc_study_effects(&s, &o, r); break;
        }
        if (!st && k != GAL_ACC_FRONT) choose(r, (gal_acc_study)k);
    }
    r->wall_time_s = gal_wall_time() - t0;
    return st;
}
