/* cli/bundle.c: `gallop modes SCENE` on an explicit bundle ([bundle] model = explicit): the
 * bundle's statics and modes (src/bundle/), a table on stdout, files in DIR. */
#include <stdio.h>

#include "cli.h"
#include "gallop.h"
#include "gallop/model/model.h"
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
