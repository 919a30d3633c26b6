/* bench_rom.c: the recomputed reduced model (rom.h) against the full model on the spans of
 * tests/rom/ (or the scenes given): the same set-up, wind and steady window (the full run's, at
 * most its last half: some limit cycles settle slowly); dominant frequency,
 * peak-to-peak amplitudes, largest support tension, residual check, and speed. Usage:
 *   bench_rom [--derivatives 0|1] [--manifold 0|1|2] [--h H] [--tolerance T] [--policy 1|2|3] [--relax 0|1] [--seeds N]
 *             [--spread] [--set key=value]... [SCENE...]   (default: every tests/rom scene)
 * Steady wind: peak-to-peak; turbulent wind: RMS over the window, mean of N seeds (default 3); a
 * scene whose header says "statistics over perturbed runs" (an irregular, not periodic, galloping):
 * RMS over the window, mean of N runs with the wind ramp 0, 1, ... s longer. There the full model's
 * own spread is printed as the yardstick: the standard error of its mean over the runs, relative.
 * --spread: the full model again with the wind ramp 1 s longer, how far its own figures move.
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
static int manifold = -1; /* --manifold 0|1|2: gal_rom_opts.manifold (-1: the default) */
static double hstep = 0; /* --h H: the reduced model's time step (0: the scene's, as the full model) */
static int policy = GAL_ROM_ADD_CORRECTION | GAL_ROM_ADD_MODE, relax = 1;

typedef struct {
    gal_sim_measures mf, mr;   /* full, reduced (on the full run's steady window, as compare measures) */
    gal_compare_ref h;         /* that window and the probes (gal_compare_reference) */
    gal_rom_sim_info info;
    double tset, tfull, trom, wfull, wrom; /* s: set-up, whole runs, integrations */
} pair_result;

/* The full and the reduced model on one scene (with the overrides), measured on the same window. */
static int pair(const char *path, const char *const *ov, int nov, int deriv, gal_scene *sc, pair_result *p)
{
    if (gal_scene_load(sc, path, ov, nov, NULL)) { printf("%s: %s\n", path, gal_error_message()); return 1; }
    gal_sim_setup s;
    double tw = gal_wall_time();
    if (gal_sim_setup_init(&s, sc, 1)) { printf("%s: %s\n", path, gal_error_message()); return 1; }
    p->tset = gal_wall_time() - tw;
    gal_sim_result rf, rr;
    gal_rom_sim_opts o;
    gal_rom_sim_default_opts(&o);
    o.derivatives = deriv;
    o.manifold = manifold, o.h = hstep;
    o.tolerance = tolerance, o.policy = policy, o.relax = relax;
    tw = gal_wall_time();
    int sf = gal_sim_run(&s, GAL_MODEL_FULL, &rf);
    p->tfull = gal_wall_time() - tw;
    if (sf) printf("%s: full: %s\n", path, gal_error_message());
    tw = gal_wall_time();
    int sr = sf ? 1 : gal_rom_sim_run(&s, &o, &rr, &p->info);
    p->trom = gal_wall_time() - tw;
    if (sr && !sf) printf("%s: reduced: %s\n", path, gal_error_message());
    if (!sf && !sr) {
        gal_compare_reference(&rf, -1, &p->h);
        double half = 0.5 * rf.time[rf.nsamples - 1]; /* the steady window: at most the last half */
        if (p->h.from < half) p->h.from = half;
        gal_compare_measure(&rf, &p->h, &p->mf);
        gal_compare_measure(&rr, &p->h, &p->mr);
        p->wfull = rf.wall_time_s, p->wrom = rr.wall_time_s;
    }
    if (!sf) gal_sim_result_clear(&rf);
    if (!sr) gal_sim_result_clear(&rr);
    gal_sim_setup_clear(&s);
    return sf || sr;
}

static int nseeds = 3, spread = 0;

/* 1 when the scene's header comment says "statistics over perturbed runs" */
static int wants_statistics(const char *path)
{
    FILE *fp = fopen(path, "r");
    char line[256];
    int yes = 0;
    while (fp && fgets(line, sizeof line, fp) && line[0] == ';')
        if (strstr(line, "statistics over perturbed runs")) yes = 1;
    if (fp) fclose(fp);
    return yes;
}

