/* forward.c: the pipeline, its stages in their order on a const model (forward.h). */
#include "gallop/run/forward.h"
#include "gallop/base/core.h"
#include "gallop/loads/windfield.h"
#include "gallop/model/damping.h"
#include "gallop/reduced/rom.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

const char *const gal_stage_names[GAL_STAGE_COUNT] = {"none", "equilibrium", "modes", "wind", "start", "reduced"};

gal_data *gal_data_alloc(const gal_model *m)
{
    gal_data *d = calloc(1, sizeof *d);
    if (!d) {
        gal_error(GAL_ENOMEM, "out of memory for the data of %s", m->sc.path);
        return NULL;
    }
    d->model = m;
    if (!(d->rom_setup = calloc(1, sizeof *d->rom_setup))) {
        gal_error(GAL_ENOMEM, "out of memory for the data of %s", m->sc.path);
        free(d);
        return NULL;
    }
    return d;
}

gal_data *gal_data_free(gal_data *d)
{
    if (d) {
        if (d->borrowed < GAL_STAGE_EQUILIBRIUM) gal_equilibrium_clear(&d->eq);
        if (d->borrowed < GAL_STAGE_MODES) {
            gal_modes_clear(&d->md);
            if (d->rom_setup) gal_rom_free(d->rom_setup->rom);
            free(d->rom_setup);
        }
        if (!d->damping_borrowed) gal_damping_free(d->damping);
        free(d->wind_u);
        free(d->q_start);
        free(d->v_start);
        free(d);
    }
    return NULL;
}

/* ---- equilibrium ---- */

static int stage_equilibrium(const gal_model *m, gal_data *d)
{
    const gal_model_rod *r = &m->rod[0];
    gal_equilibrium_clear(&d->eq);
    int st = gal_statics_solve(&r->p, r->spec, r->spec_value, &m->statics, &d->eq);
    if (st) return gal_error(st, "%s: no equilibrium: %s", m->sc.path, gal_error_message());
    return GAL_OK;
}

/* ---- modes, and the structural damping ---- */

static int stage_modes(const gal_model *m, gal_data *d)
{
    const int *want = m->want;
    gal_modes_clear(&d->md);
    if (want[GAL_FAMILY_VERTICAL] + want[GAL_FAMILY_HORIZONTAL] + want[GAL_FAMILY_TORSIONAL] == 0)
        return gal_error(GAL_EINPUT, "%s: [model] selects no modes; allowed: at least one of modes_vertical, "
                         "modes_horizontal, modes_torsional (torsional with torsion on)", m->sc.path);
    int st = gal_modes_find_eq(&d->eq, want, m->max_modes, &d->md);
    if (st) return gal_error(st, "%s: %s", m->sc.path, gal_error_message());
    /* the damping is the structure's: the stated ratio at every mode of the band, whichever
     * modes the scene selects */
    d->damping = gal_damping_free(d->damping);
    d->damping = gal_damping_modal_alloc(d->eq.rod, d->eq.q, m->damping_ratio, GAL_DAMPING_BAND_HZ);
    if (!d->damping) return gal_error(GAL_EFAIL, "%s: %s", m->sc.path, gal_error_message());
    return GAL_OK;
}

/* ---- the loads on the equilibrium rod, and the turbulent wind field ---- */

static int stage_wind(const gal_model *m, gal_data *d)
{
    free(d->wind_u);
    d->wind_u = NULL;
    d->loads = m->loads;
    d->loads.rod = d->eq.rod;
    /* the along-wind turbulence on the field's points along the span, for the run's duration: the
     * same field for both integrators (and for `gallop wind`) */
    if (d->loads.table && m->turbulence) return gal_windfield_sample(&m->sc, &d->loads, &d->wind_u);
    return GAL_OK;
}

/* ---- the start of a run ---- */

