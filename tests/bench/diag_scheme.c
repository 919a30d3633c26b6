/* diag_scheme.c: the reduced model's time schemes against their step (issue 13): generalized-alpha
 * (rom_step.c) and the two-stage Gauss-Legendre method (rom_irk.c) on one scene, each run at the
 * output interval over SUB, against one reference run of the reduced model (default generalized-
 * alpha at dt_out/64: the reduced equations' converged result). Per run: the RMS trajectory
 * difference at the first probe over [T0, T1] (tests/trace_rms.h, over the reference's RMS), the
 * headline figures over the full run's steady window as `gallop compare` measures them (frequency,
 * vertical, horizontal, twist p-p, the largest tension) against the reference's, and the CPU per
 * simulated second (this process; the BLAS on one thread), with the full model's for the ratio.
 * Not in make bench (a study). Build as tests/bench/run.sh builds the benches. Usage:
 *   diag_scheme SCENE T0 T1 [--runs g4,g8,G1,G2] [--ref g64] [--set key=value]... */
#include "bench_util.h"

#include "gallop/analysis/compare.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"
#include "../trace_rms.h"

#include <math.h>

void openblas_set_num_threads(int n) __attribute__((weak));

typedef struct {
    double f, v, h, tw, T;
} figs;

static void figures(const gal_sim_result *r, const gal_compare_ref *ref, figs *o)
{
    gal_sim_measures m;
    if (gal_compare_measure(r, ref, &m)) {
        memset(o, 0, sizeof *o);
        return;
    }
    o->f = m.frequency_hz[1], o->v = m.peak_to_peak[1], o->h = m.peak_to_peak[0], o->tw = m.peak_to_peak[3];
    o->T = m.tension_max_steady;
}

static double rel(double a, double b) { return fabs(a - b) / fabs(b) * 100; }

/* "g8" / "G2": the scheme and the sub */
static int spec(const char *s, int *scheme, int *sub)
{
    *scheme = s[0] == 'G' ? 1 : 0;
    *sub = atoi(s + 1);
    return *sub > 0 ? 0 : 1;
}

static int run(const gal_sim_setup *s, const gal_run_opts *o, double dt_out, const char *sp, gal_sim_result *r,
               double *cpu)
{
    int scheme, sub;
    if (spec(sp, &scheme, &sub)) return 2;
    gal_run_opts oo = *o;
    oo.time_step = dt_out / sub, oo.rom_scheme = scheme;
    double c0 = bench_cpu();
    int st = gal_run(s->model, s->data, &gal_integrator_reduced, &oo, r);
    *cpu = bench_cpu() - c0;
    return st;
}

int main(int argc, char **argv)
{
    const char *ov[32], *runs[32], *refs = "g64";
    int nov = 0, nrun = 0;
    if (argc < 4) {
        fprintf(stderr, "usage: diag_scheme SCENE T0 T1 [--runs g4,G1] [--ref g64] [--set key=value]...\n");
        return 2;
    }
    double t0 = atof(argv[2]), t1 = atof(argv[3]);
    static char buf[512];
    for (int i = 4; i < argc; i++) {
        if (!strcmp(argv[i], "--set") && i + 1 < argc && nov < 32) ov[nov++] = argv[++i];
        else if (!strcmp(argv[i], "--ref") && i + 1 < argc) refs = argv[++i];
        else if (!strcmp(argv[i], "--runs") && i + 1 < argc) {
            snprintf(buf, sizeof buf, "%s", argv[++i]);
            for (char *p = strtok(buf, ","); p && nrun < 32; p = strtok(NULL, ",")) runs[nrun++] = p;
        }
    }
    if (!nrun) runs[0] = "g4", runs[1] = "G1", nrun = 2;
    if (openblas_set_num_threads) openblas_set_num_threads(1);
    gal_scene sc;
    gal_sim_setup s;
    if (gal_scene_load(&sc, argv[1], ov, nov, NULL) || gal_sim_setup_init(&s, &sc, 1)) {
        fprintf(stderr, "diag_scheme: %s\n", gal_error_message());
        return 1;
    }
    gal_run_opts o;
    gal_run_opts_from_scene(&sc, &o);
    gal_sim_result full, R, r;
    double c0 = bench_cpu(), cpu;
    if (gal_run_check_measurable(s.model, s.data, &o) || gal_run(s.model, s.data, &gal_integrator_full, &o, &full)) {
        fprintf(stderr, "diag_scheme: full: %s\n", gal_error_message());
        return 1;
    }
    double cpu_full = bench_cpu() - c0, dt_out = full.dt_out, T = sc.simulation.duration;
    gal_compare_ref cref;
    if (gal_compare_reference(&full, -1, &cref) || run(&s, &o, dt_out, refs, &R, &cpu)) {
        fprintf(stderr, "diag_scheme: %s\n", gal_error_message());
        return 1;
    }
    figs fR, f, fF;
    figures(&R, &cref, &fR);
    figures(&full, &cref, &fF);
    printf("%s: dt_out %.5g s; full %.4f ms/s; reference %s (%.4f ms/s, basis %d->%d): f %.4f v %.4f h %.4f twist %.2f "
           "T %.0f; window from %.1f s; RMS over [%g, %g] s\n", argv[1], dt_out, cpu_full / T * 1e3, refs, cpu / T * 1e3,
           R.basis_start, R.basis, fR.f, fR.v, fR.h, fR.tw, fR.T, cref.from, t0, t1);
    for (int k = 0; k < nrun; k++) {
        int st = run(&s, &o, dt_out, runs[k], &r, &cpu);
        if (st) {
            printf(" %-4s failed: %s\n", runs[k], gal_error_message());
            continue;
        }
        figures(&r, &cref, &f);
        const int col[3] = {0, 1, 3};
        double e[3];
        for (int c = 0; c < 3; c++) e[c] = rms_error(&r, &R, col[c], t0, t1);
        printf(" %-4s h %.5f: %.4f ms/s (x%.1f), %.2f Newton/step, %.3f LU/step, basis %d->%d, valid %d | RMS h %.2e v %.2e tw %.2e | "
               "p-p vs ref: f %.3f%% v %.2f%% h %.2f%% tw %.2f%% (%.2f deg) T %.2f%%\n", runs[k], r.time_step_s,
               cpu / T * 1e3, cpu_full / cpu, (double)r.newton_iterations / r.steps, (double)r.factorizations / r.steps, r.basis_start, r.basis, r.valid,
               e[0], e[1], e[2], rel(f.f, fR.f), rel(f.v, fR.v), rel(f.h, fR.h), rel(f.tw, fR.tw), fabs(f.tw - fR.tw),
               rel(f.T, fR.T));
        printf("      vs full: f %.3f%% v %.2f%% h %.2f%% tw %.2f%% T %.2f%%\n",
               rel(f.f, fF.f), rel(f.v, fF.v), rel(f.h, fF.h), rel(f.tw, fF.tw), rel(f.T, fF.T));
        fflush(stdout);
        gal_sim_result_clear(&r);
    }
    gal_sim_result_clear(&R);
    gal_sim_result_clear(&full);
    gal_sim_setup_clear(&s);
    return 0;
}
