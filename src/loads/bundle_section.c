/* bundle_section.c: the aerodynamic load on an equivalent bundle's section (loads.h,
 * gal_loads_bundle): the scene's table on each sub-conductor at its place on the bundle circle,
 * turned with the section's twist, in its own relative wind (the centroid's velocity plus the
 * bundle's rotation about the tangent: a twist rate moves a sub-conductor by spin tan x p_k, the
 * torsional aerodynamic damping of order n R^2 that one load at the centroid lacks), with the wake
 * factor on the leeward ones as in the explicit model (src/bundle/loads.c), summed as a force and
 * a moment about the centroid. */
#include "loads_impl.h"
#include "gallop/base/core.h"
#include "gallop/base/vec3.h"

#include <math.h>
#include <string.h>

/* Sub-conductor r is leeward when another lies upwind of it, further than half a diameter along
 * the wind's component across the span (y) and within one diameter of its line, at rest. */
static int leeward(const gal_loads_bundle *b, int r, double dir_y, double diam)
{
    if (fabs(dir_y) < 1e-12) return 0;
    double sg = dir_y > 0 ? 1.0 : -1.0;
    for (int k = 0; k < b->n; k++) {
        if (k == r) continue;
        double along = sg * (b->off[r][0] - b->off[k][0]), across = fabs(b->off[r][1] - b->off[k][1]);
        if (along > 0.5 * diam && across < diam) return 1;
    }
    return 0;
}

void gal_loads_bundle_set(gal_loads *L, int n, double radius, double orientation, double air_density,
                          double wake_factor)
{
    gal_loads_bundle *b = &L->bundle;
    memset(b, 0, sizeof *b);
    if (n < 2) return;
    if (n > GAL_LOADS_MAX_SUB) n = GAL_LOADS_MAX_SUB;
    b->n = n;
    for (int k = 0; k < n; k++) {
        double a = orientation + 2 * GAL_PI * k / n;
        b->off[k][0] = radius * cos(a), b->off[k][1] = radius * sin(a);
    }
    for (int k = 0; k < n; k++) {
        b->leeward[k] = leeward(b, k, L->dir[1], L->diam);
        b->rho[k] = air_density * (b->leeward[k] ? wake_factor : 1.0);
    }
}

int gal_loads_bundle_section(const gal_loads *L, const gal_loads_list *ls, const double w[3],
                             const double rdot[3], double spin, const double tan[3], const double d1[3],
                             const double da[3], double f[3], double *m)
{
    const gal_loads_bundle *b = &L->bundle;
    double e1[3], e2[3], e3[3], nt = gal_norm3(tan);
    f[0] = f[1] = f[2] = 0, *m = 0;
    if (!(nt > 0)) return gal_error(GAL_EINPUT, "aerodynamic load: zero tangent");
    for (int i = 0; i < 3; i++) e3[i] = tan[i] / nt;
    double s = gal_dot3(d1, e3);
    for (int i = 0; i < 3; i++) e1[i] = d1[i] - s * e3[i];
    double n1 = gal_norm3(e1);
    if (!(n1 > 0)) return gal_error(GAL_EINPUT, "aerodynamic load: reference direction parallel to the tangent");
    for (int i = 0; i < 3; i++) e1[i] /= n1;
    gal_cross3(e3, e1, e2);
    for (int k = 0; k < b->n; k++) {
        double p[3], u[3], wk[3], fk[3], mk = 0, pf[3];
        const double a = b->off[k][0], c = b->off[k][1];
        for (int i = 0; i < 3; i++) {
            p[i] = a * e1[i] + c * e2[i];
            u[i] = rdot[i] + spin * (a * e2[i] - c * e1[i]); /* e3 x p = a e2 - c e1 */
            wk[i] = w[i];
        }
        for (int j = 0; j < ls->nwind; j++)
            if (ls->wind[j]->relative) ls->wind[j]->relative(L, u, wk);
        int st = gal_aero_load_terms(L->table, tan, da, wk, b->rho[k], L->diam, ls->section, ls->nsection,
                                     fk, &mk, NULL, NULL);
        if (st) return st;
        gal_cross3(p, fk, pf);
        for (int i = 0; i < 3; i++) f[i] += fk[i];
        *m += mk + gal_dot3(pf, e3);
    }
    return GAL_OK;
}
