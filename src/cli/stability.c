/* cli/stability.c: `gallop stability SCENE [-o DIR] [--set section.key=value]...` (issue 4): Den
 * Hartog's criterion H(alpha) = dC_L/dalpha + C_D over the angle of attack of the scene's iced
 * section, and the onset wind speed U_c = -4 m zeta w / (rho d H) of each vertical mode of the
 * span where H < 0 (stability.h). stability.csv and summary.json in DIR, a table on stdout. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cli.h"
#include "gallop.h"
#include "gallop/model/model.h"
#include "gallop/modes/modes.h"
#include "gallop/scene/scene.h"
#include "gallop/analysis/stability.h"
#include "gallop/statics/statics.h"

#define NALPHA 361 /* -180 .. 180 deg in 1-deg steps */
#define DEG (GAL_PI / 180)

typedef struct {
    double alpha_deg, c[3], dcl, h; /* coefficients, dC_L/dalpha (per rad), Den Hartog H */
    double *onset;                  /* m/s per vertical mode; INFINITY where H >= 0 */
} row;

typedef struct {
    const gal_scene *sc;
    const gal_aero_table *t;
    double mass, zeta, rho, diam;   /* kg/m, -, kg/m^3, m */
    int nm;                         /* vertical modes */
    double omega[64];               /* rad/s of each */
    row r[NALPHA];
    int imin;                       /* row of the lowest H */
    double h_rest;                  /* H at the attack angle */
    double wall;
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
    gal_rod_params p;
    gal_statics_spec spec;
    double value;
    int st = gal_model_rod_params(sc, &p, &spec, &value);
    if (st) return st;
    gal_equilibrium eq;
    if ((st = gal_statics_solve(&p, spec, value, NULL, &eq)))
        return gal_error(st, "%s: no equilibrium: %s", sc->path, gal_error_message());
    int want[GAL_FAMILY_COUNT] = {nv, 0, 0, 0};
    gal_modes md;
    st = gal_modes_find(eq.rod, eq.q, want, 1000, &md);
    if (st) {
        gal_equilibrium_clear(&eq);
        return gal_error(st, "%s: modes: %s", sc->path, gal_error_message());
    }
    for (int k = 0; k < md.n && S->nm < nv; k++)
        if (md.mode[k].family == GAL_FAMILY_VERTICAL && md.mode[k].selected) S->omega[S->nm++] = md.mode[k].omega;
    gal_modes_clear(&md);
    gal_equilibrium_clear(&eq);
    return GAL_OK;
}

/* ---- outputs ---- */

static void csv_num(FILE *fp, double v)
{
    if (isfinite(v)) fprintf(fp, ",%.10g", v);
    else fputc(',', fp); /* inf (stable at any speed): empty field */
}

static int write_csv(const stab *S, const char *dir)
{
    gal_ofile f;
    int st = gal_ofile_open_in(&f, dir, "stability.csv");
    if (st) return st;
    fprintf(f.fp, "alpha_deg,cd,cl,cm,dcl_dalpha,den_hartog");
    for (int m = 0; m < S->nm; m++) fprintf(f.fp, ",onset_speed_mode%d_m_s", m + 1);
    fputc('\n', f.fp);
    for (int i = 0; i < NALPHA; i++) {
        const row *r = S->r + i;
        fprintf(f.fp, "%g", r->alpha_deg);
        for (int c = 0; c < 3; c++) csv_num(f.fp, r->c[c]);
        csv_num(f.fp, r->dcl);
        csv_num(f.fp, r->h);
        for (int m = 0; m < S->nm; m++) csv_num(f.fp, r->onset[m]);
        fputc('\n', f.fp);
    }
    return gal_ofile_close(&f, 1);
}

