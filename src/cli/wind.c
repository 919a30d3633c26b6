/* cli/wind.c: `gallop wind SCENE [-o DIR] [--set section.key=value]... [--points N]` (issue 4): the
 * scene's turbulent wind field as the simulations use it (windfield.h: spectral representation,
 * DESIGN.md "Wind"): wind.csv (U + u at a few points along the span) and summary.json in DIR. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cli.h"
#include "gallop.h"
#include "gallop/scene/scene.h"
#include "gallop/loads/windfield.h"

static const char *const spectrum_names[] = {"none", "kaimal", "davenport", "von_karman"};

static int fail(int st)
{
    fprintf(stderr, "gallop wind: %s\n", gal_error_message());
    return gal_exit_code(st);
}

/* Mean and (population) standard deviation of U + u over the whole record at point j. */
static void moments(const gal_wind *w, int j, double U, double *mean, double *sd)
{
    const double *u = gal_wind_history(w, j);
    int n = gal_wind_samples(w);
    double s = 0, s2 = 0;
    for (int k = 0; k < n; k++) s += u[k];
    double mu = s / n;
    for (int k = 0; k < n; k++) s2 += (u[k] - mu) * (u[k] - mu); /* two passes: no cancellation */
    *mean = U + mu;
    *sd = sqrt(s2 / n);
}

static int write_csv(const char *dir, const gal_wind *w, double U, const int *pt, int np)
{
    gal_ofile f;
    int st = gal_ofile_open_in(&f, dir, "wind.csv");
    if (st) return st;
    double dx = gal_wind_spacing(w), dt = gal_wind_time_step(w);
    fprintf(f.fp, "time_s");
    for (int i = 0; i < np; i++) fprintf(f.fp, ",u_x%.6gm", pt[i] * dx);
    fputc('\n', f.fp);
    int n = gal_wind_samples(w);
    for (int k = 0; k < n; k++) {
        fprintf(f.fp, "%.6g", k * dt);
        for (int i = 0; i < np; i++) fprintf(f.fp, ",%.9g", U + gal_wind_u(w, pt[i], k));
        fputc('\n', f.fp);
    }
    return gal_ofile_close(&f, 1);
}

static int write_summary(const char *dir, const gal_scene *sc, const gal_wind_params *wp, const gal_wind *w,
                         const int *pt, int np, const double *mean, const double *sd, double gen, double wall)
{
    gal_ofile f;
    int st = gal_ofile_open_in(&f, dir, "summary.json");
    if (st) return st;
    gal_json j;
    gal_json_begin(&j, f.fp);
    gal_json_kv_str(&j, "command", "wind");
    gal_json_kv_str(&j, "scene", sc->path);
    gal_json_kv_str(&j, "spectrum", spectrum_names[sc->wind.turbulence]);
    gal_json_kv_num(&j, "speed_m_s", wp->speed);
    gal_json_kv_num(&j, "intensity", wp->intensity);
    gal_json_kv_num(&j, "target_sigma_m_s", wp->intensity * wp->speed);
    gal_json_kv_num(&j, "discrete_sigma_m_s", sqrt(gal_wind_variance(w)));
    gal_json_kv_num(&j, "length_scale_m", gal_wind_length_scale(wp));
    gal_json_kv_num(&j, "coherence_decay", wp->coherence_decay);
    gal_json_kv_int(&j, "seed", (long)wp->seed);
    gal_json_kv_int(&j, "field_points", gal_wind_points(w));
    gal_json_kv_num(&j, "spacing_m", gal_wind_spacing(w));
    gal_json_kv_num(&j, "time_step_s", gal_wind_time_step(w));
    gal_json_kv_int(&j, "samples", gal_wind_samples(w));
    gal_json_kv_num(&j, "duration_s", gal_wind_samples(w) * gal_wind_time_step(w));
    gal_json_kv_str(&j, "turbulence_effect", sc->effect[GAL_FX_TURBULENCE] ? "on" : "off");
    gal_json_key(&j, "points");
    gal_json_arr_begin(&j);
    for (int i = 0; i < np; i++) {
        gal_json_obj_begin(&j);
        gal_json_kv_int(&j, "index", pt[i]);
        gal_json_kv_num(&j, "x_m", pt[i] * gal_wind_spacing(w));
        gal_json_kv_num(&j, "mean_m_s", mean[i]);
        gal_json_kv_num(&j, "std_m_s", sd[i]);
        gal_json_obj_end(&j);
    }
    gal_json_arr_end(&j);
    gal_json_kv_num(&j, "generation_wall_time_s", gen);
    gal_json_kv_num(&j, "wall_time_s", wall);
    gal_json_end(&j);
    return gal_ofile_close(&f, 1);
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
    gal_wind *w = gal_wind_alloc(&wp);
    if (!w) {
        fprintf(stderr, "gallop wind: %s: [wind]: %s\n", sc.path, gal_error_message());
        return 2;
    }
    double tg = gal_wall_time();
    st = gal_wind_generate(w);
    double gen = gal_wall_time() - tg;
    /* the written points: N evenly spaced over the field's points (the nearest), or mid-span alone */
    int pt[GAL_WINDFIELD_POINTS], last = gal_wind_points(w) - 1;
    double mean[GAL_WINDFIELD_POINTS], sd[GAL_WINDFIELD_POINTS];
    for (int i = 0; i < np; i++) pt[i] = np == 1 ? last / 2 : (int)lround((double)i * last / (np - 1));
    for (int i = 0; i < np && !st; i++) moments(w, pt[i], wp.speed, mean + i, sd + i);
    if (!st) st = gal_mkdirs(outdir);
    if (!st) st = write_csv(outdir, w, wp.speed, pt, np);
    if (!st) st = write_summary(outdir, &sc, &wp, w, pt, np, mean, sd, gen, gal_wall_time() - t0);
    if (!st) {
        printf("wind field of %s: %s spectrum, U = %g m/s, I = %g (target sigma %.4g m/s, the discrete spectrum "
               "carries %.4g m/s), C = %g, seed %lu\n", sc.path, spectrum_names[sc.wind.turbulence], wp.speed,
               wp.intensity, wp.intensity * wp.speed, sqrt(gal_wind_variance(w)), wp.coherence_decay, wp.seed);
        printf("%d points %.4g m apart, %d samples at %g s (%.4g s); generated in %.3f s\n", gal_wind_points(w),
               gal_wind_spacing(w), gal_wind_samples(w), gal_wind_time_step(w),
               gal_wind_samples(w) * gal_wind_time_step(w), gen);
        printf("%10s %12s %12s %12s\n", "x m", "mean m/s", "std m/s", "std / I U");
        for (int i = 0; i < np; i++)
            printf("%10.4g %12.4f %12.4f %12.4f\n", pt[i] * gal_wind_spacing(w), mean[i], sd[i],
                   wp.intensity * wp.speed > 0 ? sd[i] / (wp.intensity * wp.speed) : NAN);
        printf("files: %s/{wind.csv,summary.json}\n", outdir);
    }
    gal_wind_free(w);
    return st ? fail(st) : 0;
}
