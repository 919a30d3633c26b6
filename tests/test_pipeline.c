/* test_pipeline.c: the pipeline (run/forward.h) and the run loop (run/sim.h): gal_forward stops at
 * the stage asked for and goes on from there; a failing stage leaves the data at the one before; the
 * model is the same, byte for byte, after every stage and both integrators have run on it; no stage
 * writes into the rod's pattern; two data of one model reach identical results; the reduced stage
 * refuses a mode at 0 Hz. */
#include "check.h"
#include "gallop.h"
#include "gallop/model/model.h"
#include "gallop/run/forward.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"

static gal_model *model_of(const char *path, const char *const *ov, int n)
{
    gal_scene sc;
    int st = gal_scene_load(&sc, path, ov, n, NULL);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (st) return NULL;
    gal_model *m = gal_model_alloc(&sc, &st);
    CHECK(m && st == GAL_OK, "%s", gal_error_message());
    return m;
}

static const char *const small[] = {"model.elements=20", "simulation.duration=2"};

/* Each stage's result is there once the pipeline has gone that far, and not before. */
static void test_stops_at_the_stage_asked(void)
{
    gal_model *m = model_of("data/scenes/iced_gallop.ini", small, 2);
    if (!m) return;
    gal_data *d = gal_data_alloc(m);
    CHECK(d && d->stage == GAL_STAGE_NONE, "a new data has no stage done");
    CHECK(gal_forward(m, d, GAL_STAGE_EQUILIBRIUM) == GAL_OK, "%s", gal_error_message());
    CHECK(d->stage == GAL_STAGE_EQUILIBRIUM && d->eq.rod && d->eq.q, "equilibrium done");
    CHECK(d->md.n == 0 && !d->md.mode && !d->q_start && d->basis == 0, "nothing after the equilibrium");
    CHECK(d->eq.sag > 0 && d->eq.unstretched_length > 0, "a sagged span");
    CHECK(gal_forward(m, d, GAL_STAGE_MODES) == GAL_OK, "%s", gal_error_message());
    CHECK(d->stage == GAL_STAGE_MODES && d->md.n > 0, "modes done");
    int sel = 0;
    for (int k = 0; k < d->md.n; k++) sel += d->md.mode[k].selected;
    CHECK(sel == m->want[0] + m->want[1] + m->want[2], "%d modes selected, %d wanted", sel,
          m->want[0] + m->want[1] + m->want[2]);
    CHECK(d->damping && (m->damping_ratio == 0 || (d->damping->kind == GAL_DAMPING_MODAL && d->damping->nb > 0 &&
                                                    d->damping->zeta == m->damping_ratio)),
          "the structural damping built at the modes");
    CHECK(!d->q_start && d->basis == 0, "nothing after the modes");
    const gal_rod *rod = d->eq.rod;
    CHECK(gal_forward(m, d, GAL_STAGE_START) == GAL_OK, "%s", gal_error_message());
    CHECK(d->stage == GAL_STAGE_START && d->q_start && d->loads.rod == rod && d->loads.table, "start done");
    CHECK(d->basis == 0, "no reduced basis before it is asked for");
    CHECK(d->eq.rod == rod, "earlier stages are not repeated");
    CHECK(gal_forward(m, d, GAL_STAGE_REDUCED) == GAL_OK, "%s", gal_error_message());
    CHECK(d->stage == GAL_STAGE_REDUCED && d->basis == sel, "reduced basis on the %d selected modes", sel);
    int in_order = 1;
    for (int i = 0; i < d->basis; i++)
        in_order &= d->md.mode[d->sel[i]].selected && (i == 0 || d->sel[i] > d->sel[i - 1]) &&
                    d->md.mode[d->sel[i]].frequency_hz >= GAL_MODE_FLOOR_HZ;
    CHECK(in_order, "the basis modes are the selected ones, in order, none at 0 Hz");
    CHECK(gal_forward(m, d, GAL_STAGE_MODES) == GAL_OK && d->stage == GAL_STAGE_REDUCED, "asking less undoes nothing");
    CHECK(gal_forward(m, d, GAL_STAGE_COUNT) == GAL_EINPUT, "no stage beyond the last");
    gal_data_free(d);
    gal_model_free(m);
}

