/* rom_third.c: what the adaptation (rom_adapt.c) grows past the second-order basis: the cubic
 * growth (the selected modes' third-order modal derivatives and the rod's torsional modes their twist
 * reaches above the damping's band) and the ringing growth (the torsional modes above the band that a
 * ringing basis lacks); rom_adapt.h says when each applies. */
#include "gallop/reduced/rom_adapt.h"
#include "gallop/base/core.h"
#include "gallop/base/sparse.h"
#include "gallop/model/damping.h"
#include "base/chol.h"
#include "reduced/adapt.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The third-order modal derivatives of m's first nm modes (M-orthonormal, V's first columns) into
 * X (ndof x nm (nm+1)(nm+2)/6): -K0^-1 (d2K/d eta_j d eta_k) phi_i, i <= j <= k, the tangent's
 * second directional derivative by central differences over 2 cm of each mode's largest entry (a
 * second difference needs a larger step than the modal derivatives' first one). */
static int third_derivatives(const gal_rom *m, int nm, double *X)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof, nq = m->nq, st = GAL_OK, id = 0;
    const double sg[4][2] = {{1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
    gal_csc *K[4] = {NULL, NULL, NULL, NULL};
    double *q = malloc((size_t)nq * sizeof(double)), *w = malloc((size_t)2 * n * sizeof(double));
    for (int s = 0; s < 4; s++) K[s] = gal_csc_clone(rod->K);
    if (!q || !w || !K[0] || !K[1] || !K[2] || !K[3]) st = gal_error(GAL_ENOMEM, "reduced model: out of memory");
    for (int j = 0; j < nm && !st; j++)
        for (int k = j; k < nm && !st; k++) {
            const double *pj = m->V + (size_t)j * n, *pk = m->V + (size_t)k * n;
            double mj = 0, mk = 0;
            for (int d = 0; d < n; d++) mj = fmax(mj, fabs(pj[d])), mk = fmax(mk, fabs(pk[d]));
            double ej = 2e-2 / mj, ek = 2e-2 / mk;
            for (int s = 0; s < 4 && !st; s++) {
                memcpy(q, m->q_eq, (size_t)nq * sizeof(double));
                for (int d = 0; d < n; d++) q[rod->free_q[d]] += sg[s][0] * ej * pj[d] + sg[s][1] * ek * pk[d];
                if ((st = gal_rod_eval(rod, q, NULL, NULL, K[s]))) {
                    char why[256];
                    snprintf(why, sizeof why, "%s", gal_error_message());
                    gal_error(st, "reduced model: the third-order modal derivatives: %s", why);
                }
            }
            for (int i = 0; i <= j && !st; i++, id++) {
                double *y = X + (size_t)id * n;
                memset(y, 0, (size_t)n * sizeof(double));
                for (int s = 0; s < 4; s++) {
                    gal_csc_symv(K[s], m->V + (size_t)i * n, w);
                    for (int d = 0; d < n; d++) y[d] -= sg[s][0] * sg[s][1] * w[d] / (4 * ej * ek);
                }
                memcpy(w + n, y, (size_t)n * sizeof(double));
                st = gal_chol_solve(m->chol0, w + n, y);
            }
        }
    for (int s = 0; s < 4; s++) gal_csc_free(K[s]);
    free(q); free(w);
    return st;
}

/* The rod's torsional modes that the cubic growth adds (rom_adapt.h, GAL_ROM_THIRD_TORSION): those
 * above the damping's band (as band_check reads it) up to GAL_ROM_THIRD_TORSION times the highest
 * selected torsional mode's frequency (of the first nm selected), within GAL_ROM_THIRD_TORSION_SLACK,
 * not selected, lowest first, at most room of them, into X (ndof each); their count into *nadd. */
static int third_torsion(gal_rom_adapt *a, int nm, double *X, int room, int *nadd)
{
    const gal_damping *d = a->o.damping;
    double ft = 0, lo = d && d->band_hz > 0 ? d->band_hz : GAL_DAMPING_BAND_HZ;
    const gal_family t = GAL_FAMILY_TORSIONAL;
    int n = a->rod->ndof, want[GAL_FAMILY_COUNT] = {0};
    *nadd = 0;
    for (int j = 0; j < nm; j++)
        if (a->md->mode[a->sel[j]].family == t) ft = fmax(ft, a->md->mode[a->sel[j]].frequency_hz);
    double hi = GAL_ROM_THIRD_TORSION * ft * (1 + GAL_ROM_THIRD_TORSION_SLACK);
    if (!(hi > lo) || room <= 0) return GAL_OK;
    for (int k = 0; k < a->md->n; k++)
        if (a->md->mode[k].family != GAL_FAMILY_AXIAL) want[a->md->mode[k].family]++;
    want[t] = (int)ceil(GAL_ROM_THIRD_TORSION) * (want[t] > 0 ? want[t] : 1) + 2; /* ~ k f1 each */
    gal_modes md;
    memset(&md, 0, sizeof md);
    int st = gal_modes_find(a->rod, a->q_eq, want, a->md->n + want[t] + 64, &md);
    if (st) {
        char why[256];
        snprintf(why, sizeof why, "%s", gal_error_message());
        return gal_error(st, "reduced model: the torsional modes for the third-order set: %s", why);
    }
    for (int k = 0; k < md.n && *nadd < room; k++) {
        const gal_mode *mo = &md.mode[k];
        if (mo->family != t || !(mo->frequency_hz > lo && mo->frequency_hz <= hi)) continue;
        int in = 0;
        for (int j = 0; j < a->nsel; j++)
            in |= a->md->mode[a->sel[j]].family == t &&
                  fabs(a->md->mode[a->sel[j]].frequency_hz - mo->frequency_hz) <= 1e-6 * mo->frequency_hz;
        if (!in) memcpy(X + (size_t)(*nadd)++ * n, md.shape + (size_t)k * n, (size_t)n * sizeof(double));
    }
    gal_modes_clear(&md);
    return GAL_OK;
}

/* The ringing growth (rom_adapt.h, GAL_ROM_RING_OUTSIDE): the rod's torsional modes above the
 * damping's band that old's basis does not hold (their M-norm outside it over GAL_ROM_RING_OUTSIDE),
 * lowest first, as many as GAL_ROM_BASIS_CAP leaves room for beside old's basis, appended to the
 * extra vectors (counted into *corr); GAL_ROM_ELIMIT with a message, nothing changed, when none. */
int gal_rom_adapt_ring_growth(gal_rom_adapt *a, const gal_rom *old, const gal_rom_check *chk, int *corr)
{
    const gal_damping *d = a->o.damping;
    const gal_family t = GAL_FAMILY_TORSIONAL;
    double lo = d && d->band_hz > 0 ? d->band_hz : GAL_DAMPING_BAND_HZ;
    int n = a->rod->ndof, room = GAL_ROM_BASIS_CAP - old->r, nadd = 0, st = GAL_OK;
    double *X = NULL, *w = NULL;
    gal_modes md;
    memset(&md, 0, sizeof md);
    if (room > 0) {
        int want[GAL_FAMILY_COUNT] = {0};
        for (int k = 0; k < a->md->n; k++)
            if (a->md->mode[k].family != GAL_FAMILY_AXIAL) want[a->md->mode[k].family]++;
        /* those third_torsion reached (~ k f1 each) and room more */
        want[t] = (int)ceil(GAL_ROM_THIRD_TORSION) * (want[t] > 0 ? want[t] : 1) + 2 + room;
        if ((st = gal_modes_find(a->rod, a->q_eq, want, a->md->n + want[t] + 64, &md))) {
            char why[256];
            snprintf(why, sizeof why, "%s", gal_error_message());
            return gal_error(st, "reduced model: the torsional modes for the ringing basis: %s", why);
        }
        X = malloc((size_t)n * (a->nextra + room) * sizeof(double));
        w = malloc((size_t)(2 * n + old->r) * sizeof(double));
        if (!X || !w) st = gal_error(GAL_ENOMEM, "reduced model: out of memory");
        else memcpy(X, a->extra, (size_t)n * a->nextra * sizeof(double));
    }
    for (int k = 0; !st && X && k < md.n && nadd < room; k++) {
        const gal_mode *mo = &md.mode[k];
        if (mo->family != t || !(mo->frequency_hz > lo)) continue;
        double *u = w, *Mu = w + n, *c = w + 2 * n, out = 0;
        memcpy(u, md.shape + (size_t)k * n, (size_t)n * sizeof(double));
        for (int pass = 0; pass < 2; pass++) { /* minus its part in old's basis (M-orthonormal), twice */
            gal_rod_mass_mult(a->rod, u, Mu);
            for (int i = 0; i < old->r; i++) {
                double s = 0;
                for (int j = 0; j < n; j++) s += old->V[(size_t)i * n + j] * Mu[j];
                c[i] = s;
            }
            for (int i = 0; i < old->r; i++)
                for (int j = 0; j < n; j++) u[j] -= c[i] * old->V[(size_t)i * n + j];
        }
        gal_rod_mass_mult(a->rod, u, Mu);
        for (int j = 0; j < n; j++) out += u[j] * Mu[j];
        if (sqrt(fmax(out, 0)) > GAL_ROM_RING_OUTSIDE)
            memcpy(X + (size_t)(a->nextra + nadd++) * n, md.shape + (size_t)k * n, (size_t)n * sizeof(double));
    }
    gal_modes_clear(&md);
    free(w);
    if (st || !nadd) {
        free(X);
        if (st) return st;
        gal_error(GAL_EFAIL, "the basis (%d vectors) rings undamped: its reduced modes above the damping's band carry "
                  "a twist of %.3g of the twist's scale (times %g) that the full model does not hold (%s)", old->r,
                  chk->ring / GAL_ROM_BAND_WEIGHT, GAL_ROM_BAND_WEIGHT,
                  room > 0 ? "the rod's torsional modes computed above the band are in it"
                           : "it cannot grow by the rod's torsional modes: it is at its cap");
        return GAL_ROM_ELIMIT;
    }
    free(a->extra);
    a->extra = X, a->nextra += nadd;
    *corr = nadd;
    return GAL_OK;
}

/* The cubic growth (rom_adapt.h): the basis back to the initial selection and extra vectors, plus
 * the third-order modal derivatives of the selected modes and the rod's torsional modes that their
 * twist reaches above the damping's band (third_torsion; all counted into *corr); GAL_ROM_ELIMIT
 * with a message, nothing changed, when they are in the basis already or pass the cap. */
int gal_rom_adapt_third_growth(gal_rom_adapt *a, const gal_rom *old, const gal_rom_check *chk, int f, int *corr)
{
    int nm = a->nsel0, nt = nm * (nm + 1) * (nm + 2) / 6, n = a->rod->ndof;
    if (a->third || nm > old->nmodes || gal_rom_adapt_basis_size(a, nm, a->nextra0 + nt) > GAL_ROM_BASIS_CAP) {
        gal_error(GAL_EFAIL, "the basis (%d vectors) lacks the modes' third-order coupling: the cubic part of the "
                  "%s motion outside it is %.3g of the motion (the basis cannot grow by it%s)", old->r,
                  gal_family_names[f], chk->cubic[f],
                  a->third ? ": its third-order modal derivatives are in it" : ": their set passes the cap");
        return GAL_ROM_ELIMIT;
    }
    int room = GAL_ROM_BASIS_CAP - gal_rom_adapt_basis_size(a, nm, a->nextra0 + nt), nadd = 0;
    double *X = malloc((size_t)n * (a->nextra0 + nt + room + GAL_ROM_EVENTS_MAX * 2) * sizeof(double));
    if (!X) return gal_error(GAL_ENOMEM, "reduced model: out of memory");
    memcpy(X, a->extra, (size_t)n * a->nextra0 * sizeof(double));
    int st = third_derivatives(old, nm, X + (size_t)n * a->nextra0);
    if (!st) st = third_torsion(a, nm, X + (size_t)n * (a->nextra0 + nt), room, &nadd);
    if (st) { free(X); return st; }
    free(a->extra);
    a->extra = X, a->nextra = a->nextra0 + nt + nadd, a->nsel = nm, a->third = nt;
    memset(a->corrected, 0, sizeof a->corrected);
    *corr = nt + nadd;
    return GAL_OK;
}
