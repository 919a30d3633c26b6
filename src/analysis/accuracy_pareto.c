/* accuracy_pareto.c: the choices of the front study (issue 20) measured against the converged
 * reference on the same wind: the model (full, reduced), elements, modes per family, time step,
 * Newton's tolerance (simulation.newton_tolerance) of either model, each effect off, one at a
 * time around the base configuration; then combined choices whose
 * errors are predicted additive (each measure shifted by the sum of the one-at-a-time shifts, the
 * wall time scaled by the product of their ratios), run where the front is least known (the
 * largest gap of the measured front in log-log); the Pareto front of the worst error against
 * wall time; the cheapest configuration within the tolerance, run again as a check; which effects
 * may be switched off. */
#include "gallop/analysis/accuracy.h"
#include "analysis/accuracy_front_int.h"
#include "analysis/accuracy_int.h"
#include "gallop/base/core.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define MIN_SAVING 0.10  /* an effect is recommended off only when it saves this share of the time */
#define MAX_COMBINED 4   /* combined configurations run without a budget */

static int same_config(const gal_acc_config *a, const gal_acc_config *b)
{
    return a->reduced == b->reduced && a->elements == b->elements && fabs(a->time_step / b->time_step - 1) < 1e-9 &&
           a->effect_off == b->effect_off && a->newton_tol == b->newton_tol &&
           (!a->reduced || (a->modes[0] == b->modes[0] && a->modes[1] == b->modes[1] && a->modes[2] == b->modes[2]));
}

static int find_config(const gal_acc_front *F, const gal_acc_config *c)
{
    for (int i = 0; i < F->n; i++)
        if (same_config(&F->pt[i].c, c) && !F->pt[i].failed[0]) return i;
    return -1;
}

/* the wall time of c predicted from the base's: cost ~ elements / step (x the reduced model's
 * measured ratio when one ran) */
static double predict_time(const acc_study *S, const gal_acc_config *c)
{
    const gal_acc_front *F = S->F;
    double t = F->ref_level_wall_s[0] * c->elements / F->base_elements * F->base_time_step_s / c->time_step;
    if (c->reduced) {
        double ratio = 2;
        for (int i = 0; i < F->n; i++)
            if (F->pt[i].c.reduced && !F->pt[i].failed[0] && !strcmp(F->pt[i].group, "model"))
                ratio = F->pt[i].wall_time_s / F->ref_level_wall_s[0];
        t *= ratio;
    }
    return t;
}

/* run c as a new point of `group` (skipped when the budget cannot pay for it); its index or -1 */
static int run_point(acc_study *S, const char *group, const gal_acc_config *c)
{
    gal_acc_front *F = S->F;
    int have = find_config(F, c);
    if (have >= 0) return have;
    double left = gal_acc_budget_left(S), need = predict_time(S, c);
    if (need > left) {
        char lab[96];
        gal_acc_config_label(c, lab, sizeof lab);
        if (S->o->progress) fprintf(stderr, "accuracy: front: skipped %s (about %.3g s, budget left %.3g s)\n", lab,
                                    need, left);
        size_t n = strlen(F->note);
        if (!strstr(F->note, "budget"))
            snprintf(F->note + n, sizeof F->note - n, "%sthe budget of %.4g s skipped some configurations (the "
                     "first: %s)", n ? "; " : "", S->o->budget_s, lab);
        return -1;
    }
    gal_acc_point *p = gal_acc_point_add(F);
    if (!p) return -2;
    snprintf(p->group, sizeof p->group, "%s", group);
    gal_acc_config_run(S, c, F->steady_from_s, p);
    gal_acc_score(F, p);
    gal_acc_progress_point(S, p);
    return (int)(p - F->pt);
}

/* ======================================================================================
 * one choice at a time around the base */

/* Newton's tolerance of the implicit step, full and reduced, at the base mesh and step (the
 * scene's own value is the base's) */
static const double newton_tols[] = {1e-10, 1e-6, 1e-4, 1e-3};

static int tolerances(acc_study *S, const gal_acc_config *base)
{
    for (int r = 0; r < 2; r++)
        for (size_t i = 0; i < sizeof newton_tols / sizeof newton_tols[0]; i++) {
            if (fabs(newton_tols[i] / S->sc->simulation.newton_tolerance - 1) < 1e-9) continue;
            gal_acc_config c = *base;
            c.reduced = r, c.newton_tol = newton_tols[i];
            if (run_point(S, "newton_tolerance", &c) == -2) return GAL_ENOMEM;
        }
    return GAL_OK;
}

