/* adapt.h: what rom_adapt.c shares with its companion sources (internal to src/reduced). */
#ifndef GALLOP_REDUCED_ADAPT_H
#define GALLOP_REDUCED_ADAPT_H

#include "gallop/reduced/rom_adapt.h"

/* The orbit's corrections of family f (rom_orbit.c) into dir (ndof x *K, each unit in the mass
 * norm; *K: 1 or 2 in, how many out): the Hann-weighted mean of the family's correction sampled
 * along old's run on from du (the failing check's), and the dominant direction of the rest (their
 * weighted POD in chk's norm, when it carries more than round-off). old is left where the sampling
 * ended. GAL_OK, or GAL_ENOMEM / GAL_EFAIL. */
int gal_rom_adapt_orbit_correction(gal_rom_adapt *a, gal_rom *old, const gal_rom_check *chk, const double *du, int f,
                                   int *K, double *dir);

/* The size of the basis with nsel modes and nextra corrections (before deflation). */
static inline int gal_rom_adapt_basis_size(const gal_rom_adapt *a, int nsel, int nextra)
{
    return nsel + (a->o.derivatives ? nsel * (nsel + 1) / 2 : 0) + nextra +
           (!a->o.manifold && a->o.weight_vector) + (!a->o.manifold && a->o.wind_vector && a->o.mean_load);
}

/* The ringing growth (rom_third.c, rom_adapt.h GAL_ROM_RING_OUTSIDE) and the cubic growth of family f
 * (rom_third.c): the new extra vectors into a (their count into *corr), or GAL_ROM_ELIMIT with a
 * message and nothing changed. */
int gal_rom_adapt_ring_growth(gal_rom_adapt *a, const gal_rom *old, const gal_rom_check *chk, int *corr);
int gal_rom_adapt_third_growth(gal_rom_adapt *a, const gal_rom *old, const gal_rom_check *chk, int f, int *corr);

#endif
