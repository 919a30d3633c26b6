/* romcheck.c: the explicit bundle's reduced model checks itself (bundle_rom.h): the assembled
 * system's residual R = M(s) a + C v + grad U(s) - F(t, s, v) at the reconstructed state, a the
 * reduced equations' own acceleration there, turned into the displacement du = K0^-1 R that would
 * correct it and split into the bundle's families (gal_bundle_classify's shares) in the mass norm
 * of M0, each against the family's own displacement V x (at least 2% of the whole motion's). */
#include "gallop/bundle/bundle_rom.h"
#include "gallop/base/core.h"
#include "bundle_impl.h"
#include "rom_impl.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/chol.h"

/* y^T M0 y and its shares per family (the map's values at the equilibrium); w: ndof. */
static double family_norms(const gal_bundle_rom *m, const double *y, double *w, double *scratch,
                           double acc[GAL_FAMILY_COUNT])
{
    gal_csc_symv(m->M0, y, w);
    double nrm = 0;
    for (int j = 0; j < m->ndof; j++) nrm += y[j] * w[j];
    gal_mode md;
    memset(&md, 0, sizeof md);
    gal_bundle_classify(m->b, y, scratch, &md);
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) acc[f] = md.share[f] * nrm;
    return nrm;
}

/* R over the system's dofs into R at the state (x, v, t); w: 2 ndof of scratch. */
static int full_residual(gal_bundle_rom *m, double *R, double *w)
{
    gal_bundle *b = m->b;
    int n = m->ndof, st;
    if ((st = gal_bundle_rom_forces(m, m->x, m->v, m->t, 0, m->s1, m->fi1, m->fe1))) return st;
    for (int j = 0; j < n; j++) R[j] = b->grad[j] - m->f[j];
    if ((st = gal_bundle_rom_acceleration(m, m->s1, m->v, m->fi1, m->fe1, m->a1))) return st;
    gal_bundle_rom_expand(m, m->a1, w);
    gal_bundle_mass_mult(b, m->s1, w, w + n, m->wrk);
    for (int j = 0; j < n; j++) R[j] += w[n + j];
    gal_bundle_rom_expand(m, m->v, w);
    if (m->o.damping) { /* the full model's modal damping */
        gal_damping_apply(m->o.damping, w, R);
        return GAL_OK;
    }
    gal_csc_symv(m->M0, w, w + n);
    for (int j = 0; j < n; j++) R[j] += m->o.alpha * w[n + j];
    gal_csc_symv(m->K0, w, w + n);
    for (int j = 0; j < n; j++) R[j] += m->o.beta * w[n + j];
    return GAL_OK;
}

int gal_bundle_rom_residual(gal_bundle_rom *m, gal_bundle_rom_check *chk)
{
    gal_bundle *b = m->b;
    int n = m->ndof, st;
    memset(chk, 0, sizeof *chk);
    double *w = malloc((4 * (size_t)n + gal_bundle_classify_scratch(b)) * sizeof(double));
    if (!w) return gal_error(GAL_ENOMEM, "bundle reduced model: out of memory for the residual");
    double *R = w, *du = w + n, *tmp = w + 2 * n, *scratch = w + 4 * n;
    if ((st = full_residual(m, R, tmp)) || (st = gal_chol_solve(m->chol0, R, du))) {
        free(w);
        return st;
    }
    gal_bundle_map_values(b, b->state); /* the families are the equilibrium's */
    double ad[GAL_FAMILY_COUNT], au[GAL_FAMILY_COUNT];
    family_norms(m, du, tmp, scratch, ad);
    gal_bundle_rom_expand(m, m->x, R);
    double total = family_norms(m, R, tmp, scratch, au);
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) {
        double scale = fmax(sqrt(au[f]), 0.02 * sqrt(total));
        chk->rel[f] = scale > 0 ? sqrt(ad[f]) / scale : 0;
        chk->max = fmax(chk->max, chk->rel[f]);
    }
    free(w);
    return GAL_OK;
}

static const char *const family_keys[GAL_FAMILY_COUNT] = {"modes_vertical", "modes_horizontal", "modes_torsional",
                                                          "modes_vertical", "modes_vertical"};

int gal_bundle_rom_selfcheck(gal_bundle_rom *m, double tol, int warn, const char *path)
{
    gal_bundle_rom_check chk;
    int st = gal_bundle_rom_residual(m, &chk);
    if (st) return st;
    m->checks++;
    if (chk.max > m->residual_max) m->residual_max = chk.max, m->worst = chk;
    if (!(tol > 0) || chk.max <= tol || !m->valid) return GAL_OK;
    m->valid = 0;
    int f = 0;
    for (int k = 1; k < GAL_FAMILY_COUNT; k++)
        if (chk.rel[k] > chk.rel[f]) f = k;
    if (warn) return GAL_OK;
    return gal_error(GAL_EFAIL, "%s: the explicit bundle's reduced model: its residual grew to %.3g in the %s family "
                     "at t = %.4g s, past model.residual_tolerance = %.3g (basis %d, no adaptation); select more "
                     "modes (model.%s), raise model.residual_tolerance, set model.on_invalid = warn to finish the "
                     "run marked invalid, or run --model full", path, chk.rel[f], gal_family_names[f], m->t, tol,
                     m->r, family_keys[f]);
}
