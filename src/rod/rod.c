/* rod.c: the discrete Cosserat rod (paper Eqs. 1-5, DESIGN.md "The rod"): construction (free
 * dofs, rest lengths, reference frames), rest length changes, gather/scatter and tensions. */
#include "gallop/base/core.h"
#include "rod_impl.h"
#include "gallop/base/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- construction ---- */

gal_rod *gal_rod_free(gal_rod *rod)
{
    if (rod) {
        free(rod->dof);
        free(rod->free_q);
        free(rod->l0);
        free(rod->tbar);
        free(rod->abar);
        free(rod->node_mass);
        free(rod->edge_inertia);
        free(rod->q0);
        gal_csc_free(rod->K);
        gal_csc_free(rod->M);
        free(rod->ecc_c);
        free(rod->mdiag);
        free(rod->slot_node);
        free(rod->slot_edge);
        free(rod);
    }
    return NULL;
}

/* Free dofs numbered node by node (positions, then the twist and the bundle fields of the edge
 * that follows), so that the tangent is banded before any reordering. */
static void number_dofs(gal_rod *rod)
{
    int nn = rod->nn, nel = rod->p.elements, nd = 0, nf = rod->p.torsion ? rod->p.bundle_fields : 0;
    for (int k = 0; k < rod->nq; k++) rod->dof[k] = -1;
    for (int i = 0; i < nn; i++) {
        if (i > 0 && i < nn - 1)
            for (int k = 0; k < 3; k++) rod->free_q[nd] = 3 * i + k, rod->dof[3 * i + k] = nd++;
        if (rod->p.torsion && i < nel)
            for (int f = 0; f <= nf; f++) {
                int k = 3 * nn + f * nel + i;
                rod->free_q[nd] = k, rod->dof[k] = nd++;
            }
    }
    rod->ndof = nd;
}

int gal_rod_nq(const gal_rod_params *p)
{
    int nel = p->elements;
    return 3 * (nel + 1) + (p->torsion ? (1 + p->bundle_fields) * nel : 0);
}

gal_rod *gal_rod_alloc(const gal_rod_params *p, const double *q0)
{
    if (p->elements < 2 || !(p->length > 0) || !(p->unstretched_length > 0) || !(p->EA > 0) ||
        !(p->EI >= 0) || !(p->mass > 0) || (p->torsion && (!(p->GJ > 0) || !(p->polar_inertia > 0))) ||
        p->bundle_fields < 0 || p->bundle_fields > 2 ||
        (p->bundle_fields && (!p->torsion || !(p->bundle_field_k > 0) || !(p->bundle_field_inertia > 0)))) {
        gal_error(GAL_EINPUT, "rod: invalid parameters (elements %d, length %g, L0 %g, EA %g, EI %g, "
                  "GJ %g, mass %g, polar inertia %g)", p->elements, p->length, p->unstretched_length,
                  p->EA, p->EI, p->GJ, p->mass, p->polar_inertia);
        return NULL;
    }
    gal_rod *rod = calloc(1, sizeof *rod);
    if (!rod) return NULL;
    rod->p = *p;
    int nel = p->elements, nn = nel + 1;
    rod->nn = nn;
    rod->nq = gal_rod_nq(p);
    rod->dof = malloc((size_t)rod->nq * sizeof(int));
    rod->free_q = malloc((size_t)rod->nq * sizeof(int));
    rod->l0 = malloc((size_t)nel * sizeof(double));
    rod->tbar = malloc((size_t)3 * nel * sizeof(double));
    rod->abar = malloc((size_t)3 * nel * sizeof(double));
    rod->node_mass = calloc((size_t)nn, sizeof(double));
    rod->edge_inertia = calloc((size_t)nel * (1 + (p->torsion ? p->bundle_fields : 0)), sizeof(double));
    rod->q0 = malloc((size_t)rod->nq * sizeof(double));
    if (!rod->dof || !rod->free_q || !rod->l0 || !rod->tbar || !rod->abar || !rod->node_mass ||
        !rod->edge_inertia || !rod->q0) {
        gal_error(GAL_ENOMEM, "rod: out of memory for %d elements", nel);
        return gal_rod_free(rod);
    }
    memcpy(rod->q0, q0, (size_t)rod->nq * sizeof(double));

    number_dofs(rod);
    gal_rod_set_unstretched_length(rod, p->unstretched_length);
    if (gal_rod_frames_init(rod, q0) != GAL_OK) return gal_rod_free(rod);
    if (gal_rod_pattern_build(rod) != GAL_OK || !(rod->M = gal_csc_clone(rod->K))) {
        gal_error(GAL_ENOMEM, "rod: out of memory building the stiffness pattern");
        return gal_rod_free(rod);
    }
    if (gal_rod_ice_init(rod) != GAL_OK) return gal_rod_free(rod);
    gal_rod_terms_init(rod);
    gal_rod_mass_build(rod);
    return rod;
}

void gal_rod_set_unstretched_length(gal_rod *rod, double L0)
{
    int nel = rod->p.elements;
    double l0 = L0 / nel;
    rod->p.unstretched_length = L0;
    for (int i = 0; i < rod->nn; i++) rod->node_mass[i] = 0;
    for (int j = 0; j < nel; j++) {
        rod->l0[j] = l0;
        rod->node_mass[j] += 0.5 * rod->p.mass * l0;
        rod->node_mass[j + 1] += 0.5 * rod->p.mass * l0;
        rod->edge_inertia[j] = rod->p.polar_inertia * l0;
        for (int f = 0; rod->p.torsion && f < rod->p.bundle_fields; f++)
            rod->edge_inertia[(1 + f) * nel + j] = rod->p.bundle_field_inertia * l0;
    }
    gal_rod_mass_build(rod);
}

void gal_rod_gather(const gal_rod *rod, const double *full, double *free_part)
{
    for (int d = 0; d < rod->ndof; d++) free_part[d] = full[rod->free_q[d]];
}

void gal_rod_scatter(const gal_rod *rod, const double *free_part, double *full)
{
    for (int d = 0; d < rod->ndof; d++) full[rod->free_q[d]] = free_part[d];
}

void gal_rod_tensions(const gal_rod *rod, const double *q, double *tension)
{
    for (int j = 0; j < rod->p.elements; j++) {
        double e[3];
        for (int k = 0; k < 3; k++) e[k] = q[3 * (j + 1) + k] - q[3 * j + k];
        tension[j] = rod->p.EA * (gal_norm3(e) / rod->l0[j] - 1.0);
    }
}
