/* bench_step.c: the full model's cost per time step (issue 16) on data/scenes/iced_gallop.ini
 * from the mean-wind start at h = 5 ms, at 100 and 1000 elements (median of 5 runs of a fixed
 * number of steps), against the step's floor: one element evaluation (forces and tangent), one
 * factorization of the iteration matrix and two solves, timed the same way (median of 21), with
 * CHOLMOD's flop count of the factorization. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gallop.h"
#include "gallop/full/dynamics.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"

#include "base/chol.h"

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *a, int n)
{
    qsort(a, n, sizeof(double), cmp);
    return a[n / 2];
}

/* ms per step of `steps` steps, and the Newton iterations and factorizations per step */
static int steps_ms(const gal_data *d, int steps, double *ms, double *its, double *facs)
{
    gal_dyn_opts o;
    gal_dyn_default_opts(&o);
    o.h = 0.005, o.damping = d->damping;
    gal_force F = {gal_loads_full, (void *)&d->loads};
    gal_dyn *dy = gal_dyn_alloc(d->eq.rod, d->q_start, NULL, &o, &F);
    if (!dy) return 1;
    double t0 = gal_wall_time();
    for (int s = 0; s < steps; s++)
        if (gal_dyn_step(dy)) { gal_dyn_free(dy); return 1; }
    *ms = 1e3 * (gal_wall_time() - t0) / steps;
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
        double t0 = gal_wall_time();
        gal_rod_eval(rod, d->q_start, NULL, f, S);
        for (int p = 0; p < S->nnz; p++) S->val[p] += 1e6 * rod->M->val[p];
        if (gal_chol_factor(ch, S, 0, NULL)) return 1;
        gal_chol_solve(ch, b, f);
        gal_chol_solve(ch, b, f);
        t[r] = 1e3 * (gal_wall_time() - t0);
    }
    *ms = median(t, 21);
    *mflop = (ch->c.fl + 4 * ch->c.lnz) / 1e6;
    gal_chol_free(ch);
    gal_csc_free(S);
    free(f);
    free(b);
    return 0;
}

int main(void)
{
    int nel[2] = {100, 1000}, nsteps[2] = {400, 100};
    for (int k = 0; k < 2; k++) {
        char e[64];
        snprintf(e, sizeof e, "model.elements=%d", nel[k]);
        const char *ov[] = {e};
        gal_scene sc;
        gal_sim_setup s;
        if (gal_scene_load(&sc, "data/scenes/iced_gallop.ini", ov, 1, NULL) || gal_sim_setup_init(&s, &sc, 1)) {
            fprintf(stderr, "bench_step: %s\n", gal_error_message());
            return 1;
        }
        double t[5], its = 0, facs = 0, fl_ms, mflop;
        for (int r = 0; r < 5; r++)
            if (steps_ms(s.data, nsteps[k], &t[r], &its, &facs)) { fprintf(stderr, "bench_step: %s\n", gal_error_message()); return 1; }
        if (floor_ms(s.data, &fl_ms, &mflop)) return 1;
        double ms = median(t, 5);
        printf("BENCH|full-model step, %d elements, iced_gallop|%.4f|ms per step|median of 5 runs of %d steps of 5 ms "
               "(%.2f Newton iterations, %.2f factorizations per step)\n", nel[k], ms, nsteps[k], its, facs);
        printf("BENCH|its floor (element evaluation + 1 factorization + 2 solves)|%.4f|ms|median of 21; factorization "
               "and solves %.3f MFlop\n", fl_ms, mflop);
        printf("BENCH|step / floor, %d elements|%.2f|-|\n", nel[k], ms / fl_ms);
        gal_sim_setup_clear(&s);
    }
    return 0;
}