/* relative standard error of the mean of x[0..n-1] */
static double sem_rel(const double *x, int n)
{
    double m = 0, v = 0;
    for (int k = 0; k < n; k++) m += x[k] / n;
    for (int k = 0; k < n; k++) v += (x[k] - m) * (x[k] - m) / (n > 1 ? n - 1 : 1);
    return n > 1 ? sqrt(v / n) / fmax(fabs(m), 1e-300) : NAN;
}

/* The full model again with the wind ramp 1 s longer (steady wind): how far its own figures move
 * (largest of the relative f, v, h, T differences; twist apart, deg). */
static void full_spread(const char *path, const char *const *ov0, int nov0, const gal_compare_ref *h,
                        const gal_sim_measures *mf, double *rel_max,
                        double *twist)
{
    const char *ov[41];
    char kv[48];
    gal_scene sc;
    memcpy(ov, ov0, (size_t)nov0 * sizeof *ov);
    *rel_max = *twist = NAN;
    if (gal_scene_load(&sc, path, ov, nov0, NULL)) return;
    snprintf(kv, sizeof kv, "simulation.wind_ramp=%g", sc.simulation.wind_ramp + 1);
    ov[nov0] = kv;
    gal_sim_setup s;
    gal_sim_result r;
    if (gal_scene_load(&sc, path, ov, nov0 + 1, NULL) || gal_sim_setup_init(&s, &sc, 1)) return;
    if (!gal_sim_run(&s, GAL_MODEL_FULL, &r)) {
        gal_sim_measures m;
        gal_compare_measure(&r, h, &m);
        *rel_max = fmax(fmax(rel(m.frequency_hz[1], mf->frequency_hz[1]), rel(m.peak_to_peak[1], mf->peak_to_peak[1])),
                        fmax(fabs(m.peak_to_peak[0] - mf->peak_to_peak[0]) / fmax(mf->peak_to_peak[0], 0.4 * mf->peak_to_peak[1]),
                             rel(m.tension_max_steady, mf->tension_max_steady)));
        *twist = fabs(m.peak_to_peak[3] - mf->peak_to_peak[3]);
        gal_sim_result_clear(&r);
    }
    gal_sim_setup_clear(&s);
}

/* One span: steady wind, peak-to-peak over the steady window; turbulent wind, RMS over the window
 * averaged over nseeds seeds (wind.seed = 1..nseeds). The largest support tension is the steady
 * window's in both. */
