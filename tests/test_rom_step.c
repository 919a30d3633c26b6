/* test_rom_step.c: the reduced model's time error at its default step (gal_integrator_reduced,
 * integrator_rom.c: 40 steps a period of the highest selected mode, whole steps an output interval)
 * on a short run, against the same model at a quarter of that step (its own converged result, so
 * that the time error is apart from the reduction's): the headline figures of `gallop compare`
 * (each family at the probe where the reference moves most, over its steady window) within a
 * budget of a fifth of issue 13's limits: frequency 0.2%, vertical 1%, horizontal 1% or 0.4% of the
 * vertical, twist 1% or 0.6 deg, largest support tension 1%. The same run at four times the step
 * must leave that budget (the measure can see a coarse step; BENCHMARKS.md "The reduced model's
 * time step against its error": condor at 40 elements, 1.25% in frequency, 3% vertical, 22% twist). */
#include "check.h"
#include "sim_fixture.h"
#include "gallop.h"
#include "gallop/analysis/compare.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"

#define SCENE "tests/rom/condor_150_taut_dshape.ini"

typedef struct {
    double f, v, h, tw, T;
} figs;

static int measure(const gal_sim_result *r, const gal_compare_ref *ref, figs *o)
{
    gal_sim_measures m;
    int st = gal_compare_measure(r, ref, &m);
    o->f = m.frequency_hz[1], o->v = m.peak_to_peak[1], o->h = m.peak_to_peak[0], o->tw = m.peak_to_peak[3];
    o->T = m.tension_max_steady;
    return st;
}

/* 1 when every headline figure of a is within the budget of b's */
static int within(const figs *a, const figs *b, int verbose, const char *what)
{
    double ef = fabs(a->f - b->f) / b->f, ev = fabs(a->v - b->v) / b->v, eh = fabs(a->h - b->h);
    double et = fabs(a->tw - b->tw), eT = fabs(a->T - b->T) / b->T;
    if (verbose)
        printf("    %s: f %.3f%%, vertical %.2f%%, horizontal %.2f%% (%.2f%% of v), twist %.2f%% (%.2f deg), T %.2f%%\n",
               what, 100 * ef, 100 * ev, 100 * eh / b->h, 100 * eh / b->v, 100 * et / b->tw, et, 100 * eT);
    return ef <= 2e-3 && ev <= 1e-2 && eh <= fmax(1e-2 * b->h, 4e-3 * b->v) && et <= fmax(1e-2 * b->tw, 0.6) &&
           eT <= 1e-2;
}

static void test_time_error_budget(void)
{
    gal_scene sc;
    gal_sim_setup s;
    if (sim_fixture(&sc, &s, SCENE, NULL, 0)) return;
    gal_run_opts o;
    gal_run_opts_from_scene(&sc, &o);
    gal_sim_result r[3] = {{0}}; /* the default step h, h/4, 4 h */
    int st = gal_run_check_measurable(s.model, s.data, &o);
    if (!st) st = gal_run(s.model, s.data, &gal_integrator_reduced, &o, &r[0]);
    CHECK(st == GAL_OK, "reduced run: %s", gal_error_message());
    double h = r[0].time_step_s;
    for (int k = 1; k < 3 && !st; k++) {
        gal_run_opts ok = o;
        ok.time_step = k == 1 ? 0.25 * h : 4 * h;
        st = gal_run(s.model, s.data, &gal_integrator_reduced, &ok, &r[k]);
        CHECK(st == GAL_OK, "reduced run at %g s: %s", ok.time_step, gal_error_message());
    }
    if (!st) {
        CHECK(r[0].time_step_s > 0 && fabs(r[1].time_step_s - 0.25 * h) <= 1e-12 * h, "steps %g and %g s",
              r[0].time_step_s, r[1].time_step_s);
        CHECK(r[2].time_step_s > 3 * h, "the coarse step %g s, the default %g s", r[2].time_step_s, h);
        gal_compare_ref ref;
        figs a, b, c;
        CHECK(gal_compare_reference(&r[1], -1, &ref) == GAL_OK, "%s", gal_error_message());
        double dur = r[1].time[r[1].nsamples - 1];
        CHECK(ref.from > 0 && ref.from <= 0.75 * dur, "the reference is not steady (from %g of %g s)", ref.from, dur);
        if (ref.from < 0.5 * dur) ref.from = 0.5 * dur;
        CHECK(measure(&r[0], &ref, &a) == GAL_OK && measure(&r[1], &ref, &b) == GAL_OK &&
              measure(&r[2], &ref, &c) == GAL_OK, "%s", gal_error_message());
        printf("    reference (h/4 = %.5g s): f %.4f Hz, vertical %.3f m, horizontal %.3f m, twist %.2f deg, T %.0f N\n",
               r[1].time_step_s, b.f, b.v, b.h, b.tw, b.T);
        CHECK(b.v > 1.0 && b.tw > 10, "no galloping to measure (vertical %g m, twist %g deg)", b.v, b.tw);
        CHECK(within(&a, &b, 1, "default step"), "the default step %g s leaves its time-error budget", h);
        CHECK(!within(&c, &b, 1, "4 x the step"), "four times the step (%g s) stays within the budget: the "
              "measure cannot see a coarse step", r[2].time_step_s);
    }
    for (int k = 0; k < 3; k++) gal_sim_result_clear(&r[k]);
    gal_sim_setup_clear(&s);
}

int main(void)
{
    RUN(test_time_error_budget);
    return CHECK_SUMMARY();
}
