/* model.c: scene -> rod parameters (DESIGN.md "The rod": only what the scene calls for). */
#include "gallop/model/model.h"
#include "gallop/base/core.h"

#include <string.h>

int gal_model_rod_params(const gal_scene *sc, gal_rod_params *p, gal_statics_spec *spec, double *value)
{
    memset(p, 0, sizeof *p);
    if (!sc->effect[GAL_FX_EXTENSION])
        return gal_error(GAL_EINPUT, "%s: [effects] extension = off: a rod without axial stiffness "
                         "has no sagged equilibrium; allowed: on (give a large axial_stiffness for a "
                         "nearly inextensible conductor)", sc->path);
    p->length = sc->span.length;
    p->height_difference = sc->span.height_difference;
    p->elements = sc->model.elements;
    p->EA = sc->conductor.axial_stiffness;
    p->EI = sc->effect[GAL_FX_BENDING] ? sc->conductor.bending_stiffness : 0.0;
    p->GJ = sc->conductor.torsional_stiffness;
    p->mass = sc->conductor.mass_per_length + (sc->ice.present ? sc->ice.mass_per_length : 0.0);
    p->polar_inertia = sc->conductor.polar_inertia + (sc->ice.present ? sc->ice.polar_inertia : 0.0);
    p->gravity = sc->effect[GAL_FX_GRAVITY] ? GAL_GRAVITY : 0.0;
    p->torsion = sc->effect[GAL_FX_TORSION];
    p->twist_clamped = sc->span.end_twist == GAL_TWIST_CLAMPED;
    if (sc->ice.present && sc->effect[GAL_FX_ICE_ECCENTRICITY]) {
        /* the ice centre on the windward side of the section: opposite the reference direction
         * as the loads turn it by the attack angle (src/loads/loads.c) */
        p->ecc_mass = sc->ice.mass_per_length;
        p->ecc = sc->ice.eccentricity;
        p->ecc_angle = GAL_PI - sc->ice.attack_angle;
    }
    switch (sc->span.spec) {
    case GAL_SPEC_TENSION: *spec = GAL_BY_TENSION, *value = sc->span.horizontal_tension; break;
    case GAL_SPEC_SAG: *spec = GAL_BY_SAG, *value = sc->span.sag; break;
    default: *spec = GAL_BY_LENGTH, *value = sc->span.unstretched_length; break;
    }
    p->unstretched_length = *spec == GAL_BY_LENGTH ? *value : 0.0;
    return GAL_OK;
}
