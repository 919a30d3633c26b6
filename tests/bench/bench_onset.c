/* bench_onset.c: the coupled onset (issue 15) against the full model, in runs longer than make
 * check affords. For each scene (torsion on, the pipeline's damping): the predicted onset U_c (and
 * the speed above which the span is stable again, U_r, where there is one), then full-model runs
 * of `duration` s at 0.9, 0.95, 1.05 and 1.1 of it; the growth rate is the slope of the log of the
 * 10-s window maxima of the quarter-span vertical motion over the last two thirds of the run (a
 * span that saturates into a limit cycle shows ~0: its peak-to-peak is printed beside it).
 * Prints BENCH| rows for make bench and a ROW| line per run.
 * Usage: bench_onset [duration_s] (default 800). */
#include "gallop.h"
#include "gallop/analysis/onset.h"
#include "gallop/run/sim.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static int full_run(const char *scene, double U, double duration, double *growth, double *pp)
{
    char sp[64], du[64];
    snprintf(sp, sizeof sp, "wind.speed=%.6g", U);
    snprintf(du, sizeof du, "simulation.duration=%.6g", duration);
    const char *ov[] = {sp, du};
    gal_scene sc;
    gal_sim_setup s;
    gal_sim_result r;
    *growth = *pp = NAN;
    if (gal_scene_load(&sc, scene, ov, 2, NULL) || gal_sim_setup_init(&s, &sc, 1)) return GAL_EFAIL;
    int st = gal_sim_run(&s, GAL_MODEL_FULL, &r);
    if (!st && r.nsamples) {
        int np = r.nprobe, k = 1;
        long win = (long)(10.0 / r.dt_out), tail = (long)(50.0 / r.dt_out);
        double sx = 0, sy = 0, sxx = 0, sxy = 0, lo = INFINITY, hi = -INFINITY;
        int m = 0;
        for (long a = r.nsamples / 3; a + win <= r.nsamples; a += win, m++) {
            double mx = 0, mean = 0;
            for (long i = a; i < a + win; i++) mean += r.trace[(size_t)i * 4 * np + 4 * k + 1] / win;
            for (long i = a; i < a + win; i++) mx = fmax(mx, fabs(r.trace[(size_t)i * 4 * np + 4 * k + 1] - mean));
            double t = r.time[a + win / 2], y = log(mx);
            sx += t, sy += y, sxx += t * t, sxy += t * y;
        }
        for (long i = r.nsamples - tail; i < r.nsamples; i++) {
            double z = r.trace[(size_t)i * 4 * np + 4 * k + 1];
            lo = fmin(lo, z), hi = fmax(hi, z);
        }
        *growth = (m * sxy - sx * sy) / (m * sxx - sx * sx);
        *pp = hi - lo;
        gal_sim_result_clear(&r);
    }
    gal_sim_setup_clear(&s);
    return st;
}

/* The runs about one predicted speed u (an onset: grows above; a restabilization: grows below). */
static void bracket(const char *name, const char *scene, const char *what, double u, int grows_above, double duration)
{
    static const double f[4] = {0.9, 0.95, 1.05, 1.1};
    double g[4], pp[4];
    for (int k = 0; k < 4; k++) {
        full_run(scene, f[k] * u, duration, g + k, pp + k);
        printf("ROW|%s|%s %.4g m/s|x%.2f = %.4g m/s|growth %.4g 1/s|p-p %.3g m\n", name, what, u, f[k], f[k] * u, g[k], pp[k]);
    }
    /* the side that should grow: a positive rate or a limit cycle (p-p over 0.1 m) */
    int ok = 1;
    for (int k = 0; k < 4; k++) {
        int above = f[k] > 1, unstable = g[k] > 0 || pp[k] > 0.1;
        ok &= (above == grows_above) == unstable;
    }
    printf("BENCH|%s: %s predicted|%.4g|m/s|coupled analysis, 30 modes|\n", name, what, u);
    printf("BENCH|%s: full-model growth at 0.9 / 0.95 / 1.05 / 1.1 of it|%.2g / %.2g / %.2g / %.2g|1/s|%g-s runs, quarter span; "
           "consistent with the prediction: %s|\n", name, g[0], g[1], g[2], g[3], duration, ok ? "yes" : "NO");
}

int main(int argc, char **argv)
{
    double duration = argc > 1 ? atof(argv[1]) : 800;
    const char *scenes[][2] = {{"iced_gallop", "data/scenes/iced_gallop.ini"},
                               {"crescent_condor", "data/scenes/crescent_condor.ini"},
                               {"condor_twisted", "data/scenes/condor_twisted.ini"}};
    for (int c = 0; c < 3; c++) {
        gal_scene sc;
        gal_sim_setup s;
        if (gal_scene_load(&sc, scenes[c][1], NULL, 0, NULL) || gal_sim_setup_init(&s, &sc, 1)) {
            fprintf(stderr, "bench_onset: %s\n", gal_error_message());
            return 1;
        }
        gal_onset_opts o;
        gal_onset_default_opts(&o);
        o.speed_min = 0.25, o.speed_max = 20, o.speed_step = 0.25;
        gal_onset r;
        double mass = sc.conductor.mass_per_length + sc.ice.mass_per_length;
        int st = gal_onset_analyse(s.data->eq.rod, s.data->eq.q, &s.data->loads, s.data->damping, mass, &o, &r);
        gal_sim_setup_clear(&s);
        if (st) {
            fprintf(stderr, "bench_onset: %s\n", gal_error_message());
            return 1;
        }
        double uc = r.onset_speed, ur = r.restable_speed;
        gal_onset_clear(&r);
        if (isfinite(uc)) bracket(scenes[c][0], scenes[c][1], "onset", uc, 1, duration);
        if (isfinite(ur)) bracket(scenes[c][0], scenes[c][1], "stable again above", ur, 0, duration);
    }
    return 0;
}
