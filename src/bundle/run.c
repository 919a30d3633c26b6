/* run.c: the explicit bundle of a scene's model: its parameters, statics and modes (bundle.h). */
#include "gallop/bundle/bundle.h"
#include "gallop/base/core.h"
#include "gallop/model/model.h"

#include <string.h>

void gal_bundle_params_of(const gal_scene *sc, gal_bundle_params *bp)
{
    memset(bp, 0, sizeof *bp);
    bp->subconductors = sc->bundle.subconductors;
    bp->radius = sc->bundle.radius;
    bp->orientation = sc->bundle.orientation;
    bp->spacers = sc->bundle.spacers;
    bp->positions = sc->bundle.nspacer_positions ? sc->bundle.spacer_positions : NULL;
    bp->spacer_mass = sc->bundle.spacer_mass;
    bp->spacer_inertia = sc->bundle.spacer_inertia;
    bp->spacer_stiffness = sc->bundle.spacer_stiffness;
}

int gal_bundle_solve_model(const gal_model *m, gal_bundle **out, gal_modes *md)
{
    gal_bundle_params bp;
    gal_bundle_params_of(&m->sc, &bp);
    memset(md, 0, sizeof *md);
    int st = gal_bundle_statics(&m->rod[0].p, &bp, m->rod[0].spec, m->rod[0].spec_value, &m->statics, out);
    if (st) return st;
    st = gal_bundle_modes_find(*out, m->want, m->max_modes, md);
    if (st) *out = gal_bundle_free(*out);
    return st;
}
