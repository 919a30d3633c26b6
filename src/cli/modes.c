/* cli/modes.c: `gallop modes SCENE [-o DIR] [--set section.key=value]...`: the pipeline to the
 * modes (statics and modes), a table on stdout, files in DIR (DESIGN.md "Command line"). */
#include <stdio.h>

#include "cli.h"
#include "gallop.h"
#include "gallop/model/model.h"
#include "gallop/output/report.h"
#include "gallop/run/forward.h"
#include "gallop/scene/scene.h"

int gal_cli_modes(int argc, char **argv)
{
    gal_scene sc;
    const char *outdir = NULL;
    int rc = gal_cli_load_scene(argc, argv, &sc, &outdir);
    if (rc) return rc;
    if (sc.bundle.subconductors > 1 && sc.bundle.explicit_model) return gal_cli_modes_bundle(&sc, outdir);
    double t0 = gal_wall_time();
    int st;
    gal_model *m = gal_model_alloc(&sc, &st);
    gal_data *d = m ? gal_data_alloc(m) : NULL;
    if (m && !d) st = GAL_ENOMEM;
    if (!st) st = gal_forward(m, d, GAL_STAGE_MODES);
    if (st) {
        fprintf(stderr, "gallop modes: %s\n", gal_error_message());
        gal_data_free(d);
        gal_model_free(m);
        return gal_exit_code(st);
    }
    double wall = gal_wall_time() - t0;
    gal_report_modes_table(stdout, &sc, &d->eq, &d->md, m->want, wall);
    st = gal_report_modes(outdir, &sc, &d->eq, &d->md, m->want, wall);
    if (st) fprintf(stderr, "gallop modes: %s\n", gal_error_message());
    else printf("files: %s/{summary.json,modes.csv,shapes.csv,equilibrium.csv}\n", outdir);
    gal_data_free(d);
    gal_model_free(m);
    return gal_exit_code(st);
}
