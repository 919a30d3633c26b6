/* report.c: `gallop modes` outputs of an explicit bundle (bundle.h): the table, and equilibrium.csv,
 * modes.csv, shapes.csv and summary.json as a single rod's, per sub-conductor where it matters. */
#include "gallop/bundle/bundle.h"
#include "gallop/base/core.h"
#include "gallop/output/json.h"
#include "gallop/output/outset.h"
#include "gallop/output/report.h"

#include <math.h>
#include <stdlib.h>

static double node_twist(const gal_bundle *b, const double *q, int i)
{
    int nel = b->nn - 1, a = i > 0 ? i - 1 : 0, c = i < nel ? i : nel - 1;
    return 0.5 * (q[3 * b->nn + a] + q[3 * b->nn + c]);
}

static int write_equilibrium(gal_outset *o, const gal_bundle *b)
{
    FILE *fp = gal_outset_open(o, "equilibrium.csv");
    if (!fp) return GAL_EIO;
    int nel = b->nn - 1;
    double *T = malloc((size_t)nel * sizeof(double));
    if (!T) { gal_outset_close(o, fp); return gal_error(GAL_ENOMEM, "out of memory"); }
    fprintf(fp, "sub,node,x_m,y_m,z_m,twist_rad,tension_n,spacer\n");
    for (int r = 0; r < b->n; r++) {
        const double *q = b->state + (size_t)r * b->rod[0]->nq;
        gal_rod_tensions(b->rod[r], q, T);
        for (int i = 0; i < b->nn; i++) {
            double t = i == 0 ? T[0] : i == nel ? T[nel - 1] : 0.5 * (T[i - 1] + T[i]);
            fprintf(fp, "%d,%d,%.9g,%.9g,%.9g,%.9g,%.9g,%d\n", r + 1, i, q[3 * i], q[3 * i + 1], q[3 * i + 2],
                    node_twist(b, q, i), t, b->spat[i] + 1);
        }
    }
    free(T);
    return gal_outset_close(o, fp);
}

static int write_shapes(gal_outset *o, const gal_bundle *b, const gal_modes *md)
{
    FILE *fp = gal_outset_open(o, "shapes.csv");
    if (!fp) return GAL_EIO;
    int nq = b->rod[0]->nq;
    double *full = malloc((size_t)(nq + b->rod[0]->ndof) * sizeof(double)), *fr = full + nq;
    if (!full) { gal_outset_close(o, fp); return gal_error(GAL_ENOMEM, "out of memory"); }
    fprintf(fp, "mode,family,frequency_hz,sub,node,x_m,z_m,ux,uy,uz,twist\n");
    for (int k = 0; k < md->n; k++) {
        const gal_mode *m = md->mode + k;
        if (!m->selected) continue;
        for (int r = 0; r < b->n; r++) {
            const double *q = b->state + (size_t)r * nq;
            for (int j = 0; j < nq; j++) full[j] = 0;
            gal_bundle_map(b, r, md->shape + (size_t)k * md->ndof, fr);
            gal_rod_scatter(b->rod[r], fr, full);
            for (int i = 0; i < b->nn; i++)
                fprintf(fp, "%d,%s,%.9g,%d,%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", k + 1, gal_family_names[m->family],
                        m->frequency_hz, r + 1, i, q[3 * i], q[3 * i + 2], full[3 * i], full[3 * i + 1], full[3 * i + 2],
                        node_twist(b, full, i));
        }
        fprintf(fp, "\n\n");
    }
    free(full);
    return gal_outset_close(o, fp);
}

static void summary_bundle(gal_json *j, const gal_bundle *b)
{
    gal_json_key(j, "bundle");
    gal_json_obj_begin(j);
    gal_json_kv_str(j, "model", "explicit");
    gal_json_kv_int(j, "subconductors", b->n);
    gal_json_kv_int(j, "spacers", b->ns);
    gal_json_key(j, "spacer_positions");
    gal_json_arr_begin(j);
    for (int sp = 0; sp < b->ns; sp++) gal_json_num(j, (double)b->spnode[sp] / (b->nn - 1));
    gal_json_arr_end(j);
    gal_json_kv_num(j, "radius_m", b->bp.radius);
    gal_json_kv_num(j, "asymmetry_m", b->asymmetry);
    gal_json_kv_str(j, "figures", "sag, tensions and unstretched length are one sub-conductor's (sub-conductor 1)");
    gal_json_obj_end(j);
}

