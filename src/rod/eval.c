/* eval.c: the rod's energy, forces and sparse tangent stiffness (paper Eqs. 1-8) as the sum over
 * its list of terms, one per physical effect that is on (rod.h lists them and their files); the
 * node terms that follow each other share one pass over the nodes (node.c). */
#include "gallop/base/core.h"
#include "rod_impl.h"

#include <math.h>
#include <string.h>

void gal_rod_terms_init(gal_rod *rod)
{
    const gal_rod_params *p = &rod->p;
    int n = 0;
    rod->term[n++] = &gal_rod_term_extension;                   /* EA > 0 (checked at alloc) */
    if (p->EI > 0) rod->term[n++] = &gal_rod_term_bending;
    if (p->torsion) rod->term[n++] = &gal_rod_term_torsion;
    if (p->torsion && p->bundle_radius2 > 0) rod->term[n++] = &gal_rod_term_bundle_torsion;
    if (p->torsion && p->twist_clamped) rod->term[n++] = &gal_rod_term_torsion_clamps;
    if (p->torsion && p->twist_clamped && p->bundle_radius2 > 0)
        rod->term[n++] = &gal_rod_term_bundle_clamps;
    if (p->torsion && p->twist_clamped && p->bundle_fields > 0) rod->term[n++] = &gal_rod_term_bundle_irvine;
    if (rod->ecc_c && p->gravity != 0) rod->term[n++] = &gal_rod_term_ice;
    if (p->gravity != 0) rod->term[n++] = &gal_rod_term_gravity;
    rod->nterm = n;
}

/* Clear the outputs, add the terms k0 <= k < k1 (frames, *framed: gal_rod_node_pass). */
static int sum(const gal_rod *rod, int k0, int k1, const double *q, double *energy, double *grad,
               gal_csc *K, double *frames, int *framed)
{
    double U = 0.0;
    if (grad) memset(grad, 0, (size_t)rod->nq * sizeof(double));
    if (K) memset(K->val, 0, (size_t)K->nnz * sizeof(double));
    for (int k = k0; k < k1;) {
        int st, k2 = k;
        if (rod->term[k]->node) { /* a run of node terms: one pass */
            while (k2 < k1 && rod->term[k2]->node) k2++;
            st = gal_rod_node_pass(rod, rod->term + k, k2 - k, q, &U, grad, K, frames, framed);
        } else {
            st = rod->term[k]->eval(rod, q, &U, grad, K);
            k2 = k + 1;
        }
        if (st) return st;
        k = k2;
    }
    if (energy) *energy = U;
    if (!isfinite(U)) return gal_error(GAL_EFAIL, "rod: the energy is not finite");
    return GAL_OK;
}

int gal_rod_eval(const gal_rod *rod, const double *q, double *energy, double *grad, gal_csc *K)
{
    return sum(rod, 0, rod->nterm, q, energy, grad, K, NULL, NULL);
}

int gal_rod_eval_frames(const gal_rod *rod, const double *q, double *energy, double *grad, gal_csc *K,
                        double *frames)
{
    int framed = 0, st = sum(rod, 0, rod->nterm, q, energy, grad, K, frames, &framed);
    for (int j = 0; j < rod->p.elements && !st && !framed; j++) gal_rod_edge_frame(rod, q, j, frames + 6 * j);
    return st;
}

int gal_rod_eval_term(const gal_rod *rod, int k, const double *q, double *energy, double *grad,
                      gal_csc *K)
{
    if (k < 0 || k >= rod->nterm)
        return gal_error(GAL_EINPUT, "rod: term %d of %d", k, rod->nterm);
    return sum(rod, k, k + 1, q, energy, grad, K, NULL, NULL);
}
