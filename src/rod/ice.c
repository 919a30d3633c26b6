/* ice.c: everything of the eccentric ice on the rod (DESIGN.md "Ice"): a line mass m_i (kg/m) whose
 * centre sits at e (m) from the axis, at angle ecc_angle from the reference director, turning
 * with the twist. Its position x + e c(theta) gives
 *   - the weight moment (the term "ice_eccentricity"): U = sum_j m_i g e l0_j c_z(theta_j), c turned by the
 *     twist about the reference tangent (the tangent's own turn is left out: second order here);
 *   - the mass coupling of twist and translation (in rod->M): the kinetic energy of the ice centre
 *     holds m_i e xdot . (t x c) thetadot, 1/2 l0 m_i e (t x c) to each node of the edge.
 * The scene's side (model.c: ecc_angle = pi - attack angle, the ice on the windward side; scene.c:
 * the ice's polar inertia m_i (r^2 + e^2)) gives the parameters. */
#include "gallop/base/core.h"
#include "rod_impl.h"
#include "gallop/base/vec3.h"

#include <math.h>
#include <stdlib.h>

int gal_rod_ice_init(gal_rod *rod)
{
    const gal_rod_params *p = &rod->p;
    if (!(p->ecc_mass > 0 && p->ecc != 0 && p->torsion)) return GAL_OK; /* no eccentric ice */
    int nel = p->elements;
    rod->ecc_c = malloc((size_t)3 * nel * sizeof(double));
    if (!rod->ecc_c) return gal_error(GAL_ENOMEM, "rod: out of memory");
    for (int j = 0; j < nel; j++) {
        /* c = cos(angle) abar + sin(angle) tbar x abar: the ice centre's direction at zero twist */
        double *t = rod->tbar + 3 * j, *a = rod->abar + 3 * j, b[3];
        gal_cross3(t, a, b);
        for (int k = 0; k < 3; k++) rod->ecc_c[3 * j + k] = cos(p->ecc_angle) * a[k] + sin(p->ecc_angle) * b[k];
    }
    return GAL_OK;
}

/* Add to rod->M the coupling of each edge's twist with the translation of its two nodes. */
void gal_rod_ice_mass(gal_rod *rod)
{
    if (!rod->ecc_c) return;
    gal_csc *M = rod->M;
    int nn = rod->nn;
    for (int j = 0; j < rod->p.elements; j++) {
        int dt = rod->dof[3 * nn + j];
        if (dt < 0) continue;
        double g[3], *c = rod->ecc_c + 3 * j, *t = rod->tbar + 3 * j;
        gal_cross3(t, c, g);
        double f = 0.5 * rod->l0[j] * rod->p.ecc_mass * rod->p.ecc;
        for (int node = j; node <= j + 1; node++)
            for (int k = 0; k < 3; k++) {
                int dx = rod->dof[3 * node + k];
                if (dx < 0) continue;
                int a = dx < dt ? dx : dt, b = dx < dt ? dt : dx;
                int sl = gal_csc_find(M, a, b);
                if (sl >= 0) M->val[sl] += f * g[k];
            }
    }
}

/* The weight moment: U_j = w cz(theta), w = m_i g e l0_j, cz = cos(theta) c_z + sin(theta) (t x c)_z */
static int eval(const gal_rod *rod, const double *q, double *U, double *grad, gal_csc *K)
{
    const gal_rod_params *p = &rod->p;
    int nn = rod->nn;
    for (int j = 0; j < p->elements; j++) {
        int k = 3 * nn + j;
        double *c = rod->ecc_c + 3 * j, *t = rod->tbar + 3 * j, tc[3];
        gal_cross3(t, c, tc);
        double th = q[k], w = p->ecc_mass * p->gravity * p->ecc * rod->l0[j];
        double cz = cos(th) * c[2] + sin(th) * tc[2], dcz = -sin(th) * c[2] + cos(th) * tc[2];
        *U += w * cz;
        if (grad) grad[k] += w * dcz;
        if (K && rod->dof[k] >= 0) K->val[K->diag[rod->dof[k]]] -= w * cz; /* d2cz = -cz */
    }
    return GAL_OK;
}

/* Edge j alone: the weight moment of its ice, over theta_j (local 6). */
static int edge(const gal_rod *rod, int j, const double *q, double *U, double *g, double (*H)[7])
{
    const gal_rod_params *p = &rod->p;
    double *c = rod->ecc_c + 3 * j, *t = rod->tbar + 3 * j, tc[3];
    gal_cross3(t, c, tc);
    double th = q[3 * rod->nn + j], w = p->ecc_mass * p->gravity * p->ecc * rod->l0[j];
    double cz = cos(th) * c[2] + sin(th) * tc[2], dcz = -sin(th) * c[2] + cos(th) * tc[2];
    *U += w * cz;
    g[6] += w * dcz;
    if (H) H[6][6] -= w * cz;
    return GAL_OK;
}

const gal_rod_term gal_rod_term_ice = {"ice_eccentricity", eval, NULL, edge};
