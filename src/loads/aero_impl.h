/* aero_impl.h: what the files of the aerodynamic tables share inside src/loads/ (not public):
 * the coefficient names and the check-and-build of a table from rows (table.c), used by the CSV
 * reader (table_read.c) and gal_aero_table_make. */
#ifndef GALLOP_AERO_IMPL_H
#define GALLOP_AERO_IMPL_H

#include "gallop/loads/aero.h"

extern const char *const gal_aero_coef_name[3]; /* "cd", "cl", "cm" */

/* Validate rows (alpha in degrees) and build the splines. `line` (may be NULL) gives the file
 * line of each row for messages; `col` (may be NULL) the column where each of the 4 fields
 * starts, row-major. NULL with *status and a message on error. */
gal_aero_table *gal_aero_table_build(const char *name, const char *source, int rows,
                                     const double *adeg, const double *cd, const double *cl,
                                     const double *cm, const int *line, const int *col, int *status);

#endif
