/* gallop.h: the public API of libgallop, a modal-reduction analysis library for the galloping of
 * overhead transmission conductors (Cosserat rod, paper Eqs. 1-10): every public header, in the
 * order of the pipeline (tests/test_header.sh checks that none is missing). */
#ifndef GALLOP_H
#define GALLOP_H

/* base: status and errors, output files, vectors, sparse matrices */
#include "gallop/base/error.h"
#include "gallop/base/core.h"
#include "gallop/base/vec3.h"
#include "gallop/base/sparse.h"
#include "gallop/base/datadir.h"
/* scene: a scene file read, checked and resolved */
#include "gallop/scene/scene.h"
#include "gallop/scene/terrain.h"
/* model: from the scene to the discretized span and its tables */
#include "gallop/model/model.h"
#include "gallop/model/stringing.h"
#include "gallop/model/tables.h"
#include "gallop/model/damping.h"
#include "gallop/model/force.h"
/* rod: the discrete Cosserat rod */
#include "gallop/rod/rod.h"
/* statics: the sagged equilibrium */
#include "gallop/statics/catenary.h"
#include "gallop/statics/statics.h"
/* modes: natural modes about the equilibrium */
#include "gallop/modes/modes.h"
/* bundle: the explicit bundle model (one rod per sub-conductor, rigid spacers) */
#include "gallop/bundle/bundle.h"
#include "gallop/bundle/bundle_dyn.h"
#include "gallop/bundle/bundle_rom.h"
/* loads: aerodynamic tables and section loads, wind */
#include "gallop/loads/aero.h"
#include "gallop/loads/loads.h"
#include "gallop/loads/wind.h"
#include "gallop/loads/windfield.h"
/* full: the full model's time integration */
#include "gallop/full/dynamics.h"
/* reduced: the reduced model (modes and modal derivatives, recomputed forces) */
#include "gallop/reduced/rom.h"
#include "gallop/reduced/ecsw.h"
#include "gallop/reduced/rom_adapt.h"
#include "gallop/reduced/rom_turb.h"
#include "gallop/reduced/rom_sim.h"
/* run: galloping runs */
#include "gallop/run/forward.h"
#include "gallop/run/integrator.h"
#include "gallop/run/onset_scene.h"
#include "gallop/run/sim.h"
#include "gallop/run/sweep.h"
/* analysis: spectra, stability, galloping onset, accuracy */
#include "gallop/analysis/spectrum.h"
#include "gallop/analysis/stability.h"
#include "gallop/analysis/onset.h"
#include "gallop/analysis/accuracy.h"
#include "gallop/analysis/measure.h"
#include "gallop/analysis/compare.h"
#include "gallop/analysis/trace_spectrum.h"
#include "gallop/analysis/windstats.h"
#include "gallop/analysis/cigre.h"
/* output: reports and files */
#include "gallop/output/report.h"
#include "gallop/output/simreport.h"
#include "gallop/output/cigrereport.h"
#include "gallop/output/json.h"
#include "gallop/output/ofile.h"
#include "gallop/output/accreport.h"
#include "gallop/output/outset.h"
#include "gallop/output/record.h"
#include "gallop/output/specreport.h"
#include "gallop/output/stabreport.h"
#include "gallop/output/sweepreport.h"
#include "gallop/output/windreport.h"
#endif
