/* loads.c: the quasi-steady aerodynamic loads on every sub-conductor of the explicit bundle
 * (bundle_dyn.h): the scene's loads on each rod at its own relative wind and twist, the wake
 * factor on the leeward ones, mapped onto the system's dofs by T^T. */
#include "gallop/bundle/bundle_dyn.h"
#include "gallop/base/core.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Sub-conductor r is leeward when another lies upwind of it within one diameter of the line along
 * the wind's component across the span (y), at rest. */
static int leeward(const gal_bundle *b, int r, double dir_y, double diam)
{
    if (fabs(dir_y) < 1e-12) return 0;
    double sg = dir_y > 0 ? 1.0 : -1.0;
    for (int k = 0; k < b->n; k++) {
        if (k == r) continue;
        double along = sg * (b->off[r][1] - b->off[k][1]), across = fabs(b->off[r][2] - b->off[k][2]);
        if (along > 0.5 * diam && across < diam) return 1;
    }
    return 0;
}

int gal_bundle_loads_init(gal_bundle_loads *bl, const gal_bundle *b, const gal_loads *base, double rho,
                          double wake_factor)
{
    memset(bl, 0, sizeof *bl);
    int nq = b->rod[0]->nq;
    bl->vq = malloc((size_t)2 * nq * sizeof(double));
    bl->fq = malloc((size_t)2 * nq * sizeof(double));
    if (!bl->vq || !bl->fq) {
        gal_bundle_loads_clear(bl);
        return gal_error(GAL_ENOMEM, "bundle loads: out of memory");
    }
    for (int r = 0; r < b->n; r++) {
        bl->L[r] = *base;
        bl->L[r].rod = b->rod[r];
        bl->leeward[r] = leeward(b, r, base->dir[1], base->diam);
        bl->L[r].rho = rho * (bl->leeward[r] ? wake_factor : 1.0);
    }
    return GAL_OK;
}

void gal_bundle_loads_clear(gal_bundle_loads *bl)
{
    free(bl->vq), free(bl->fq);
    bl->vq = bl->fq = NULL;
}

int gal_bundle_loads_eval(void *ctx, gal_bundle *b, double t, const double *s, const double *v, double *f)
{
    gal_bundle_loads *bl = ctx;
    for (int r = 0; r < b->n; r++) {
        const gal_rod *rod = b->rod[r];
        int nq = rod->nq, nd = rod->ndof;
        double *vf = bl->vq + nq, *ff = bl->fq + nq;
        gal_bundle_map(b, r, v, vf); /* the rod's velocity: T_r v */
        memset(bl->vq, 0, (size_t)nq * sizeof(double));
        memset(bl->fq, 0, (size_t)nq * sizeof(double));
        for (int d = 0; d < nd; d++) bl->vq[rod->free_q[d]] = vf[d];
        int st = gal_loads_full(&bl->L[r], t, s + (size_t)r * nq, bl->vq, bl->fq);
        if (st) return gal_error(st, "sub-conductor %d: %s", r + 1, gal_error_message());
        for (int d = 0; d < nd; d++) ff[d] = bl->fq[rod->free_q[d]];
        gal_bundle_map_add_t(b, r, ff, f);
    }
    return GAL_OK;
}
