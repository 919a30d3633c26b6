/* stabreport.c: the outputs of `gallop stability` (issue 4): stability.csv, summary.json and the
 * table on stdout. */
#include "gallop/output/stabreport.h"
#include "gallop/base/core.h"
#include "gallop/output/json.h"
#include "gallop/output/outset.h"

#include <math.h>

#define DEG (GAL_PI / 180)

static void csv_num(FILE *fp, double v)
{
    if (isfinite(v)) fprintf(fp, ",%.10g", v);
    else fputc(',', fp); /* inf (stable at any speed): empty field */
}

static int write_csv(const gal_stability *S, gal_outset *o)
{
    FILE *fp = gal_outset_open(o, "stability.csv");
    if (!fp) return GAL_EIO;
    fprintf(fp, "alpha_deg,cd,cl,cm,dcl_dalpha,den_hartog");
    for (int m = 0; m < S->p.nmodes; m++) fprintf(fp, ",onset_speed_mode%d_m_s", m + 1);
    fputc('\n', fp);
    for (int i = 0; i < GAL_STABILITY_NALPHA; i++) {
        const gal_stability_row *r = S->r + i;
        fprintf(fp, "%g", r->alpha_deg);
        for (int c = 0; c < 3; c++) csv_num(fp, r->c[c]);
        csv_num(fp, r->dcl);
        csv_num(fp, r->h);
        for (int m = 0; m < S->p.nmodes; m++) csv_num(fp, r->onset[m]);
        fputc('\n', fp);
    }
    return gal_outset_close(o, fp);
}

/* [from, to] in degrees of each run of grid angles where H < 0 */
static void json_ranges(const gal_stability *S, gal_json *j)
{
    gal_json_arr_begin(j);
    for (int k = 0; k < S->nranges; k++) {
        gal_json_arr_begin(j);
        gal_json_num(j, S->range[k][0]);
        gal_json_num(j, S->range[k][1]);
        gal_json_arr_end(j);
    }
    gal_json_arr_end(j);
}

static void json_modes(const gal_stability *S, gal_json *j)
{
    const gal_stability_row *lo = S->r + S->imin; /* U_c ~ 1/(-H): every mode's lowest onset is at the lowest H */
    gal_json_arr_begin(j);
    for (int m = 0; m < S->p.nmodes; m++) {
        gal_json_obj_begin(j);
        gal_json_kv_int(j, "index", m + 1);
        gal_json_kv_num(j, "frequency_hz", S->omega[m] / (2 * GAL_PI));
        gal_json_kv_num(j, "onset_speed_at_rest_m_s", S->onset_rest[m]);
        gal_json_kv_num(j, "lowest_onset_speed_m_s", lo->onset[m]);
        gal_json_kv_num(j, "at_alpha_deg", lo->h < 0 ? lo->alpha_deg : NAN);
        gal_json_obj_end(j);
    }
    gal_json_arr_end(j);
}

static int write_summary(const gal_stability *S, const gal_onset *O, const gal_scene *sc, gal_outset *o, double wall)
{
    gal_json *j = gal_outset_summary(o);
    if (!j) return GAL_EIO;
    gal_json_kv_str(j, "command", "stability");
    gal_json_kv_str(j, "scene", sc->path);
    gal_json_kv_str(j, "table", S->t->path);
    gal_json_kv_str(j, "table_source", S->t->source);
    gal_json_kv_num(j, "attack_angle_deg", S->p.attack_angle / DEG);
    gal_json_kv_num(j, "den_hartog_at_rest", S->h_rest);
    gal_json_key(j, "unstable_ranges_deg");
    json_ranges(S, j);
    gal_json_kv_num(j, "min_den_hartog", S->r[S->imin].h);
    gal_json_kv_num(j, "min_den_hartog_alpha_deg", S->r[S->imin].alpha_deg);
    gal_json_kv_num(j, "mass_per_length_kg_m", S->p.mass);
    gal_json_kv_num(j, "damping_ratio", S->p.zeta);
    gal_json_kv_num(j, "air_density_kg_m3", S->p.rho);
    gal_json_kv_num(j, "diameter_m", S->p.diam);
    gal_json_key(j, "modes");
    json_modes(S, j);
    if (O) gal_onset_write_json(O, j);
    gal_json_kv_num(j, "wall_time_s", wall);
    return GAL_OK;
}

