/* bench_bundle_rom.c: the explicit bundle's reduced model against its full model (issue 19):
 * data/scenes/quad_bundle_gallop.ini with model = explicit (and a twin), both runs in this one
 * process, alternated, CPU time of the integration (set-up excluded from both, the reduced model's
 * own basis included, as `gallop compare` reports its speedup); the ratio full/reduced per repeat
 * and its median, the counters, and the centroid's mid-span errors. Usage: bench_bundle_rom
 * [--seconds S] [--reps N] [--set key=value]... [SCENE] (default 60 s, 3 repeats, the quad and the
 * same scene with bundle.subconductors = 2; a scene or --set: that case alone). Prints ROW| and BENCH|
 * lines (make bench). */
#include "bench_util.h"

#include "gallop/bundle/bundle_rom.h"
#include "gallop/scene/scene.h"

void openblas_set_num_threads(int n) __attribute__((weak));

typedef struct {
    double cpu, pp[3];
    long steps, newton, tangents, evals, basis;
} one_run;

static int run(const char *path, const char *const *ov, int nov, int reduced, one_run *out)
{
    gal_scene sc;
    if (gal_scene_load(&sc, path, ov, nov, NULL)) return 1;
    int st;
    gal_model *m = gal_model_alloc(&sc, &st);
    if (!m) return 1;
    gal_run_opts o;
    gal_run_opts_from_scene(&sc, &o);
    gal_bundle_sim_result R;
    memset(&R, 0, sizeof R);
    double t0 = bench_cpu();
    st = reduced ? gal_bundle_simulate_reduced(m, &o, &R) : gal_bundle_simulate(m, &o, &R);
    double t1 = bench_cpu();
    if (!st) {
        gal_sim_measures ms;
        gal_sim_measure(&R.c, gal_sim_mid_probe(&R.c), -1, &ms);
        out->cpu = t1 - t0 - R.setup_time_s; /* the integration (and the basis), as compare's wall_time_s */
        out->pp[0] = ms.peak_to_peak[1], out->pp[1] = ms.peak_to_peak[0], out->pp[2] = ms.peak_to_peak[3];
        out->steps = R.c.steps, out->newton = R.c.newton_iterations, out->tangents = R.c.factorizations;
        out->evals = R.c.force_evaluations, out->basis = R.c.basis;
    }
    gal_bundle_sim_result_clear(&R);
    gal_model_free(m);
    return st;
}

/* Both models on one scene, alternated reps times: ROW| lines and one BENCH| line named by tag. */
static int bench_case(const char *path, const char *const *ov, int nov, double T, int reps, const char *tag)
{
    double ratio[16], tf[16], tr[16];
    one_run F, R;
    memset(&F, 0, sizeof F), memset(&R, 0, sizeof R);
    for (int k = 0; k < reps; k++) {
        if (run(path, ov, nov, 0, &F) || run(path, ov, nov, 1, &R)) {
            fprintf(stderr, "bench_bundle_rom: %s\n", gal_error_message());
            return 1;
        }
        tf[k] = F.cpu, tr[k] = R.cpu, ratio[k] = F.cpu / R.cpu;
        printf("ROW| %s rep %d | full %.3f s | reduced %.3f s | full/reduced %.2f\n", tag, k, F.cpu, R.cpu, ratio[k]);
    }
    double mr = bench_median(ratio, reps), mf = bench_median(tf, reps), mre = bench_median(tr, reps);
    printf("ROW| %s, %g s: full %ld steps %ld Newton %ld tangents %ld evaluations; reduced (basis %ld) %ld steps "
           "%ld Newton %ld tangents %ld evaluations\n", tag, T, F.steps, F.newton, F.tangents, F.evals, R.basis,
           R.steps, R.newton, R.tangents, R.evals);
    const char *nm[3] = {"vertical", "horizontal", "rotation"};
    for (int k = 0; k < 3; k++)
        printf("ROW| %s centroid %s p-p: full %.6g, reduced %.6g, error %.3g%%\n", tag, nm[k], F.pp[k], R.pp[k],
               100 * fabs(R.pp[k] - F.pp[k]) / fabs(F.pp[k]));
    printf("BENCH|explicit %s: full over reduced, CPU of %g s, median of %d (full %.4f, reduced %.4f s per simulated s)"
           "|%.2f|x|tests/bench/bench_bundle_rom.c|\n", tag, T, reps, mf / T, mre / T, mr);
    return 0;
}

int main(int argc, char **argv)
{
    double T = 60;
    int reps = 3, nov = 0, given = 0;
    const char *ov[40], *path = "data/scenes/quad_bundle_gallop.ini";
    static char dur[64];
    ov[nov++] = "bundle.model=explicit";
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--seconds") && i + 1 < argc) T = atof(argv[++i]);
        else if (!strcmp(argv[i], "--reps") && i + 1 < argc) reps = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--set") && i + 1 < argc && nov < 36) ov[nov++] = argv[++i], given = 1;
        else path = argv[i], given = 1;
    }
    if (reps < 1 || reps > 15) reps = 3;
    snprintf(dur, sizeof dur, "simulation.duration=%g", T);
    ov[nov++] = dur;
    if (openblas_set_num_threads) openblas_set_num_threads(1);
    if (given) return bench_case(path, ov, nov, T, reps, "bundle (given)");
    if (bench_case(path, ov, nov, T, reps, "quad bundle")) return 1;
    ov[nov++] = "bundle.subconductors=2";
    return bench_case(path, ov, nov, T, reps, "twin bundle");
}
