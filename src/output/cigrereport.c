/* cigrereport.c: the CIGRE TB 322 outputs of a galloping run in its summary.json (cigrereport.h):
 * the galloping ellipse of each probe over its steady window, the clearances to the neighbouring
 * phases (output.neighbour_phases), the dynamic support tensions, the empirical envelope. */
#include "gallop/output/cigrereport.h"
#include "gallop/analysis/cigre.h"
#include "gallop/base/core.h"

#include <math.h>
#include <stdlib.h>

/* the ellipse of probe k over samples from t0 on */
static int probe_ellipse(const gal_sim_result *r, int k, double t0, gal_ellipse *e)
{
    long i0 = (long)floor(t0 / r->dt_out);
    if (i0 < 0) i0 = 0;
    if (i0 > r->nsamples - 2) i0 = r->nsamples > 2 ? r->nsamples - 2 : 0;
    size_t n = (size_t)(r->nsamples - i0), w = 4 * (size_t)r->nprobe;
    double *y = malloc(2 * n * sizeof(double));
    if (!y) return gal_error(GAL_ENOMEM, "out of memory");
    for (size_t i = 0; i < n; i++) {
        y[i] = r->trace[(i0 + i) * w + 4 * (size_t)k];
        y[n + i] = r->trace[(i0 + i) * w + 4 * (size_t)k + 1];
    }
    int st = gal_cigre_ellipse(y, y + n, n, e);
    free(y);
    return st;
}

int gal_cigre_json_probe(gal_json *j, const gal_scene *sc, const gal_sim_result *r, int k, double steady_from_s)
{
    gal_ellipse e;
    int st = probe_ellipse(r, k, steady_from_s, &e);
    if (st) return st;
    gal_json_key(j, "ellipse");
    gal_json_obj_begin(j);
    gal_json_kv_num(j, "major_peak_to_peak_m", e.major_pp);
    gal_json_kv_num(j, "minor_peak_to_peak_m", e.minor_pp);
    gal_json_kv_num(j, "tilt_deg", e.tilt_deg);
    gal_json_kv_num(j, "centre_horizontal_m", e.centre_y);
    gal_json_kv_num(j, "centre_vertical_m", e.centre_z);
    gal_json_kv_num(j, "from_s", steady_from_s);
    gal_json_obj_end(j);
    gal_json_key(j, "clearances");
    gal_json_arr_begin(j);
    for (int p = 0; p < sc->output.nneighbours; p++) {
        const double *o = sc->output.neighbour[p];
        gal_json_obj_begin(j);
        gal_json_kv_num(j, "neighbour_horizontal_m", o[0]);
        gal_json_kv_num(j, "neighbour_vertical_m", o[1]);
        gal_json_kv_num(j, "clearance_m", gal_cigre_clearance(&e, o[0], o[1]));
        gal_json_obj_end(j);
    }
    gal_json_arr_end(j);
    return GAL_OK;
}

int gal_cigre_json_run(gal_json *j, const gal_scene *sc, const gal_sim_result *r, const double *steady_from_s,
                       double rts_n)
{
    gal_tension_range t;
    gal_cigre_tensions(r->tension, r->nsamples, rts_n, &t);
    gal_json_key(j, "support_tensions");
    gal_json_obj_begin(j);
    gal_json_kv_num(j, "min_n", t.min_n);
    gal_json_kv_num(j, "max_n", t.max_n);
    gal_json_kv_num(j, "static_n", t.static_n);
    gal_json_kv_num(j, "max_over_static", t.max_over_static);
    if (rts_n > 0) {   /* absent when unknown: a summary.json holds finite numbers only */
        gal_json_kv_num(j, "rated_strength_n", rts_n);
        gal_json_kv_num(j, "max_over_rated_strength", t.max_over_rts);
    }
    gal_json_kv_str(j, "over", "both supports, the whole run; static: the start state (sample 0)");
    gal_json_obj_end(j);
    /* the largest galloping ellipse of the probes beside the envelope */
    double amax = 0;
    for (int k = 0; k < r->nprobe; k++) {
        gal_ellipse e;
        int st = probe_ellipse(r, k, steady_from_s[k], &e);
        if (st) return st;
        amax = fmax(amax, e.major_pp);
    }
    double L = sc->span.length, D = sc->conductor.diameter, env = gal_cigre_envelope_single(L, D);
    gal_json_key(j, "cigre_envelope");
    gal_json_obj_begin(j);
    gal_json_kv_str(j, "formula", "A/D = 80 ln(L/(500 D)), A peak to peak, D bare conductor diameter");
    gal_json_kv_str(j, "source", gal_cigre_envelope_source);
    if (sc->bundle.subconductors > 1) /* the brochure's bundle envelopes differ: not applied */
        gal_json_kv_str(j, "applies_to", "single conductors: this scene is a bundle, whose envelope "
                        "the brochure gives separately (not applied here); D is one sub-conductor's");
    gal_json_kv_num(j, "span_over_diameter", L / D);
    gal_json_kv_num(j, "envelope_peak_to_peak_m", env);
    gal_json_kv_num(j, "simulated_peak_to_peak_m", amax);
    if (env > 0) gal_json_kv_num(j, "simulated_over_envelope", amax / env);
    gal_json_obj_end(j);
    return GAL_OK;
}
