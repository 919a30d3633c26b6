/* accuracy_front.c: the front study of `gallop accuracy` (issue 20): one configuration's runs and
 * measures (every seed in turbulent wind), the converged reference (the full model refined in
 * elements and time step until every measure's estimated error is below a tenth of the tolerance:
 * Richardson's, M* = M_K + (M_K - M_K-1) / (2^p - 1), with p the order observed over the last three
 * levels where it is known, else the last change) and the study's constants (output interval,
 * base step). */
#include "gallop/analysis/accuracy.h"
#include "analysis/accuracy_front_int.h"
#include "analysis/accuracy_int.h"
#include "gallop/analysis/measure.h"
#include "gallop/base/core.h"
#include "gallop/model/model.h"
#include "gallop/run/forward.h"
#include "gallop/run/sim.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const gal_acc_measure_names[GAL_ACC_NMEAS] = {"frequency", "vertical", "horizontal",
                                                          "twist",     "tension",  "time_to_steady"};

double gal_acc_budget_left(const acc_study *S)
{
    if (!(S->o->budget_s > 0)) return INFINITY;
    return S->o->budget_s - (gal_wall_time() - S->t0);
}

void gal_acc_config_label(const gal_acc_config *c, char *buf, size_t n)
{
    char m[56] = "full";
    if (c->reduced) snprintf(m, sizeof m, "reduced %d/%d/%d", c->modes[0], c->modes[1], c->modes[2]);
    if (c->newton_tol > 0) { /* before N and h: they stay the label's last two words */
        size_t l = strlen(m);
        snprintf(m + l, sizeof m - l, " tol=%.3g", c->newton_tol);
    }
    if (c->effect_off >= 0)
        snprintf(buf, n, "%s N=%d h=%.4g -%s", m, c->elements, c->time_step, gal_effect_names[c->effect_off]);
    else snprintf(buf, n, "%s N=%d h=%.4g", m, c->elements, c->time_step);
}

gal_acc_point *gal_acc_point_add(gal_acc_front *F)
{
    if (F->n == F->cap) {
        int cap = F->cap ? 2 * F->cap : 32;
        gal_acc_point *p = realloc(F->pt, (size_t)cap * sizeof *p);
        if (!p) return NULL;
        F->pt = p, F->cap = cap;
    }
    gal_acc_point *p = F->pt + F->n++;
    memset(p, 0, sizeof *p);
    for (int k = 0; k < GAL_ACC_NMEAS; k++) p->value[k] = p->err[k] = p->spread[k] = NAN;
    p->error = INFINITY;
    p->predicted_error = p->predicted_time_s = NAN;
    return p;
}

/* the scene of configuration c (seed k) */
static void config_scene(const acc_study *S, const gal_acc_config *c, int seed, gal_scene *s)
{
    *s = *S->sc;
    s->model.elements = c->elements;
    if (c->reduced) {
        s->model.modes_vertical = c->modes[0], s->model.modes_horizontal = c->modes[1];
        s->model.modes_torsional = c->modes[2];
        s->model.on_invalid_warn = 1; /* an invalid run is scored, not dropped */
    }
    s->simulation.time_step = c->time_step;
    if (c->newton_tol > 0) s->simulation.newton_tolerance = c->newton_tol;
    s->simulation.output_interval = S->F->output_interval_s;
    s->simulation.duration = S->duration;
    if (c->effect_off >= 0) s->effect[c->effect_off] = 0;
    s->wind.seed = S->sc->wind.seed + seed;
}

/* the measures of one run into v, as `gallop compare` takes them (compare.h): each family at the
 * probe where the reference moves most, over its window; the first run measured with a detected
 * window (from < 0) sets them */