static const int bases[][3] = {{1, 1, 1}, {2, 1, 1}, {2, 2, 1}, {3, 2, 1}, {3, 2, 2}, {4, 3, 2}};
#define NBASES (int)(sizeof bases / sizeof bases[0])

static int one_at_a_time(acc_study *S, const gal_acc_config *base)
{
    const gal_scene *sc = S->sc;
    int tors = sc->effect[GAL_FX_TORSION];
    gal_acc_config c;
    /* the reduced model of the scene's own modes, then the elements and the steps of the full */
    c = *base, c.reduced = 1;
    if (run_point(S, "model", &c) == -2) return GAL_ENOMEM;
    const int div[] = {4, 2}, mul[] = {4, 2, -2}; /* elements N/4, N/2; steps 4h, 2h, h/2 */
    for (int i = 0; i < 2; i++) {
        c = *base, c.elements = base->elements / div[i];
        if (c.elements >= 4 && run_point(S, "elements", &c) == -2) return GAL_ENOMEM;
    }
    c = *base, c.elements = 2 * base->elements;
    if (run_point(S, "elements", &c) == -2) return GAL_ENOMEM;
    for (int i = 0; i < 3; i++) {
        c = *base, c.time_step = mul[i] > 0 ? base->time_step * mul[i] : base->time_step / -mul[i];
        if (run_point(S, "time_step", &c) == -2) return GAL_ENOMEM;
    }
    /* the modes per family, and the reduced model's step */
    for (int b = 0; b < NBASES; b++) {
        c = *base, c.reduced = 1;
        memcpy(c.modes, bases[b], sizeof c.modes);
        if (!tors) c.modes[2] = 0;
        if (run_point(S, "modes", &c) == -2) return GAL_ENOMEM;
    }
    for (int i = 0; i < 2; i++) {
        c = *base, c.reduced = 1, c.time_step = base->time_step * mul[i];
        if (run_point(S, "time_step", &c) == -2) return GAL_ENOMEM;
    }
    if (tolerances(S, base)) return GAL_ENOMEM;
    /* each effect the scene has, switched off in the full model */
    static const gal_effect fx[] = {GAL_FX_ICE_ECCENTRICITY, GAL_FX_AERO_DRAG, GAL_FX_AERO_LIFT, GAL_FX_AERO_MOMENT,
                                    GAL_FX_BENDING, GAL_FX_TORSION, GAL_FX_AERO_DAMPING, GAL_FX_TURBULENCE,
                                    GAL_FX_DAMPING};
    for (size_t i = 0; i < sizeof fx / sizeof fx[0]; i++) {
        gal_effect e = fx[i];
        if (!sc->effect[e]) continue;
        if (e == GAL_FX_ICE_ECCENTRICITY && !(sc->ice.present && sc->ice.eccentricity != 0)) continue;
        /* a bare conductor's table has no lift and no moment */
        if ((e == GAL_FX_AERO_MOMENT || e == GAL_FX_AERO_LIFT) && !sc->ice.aero_table[0]) continue;
        if (e == GAL_FX_AERO_MOMENT && !tors) continue;
        if (e == GAL_FX_TURBULENCE && !S->turbulent) continue;
        if (e == GAL_FX_DAMPING && !(sc->conductor.damping_ratio > 0)) continue;
        if ((e == GAL_FX_AERO_DRAG || e == GAL_FX_AERO_LIFT || e == GAL_FX_AERO_DAMPING) && !(sc->wind.speed > 0))
            continue;
        c = *base, c.effect_off = e;
        if (run_point(S, "effect", &c) == -2) return GAL_ENOMEM;
    }
    return GAL_OK;
}

/* ======================================================================================
 * the front, and combined choices where it is least known */

static int counts_for_front(const gal_acc_point *p)
{
    return !p->failed[0] && p->c.effect_off < 0 && isfinite(p->error);
}

static void mark_front(gal_acc_front *F)
{
    for (int i = 0; i < F->n; i++) {
        gal_acc_point *p = F->pt + i;
        p->on_front = counts_for_front(p);
        for (int j = 0; j < F->n && p->on_front; j++) {
            const gal_acc_point *q = F->pt + j;
            if (j == i || !counts_for_front(q)) continue;
            if (q->wall_time_s <= p->wall_time_s && q->error <= p->error &&
                (q->wall_time_s < p->wall_time_s || q->error < p->error))
                p->on_front = 0;
        }
    }
}

