/* bench_rom_scale.c: how the hyper-reduced recomputed reduced model (rom.h, ecsw.h) scales with
 * the mesh: on one span (default tests/rom/drake_200_level_dshape.ini) at 100, 400 and 1000
 * elements, the reduced model's own set-up (gal_rom_alloc, after statics and modes), its cost
 * per step and per simulated second, against the full model's on the same set-up and wind.
 * CPU time of this process (the machine is shared; the BLAS on one thread, as in the command line,
 * src/cli/blas.c), medians of 3 (the set-up: of 7 builds). Usage:
 *   bench_rom_scale [--seconds S] [--set key=value]... [SCENE]
 * Prints one ROW| line per mesh and BENCH| lines (make bench). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "gallop.h"
#include "gallop/base/core.h"
#include "gallop/reduced/ecsw.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"

void openblas_set_num_threads(int n) __attribute__((weak));

static double cpu(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static double med3(double a, double b, double c)
{
    return fmax(fmin(a, b), fmin(fmax(a, b), c));
}

static int cmpd(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

typedef struct {
    int elements, sample, loads, basis;
    double setup_s, step_us, full_step_us, ratio, its, evals;
    long tangents; /* ratio: full over reduced per simulated second */
    long train_elements, train_full; /* the training's element and whole-rod evaluations */
} row;

/* One mesh: set-up, then three reduced builds and runs of `seconds`, one full run of as long. */
static int manifold = -1; /* --manifold 0|1 (-1: the default) */

static int one(const char *path, const char *const *ov, int nov, int nel, double seconds, row *out)
{
    char e[64], d[64];
    const char *o2[40];
    int n2 = 0;
    for (int k = 0; k < nov && n2 < 36; k++) o2[n2++] = ov[k];
    snprintf(e, sizeof e, "model.elements=%d", nel), o2[n2++] = e;
    snprintf(d, sizeof d, "simulation.duration=%g", seconds), o2[n2++] = d;
    gal_scene sc;
    gal_sim_setup s;
    if (gal_scene_load(&sc, path, o2, n2, NULL) || gal_sim_setup_init(&s, &sc, 1)) {
        printf("%s: %s\n", path, gal_error_message());
        return 1;
    }
    const gal_data *dt = s.data;
    int sel[64], r = 0;
    double fhi = 0;
    for (int k = 0; k < dt->md.n && r < 64; k++)
        if (dt->md.mode[k].selected) sel[r++] = k, fhi = fmax(fhi, dt->md.mode[k].frequency_hz);
    double dt_out = sc.simulation.output_interval > 0 ? sc.simulation.output_interval : fmin(0.05, 1.0 / (10 * fhi));
    double h = sc.simulation.time_step > 0 ? sc.simulation.time_step : fmin(dt_out, 1.0 / (40 * fhi));
    gal_rom_opts ro;
    gal_rom_default_opts(&ro);
    ro.h = dt_out / ceil(dt_out / h - 1e-9);
    ro.rho_inf = sc.simulation.rho_inf;
    ro.damping = dt->damping;
    ro.k0 = dt->eq.k0; /* as the command line: the statics' K0 and its factorization */
    if (manifold >= 0) ro.manifold = manifold;
    gal_force F = {0};
    if (dt->loads.table)
        F.eval = gal_loads_full, F.element = gal_loads_element, F.eval_framed = gal_loads_full_framed, F.ctx = (void *)&dt->loads;
    double ts[7], tr[3];
    int st = 0;
    for (int rep = 3; rep < 7 && !st; rep++) { /* set-up alone, four more times */
        double t0 = cpu();
        gal_rom *m = gal_rom_alloc(dt->eq.rod, dt->eq.q, &dt->md, sel, r, &ro, &F);
        ts[rep] = cpu() - t0;
        if (!m) { printf("%s: %s\n", path, gal_error_message()); st = 1; }
        gal_rom_free(m);
    }
    for (int rep = 0; rep < 3 && !st; rep++) {
        double t0 = cpu();
        gal_rom *m = gal_rom_alloc(dt->eq.rod, dt->eq.q, &dt->md, sel, r, &ro, &F);
        ts[rep] = cpu() - t0;
        if (!m || gal_rom_start(m, 0, dt->q_start, NULL)) { printf("%s: %s\n", path, gal_error_message()); st = 1; break; }
        t0 = cpu();
        st = gal_rom_advance(m, seconds);
        tr[rep] = (cpu() - t0) / fmax(m->steps, 1);
        out->its = (double)m->newton_iterations / fmax(m->steps, 1), out->tangents = m->tangents;
        out->evals = (double)m->force_evaluations / fmax(m->steps, 1);
        gal_rom_hyper_info hi;
        gal_rom_hyper_get_info(m, &hi);
        out->sample = hi.elements, out->loads = hi.load_elements, out->basis = m->r;
        out->train_elements = hi.train_element_evals, out->train_full = hi.train_full_evals;
        if (st) printf("%s: reduced: %s\n", path, gal_error_message());
        gal_rom_free(m);
    }
    gal_sim_result rf;
    double t0 = cpu();
    if (!st && (st = gal_sim_run(&s, GAL_MODEL_FULL, &rf))) printf("%s: full: %s\n", path, gal_error_message());
    if (!st) {
        out->full_step_us = 1e6 * (cpu() - t0) / fmax(rf.steps, 1);
        qsort(ts, 7, sizeof(double), cmpd);
        out->elements = nel, out->setup_s = ts[3], out->step_us = 1e6 * med3(tr[0], tr[1], tr[2]);
        out->ratio = out->full_step_us * rf.steps / (out->step_us * seconds / ro.h);
        printf("ROW|%s|n=%d|sample %d energy elements of %d, %d load elements|reduced set-up %.3f s|"
               "reduced %.1f us/step, full %.1f us/step (%ld steps of %.4g s)|x%.1f per simulated second|"
               "basis %d, %.2f Newton iterations and %.2f load evaluations a step, %ld tangents|"
               "training: %ld element and %ld whole-rod/loads evaluations\n",
               path, nel, out->sample, 2 * nel - 1, out->loads, out->setup_s, out->step_us, out->full_step_us,
               rf.steps, ro.h, out->ratio, out->basis, out->its, out->evals, out->tangents,
               out->train_elements, out->train_full);
        fflush(stdout);
        gal_sim_result_clear(&rf);
    }
    gal_sim_setup_clear(&s);
    return st;
}

