/* bench_rom_step.c: the reduced model's cost per step on data/scenes/iced_gallop.ini (issue 13),
 * taken apart, at 100, 125, 400 and 1000 elements: a run of `seconds` simulated seconds at the
 * full model's step and rho_inf (CPU per step, and per step: Newton passes, evaluations of the
 * loads, fresh tangents, the element evaluations of gal_rom's counters), then at the state reached
 * the parts timed alone (medians of 7 batches): one pass of the sampled internal force, one of the
 * sampled loads, one fresh tangent, one sample check (gal_rom_hyper_check: the exact projected
 * forces over the whole rod) and one self-check (gal_rom_residual_dir: the full residual and a K0
 * solve) with its cubic part (gal_rom_cubic: two tangents of the whole rod and a K0 solve), each
 * check once every gal_rom_check_interval (1 s on coarse meshes). The rest of the
 * step (Newmark updates, residual, LU solves) is the step's CPU less the parts. Each size in its
 * own process; the BLAS on one thread. Usage: bench_rom_step [--seconds S] (default 60). Prints
 * ROW| and BENCH| lines (make bench). */
#include "bench_util.h"

#include "gallop/reduced/ecsw.h"
#include "gallop/reduced/rom_adapt.h"
#include "gallop/run/forward.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"

void openblas_set_num_threads(int n) __attribute__((weak));

enum { O_STEP, O_PASSES, O_TANGENTS, O_EL, O_LEL, O_CHK_EL, O_INT, O_EXT, O_TAN, O_HCHK, O_SELF, O_STEPS_S, O_IVL,
       O_LOADS, O_CUBIC, O_COUNT };

/* us per call of part k (0 internal, 1 loads, 2 tangent, 3 sample check, 4 self-check): median of 7
 * batches of n calls */
static int part_us(gal_rom *m, int k, int n, double *us)
{
    double t[7], *f = malloc((size_t)m->r * sizeof(double)), *Kr = malloc((size_t)m->r * m->r * sizeof(double));
    double *du = malloc((size_t)m->ndof * sizeof(double));
    gal_rom_check chk;
    int st = !f || !Kr || !du;
    for (int b = 0; b < 7 && !st; b++) {
        double t0 = bench_cpu();
        for (int i = 0; i < n && !st; i++) {
            if (k == 0) st = gal_rom_hyper_internal(m, m->x, f, NULL);
            else if (k == 1) st = gal_rom_hyper_external(m, m->t, m->x, m->v, f);
            else if (k == 2) st = gal_rom_hyper_internal(m, m->x, f, Kr);
            else if (k == 3) st = gal_rom_hyper_check(m, NULL);
            else if (k == 4) st = gal_rom_residual_dir(m, &chk, du);
            else st = gal_rom_cubic(m, m->x, chk.cubic);
        }
        t[b] = 1e6 * (bench_cpu() - t0) / n;
    }
    *us = bench_median(t, 7);
    free(f), free(Kr), free(du);
    return st;
}

