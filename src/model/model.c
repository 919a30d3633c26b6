/* model.c: scene -> model (model.h; DESIGN.md "The rod", "Aerodynamics", "Wind": only what the
 * scene calls for). */
#include "gallop/model/model.h"
#include "gallop/base/core.h"
#include "gallop/loads/windfield.h"
#include "gallop/model/stringing.h"
#include "gallop/model/tables.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The sub-conductors' differential-stretch fields of an equivalent bundle (src/rod/bundle_irvine.c):
 * with S = sum_k p_k p_k^T over the offsets p_k = R (cos a_k, sin a_k) (horizontal, vertical; a_k
 * the orientation plus 2 pi k / n), the fields are S's eigenvectors of non-zero eigenvalue lambda:
 * for 3 to 8 sub-conductors S = (n R^2 / 2) I (two fields, horizontal and vertical), for a twin
 * 2 p_1 p_1^T (one field, along p_1). Stiffness EA_sub lambda, inertia m_sub lambda plus the spacers'
 * (half their inertia about the bundle axis, about each axis across: a plane frame) smeared over
 * the chord. With the twist free at the supports the yokes do not hold the fields: none. */
static void bundle_fields(const gal_scene *sc, gal_rod_params *p, double EA1, double m1)
{
    int n = sc->bundle.subconductors;
    double R = sc->bundle.radius, L = sc->span.length, h = sc->span.height_difference;
    double chord = sqrt(L * L + h * h), a = sc->bundle.orientation;
    if (!p->torsion || !p->twist_clamped) return;
    p->bundle_fields = n == 2 ? 1 : 2;
    double lambda = n == 2 ? 2 * R * R : n * R * R / 2;
    p->bundle_field_k = EA1 * lambda;
    p->bundle_field_inertia = m1 * lambda + sc->bundle.spacers * 0.5 * sc->bundle.spacer_inertia / chord;
    if (n == 2) p->bundle_field_dir[0][0] = cos(a), p->bundle_field_dir[0][1] = sin(a);
    else p->bundle_field_dir[0][0] = 1, p->bundle_field_dir[1][1] = 1;
}

/* A bundle carried as one rod (the equivalent model): n sub-conductors at radius R on the bundle
 * circle, each the scene's conductor with its ice and its share of the span's tension, all moving
 * with the bundle's centre and twist (rigid spacers, the sub-conductors clamped at the yokes).
 * Stiffness, mass and tension are n times one sub-conductor's (its sag is the bundle's), the spacers
 * smeared over the chord; the polar inertia adds each sub-conductor's m R^2 and the spacers'; the
 * twist is stiffened by the sub-conductors' tension, T R^2 (src/rod/bundle.c). Bending stays n EI:
 * between spacers the sub-conductors bend about their own axes. */
static void bundle_equivalent(const gal_scene *sc, gal_model_rod *r)
{
    gal_rod_params *p = &r->p;
    int n = sc->bundle.subconductors;
    double R = sc->bundle.radius, L = sc->span.length, h = sc->span.height_difference;
    double chord = sqrt(L * L + h * h), m1 = p->mass;
    p->EA *= n, p->EI *= n, p->GJ *= n;
    p->mass = n * m1 + sc->bundle.spacers * sc->bundle.spacer_mass / chord;
    p->polar_inertia = n * (p->polar_inertia + m1 * R * R) +
                       sc->bundle.spacers * sc->bundle.spacer_inertia / chord;
    p->ecc_mass *= n; /* every sub-conductor's ice, at the same offset from its own axis */
    p->bundle_radius2 = R * R;
    if (r->spec == GAL_BY_TENSION) r->spec_value *= n;
    bundle_fields(sc, p, p->EA / n, m1);
}

/* The rod of the span: its parameters and equilibrium specification. */
static int rod_params(const gal_scene *sc, gal_model_rod *r)
{
    gal_rod_params *p = &r->p;
    memset(r, 0, sizeof *r);
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
    int st = gal_stringing_spec(sc, p->gravity, &r->spec, &r->spec_value); /* tension, sag or length */
    if (st != GAL_OK) return st;
    /* explicit: the rod is one sub-conductor's (src/bundle/ builds the bundle from it) */
    if (sc->bundle.subconductors > 1 && !sc->bundle.explicit_model) bundle_equivalent(sc, r);
    p->unstretched_length = r->spec == GAL_BY_LENGTH ? r->spec_value : 0.0;
    return GAL_OK;
}