static int stage_start(const gal_model *m, gal_data *d)
{
    const gal_rod *rod = d->eq.rod;
    free(d->q_start);
    d->q_start = malloc((size_t)rod->nq * sizeof(double));
    if (!d->q_start) return gal_error(GAL_ENOMEM, "out of memory");
    memcpy(d->q_start, d->eq.q, (size_t)rod->nq * sizeof(double));
    d->mean_wind_iterations = 0;
    if (!(m->start_mean_wind && d->loads.table)) return GAL_OK;
    /* under the mean wind, which then blows at full speed from t = 0 */
    double tol = 1e-6 * fmax(d->eq.horizontal_tension, 1.0) / rod->p.elements;
    int st = gal_loads_static(d->eq.rod, d->q_start, &d->loads, tol, 100, &d->mean_wind_iterations);
    if (st) return gal_error(st, "%s: no equilibrium under the mean wind: %s", m->sc.path, gal_error_message());
    d->loads.ramp_time = 0;
    return GAL_OK;
}

/* A given start state (forward.h) */
int gal_data_start_from(const gal_model *m, gal_data *d, const double *q, const double *v)
{
    int st = gal_forward(m, d, GAL_STAGE_START);
    if (st) return st;
    size_t nq = (size_t)d->eq.rod->nq;
    free(d->v_start);
    d->v_start = NULL;
    if (v && !(d->v_start = malloc(nq * sizeof(double)))) return gal_error(GAL_ENOMEM, "out of memory");
    memcpy(d->q_start, q, nq * sizeof(double));
    if (v) memcpy(d->v_start, v, nq * sizeof(double));
    d->loads.ramp_time = 0;
    return GAL_OK;
}

/* ---- the reduced model's basis modes ---- */

static const char *const family_keys[GAL_FAMILY_COUNT] = {"modes_vertical", "modes_horizontal", "modes_torsional",
                                                          "modes_vertical"};

/* The selected modes, in their order, into d->sel; a mode at or near 0 Hz (a rigid or free-twist
 * motion, which no reduced model can carry) is refused, named with the key that selects it. */
static int stage_reduced(const gal_model *m, gal_data *d)
{
    d->basis = 0;
    for (int k = 0; k < d->md.n && d->basis < GAL_BASIS_MAX; k++) {
        const gal_mode *mo = &d->md.mode[k];
        if (!mo->selected) continue;
        if (!(mo->frequency_hz >= GAL_MODE_FLOOR_HZ))
            return gal_error(GAL_EINPUT, "%s: selected mode %d (%s) is at %.3g Hz, at or near 0 Hz (a rigid or "
                             "free-twist motion): the reduced model does not take it; select fewer modes of that "
                             "family (model.%s) or clamp the twist (span.end_twist = clamped)", m->sc.path, k + 1,
                             gal_family_names[mo->family], mo->frequency_hz, family_keys[mo->family]);
        d->sel[d->basis++] = k;
    }
    if (!d->basis) return gal_error(GAL_EINPUT, "%s: no mode selected for the reduced model (model.modes_*)", m->sc.path);
    return GAL_OK;
}

/* ---- the pipeline ---- */

typedef int (*stage_fn)(const gal_model *m, gal_data *d);
static const stage_fn stages[GAL_STAGE_COUNT] = {NULL, stage_equilibrium, stage_modes, stage_wind, stage_start,
                                                 stage_reduced};

int gal_forward(const gal_model *m, gal_data *d, gal_stage upto)
{
    if (upto < GAL_STAGE_NONE || upto >= GAL_STAGE_COUNT)
        return gal_error(GAL_EINPUT, "pipeline: stage %d; allowed: %d to %d", (int)upto, GAL_STAGE_NONE, GAL_STAGE_COUNT - 1);
    if (d->model != m) return gal_error(GAL_EINPUT, "pipeline: the data were made for another model");
    if (m->nrods != 1 || m->ncouplings != 0)
        return gal_error(GAL_EINPUT, "%s: %d rods and %d couplings: the pipeline solves one rod (bundles are to come)",
                         m->sc.path, m->nrods, m->ncouplings);
    for (int s = d->stage + 1; s <= (int)upto; s++) {
        double t0 = gal_wall_time();
        int st = stages[s](m, d);
        d->stage_time_s[s] = gal_wall_time() - t0;
        if (st) return st;
        d->stage = (gal_stage)s;
    }
    return GAL_OK;
}