static int run_size(void *arg, double *o)
{
    int nel = ((const int *)arg)[0], secs = ((const int *)arg)[1];
    if (openblas_set_num_threads) openblas_set_num_threads(1);
    char e[64];
    snprintf(e, sizeof e, "model.elements=%d", nel);
    const char *ov[] = {e};
    gal_scene sc;
    gal_sim_setup s;
    if (gal_scene_load(&sc, "data/scenes/iced_gallop.ini", ov, 1, NULL) || gal_sim_setup_init(&s, &sc, 1) ||
        gal_forward(s.model, s.data, GAL_STAGE_REDUCED)) {
        fprintf(stderr, "bench_rom_step: %s\n", gal_error_message());
        return 1;
    }
    gal_data *d = s.data;
    double fhi = 0;
    for (int k = 0; k < d->basis; k++) fhi = fmax(fhi, d->md.mode[d->sel[k]].frequency_hz);
    gal_rom_opts ro;
    gal_rom_default_opts(&ro);
    double dt_out = fmin(0.05, 1.0 / (10 * fhi)), h = fmin(dt_out, 1.0 / (40 * fhi)); /* as gal_run */
    ro.h = dt_out / ceil(dt_out / h - 1e-9), ro.rho_inf = sc.simulation.rho_inf, ro.damping = d->damping;
    gal_force F = {gal_loads_full, (void *)&d->loads, gal_loads_element, gal_loads_full_framed};
    gal_rom *m = gal_rom_alloc(d->eq.rod, d->eq.q, &d->md, d->sel, d->basis, &ro, &F);
    if (!m || gal_rom_start(m, 0, d->q_start, d->v_start)) {
        fprintf(stderr, "bench_rom_step: %s\n", gal_error_message());
        return 1;
    }
    double t0 = bench_cpu();
    if (gal_rom_advance(m, secs)) {
        fprintf(stderr, "bench_rom_step: %s\n", gal_error_message());
        return 1;
    }
    double ns = (double)m->steps;
    o[O_STEP] = 1e6 * (bench_cpu() - t0) / ns;
    o[O_PASSES] = (m->newton_iterations + ns) / ns, o[O_TANGENTS] = m->tangents / ns;
    o[O_LOADS] = m->force_evaluations / ns;
    o[O_EL] = m->element_evaluations / ns, o[O_LEL] = m->load_element_evaluations / ns;
    o[O_CHK_EL] = m->check_element_evaluations / ns, o[O_STEPS_S] = 1 / ro.h;
    o[O_IVL] = gal_rom_check_interval(m, 1.0); /* s between checks (integrator_rom.c's) */
    int st = part_us(m, 0, 200, &o[O_INT]) || part_us(m, 1, 200, &o[O_EXT]) || part_us(m, 2, 50, &o[O_TAN]) ||
             part_us(m, 3, 3, &o[O_HCHK]) || part_us(m, 4, 3, &o[O_SELF]) || part_us(m, 5, 3, &o[O_CUBIC]);
    if (st) fprintf(stderr, "bench_rom_step: %s\n", gal_error_message());
    gal_rom_free(m);
    gal_sim_setup_clear(&s);
    return st;
}

int main(int argc, char **argv)
{
    int secs = 60;
    for (int i = 1; i < argc; i++)
        if (!strcmp(argv[i], "--seconds") && i + 1 < argc) secs = atoi(argv[++i]);
    const int ne[4] = {100, 125, 400, 1000};
    for (int k = 0; k < 4; k++) {
        int arg[2] = {ne[k], secs};
        double o[O_COUNT], mb;
        if (bench_fork(run_size, arg, o, O_COUNT, &mb)) return 1;
        double sps = o[O_STEPS_S] * o[O_IVL]; /* steps per check */
        double passes = o[O_PASSES] * o[O_INT] + o[O_LOADS] * o[O_EXT], tan = o[O_TAN] * o[O_TANGENTS];
        double checks = (o[O_HCHK] + o[O_SELF] + o[O_CUBIC]) / sps, rest = o[O_STEP] - passes - tan - o[O_HCHK] / sps;
        printf("ROW|%d elements|step %.2f us (%.0f steps/s): %.2f passes x internal %.2f + %.2f x loads %.2f us = %.2f, "
               "%.3f tangents x %.1f us = %.2f, sample check %.0f us every %.2f s = %.2f, rest %.2f; self-check %.0f us "
               "= %.2f us/step more, its cubic part %.0f us = %.2f us/step more|per step: %.1f energy + %.1f load elements, %.1f by the "
               "sample check\n",
               ne[k], o[O_STEP], o[O_STEPS_S], o[O_PASSES], o[O_INT], o[O_LOADS], o[O_EXT], passes, o[O_TANGENTS], o[O_TAN], tan,
               o[O_HCHK], o[O_IVL], o[O_HCHK] / sps, rest, o[O_SELF], o[O_SELF] / sps, o[O_CUBIC], o[O_CUBIC] / sps, o[O_EL], o[O_LEL], o[O_CHK_EL]);
        printf("BENCH|reduced-model step, %d elements, iced_gallop|%.2f|us CPU per step|%.2f Newton passes of %.2f us "
               "(sampled forces) and %.2f of the loads of %.2f us, checks %.2f us per step amortised (sample + self-check every %.2f s); run "
               "of %d s\n", ne[k], o[O_STEP] + (o[O_SELF] + o[O_CUBIC]) / sps, o[O_PASSES], o[O_INT], o[O_LOADS], o[O_EXT], checks, o[O_IVL], secs);
        fflush(stdout);
    }
    return 0;
}
