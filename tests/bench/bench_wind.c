/* bench_wind.c: time to generate 10 minutes of turbulence at 20 Hz on 100 points (Kaimal, C = 10,
 * dx = 3 m), median of 5 runs, for the set-up (gal_wind_alloc: FFTW plan, tables) and for
 * gal_wind_generate alone. Not part of `make check`. Build and run from the repository root:
 *   make bench (tests/bench/run.sh builds and runs it) */
#define _POSIX_C_SOURCE 200809L
#include "gallop.h"

#include <stdio.h>
#include <stdlib.h>

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    gal_wind_params p;
    gal_wind_params_default(&p);
    p.speed = 10;
    p.intensity = 0.15;
    p.points = argc > 1 ? atoi(argv[1]) : 100;
    p.spacing = 3;
    p.duration = 600;
    p.time_step = 0.05;
    enum { RUNS = 5 };
    double ta[RUNS], tg[RUNS];
    for (int r = 0; r < RUNS; r++) {
        p.seed = 1 + r;
        double t0 = gal_wall_time();
        gal_wind *w = gal_wind_alloc(&p);
        if (!w) {
            fprintf(stderr, "bench_wind: %s\n", gal_error_message());
            return 1;
        }
        double t1 = gal_wall_time();
        gal_wind_generate(w);
        double t2 = gal_wall_time();
        ta[r] = t1 - t0, tg[r] = t2 - t1;
        gal_wind_free(w);
    }
    qsort(ta, RUNS, sizeof(double), cmp);
    qsort(tg, RUNS, sizeof(double), cmp);
    printf("BENCH|wind generation, %d points x %.0f s at %.0f Hz|%.2f|ms|median of %d (set-up %.2f ms apart)\n",
           p.points, p.duration, 1 / p.time_step, 1e3 * tg[RUNS / 2], RUNS, 1e3 * ta[RUNS / 2]);
    return 0;
}
