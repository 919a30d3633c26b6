/* rom_adapt.c: the reduced model's adaptation (rom_adapt.h): a larger basis after a failed
 * self-check, the model rebuilt on it by gal_rom_alloc and run again from the run's start to the
 * failing check's time (or, without a start, restarted from the reconstructed state). */
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

static gal_rom *build(gal_rom_adapt *a)
{
    gal_rom_opts o = a->o;
    o.extra = a->extra, o.nextra = a->nextra;
    return gal_rom_alloc(a->rod, a->q_eq, a->md, a->sel, a->nsel, &o, &a->force);
}

int gal_rom_adapt_init(gal_rom_adapt *a, gal_rom **m, const gal_rod *rod, const double *q_eq, const gal_modes *md,
                       const int *sel, int nsel, const gal_rom_opts *o, const gal_force *force)
{
    memset(a, 0, sizeof *a);
    *m = NULL;
    if (nsel > GAL_ROM_MODES_MAX)
        return gal_error(GAL_EINPUT, "reduced model: %d modes selected, at most %d", nsel, GAL_ROM_MODES_MAX);
    a->rod = rod, a->q_eq = q_eq, a->md = md, a->nsel = nsel;
    a->policy = GAL_ROM_ADD_CORRECTION | GAL_ROM_ADD_MODE;
    a->relax = 1;
    a->orbit_vectors = GAL_ROM_ORBIT_VECTORS;
    memcpy(a->sel, sel, (size_t)nsel * sizeof(int));
    if (o) a->o = *o;
    else gal_rom_default_opts(&a->o);
    int n0 = a->o.nextra > 0 ? a->o.nextra : 0;
    if (force) a->force = *force;
    if (!(a->extra = malloc((size_t)rod->ndof * (GAL_ROM_EVENTS_MAX * 2 + n0) * sizeof(double))))
        return gal_error(GAL_ENOMEM, "reduced model: out of memory");
    if (n0) memcpy(a->extra, a->o.extra, (size_t)rod->ndof * n0 * sizeof(double));
    a->nextra = a->nextra0 = n0;
    a->nsel0 = nsel;
    a->o.extra = NULL, a->o.nextra = 0;
    double mt = 0; /* the twist's mass along the span */
    if (rod->p.torsion)
        for (int j = 0; j < rod->p.elements; j++) {
            int d = rod->dof[3 * rod->nn + j];
            if (d >= 0) mt += rod->mdiag[d];
        }
    a->twist_floor = (3.14159265358979323846 / 180) * sqrt(0.5 * mt);
    *m = build(a);
    return *m ? GAL_OK : GAL_EFAIL;
}

/* The cubic check (rom_adapt.h) into chk->cubic, and into chk->rel where larger (vertical and
 * horizontal), from GAL_ROM_CUBIC_SETTLE_S on, every GAL_ROM_CUBIC_EVERY-th check. */
static int cubic_check(gal_rom_adapt *a, gal_rom *m, gal_rom_check *chk)
{
    if (m->t < GAL_ROM_CUBIC_SETTLE_S || a->cubic_checks++ % GAL_ROM_CUBIC_EVERY) return GAL_OK;
    double ce[GAL_FAMILY_COUNT];
    int st = gal_rom_cubic(m, m->x, ce);
    if (st) return st;
    for (int f = GAL_FAMILY_VERTICAL; f <= GAL_FAMILY_HORIZONTAL; f++) {
        chk->cubic[f] = chk->scale[f] > 0 ? ce[f] / chk->scale[f] : 0;
        chk->rel[f] = fmax(chk->rel[f], chk->cubic[f] / GAL_ROM_CUBIC_SHARE);
    }
    return GAL_OK;
}

/* The twist's ringing above the damping band (rom_adapt.h, GAL_ROM_BAND_WEIGHT) into chk->ring and
 * the torsional residual, once the basis holds the third-order set; the band's modes recomputed
 * when the basis changed. */
