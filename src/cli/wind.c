/* cli/wind.c: `gallop wind SCENE [-o DIR] [--set section.key=value]... [--points N]` (issue 4): the
 * scene's turbulent wind field as the simulations use it (windfield.h: spectral representation,
 * DESIGN.md "Wind"), its statistics at a few points along the span (analysis/windstats.h):
 * wind.csv and summary.json in DIR and a table (output/windreport.h). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>

#include "cli.h"
#include "gallop.h"
#include "gallop/scene/scene.h"
#include "gallop/loads/windfield.h"
#include "gallop/analysis/windstats.h"
#include "gallop/output/windreport.h"

static int fail(int st)
{
    fprintf(stderr, "gallop wind: %s\n", gal_error_message());
    return gal_exit_code(st);
}

int gal_cli_wind(int argc, char **argv)
{
    gal_scene sc;
    const char *outdir = NULL, *vals[1] = {NULL};
    static const char *const opts[] = {"--points", NULL};
    int rc = gal_cli_load_scene_opts(argc, argv, &sc, &outdir, opts, vals);
    if (rc) return rc;
    int np = 5;
    if (vals[0]) {
        char *end;
        errno = 0;
        long v = strtol(vals[0], &end, 10);
        if (errno || end == vals[0] || *end || v < 1 || v > GAL_WINDFIELD_POINTS) {
            fprintf(stderr, "gallop wind: --points %s; allowed: an integer from 1 to %d\n", vals[0],
                    GAL_WINDFIELD_POINTS);
            return 2;
        }
        np = (int)v;
    }
    double t0 = gal_wall_time();
    gal_wind_params wp;
    int st = gal_windfield_params(&sc, &wp);
    if (st) {
        fprintf(stderr, "gallop wind: %s: needs [wind] turbulence (kaimal, davenport or von_karman): "
                "turbulence = none has no field\n", sc.path);
        return 2;
    }
    gal_wind_params wpv;
    int vert = sc.wind.vertical_turbulence && gal_windfield_params_vertical(&sc, &wpv) == GAL_OK;
    gal_wind *w = gal_wind_alloc(&wp), *wv = vert && w ? gal_wind_alloc(&wpv) : NULL;
    if (!w || (vert && !wv)) {
        fprintf(stderr, "gallop wind: %s: [wind]: %s\n", sc.path, gal_error_message());
        gal_wind_free(w);
        return 2;
    }
    if (!sc.effect[GAL_FX_TURBULENCE])
        fprintf(stderr, "gallop wind: note: %s: [effects] turbulence = off: simulations use neither the along-wind "
                "field%s (this is the field they would use with it on)\n", sc.path, vert ? " nor the vertical one" : "");
    double tg = gal_wall_time();
    st = gal_wind_generate(w);
    if (!st && wv) st = gal_wind_generate(wv);
    double gen = gal_wall_time() - tg;
    gal_wind_stats ws, wvs;
    if (!st) st = gal_wind_stats_compute(w, wp.speed, sc.span.length, np, &ws);
    if (!st && wv) st = gal_wind_stats_compute(wv, 0.0, sc.span.length, np, &wvs);
    gal_wind_report r = {&sc, &wp, w, &ws, gen, vert ? &wpv : NULL, wv, vert ? &wvs : NULL};
    if (!st) st = gal_wind_write(outdir, &r, gal_wall_time() - t0);
    if (!st) {
        gal_wind_print(stdout, &r);
        printf("files: %s/{wind.csv,summary.json}\n", outdir);
    }
    gal_wind_free(w);
    gal_wind_free(wv);
    return st ? fail(st) : 0;
}
