/* model.h: the model of a scene (MuJoCo's mjModel), built once from the resolved scene and never
 * changed by any stage: the rods (mesh, material and the effects they carry: bending off is EI = 0,
 * torsion off is no twist unknowns, gravity off is g = 0) with their equilibrium specification, the
 * couplings between rods, the modes the scene selects, the structural damping, the loads'
 * configuration and aerodynamic table, the turbulent wind field's parameters, and the start of a run
 * (the reduced model's controls, model.residual_tolerance and on_invalid, are read from sc). Every
 * stage reads it through a const pointer and writes what it finds into a gal_data (run/forward.h). */
#ifndef GALLOP_MODEL_H
#define GALLOP_MODEL_H

#include "gallop/loads/aero.h"
#include "gallop/loads/loads.h"
#include "gallop/loads/wind.h"
#include "gallop/modes/modes.h"
#include "gallop/rod/rod.h"
#include "gallop/scene/scene.h"
#include "gallop/statics/statics.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GAL_GRAVITY 9.80665 /* m/s^2, standard gravity */

/* The most modes one search computes (gal_modes_find's max_modes). A scene selects at most 200 per
 * family (src/scene/keys.c), 600 in all, and the search doubles its request while a family is
 * short, so the cap must leave room for the modes of other families (axial ones among them) that
 * lie below the highest one selected; beyond it ARPACK's basis (2 nev + 1 vectors of the dofs:
 * 16 MB per 1,000 dofs at 1,000 modes) costs more than any scene needs. gal_modes_find lowers it
 * to the dofs less one on coarse meshes. */
#define GAL_MODES_MAX 1000

/* One conductor: its discretization and material, and how its equilibrium is given. */
typedef struct gal_model_rod {
    gal_rod_params p;        /* p.unstretched_length: the scene's when spec is GAL_BY_LENGTH, else 0
                              * (the equilibrium stage solves for it) */
    gal_statics_spec spec;
    double spec_value;       /* N (horizontal tension), m (sag) or m (unstretched length) */
} gal_model_rod;

/* A spacer joining two rods of a bundle at a point of each (bundles are to come: no scene has
 * one yet, and the pipeline refuses a model with couplings). */
typedef struct gal_coupling {
    int rod[2];              /* indices into gal_model.rod */
    double at[2];            /* fractions of the two spans */
} gal_coupling;

typedef struct gal_model {
    gal_scene sc;            /* the resolved scene it was built from (a copy: its path names the
                              * model in messages) */
    int nrods;
    gal_model_rod *rod;      /* nrods (1 today) */
    int ncouplings;
    gal_coupling *coupling;  /* ncouplings (0 today) */
    gal_statics_opts statics;
    int want[GAL_FAMILY_COUNT]; /* modes selected per family (torsional: 0 with torsion off) */
    int max_modes;           /* GAL_MODES_MAX */
    /* structural damping: a modal ratio, realized as Rayleigh damping C = a M + b K0 fitted to it at
     * the lowest and highest selected modes (the same in full and reduced runs); 0: none */
    double damping_ratio;
    gal_aero_table *table;   /* owned; NULL when no aerodynamic load is on (no wind, or every
                              * aerodynamic effect off) */
    gal_loads loads;         /* the loads' configuration: effects, air, section, mean wind, ramp
                              * and reversal (its rod and turbulence field are the data's) */
    int turbulence;          /* a turbulent field is generated, with these parameters: */
    gal_wind_params wind;
    int start_mean_wind;     /* runs start on the equilibrium under the mean wind (the wind then
                              * blows at full speed from t = 0), else on the sagged equilibrium */
    int nprobe;
    double probe[GAL_MAX_PROBES]; /* fractions of the span where runs record their traces */
} gal_model;

/* Build the model of a resolved scene. NULL with a message (and *status, when status is not NULL,
 * GAL_EINPUT for what the model cannot represent or a table it cannot read, GAL_ENOMEM, GAL_EFAIL)
 * on failure. */
gal_model *gal_model_alloc(const gal_scene *sc, int *status);
gal_model *gal_model_free(gal_model *m);

#ifdef __cplusplus
}
#endif

#endif
