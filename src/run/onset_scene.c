/* onset_scene.c: the coupled onset of a scene's span through the pipeline (onset_scene.h). */
#include "gallop/run/onset_scene.h"
#include "gallop/base/core.h"
#include "gallop/model/model.h"
#include "gallop/run/forward.h"

int gal_scene_onset(const gal_scene *sc, gal_onset *O)
{
    int st;
    gal_model *m = gal_model_alloc(sc, &st);
    gal_data *d = m ? gal_data_alloc(m) : NULL;
    if (m && !d) st = GAL_ENOMEM;
    if (!st) st = gal_forward(m, d, GAL_STAGE_WIND);
    if (!st) {
        gal_onset_opts o;
        gal_onset_default_opts(&o);
        o.speed_min = sc->stability.speed_min, o.speed_max = sc->stability.speed_max;
        o.speed_step = sc->stability.speed_step;
        double mass = sc->conductor.mass_per_length + (sc->ice.present ? sc->ice.mass_per_length : 0);
        st = gal_onset_analyse(d->eq.rod, d->eq.q, &d->loads, d->damping, mass, &o, O);
    }
    gal_data_free(d);
    gal_model_free(m);
    return st;
}
