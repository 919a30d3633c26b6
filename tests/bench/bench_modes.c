/* bench_modes.c: wall time of statics + 20 modes of a 300 m ACSR Drake span at 100, 1000 and
 * 10000 elements, median of repeats (issue: target 1000 elements under 50 ms on one core). */
#include <stdio.h>
#include <stdlib.h>

#include "gallop.h"
#include "gallop/modes/modes.h"
#include "gallop/statics/statics.h"

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(void)
{
    int nels[3] = {100, 1000, 10000}, reps[3] = {15, 9, 5};
    for (int c = 0; c < 3; c++) {
        double ts[32], tm[32], tt[32];
        for (int r = 0; r < reps[c]; r++) {
            gal_rod_params p = {.length = 300, .elements = nels[c], .EA = 2.9e7, .EI = 28, .GJ = 160,
                                .mass = 1.628, .polar_inertia = 1.6e-4, .gravity = 9.80665,
                                .torsion = 1, .twist_clamped = 1};
            double t0 = gal_wall_time();
            gal_equilibrium eq;
            gal_modes md;
            if (gal_statics_solve(&p, GAL_BY_TENSION, 28000, NULL, &eq) ||
                gal_modes_solve(eq.rod, eq.q, 20, &md)) {
                fprintf(stderr, "bench_modes: %s\n", gal_error_message());
                return 1;
            }
            double t2 = gal_wall_time();
            ts[r] = 1e3 * eq.wall_time_s, tm[r] = 1e3 * md.wall_time_s, tt[r] = 1e3 * (t2 - t0);
            gal_modes_clear(&md);
            gal_equilibrium_clear(&eq);
        }
        qsort(ts, reps[c], sizeof(double), cmp);
        qsort(tm, reps[c], sizeof(double), cmp);
        qsort(tt, reps[c], sizeof(double), cmp);
        printf("BENCH|statics + 20 modes, %d elements (300 m Drake)|%.2f|ms|median of %d (statics %.2f, modes %.2f)\n",
               nels[c], tt[reps[c] / 2], reps[c], ts[reps[c] / 2], tm[reps[c] / 2]);
    }
    return 0;
}
