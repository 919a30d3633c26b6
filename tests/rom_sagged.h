/* rom_sagged.h: the small sagged span of the reduced model's self-check tests (test_rom_adapt,
 * test_rom_check, test_rom_irk, test_rom_rates, test_rom_recon): its parameters, and its equilibrium with modes 2/1/1 and the selected ones. */
#ifndef GALLOP_TESTS_ROM_SAGGED_H
#define GALLOP_TESTS_ROM_SAGGED_H

#include "gallop.h"
#include "gallop/modes/modes.h"
#include "gallop/statics/statics.h"

static const gal_rod_params sagged = {.length = 150, .elements = 24, .EA = 3e7, .EI = 30, .GJ = 200, .mass = 1.6,
                                      .polar_inertia = 1.6e-4, .gravity = 9.80665, .torsion = 1, .twist_clamped = 1};

/* the span at 4 m of sag, the modes of `want` per family (nfind computed) and the indices of the
 * selected ones (at most maxsel); 0 or a status */
static inline int sagged_setup_modes(gal_equilibrium *eq, gal_modes *md, const int want[GAL_FAMILY_COUNT], int nfind,
                                     int *sel, int maxsel, int *ns)
{
    int st = gal_statics_solve(&sagged, GAL_BY_SAG, 4.0, NULL, eq);
    if (!st) st = gal_modes_find(eq->rod, eq->q, want, nfind, md);
    *ns = 0;
    for (int k = 0; !st && k < md->n && *ns < maxsel; k++)
        if (md->mode[k].selected) sel[(*ns)++] = k;
    return st;
}

/* the same with modes 2/1/1 of 40 (at most 8 selected) */
static inline int sagged_setup(gal_equilibrium *eq, gal_modes *md, int sel[8], int *ns)
{
    static const int want[GAL_FAMILY_COUNT] = {2, 1, 1, 0};
    return sagged_setup_modes(eq, md, want, 40, sel, 8, ns);
}

#endif