static int band_check(gal_rom_adapt *a, gal_rom *m, gal_rom_check *chk)
{
    int t = GAL_FAMILY_TORSIONAL;
    if (!a->third || m->t < GAL_ROM_CUBIC_SETTLE_S || !(chk->scale[t] > 0)) return GAL_OK;
    if (a->band.r != m->r || a->band_events != a->nevents || !a->band.y) {
        const gal_damping *d = a->o.damping;
        int st = gal_rom_band_init(m, d && d->band_hz > 0 ? d->band_hz : GAL_DAMPING_BAND_HZ, &a->band);
        if (st) return st;
        a->band_events = a->nevents;
    }
    double amp[GAL_FAMILY_COUNT];
    gal_rom_band_amplitude(m, &a->band, amp);
    chk->ring = GAL_ROM_BAND_WEIGHT * amp[t] / chk->scale[t];
    chk->rel[t] = fmax(chk->rel[t], chk->ring);
    return GAL_OK;
}

int gal_rom_adapt_residual(gal_rom_adapt *a, gal_rom *m, gal_rom_check *chk, double *du)
{
    int st = gal_rom_residual_dir(m, chk, du);
    if (st) return st;
    int t = GAL_FAMILY_TORSIONAL;
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) a->amp[f] = fmax(a->amp[f], chk->disp[f]);
    chk->scale[t] = GAL_ROM_TWIST_WEIGHT * fmax(a->amp[t], a->twist_floor);
    chk->rel[t] = chk->scale[t] > 0 ? chk->err[t] / chk->scale[t] : 0;
    if ((st = cubic_check(a, m, chk))) return st;
    if ((st = band_check(a, m, chk))) return st;
    chk->max = 0;
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) chk->max = fmax(chk->max, chk->rel[f]);
    return GAL_OK;
}

void gal_rom_adapt_replay_from(gal_rom_adapt *a, const double *q0, const double *v0)
{
    a->q0 = q0, a->v0 = v0;
}

void gal_rom_adapt_clear(gal_rom_adapt *a)
{
    free(a->extra);
    gal_modes_clear(&a->own);
    gal_rom_band_clear(&a->band);
    memset(a, 0, sizeof *a);
}

/* The lowest computed mode of family f (axial: the in-plane modes, vertical) not in the basis and
 * not at or near 0 Hz; -1 if none. */
static int next_mode(const gal_rom_adapt *a, gal_family f)
{
    if (f == GAL_FAMILY_AXIAL) f = GAL_FAMILY_VERTICAL;
    for (int k = 0; k < a->md->n; k++) {
        const gal_mode *mo = &a->md->mode[k];
        if (mo->family != f || !(mo->frequency_hz >= 0.01)) continue;
        int in = 0;
        for (int j = 0; j < a->nsel; j++) in |= a->sel[j] == k;
        if (!in) return k;
    }
    return -1;
}

/* Compute two more modes of family f (axial: vertical) than the modes hold, with the others' counts
 * kept, into a->own, and carry the selection over to them (each selected mode is the one of its
 * family at the same frequency); GAL_OK, or a status with a message (the old set then stays). */
static int more_modes(gal_rom_adapt *a, gal_family f)
{
    if (f == GAL_FAMILY_AXIAL) f = GAL_FAMILY_VERTICAL;
    int want[GAL_FAMILY_COUNT] = {0};
    for (int k = 0; k < a->md->n; k++)
        if (a->md->mode[k].family != GAL_FAMILY_AXIAL) want[a->md->mode[k].family]++;
    want[f] += 2;
    gal_modes nw;
    memset(&nw, 0, sizeof nw);
    int st = gal_modes_find(a->rod, a->q_eq, want, a->md->n + 64, &nw);
    if (st) return st;
    int sel[GAL_ROM_MODES_MAX];
    for (int j = 0; j < a->nsel; j++) {
        const gal_mode *mo = &a->md->mode[a->sel[j]];
        sel[j] = -1;
        for (int k = 0; k < nw.n && sel[j] < 0; k++)
            if (nw.mode[k].family == mo->family &&
                fabs(nw.mode[k].frequency_hz - mo->frequency_hz) <= 1e-6 * mo->frequency_hz)
                sel[j] = k;
        if (sel[j] < 0) {
            gal_modes_clear(&nw);
            return gal_error(GAL_EFAIL, "reduced model: the selected %s mode at %.6g Hz is not among the "
                             "modes computed again", gal_family_names[mo->family], mo->frequency_hz);
        }
    }
    memcpy(a->sel, sel, (size_t)a->nsel * sizeof(int));
    gal_modes_clear(&a->own);
    a->own = nw;
    a->md = &a->own;
    return GAL_OK;
}



