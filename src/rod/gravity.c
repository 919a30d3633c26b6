/* gravity.c: the weight of the rod, U = sum_i m_i g z_i over the lumped node masses (conductor
 * plus ice); its tangent is zero. */
#include "gallop/base/core.h"
#include "rod_impl.h"

static int eval(const gal_rod *rod, const double *q, double *U, double *grad, gal_csc *K)
{
    (void)K;
    double g = rod->p.gravity;
    for (int i = 0; i < rod->nn; i++) {
        *U += rod->node_mass[i] * g * q[3 * i + 2];
        if (grad) grad[3 * i + 2] += rod->node_mass[i] * g;
    }
    return GAL_OK;
}

/* Edge j's share: the weight of node j, and of the last node on the last edge. */
static int edge(const gal_rod *rod, int j, const double *q, double *U, double *g, double (*H)[7])
{
    (void)H;
    double gr = rod->p.gravity;
    *U += rod->node_mass[j] * gr * q[3 * j + 2];
    g[2] += rod->node_mass[j] * gr;
    if (j == rod->p.elements - 1) {
        *U += rod->node_mass[j + 1] * gr * q[3 * (j + 1) + 2];
        g[5] += rod->node_mass[j + 1] * gr;
    }
    return GAL_OK;
}

const gal_rod_term gal_rod_term_gravity = {"gravity", eval, NULL, edge};
