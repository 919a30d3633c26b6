/* onsetreport.c: the coupled onset analysis in the outputs of `gallop stability` (issue 15): vg.csv
 * (the V-g and V-f table), its figures in summary.json, and its lines on stdout. */
#include "gallop/output/stabreport.h"
#include "gallop/base/core.h"
#include "gallop/output/json.h"

#include <math.h>

static void csv_num(FILE *fp, double v)
{
    if (isfinite(v)) fprintf(fp, ",%.10g", v);
    else fputc(',', fp); /* none (stable, no solution): empty field */
}

int gal_onset_write_csv(const gal_onset *O, gal_outset *o)
{
    FILE *fp = gal_outset_open(o, "vg.csv");
    if (!fp) return GAL_EIO;
    fprintf(fp, "# per wind speed: the mean-wind equilibrium at mid-span, the classic criteria there (Den Hartog"
                " with the applied damping, Nigol), and each followed aeroelastic mode's frequency and damping ratio\n");
    fprintf(fp, "speed_m_s,static_ok,fold,swing_deg,twist_deg,alpha_deg,den_hartog,den_hartog_onset_m_s,"
                "zeta_vertical,nigol_dcm_dalpha,kt_min_rad2_s2,divergence_linear_m_s,zeta_torsional,nigol_onset_m_s");
    for (int k = 0; k < O->nmodes; k++) fprintf(fp, ",f%d_hz,zeta%d", k + 1, k + 1);
    fputc('\n', fp);
    for (int i = 0; i < O->nspeed; i++) {
        const gal_onset_speed *s = O->sp + i;
        fprintf(fp, "%.10g,%d,%d", s->speed, s->ok, s->fold);
        double v[] = {s->swing_deg, s->twist_deg, s->alpha_deg, s->den_hartog, s->den_hartog_onset,
                      s->zeta_vertical, s->nigol_dcm, s->kt_min, s->divergence_linear,
                      s->zeta_torsional, s->nigol_onset};
        for (size_t c = 0; c < sizeof v / sizeof v[0]; c++) csv_num(fp, v[c]);
        for (int k = 0; k < O->nmodes; k++) {
            const gal_onset_mode *m = O->m + (size_t)i * O->nmodes + k;
            csv_num(fp, s->ok ? m->frequency_hz : NAN);
            csv_num(fp, m->damping_ratio);
        }
        fputc('\n', fp);
    }
    return gal_outset_close(o, fp);
}

void gal_onset_write_json(const gal_onset *O, gal_json *j)
{
    gal_json_kv_num(j, "speed_min_m_s", O->nspeed ? O->sp[0].speed : NAN);
    gal_json_kv_num(j, "speed_max_m_s", O->speed_max);
    gal_json_kv_num(j, "onset_speed_m_s", O->onset_speed);
    gal_json_key(j, "onset_mode");
    if (O->onset_mode < 0) gal_json_num(j, NAN);
    else {
        gal_json_obj_begin(j);
        gal_json_kv_int(j, "index", O->onset_mode + 1);
        gal_json_kv_num(j, "frequency_hz", O->onset_frequency_hz);
        gal_json_kv_num(j, "share_vertical", O->onset_share[0]);
        gal_json_kv_num(j, "share_horizontal", O->onset_share[1]);
        gal_json_kv_num(j, "share_torsional", O->onset_share[2]);
        gal_json_obj_end(j);
    }
    gal_json_kv_num(j, "onset_frequency_hz", O->onset_frequency_hz);
    gal_json_kv_num(j, "restable_speed_m_s", O->restable_speed);
    gal_json_kv_num(j, "divergence_speed_m_s", O->divergence_speed);
    gal_json_kv_num(j, "fold_speed_m_s", O->fold_speed);
    gal_json_kv_int(j, "onset_basis_modes", O->basis);
    gal_json_key(j, "vg");
    gal_json_arr_begin(j);
    for (int i = 0; i < O->nspeed; i++) {
        const gal_onset_speed *s = O->sp + i;
        gal_json_obj_begin(j);
        gal_json_kv_num(j, "speed_m_s", s->speed);
        gal_json_kv_num(j, "swing_deg", s->swing_deg);
        gal_json_kv_num(j, "twist_deg", s->twist_deg);
        gal_json_kv_num(j, "alpha_deg", s->alpha_deg);
        gal_json_kv_num(j, "den_hartog", s->den_hartog);
        gal_json_kv_num(j, "den_hartog_onset_m_s", s->den_hartog_onset);
        gal_json_kv_num(j, "nigol_dcm_dalpha", s->nigol_dcm);
        gal_json_kv_num(j, "nigol_onset_m_s", s->nigol_onset);
        gal_json_key(j, "modes");
        gal_json_arr_begin(j);
        for (int k = 0; k < O->nmodes; k++) {
            const gal_onset_mode *m = O->m + (size_t)i * O->nmodes + k;
            gal_json_obj_begin(j);
            gal_json_kv_num(j, "frequency_hz", s->ok ? m->frequency_hz : NAN);
            gal_json_kv_num(j, "damping_ratio", m->damping_ratio);
            gal_json_obj_end(j);
        }
        gal_json_arr_end(j);
        gal_json_obj_end(j);
    }
    gal_json_arr_end(j);
}

void gal_onset_print(FILE *fp, const gal_onset *O)
{
    fprintf(fp, "coupled onset about the mean-wind equilibrium (%d natural modes, %d aeroelastic modes followed, "
            "%g to %g m/s):\n", O->basis, O->nmodes, O->nspeed ? O->sp[0].speed : NAN, O->speed_max);
    if (isfinite(O->onset_speed))
        fprintf(fp, "  onset %.4g m/s: mode %d at %.4f Hz (shares vertical %.2f, horizontal %.2f, torsional %.2f)\n",
                O->onset_speed, O->onset_mode + 1, O->onset_frequency_hz, O->onset_share[0], O->onset_share[1],
                O->onset_share[2]);
    else fprintf(fp, "  no onset: every followed mode is damped up to %g m/s\n", O->speed_max);
    if (isfinite(O->restable_speed))
        fprintf(fp, "  stable again above %.4g m/s (every followed mode damped up to %g m/s)\n", O->restable_speed,
                O->speed_max);
    if (isfinite(O->divergence_speed)) fprintf(fp, "  torsional divergence at %.4g m/s\n", O->divergence_speed);
    if (isfinite(O->fold_speed)) fprintf(fp, "  the mean-wind equilibrium jumps (fold) at %.4g m/s\n", O->fold_speed);
}