/* A stage that fails says why, names the scene, and leaves the stages before it. */
static void test_failing_stage(void)
{
    const char *ov[] = {"model.elements=20", "model.modes_vertical=0", "model.modes_horizontal=0",
                        "model.modes_torsional=0"};
    gal_model *m = model_of("data/scenes/drake_300m.ini", ov, 4);
    if (!m) return;
    gal_data *d = gal_data_alloc(m);
    CHECK(gal_forward(m, d, GAL_STAGE_START) == GAL_EINPUT, "no modes selected is bad input");
    CHECK(strstr(gal_error_message(), "drake_300m.ini") && strstr(gal_error_message(), "modes"), "%s",
          gal_error_message());
    CHECK(d->stage == GAL_STAGE_EQUILIBRIUM && d->eq.rod, "the equilibrium stays");
    gal_model *other = model_of("data/scenes/drake_300m.ini", small, 1);
    if (other) CHECK(gal_forward(other, d, GAL_STAGE_MODES) == GAL_EINPUT, "data of another model refused");
    gal_model_free(other);
    gal_data_free(d);
    gal_model_free(m);
}

/* A mode at or near 0 Hz (free end twist: the span turns as a whole) is never taken into the
 * reduced basis silently: the reduced stage refuses it, naming the key that selects it; the full
 * model's run needs no basis and is not refused. */
static void test_zero_hz_mode_refused(void)
{
    const char *ov[] = {"model.elements=20", "simulation.duration=2", "span.end_twist=free",
                        "model.modes_torsional=1"};
    gal_model *m = model_of("data/scenes/drake_300m.ini", ov, 4);
    if (!m) return;
    gal_data *d = gal_data_alloc(m);
    CHECK(gal_forward(m, d, GAL_STAGE_MODES) == GAL_OK, "%s", gal_error_message());
    int low = 0;
    for (int k = 0; k < d->md.n; k++) low |= d->md.mode[k].selected && d->md.mode[k].frequency_hz < GAL_MODE_FLOOR_HZ;
    CHECK(low, "free twist: the selected torsional mode is at 0 Hz");
    CHECK(gal_forward(m, d, GAL_STAGE_REDUCED) == GAL_EINPUT, "a 0 Hz mode in the basis is bad input");
    CHECK(strstr(gal_error_message(), "0 Hz") && strstr(gal_error_message(), "model.modes_torsional") &&
          strstr(gal_error_message(), "end_twist"), "%s", gal_error_message());
    CHECK(d->stage == GAL_STAGE_START, "the stages before stay");
    gal_run_opts o;
    gal_run_opts_from_scene(&m->sc, &o);
    gal_sim_result r;
    CHECK(gal_run(m, d, &gal_integrator_reduced, &o, &r) == GAL_EINPUT, "a reduced run is refused");
    gal_sim_result_clear(&r);
    gal_data_free(d);
    gal_model_free(m);
}

/* A byte copy of everything the model holds. */
typedef struct {
    gal_model m;
    gal_model_rod *rod;
    double *table;
    size_t table_n;
} snapshot;

static void snap(const gal_model *m, snapshot *s)
{
    s->m = *m;
    s->rod = malloc((size_t)m->nrods * sizeof *s->rod);
    memcpy(s->rod, m->rod, (size_t)m->nrods * sizeof *s->rod);
    s->table_n = m->table ? (size_t)m->table->n : 0;
    s->table = malloc((4 * s->table_n + 1) * sizeof(double));
    for (size_t k = 0; k < s->table_n; k++) {
        s->table[4 * k] = m->table->alpha[k];
        for (int c = 0; c < 3; c++) s->table[4 * k + 1 + c] = m->table->c[c][k];
    }
}

static int same(const gal_model *m, const snapshot *s)
{
    snapshot t;
    snap(m, &t);
    int eq = !memcmp(&t.m, &s->m, sizeof t.m) && !memcmp(t.rod, s->rod, (size_t)m->nrods * sizeof *t.rod) &&
             t.table_n == s->table_n && !memcmp(t.table, s->table, 4 * t.table_n * sizeof(double));
    free(t.rod);
    free(t.table);
    return eq;
}

static int all_zero(const double *v, int n)
{
    for (int k = 0; k < n; k++)
        if (v[k] != 0) return 0;
    return 1;
}

/* Every stage and both integrators leave the model as it was; the rod's pattern is only a
 * pattern (no stage uses its values as scratch). */
