/* diag_order.c: the observed order in time of the full and the reduced model (issue 13): one
 * scene run by each model at the output interval over SUB (the default step is over 4 when 40 steps a
 * period of the highest mode fit 4 an interval) and at REF, the RMS difference of each family's
 * trace at the first probe from the REF run over [T0, T1], over that trace's RMS about its mean
 * there. Trajectories, not the peak-to-peak of the limit cycle (a maximum over cycles that a
 * secondary instability growing in the window makes far more step-sensitive than the orbit is).
 * CPU of this process, the BLAS on one thread. Not in make bench (a study). Build as
 * tests/bench/run.sh builds the benches. Usage:
 *   diag_order SCENE T0 T1 [--subs 2,4,8] [--ref 32] [--model full|reduced|both] [--set key=value]... */
#include "bench_util.h"

#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"
#include "../trace_rms.h"

#include <math.h>

void openblas_set_num_threads(int n) __attribute__((weak));

/* one model at the steps dt_out / subs[k] against dt_out / ref */
static int study(const gal_sim_setup *s, const gal_run_opts *o, const gal_integrator_type *T, const char *name,
                 const int *subs, int nsub, int ref, double t0, double t1)
{
    gal_sim_result R, r;
    gal_run_opts oo = *o;
    if (gal_run(s->model, s->data, T, &oo, &R)) return 1; /* the output interval */
    double dt_out = R.dt_out;
    gal_sim_result_clear(&R);
    oo.time_step = dt_out / ref;
    if (gal_run(s->model, s->data, T, &oo, &R)) return 1;
    double e[3][16];
    for (int k = 0; k < nsub; k++) {
        oo.time_step = dt_out / subs[k];
        double c0 = bench_cpu();
        if (gal_run(s->model, s->data, T, &oo, &r)) return 1;
        const int col[3] = {0, 1, 3};
        for (int c = 0; c < 3; c++) e[c][k] = rms_error(&r, &R, col[c], t0, t1);
        printf(" %-7s sub %3d h %.5g s: horizontal %.3e vertical %.3e twist %.3e (%ld Newton, %.2f s CPU)\n", name, subs[k],
               r.time_step_s, e[0][k], e[1][k], e[2][k], r.newton_iterations, bench_cpu() - c0);
        gal_sim_result_clear(&r);
    }
    for (int k = 1; k < nsub; k++) {
        double q = log((double)subs[k] / subs[k - 1]);
        printf(" %-7s order sub %d to %d: horizontal %.2f vertical %.2f twist %.2f\n", name, subs[k - 1], subs[k],
               log(e[0][k - 1] / e[0][k]) / q, log(e[1][k - 1] / e[1][k]) / q, log(e[2][k - 1] / e[2][k]) / q);
    }
    gal_sim_result_clear(&R);
    return 0;
}

int main(int argc, char **argv)
{
    const char *ov[32];
    int nov = 0, subs[16] = {2, 4, 8}, nsub = 3, ref = 32, which = 3;
    if (argc < 4) {
        fprintf(stderr, "usage: diag_order SCENE T0 T1 [--subs 2,4,8] [--ref 32] [--model full|reduced|both] "
                        "[--set key=value]...\n");
        return 2;
    }
    double t0 = atof(argv[2]), t1 = atof(argv[3]);
    for (int i = 4; i < argc; i++) {
        if (!strcmp(argv[i], "--set") && i + 1 < argc && nov < 32) ov[nov++] = argv[++i];
        else if (!strcmp(argv[i], "--ref") && i + 1 < argc) ref = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--model") && i + 1 < argc) {
            i++;
            which = !strcmp(argv[i], "full") ? 1 : !strcmp(argv[i], "reduced") ? 2 : 3;
        } else if (!strcmp(argv[i], "--subs") && i + 1 < argc) {
            char *p = argv[++i];
            for (nsub = 0; *p && nsub < 16; nsub++) {
                subs[nsub] = (int)strtol(p, &p, 10);
                if (*p == ',') p++;
            }
        }
    }
    if (openblas_set_num_threads) openblas_set_num_threads(1);
    gal_scene sc;
    gal_sim_setup s;
    if (gal_scene_load(&sc, argv[1], ov, nov, NULL) || gal_sim_setup_init(&s, &sc, 1)) {
        fprintf(stderr, "diag_order: %s\n", gal_error_message());
        return 1;
    }
    gal_run_opts o;
    gal_run_opts_from_scene(&sc, &o);
    int st = gal_run_check_measurable(s.model, s.data, &o);
    printf("%s: RMS trajectory error over [%g, %g] s against the step dt_out/%d\n", argv[1], t0, t1, ref);
    if (!st && (which & 1)) st = study(&s, &o, &gal_integrator_full, "full", subs, nsub, ref, t0, t1);
    if (!st && (which & 2)) st = study(&s, &o, &gal_integrator_reduced, "reduced", subs, nsub, ref, t0, t1);
    if (st) fprintf(stderr, "diag_order: %s\n", gal_error_message());
    gal_sim_setup_clear(&s);
    return st ? 1 : 0;
}