static int write_summary(gal_outset *o, const gal_scene *sc, const gal_bundle *b, const gal_modes *md,
                         const int want[GAL_FAMILY_COUNT], double wall)
{
    gal_json *j = gal_outset_summary(o);
    if (!j) return GAL_EIO;
    gal_json_kv_str(j, "command", "modes");
    gal_json_kv_str(j, "scene", sc->path);
    gal_json_kv_num(j, "sag_m", b->sag);
    gal_json_kv_num(j, "horizontal_tension_n", b->horizontal_tension);
    gal_json_kv_num(j, "unstretched_length_m", b->unstretched_length);
    gal_json_kv_num(j, "element_tension_max_n", b->tension_max);
    gal_json_kv_int(j, "elements", b->rod[0]->p.elements);
    gal_json_kv_int(j, "dofs", b->ndof);
    gal_json_kv_int(j, "newton_iterations", b->newton_iterations);
    gal_json_kv_num(j, "wall_time_s", wall);
    summary_bundle(j, b);
    gal_json_key(j, "shapes_csv");
    gal_json_obj_begin(j);
    gal_json_kv_str(j, "holds", "mass-normalized shapes of the selected modes, per sub-conductor (column sub), one "
                    "block per mode separated by two blank lines");
    gal_json_kv_str(j, "units", "x_m, z_m: m (equilibrium); ux, uy, uz: m/sqrt(kg); twist: rad/sqrt(kg m^2)");
    gal_json_obj_end(j);
    gal_report_families_json(j, md, want);
    gal_json_kv_int(j, "subspan_modes_computed", md->found[GAL_FAMILY_SUBSPAN]);
    gal_json_key(j, "modes");
    gal_json_arr_begin(j);
    for (int k = 0; k < md->n; k++) {
        const gal_mode *m = md->mode + k;
        if (!m->selected) continue;
        gal_json_obj_begin(j);
        gal_json_kv_int(j, "index", k + 1);
        gal_json_kv_str(j, "family", gal_family_names[m->family]);
        gal_json_kv_str(j, "symmetry", gal_symmetry_names[m->symmetry]);
        gal_json_kv_num(j, "frequency_hz", m->frequency_hz);
        for (int f = 0; f < GAL_FAMILY_COUNT; f++) {
            char key[32];
            snprintf(key, sizeof key, "share_%s", gal_family_names[f]);
            gal_json_kv_num(j, key, m->share[f]);
        }
        gal_json_kv_str(j, "selected_as", m->partner ? "partner" : "lowest");
        if (m->partner) gal_json_kv_int(j, "partner_of", m->partner);
        gal_json_obj_end(j);
    }
    gal_json_arr_end(j);
    return GAL_OK;
}

int gal_bundle_report(const char *dir, const gal_scene *sc, const gal_bundle *b, const gal_modes *md,
                      const int want[GAL_FAMILY_COUNT], double wall)
{
    gal_outset *o;
    int st = gal_outset_begin(&o, dir, "modes");
    if (!st) st = gal_outset_scene(o, sc);
    if (!st) st = write_equilibrium(o, b);
    if (!st) st = gal_report_modes_csv(o, md, 1);
    if (!st) st = write_shapes(o, b, md);
    if (!st) st = write_summary(o, sc, b, md, want, wall);
    if (!st) st = gal_outset_commit(o);
    gal_outset_free(o);
    return st;
}

void gal_bundle_report_table(FILE *fp, const gal_scene *sc, const gal_bundle *b, const gal_modes *md,
                             const int want[GAL_FAMILY_COUNT], double wall)
{
    fprintf(fp, "scene %s: explicit bundle of %d sub-conductors, %d spacers, span %.6g m, %d elements each, "
            "%d dofs\n", sc->name, b->n, b->ns, b->rod[0]->p.length, b->rod[0]->p.elements, b->ndof);
    fprintf(fp, "equilibrium (each sub-conductor): horizontal tension %.6g N, sag %.6g m, unstretched length "
            "%.8g m (%d Newton iterations; sub-conductors alike within %.2g m)\n", b->horizontal_tension, b->sag,
            b->unstretched_length, b->newton_iterations, b->asymmetry);
    fprintf(fp, "\n%5s  %-10s  %-13s  %12s  %10s  %6s %6s %6s %6s %7s\n", "mode", "family", "symmetry",
            "frequency Hz", "period s", "vert", "horiz", "tors", "axial", "subspan");
    for (int k = 0; k < md->n; k++) {
        const gal_mode *m = md->mode + k;
        if (!m->selected) continue;
        fprintf(fp, "%5d  %-10s  %-13s  %12.6f  %10.4f  %6.3f %6.3f %6.3f %6.3f %7.3f\n", k + 1,
                gal_family_names[m->family], gal_symmetry_names[m->symmetry], m->frequency_hz, 1.0 / m->frequency_hz,
                m->share[0], m->share[1], m->share[2], m->share[3], m->share[4]);
    }
    gal_report_modes_notes(fp, md, want);
    fprintf(fp, "\n%d modes computed (%d subspan), wall time %.3f s\n", md->n, md->found[GAL_FAMILY_SUBSPAN], wall);
}