static int measures_of(acc_study *S, const gal_sim_result *res, double from, double v[GAL_ACC_NMEAS],
                       double *from_out)
{
    gal_sim_measures m;
    int st = GAL_OK;
    if (!S->have_ref && !(st = gal_compare_reference(res, from, &S->ref))) {
        S->have_ref = 1;
        memcpy(S->F->probe, S->ref.position, sizeof S->F->probe);
    }
    if (st) return st;
    gal_compare_ref h = S->ref;
    if (from >= 0) h.from = from;
    if ((st = gal_compare_measure(res, &h, &m))) return st;
    /* amplitudes as RMS over the window: an integral of the trace, smooth in the discretization
     * (a peak-to-peak read off samples moves with where the samples fall on the crest) */
    const double *a = m.rms;
    int fc = S->fcomp >= 0 ? S->fcomp : a[1] >= a[0]; /* not chosen yet: the larger of this run */
    v[GAL_ACC_M_FREQUENCY] = m.frequency_hz[fc];
    v[GAL_ACC_M_VERTICAL] = a[1];
    v[GAL_ACC_M_HORIZONTAL] = a[0];
    v[GAL_ACC_M_TWIST] = a[3];
    v[GAL_ACC_M_TENSION] = m.tension_max_steady;
    v[GAL_ACC_M_STEADY] = m.time_to_steady_s;
    *from_out = m.steady_from_s;
    return GAL_OK;
}

int gal_acc_config_run(acc_study *S, const gal_acc_config *c, double from, gal_acc_point *p)
{
    p->c = *c;
    gal_acc_config_label(c, p->label, sizeof p->label);
    int ns = S->F->nseeds, st = GAL_OK;
    double sum[GAL_ACC_NMEAS] = {0}, sq[GAL_ACC_NMEAS] = {0}, t0 = gal_wall_time(), fr = from;
    for (int k = 0; k < ns && !st; k++) {
        gal_scene s;
        config_scene(S, c, k, &s);
        gal_sim_setup su;
        gal_sim_result res;
        memset(&res, 0, sizeof res);
        double v[GAL_ACC_NMEAS];
        st = gal_sim_setup_init(&su, &s, 1);
        if (!st) st = gal_sim_run(&su, c->reduced ? GAL_MODEL_REDUCED : GAL_MODEL_FULL, &res);
        if (!st) st = measures_of(S, &res, fr, v, &fr);
        p->newton_iterations += res.newton_iterations;
        gal_sim_result_clear(&res);
        gal_sim_setup_clear(&su);
        for (int j = 0; j < GAL_ACC_NMEAS && !st; j++) sum[j] += v[j] / ns, sq[j] += v[j] * v[j] / ns;
    }
    p->wall_time_s = gal_wall_time() - t0;
    if (st) {
        snprintf(p->failed, sizeof p->failed, "%s", gal_error_message());
        p->error = INFINITY;
        return st;
    }
    memcpy(p->value, sum, sizeof sum);
    for (int j = 0; j < GAL_ACC_NMEAS; j++) /* standard error of the mean over the seeds, relative */
        p->spread[j] = ns > 1 && sum[j] != 0
                           ? sqrt(fmax(sq[j] - sum[j] * sum[j], 0) * ns / (ns - 1) / ns) / fabs(sum[j]) : NAN;
    if (from < 0) S->F->steady_from_s = fr;
    return GAL_OK;
}

void gal_acc_score(const gal_acc_front *F, gal_acc_point *p)
{
    if (p->failed[0]) { p->error = INFINITY; return; }
    p->error = 0;
    for (int k = 0; k < GAL_ACC_NMEAS; k++) {
        p->err[k] = F->scored[k] ? gal_acc_relerr(p->value[k], F->ref_value[k]) : NAN;
        if (F->scored[k]) p->error = fmax(p->error, p->err[k]);
    }
}

void gal_acc_progress_point(const acc_study *S, const gal_acc_point *p)
{
    if (!S->o->progress) return;
    double left = gal_acc_budget_left(S);
    fprintf(stderr, "accuracy: front %-9s %-40s error %-10.3g wall %8.3f s", p->group, p->label, p->error,
            p->wall_time_s);
    if (isfinite(left)) fprintf(stderr, "  (budget left %.0f s)", left);
    if (p->failed[0]) fprintf(stderr, "  failed: %s", p->failed);
    fprintf(stderr, "\n");
}

/* ======================================================================================
 * the reference */

/* which measures are scored: finite in the first level and above a floor (a motion that is not
 * there has no relative error); time to steady only when the span gallops up to a steady orbit */
