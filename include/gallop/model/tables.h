/* tables.h: the tables a model is built with, read from the files its scene names: the
 * aerodynamic coefficients of the conductor section (DESIGN.md "Aerodynamics"). */
#ifndef GALLOP_MODEL_TABLES_H
#define GALLOP_MODEL_TABLES_H

#include "gallop/loads/aero.h"
#include "gallop/scene/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The section's aerodynamic table: the scene's [ice] aero_table when it has one, else the
 * built-in table of a bare stranded conductor (a circular cylinder at subcritical Reynolds
 * number: C_D = 1, no lift or moment). *out is set on success (free it with
 * gal_aero_table_free), NULL otherwise. A table that cannot be read or is wrong is GAL_EINPUT
 * (GAL_ENOMEM when out of memory) with the message "SCENE:LINE: [ice] aero_table = VALUE: what
 * the table reader found; allowed: ..." ("--set: ..." when a --set gave it), as the scene reader
 * words its own. */
int gal_model_aero_table(const gal_scene *sc, gal_aero_table **out);

#ifdef __cplusplus
}
#endif

#endif
