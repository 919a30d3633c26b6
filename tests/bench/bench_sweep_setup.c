/* bench_sweep_setup.c: the set-up of a sweep over the wind done once (issue 13; run/sweep.h
 * gal_sweep_setup_cache): iced_gallop's 10 speeds 2..20 m/s, 10 s of the reduced model each, at
 * 80 (the scene's) and 400 elements, run case by case in this process as `gallop sweep` runs them,
 * each case with its own set-up (as before the cache) and with the span's equilibrium, modes and
 * the reduced model's own wind-independent set-up (gal_data.rom_setup) kept between cases, alternately, REPEATS times: the CPU time of the 10 cases and the median set-up
 * time of a case (the pipeline to the start and the reduced model's own set-up, wall), medians of
 * the repeats. The onset (once per span either way) is computed before the timing. */
#include "bench_util.h"

void openblas_set_num_threads(int n) __attribute__((weak));

#define REPEATS 5
#define NSPEEDS 10

static int load(gal_scene *sc, int elements, double speed)
{
    char e[64], v[64];
    snprintf(e, sizeof e, "model.elements=%d", elements);
    snprintf(v, sizeof v, "wind.speed=%g", speed);
    const char *ov[3] = {e, v, "simulation.duration=10"};
    return gal_scene_load(sc, "data/scenes/iced_gallop.ini", ov, 3, NULL);
}

/* The 10 cases: CPU time, and the median set-up time of a case into *setup. */
static int sweep(int elements, gal_sweep_onset_cache *onset, gal_sweep_setup_cache *setup, double *cpu, double *setup_s)
{
    gal_scene *sc = malloc(sizeof *sc);
    double s[NSPEEDS];
    int st = sc ? GAL_OK : GAL_ENOMEM;
    double t0 = bench_cpu();
    for (int i = 0; i < NSPEEDS && !st; i++) {
        gal_sweep_result r;
        if (!(st = load(sc, elements, 2.0 + 2.0 * i)))
            st = gal_sweep_case_run(sc, GAL_MODEL_REDUCED, NULL, NULL, 0, onset, setup, &r, NULL, NULL, NULL);
        if (!st) st = r.status;
        s[i] = r.setup_time_s;
    }
    *cpu = bench_cpu() - t0;
    *setup_s = st ? 0 : bench_median(s, NSPEEDS);
    free(sc);
    return st;
}

int main(void)
{
    static const int ne[2] = {80, 400};
    if (openblas_set_num_threads) openblas_set_num_threads(1);
    for (int k = 0; k < 2; k++) {
        gal_sweep_onset_cache onset;
        memset(&onset, 0, sizeof onset);
        double c0[REPEATS], c1[REPEATS], s0[REPEATS], s1[REPEATS], x;
        if (sweep(ne[k], &onset, NULL, &x, &x)) { /* the onset into its cache, and a warm-up */
            fprintf(stderr, "bench_sweep_setup: %s\n", gal_error_message());
            return 1;
        }
        for (int r = 0; r < REPEATS; r++) {
            gal_sweep_setup_cache setup;
            memset(&setup, 0, sizeof setup);
            int st = sweep(ne[k], &onset, NULL, &c0[r], &s0[r]);
            if (!st) st = sweep(ne[k], &onset, &setup, &c1[r], &s1[r]);
            gal_sweep_setup_cache_clear(&setup);
            if (st) {
                fprintf(stderr, "bench_sweep_setup: %s\n", gal_error_message());
                return 1;
            }
        }
        double C0 = bench_median(c0, REPEATS), C1 = bench_median(c1, REPEATS);
        double S0 = bench_median(s0, REPEATS), S1 = bench_median(s1, REPEATS);
        printf("BENCH|wind sweep of 10 cases, %d elements, each its own set-up|%.3f|s CPU|iced_gallop 2..20 m/s, 10 s "
               "reduced each, median of %d; set-up %.4f s per case (median)\n", ne[k], C0, REPEATS, S0);
        printf("BENCH|wind sweep of 10 cases, %d elements, set-up kept|%.3f|s CPU|the same, %.2fx faster; set-up %.4f s "
               "per case (median; %.1fx less)\n", ne[k], C1, C0 / C1, S1, S0 / S1);
    }
    return 0;
}
