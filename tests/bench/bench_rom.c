/* bench_rom.c: the recomputed reduced model (rom.h) against the full model on the spans of
 * tests/rom/ (or the scenes given): the same set-up, wind and steady window; dominant frequency,
 * peak-to-peak amplitudes, largest support tension, residual check, and speed. Usage:
 *   bench_rom [--derivatives 0|1] [--set key=value]... [SCENE...]   (default: every tests/rom scene)
 * Prints one ROW| line per scene and BENCH| lines (make bench) with the medians. */
#include <glob.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gallop.h"
#include "gallop/base/core.h"
#include "gallop/output/simreport.h"
#include "gallop/reduced/rom_sim.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"

static double rel(double a, double b) { return fabs(a - b) / fmax(fabs(b), 1e-300); }

static int cmpd(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    qsort(v, n, sizeof(double), cmpd);
    return n ? (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2])) : NAN;
}

static double tolerance = -1;
static int policy = GAL_ROM_ADD_CORRECTION | GAL_ROM_ADD_MODE, relax = 1;

static int one(const char *path, const char *const *ov, int nov, int deriv, double *speed, double *whole)
{
    gal_scene sc;
    if (gal_scene_load(&sc, path, ov, nov, NULL)) { printf("%s: %s\n", path, gal_error_message()); return 1; }
    gal_sim_setup s;
    double tw = gal_wall_time();
    if (gal_sim_setup_init(&s, &sc, 1)) { printf("%s: %s\n", path, gal_error_message()); return 1; }
    double tset = gal_wall_time() - tw;
    gal_sim_result rf, rr;
    gal_rom_sim_info info;
    gal_rom_sim_opts o;
    gal_rom_sim_default_opts(&o);
    o.derivatives = deriv;
    o.tolerance = tolerance, o.policy = policy, o.relax = relax;
    tw = gal_wall_time();
    int sf = gal_sim_run(&s, GAL_MODEL_FULL, &rf);
    double tfull = gal_wall_time() - tw;
    if (sf) printf("%s: full: %s\n", path, gal_error_message());
    tw = gal_wall_time();
    int sr = gal_rom_sim_run(&s, &o, &rr, &info);
    double trom = gal_wall_time() - tw;
    if (sr) printf("%s: reduced: %s\n", path, gal_error_message());
    if (!sf && !sr) {
        int k = gal_sim_mid_probe(&rf);
        gal_sim_measures mf, mr;
        gal_sim_measure(&rf, k, -1, &mf);
        gal_sim_measure(&rr, k, mf.steady_from_s, &mr);
        double ev = rel(mr.peak_to_peak[1], mf.peak_to_peak[1]);
        double eh = fabs(mr.peak_to_peak[0] - mf.peak_to_peak[0]) /
                    fmax(mf.peak_to_peak[0], 0.4 * mf.peak_to_peak[1]); /* 2% of vertical = 5% of 0.4 v */
        double et = fabs(mr.peak_to_peak[3] - mf.peak_to_peak[3]);
        double ef = rel(mr.frequency_hz[1], mf.frequency_hz[1]);
        double eT = rel(mr.tension_max, mf.tension_max);
        *speed = rf.wall_time_s / rr.wall_time_s;
        *whole = (tset + tfull) / (tset + trom);
        printf("ROW|%s|n=%d r=%d|f %.4f/%.4f Hz (%.2f%%)|v %.3f/%.3f m (%.1f%%)|h %.3f/%.3f m (%.1f%%)|tw %.1f/%.1f deg (%.1f deg)|"
               "T %.0f/%.0f N (%.1f%%)|res %.3g [v %.2g h %.2g t %.2g a %.2g]|x%.1f step, x%.1f whole|build %.2fs\n",
               path, sc.model.elements, info.basis, mr.frequency_hz[1], mf.frequency_hz[1], 100 * ef, mr.peak_to_peak[1],
               mf.peak_to_peak[1], 100 * ev, mr.peak_to_peak[0], mf.peak_to_peak[0], 100 * eh, mr.peak_to_peak[3],
               mf.peak_to_peak[3], et, mr.tension_max, mf.tension_max, 100 * eT, info.residual_max,
               info.residual_family[0], info.residual_family[1], info.residual_family[2], info.residual_family[3],
               *speed, *whole, info.build_time_s);
        for (int e = 0; e < info.nevents; e++)
            printf("  grew at t = %.1f s (residual %.3g, %s): basis %d -> %d (mode %d, %d correction)\n", info.ev[e].t_s,
                   info.ev[e].residual, gal_family_names[info.ev[e].family], info.ev[e].basis_before,
                   info.ev[e].basis_after, info.ev[e].mode_added, info.ev[e].corrections);
        fflush(stdout);
    }
    if (!sf) gal_sim_result_clear(&rf);
    if (!sr) gal_sim_result_clear(&rr);
    gal_sim_setup_clear(&s);
    return sf || sr;
}

int main(int argc, char **argv)
{
    const char *ov[32];
    const char *scenes[64];
    int nov = 0, nsc = 0, deriv = 1;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--set") && i + 1 < argc && nov < 32) ov[nov++] = argv[++i];
        else if (!strcmp(argv[i], "--derivatives") && i + 1 < argc) deriv = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--tolerance") && i + 1 < argc) tolerance = atof(argv[++i]);
        else if (!strcmp(argv[i], "--policy") && i + 1 < argc) policy = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--relax") && i + 1 < argc) relax = atoi(argv[++i]);
        else if (nsc < 64) scenes[nsc++] = argv[i];
    }
    glob_t g = {0};
    if (!nsc && glob("tests/rom/*.ini", 0, NULL, &g) == 0)
        for (size_t k = 0; k < g.gl_pathc && nsc < 64; k++) scenes[nsc++] = g.gl_pathv[k];
    double sp[64], wh[64];
    int n = 0, fails = 0;
    for (int k = 0; k < nsc; k++) {
        if (one(scenes[k], ov, nov, deriv, sp + n, wh + n)) fails++;
        else n++;
    }
    printf("BENCH|reduced (recomputed) over full, per simulated second, median of %d spans|%.1f|x|tests/rom|\n", n, median(sp, n));
    printf("BENCH|reduced (recomputed) over full, whole process, median|%.1f|x|tests/rom|\n", median(wh, n));
    globfree(&g);
    return fails ? 1 : 0;
}
