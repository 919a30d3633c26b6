/* test_rom_speed.c: the reduced model's cost per step counted, not timed (issue 13: "the cost per
 * step does not grow with the mesh"): the element evaluations of its steps (gal_rom's
 * element_evaluations and load_element_evaluations) on data/scenes/iced_gallop.ini at 60 and 240
 * elements, and the counters' own exactness (each evaluation of the loads counts its sample, or
 * the whole mesh when the loads are not sampled); the loads once a step (o.loads_once). */
#include "check.h"
#include "gallop.h"
#include "gallop/reduced/ecsw.h"
#include "gallop/reduced/rom_adapt.h"
#include "gallop/run/forward.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"
#include "sim_fixture.h"

typedef struct {
    int elements;             /* the mesh */
    double per_step;          /* energy elements evaluated per step */
    double loads_per_step;    /* load elements evaluated per step */
    double per_evaluation;    /* energy elements per Newton pass */
    double load_evals;        /* evaluations of the loads per step */
    double passes;            /* Newton passes per step */
    double check_per_step;    /* the sample checks' element evaluations per step */
} cost;

/* The reduced model of iced_gallop at `elements` over `seconds` of simulated time (hyper_loads: the
 * loads sampled or not); its counters into *c. */
static int run_opts(int elements, double seconds, int hyper_loads, int loads_once, int one_pass, cost *c)
{
    char e[64];
    snprintf(e, sizeof e, "model.elements=%d", elements);
    const char *ov[] = {e};
    gal_scene sc;
    gal_sim_setup s;
    if (sim_fixture(&sc, &s, "data/scenes/iced_gallop.ini", ov, 1)) return 1;
    gal_rom_opts ro;
    gal_rom_default_opts(&ro);
    ro.h = 0.01, ro.rho_inf = 0.9, ro.hyper_loads = hyper_loads;
    ro.loads_once = loads_once, ro.one_pass = one_pass;
    gal_rom *m = rom_fixture(&s, &ro);
    int st = GAL_OK;
    if (m) {
        st = gal_rom_advance(m, seconds);
        CHECK(st == GAL_OK, "%s", gal_error_message());
        gal_rom_hyper_info hi;
        gal_rom_hyper_get_info(m, &hi);
        /* exactness: every evaluation of the loads is counted with its own element count */
        long per_load = hyper_loads ? hi.load_elements : elements;
        CHECK(m->load_element_evaluations == m->force_evaluations * per_load,
              "%d elements: %ld load element evaluations, %ld evaluations of %ld elements", elements,
              m->load_element_evaluations, m->force_evaluations, per_load);
        CHECK(m->steps > 0 && m->check_element_evaluations > 0, "%ld steps, %ld by the checks", m->steps,
              m->check_element_evaluations);
        c->elements = elements;
        c->per_step = (double)m->element_evaluations / (double)m->steps;
        c->loads_per_step = (double)m->load_element_evaluations / (double)m->steps;
        c->passes = (double)(m->newton_iterations + m->steps) / (double)m->steps;
        c->per_evaluation = (double)m->element_evaluations / (double)(m->newton_iterations + m->steps);
        c->load_evals = (double)m->force_evaluations / (double)m->steps;
        c->check_per_step = (double)m->check_element_evaluations / (double)m->steps;
        printf("    %d elements: %.1f energy and %.1f load element evaluations per step (%.1f per pass, %.2f passes, "
               "%.2f evaluations of the loads), %.1f by the sample's checks\n", elements, c->per_step, c->loads_per_step,
               c->per_evaluation, c->passes, c->load_evals, c->check_per_step);
    }
    gal_rom_free(m);
    gal_sim_setup_clear(&s);
    return st || !m;
}

static int run(int elements, double seconds, int hyper_loads, cost *c)
{
    gal_rom_opts d;
    gal_rom_default_opts(&d);
    return run_opts(elements, seconds, hyper_loads, 1, d.one_pass, c);
}

/* 4x the mesh: the steps evaluate as many elements (the samples' sizes vary by a few elements), and
 * far fewer than the mesh has. */
