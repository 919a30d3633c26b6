/* diag_orbit.c: one scene's reduced run against its full run, measured as `gallop compare`
 * measures (gal_compare_runs), with the full run cached (its trace) so that several reduced runs
 * (meshes, BLAS thread counts, before and after a change) reuse one full run (issue 13, the
 * growth's correction taken over the orbit). Usage:
 *   diag_orbit CACHE SCENE ELEMENTS DURATION [full]
 * "full": run and cache the full model only. The reduced run has model.on_invalid = warn. Prints one line:
 *   ORBIT|elements|twist err|vertical err|horizontal err|freq err|valid|growths (t s)|basis|reduced CPU s
 * The thread count is OPENBLAS_NUM_THREADS's (the library's default when unset). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "gallop.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"

static int load_full(const char *path, gal_sim_result *r)
{
    FILE *f = fopen(path, "rb");
    if (!f) return 1;
    memset(r, 0, sizeof *r);
    int ok = fread(r, sizeof *r, 1, f) == 1;
    long n = ok ? r->nsamples : 0;
    r->time = malloc((size_t)n * sizeof(double));
    r->trace = malloc((size_t)n * 4 * r->nprobe * sizeof(double));
    r->tension = malloc((size_t)n * 2 * sizeof(double));
    ok = ok && r->time && r->trace && r->tension && fread(r->time, sizeof(double), n, f) == (size_t)n &&
         fread(r->trace, sizeof(double), (size_t)n * 4 * r->nprobe, f) == (size_t)n * 4 * r->nprobe &&
         fread(r->tension, sizeof(double), (size_t)n * 2, f) == (size_t)n * 2;
    fclose(f);
    return !ok;
}

static void save_full(const char *path, const gal_sim_result *r)
{
    FILE *f = fopen(path, "wb");
    if (!f) return;
    long n = r->nsamples;
    fwrite(r, sizeof *r, 1, f);
    fwrite(r->time, sizeof(double), n, f);
    fwrite(r->trace, sizeof(double), (size_t)n * 4 * r->nprobe, f);
    fwrite(r->tension, sizeof(double), (size_t)n * 2, f);
    fclose(f);
}

int main(int argc, char **argv)
{
    if (argc < 5) return 2;
    char kv[2][64];
    const char *ov[3] = {kv[0], kv[1], "model.on_invalid=warn"};
    snprintf(kv[0], 64, "model.elements=%s", argv[3]);
    snprintf(kv[1], 64, "simulation.duration=%s", argv[4]);
    gal_scene sc;
    gal_sim_setup s;
    if (gal_scene_load(&sc, argv[2], ov, 3, NULL) || gal_sim_setup_init(&s, &sc, 1)) {
        printf("ERR|%s\n", gal_error_message());
        return 1;
    }
    gal_sim_result full, red;
    if (load_full(argv[1], &full)) {
        if (gal_sim_run(&s, GAL_MODEL_FULL, &full)) { printf("ERR|full %s\n", gal_error_message()); return 1; }
        save_full(argv[1], &full);
    }
    if (argc > 5 && !strcmp(argv[5], "full")) return 0;
    clock_t c0 = clock();
    if (gal_sim_run(&s, GAL_MODEL_REDUCED, &red)) { printf("ERR|reduced %s\n", gal_error_message()); return 1; }
    double cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
    gal_compare_figures c;
    if (gal_compare_runs(&full, &red, -1, &c)) { printf("ERR|compare %s\n", gal_error_message()); return 1; }
    char gr[256] = "";
    for (int k = 0; k < red.growths; k++) {
        size_t l = strlen(gr);
        snprintf(gr + l, sizeof gr - l, "%s%.1f %s %d->%d %.3g Hz", k ? ", " : "", red.growth[k].t_s,
                 gal_family_names[red.growth[k].family], red.growth[k].basis_before, red.growth[k].basis_after,
                 red.growth[k].mode_added_hz);
    }
    printf("ORBIT|%s|tw %+.1f%%|v %+.1f%%|h %+.1f%%|f %+.2f%%|valid %d|res %.3g|growths %d (%s)|basis %d|cpu %.1f s|"
           "tw %.2f/%.2f deg\n", argv[3], 100 * c.err_twist, 100 * c.err_vertical, 100 * c.err_horizontal,
           100 * c.frequency_error, red.valid, red.residual_max, red.growths, gr, red.basis, cpu,
           c.reduced.peak_to_peak[3], c.full.peak_to_peak[3]);
    gal_sim_result_clear(&red);
    gal_sim_setup_clear(&s);
    return 0;
}