/* Runs of consecutive grid angles where H < 0: [from, to] in degrees (both ends have H < 0). */
static void unstable_ranges(const stab *S, gal_json *j)
{
    gal_json_arr_begin(j);
    for (int i = 0; i < NALPHA; i++) {
        if (!(S->r[i].h < 0)) continue;
        int e = i;
        while (e + 1 < NALPHA && S->r[e + 1].h < 0) e++;
        gal_json_arr_begin(j);
        gal_json_num(j, S->r[i].alpha_deg);
        gal_json_num(j, S->r[e].alpha_deg);
        gal_json_arr_end(j);
        i = e;
    }
    gal_json_arr_end(j);
}

static int write_summary(const stab *S, const char *dir)
{
    const gal_scene *sc = S->sc;
    gal_ofile f;
    int st = gal_ofile_open_in(&f, dir, "summary.json");
    if (st) return st;
    gal_json j;
    gal_json_begin(&j, f.fp);
    gal_json_kv_str(&j, "command", "stability");
    gal_json_kv_str(&j, "scene", sc->path);
    gal_json_kv_str(&j, "table", S->t->path);
    gal_json_kv_str(&j, "table_source", S->t->source);
    gal_json_kv_num(&j, "attack_angle_deg", sc->ice.attack_angle / DEG);
    gal_json_kv_num(&j, "den_hartog_at_rest", S->h_rest);
    gal_json_key(&j, "unstable_ranges_deg");
    unstable_ranges(S, &j);
    gal_json_kv_num(&j, "min_den_hartog", S->r[S->imin].h);
    gal_json_kv_num(&j, "min_den_hartog_alpha_deg", S->r[S->imin].alpha_deg);
    gal_json_kv_num(&j, "mass_per_length_kg_m", S->mass);
    gal_json_kv_num(&j, "damping_ratio", S->zeta);
    gal_json_kv_num(&j, "air_density_kg_m3", S->rho);
    gal_json_kv_num(&j, "diameter_m", S->diam);
    gal_json_key(&j, "modes");
    gal_json_arr_begin(&j);
    const row *lo = S->r + S->imin; /* U_c ~ 1/(-H): every mode's lowest onset is at the lowest H */
    for (int m = 0; m < S->nm; m++) {
        gal_json_obj_begin(&j);
        gal_json_kv_int(&j, "index", m + 1);
        gal_json_kv_num(&j, "frequency_hz", S->omega[m] / (2 * GAL_PI));
        gal_json_kv_num(&j, "onset_speed_at_rest_m_s",
                        gal_stability_onset(S->t, sc->ice.attack_angle, S->mass, S->zeta, S->omega[m], S->rho, S->diam));
        gal_json_kv_num(&j, "lowest_onset_speed_m_s", lo->onset[m]);
        gal_json_kv_num(&j, "at_alpha_deg", lo->h < 0 ? lo->alpha_deg : NAN);
        gal_json_obj_end(&j);
    }
    gal_json_arr_end(&j);
    gal_json_kv_num(&j, "wall_time_s", S->wall);
    gal_json_end(&j);
    return gal_ofile_close(&f, 1);
}

static void print_onset(double u)
{
    if (isfinite(u)) printf(" %9.3g", u);
    else printf(" %9s", "-");
}

