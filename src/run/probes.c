/* probes.c: where a run looks at the span: the probes and the support elements' tension. */
#include "run/probes.h"
#include "gallop/base/core.h"

#include <math.h>

gal_probe gal_probe_locate(const gal_rod *rod, double frac)
{
    gal_probe pa;
    int nel = rod->p.elements;
    double s = frac * nel;
    pa.e = (int)s;
    if (pa.e > nel - 1) pa.e = nel - 1;
    pa.xi = s - pa.e;
    double se = s - 0.5;
    pa.e0 = (int)floor(se);
    pa.w1 = se - pa.e0;
    if (pa.e0 < 0) pa.e0 = 0, pa.w1 = 0;
    if (pa.e0 >= nel - 1) pa.e0 = nel - 1, pa.w1 = 0;
    pa.e1 = pa.e0 + 1 < nel ? pa.e0 + 1 : pa.e0;
    return pa;
}

void gal_probe_sample(const gal_rod *rod, const gal_probe *pa, int np, const double *u, double *row)
{
    int nn = rod->nn;
    for (int k = 0; k < np; k++) {
        const gal_probe *a = pa + k;
        double d[3];
        for (int c = 0; c < 3; c++) d[c] = (1 - a->xi) * u[3 * a->e + c] + a->xi * u[3 * (a->e + 1) + c];
        double th = rod->p.torsion ? (1 - a->w1) * u[3 * nn + a->e0] + a->w1 * u[3 * nn + a->e1] : 0;
        row[4 * k + 0] = d[1];          /* horizontal (y) */
        row[4 * k + 1] = d[2];          /* vertical (z) */
        row[4 * k + 2] = d[0];          /* along (x) */
        row[4 * k + 3] = th * 180 / GAL_PI;
    }
}

double gal_probe_tension(const gal_rod *rod, const double *q, int j)
{
    double e[3];
    for (int k = 0; k < 3; k++) e[k] = q[3 * (j + 1) + k] - q[3 * j + k];
    return rod->p.EA * (sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]) / rod->l0[j] - 1);
}