/* The new directions of nw (M-orthogonal to old's basis) that are stiff (their Rayleigh frequency
 * over STIFF_RATIO times the highest mode's: stretching, not motion) are relaxed to their quasi-
 * static position at the restart (they start where the old model could not put them: without it
 * they ring): modified Newton on B^T a = 0 over them, B their coordinates in nw's basis, with
 * B^T K0r B; back to the unrelaxed start if it does not converge. */
#define STIFF_RATIO 3.0
#define RELAX_ITER 30
/* The new directions of nw, M-orthogonal to old's basis, that are stiff, as k columns of B (r1 each,
 * in nw's coordinates, orthonormal); work: 2 ndof + old->r. */
static int stiff_directions(const gal_rom *old, const gal_rom *nw, double *B, double *work)
{
    const gal_rod *rod = nw->rod;
    int n = nw->ndof, r0 = old->r, r1 = nw->r, k = 0;
    double w2max = 0, *c = work, *Mc = c + n, *p = Mc + n;
    for (int i = 0; i < nw->nmodes; i++) w2max = fmax(w2max, nw->omega2[i]);
    for (int j = 0; j < r1 && k < r1; j++) {
        /* column j minus its part in the old span, in nw's coordinates */
        double *b = B + (size_t)k * r1;
        memcpy(c, nw->V + (size_t)j * n, (size_t)n * sizeof(double));
        gal_rod_mass_mult(rod, c, Mc);
        for (int i = 0; i < r0; i++) {
            double s = 0;
            for (int d = 0; d < n; d++) s += old->V[(size_t)i * n + d] * Mc[d];
            p[i] = s;
        }
        for (int d = 0; d < n; d++) {
            double s = 0;
            for (int i = 0; i < r0; i++) s += old->V[(size_t)i * n + d] * p[i];
            c[d] -= s;
        }
        gal_rod_mass_mult(rod, c, Mc);
        for (int i = 0; i < r1; i++) {
            double s = 0;
            for (int d = 0; d < n; d++) s += nw->V[(size_t)i * n + d] * Mc[d];
            b[i] = s;
        }
        for (int pass = 0; pass < 2; pass++) /* against the directions kept */
            for (int l = 0; l < k; l++) {
                double s = 0;
                for (int i = 0; i < r1; i++) s += B[(size_t)l * r1 + i] * b[i];
                for (int i = 0; i < r1; i++) b[i] -= s * B[(size_t)l * r1 + i];
            }
        double nb = 0, kb = 0;
        for (int i = 0; i < r1; i++) nb += b[i] * b[i];
        if (!(nb > 1e-6)) continue;
        for (int i = 0; i < r1; i++) b[i] /= sqrt(nb);
        for (int i = 0; i < r1; i++)
            for (int l = 0; l < r1; l++) kb += b[i] * nw->K0r[i * r1 + l] * b[l];
        if (kb > STIFF_RATIO * STIFF_RATIO * w2max) k++;
    }
    return k;
}

/* nw's state back to x0 (a relaxation that did not converge). */
static int restore(gal_rom *nw, const double *x0, double *q, const double *v)
{
    memcpy(nw->x, x0, (size_t)nw->r * sizeof(double));
    gal_rom_reconstruct(nw, q, NULL);
    return gal_rom_start(nw, nw->t, q, v);
}