static void print_table(const stab *S)
{
    const gal_scene *sc = S->sc;
    printf("Den Hartog criterion H = dC_L/dalpha + C_D (per rad) for %s\n", sc->path);
    printf("table %s\n", S->t->path);
    printf("m = %.4g kg/m, zeta = %.4g, rho = %.4g kg/m^3, d = %.4g m\n", S->mass, S->zeta, S->rho, S->diam);
    printf("%6s %7s %7s %7s %9s %9s", "alpha", "C_D", "C_L", "C_M", "dC_L/da", "H");
    for (int m = 0; m < S->nm; m++) printf("  U_c%d m/s", m + 1);
    printf("\n");
    for (int i = 0; i < NALPHA; i += 10) {
        const row *r = S->r + i;
        printf("%6g %7.3f %7.3f %7.3f %9.3f %9.3f", r->alpha_deg, r->c[0], r->c[1], r->c[2], r->dcl, r->h);
        for (int m = 0; m < S->nm; m++) print_onset(r->onset[m]);
        printf("%s\n", r->h < 0 ? "  unstable" : "");
    }
    printf("(every 10 deg; stability.csv has every degree)\n");
    printf("attack angle at rest %g deg: H = %.4g (%s)\n", sc->ice.attack_angle / DEG, S->h_rest,
           S->h_rest < 0 ? "Den Hartog unstable" : "stable");
    printf("unstable (H < 0):");
    int any = 0;
    for (int i = 0; i < NALPHA; i++) {
        if (!(S->r[i].h < 0)) continue;
        int e = i;
        while (e + 1 < NALPHA && S->r[e + 1].h < 0) e++;
        printf(" [%g, %g]", S->r[i].alpha_deg, S->r[e].alpha_deg);
        any = 1, i = e;
    }
    printf("%s deg\n", any ? "" : " none,");
    printf("lowest H = %.4g at %g deg\n", S->r[S->imin].h, S->r[S->imin].alpha_deg);
    const row *lo = S->r + S->imin;
    for (int m = 0; m < S->nm; m++) {
        double u0 = gal_stability_onset(S->t, sc->ice.attack_angle, S->mass, S->zeta, S->omega[m], S->rho, S->diam);
        printf("vertical mode %d: %.4f Hz, onset at rest", m + 1, S->omega[m] / (2 * GAL_PI));
        if (isfinite(u0)) printf(" %.3g m/s", u0);
        else printf(" none (H >= 0)");
        if (lo->h < 0) printf(", lowest onset %.3g m/s at %g deg\n", lo->onset[m], lo->alpha_deg);
        else printf(", stable at every angle\n");
    }
    if (S->zeta == 0 && any && S->nm > 0)
        printf("no structural damping: the onset speed is 0 wherever H < 0: any wind gallops there\n");
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
    stab *S = calloc(1, sizeof *S);
    if (!S) { fprintf(stderr, "gallop stability: out of memory\n"); return 1; }
    S->sc = &sc;
    gal_aero_table *t = gal_aero_table_load(sc.ice.aero_table);
    if (!t) {
        fprintf(stderr, "gallop stability: %s: [ice] aero_table: %s\n", sc.path, gal_error_message());
        free(S);
        return 2;
    }
    S->t = t;
    int st = vertical_modes(S);
    double *onset = st ? NULL : malloc((size_t)NALPHA * (S->nm > 0 ? S->nm : 1) * sizeof *onset);
    if (!st && !onset) st = gal_error(GAL_ENOMEM, "out of memory");
    if (!st) {
        S->mass = sc.conductor.mass_per_length + sc.ice.mass_per_length;
        /* the structural damping the runs use: none when the damping effect is off */
        S->zeta = sc.effect[GAL_FX_DAMPING] ? sc.conductor.damping_ratio : 0.0;
        S->rho = sc.wind.air_density;
        S->diam = sc.conductor.diameter;
        S->h_rest = gal_aero_den_hartog(t, sc.ice.attack_angle);
        for (int i = 0; i < NALPHA; i++) {
            row *r = S->r + i;
            double dc[3], a;
            r->alpha_deg = -180 + i;
            a = r->alpha_deg * DEG;
            gal_aero_eval(t, a, r->c, dc);
            r->dcl = dc[1];
            r->h = gal_aero_den_hartog(t, a);
            r->onset = onset + (size_t)i * (S->nm > 0 ? S->nm : 1);
            for (int m = 0; m < S->nm; m++)
                r->onset[m] = gal_stability_onset(t, a, S->mass, S->zeta, S->omega[m], S->rho, S->diam);
            if (r->h < S->r[S->imin].h) S->imin = i;
        }
        S->wall = gal_wall_time() - t0;
        st = gal_mkdirs(outdir);
        if (!st) st = write_csv(S, outdir);
        if (!st) st = write_summary(S, outdir);
    }
    if (!st) {
        print_table(S);
        printf("files: %s/{stability.csv,summary.json}\n", outdir);
    }
    rc = st ? fail(st) : 0;
    free(onset);
    gal_aero_table_free(t);
    free(S);
    return rc;
}
