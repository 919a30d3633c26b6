/* windreport.c: the outputs of `gallop wind` (issue 4, DESIGN.md "Wind"): wind.csv, summary.json
 * and the table on stdout. */
#include "gallop/output/windreport.h"
#include "gallop/base/core.h"
#include "gallop/output/json.h"
#include "gallop/output/outset.h"

#include <math.h>

static const char *const spectrum_names[] = {"none", "kaimal", "davenport", "von_karman", "en1991"};

static int write_csv(gal_outset *o, const gal_wind_report *r)
{
    FILE *fp = gal_outset_open(o, "wind.csv");
    if (!fp) return GAL_EIO;
    const gal_wind_stats *s = r->s, *sv = r->wv ? r->sv : NULL;
    double U = r->wp->speed, dt = gal_wind_time_step(r->w);
    fprintf(fp, "time_s");
    for (int i = 0; i < s->np; i++) fprintf(fp, ",u_x%.6gm", s->x[i]);
    for (int i = 0; sv && i < sv->np; i++) fprintf(fp, ",w_x%.6gm", sv->x[i]);
    fputc('\n', fp);
    int n = gal_wind_samples(r->w);
    for (int k = 0; k < n; k++) {
        fprintf(fp, "%.6g", k * dt);
        for (int i = 0; i < s->np; i++) fprintf(fp, ",%.9g", U + gal_wind_stats_u(r->w, s, i, k));
        for (int i = 0; sv && i < sv->np; i++) fprintf(fp, ",%.9g", gal_wind_stats_u(r->wv, sv, i, k));
        fputc('\n', fp);
    }
    return gal_outset_close(o, fp);
}

static void json_points(gal_json *j, const gal_wind_stats *s)
{
    gal_json_arr_begin(j);
    for (int i = 0; i < s->np; i++) {
        gal_json_obj_begin(j);
        gal_json_kv_int(j, "index", s->pt[i]);
        gal_json_kv_num(j, "x_m", s->x[i]);
        gal_json_kv_num(j, "mean_m_s", s->mean[i]);
        gal_json_kv_num(j, "std_m_s", s->sd[i]);
        gal_json_obj_end(j);
    }
    gal_json_arr_end(j);
}

/* the vertical component's figures (summary.json "vertical") */
static void json_vertical(gal_json *j, const gal_wind_report *r)
{
    const gal_wind_params *p = r->wpv;
    gal_json_key(j, "vertical");
    gal_json_obj_begin(j);
    gal_json_kv_num(j, "intensity", p->intensity);
    gal_json_kv_num(j, "target_sigma_m_s", p->intensity * p->speed);
    gal_json_kv_num(j, "discrete_sigma_m_s", sqrt(gal_wind_variance(r->wv)));
    gal_json_kv_num(j, "length_scale_m", gal_wind_length_scale(p));
    gal_json_kv_num(j, "coherence_decay", p->coherence_decay);
    gal_json_kv_int(j, "seed", (long)p->seed);
    gal_json_key(j, "points");
    json_points(j, r->sv);
    gal_json_obj_end(j);
}

static int write_summary(gal_outset *o, const gal_wind_report *r, double wall)
{
    const gal_scene *sc = r->sc;
    const gal_wind_params *wp = r->wp;
    const gal_wind *w = r->w;
    gal_json *j = gal_outset_summary(o);
    if (!j) return GAL_EIO;
    gal_json_kv_str(j, "command", "wind");
    gal_json_kv_str(j, "scene", sc->path);
    gal_json_kv_str(j, "spectrum", spectrum_names[sc->wind.turbulence]);
    gal_json_kv_num(j, "speed_m_s", wp->speed);
    gal_json_kv_num(j, "intensity", wp->intensity);
    gal_json_kv_num(j, "target_sigma_m_s", wp->intensity * wp->speed);
    gal_json_kv_num(j, "discrete_sigma_m_s", sqrt(gal_wind_variance(w)));
    gal_json_kv_num(j, "length_scale_m", gal_wind_length_scale(wp));
    gal_json_kv_num(j, "coherence_decay", wp->coherence_decay);
    gal_json_kv_int(j, "seed", (long)wp->seed);
    gal_json_kv_int(j, "field_points", gal_wind_points(w));
    gal_json_kv_num(j, "spacing_m", gal_wind_spacing(w));
    gal_json_kv_num(j, "time_step_s", gal_wind_time_step(w));
    gal_json_kv_int(j, "samples", gal_wind_samples(w));
    gal_json_kv_num(j, "duration_s", gal_wind_samples(w) * gal_wind_time_step(w));
    gal_json_kv_str(j, "turbulence_effect", sc->effect[GAL_FX_TURBULENCE] ? "on" : "off");
    gal_json_key(j, "points");
    json_points(j, r->s);
    gal_json_kv_str(j, "vertical_turbulence", r->wv ? "on" : "off");
    if (r->wv) json_vertical(j, r);
    gal_json_kv_num(j, "generation_wall_time_s", r->gen_time_s);
    gal_json_kv_num(j, "wall_time_s", wall);
    return GAL_OK;
}

int gal_wind_write(const char *dir, const gal_wind_report *r, double wall_time_s)
{
    gal_outset *o;
    int st = gal_outset_begin(&o, dir, "wind");
    if (!st) st = gal_outset_scene(o, r->sc);
    if (!st) st = write_csv(o, r);
    if (!st) st = write_summary(o, r, wall_time_s);
    if (!st) st = gal_outset_commit(o);
    gal_outset_free(o);
    return st;
}

static void print_table(FILE *fp, const char *c, const gal_wind_stats *s, const gal_wind_params *p)
{
    double sig = p->intensity * p->speed;
    fprintf(fp, "%10s %12s %12s %12s\n", "x m", c[0] == 'u' ? "mean m/s" : "w mean m/s", "std m/s",
            c[0] == 'u' ? "std / I U" : "std / I_w U");
    for (int i = 0; i < s->np; i++)
        fprintf(fp, "%10.4g %12.4f %12.4f %12.4f\n", s->x[i], s->mean[i], s->sd[i], sig > 0 ? s->sd[i] / sig : NAN);
}

void gal_wind_print(FILE *fp, const gal_wind_report *r)
{
    const gal_wind_params *wp = r->wp;
    const gal_wind *w = r->w;
    const gal_wind_stats *s = r->s;
    fprintf(fp, "wind field of %s: %s spectrum, U = %g m/s, I = %g (target sigma %.4g m/s, the discrete spectrum "
                "carries %.4g m/s), C = %g, seed %lu\n", r->sc->path, spectrum_names[r->sc->wind.turbulence],
            wp->speed, wp->intensity, wp->intensity * wp->speed, sqrt(gal_wind_variance(w)), wp->coherence_decay,
            wp->seed);
    fprintf(fp, "%d points %.4g m apart, %d samples at %g s (%.4g s); generated in %.3f s\n", gal_wind_points(w),
            gal_wind_spacing(w), gal_wind_samples(w), gal_wind_time_step(w),
            gal_wind_samples(w) * gal_wind_time_step(w), r->gen_time_s);
    print_table(fp, "u", s, wp);
    if (r->wv) {
        fprintf(fp, "vertical w: I_w = %g (target sigma %.4g m/s, the discrete spectrum carries %.4g m/s), "
                    "L_w = %.4g m, C = %g, seed %lu\n", r->wpv->intensity, r->wpv->intensity * r->wpv->speed,
                sqrt(gal_wind_variance(r->wv)), gal_wind_length_scale(r->wpv), r->wpv->coherence_decay,
                r->wpv->seed);
        print_table(fp, "w", r->sv, r->wpv);
    }
}
