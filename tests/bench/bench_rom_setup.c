/* bench_rom_setup.c: the reduced model's own set-up alone (gal_rom_alloc after statics and modes:
 * the basis, V^T K0 V, the samples, the damping, the start), CPU time of this process, median of 21
 * builds at 100 and at 1000 elements, the two meshes alternated (the machine is shared: run it
 * with OPENBLAS_NUM_THREADS=1, as the command line does). Also the floor that the whole-mesh
 * evaluations of the set-up put under the ratio: at 1000 elements it evaluates the rod's tangent
 * 2 nsel times (the modal derivatives' central differences; K0 and its factorization are the
 * statics', gal_rom_opts.k0, as on the command line), and above 128 elements
 * the rod's gradient and the loads once per training state each (the fits' targets; there
 * gal_rom_opts.hyper_snapshots_fine states); each kind
 * timed alone here (median of 21), times its count, against the whole set-up at 100 elements.
 * Usage: bench_rom_setup [SCENE [FINE]] (default tests/rom/drake_200_level_dshape.ini; FINE: the
 * options' hyper_snapshots_fine, default 0: the library's default). Prints BENCH| lines (make
 * bench). */
#include "gallop.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double cpu(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static int cmpd(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

typedef struct {
    gal_scene sc;
    gal_sim_setup s;
    int sel[64], r;
    gal_rom_opts ro;
    gal_force F;
} mesh;

static int fine; /* gal_rom_opts.hyper_snapshots_fine when > 0 (the command line's second argument) */

static int init(mesh *M, const char *path, int nel)
{
    char e[64];
    snprintf(e, sizeof e, "model.elements=%d", nel);
    const char *ov[1] = {e};
    if (gal_scene_load(&M->sc, path, ov, 1, NULL) || gal_sim_setup_init(&M->s, &M->sc, 1)) {
        printf("%s\n", gal_error_message());
        return 1;
    }
    const gal_data *dt = M->s.data;
    double fhi = 0;
    M->r = 0;
    for (int k = 0; k < dt->md.n && M->r < 64; k++)
        if (dt->md.mode[k].selected) M->sel[M->r++] = k, fhi = fmax(fhi, dt->md.mode[k].frequency_hz);
    double dt_out =
        M->sc.simulation.output_interval > 0 ? M->sc.simulation.output_interval : fmin(0.05, 1.0 / (10 * fhi));
    double h = M->sc.simulation.time_step > 0 ? M->sc.simulation.time_step : fmin(dt_out, 1.0 / (40 * fhi));
    gal_rom_default_opts(&M->ro);
    M->ro.h = dt_out / ceil(dt_out / h - 1e-9);
    M->ro.rho_inf = M->sc.simulation.rho_inf;
    M->ro.damping = dt->damping;
    M->ro.k0 = dt->eq.k0; /* as the command line: the statics' K0 and its factorization */
    if (fine > 0) M->ro.hyper_snapshots_fine = fine;
    memset(&M->F, 0, sizeof M->F);
    if (dt->loads.table)
        M->F.eval = gal_loads_full, M->F.element = gal_loads_element, M->F.eval_framed = gal_loads_full_framed,
        M->F.ctx = (void *)&dt->loads;
    return 0;
}

static double once(mesh *M)
{
    const gal_data *dt = M->s.data;
    double t0 = cpu();
    gal_rom *m = gal_rom_alloc(dt->eq.rod, dt->eq.q, &dt->md, M->sel, M->r, &M->ro, &M->F);
    double t = cpu() - t0;
    if (!m) {
        printf("%s\n", gal_error_message());
        exit(1);
    }
    gal_rom_free(m);
    return t;
}

/* Median CPU time of one whole-mesh evaluation of kind k (0: the rod's tangent, 1: its gradient,
 * 2: the loads) at M's equilibrium, of 21. */
static double whole(mesh *M, int k)
{
    const gal_data *dt = M->s.data;
    const gal_rod *rod = dt->eq.rod;
    gal_csc *K = gal_csc_clone(rod->K);
    double *g = malloc((size_t)rod->nq * sizeof(double)), *v = calloc((size_t)rod->nq, sizeof(double)), t[21];
    if (!K || !g || !v) exit(1);
    for (int i = 0; i < 21; i++) {
        double t0 = cpu();
        if (k == 0) gal_rod_eval(rod, dt->eq.q, NULL, NULL, K);
        else if (k == 1) gal_rod_eval(rod, dt->eq.q, NULL, g, NULL);
        else memset(g, 0, (size_t)rod->nq * sizeof(double)), gal_loads_full((void *)&dt->loads, 10.0, dt->eq.q, v, g);
        t[i] = cpu() - t0;
    }
    qsort(t, 21, sizeof(double), cmpd);
    gal_csc_free(K), free(g), free(v);
    return t[10];
}

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "tests/rom/drake_200_level_dshape.ini";
    fine = argc > 2 ? atoi(argv[2]) : 0;
    static mesh a, b;
    if (init(&a, path, 100) || init(&b, path, 1000)) return 1;
    enum { R = 21 };
    double ta[R], tb[R];
    for (int k = 0; k < R; k++)
        ta[k] = once(&a), tb[k] = once(&b);
    qsort(ta, R, sizeof(double), cmpd), qsort(tb, R, sizeof(double), cmpd);
    printf("%s: set-up 100 el %.2f ms, 1000 el %.2f ms, ratio %.2f (training states at 1000 el: %d)\n", path,
           1e3 * ta[R / 2], 1e3 * tb[R / 2], tb[R / 2] / ta[R / 2],
           b.ro.hyper_snapshots_fine > 0 ? b.ro.hyper_snapshots_fine : b.ro.hyper_snapshots);
    printf("BENCH|reduced set-up alone at 100 elements (CPU, median of %d)|%.2f|ms|%s|\n", R, 1e3 * ta[R / 2], path);
    printf("BENCH|reduced set-up alone at 1000 elements (CPU, median of %d)|%.2f|ms|%s|\n", R, 1e3 * tb[R / 2], path);
    printf("BENCH|reduced set-up alone, 1000 over 100 elements (target <= 3)|%.2f|x|%s|\n", tb[R / 2] / ta[R / 2],
           path);
    /* the training states at 1000 elements: hyper_snapshots_fine (more than the 128 candidates) */
    int nt = (b.ro.k0 ? 0 : 1) + 2 * b.r, ns = b.ro.hyper_snapshots_fine > 0 ? b.ro.hyper_snapshots_fine : b.ro.hyper_snapshots;
    int nl = b.F.element ? ns : 0;
    double wk = whole(&b, 0), wg = whole(&b, 1), wl = b.F.eval ? whole(&b, 2) : 0, wf = nt * wk + ns * wg + nl * wl;
    printf("whole-mesh evaluations at 1000 el: %d tangents x %.3f + %d gradients x %.3f + %d loads x %.3f = %.2f ms "
           "= %.2f x the whole set-up at 100 el\n", nt, 1e3 * wk, ns, 1e3 * wg, nl, 1e3 * wl, 1e3 * wf, wf / ta[R / 2]);
    printf("BENCH|reduced set-up: its whole-mesh evaluations alone at 1000 elements over the whole set-up at 100|%.2f|x|%s|\n",
           wf / ta[R / 2], path);
    return 0;
}