int main(int argc, char **argv)
{
    const char *ov[32], *scene = "tests/rom/drake_200_level_dshape.ini";
    int nov = 0;
    double seconds = 20;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--set") && i + 1 < argc && nov < 32) ov[nov++] = argv[++i];
        else if (!strcmp(argv[i], "--seconds") && i + 1 < argc) seconds = atof(argv[++i]);
        else if (!strcmp(argv[i], "--manifold") && i + 1 < argc) manifold = atoi(argv[++i]);
        else scene = argv[i];
    }
    if (openblas_set_num_threads) openblas_set_num_threads(1);
    int mesh[3] = {100, 400, 1000};
    row rw[3];
    for (int k = 0; k < 3; k++)
        if (one(scene, ov, nov, mesh[k], seconds, rw + k)) return 1;
    printf("BENCH|reduced model's own set-up at 1000 elements over 100 (target <= 3)|%.1f|x|%s|\n", rw[2].setup_s / rw[0].setup_s, scene);
    for (int k = 0; k < 3; k++)
        printf("BENCH|reduced model's own set-up at %d elements (CPU, median of 7)|%.1f|ms|%s|\n", mesh[k], 1e3 * rw[k].setup_s, scene);
    printf("BENCH|reduced cost per step at 1000 elements over 100 (flat: ~1)|%.2f|x|%s|\n", rw[2].step_us / rw[0].step_us, scene);
    printf("BENCH|reduced over full per simulated second at 400 elements (target >= 100)|%.1f|x|%s|\n",
           rw[1].ratio, scene);
    return 0;
}