static void choose_scored(acc_study *S)
{
    gal_acc_front *F = S->F;
    const double *v = F->ref_level_value[0];
    double tr = fmax(fabs(v[GAL_ACC_M_VERTICAL]), fabs(v[GAL_ACC_M_HORIZONTAL]));
    for (int k = 0; k < GAL_ACC_NMEAS; k++) F->scored[k] = isfinite(v[k]) && v[k] > 0;
    F->scored[GAL_ACC_M_VERTICAL] &= v[GAL_ACC_M_VERTICAL] >= 1e-3 * tr && v[GAL_ACC_M_VERTICAL] > 1e-9;
    F->scored[GAL_ACC_M_HORIZONTAL] &= v[GAL_ACC_M_HORIZONTAL] >= 1e-3 * tr && v[GAL_ACC_M_HORIZONTAL] > 1e-9;
    F->scored[GAL_ACC_M_TWIST] &= v[GAL_ACC_M_TWIST] >= 0.0035; /* deg RMS: 0.01 deg peak-to-peak */
    double T = 1.0 / v[GAL_ACC_M_FREQUENCY], ts = v[GAL_ACC_M_STEADY];
    /* the detector returns the start of the run's last fifth when the envelope still grows there */
    F->scored[GAL_ACC_M_STEADY] &= !S->turbulent && isfinite(T) && ts >= 5 * T && ts < 0.75 * S->duration;
    if (!S->turbulent && !F->scored[GAL_ACC_M_STEADY]) {
        size_t n = strlen(F->note);
        snprintf(F->note + n, sizeof F->note - n, "%stime to steady galloping not scored: %s", n ? "; " : "",
                 ts >= 0.75 * S->duration ? "the envelope still grows at the end of the run (lengthen "
                                            "simulation.duration)" : "no growth to a steady orbit in this run");
    }
}

/* Richardson's estimate of measure k from levels 0..K: the observed order (NaN when it cannot be
 * observed: fewer than 3 levels, or changes that do not shrink), the reference value and its
 * estimated relative error. The order is "known" when observed within [ORDER_MIN, ORDER_MAX] (the
 * generalized-alpha step and the rod's mesh are both second order; a mixture of the two, or an
 * amplitude that is a nonlinear function of them, shows 1.5-2.3): then M* = M_K + d / (2^p - 1),
 * d = M_K - M_K-1, and the estimated error is |d| / (2^p - 1), the finest level's own (the
 * extrapolated value is better by an amount no three levels can measure). Without a known order
 * there is no extrapolation: the finest level, with the last change as its estimated error. */
#define ORDER_MIN 1.0
#define ORDER_MAX 3.0
static void richardson(const gal_acc_front *F, int k, int K, double *order, double *value, double *err)
{
    const double *m = &F->ref_level_value[0][k];
#define LV(i) m[(size_t)(i) * GAL_ACC_NMEAS]
    *order = NAN;
    if (K < 1) { *value = LV(0), *err = NAN; return; }
    double d1 = LV(K) - LV(K - 1);
    *value = LV(K), *err = gal_acc_relerr(LV(K - 1), LV(K));
    if (k == GAL_ACC_M_STEADY) return; /* no order: the finest run as it is */
    if (K >= 2) {
        double q = (LV(K - 1) - LV(K - 2)) / d1;
        if (isfinite(q) && q > 1) *order = log2(q);
    }
    if (!(*order >= ORDER_MIN && *order <= ORDER_MAX)) return;
    double e = d1 / (pow(2, *order) - 1);
    *value = LV(K) + e;
    *err = *value != 0 ? fabs(e / *value) : NAN;
#undef LV
}

/* the change of each scored measure over the last refinement, and whether every estimated error
 * (Richardson with the observed order where it is known, else the last change) is below tol/10
 * (the time to steady galloping, a threshold crossing with no order, is compared directly and
 * does not hold the refinement back; in turbulent wind the seeds' spread does not either: every
 * configuration runs on the same seeds) */
