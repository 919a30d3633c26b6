/* diag_steps.c: the reduced model's time error against its step (issue 13): one scene's full run at
 * its own step, then reduced runs at several steps, each measured as `gallop compare` measures it
 * (the headline figures over the full run's steady window: frequency, vertical, horizontal, twist,
 * the largest support tension over the window) against the full run and against the reduced run at
 * the smallest step (its own converged result: the time error apart from the reduction's). The
 * steps are the output interval divided by SUB (1 = one step an output interval) and by REF (the
 * reference). --rms FROM: the RMS about the mean instead of peak-to-peak, over [FROM, end] (turbulent
 * or irregular wind). CPU time of this process (the machine is shared), the BLAS on one thread.
 * Not in make bench (a study, minutes a scene). Build as tests/bench/run.sh builds the benches.
 * Usage: diag_steps SCENE [--subs 1,2,3,4] [--ref 16] [--rms FROM] [--full-h H] [--set key=value]... */
#include "bench_util.h"

#include "gallop/analysis/compare.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"

#include <math.h>

void openblas_set_num_threads(int n) __attribute__((weak));

typedef struct {
    double f, v, h, tw, T; /* frequency Hz, vertical m, horizontal m, twist deg, tension N */
} figs;

static void figures(const gal_sim_result *r, const gal_compare_ref *ref, int rms, figs *o)
{
    gal_sim_measures m;
    if (gal_compare_measure(r, ref, &m)) {
        memset(o, 0, sizeof *o);
        return;
    }
    const double *a = rms ? m.rms : m.peak_to_peak;
    o->f = m.frequency_hz[1], o->v = a[1], o->h = a[0], o->tw = a[3], o->T = m.tension_max_steady;
}

static double rel(double a, double b) { return fabs(a - b) / fabs(b) * 100; }

/* errors of a against b in % (horizontal also in % of b's vertical; twist also in deg) */
static void print_err(const char *what, const figs *a, const figs *b)
{
    printf("  %-7s f %.3f%%  v %.2f%%  h %.2f%% (%.2f%% of v)  twist %.2f%% (%.2f deg)  T %.2f%%", what, rel(a->f, b->f),
           rel(a->v, b->v), rel(a->h, b->h), fabs(a->h - b->h) / b->v * 100, rel(a->tw, b->tw), fabs(a->tw - b->tw),
           rel(a->T, b->T));
}

typedef struct {
    const char *ov[32], *path;
    int nov, subs[17], nsub, ref_sub;
    double rms_from, full_h;
} args;

/* the command line into *a; 0 when it names a scene */
static int parse(int argc, char **argv, args *a)
{
    memset(a, 0, sizeof *a);
    a->subs[0] = 1, a->subs[1] = 2, a->subs[2] = 3, a->subs[3] = 4, a->nsub = 4, a->ref_sub = 16, a->rms_from = -1;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--set") && i + 1 < argc && a->nov < 32) a->ov[a->nov++] = argv[++i];
        else if (!strcmp(argv[i], "--ref") && i + 1 < argc) a->ref_sub = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--rms") && i + 1 < argc) a->rms_from = atof(argv[++i]);
        else if (!strcmp(argv[i], "--full-h") && i + 1 < argc) a->full_h = atof(argv[++i]);
        else if (!strcmp(argv[i], "--subs") && i + 1 < argc) {
            char *p = argv[++i];
            for (a->nsub = 0; *p && a->nsub < 16; a->nsub++) {
                a->subs[a->nsub] = (int)strtol(p, &p, 10);
                if (*p == ',') p++;
            }
        } else a->path = argv[i];
    }
    if (a->path) return 0;
    fprintf(stderr, "usage: diag_steps SCENE [--subs 1,2,3,4] [--ref 16] [--rms FROM] [--full-h H] [--set key=value]...\n");
    return 2;
}

int main(int argc, char **argv)
{
    args A;
    if (parse(argc, argv, &A)) return 2;
    const char *path = A.path;
    int nsub = A.nsub, *subs = A.subs, ref_sub = A.ref_sub;
    double rms_from = A.rms_from, full_h = A.full_h;
    if (openblas_set_num_threads) openblas_set_num_threads(1);
    gal_scene sc;
    gal_sim_setup s;
    if (gal_scene_load(&sc, path, A.ov, A.nov, NULL) || gal_sim_setup_init(&s, &sc, 1)) {
        fprintf(stderr, "diag_steps: %s\n", gal_error_message());
        return 1;
    }
    gal_run_opts o;
    gal_run_opts_from_scene(&sc, &o);
    if (gal_run_check_measurable(s.model, s.data, &o)) {
        fprintf(stderr, "diag_steps: %s\n", gal_error_message());
        return 1;
    }
    gal_sim_result full, red[17];
    double t0 = bench_cpu();
    gal_run_opts of = o;
    if (full_h > 0) of.time_step = full_h;
    if (gal_run(s.model, s.data, &gal_integrator_full, &of, &full)) {
        fprintf(stderr, "diag_steps: full: %s\n", gal_error_message());
        return 1;
    }
    double cpu_full = bench_cpu() - t0;
    gal_compare_ref ref;
    double from = rms_from >= 0 ? rms_from : -1;
    if (gal_compare_reference(&full, from, &ref)) {
        fprintf(stderr, "diag_steps: %s\n", gal_error_message());
        return 1;
    }
    figs ff, fr[17];
    int rms = rms_from >= 0;
    figures(&full, &ref, rms, &ff);
    printf("%s |%s| dt_out %.5g s, full h %.5g s (%ld steps, %.2f s CPU): f %.4f Hz, v %.4f m, h %.4f m, twist %.2f deg, "
           "T %.0f N, window from %.1f s\n", path, rms ? "RMS" : "p-p", full.dt_out, full.time_step_s, full.steps, cpu_full,
           ff.f, ff.v, ff.h, ff.tw, ff.T, ref.from);
    subs[nsub] = ref_sub;
    for (int k = 0; k <= nsub; k++) {
        gal_run_opts orr = o;
        orr.time_step = full.dt_out / subs[k];
        t0 = bench_cpu();
        int st = gal_run(s.model, s.data, &gal_integrator_reduced, &orr, &red[k]);
        double cpu = bench_cpu() - t0;
        if (st) {
            printf(" sub %d: reduced failed: %s\n", subs[k], gal_error_message());
            memset(&red[k], 0, sizeof red[k]);
            fr[k].v = NAN;
            continue;
        }
        figures(&red[k], &ref, rms, &fr[k]);
        printf(" sub %2d h %.5g s (%ld steps, %ld Newton, basis %d->%d, residual_max %.3f, valid %d, %.3f s CPU, %.3f ms "
               "per simulated s)\n", subs[k], red[k].time_step_s, red[k].steps, red[k].newton_iterations, red[k].basis_start,
               red[k].basis, red[k].residual_max, red[k].valid, cpu, cpu / sc.simulation.duration * 1e3);
        print_err("vs full", &fr[k], &ff);
        printf("\n");
    }
    if (!isnan(fr[nsub].v))
        for (int k = 0; k < nsub; k++) {
            if (isnan(fr[k].v)) continue;
            printf(" sub %2d", subs[k]);
            print_err("vs ref", &fr[k], &fr[nsub]);
            printf("\n");
        }
    for (int k = 0; k <= nsub; k++) gal_sim_result_clear(&red[k]);
    gal_sim_result_clear(&full);
    gal_sim_setup_clear(&s);
    return 0;
}
