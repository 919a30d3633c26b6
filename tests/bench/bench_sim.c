/* bench_sim.c: cost of the galloping runs of data/scenes/iced_gallop.ini (issues 5, 6, 7, 13):
 * the full model's wall time per simulated second at 100 and 400 elements (60 s of the run, median
 * of 3), the reduced model's at 100 and 1000 elements (60 s, median of 3; its own set-up, the
 * basis of modes and modal derivatives, apart), and the speedup of reduced over full at 200
 * elements over 120 s (one run each: they are deterministic). Until hyper-reduction (issue 13) the
 * reduced model evaluates the whole rod, so its runs are as long as the full model's. */
#include <stdio.h>
#include <stdlib.h>

#include "gallop.h"
#include "gallop/scene/scene.h"
#include "gallop/run/sim.h"

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* wall time per simulated second (integration), and the set-up time (pipeline + the model's own) */
static int run(int elements, gal_model_kind kind, double duration, double *per_s, double *build)
{
    char e[64], d[64];
    snprintf(e, sizeof e, "model.elements=%d", elements);
    snprintf(d, sizeof d, "simulation.duration=%g", duration);
    const char *ov[] = {e, d};
    gal_scene sc;
    if (gal_scene_load(&sc, "data/scenes/iced_gallop.ini", ov, 2, NULL)) return 1;
    gal_sim_setup s;
    gal_sim_result r;
    if (gal_sim_setup_init(&s, &sc, 1) || gal_sim_run(&s, kind, &r)) {
        fprintf(stderr, "bench_sim: %s\n", gal_error_message());
        return 1;
    }
    *per_s = r.wall_time_s / duration;
    *build = s.setup_time_s + r.build_time_s;
    gal_sim_result_clear(&r);
    gal_sim_setup_clear(&s);
    return 0;
}

static int median(int elements, gal_model_kind kind, double duration, int reps, double *per_s, double *build)
{
    double a[8], b[8];
    for (int k = 0; k < reps; k++)
        if (run(elements, kind, duration, &a[k], &b[k])) return 1;
    qsort(a, reps, sizeof(double), cmp);
    qsort(b, reps, sizeof(double), cmp);
    *per_s = a[reps / 2], *build = b[reps / 2];
    return 0;
}

int main(void)
{
    double ps, bt;
    int nf[2] = {100, 400}, nr[2] = {100, 1000};
    for (int k = 0; k < 2; k++) {
        if (median(nf[k], GAL_MODEL_FULL, 60, 3, &ps, &bt)) return 1;
        printf("BENCH|full model, %d elements, iced_gallop|%.5f|s per simulated s|median of 3 runs of 60 s\n", nf[k], ps);
    }
    for (int k = 0; k < 2; k++) {
        if (median(nr[k], GAL_MODEL_REDUCED, 60, 3, &ps, &bt)) return 1;
        printf("BENCH|reduced model, %d elements, iced_gallop|%.5f|s per simulated s|median of 3 runs of 60 s; set-up %.3f s\n", nr[k], ps, bt);
    }
    double pf, pr, bf, br;
    const double T = 120;
    if (run(200, GAL_MODEL_FULL, T, &pf, &bf) || run(200, GAL_MODEL_REDUCED, T, &pr, &br)) return 1;
    printf("BENCH|full model, 200 elements, iced_gallop|%.5f|s per simulated s|one run of %.0f s\n", pf, T);
    printf("BENCH|reduced model, 200 elements, iced_gallop|%.5f|s per simulated s|one run of %.0f s; set-up %.3f s\n", pr, T, br);
    printf("BENCH|speedup reduced over full, 200 elements|%.2f|x|per simulated second; %.2fx counting both set-ups\n",
           pf / pr, (pf * T + bf) / (pr * T + br));
    return 0;
}