static int level_converged(acc_study *S, int K)
{
    gal_acc_front *F = S->F;
    int ok = 1;
    for (int k = 0; k < GAL_ACC_NMEAS; k++) {
        double p, x, e;
        F->ref_change[k] = gal_acc_relerr(F->ref_level_value[K - 1][k], F->ref_level_value[K][k]);
        richardson(F, k, K, &p, &x, &e);
        if (F->scored[k] && k != GAL_ACC_M_STEADY && !(e < 0.1 * S->o->tolerance)) ok = 0;
    }
    return ok;
}

/* the reference values, their observed orders and estimated errors (in turbulent wind at least
 * the seeds' standard error) */
static void extrapolate(acc_study *S)
{
    gal_acc_front *F = S->F;
    for (int k = 0; k < GAL_ACC_NMEAS; k++) {
        richardson(F, k, F->levels - 1, &F->order[k], &F->ref_value[k], &F->ref_disc_error[k]);
        F->ref_error[k] = F->ref_disc_error[k];
        if (isfinite(F->ref_spread[k])) F->ref_error[k] = fmax(F->ref_error[k], F->ref_spread[k]);
    }
}

int gal_acc_reference(acc_study *S, const gal_acc_config *base)
{
    gal_acc_front *F = S->F;
    int maxl = S->o->max_levels < 1 ? 1 : S->o->max_levels > 8 ? 8 : S->o->max_levels;
    F->levels = 0;
    for (int K = 0; K < maxl; K++) {
        gal_acc_config c = *base;
        c.elements = base->elements << K;
        c.time_step = base->time_step / (1 << K);
        if (K > 0 && 5 * F->ref_level_wall_s[K - 1] > 0.5 * gal_acc_budget_left(S)) {
            snprintf(F->ref_note, sizeof F->ref_note, "the budget stopped the refinement at %d elements, step %.4g s",
                     F->ref_elements[K - 1], F->ref_time_step[K - 1]);
            break;
        }
        gal_acc_point *p = gal_acc_point_add(F);
        if (!p) return gal_error(GAL_ENOMEM, "out of memory");
        snprintf(p->group, sizeof p->group, "%s", K ? "refine" : "model");
        int st = gal_acc_config_run(S, &c, K ? F->steady_from_s : -1, p);
        if (st && K == 0) return gal_error(st, "front: the base full-model run: %s", p->failed);
        if (st) {
            snprintf(F->ref_note, sizeof F->ref_note, "the refinement to %d elements failed: %.200s", c.elements,
                     p->failed);
            break;
        }
        F->ref_elements[K] = c.elements, F->ref_time_step[K] = c.time_step;
        F->ref_level_wall_s[K] = p->wall_time_s;
        memcpy(F->ref_level_value[K], p->value, sizeof p->value);
        memcpy(F->ref_spread, p->spread, sizeof p->spread);
        F->levels = K + 1;
        if (K == 0) {
            /* the scored frequency is the larger translation's, from now on */
            S->fcomp = p->value[GAL_ACC_M_VERTICAL] >= p->value[GAL_ACC_M_HORIZONTAL] ? 1 : 0;
            choose_scored(S);
        }
        if (S->o->progress)
            fprintf(stderr, "accuracy: front reference level %d: %d elements, step %.4g s, wall %.3f s\n", K,
                    c.elements, c.time_step, p->wall_time_s);
        if (K > 0 && (F->converged = level_converged(S, K))) break;
    }
    if (F->levels < 2) snprintf(F->ref_note, sizeof F->ref_note, "one level only: the reference error is unknown");
    extrapolate(S);
    if (S->o->progress) { /* the reference's state before the long part of a study */
        fprintf(stderr, "accuracy: front reference %s in %d levels; estimated error:",
                F->converged ? "converged" : "NOT converged", F->levels);
        for (int k = 0; k < GAL_ACC_NMEAS; k++)
            if (F->scored[k]) {
                fprintf(stderr, " %s %.2g%%", gal_acc_measure_names[k], 100 * F->ref_error[k]);
                if (isfinite(F->order[k])) fprintf(stderr, " (order %.2g)", F->order[k]);
            }
        fprintf(stderr, "\n");
    }
    if (!F->converged && !F->ref_note[0])
        snprintf(F->ref_note, sizeof F->ref_note, "not converged to a tenth of the tolerance in %d levels "
                 "(raise --set or the level count); the errors below include the reference's", F->levels);
    for (int i = 0; i < F->n; i++) gal_acc_score(F, F->pt + i);
    return GAL_OK;
}

