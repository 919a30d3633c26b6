/* bending.c: isotropic bending of the discrete rod (B1 = B2 = EI; paper Eqs. 3-5, Bergou et al.
 * 2008): at each interior node U = EI |kb|^2 / lbar with kb = 2 t0 x t1 / (1 + t0 . t1), written
 * as U = k f(c), f = (1 - c)/(1 + c) = |kb|^2 / 4, k = 4 EI / lbar, c = t0 . t1; gradient and
 * Hessian over the two edges in closed form. */
#include "gallop/base/core.h"
#include "rod_impl.h"

/* The node term: energy k f(c) at node i; adds its gradient over (e0, e1) to g and its Hessian to H. */
static double node(const gal_rod *rod, int i, const double *q, const gal_rod_node *nd, double *g,
                   double (*H)[8])
{
    (void)i, (void)q;
    const double *t0 = nd->t0, *t1 = nd->t1, n0 = nd->n0, n1 = nd->n1, c = nd->c;
    double k = 4.0 * rod->p.EI / nd->lbar, f = (1 - c) / (1 + c);
    double f1 = -2.0 / ((1 + c) * (1 + c)), f2 = 4.0 / ((1 + c) * (1 + c) * (1 + c));
    double a0[3], a1[3]; /* dc/de0 = (t1 - c t0)/n0, dc/de1 = (t0 - c t1)/n1 */
    for (int d = 0; d < 3; d++) a0[d] = (t1[d] - c * t0[d]) / n0, a1[d] = (t0[d] - c * t1[d]) / n1;
    for (int d = 0; d < 3; d++) g[d] += k * f1 * a0[d], g[3 + d] += k * f1 * a1[d];
    if (H) {
        double gc[6] = {a0[0], a0[1], a0[2], a1[0], a1[1], a1[2]};
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                /* d2c/de0^2 = -(t0 a0^T + a0 t0^T + c P0/n0)/n0, d2c/de0 de1 = (P1/n1 - t0 a1^T)/n0;
                 * c00 and c11 are symmetric in a, b bit for bit (each two-term product and sum
                 * commutes, P0 and P1 are): computed for b >= a, used for both entries (f2 gc_a gc_b
                 * is not: a product of three, taken in each entry's own order) */
                if (b >= a) {
                    double c00 = -(t0[a] * a0[b] + a0[a] * t0[b] + c * nd->P0[a][b] / n0) / n0;
                    double c11 = -(t1[a] * a1[b] + a1[a] * t1[b] + c * nd->P1[a][b] / n1) / n1;
                    H[a][b] += k * (f2 * gc[a] * gc[b] + f1 * c00);
                    H[3 + a][3 + b] += k * (f2 * gc[3 + a] * gc[3 + b] + f1 * c11);
                    if (b != a) {
                        H[b][a] += k * (f2 * gc[b] * gc[a] + f1 * c00);
                        H[3 + b][3 + a] += k * (f2 * gc[3 + b] * gc[3 + a] + f1 * c11);
                    }
                }
                double c01 = (nd->P1[a][b] / n1 - t0[a] * a1[b]) / n0;
                H[a][3 + b] += k * (f2 * gc[a] * gc[3 + b] + f1 * c01);
                H[3 + b][a] = H[a][3 + b];
            }
    }
    return k * f;
}

const gal_rod_term gal_rod_term_bending = {"bending", NULL, node, NULL};
