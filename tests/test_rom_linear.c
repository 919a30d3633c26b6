/* test_rom_linear.c: the reduced model's linear steps (o.one_pass, rom_step.c) are taken only while
 * the kept tangent predicts the internal force (GAL_ROM_LINEAR_TOL): a state whose force is off
 * gets a Newton step from its own force, and a fine mesh whose stiffest basis vector has
 * h omega ~ 10 runs (before: the carried forces' errors grew from step to step until the rod's
 * energy at element 0 was not finite, exit 1 at t = 13 s). */
#include "check.h"
#include "gallop.h"
#include "gallop/reduced/rom_adapt.h"
#include "gallop/run/forward.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"

/* iced_gallop at `elements` for `seconds` (0: the scene's), set up to the reduced stage */
static int setup(gal_scene *sc, gal_sim_setup *s, int elements, double seconds)
{
    char e[64], t[64];
    snprintf(e, sizeof e, "model.elements=%d", elements);
    snprintf(t, sizeof t, "simulation.duration=%g", seconds);
    const char *ov[] = {e, t};
    int st = gal_scene_load(sc, "data/scenes/iced_gallop.ini", ov, seconds > 0 ? 2 : 1, "data/conductors.csv");
    if (!st) st = gal_sim_setup_init(s, sc, 1);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    return st;
}

/* A state whose internal force is off (as a linear step's carried force can be) before a step that
 * would be linear: the step is a Newton step from the state's own force, whose result carries the
 * exact force at the new state. */
static void test_bad_force_refused(void)
{
    gal_scene sc;
    gal_sim_setup s;
    if (setup(&sc, &s, 80, 0)) return;
    gal_data *d = s.data;
    int st = gal_forward(s.model, d, GAL_STAGE_REDUCED);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    gal_rom_opts ro;
    gal_rom_default_opts(&ro);
    ro.h = 0.01, ro.rho_inf = 0.9, ro.damping = d->damping, ro.one_pass = 8; /* opt-in */
    gal_force F = {gal_loads_full, (void *)&d->loads, gal_loads_element, gal_loads_full_framed};
    gal_rom *m = st ? NULL : gal_rom_alloc(d->eq.rod, d->eq.q, &d->md, d->sel, d->basis, &ro, &F);
    if (m && !(st = gal_rom_start(m, 0, d->q_start, d->v_start)) && !(st = gal_rom_advance(m, 5.0))) {
        while (!st && !(m->lin_ok && m->hJ == m->o.h && m->steps % m->o.one_pass)) st = gal_rom_step(m);
        double *f = malloc((size_t)m->r * sizeof(double)), fmx = m->fscale; /* the step's force scale */
        for (int k = 0; k < m->r; k++) fmx = fmax(fmx, fabs(m->fi[k]) + fabs(m->fe[k]));
        for (int k = 0; k < m->r; k++) m->fi[k] += 0.5 * fmx; /* half of it off */
        long rej = m->linear_rejections;
        if (!st) st = gal_rom_step(m);
        CHECK(st == GAL_OK, "%s", gal_error_message());
        CHECK(m->linear_rejections == rej + 1, "%ld linear steps refused", m->linear_rejections - rej);
        if (!st) st = gal_rom_internal_force(m, m->x, f);
        double e = 0;
        for (int k = 0; k < m->r && !st; k++) e = fmax(e, fabs(f[k] - m->fi[k]));
        CHECK(!st && e <= 1e-9 * fmx, "the state's force off its own by %.3g (scale %.3g)", e, fmx);
        free(f);
    }
    CHECK(m && st == GAL_OK, "%s", gal_error_message());
    gal_rom_free(m);
    gal_sim_setup_clear(&s);
}

/* The user's run (self-checked, adapting) at 900 elements, 15 s: it finishes, checked, and the
 * support tension stays within the small motion's range (before: exit 1 at t = 13.0 s, "the energy
 * of element 0 is not finite"). */
static void test_fine_mesh_runs(void)
{
    gal_scene sc;
    gal_sim_setup s;
    if (setup(&sc, &s, 900, 15)) return;
    gal_sim_result res;
    memset(&res, 0, sizeof res);
    int st = gal_sim_run(&s, GAL_MODEL_REDUCED, &res);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (!st) {
        double tmax = 0;
        for (long i = 0; i < 2 * res.nsamples; i++) tmax = fmax(tmax, fabs(res.tension[i]));
        CHECK(res.checked && res.valid, "checked %d valid %d residual %.3g", res.checked, res.valid, res.residual_max);
        CHECK(tmax < 1.1 * res.tension[0] && isfinite(tmax), "largest support tension %.6g N, static %.6g N", tmax,
              res.tension[0]);
    }
    gal_sim_result_clear(&res);
    gal_sim_setup_clear(&s);
}

int main(void)
{
    RUN(test_bad_force_refused);
    RUN(test_fine_mesh_runs);
    return CHECK_SUMMARY();
}
