/* report.h: the output files of `gallop modes` (DESIGN.md "Command line", "summary.json"), each
 * written to a temporary file and renamed, so that nothing half-written is left on failure. */
#ifndef GALLOP_REPORT_H
#define GALLOP_REPORT_H

#include <stdio.h>

#include "gallop/modes/modes.h"
#include "gallop/output/json.h"
#include "gallop/output/outset.h"
#include "gallop/scene/scene.h"
#include "gallop/statics/statics.h"

#ifdef __cplusplus
extern "C" {
#endif

/* DIR/summary.json, DIR/modes.csv, DIR/shapes.csv, DIR/equilibrium.csv; `want` is what the scene
 * asked per family. */
int gal_report_modes(const char *dir, const gal_scene *sc, const gal_equilibrium *eq,
                     const gal_modes *md, const int want[GAL_FAMILY_COUNT], double wall_time_s);

/* DIR's modes.csv through the output set o: one line per mode (DESIGN.md "modes.csv"); with `subspan`,
 * the explicit bundle's extra column share_subspan. */
int gal_report_modes_csv(gal_outset *o, const gal_modes *md, int subspan);

/* The table of `gallop modes` (equilibrium figures, then one line per selected mode). */
void gal_report_modes_table(FILE *fp, const gal_scene *sc, const gal_equilibrium *eq,
                            const gal_modes *md, const int want[GAL_FAMILY_COUNT], double wall_time_s);

/* summary.json's "families" object into j: each family's modes asked and selected. */
void gal_report_families_json(gal_json *j, const gal_modes *md, const int want[GAL_FAMILY_COUNT]);

/* The table's notes on the selection (gal_modes_select): each torsional partner with the vertical
 * mode it was added for, and each family with fewer selected than asked. */
void gal_report_modes_notes(FILE *fp, const gal_modes *md, const int want[GAL_FAMILY_COUNT]);

#ifdef __cplusplus
}
#endif

#endif