/* ======================================================================================
 * the study */

/* the output interval and the base step: the step gallop chooses for the scene's own modes,
 * a quarter or less of an output interval that resolves the largest basis studied */
static int constants(acc_study *S, gal_acc_config *base)
{
    const gal_scene *sc = S->sc;
    gal_model *m;
    int st;
    if (!(m = gal_model_alloc(sc, &st))) return st;
    gal_data *d = gal_data_alloc(m);
    if (!d) { gal_model_free(m); return GAL_ENOMEM; }
    st = gal_forward(m, d, GAL_STAGE_MODES);
    double fown = 0, fhi = 0;
    int seen[GAL_FAMILY_COUNT] = {0}, cap[GAL_FAMILY_COUNT] = {4, 3, 2, 0};
    for (int i = 0; !st && i < d->md.n; i++) {
        const gal_mode *mo = &d->md.mode[i];
        if (mo->selected) fown = fmax(fown, mo->frequency_hz);
        if (seen[mo->family]++ < cap[mo->family]) fhi = fmax(fhi, mo->frequency_hz);
    }
    gal_data_free(d);
    gal_model_free(m);
    if (st) return st;
    if (!(fown > 0)) return gal_error(GAL_EINPUT, "%s: no selected mode with a positive frequency", sc->path);
    fhi = fmax(fhi, fown);
    double dt = sc->simulation.output_interval > 0 ? sc->simulation.output_interval : fmin(0.05, 1.0 / (10 * fown));
    dt = fmin(dt, 0.25 / fhi);
    double h = sc->simulation.time_step > 0 ? sc->simulation.time_step : fmin(dt, 1.0 / (40 * fown));
    int sub = (int)ceil(dt / h - 1e-9);
    sub = 4 * ((sub + 3) / 4); /* a multiple of 4: steps 2h and 4h still divide the interval */
    S->F->output_interval_s = dt;
    S->F->base_time_step_s = base->time_step = dt / sub;
    S->F->base_elements = base->elements = sc->model.elements;
    return GAL_OK;
}

int gal_acc_study_front(const gal_scene *sc, const gal_acc_opts *o, gal_acc_result *r)
{
    gal_acc_front *F = &r->front;
    acc_study S = {sc, o, F, gal_wall_time(), 0, -1, {0}, sc->simulation.duration, 0, {0, {0}, {0}}};
    F->chosen = -1;
    F->steady_from_s = F->probe[0] = F->probe[1] = F->probe[2] = NAN;
    F->base_newton_tol = sc->simulation.newton_tolerance;
    S.turbulent = sc->effect[GAL_FX_TURBULENCE] && sc->wind.turbulence != GAL_TURB_NONE;
    F->nseeds = S.turbulent ? (o->seeds > 0 ? o->seeds : 3) : 1;
    S.own[0] = sc->model.modes_vertical, S.own[1] = sc->model.modes_horizontal;
    S.own[2] = sc->effect[GAL_FX_TORSION] ? sc->model.modes_torsional : 0;
    gal_acc_config base = {0, 0, {S.own[0], S.own[1], S.own[2]}, 0, -1, 0};
    int st = constants(&S, &base);
    if (st) return gal_error(st, "front: %s: %s", sc->path, gal_error_message());
    if (S.turbulent)
        snprintf(F->note, sizeof F->note, "turbulent wind: every measure is the mean over %d seeds (wind.seed to "
                 "wind.seed + %d), every configuration on the same realizations (the field is the span's and the "
                 "seed's, not the mesh's); amplitudes are RMS, the frequency the spectral peak; the reference's "
                 "estimated error includes the seeds' standard error", F->nseeds, F->nseeds - 1);
    if ((st = gal_acc_reference(&S, &base))) return st;
    return gal_acc_pareto(&S, &base);
}
