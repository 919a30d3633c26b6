/* rom_sagged.h: the small sagged span of the reduced model's self-check tests (test_rom_adapt,
 * test_rom_check): its parameters, and its equilibrium with modes 2/1/1 and the selected ones. */
#ifndef GALLOP_TESTS_ROM_SAGGED_H
#define GALLOP_TESTS_ROM_SAGGED_H

#include "gallop.h"
#include "gallop/modes/modes.h"
#include "gallop/statics/statics.h"

static const gal_rod_params sagged = {.length = 150, .elements = 24, .EA = 3e7, .EI = 30, .GJ = 200, .mass = 1.6,
                                      .polar_inertia = 1.6e-4, .gravity = 9.80665, .torsion = 1, .twist_clamped = 1};

/* the span at 4 m of sag, its modes and the indices of the selected ones (at most 8); 0 or a status */
static int sagged_setup(gal_equilibrium *eq, gal_modes *md, int sel[8], int *ns)
{
    int want[GAL_FAMILY_COUNT] = {2, 1, 1, 0}, st = gal_statics_solve(&sagged, GAL_BY_SAG, 4.0, NULL, eq);
    if (!st) st = gal_modes_find(eq->rod, eq->q, want, 40, md);
    *ns = 0;
    for (int k = 0; !st && k < md->n && *ns < 8; k++)
        if (md->mode[k].selected) sel[(*ns)++] = k;
    return st;
}

#endif