/* the point of one choice (full or reduced basis, elements, step) or -1 */
static int choice_point(const gal_acc_front *F, const gal_acc_config *c)
{
    return find_config(F, c);
}

/* predicted measures of the combination of basis point ib, mesh point ie and step point ih (its
 * model at the base step: ih0) about the base point i0 (additive shifts); its worst error and time */
static void predict(const acc_study *S, int i0, int ib, int ie, int ih, int ih0, double *err, double *t)
{
    const gal_acc_front *F = S->F;
    const gal_acc_point *b0 = F->pt + i0, *pb = F->pt + ib, *pe = F->pt + ie, *ph = F->pt + ih, *ph0 = F->pt + ih0;
    *err = 0;
    for (int k = 0; k < GAL_ACC_NMEAS; k++) {
        if (!F->scored[k]) continue;
        double v = pb->value[k] + (pe->value[k] - b0->value[k]) + (ph->value[k] - ph0->value[k]);
        *err = fmax(*err, gal_acc_relerr(v, F->ref_value[k]));
    }
    *t = pb->wall_time_s * (pe->wall_time_s / b0->wall_time_s) * (ph->wall_time_s / ph0->wall_time_s);
}

/* distance in log-log from (e, t) to the measured front (how little is known there) */
static double front_gap(const gal_acc_front *F, double e, double t)
{
    double best = INFINITY, le = log10(fmax(e, 1e-12)), lt = log10(t);
    for (int i = 0; i < F->n; i++) {
        const gal_acc_point *p = F->pt + i;
        if (!p->on_front) continue;
        double de = log10(fmax(p->error, 1e-12)) - le, dt = log10(p->wall_time_s) - lt;
        best = fmin(best, sqrt(de * de + dt * dt));
    }
    return best;
}

/* 1: (e, t) is not dominated by the measured front */
static int undominated(const gal_acc_front *F, double e, double t)
{
    for (int i = 0; i < F->n; i++)
        if (F->pt[i].on_front && F->pt[i].wall_time_s <= t && F->pt[i].error <= e) return 0;
    return 1;
}

/* the next combination to run: undominated by prediction, farthest from the measured front */
static int next_combined(acc_study *S, const gal_acc_config *base, gal_acc_config *out, double *pe, double *pt)
{
    gal_acc_front *F = S->F;
    gal_acc_config rb = *base;
    rb.reduced = 1;
    memcpy(rb.modes, S->own, sizeof rb.modes);
    int i0 = choice_point(F, base), ir0 = choice_point(F, &rb), found = 0;
    if (i0 < 0) return 0;
    double best = 0;
    for (int ib = 0; ib < F->n; ib++) {
        const gal_acc_config *cb = &F->pt[ib].c;
        if (F->pt[ib].failed[0] || cb->effect_off >= 0 || cb->elements != base->elements ||
            fabs(cb->time_step / base->time_step - 1) > 1e-9) continue; /* a model/basis choice */
        for (int ie = 0; ie < F->n; ie++) {
            const gal_acc_config *ce = &F->pt[ie].c;
            if (F->pt[ie].failed[0] || ce->reduced || ce->effect_off >= 0 || ce->newton_tol != base->newton_tol ||
                fabs(ce->time_step / base->time_step - 1) > 1e-9) continue; /* a mesh of the full model */
            for (int ih = 0; ih < F->n; ih++) {
                const gal_acc_config *ch = &F->pt[ih].c;
                if (F->pt[ih].failed[0] || ch->reduced != cb->reduced || ch->effect_off >= 0 ||
                    ch->newton_tol != base->newton_tol ||
                    ch->elements != base->elements) continue; /* a step of the same model */
                if (cb->reduced && (ir0 < 0 || ch->modes[0] != S->own[0] || ch->modes[1] != S->own[1] ||
                                    ch->modes[2] != S->own[2])) continue;
                gal_acc_config c = *cb;
                c.elements = ce->elements, c.time_step = ch->time_step;
                if (find_config(F, &c) >= 0) continue;
                int tried = 0;
                for (int i = 0; i < F->n; i++) tried |= same_config(&F->pt[i].c, &c);
                if (tried) continue;
                double e, t;
                predict(S, i0, ib, ie, ih, cb->reduced ? ir0 : i0, &e, &t);
                if (!undominated(F, e, t) || t > gal_acc_budget_left(S)) continue;
                double g = front_gap(F, e, t);
                if (g > best) best = g, *out = c, *pe = e, *pt = t, found = 1;
            }
        }
    }
    return found;
}

