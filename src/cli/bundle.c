/* cli/bundle.c: `gallop modes SCENE` and `gallop simulate SCENE [--model reduced|full]` on an explicit bundle
 * ([bundle] model = explicit): the bundle's statics and modes (src/bundle/), a table on stdout,
 * files in DIR; a galloping run of the assembled bundle, trace.csv and summary.json. */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "gallop.h"
#include "gallop/model/model.h"
#include "gallop/analysis/measure.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"

int gal_cli_modes_bundle(const gal_scene *sc, const char *outdir)
{
    double t0 = gal_wall_time();
    int st;
    gal_model *m = gal_model_alloc(sc, &st);
    gal_bundle *b = NULL;
    gal_modes md = {0};
    if (!st) st = gal_bundle_solve_model(m, &b, &md);
    if (st) {
        fprintf(stderr, "gallop modes: %s\n", gal_error_message());
        gal_model_free(m);
        return gal_exit_code(st);
    }
    double wall = gal_wall_time() - t0;
    gal_bundle_report_table(stdout, sc, b, &md, m->want, wall);
    st = gal_bundle_report(outdir, sc, b, &md, m->want, wall);
    if (st) fprintf(stderr, "gallop modes: %s\n", gal_error_message());
    else printf("files: %s/{summary.json,modes.csv,shapes.csv,equilibrium.csv}\n", outdir);
    gal_modes_clear(&md);
    gal_bundle_free(b);
    gal_model_free(m);
    return gal_exit_code(st);
}

void gal_cli_bundle_mesh_warning(const gal_scene *sc, const char *cmd)
{
    gal_bundle_params bp;
    gal_bundle_params_of(sc, &bp);
    int N = gal_bundle_mesh(sc->model.elements, &bp), few = gal_bundle_subspan_elements(sc->model.elements, &bp);
    if (bp.spacers <= 0 || N <= 0 || few >= GAL_BUNDLE_SUBSPAN_ELEMENTS) return;
    fprintf(stderr, "gallop %s: warning: the explicit bundle's mesh has %d elements in its shortest sub-span "
            "(model.elements = %d, %d with %d spacers); a galloping twin turning ~100 deg p-p had its rotation "
            "17-21%% low below %d per sub-span (README \"Bundles\"): allowed: any, but for converged galloping "
            "figures model.elements ", cmd, few, sc->model.elements, N, bp.spacers, GAL_BUNDLE_SUBSPAN_ELEMENTS);
    if (bp.positions) fprintf(stderr, "that puts %d in every sub-span\n", GAL_BUNDLE_SUBSPAN_ELEMENTS);
    else fprintf(stderr, ">= %d\n", GAL_BUNDLE_SUBSPAN_ELEMENTS * (bp.spacers + 1));
}

int gal_cli_simulate_bundle(const gal_scene *sc, const char *outdir, int reduced)
{
    gal_cli_bundle_mesh_warning(sc, "simulate");
    int st;
    gal_model *m = gal_model_alloc(sc, &st);
    gal_run_opts o;
    gal_run_opts_from_scene(sc, &o);
    gal_bundle_sim_result r;
    memset(&r, 0, sizeof r);
    if (!st) st = reduced ? gal_bundle_simulate_reduced(m, &o, &r) : gal_bundle_simulate(m, &o, &r);
    gal_sim_measures ms;
    if (!st) st = gal_sim_measure(&r.c, gal_sim_mid_probe(&r.c), -1, &ms);
    if (!st) st = gal_bundle_sim_write(outdir, sc, &r);
    if (!st) {
        printf("explicit bundle of %d, %s model, %d dofs: set-up %.3f s, wall %.3f s (%.4f s per simulated s); centroid: "
               "vertical p-p %.4g m at %.4g Hz, horizontal p-p %.4g m, rotation p-p %.3g deg, steady after %.1f s\n",
               r.n, reduced ? "reduced" : "full", r.ndof, r.setup_time_s, r.c.wall_time_s, r.c.wall_time_s / r.c.time[r.c.nsamples - 1],
               ms.peak_to_peak[1], ms.frequency_hz[1], ms.peak_to_peak[0], ms.peak_to_peak[3], ms.time_to_steady_s);
        if (reduced) printf("reduced model: basis %d, self-check residual_max %.3g (%s)\n", r.c.basis, r.c.residual_max,
                            r.c.valid ? "valid" : "NOT valid");
        printf("files: %s/{trace.csv,summary.json}\n", outdir);
        if (reduced && !r.c.valid)
            fprintf(stderr, "gallop simulate: warning: the reduced model's residual reached %.3g, past "
                    "model.residual_tolerance = %.3g: its results are not checked (summary.json: valid: false)\n",
                    r.c.residual_max, sc->model.residual_tolerance);
    } else {
        fprintf(stderr, "gallop simulate: %s\n", gal_error_message());
    }
    gal_bundle_sim_result_clear(&r);
    gal_model_free(m);
    return gal_exit_code(st);
}
