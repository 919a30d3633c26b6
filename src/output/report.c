/* report.c: CSV and JSON outputs of the modes stage. */
#include "gallop/output/report.h"
#include "gallop/base/core.h"
#include "gallop/output/json.h"
#include "gallop/output/outset.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "output/numfmt.h"

/* Node twist: mean of the adjacent edges' twists. */
static double node_twist(const gal_rod *rod, const double *q, int i)
{
    if (!rod->p.torsion) return 0.0;
    int nel = rod->p.elements, a = i > 0 ? i - 1 : 0, b = i < nel ? i : nel - 1;
    return 0.5 * (q[3 * rod->nn + a] + q[3 * rod->nn + b]);
}

static int write_equilibrium(gal_outset *o, const gal_equilibrium *eq)
{
    FILE *fp = gal_outset_open(o, "equilibrium.csv");
    if (!fp) return GAL_EIO;
    const gal_rod *rod = eq->rod;
    int nel = rod->p.elements;
    double *T = malloc((size_t)nel * sizeof(double));
    if (!T) { gal_outset_close(o, fp); return gal_error(GAL_ENOMEM, "out of memory"); }
    gal_rod_tensions(rod, eq->q, T);
    fprintf(fp, "node,s_m,x_m,y_m,z_m,twist_rad,tension_n\n");
    double s = 0;
    for (int i = 0; i < rod->nn; i++) {
        const double *x = eq->q + 3 * i;
        if (i > 0) {
            const double *xp = x - 3;
            s += sqrt((x[0] - xp[0]) * (x[0] - xp[0]) + (x[1] - xp[1]) * (x[1] - xp[1]) + (x[2] - xp[2]) * (x[2] - xp[2]));
        }
        /* node tension: mean of the adjacent elements' */
        double t = i == 0 ? T[0] : i == nel ? T[nel - 1] : 0.5 * (T[i - 1] + T[i]);
        fprintf(fp, "%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", i, s, x[0], x[1], x[2], node_twist(rod, eq->q, i), t);
    }
    free(T);
    return gal_outset_close(o, fp);
}

int gal_report_modes_csv(gal_outset *o, const gal_modes *md, int subspan)
{
    FILE *fp = gal_outset_open(o, "modes.csv");
    if (!fp) return GAL_EIO;
    fprintf(fp, "index,family,symmetry,frequency_hz,period_s,share_vertical,share_horizontal,"
                  "share_torsional,share_axial,selected%s\n", subspan ? ",share_subspan" : "");
    for (int k = 0; k < md->n; k++) {
        const gal_mode *m = md->mode + k;
        fprintf(fp, "%d,%s,%s,%.9g,%.9g,%.6f,%.6f,%.6f,%.6f,%d", m->index, gal_family_names[m->family],
                gal_symmetry_names[m->symmetry], m->frequency_hz, m->frequency_hz > 0 ? 1 / m->frequency_hz : INFINITY,
                m->share[0], m->share[1], m->share[2], m->share[3], m->selected);
        if (subspan) fprintf(fp, ",%.6f", m->share[GAL_FAMILY_SUBSPAN]);
        fputc('\n', fp);
    }
    return gal_outset_close(o, fp);
}

/* One line of shapes.csv into buf: mode,family,frequency_hz,node,x_m,z_m,ux,uy,uz,twist. */
static int shape_line(char *buf, const gal_mode *m, int i, const double *v)
{
    int len = gal_fmt_int(buf, m->index);
    buf[len++] = ',';
    size_t fl = strlen(gal_family_names[m->family]);
    memcpy(buf + len, gal_family_names[m->family], fl);
    len += (int)fl;
    buf[len++] = ',';
    len += gal_fmt_g9(buf + len, m->frequency_hz);
    buf[len++] = ',';
    len += gal_fmt_int(buf + len, i);
    for (int k = 0; k < 6; k++) {
        buf[len++] = ',';
        len += gal_fmt_g9(buf + len, v[k]);
    }
    buf[len++] = '\n';
    return len;
}

/* The selected modes' shapes, one gnuplot block per mode; the numbers as "%.9g" by gal_fmt_g9
 * (printf's cost per number was 15% of `gallop modes` at 1000 elements), written a block at a
 * time. */
