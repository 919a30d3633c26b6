/* extension.c: the rod's axial strain energy (paper Eq. 5, EA (v3 - 1)^2), per edge
 * U = EA/2 (|e|/l0 - 1)^2 l0, its gradient and tangent in closed form. */
#include "gallop/base/core.h"
#include "rod_impl.h"
#include "gallop/base/vec3.h"

#include <math.h>

/* Add the edge Hessian H (over e = x_{j+1} - x_j) to the 6 x 6 block of nodes j, j + 1. */
static void add_edge(const gal_rod *rod, int j, double H[3][3], gal_csc *K)
{
    const int *s = rod->slot_edge + (size_t)j * EL * EL;
    for (int a = 0; a < EL; a++)
        for (int b = 0; b < EL; b++) {
            int sl = s[a * EL + b];
            if (sl < 0) continue;
            double sg = ((a < 3) == (b < 3)) ? 1.0 : -1.0;
            K->val[sl] += sg * H[a % 3][b % 3];
        }
}

static int eval(const gal_rod *rod, const double *q, double *U, double *grad, gal_csc *K)
{
    const gal_rod_params *p = &rod->p;
    for (int j = 0; j < p->elements; j++) {
        double e[3], l0 = rod->l0[j];
        for (int k = 0; k < 3; k++) e[k] = q[3 * (j + 1) + k] - q[3 * j + k];
        double le = gal_norm3(e);
        if (!(le > 1e-12 * l0)) return gal_error(GAL_EFAIL, "rod: element %d has collapsed (length %g m)", j, le);
        double eps = le / l0 - 1.0, t[3] = {e[0] / le, e[1] / le, e[2] / le};
        *U += 0.5 * p->EA * eps * eps * l0;
        if (grad)
            for (int k = 0; k < 3; k++) {
                double g = p->EA * eps * t[k];   /* dU/de = EA eps t */
                grad[3 * j + k] -= g;
                grad[3 * (j + 1) + k] += g;
            }
        if (K) {
            /* d2U/de2 = EA/l0 t t^T + EA eps/|e| (I - t t^T) */
            double H[3][3];
            for (int a = 0; a < 3; a++)
                for (int b = 0; b < 3; b++)
                    H[a][b] = p->EA / l0 * t[a] * t[b] + p->EA * eps / le * ((a == b) - t[a] * t[b]);
            add_edge(rod, j, H, K);
        }
    }
    return GAL_OK;
}

/* Edge j alone over (x_j, x_{j+1}, theta_j): g = (-EA eps t, EA eps t, 0), H = [H -H; -H H]. */
static int edge(const gal_rod *rod, int j, const double *q, double *U, double *g, double (*H)[7])
{
    const gal_rod_params *p = &rod->p;
    double e[3], l0 = rod->l0[j];
    for (int k = 0; k < 3; k++) e[k] = q[3 * (j + 1) + k] - q[3 * j + k];
    double le = gal_norm3(e);
    if (!(le > 1e-12 * l0)) return gal_error(GAL_EFAIL, "rod: element %d has collapsed (length %g m)", j, le);
    double eps = le / l0 - 1.0, t[3] = {e[0] / le, e[1] / le, e[2] / le};
    *U += 0.5 * p->EA * eps * eps * l0;
    for (int k = 0; k < 3; k++) g[k] -= p->EA * eps * t[k], g[3 + k] += p->EA * eps * t[k];
    if (H)
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                double h = p->EA / l0 * t[a] * t[b] + p->EA * eps / le * ((a == b) - t[a] * t[b]);
                H[a][b] += h, H[3 + a][3 + b] += h, H[a][3 + b] -= h, H[3 + a][b] -= h;
            }
    return GAL_OK;
}

const gal_rod_term gal_rod_term_extension = {"extension", eval, NULL, edge};
