/* bench_step.c: the full model's cost per time step (issue 16) on data/scenes/iced_gallop.ini
 * from the mean-wind start at h = 5 ms, at 100 and 1000 elements (median of 5 runs of a fixed
 * number of steps, CPU time, each size in its own process: its peak memory beside), against the
 * step's floor: one element evaluation (forces and tangent), one factorization of the iteration
 * matrix and two solves, timed the same way (median of 21), with the flop counts of the
 * factorization (CHOLMOD's) and the solves (4 lnz + n each) and the time they take at the
 * measured sparse rates (the element evaluation's flops are not counted: no floating-point
 * counters on the machine; its time is measured). */
#include "bench_util.h"
#include "gallop/full/dynamics.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"


static double median(double *a, int n) { return bench_median(a, n); }

/* ms per step of `steps` steps, and the Newton iterations and factorizations per step */
static int steps_ms(const gal_data *d, int steps, double *ms, double *its, double *facs)
{
    gal_dyn_opts o;
    gal_dyn_default_opts(&o);
    o.h = 0.005, o.damping = d->damping;
    gal_force F = {gal_loads_full, (void *)&d->loads, gal_loads_element, gal_loads_full_framed};
    gal_dyn *dy = gal_dyn_alloc(d->eq.rod, d->q_start, NULL, &o, &F);
    if (!dy) return 1;
    double t0 = bench_cpu();
    for (int s = 0; s < steps; s++)
        if (gal_dyn_step(dy)) { gal_dyn_free(dy); return 1; }
    *ms = 1e3 * (bench_cpu() - t0) / steps;
    *its = (double)dy->newton_iterations / steps, *facs = (double)dy->factorizations / steps;
    gal_dyn_free(dy);
    return 0;
}

/* ms of the floor: rod evaluation with tangent, one factorization, two solves; its flops */
static int floor_ms(const gal_data *d, double *ms, double *mflop)
{
    const gal_rod *rod = d->eq.rod;
    int nq = rod->nq, n = rod->ndof;
    double *f = malloc((size_t)nq * sizeof(double)), *b = calloc((size_t)n, sizeof(double)), t[21];
    gal_csc *S = gal_csc_clone(rod->K);
    gal_chol *ch = gal_chol_alloc(rod->K);
    if (!f || !b || !S || !ch) return 1;
    for (int j = 0; j < n; j++) b[j] = 1;
    for (int r = 0; r < 21; r++) {
        double t0 = bench_cpu();
        gal_rod_eval(rod, d->q_start, NULL, f, S);
        for (int p = 0; p < S->nnz; p++) S->val[p] += 1e6 * rod->M->val[p];
        if (gal_chol_factor(ch, S, 0, NULL)) return 1;
        gal_chol_solve(ch, b, f);
        gal_chol_solve(ch, b, f);
        t[r] = 1e3 * (bench_cpu() - t0);
    }
    *ms = median(t, 21);
    *mflop = (ch->c.fl + 2 * (4 * ch->c.lnz + n)) / 1e6;
    gal_chol_free(ch);
    gal_csc_free(S);
    free(f);
    free(b);
    return 0;
}

enum { O_MS, O_ITS, O_FACS, O_FLOOR, O_MFLOP, O_FACT_FL, O_SOLVE_FL, O_FACT_RATE, O_SOLVE_RATE, O_COUNT };

static int run_size(void *arg, double *o)
{
    int nel = ((const int *)arg)[0], nsteps = ((const int *)arg)[1];
    char e[64];
    snprintf(e, sizeof e, "model.elements=%d", nel);
    const char *ov[] = {e};
    gal_scene sc;
    gal_sim_setup s;
    if (gal_scene_load(&sc, "data/scenes/iced_gallop.ini", ov, 1, NULL) || gal_sim_setup_init(&s, &sc, 1)) {
        fprintf(stderr, "bench_step: %s\n", gal_error_message());
        return 1;
    }
    double t[5], lnz;
    for (int r = 0; r < 5; r++)
        if (steps_ms(s.data, nsteps, &t[r], &o[O_ITS], &o[O_FACS])) {
            fprintf(stderr, "bench_step: %s\n", gal_error_message());
            return 1;
        }
    if (floor_ms(s.data, &o[O_FLOOR], &o[O_MFLOP])) return 1;
    if (bench_sparse_rates(s.data->eq.rod, s.data->q_start, &o[O_FACT_RATE], &o[O_SOLVE_RATE], &o[O_FACT_FL], &lnz))
        return 1;
    o[O_SOLVE_FL] = 2 * (4 * lnz + s.data->eq.rod->ndof);
    o[O_MS] = median(t, 5);
    gal_sim_setup_clear(&s);
    return 0;
}

int main(void)
{
    int cases[2][2] = {{100, 400}, {1000, 100}};
    for (int k = 0; k < 2; k++) {
        double o[O_COUNT], mb;
        if (bench_fork(run_size, cases[k], o, O_COUNT, &mb)) return 1;
        int nel = cases[k][0];
        double sparse_ms = 1e3 * 1e-9 * (o[O_FACT_FL] / o[O_FACT_RATE] + o[O_SOLVE_FL] / o[O_SOLVE_RATE]);
        printf("BENCH|full-model step, %d elements, iced_gallop|%.4f|ms per step|CPU, median of 5 runs of %d steps of 5 ms "
               "(%.2f Newton iterations, %.2f factorizations per step); peak memory %.1f MB\n",
               nel, o[O_MS], cases[k][1], o[O_ITS], o[O_FACS], mb);
        printf("BENCH|its floor (element evaluation + 1 factorization + 2 solves), %d elements|%.4f|ms|median of 21; "
               "factorization %.3f + 2 solves %.3f MFlop = %.4f ms at the measured sparse rates, the element "
               "evaluation the rest\n", nel, o[O_FLOOR], 1e-6 * o[O_FACT_FL], 1e-6 * o[O_SOLVE_FL], sparse_ms);
        printf("BENCH|step / floor, %d elements|%.2f|x|\n", nel, o[O_MS] / o[O_FLOOR]);
    }
    return 0;
}
