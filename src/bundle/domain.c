/* domain.c: where the equivalent bundle is good enough (bundle.h, gal_bundle_equivalent_outside):
 * not when a galloping vertical mode has the torsional mode of its symmetry next to it (README
 * "Bundles", measured with notebooks-free-reports/bundle_grid.sh). */
#include "gallop/bundle/bundle.h"

#include <stdio.h>

int gal_bundle_equivalent_outside(const gal_scene *sc, const gal_modes *md, double f_gallop, char *msg, size_t len)
{
    int v;
    double rel;
    if (len > 0) msg[0] = 0;
    if (sc->bundle.subconductors < 2 || sc->bundle.explicit_model) return 0;
    int t = gal_modes_partner_near(md, f_gallop, &v, &rel);
    if (t < 0 || rel > GAL_EQUIVALENT_NEAR) return 0;
    const gal_mode *mv = md->mode + v, *mt = md->mode + t;
    snprintf(msg, len, "the equivalent bundle is outside its measured domain: torsional mode %d (%s, %.4f Hz) is "
             "within %.1f%% of vertical mode %d (%.4f Hz, the nearest the galloping at %.4f Hz), closer than %.0f%%; "
             "such a bundle can rotate by tens of "
             "degrees as it gallops, where the equivalent model's amplitudes were 22%% to 50%% off the explicit "
             "model's (README \"Bundles\"): check with bundle.model = explicit", mt->index,
             gal_symmetry_names[mt->parity], mt->frequency_hz, 100 * rel, mv->index, mv->frequency_hz, f_gallop,
             100 * GAL_EQUIVALENT_NEAR);
    return 1;
}