static int relax(const gal_rom *old, gal_rom *nw, double *q, double *v)
{
    int n = nw->ndof, r0 = old->r, r1 = nw->r, st = GAL_OK;
    double *w = malloc((size_t)(2 * n + r0 + 2 * (size_t)r1 * r1 + 3 * (size_t)r1) * sizeof(double));
    if (!w) return gal_error(GAL_ENOMEM, "reduced model: out of memory");
    double *B = w + 2 * n + r0, *KB = B + (size_t)r1 * r1, *g = KB + (size_t)r1 * r1, *dy = g + r1, *x0 = dy + r1;
    memcpy(x0, nw->x, (size_t)r1 * sizeof(double));
    int k = stiff_directions(old, nw, B, w);
    /* Kb = B^T K0r B (k x k), factored by Cholesky in place */
    for (int a = 0; a < k; a++)
        for (int b2 = 0; b2 < k; b2++) {
            double s = 0;
            for (int i = 0; i < r1; i++)
                for (int l = 0; l < r1; l++) s += B[(size_t)a * r1 + i] * nw->K0r[i * r1 + l] * B[(size_t)b2 * r1 + l];
            KB[a * k + b2] = s;
        }
    for (int a = 0; a < k && !st; a++) {
        for (int b2 = 0; b2 < a; b2++) KB[a * k + a] -= KB[a * k + b2] * KB[a * k + b2];
        if (!(KB[a * k + a] > 0)) { k = 0; break; } /* not positive definite: no relaxation */
        KB[a * k + a] = sqrt(KB[a * k + a]);
        for (int i = a + 1; i < k; i++) {
            for (int b2 = 0; b2 < a; b2++) KB[i * k + a] -= KB[i * k + b2] * KB[a * k + b2];
            KB[i * k + a] /= KB[a * k + a];
        }
    }
    double g0 = 0, gprev = INFINITY;
    for (int it = 0; it < RELAX_ITER && k > 0 && !st; it++) {
        double gn = 0;
        for (int a = 0; a < k; a++) {
            double s = 0;
            for (int i = 0; i < r1; i++) s += B[(size_t)a * r1 + i] * nw->a[i];
            g[a] = s, gn += s * s;
        }
        if (it == 0) g0 = gn;
        if (gn <= 1e-16 * g0 || !(gn > 0)) break;
        if (!(gn < gprev)) { /* not converging: back to the unrelaxed start */
            st = restore(nw, x0, q, v);
            break;
        }
        gprev = gn;
        for (int a = 0; a < k; a++) { /* forward, backward */
            for (int b2 = 0; b2 < a; b2++) g[a] -= KB[a * k + b2] * g[b2];
            g[a] /= KB[a * k + a];
        }
        for (int a = k - 1; a >= 0; a--) {
            for (int b2 = a + 1; b2 < k; b2++) g[a] -= KB[b2 * k + a] * g[b2];
            g[a] /= KB[a * k + a];
        }
        for (int i = 0; i < r1; i++) {
            double s = 0;
            for (int a = 0; a < k; a++) s += B[(size_t)a * r1 + i] * g[a];
            dy[i] = s;
        }
        for (int i = 0; i < r1; i++) nw->x[i] += dy[i];
        gal_rom_reconstruct(nw, q, NULL);
        if ((st = gal_rom_start(nw, nw->t, q, v))) { /* a degenerate rod: back to the start */
            st = restore(nw, x0, q, v);
            break;
        }
    }
    free(w);
    return st;
}


