/* gallop.h: the public API of libgallop, a modal-reduction analysis library for the galloping of
 * overhead transmission conductors (Cosserat rod, paper Eqs. 1-10). */
#ifndef GALLOP_H
#define GALLOP_H
#include "gallop/core.h"
#include "gallop/aero.h"
#include "gallop/wind.h"
#include "gallop/spectrum.h"
#endif
