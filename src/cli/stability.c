/* cli/stability.c: `gallop stability SCENE [-o DIR] [--set section.key=value]...` (issues 4, 15):
 * Den Hartog's criterion H(alpha) = dC_L/dalpha + C_D over the angle of attack of the scene's iced
 * section, and the onset wind speed U_c = -4 m zeta w / (rho d H) of each vertical mode of the
 * span where H < 0 (analysis/stability.h); then the onset of the coupled aeroelastic system about
 * the mean-wind equilibrium over [stability] speed_min to speed_max, with the structural damping
 * the dynamic models apply (analysis/onset.h). stability.csv, vg.csv and summary.json in DIR, a
 * table on stdout (output/stabreport.h). */
#include <stdio.h>
#include <stdlib.h>

#include "cli.h"
#include "gallop.h"
#include "gallop/model/model.h"
#include "gallop/modes/modes.h"
#include "gallop/run/forward.h"
#include "gallop/scene/scene.h"
#include "gallop/analysis/onset.h"
#include "gallop/analysis/stability.h"
#include "gallop/output/stabreport.h"

typedef struct {
    const gal_scene *sc;
    int nm;                                  /* vertical modes */
    double omega[GAL_STABILITY_MAX_MODES];   /* rad/s of each */
} stab;

static int fail(int st)
{
    fprintf(stderr, "gallop stability: %s\n", gal_error_message());
    return gal_exit_code(st);
}

/* The lowest vertical modes of the span about its equilibrium (as `gallop modes` finds them). */
static int vertical_modes(stab *S)
{
    const gal_scene *sc = S->sc;
    int nv = sc->model.modes_vertical;
    if (nv > (int)(sizeof S->omega / sizeof S->omega[0]))
        return gal_error(GAL_EINPUT, "%s: [model] modes_vertical = %d: allowed for stability: 0 to %d", sc->path,
                         nv, (int)(sizeof S->omega / sizeof S->omega[0]));
    S->nm = 0;
    if (nv == 0) return GAL_OK;
    gal_scene vs = *sc; /* the model of the span with its vertical modes alone selected */
    vs.model.modes_horizontal = vs.model.modes_torsional = 0;
    int st;
    gal_model *m = gal_model_alloc(&vs, &st);
    gal_data *d = m ? gal_data_alloc(m) : NULL;
    if (m && !d) st = GAL_ENOMEM;
    if (!st) st = gal_forward(m, d, GAL_STAGE_MODES);
    for (int k = 0; !st && k < d->md.n && S->nm < nv; k++)
        if (d->md.mode[k].family == GAL_FAMILY_VERTICAL && d->md.mode[k].selected) S->omega[S->nm++] = d->md.mode[k].omega;
    gal_data_free(d);
    gal_model_free(m);
    return st;
}

/* the sweep, the files and the table */
static int run(const gal_scene *sc, const gal_aero_table *t, const char *outdir, double t0)
{
    stab S = {sc, 0, {0}};
    int st = vertical_modes(&S);
    if (st) return st;
    gal_onset O;
    int explicit_bundle = sc->bundle.subconductors > 1 && sc->bundle.explicit_model;
    if ((st = explicit_bundle ? gal_bundle_scene_onset(sc, &O) : gal_scene_onset(sc, &O))) return st;
    gal_stability_params p;
    gal_stability_scene_params(sc, &p);
    p.nmodes = S.nm;
    p.omega = S.omega;
    gal_stability *R = gal_stability_sweep(t, &p);
    if (!R) {
        gal_onset_clear(&O);
        return GAL_ENOMEM;
    }
    st = gal_stability_write(outdir, sc, R, &O, gal_wall_time() - t0);
    if (!st) {
        gal_stability_print(stdout, sc, R);
        gal_onset_print(stdout, &O);
        printf("files: %s/{stability.csv,vg.csv,summary.json}\n", outdir);
    }
    gal_onset_clear(&O);
    gal_stability_free(R);
    return st;
}

int gal_cli_stability(int argc, char **argv)
{
    gal_scene sc;
    const char *outdir = NULL;
    int rc = gal_cli_load_scene(argc, argv, &sc, &outdir);
    if (rc) return rc;
    if (!sc.ice.present || !sc.ice.aero_table[0]) {
        fprintf(stderr, "gallop stability: %s: needs [ice] aero_table (and an [ice] mass_per_length): a bare "
                "conductor is a circular cylinder, H = C_D > 0, no aerodynamic instability to report\n", sc.path);
        return 2;
    }
    double t0 = gal_wall_time();
    gal_aero_table *t = gal_aero_table_load(sc.ice.aero_table);
    if (!t) {
        fprintf(stderr, "gallop stability: %s: [ice] aero_table: %s\n", sc.path, gal_error_message());
        return 2;
    }
    int st = run(&sc, t, outdir, t0);
    gal_aero_table_free(t);
    return st ? fail(st) : 0;
}
