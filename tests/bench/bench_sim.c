/* bench_sim.c: cost of the galloping runs of data/scenes/iced_gallop.ini (issues 5, 6, 7, 13), full
 * against reduced model on the same set-up and wind, at 100, 125 and 400 elements: the CPU time
 * per simulated second of the integration (gal_sim_run) and of the whole process of one run
 * (statics, modes and the model's own set-up included), medians of 3. CPU time of this process
 * (the machine is shared). Usage: bench_sim [--seconds S] [--reps N] [--set key=value]...
 * (default 300 s, 3 repeats). Prints ROW| lines and BENCH| lines (make bench). The BLAS runs on one
 * thread, as in the command line (src/cli/blas.c): OpenBLAS's idle threads otherwise spin in
 * sched_yield on the process's CPU time (measured: 12% of the reduced model's). */
#include "bench_util.h"

#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"

void openblas_set_num_threads(int n) __attribute__((weak));

typedef struct {
    double run, whole;  /* s CPU: the integration, and set-up plus integration */
    long steps, basis, evaluations;
} case_time;

/* One run of the scene at `elements` with the model `kind` over `duration` s. */
static int run(int elements, gal_model_kind kind, double duration, const char *const *ov0, int nov0, case_time *c)
{
    char e[64], d[64];
    const char *ov[40];
    snprintf(e, sizeof e, "model.elements=%d", elements);
    snprintf(d, sizeof d, "simulation.duration=%g", duration);
    memcpy(ov, ov0, (size_t)nov0 * sizeof *ov);
    ov[nov0] = e, ov[nov0 + 1] = d;
    gal_scene sc;
    double t0 = bench_cpu();
    if (gal_scene_load(&sc, "data/scenes/iced_gallop.ini", ov, nov0 + 2, NULL)) {
        fprintf(stderr, "bench_sim: %s\n", gal_error_message());
        return 1;
    }
    gal_sim_setup s;
    gal_sim_result r;
    if (gal_sim_setup_init(&s, &sc, 1)) {
        fprintf(stderr, "bench_sim: %s\n", gal_error_message());
        return 1;
    }
    double t1 = bench_cpu();
    int st = gal_sim_run(&s, kind, &r);
    double t2 = bench_cpu();
    if (st) {
        fprintf(stderr, "bench_sim: %s\n", gal_error_message());
        gal_sim_setup_clear(&s);
        return 1;
    }
    c->run = t2 - t1, c->whole = t2 - t0;
    c->steps = r.steps, c->basis = r.basis, c->evaluations = r.force_evaluations;
    gal_sim_result_clear(&r);
    gal_sim_setup_clear(&s);
    return 0;
}

/* Medians over reps runs. */
static int median(int elements, gal_model_kind kind, double duration, int reps, const char *const *ov, int nov,
                  case_time *c)
{
    double a[16], b[16];
    for (int k = 0; k < reps; k++) {
        if (run(elements, kind, duration, ov, nov, c)) return 1;
        a[k] = c->run, b[k] = c->whole;
    }
    c->run = bench_median(a, reps), c->whole = bench_median(b, reps);
    return 0;
}

int main(int argc, char **argv)
{
    double T = 300;
    int reps = 3, nov = 0;
    const char *ov[32];
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--seconds") && i + 1 < argc) T = atof(argv[++i]);
        else if (!strcmp(argv[i], "--reps") && i + 1 < argc) reps = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--set") && i + 1 < argc && nov < 32) ov[nov++] = argv[++i];
    }
    if (openblas_set_num_threads) openblas_set_num_threads(1);
    if (reps < 1) reps = 1;
    if (reps > 16) reps = 16;
    const int ne[3] = {100, 125, 400};
    for (int k = 0; k < 3; k++) {
        case_time f, r;
        if (median(ne[k], GAL_MODEL_FULL, T, reps, ov, nov, &f) || median(ne[k], GAL_MODEL_REDUCED, T, reps, ov, nov, &r))
            return 1;
        printf("ROW|iced_gallop, %d elements, %.0f s|full %.5f, reduced %.5f s CPU per simulated s (%.1fx)|whole process "
               "full %.2f, reduced %.2f s CPU (%.1fx)|reduced: %ld steps, basis %ld, %.2f load evaluations per step\n",
               ne[k], T, f.run / T, r.run / T, f.run / r.run, f.whole, r.whole, f.whole / r.whole, r.steps, r.basis,
               (double)r.evaluations / (double)(r.steps > 0 ? r.steps : 1));
        printf("BENCH|full model, %d elements, iced_gallop|%.5f|s CPU per simulated s|median of %d runs of %.0f s\n", ne[k],
               f.run / T, reps, T);
        printf("BENCH|reduced model, %d elements, iced_gallop|%.5f|s CPU per simulated s|median of %d runs of %.0f s; basis %ld\n",
               ne[k], r.run / T, reps, T, r.basis);
        printf("BENCH|speedup reduced over full, %d elements|%.1f|x|per simulated second; %.1fx the whole process of a %.0f-s run\n",
               ne[k], f.run / r.run, f.whole / r.whole, T);
        fflush(stdout);
    }
    return 0;
}
