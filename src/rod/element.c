/* element.c: the rod's energy split into energy elements (rod.h: U = sum_e U_e, the edge terms of
 * each edge and the node terms of each interior node apart, so that the split is its own mirror
 * image) for hyper-reduction (energy-conserving sampling and weighting, Farhat, Avery, Chapman &
 * Cortial 2014): one element's energy, gradient and Hessian over its 11 local configuration
 * entries, and the weighted sum over a sampled set, a conservative energy in its own right (a
 * non-negative combination of the element energies). */
#include "gallop/base/core.h"
#include "rod_impl.h"

#include <math.h>
#include <string.h>

/* element-local index of edge-local variable a (x_e, x_{e+1}, theta_e) */
static const int edge_to_el[7] = {0, 1, 2, 3, 4, 5, 9};

int gal_rod_element_form(const gal_rod *rod)
{
    for (int k = 0; k < rod->nterm; k++)
        if (!rod->term[k]->node && !rod->term[k]->edge) return 0;
    return 1;
}

int gal_rod_element_count(const gal_rod *rod)
{
    return rod->p.elements + rod->nn - 2;
}

int gal_rod_element_mirror(const gal_rod *rod, int e)
{
    int nel = rod->p.elements;
    return e < nel ? nel - 1 - e : nel + (rod->nn - 1 - (e - nel + 1)) - 1;
}

void gal_rod_element_q(const gal_rod *rod, int e, int qi[GAL_ROD_ELEMENT_NQ])
{
    int nel = rod->p.elements;
    if (e >= nel) {
        gal_rod_node_q(rod, e - nel + 1, qi);
        return;
    }
    for (int k = 0; k < 6; k++) qi[k] = 3 * e + k; /* an edge */
    qi[6] = qi[7] = qi[8] = qi[10] = -1;
    qi[9] = rod->p.torsion ? 3 * rod->nn + e : -1;
}

int gal_rod_element_eval(const gal_rod *rod, int e, const double *q, double *energy, double *g, double *H)
{
    const int NQ = GAL_ROD_ELEMENT_NQ;
    int nel = rod->p.elements, st = GAL_OK;
    double U = 0, ge[7] = {0}, He[7][7];
    memset(g, 0, NQ * sizeof(double));
    if (H) memset(H, 0, NQ * NQ * sizeof(double)), memset(He, 0, sizeof He);
    if (e >= nel) { /* the node terms at node i, by runs of them */
        for (int k = 0; k < rod->nterm && !st;) {
            int k2 = k;
            while (k2 < rod->nterm && rod->term[k2]->node) k2++;
            if (k2 > k) st = gal_rod_node_local(rod, rod->term + k, k2 - k, e - nel + 1, q, &U, g, H);
            k = k2 + 1;
        }
    } else {
        for (int k = 0; k < rod->nterm && !st; k++) {
            const gal_rod_term *t = rod->term[k];
            if (t->node) continue;
            if (!t->edge) return gal_error(GAL_EINPUT, "rod: the term %s has no element form", t->name);
            st = t->edge(rod, e, q, &U, ge, H ? He : NULL);
        }
        for (int a = 0; a < 7; a++) {
            g[edge_to_el[a]] += ge[a];
            if (H)
                for (int b = 0; b < 7; b++) H[edge_to_el[a] * NQ + edge_to_el[b]] += He[a][b];
        }
    }
    if (st) return st;
    *energy = U;
    if (!isfinite(U)) return gal_error(GAL_EFAIL, "rod: the energy of element %d is not finite", e);
    return GAL_OK;
}

int gal_rod_eval_weighted(const gal_rod *rod, int n, const int *elem, const double *w, const double *q,
                          double *energy, double *grad, gal_csc *K)
{
    const int NQ = GAL_ROD_ELEMENT_NQ;
    double U = 0, g[GAL_ROD_ELEMENT_NQ], H[GAL_ROD_ELEMENT_NQ * GAL_ROD_ELEMENT_NQ];
    int qi[GAL_ROD_ELEMENT_NQ];
    if (grad) memset(grad, 0, (size_t)rod->nq * sizeof(double));
    if (K) memset(K->val, 0, (size_t)K->nnz * sizeof(double));
    for (int k = 0; k < n; k++) {
        double Ue;
        int e = elem[k];
        if (e < 0 || e >= gal_rod_element_count(rod))
            return gal_error(GAL_EINPUT, "rod: energy element %d of %d", e, gal_rod_element_count(rod));
        int st = gal_rod_element_eval(rod, e, q, &Ue, g, K ? H : NULL);
        if (st) return st;
        U += w[k] * Ue;
        gal_rod_element_q(rod, e, qi);
        for (int a = 0; a < NQ; a++) {
            if (qi[a] < 0) continue;
            if (grad) grad[qi[a]] += w[k] * g[a];
            int da = rod->dof[qi[a]];
            if (!K || da < 0) continue;
            for (int b = 0; b < NQ; b++) { /* the upper triangle: row <= column */
                int db = qi[b] < 0 ? -1 : rod->dof[qi[b]];
                if (db < da) continue;
                int sl = gal_csc_find(K, da, db);
                if (sl >= 0) K->val[sl] += w[k] * H[a * NQ + b];
            }
        }
    }
    if (energy) *energy = U;
    return GAL_OK;
}