/* The loads' configuration: only the effects the scene asks for. */
static void loads_config(const gal_scene *sc, gal_loads *L)
{
    memset(L, 0, sizeof *L);
    L->flags = (sc->effect[GAL_FX_AERO_DRAG] ? GAL_AERO_DRAG : 0u) | (sc->effect[GAL_FX_AERO_LIFT] ? GAL_AERO_LIFT : 0u) |
               (sc->effect[GAL_FX_AERO_MOMENT] && sc->effect[GAL_FX_TORSION] ? GAL_AERO_MOMENT : 0u);
    L->aero_damping = sc->effect[GAL_FX_AERO_DAMPING];
    /* the n sub-conductors of a bundle: n times the air density for the single-rod onset criteria
     * (Den Hartog, Nigol); the loads sum the sub-conductors' (gal_loads_bundle_set below) */
    L->rho = sc->wind.air_density * sc->bundle.subconductors;
    L->diam = sc->conductor.diameter;
    L->attack_angle = sc->ice.present ? sc->ice.attack_angle : 0.0;
    L->speed = sc->wind.speed;
    L->dir[0] = cos(sc->wind.yaw), L->dir[1] = sin(sc->wind.yaw), L->dir[2] = 0;
    L->ramp_time = sc->simulation.wind_ramp;
    L->reverse_time = sc->simulation.wind_reverse_time;
    /* the equivalent bundle's section load: its sub-conductors' summed (src/loads/bundle_section.c) */
    if (sc->bundle.subconductors > 1 && !sc->bundle.explicit_model)
        gal_loads_bundle_set(L, sc->bundle.subconductors, sc->bundle.radius, sc->bundle.orientation,
                             sc->wind.air_density, sc->bundle.wake_factor);
}

/* The loads, their table and the turbulent field's parameters. */
static int loads(const gal_scene *sc, gal_model *m)
{
    loads_config(sc, &m->loads);
    if (!(m->loads.flags && sc->wind.speed > 0)) return GAL_OK;
    int st = gal_model_aero_table(sc, &m->table); /* the scene's, or a bare conductor's */
    if (st) return st;
    m->loads.table = m->table;
    m->turbulence = sc->effect[GAL_FX_TURBULENCE];
    if (m->turbulence) return gal_windfield_params(sc, &m->wind); /* the same field as `gallop wind` */
    return GAL_OK;
}

gal_model *gal_model_free(gal_model *m)
{
    if (m) {
        free(m->rod);
        free(m->coupling);
        gal_aero_table_free(m->table);
        free(m);
    }
    return NULL;
}

gal_model *gal_model_alloc(const gal_scene *sc, int *status)
{
    int st = GAL_OK;
    gal_model *m = calloc(1, sizeof *m);
    if (!m || !(m->rod = calloc(1, sizeof *m->rod))) {
        st = gal_error(GAL_ENOMEM, "out of memory for the model of %s", sc->path);
        goto done;
    }
    m->sc = *sc;
    m->nrods = 1;
    if ((st = rod_params(sc, &m->rod[0]))) goto done;
    gal_statics_default_opts(&m->statics);
    m->want[GAL_FAMILY_VERTICAL] = sc->model.modes_vertical;
    m->want[GAL_FAMILY_HORIZONTAL] = sc->model.modes_horizontal;
    m->want[GAL_FAMILY_TORSIONAL] = sc->effect[GAL_FX_TORSION] ? sc->model.modes_torsional : 0;
    m->max_modes = GAL_MODES_MAX;
    m->damping_ratio = sc->effect[GAL_FX_DAMPING] ? sc->conductor.damping_ratio : 0;
    if ((st = loads(sc, m))) goto done;
    m->start_mean_wind = sc->simulation.start_mean_wind;
    m->nprobe = sc->simulation.nprobes;
    memcpy(m->probe, sc->simulation.probes, sizeof m->probe);
done:
    if (status) *status = st;
    if (st) return gal_model_free(m);
    return m;
}