int gal_rom_adapt_grow(gal_rom_adapt *a, gal_rom **m, const gal_rom_check *chk, const double *du)
{
    gal_rom *old = *m;
    int f = 0, n = a->rod->ndof;
    for (int k = 1; k < GAL_FAMILY_COUNT; k++)
        if (chk->rel[k] > chk->rel[f]) f = k;
    if (a->nevents >= GAL_ROM_EVENTS_MAX) {
        gal_error(GAL_EFAIL, "the basis grew %d times (%d vectors) and the %s residual is still %.3g",
                  a->nevents, old->r, gal_family_names[f], chk->max);
        return GAL_ROM_ELIMIT;
    }
    int st = GAL_OK, mode = -1, corr = 0, cubic = f <= GAL_FAMILY_HORIZONTAL && chk->rel[f] == chk->cubic[f] / GAL_ROM_CUBIC_SHARE;
    int nsel_was = a->nsel, nextra_was = a->nextra;
    double t = old->t, *q = NULL;
    if (f == GAL_FAMILY_TORSIONAL && chk->ring > 0 && chk->rel[f] == chk->ring) { /* rom_adapt.h: the ringing growth */
        if ((st = gal_rom_adapt_ring_growth(a, old, chk, &corr))) return st;
        cubic = 1; /* run again from the start as the cubic growth is: no correction, no mode */
    } else if (cubic) {
        if ((st = gal_rom_adapt_third_growth(a, old, chk, f, &corr))) return st;
    } else if (a->third) { /* past the third-order set, a correction or mode is not grown (rom_adapt.h) */
        gal_error(GAL_EFAIL, "the basis (%d vectors) holds the modes' third-order modal derivatives and the %s "
                  "residual is still %.3g (the basis does not grow past them)", old->r, gal_family_names[f], chk->max);
        return GAL_ROM_ELIMIT;
    } else {
        corr = (a->policy & GAL_ROM_ADD_CORRECTION) && du ? (a->orbit_vectors > 0 ? a->orbit_vectors : 1) : 0;
        /* the correction alone first; the mode when a correction has not sufficed */
        int want_mode = (a->policy & GAL_ROM_ADD_MODE) && a->nsel < GAL_ROM_MODES_MAX && (!corr || a->corrected[f]);
        mode = want_mode ? next_mode(a, f) : -1;
        if (want_mode && mode < 0 && more_modes(a, (gal_family)f) == GAL_OK) mode = next_mode(a, f);
        if (mode >= 0 && gal_rom_adapt_basis_size(a, a->nsel + 1, a->nextra + corr) > GAL_ROM_BASIS_CAP) mode = -1;
        while (corr && gal_rom_adapt_basis_size(a, a->nsel + (mode >= 0), a->nextra + corr) > GAL_ROM_BASIS_CAP) corr--;
        if (mode < 0 && !corr) {
            gal_error(GAL_EFAIL, "the basis grew to %d vectors (%d modes, %d corrections; at most %d) and the %s "
                      "residual is still %.3g", old->r, a->nsel, a->nextra, GAL_ROM_BASIS_CAP, gal_family_names[f],
                      chk->max);
            return GAL_ROM_ELIMIT;
        }
    }
    if (!(q = malloc((size_t)2 * a->rod->nq * sizeof(double)))) return gal_error(GAL_ENOMEM, "reduced model: out of memory");
    gal_rom_reconstruct(old, q, q + a->rod->nq); /* the state at the check, before the sampling */
    long steps0 = old->steps;
    if (!cubic && corr && a->orbit_vectors > 0) st = gal_rom_adapt_orbit_correction(a, old, chk, du, f, &corr, a->extra + (size_t)a->nextra * n);
    else if (!cubic && corr) st = gal_rom_residual_family(old, du, (gal_family)f, a->extra + (size_t)a->nextra * n);
    if (st) { free(q); return st; }
    a->orbit_steps += old->steps - steps0;
    if (!cubic) {
        if (mode >= 0) a->sel[a->nsel++] = mode;
        a->nextra += corr; /* the tripping family's correction alone (rom.h gal_rom_residual_family) */
    }
    gal_rom *nw = build(a);
    st = nw ? GAL_OK : GAL_EFAIL;
    if (!st && a->q0) { /* run again from the run's start: no restart transient (rom_adapt.h) */
        st = gal_rom_start(nw, 0.0, a->q0, a->v0);
        for (long i = 0; !st && a->replay_observe && a->replay_dt > 0 && i * a->replay_dt < t - 1e-3 * nw->o.h; i++)
            if (!(st = gal_rom_advance(nw, i * a->replay_dt))) a->replay_observe(a->replay_ctx, nw, i);
        if (!st) st = gal_rom_advance(nw, t);
        if (!st) a->replayed_s += t;
    } else if (!st) {
        st = gal_rom_start(nw, t, q, q + a->rod->nq);
        if (!st && a->relax) st = relax(old, nw, q, q + a->rod->nq);
    }
    free(q);
    if (st) { /* the old model stays (a cubic growth's basis is not restored: the run ends here) */
        gal_rom_free(nw);
        if (!cubic) a->nsel = nsel_was, a->nextra = nextra_was;
        return st;
    }
    if (!cubic && corr && mode < 0) a->corrected[f]++;
    gal_rom_event *e = &a->ev[a->nevents++];
    e->t_s = t, e->residual = chk->max, e->family = (gal_family)f;
    e->basis_before = old->r, e->basis_after = nw->r, e->mode_added = mode, e->corrections = corr;
    e->mode_added_hz = mode >= 0 ? a->md->mode[mode].frequency_hz : 0;
    nw->steps += old->steps, nw->newton_iterations += old->newton_iterations, nw->tangents += old->tangents;
    nw->force_evaluations += old->force_evaluations, nw->halvings += old->halvings;
    nw->build_time_s += old->build_time_s;
    nw->element_evaluations += old->element_evaluations, nw->load_element_evaluations += old->load_element_evaluations;
    nw->check_element_evaluations += old->check_element_evaluations;
    gal_rom_free(old);
    *m = nw;
    return GAL_OK;
}