int gal_stability_write(const char *dir, const gal_scene *sc, const gal_stability *S, const gal_onset *O,
                        double wall_time_s)
{
    gal_outset *o;
    int st = gal_outset_begin(&o, dir, "stability");
    if (!st) st = gal_outset_scene(o, sc);
    if (!st) st = write_csv(S, o);
    if (!st && O) st = gal_onset_write_csv(O, o);
    if (!st) st = write_summary(S, O, sc, o, wall_time_s);
    if (!st) st = gal_outset_commit(o);
    gal_outset_free(o);
    return st;
}

static void print_onset(FILE *fp, double u)
{
    if (isfinite(u)) fprintf(fp, " %9.3g", u);
    else fprintf(fp, " %9s", "-");
}

/* the coefficients every 10 deg */
static void print_rows(FILE *fp, const gal_stability *S)
{
    fprintf(fp, "%6s %7s %7s %7s %9s %9s", "alpha", "C_D", "C_L", "C_M", "dC_L/da", "H");
    for (int m = 0; m < S->p.nmodes; m++) fprintf(fp, "  U_c%d m/s", m + 1);
    fprintf(fp, "\n");
    for (int i = 0; i < GAL_STABILITY_NALPHA; i += 10) {
        const gal_stability_row *r = S->r + i;
        fprintf(fp, "%6g %7.3f %7.3f %7.3f %9.3f %9.3f", r->alpha_deg, r->c[0], r->c[1], r->c[2], r->dcl, r->h);
        for (int m = 0; m < S->p.nmodes; m++) print_onset(fp, r->onset[m]);
        fprintf(fp, "%s\n", r->h < 0 ? "  unstable" : "");
    }
    fprintf(fp, "(every 10 deg; stability.csv has every degree)\n");
}

void gal_stability_print(FILE *fp, const gal_scene *sc, const gal_stability *S)
{
    fprintf(fp, "Den Hartog criterion H = dC_L/dalpha + C_D (per rad) for %s\n", sc->path);
    fprintf(fp, "table %s\n", S->t->path);
    fprintf(fp, "m = %.4g kg/m, zeta = %.4g, rho = %.4g kg/m^3, d = %.4g m\n", S->p.mass, S->p.zeta, S->p.rho,
            S->p.diam);
    print_rows(fp, S);
    fprintf(fp, "attack angle at rest %g deg: H = %.4g (%s)\n", S->p.attack_angle / DEG, S->h_rest,
            S->h_rest < 0 ? "Den Hartog unstable" : "stable");
    fprintf(fp, "unstable (H < 0):");
    for (int k = 0; k < S->nranges; k++) fprintf(fp, " [%g, %g]", S->range[k][0], S->range[k][1]);
    fprintf(fp, "%s deg\n", S->nranges > 0 ? "" : " none,");
    fprintf(fp, "lowest H = %.4g at %g deg\n", S->r[S->imin].h, S->r[S->imin].alpha_deg);
    const gal_stability_row *lo = S->r + S->imin;
    for (int m = 0; m < S->p.nmodes; m++) {
        double u0 = S->onset_rest[m];
        fprintf(fp, "vertical mode %d: %.4f Hz, onset at rest", m + 1, S->omega[m] / (2 * GAL_PI));
        if (isfinite(u0)) fprintf(fp, " %.3g m/s", u0);
        else fprintf(fp, " none (H >= 0)");
        if (lo->h < 0) fprintf(fp, ", lowest onset %.3g m/s at %g deg\n", lo->onset[m], lo->alpha_deg);
        else fprintf(fp, ", stable at every angle\n");
    }
    if (S->p.zeta == 0 && S->nranges > 0 && S->p.nmodes > 0)
        fprintf(fp, "no structural damping: the onset speed is 0 wherever H < 0: any wind gallops there\n");
}
