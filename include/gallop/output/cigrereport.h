/* cigrereport.h: the CIGRE TB 322 outputs of a galloping run in its summary.json (analysis/cigre.h):
 * per probe the galloping ellipse and its clearances to the scene's neighbouring phases, for the
 * run the dynamic support tensions and the span's amplitude beside the empirical envelope. */
#ifndef GALLOP_OUTPUT_CIGREREPORT_H
#define GALLOP_OUTPUT_CIGREREPORT_H

#include "gallop/output/json.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* "ellipse" and "clearances" members of probe k's object, over samples from steady_from_s on. */
int gal_cigre_json_probe(gal_json *j, const gal_scene *sc, const gal_sim_result *r, int k, double steady_from_s);
/* "support_tensions" and "cigre_envelope" members of the run's object; steady_from_s[k] is probe
 * k's window; rts_n the conductor's rated tensile strength (N; NaN when unknown: its keys are left out). */
int gal_cigre_json_run(gal_json *j, const gal_scene *sc, const gal_sim_result *r, const double *steady_from_s,
                       double rts_n);

#ifdef __cplusplus
}
#endif

#endif