static int write_shapes(gal_outset *o, const gal_equilibrium *eq, const gal_modes *md)
{
    FILE *fp = gal_outset_open(o, "shapes.csv");
    if (!fp) return GAL_EIO;
    const gal_rod *rod = eq->rod;
    enum { LINE = 256, CHUNK = 256 };
    double *full = calloc((size_t)rod->nq, sizeof(double));
    char *buf = malloc((size_t)LINE * CHUNK);
    if (!full || !buf) { free(full); free(buf); gal_outset_close(o, fp); return gal_error(GAL_ENOMEM, "out of memory"); }
    fputs("mode,family,frequency_hz,node,x_m,z_m,ux,uy,uz,twist\n", fp);
    for (int k = 0; k < md->n; k++) {
        const gal_mode *m = md->mode + k;
        if (!m->selected) continue;
        for (int j = 0; j < rod->nq; j++) full[j] = 0;
        gal_rod_scatter(rod, md->shape + (size_t)k * md->ndof, full);
        size_t len = 0;
        for (int i = 0; i < rod->nn; i++) {
            double v[6] = {eq->q[3 * i], eq->q[3 * i + 2], full[3 * i], full[3 * i + 1], full[3 * i + 2],
                           node_twist(rod, full, i)};
            len += (size_t)shape_line(buf + len, m, i, v);
            if (len > (size_t)LINE * (CHUNK - 1)) fwrite(buf, 1, len, fp), len = 0;
        }
        fwrite(buf, 1, len, fp);
        fputs("\n\n", fp); /* gnuplot data blocks, one per mode */
    }
    free(full);
    free(buf);
    return gal_outset_close(o, fp);
}

void gal_report_families_json(gal_json *j, const gal_modes *md, const int want[GAL_FAMILY_COUNT])
{
    gal_json_key(j, "families");
    gal_json_obj_begin(j);
    for (int fam = 0; fam < 3; fam++) {
        gal_json_key(j, gal_family_names[fam]);
        gal_json_obj_begin(j);
        gal_json_kv_int(j, "asked", want[fam]);
        gal_json_kv_int(j, "found", md->selected[fam]);
        gal_json_obj_end(j);
    }
    gal_json_obj_end(j);
}

static int write_summary(gal_outset *o, const gal_scene *sc, const gal_equilibrium *eq,
                         const gal_modes *md, const int want[GAL_FAMILY_COUNT], double wall)
{
    gal_json *j = gal_outset_summary(o);
    if (!j) return GAL_EIO;
    gal_json_kv_str(j, "command", "modes");
    gal_json_kv_str(j, "scene", sc->path);
    gal_json_kv_num(j, "sag_m", eq->sag);
    gal_json_kv_num(j, "horizontal_tension_n", eq->horizontal_tension);
    gal_json_kv_num(j, "unstretched_length_m", eq->unstretched_length);
    gal_json_kv_num(j, "tension_left_n", eq->tension_left);
    gal_json_kv_num(j, "tension_right_n", eq->tension_right);
    /* the largest tension: at a support or in an element (the support tensions are the
     * reactions, which hold the end elements' shear too); the elements' own largest apart */
    gal_json_kv_num(j, "tension_max_n", fmax(fmax(eq->tension_left, eq->tension_right), eq->tension_max));
    gal_json_kv_num(j, "element_tension_max_n", eq->tension_max);
    gal_json_kv_int(j, "elements", eq->rod->p.elements);
    gal_json_kv_int(j, "dofs", eq->rod->ndof);
    gal_json_kv_int(j, "newton_iterations", eq->newton_iterations);
    gal_json_kv_num(j, "wall_time_s", wall);
    /* what shapes.csv holds (the CSV itself starts with its header line) */
    gal_json_key(j, "shapes_csv");
    gal_json_obj_begin(j);
    gal_json_kv_str(j, "holds", "mass-normalized shapes of the selected modes (phi^T M phi = 1), one block per "
                    "mode separated by two blank lines");
    gal_json_kv_str(j, "units", "x_m, z_m: m (equilibrium); ux, uy, uz: m/sqrt(kg); twist: rad/sqrt(kg m^2)");
    gal_json_obj_end(j);
    gal_json_key(j, "counters");
    gal_json_obj_begin(j);
    gal_json_kv_int(j, "length_iterations", eq->length_iterations);
    gal_json_kv_int(j, "load_steps", eq->load_steps);
    gal_json_kv_int(j, "statics_factorizations", eq->factorizations);
    gal_json_kv_num(j, "statics_wall_time_s", eq->wall_time_s);
    gal_json_kv_int(j, "modes_computed", md->n);
    gal_json_kv_int(j, "arpack_rounds", md->rounds);
    gal_json_kv_int(j, "arpack_operator_applications", md->op_applications);
    gal_json_kv_int(j, "modes_factorizations", md->factorizations);
    gal_json_kv_num(j, "modes_wall_time_s", md->wall_time_s);
    gal_json_obj_end(j);
    gal_json_key(j, "effects");
    gal_json_obj_begin(j);
    for (int e = 0; e < GAL_FX_COUNT; e++) gal_json_kv_str(j, gal_effect_names[e], sc->effect[e] ? "on" : "off");
    gal_json_obj_end(j);
    gal_report_families_json(j, md, want);
    gal_json_key(j, "frequencies");
    gal_json_arr_begin(j);
    for (int k = 0; k < md->n; k++)
        if (md->mode[k].selected) gal_json_num(j, md->mode[k].frequency_hz);
    gal_json_arr_end(j);
    gal_json_key(j, "modes");
    gal_json_arr_begin(j);
    for (int k = 0; k < md->n; k++) {
        const gal_mode *m = md->mode + k;
        if (!m->selected) continue;
        gal_json_obj_begin(j);
        gal_json_kv_int(j, "index", m->index);
        gal_json_kv_str(j, "family", gal_family_names[m->family]);
        gal_json_kv_str(j, "symmetry", gal_symmetry_names[m->symmetry]);
        gal_json_kv_num(j, "frequency_hz", m->frequency_hz);
        gal_json_kv_num(j, "share_vertical", m->share[GAL_FAMILY_VERTICAL]);
        gal_json_kv_num(j, "share_horizontal", m->share[GAL_FAMILY_HORIZONTAL]);
        gal_json_kv_num(j, "share_torsional", m->share[GAL_FAMILY_TORSIONAL]);
        gal_json_kv_num(j, "share_axial", m->share[GAL_FAMILY_AXIAL]);
        gal_json_kv_str(j, "selected_as", m->partner ? "partner" : "lowest");
        if (m->partner) gal_json_kv_int(j, "partner_of", m->partner);
        gal_json_obj_end(j);
    }
    gal_json_arr_end(j);
    return GAL_OK;
}