static void test_cost_per_step_flat(void)
{
    cost a, b;
    if (run(60, 8, 1, &a) || run(240, 8, 1, &b)) return;
    CHECK(b.per_step <= 1.25 * a.per_step + 8, "energy elements per step: %.1f at 240, %.1f at 60", b.per_step,
          a.per_step);
    CHECK(b.loads_per_step <= 1.25 * a.loads_per_step + 8, "load elements per step: %.1f at 240, %.1f at 60",
          b.loads_per_step, a.loads_per_step);
    CHECK(b.per_evaluation < 0.1 * 2 * 240, "%.1f energy elements per evaluation of 479", b.per_evaluation);
}

/* The sample's checks (the whole rod and its loads each) come less often on a fine mesh: at 800
 * elements they cost at most GAL_ROM_CHECK_SHARE / 2 of the steps' evaluations (the other half is
 * the full residual's), at 60 they come every second. */
static void test_checks_amortised(void)
{
    cost a, b;
    if (run(60, 4, 1, &a) || run(800, 8, 1, &b)) return;
    double sa = a.per_step + a.loads_per_step, sb = b.per_step + b.loads_per_step;
    CHECK(b.check_per_step <= 1.3 * 0.5 * GAL_ROM_CHECK_SHARE * sb, "800 elements: %.1f by the checks, %.1f by the "
          "steps", b.check_per_step, sb);
    CHECK(a.check_per_step > 0.5 * (119 + 60) / 100.0, "60 elements: %.2f by the checks per step (one a second: %.2f)",
          a.check_per_step, (119 + 60) / 100.0);
    CHECK(b.check_per_step + sb <= 1.5 * (a.check_per_step + sa), "per step, checks included: %.1f at 800, %.1f at 60",
          b.check_per_step + sb, a.check_per_step + sa);
}

/* The loads on every element: each evaluation costs the mesh (the counter sees the difference). */
static void test_counters_unsampled_loads(void)
{
    cost a;
    if (run(60, 2, 0, &a)) return;
    CHECK(a.loads_per_step >= 60, "%.1f load elements per step on 60", a.loads_per_step);
}

/* The loads once a step (o.loads_once, the default): one evaluation a step (a few more only on the
 * steps halved), while Newton takes about two passes; at every pass (loads_once = 0) as many as the
 * passes. */
static void test_loads_once_a_step(void)
{
    cost a, b;
    if (run_opts(60, 8, 1, 1, 0, &a) || run_opts(60, 8, 1, 0, 0, &b)) return;
    CHECK(a.load_evals >= 1 && a.load_evals <= 1.01, "%.3f evaluations of the loads per step", a.load_evals);
    CHECK(a.passes >= 1.9, "%.2f Newton passes per step", a.passes);
    CHECK(b.load_evals >= b.passes - 1e-9 && b.load_evals >= 1.9, "loads_once = 0: %.2f evaluations, %.2f passes",
          b.load_evals, b.passes);
    CHECK(a.loads_per_step <= 0.55 * b.loads_per_step, "load elements per step: %.1f once, %.1f at every pass",
          a.loads_per_step, b.loads_per_step);
}

/* o.one_pass (opt-in; the default 0, Newton every step, rom.h) at 8: 7 steps of 8 evaluate the sampled energy once (linearly implicit), the
 * 8th a Newton of ~2 passes: ~1.15 passes a step, one evaluation of the loads. */
static void test_one_pass(void)
{
    gal_rom_opts d;
    gal_rom_default_opts(&d);
    CHECK(d.one_pass == 0 && d.loads_once == 1, "defaults: one_pass %d, loads_once %d", d.one_pass, d.loads_once);
    cost a;
    if (run_opts(60, 8, 1, 1, 8, &a)) return;
    CHECK(a.passes >= 1 && a.passes <= 1.25, "%.2f passes per step", a.passes);
    CHECK(a.load_evals >= 1 && a.load_evals <= 1.01, "%.3f evaluations of the loads per step", a.load_evals);
}

int main(void)
{
    RUN(test_loads_once_a_step);
    RUN(test_one_pass);
    RUN(test_cost_per_step_flat);
    RUN(test_checks_amortised);
    RUN(test_counters_unsampled_loads);
    return CHECK_SUMMARY();
}
