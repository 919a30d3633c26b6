/* cli/bundle_compare.c: `gallop compare SCENE` on an explicit bundle ([bundle] model = explicit):
 * the full and the reduced model of the assembled bundle on the same statics, modes, damping and
 * loads (bundle_rom.h), compare.csv and summary.json per sub-conductor; the full model's results
 * written alone (trace.csv, summary.json; exit 1) when the reduced model fails. */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "gallop.h"
#include "gallop/model/model.h"
#include "gallop/output/simreport.h"
#include "gallop/scene/scene.h"

static void print_run(const char *label, const gal_bundle_sim_result *r, const gal_sim_measures *m)
{
    const gal_sim_result *c = &r->c;
    printf("%-8s wall %8.3f s (%.4f s per simulated s)  centroid: vertical p-p %.4g m at %.4g Hz, horizontal p-p "
           "%.4g m, rotation p-p %.3g deg\n", label, c->wall_time_s, c->wall_time_s / c->time[c->nsamples - 1],
           m->peak_to_peak[1], m->frequency_hz[1], m->peak_to_peak[0], m->peak_to_peak[3]);
}

/* The full model's results alone, when the reduced model failed; exit 1. */
static int full_only(const char *outdir, const gal_scene *sc, const gal_bundle_sim_result *full)
{
    char why[1024];
    snprintf(why, sizeof why, "%s", gal_error_message());
    int st = gal_bundle_sim_write(outdir, sc, full);
    if (st) {
        fprintf(stderr, "gallop compare: %s\n", gal_error_message());
        return gal_exit_code(st);
    }
    fprintf(stderr, "gallop compare: the reduced model failed: %s\ngallop compare: the full model's results are "
            "written alone: %s/{trace.csv,summary.json}\n", why, outdir);
    return 1;
}

static int report(const char *outdir, const gal_scene *sc, const gal_bundle_sim_result *F,
                  const gal_bundle_sim_result *R)
{
    gal_compare_figures c;
    int st = gal_bundle_write_compare(outdir, sc, F, R, &c);
    if (st) return st;
    printf("explicit bundle of %d, %d dofs; reduced basis %d, self-check residual_max %.3g (%s)\n", F->n, F->ndof,
           R->c.basis, R->c.residual_max, R->c.valid ? "valid" : "NOT valid");
    print_run("full", F, &c.full);
    print_run("reduced", R, &c.reduced);
    gal_cli_print_compare(&c, "rotation", R->c.build_time_s);
    printf("files: %s/{compare.csv,summary.json}\n", outdir);
    if (!R->c.valid)
        fprintf(stderr, "gallop compare: warning: the reduced model's residual reached %.3g, past "
                "model.residual_tolerance = %.3g: its results are not checked (summary.json: valid: false)\n",
                R->c.residual_max, sc->model.residual_tolerance);
    return GAL_OK;
}

int gal_cli_compare_bundle(const gal_scene *sc, const char *outdir)
{
    gal_cli_bundle_mesh_warning(sc, "compare");
    int st, rc = 0;
    gal_model *m = gal_model_alloc(sc, &st);
    gal_run_opts o;
    gal_run_opts_from_scene(sc, &o);
    gal_bundle_sim_result F, R;
    memset(&F, 0, sizeof F);
    memset(&R, 0, sizeof R);
    if (!st) st = gal_bundle_simulate(m, &o, &F);
    if (!st && gal_bundle_simulate_reduced(m, &o, &R) != GAL_OK) {
        rc = full_only(outdir, sc, &F);
    } else if (!st) {
        st = report(outdir, sc, &F, &R);
    }
    if (st) {
        fprintf(stderr, "gallop compare: %s\n", gal_error_message());
        rc = gal_exit_code(st);
    }
    gal_bundle_sim_result_clear(&F);
    gal_bundle_sim_result_clear(&R);
    gal_model_free(m);
    return rc;
}