static int combined(acc_study *S, const gal_acc_config *base)
{
    gal_acc_front *F = S->F;
    int cap = S->o->budget_s > 0 ? 1000 : MAX_COMBINED;
    for (int k = 0; k < cap; k++) {
        mark_front(F);
        gal_acc_config c;
        double e = 0, t = 0;
        if (!next_combined(S, base, &c, &e, &t)) break;
        int i = run_point(S, "combined", &c);
        if (i == -2) return GAL_ENOMEM;
        if (i < 0) break;
        F->pt[i].predicted = 1, F->pt[i].predicted_error = e, F->pt[i].predicted_time_s = t;
    }
    mark_front(F);
    return GAL_OK;
}

/* ======================================================================================
 * the tolerance and the effects */

static void choose_and_check(acc_study *S)
{
    gal_acc_front *F = S->F;
    double E = S->o->tolerance;
    F->chosen = -1;
    for (int i = 0; i < F->n; i++) {
        const gal_acc_point *p = F->pt + i;
        if (counts_for_front(p) && p->error <= E && (F->chosen < 0 || p->wall_time_s < F->pt[F->chosen].wall_time_s))
            F->chosen = i;
    }
    if (F->chosen < 0) return;
    gal_acc_point *c = &F->check;
    memset(c, 0, sizeof *c);
    for (int k = 0; k < GAL_ACC_NMEAS; k++) c->value[k] = c->err[k] = c->spread[k] = NAN;
    snprintf(c->group, sizeof c->group, "check");
    gal_acc_config cfg = F->pt[F->chosen].c;
    gal_acc_config_run(S, &cfg, F->steady_from_s, c);
    gal_acc_score(F, c);
    F->checked = 1;
    gal_acc_progress_point(S, c);
}

static void effects_text(acc_study *S)
{
    gal_acc_front *F = S->F;
    double E = S->o->tolerance, t0 = F->ref_level_wall_s[0];
    const double *b = F->ref_level_value[0]; /* the base: what switching the effect off changes */
    size_t len = 0;
    F->effects[0] = 0;
    for (int i = 0; i < F->n; i++) {
        const gal_acc_point *p = F->pt + i;
        if (p->c.effect_off < 0) continue;
        const char *name = gal_effect_names[p->c.effect_off];
        double save = 1 - p->wall_time_s / t0;
        int wb = 0;
        double db = 0;
        for (int k = 0; k < GAL_ACC_NMEAS; k++) {
            if (!F->scored[k]) continue;
            double d = gal_acc_relerr(p->value[k], b[k]);
            if (d > db || !F->scored[wb]) db = d, wb = k;
        }
        /* the effect's own share: every measure against the same configuration with it on (the
         * base); the error against the reference is stated beside it */
        char line[320];
        if (p->failed[0]) snprintf(line, sizeof line, "%s: keep on (the run without it failed); ", name);
        else if (db > E)
            snprintf(line, sizeof line, "%s: keep on (off changes the %s by %.3g%% > %.3g%%); ", name,
                     gal_acc_measure_names[wb], 100 * db, 100 * E);
        else if (save < MIN_SAVING)
            snprintf(line, sizeof line, "%s: keep on (off changes no measure by more than %.3g%% but %s %.0f%% of the "
                     "time, under %.0f%%); ", name, 100 * db, save < 0 ? "took more time here, by" : "saves only",
                     100 * fabs(save), 100 * MIN_SAVING);
        else
            snprintf(line, sizeof line, "%s: may be switched off (every measure within %.3g%% of the run with it on, "
                     "worst %s %.3g%%; %.3g%% off the reference; saves %.0f%% of the time); ", name, 100 * E,
                     gal_acc_measure_names[wb], 100 * db, 100 * p->error, 100 * save);
        if (len + strlen(line) < sizeof F->effects) {
            strcpy(F->effects + len, line);
            len += strlen(line);
        }
    }
    if (len >= 2) F->effects[len - 2] = 0;
}

int gal_acc_pareto(acc_study *S, const gal_acc_config *base)
{
    int st = one_at_a_time(S, base);
    if (!st) st = combined(S, base);
    if (st) return gal_error(st, "front: out of memory");
    choose_and_check(S);
    effects_text(S);
    return GAL_OK;
}