static int one(const char *path, const char *const *ov0, int nov0, int deriv, double *speed, double *whole)
{
    const char *ov[40];
    char seedkv[48];
    int nov = nov0;
    memcpy(ov, ov0, (size_t)nov0 * sizeof *ov);
    gal_scene sc;
    if (gal_scene_load(&sc, path, ov, nov, NULL)) { printf("%s: %s\n", path, gal_error_message()); return 1; }
    int turb = sc.wind.turbulence != GAL_TURB_NONE, stat = turb || wants_statistics(path);
    int runs = stat ? (nseeds < 16 ? nseeds : 16) : 1;
    double ramp0 = sc.simulation.wind_ramp, own[4][16] = {{0}}; /* the full model's per-run f, v, h, T */
    double f[2] = {0}, a[2][4] = {{0}}, T[2] = {0}, tfull = 0, trom = 0, wf = 0, wr = 0, rmax = 0, fam[4] = {0};
    int basis = 0, basis0 = 0, growths = 0;
    double sp = NAN, spt = NAN;
    if (stat) ov[nov++] = seedkv;
    for (int k = 0; k < runs; k++) {
        if (turb) snprintf(seedkv, sizeof seedkv, "wind.seed=%d", k + 1);
        else snprintf(seedkv, sizeof seedkv, "simulation.wind_ramp=%g", ramp0 + k);
        pair_result p;
        if (pair(path, ov, nov, deriv, &sc, &p)) return 1;
        const gal_sim_measures *m[2] = {&p.mr, &p.mf};
        if (spread && !stat) full_spread(path, ov, nov, &p.h, &p.mf, &sp, &spt);
        for (int j = 0; j < 2; j++) {
            f[j] += m[j]->frequency_hz[1] / runs, T[j] += m[j]->tension_max_steady / runs;
            for (int c = 0; c < 4; c++) a[j][c] += (stat ? m[j]->rms[c] : m[j]->peak_to_peak[c]) / runs;
        }
        own[0][k] = p.mf.frequency_hz[1], own[1][k] = p.mf.rms[1], own[2][k] = p.mf.rms[0], own[3][k] = p.mf.tension_max_steady;
        tfull += p.tset + p.tfull, trom += p.tset + p.trom, wf += p.wfull, wr += p.wrom;
        rmax = fmax(rmax, p.info.residual_max);
        for (int c = 0; c < 4; c++) fam[c] = fmax(fam[c], p.info.residual_family[c]);
        basis = p.info.basis > basis ? p.info.basis : basis, basis0 = p.info.basis_start, growths += p.info.nevents;
        for (int e = 0; e < p.info.nevents; e++)
            printf("  grew at t = %.1f s (residual %.3g, %s): basis %d -> %d (mode %d, %d correction)\n",
                   p.info.ev[e].t_s, p.info.ev[e].residual, gal_family_names[p.info.ev[e].family],
                   p.info.ev[e].basis_before, p.info.ev[e].basis_after, p.info.ev[e].mode_added, p.info.ev[e].corrections);
    }
    double ef = rel(f[0], f[1]), ev = rel(a[0][1], a[1][1]), eT = rel(T[0], T[1]);
    double eh = fabs(a[0][0] - a[1][0]) / fmax(a[1][0], 0.4 * a[1][1]); /* 2% of vertical = 5% of 0.4 v */
    double et = fabs(a[0][3] - a[1][3]);
    int ok = ef <= 0.01 && ev <= 0.05 && eh <= 0.05 && (et <= 3 || et <= 0.05 * a[1][3]) && eT <= 0.05;
    if (stat) { /* the yardstick: the standard error of the full model's mean over the runs */
        sp = 0;
        for (int c = 0; c < 4; c++) sp = fmax(sp, sem_rel(own[c], runs));
    }
    *speed = wf / wr, *whole = tfull / trom;
    printf("ROW|%s|n=%d r=%d->%d (%d growths)|%s|f %.4f/%.4f Hz (%.2f%%)|v %.3f/%.3f m (%.1f%%)|h %.3f/%.3f m (%.1f%%)|"
           "tw %.1f/%.1f deg (%.1f deg)|T %.0f/%.0f N (%.1f%%)|res %.3g [v %.2g h %.2g t %.2g a %.2g]|%s|"
           "%s %.1f%%, %.1f deg|x%.1f step, x%.1f whole\n",
           path, sc.model.elements, basis0, basis, growths,
           turb ? "RMS, mean of the seeds" : stat ? "RMS, mean of the ramps" : "p-p", f[0], f[1],
           100 * ef, a[0][1], a[1][1], 100 * ev, a[0][0], a[1][0], 100 * eh, a[0][3], a[1][3], et, T[0], T[1], 100 * eT,
           rmax, fam[0], fam[1], fam[2], fam[3], ok ? "within" : "OUTSIDE",
           stat ? "full's own spread (s.e. of its mean over the runs)" : "full vs full (ramp + 1 s)", 100 * sp, spt,
           *speed, *whole);
    fflush(stdout);
    return 0;
}

int main(int argc, char **argv)
{
    const char *ov[32];
    const char *scenes[64];
    int nov = 0, nsc = 0, deriv = 1;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--set") && i + 1 < argc && nov < 32) ov[nov++] = argv[++i];
        else if (!strcmp(argv[i], "--derivatives") && i + 1 < argc) deriv = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--manifold") && i + 1 < argc) manifold = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--h") && i + 1 < argc) hstep = atof(argv[++i]);
        else if (!strcmp(argv[i], "--tolerance") && i + 1 < argc) tolerance = atof(argv[++i]);
        else if (!strcmp(argv[i], "--policy") && i + 1 < argc) policy = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--relax") && i + 1 < argc) relax = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--seeds") && i + 1 < argc) nseeds = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--spread")) spread = 1;
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
    printf("BENCH|reduced (recomputed) over full, per simulated second, median of %d spans|%.1f|x|tests/rom, each span's own mesh and duration, wall time (one run each; make report-spanset: 300 s, CPU, 100-400 elements)|\n", n, median(sp, n));
    printf("BENCH|reduced (recomputed) over full, whole process, median|%.1f|x|tests/rom, as above|\n", median(wh, n));
    globfree(&g);
    return fails ? 1 : 0;
}
