/* cli/modes.c: `gallop modes SCENE [-o DIR] [--set section.key=value]...`: statics and modes, a
 * table on stdout, files in DIR (DESIGN.md "Command line"). */
#include <stdio.h>

#include "cli.h"
#include "gallop.h"
#include "gallop/model/model.h"
#include "gallop/modes/modes.h"
#include "gallop/output/report.h"
#include "gallop/scene/scene.h"
#include "gallop/statics/statics.h"

int gal_cli_modes(int argc, char **argv)
{
    gal_scene sc;
    const char *outdir = NULL;
    int rc = gal_cli_load_scene(argc, argv, &sc, &outdir);
    if (rc) return rc;
    double t0 = gal_wall_time();
    gal_rod_params p;
    gal_statics_spec spec;
    double value;
    int st = gal_model_rod_params(&sc, &p, &spec, &value);
    if (st) {
        fprintf(stderr, "gallop modes: %s\n", gal_error_message());
        return gal_exit_code(st);
    }
    gal_equilibrium eq;
    st = gal_statics_solve(&p, spec, value, NULL, &eq);
    if (st) {
        fprintf(stderr, "gallop modes: %s: no equilibrium: %s\n", sc.path, gal_error_message());
        return gal_exit_code(st);
    }
    int want[GAL_FAMILY_COUNT] = {sc.model.modes_vertical, sc.model.modes_horizontal,
                                  sc.effect[GAL_FX_TORSION] ? sc.model.modes_torsional : 0, 0};
    gal_modes md;
    int total = want[0] + want[1] + want[2];
    if (total == 0) {
        fprintf(stderr, "gallop modes: %s: [model] asks for no modes\n", sc.path);
        gal_equilibrium_clear(&eq);
        return 2;
    }
    st = gal_modes_find(eq.rod, eq.q, want, 1000, &md);
    if (st) {
        fprintf(stderr, "gallop modes: %s: %s\n", sc.path, gal_error_message());
        gal_equilibrium_clear(&eq);
        return gal_exit_code(st);
    }
    double wall = gal_wall_time() - t0;
    gal_report_modes_table(stdout, &sc, &eq, &md, want, wall);
    st = gal_report_modes(outdir, &sc, &eq, &md, want, wall);
    if (st) fprintf(stderr, "gallop modes: %s\n", gal_error_message());
    else printf("files: %s/{summary.json,modes.csv,shapes.csv,equilibrium.csv}\n", outdir);
    gal_modes_clear(&md);
    gal_equilibrium_clear(&eq);
    return gal_exit_code(st);
}
