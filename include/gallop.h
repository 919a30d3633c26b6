/* gallop.h: the public API of libgallop, a modal-reduction analysis library for the galloping of
 * overhead transmission conductors (Cosserat rod, paper Eqs. 1-10). */
#ifndef GALLOP_H
#define GALLOP_H
#include "gallop/base/core.h"
#include "gallop/loads/aero.h"
#include "gallop/loads/wind.h"
#include "gallop/analysis/spectrum.h"
#include "gallop/output/json.h"
#include "gallop/output/ofile.h"
#endif
