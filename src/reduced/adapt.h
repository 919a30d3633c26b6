/* adapt.h: what rom_adapt.c takes from its companion sources (internal to src/reduced). */
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

#endif
