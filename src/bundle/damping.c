/* damping.c: the explicit bundle's structural damping as the single rod's (model/damping.h, issue
 * 15): modal, conductor.damping_ratio on every natural mode of the assembled bundle about its
 * equilibrium up to the band limit (GAL_DAMPING_BAND_HZ), none above,
 *     C = M0 Phi_b diag(2 zeta w_k) Phi_b^T M0   over the system's dofs,
 * so that phi_k^T C phi_j = 2 zeta w_k delta_kj for every pair of bundle modes in the band. */
#include "gallop/bundle/bundle_dyn.h"
#include "gallop/base/core.h"

#include <stdlib.h>
#include <string.h>

/* The bundle's modes up to band_hz: more asked until the highest is above the band (or the cap). */
static int band_modes(gal_bundle *b, double band_hz, gal_modes *md)
{
    int n = b->ndof, nev = 32;
    for (;;) {
        if (nev > n - 1) nev = n - 1;
        if (nev > GAL_DAMPING_MAX_MODES + 1) nev = GAL_DAMPING_MAX_MODES + 1;
        int st = gal_bundle_modes_solve(b, nev, md);
        if (st) return st;
        if (md->mode[md->n - 1].frequency_hz > band_hz || nev >= n - 1 || nev > GAL_DAMPING_MAX_MODES) return GAL_OK;
        gal_modes_clear(md);
        nev *= 2;
    }
}

gal_damping *gal_bundle_damping_modal(gal_bundle *b, double zeta, double band_hz)
{
    gal_damping *c = calloc(1, sizeof *c);
    if (!c) { gal_error(GAL_ENOMEM, "bundle damping: out of memory"); return NULL; }
    c->ndof = b->ndof, c->zeta = zeta;
    c->band_hz = band_hz > 0 ? band_hz : GAL_DAMPING_BAND_HZ;
    c->kind = zeta > 0 ? GAL_DAMPING_MODAL : GAL_DAMPING_NONE;
    if (c->kind == GAL_DAMPING_NONE) return c;
    gal_modes md;
    if (band_modes(b, c->band_hz, &md)) {
        gal_error(GAL_EFAIL, "bundle damping: modes of the band: %s", gal_error_message());
        return gal_damping_free(c);
    }
    int nb = 0, n = b->ndof;
    while (nb < md.n && nb < GAL_DAMPING_MAX_MODES && md.mode[nb].frequency_hz <= c->band_hz) nb++;
    if (nb == 0) nb = 1; /* the band holds at least the fundamental */
    if (nb < md.n && md.mode[nb].frequency_hz <= c->band_hz) c->band_hz = md.mode[nb - 1].frequency_hz;
    c->nb = nb;
    c->omega = malloc((size_t)nb * sizeof(double));
    c->mphi = malloc((size_t)nb * n * sizeof(double));
    int st = c->omega && c->mphi ? gal_bundle_eval(b, NULL, NULL, 1) : GAL_ENOMEM; /* M0: at the equilibrium */
    for (int k = 0; !st && k < nb; k++) {
        c->omega[k] = md.mode[k].omega;
        gal_csc_symv(b->M, md.shape + (size_t)k * n, c->mphi + (size_t)k * n); /* M0 phi_k */
    }
    gal_modes_clear(&md);
    if (st) {
        gal_error(st, "bundle damping: %s", st == GAL_ENOMEM ? "out of memory" : gal_error_message());
        return gal_damping_free(c);
    }
    return c;
}