void gal_report_modes_notes(FILE *fp, const gal_modes *md, const int want[GAL_FAMILY_COUNT])
{
    for (int k = 0; k < md->n; k++) {
        const gal_mode *m = md->mode + k, *v = NULL;
        for (int i = 0; i < md->n && m->partner; i++)
            if (md->mode[i].index == m->partner) v = md->mode + i;
        if (!v) continue;
        /* the parity; "mostly" where the symmetry is none (an inclined span) */
        fprintf(fp, "note: torsional mode %d (%s%s, %.6f Hz) added to the %d asked: the torsional mode of the "
                "symmetry of vertical mode %d (%s%s, %.6f Hz) nearest it, within %.0f%% (galloping couples them)\n",
                m->index, m->symmetry == GAL_SYM_NONE ? "mostly " : "", gal_symmetry_names[m->parity],
                m->frequency_hz, want[GAL_FAMILY_TORSIONAL], v->index, v->symmetry == GAL_SYM_NONE ? "mostly " : "",
                gal_symmetry_names[v->parity], v->frequency_hz, 100 * GAL_PARTNER_BAND);
    }
    for (int f = 0; f < 3; f++)
        if (md->selected[f] < want[f])
            fprintf(fp, "note: %d %s mode%s asked, %d found among the %d lowest modes\n", want[f],
                    gal_family_names[f], want[f] > 1 ? "s" : "", md->selected[f], md->n);
}

int gal_report_modes(const char *dir, const gal_scene *sc, const gal_equilibrium *eq,
                     const gal_modes *md, const int want[GAL_FAMILY_COUNT], double wall)
{
    gal_outset *o;
    int st = gal_outset_begin(&o, dir, "modes");
    if (!st) st = gal_outset_scene(o, sc);
    if (!st) st = write_equilibrium(o, eq);
    if (!st) st = gal_report_modes_csv(o, md, 0);
    if (!st) st = write_shapes(o, eq, md);
    if (!st) st = write_summary(o, sc, eq, md, want, wall);
    if (!st) st = gal_outset_commit(o); /* summary.json last: the commit record */
    gal_outset_free(o);
    return st;
}

void gal_report_modes_table(FILE *fp, const gal_scene *sc, const gal_equilibrium *eq,
                            const gal_modes *md, const int want[GAL_FAMILY_COUNT], double wall)
{
    const gal_rod *rod = eq->rod;
    fprintf(fp, "scene %s: span %.6g m, height difference %.6g m, %d elements, %d dofs\n", sc->name,
            rod->p.length, rod->p.height_difference, rod->p.elements, rod->ndof);
    fprintf(fp, "equilibrium: horizontal tension %.6g N, sag %.6g m, unstretched length %.8g m, "
                "support tensions %.6g / %.6g N (%d Newton iterations)\n",
            eq->horizontal_tension, eq->sag, eq->unstretched_length, eq->tension_left, eq->tension_right,
            eq->newton_iterations);
    fprintf(fp, "\n%5s  %-10s  %-13s  %12s  %10s  %6s %6s %6s %6s\n", "mode", "family", "symmetry",
            "frequency Hz", "period s", "vert", "horiz", "tors", "axial");
    for (int k = 0; k < md->n; k++) {
        const gal_mode *m = md->mode + k;
        if (!m->selected) continue;
        fprintf(fp, "%5d  %-10s  %-13s  %12.6f  %10.4f  %6.3f %6.3f %6.3f %6.3f\n", m->index,
                gal_family_names[m->family], gal_symmetry_names[m->symmetry], m->frequency_hz,
                1.0 / m->frequency_hz, m->share[0], m->share[1], m->share[2], m->share[3]);
    }
    gal_report_modes_notes(fp, md, want);
    fprintf(fp, "\n%d modes computed (%d ARPACK run%s), wall time %.3f s\n", md->n, md->rounds,
            md->rounds > 1 ? "s" : "", wall);
}