static void test_model_unchanged(void)
{
    gal_model *m = model_of("data/scenes/iced_gallop.ini", small, 2);
    if (!m) return;
    snapshot s;
    snap(m, &s);
    gal_data *d = gal_data_alloc(m);
    CHECK(gal_forward(m, d, GAL_STAGE_REDUCED) == GAL_OK, "%s", gal_error_message());
    CHECK(same(m, &s), "the model changed in the pipeline");
    gal_run_opts o;
    gal_run_opts_from_scene(&m->sc, &o);
    const gal_integrator_type *T[2] = {&gal_integrator_full, &gal_integrator_reduced};
    for (int k = 0; k < 2; k++) {
        gal_sim_result r;
        CHECK(gal_run(m, d, T[k], &o, &r) == GAL_OK, "%s: %s", T[k]->name, gal_error_message());
        CHECK(r.kind == T[k]->kind && r.nsamples > 1, "%s run", T[k]->name);
        gal_sim_result_clear(&r);
    }
    CHECK(same(m, &s), "the model changed in the runs");
    const gal_csc *K = d->eq.rod->K;
    CHECK(all_zero(K->val, K->nnz), "a stage wrote into the rod's pattern");
    free(s.rod);
    free(s.table);
    gal_data_free(d);
    gal_model_free(m);
}

static int same_doubles(const double *a, const double *b, size_t n)
{
    return (a == NULL) == (b == NULL) && (!a || !memcmp(a, b, n * sizeof(double)));
}

/* Two data of one model: the same equilibrium, modes, start, reduced basis and runs, bit for bit. */
static void test_repeatable(void)
{
    const char *ov[] = {"model.elements=20", "simulation.duration=2", "simulation.start=mean_wind"};
    gal_model *m = model_of("data/scenes/iced_gallop.ini", ov, 3);
    if (!m) return;
    gal_data *d[2];
    gal_sim_result r[2][2];
    gal_run_opts o;
    gal_run_opts_from_scene(&m->sc, &o);
    for (int k = 0; k < 2; k++) {
        d[k] = gal_data_alloc(m);
        CHECK(gal_run(m, d[k], &gal_integrator_full, &o, &r[k][0]) == GAL_OK, "%s", gal_error_message());
        CHECK(d[k]->stage == GAL_STAGE_START, "a full run forwards to the start only");
        CHECK(gal_run(m, d[k], &gal_integrator_reduced, &o, &r[k][1]) == GAL_OK, "%s", gal_error_message());
        CHECK(d[k]->stage == GAL_STAGE_REDUCED, "a reduced run forwards to the reduced model");
    }
    const gal_data *a = d[0], *b = d[1];
    int nq = a->eq.rod->nq, n = a->md.ndof;
    CHECK(same_doubles(a->eq.q, b->eq.q, nq) && a->eq.unstretched_length == b->eq.unstretched_length, "equilibrium");
    CHECK(a->md.n == b->md.n && same_doubles(a->md.shape, b->md.shape, (size_t)n * a->md.n), "modes");
    CHECK(a->damping->kind == b->damping->kind && a->damping->nb == b->damping->nb &&
          same_doubles(a->damping->omega, b->damping->omega, a->damping->nb) &&
          same_doubles(a->damping->mphi, b->damping->mphi, (size_t)a->damping->nb * a->damping->ndof), "damping");
    CHECK(same_doubles(a->q_start, b->q_start, nq) && !same_doubles(a->q_start, a->eq.q, nq), "mean-wind start");
    CHECK(a->basis == b->basis && !memcmp(a->sel, b->sel, sizeof a->sel), "reduced basis modes");
    for (int k = 0; k < 2; k++) {
        const gal_sim_result *x = &r[0][k], *y = &r[1][k];
        CHECK(x->nsamples == y->nsamples && same_doubles(x->trace, y->trace, (size_t)x->nsamples * 4 * x->nprobe) &&
              same_doubles(x->tension, y->tension, (size_t)x->nsamples * 2), "%s traces", k ? "reduced" : "full");
    }
    for (int k = 0; k < 2; k++) {
        gal_sim_result_clear(&r[k][0]);
        gal_sim_result_clear(&r[k][1]);
        gal_data_free(d[k]);
    }
    gal_model_free(m);
}

int main(void)
{
    RUN(test_stops_at_the_stage_asked);
    RUN(test_failing_stage);
    RUN(test_zero_hz_mode_refused);
    RUN(test_model_unchanged);
    RUN(test_repeatable);
    return CHECK_SUMMARY();
}
