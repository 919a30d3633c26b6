/* onset.c: the galloping onset of the explicit bundle (bundle_dyn.h, gal_bundle_onset): at each wind
 * speed the mean-wind equilibrium of the assembled system, its natural modes there, the loads of
 * every sub-conductor linearized about it (each at its own relative wind: the spacers' rotation
 * moves the sub-conductors, R theta'), projected through the spacer map T on the modes, and the
 * single rod's eigen-sweep (analysis/onset.h, gal_onset_track). */
#include "gallop/bundle/bundle_dyn.h"
#include "gallop/base/core.h"
#include "gallop/analysis/stability.h"
#include "gallop/model/damping.h"
#include "gallop/model/model.h"
#include "bundle_impl.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/chol.h"

typedef struct {
    gal_bundle *b;
    gal_bundle_loads bl;
    gal_chol *chol;
    gal_csc *K0, *M0;          /* tangent and mass at the no-wind equilibrium */
    gal_damping *damping;      /* modal, as gal_bundle_simulate applies it */
    int n, nb;
    double *phi, *omega, *Ka, *Ca, *Cs, *f, *fp, *fm, *z, *v, *st, *mdiag, *scratch, *s0;
} ows;

static void ows_clear(ows *w)
{
    gal_bundle_loads_clear(&w->bl);
    gal_chol_free(w->chol);
    gal_csc_free(w->K0), gal_csc_free(w->M0);
    gal_damping_free(w->damping);
    double *p[] = {w->phi, w->omega, w->Ka, w->Ca, w->Cs, w->f, w->fp, w->fm, w->z, w->v, w->st, w->mdiag,
                   w->scratch, w->s0};
    for (size_t k = 0; k < sizeof p / sizeof p[0]; k++) free(p[k]);
    gal_bundle_free(w->b);
}

static double inf_norm(const double *v, int n)
{
    double m = 0;
    for (int k = 0; k < n; k++) m = fmax(m, fabs(v[k]));
    return m;
}

/* The residual r = T^T (grad U - F(s, 0)) at state s into w->f (and b->K, b->M with tangent). */
static int residual(ows *w, const double *s, int tangent)
{
    gal_bundle *b = w->b;
    int st = gal_bundle_eval(b, s, NULL, tangent);
    if (st) return st;
    memset(w->v, 0, (size_t)w->n * sizeof(double));
    memset(w->fp, 0, (size_t)w->n * sizeof(double));
    if ((st = gal_bundle_loads_eval(&w->bl, b, 0.0, s, w->v, w->fp))) return st;
    for (int j = 0; j < w->n; j++) w->f[j] = b->grad[j] - w->fp[j];
    return GAL_OK;
}

/* The equilibrium under the mean wind from b->state (in place): Newton with the structural tangent
 * (the aerodynamic stiffness is left out of the iteration matrix: a contraction while it is small
 * beside the tension's), a backtracking line search on the residual. */
static int equilibrium(ows *w, double U, double tol)
{
    gal_bundle *b = w->b;
    for (int r = 0; r < b->n; r++) w->bl.L[r].speed = U;
    for (int it = 0; it < 60; it++) {
        int st = residual(w, b->state, 1);
        if (st) return st;
        double rn = inf_norm(w->f, w->n);
        if (!isfinite(rn)) break;
        if (rn <= tol) return GAL_OK;
        if (gal_chol_factor(w->chol, b->K, 0, NULL) || w->chol->negative_pivots || gal_chol_solve(w->chol, w->f, w->z))
            break;
        int done = 0;
        for (double a = 1; a > 1e-3 && !done; a *= 0.5) {
            gal_bundle_step(b, b->state, w->z, -a, w->st);
            done = !residual(w, w->st, 0) && inf_norm(w->f, w->n) < rn;
        }
        if (!done) break;
        memcpy(b->state, w->st, (size_t)b->nstate * sizeof(double));
    }
    return gal_error(GAL_EFAIL, "bundle onset: no equilibrium under the mean wind at %.4g m/s", U);
}

/* Column c of -Phi^T d(T^T F)/dx phi_c by a central difference along basis vector c: of the state
 * (dv = 0; the map T re-evaluated at each side) or of the velocity (dv = 1, at the state). */
static int aero_column(ows *w, int c, int dv, double *col)
{
    gal_bundle *b = w->b;
    const double *p = w->phi + (size_t)c * w->n;
    double big = inf_norm(p, w->n), U = fmax(fabs(w->bl.L[0].speed), 1.0);
    double h = (dv ? 1e-6 * U : 1e-6) / fmax(big, 1e-300);
    double *out[2] = {w->fp, w->fm};
    for (int side = 0; side < 2; side++) {
        double sg = side ? -h : h;
        int st;
        memset(out[side], 0, (size_t)w->n * sizeof(double));
        if (dv) {
            for (int j = 0; j < w->n; j++) w->v[j] = sg * p[j];
            if ((st = gal_bundle_eval(b, NULL, NULL, 0))) return st;
            st = gal_bundle_loads_eval(&w->bl, b, 0.0, b->state, w->v, out[side]);
        } else {
            gal_bundle_step(b, b->state, p, sg, w->st);
            memset(w->v, 0, (size_t)w->n * sizeof(double));
            if (!(st = gal_bundle_eval(b, w->st, NULL, 0))) st = gal_bundle_loads_eval(&w->bl, b, 0.0, w->st, w->v, out[side]);
        }
        if (st) return st;
    }
    for (int a = 0; a < w->nb; a++) {
        const double *pa = w->phi + (size_t)a * w->n;
        double s = 0;
        for (int j = 0; j < w->n; j++) s += pa[j] * (w->fp[j] - w->fm[j]);
        col[a] = -s / (2 * h);
    }
    return GAL_OK;
}

/* Kinetic-energy shares (vertical, horizontal, torsional: the bundle's kinematics, bundle.h) of the
 * complex shape ure + i uim over the system's dofs: its two parts' shares weighted by their energy. */
static void shares(void *ctx, const double *ure, const double *uim, double share[3])
{
    ows *w = ctx;
    const double *u[2] = {ure, uim};
    double e[2], sh[2][3];
    for (int p = 0; p < 2; p++) {
        gal_mode md;
        memset(&md, 0, sizeof md);
        gal_csc_symv(w->M0, u[p], w->fp);
        e[p] = 0;
        for (int j = 0; j < w->n; j++) e[p] += u[p][j] * w->fp[j];
        if (e[p] > 0) gal_bundle_classify(w->b, u[p], w->scratch, &md);
        for (int f = 0; f < 3; f++) sh[p][f] = md.share[f];
    }
    double tot = e[0] + e[1];
    for (int f = 0; f < 3; f++) share[f] = tot > 0 ? (e[0] * sh[0][f] + e[1] * sh[1][f]) / tot : 0;
}

/* The basis, the projected matrices and the classic columns at the equilibrium of speed sp->speed. */
static int at_speed(ows *w, double mass, gal_onset_speed *sp)
{
    gal_bundle *b = w->b;
    gal_modes md;
    int st = gal_bundle_modes_solve(b, w->nb, &md), n = w->n, nb = w->nb;
    if (st) return gal_error(st, "bundle onset: modes at %.4g m/s: %s", sp->speed, gal_error_message());
    memcpy(w->phi, md.shape, (size_t)n * nb * sizeof(double));
    for (int k = 0; k < nb; k++) w->omega[k] = md.mode[k].omega;
    if (!st) st = gal_damping_project(w->damping, w->phi, nb, w->Cs); /* Cs = Phi^T C Phi */
    for (int c = 0; c < nb && !st; c++) st = aero_column(w, c, 0, w->Ka + (size_t)c * nb);
    for (int c = 0; c < nb && !st; c++)
        if (w->bl.L[0].aero_damping) st = aero_column(w, c, 1, w->Ca + (size_t)c * nb);
        else memset(w->Ca + (size_t)c * nb, 0, (size_t)nb * sizeof(double));
    if (!st) st = gal_bundle_eval(b, NULL, NULL, 0);
    gal_onset_measures(b->rod[0], b->state, &w->bl.L[0], sp);
    sp->zeta_vertical = sp->den_hartog_onset = sp->zeta_torsional = sp->nigol_onset = NAN;
    for (int k = nb - 1; k >= 0; k--) {
        double z = w->Cs[k + (size_t)k * nb] / (2 * w->omega[k]);
        if (md.mode[k].family == GAL_FAMILY_TORSIONAL) sp->zeta_torsional = z;
        if (md.mode[k].family != GAL_FAMILY_VERTICAL) continue;
        sp->zeta_vertical = z;
        sp->den_hartog_onset = gal_stability_onset(w->bl.L[0].table, sp->alpha_deg * GAL_PI / 180, mass, z,
                                                   w->omega[k], w->bl.L[0].rho, w->bl.L[0].diam);
    }
    gal_modes_clear(&md);
    return st;
}

/* The bundle at its no-wind equilibrium, the damping, the loads and the work arrays. */
static int setup(ows *w, const gal_model *m, int basis)
{
    gal_modes md;
    memset(w, 0, sizeof *w);
    int st = gal_bundle_solve_model(m, &w->b, &md);
    if (st) return st;
    gal_modes_clear(&md);
    gal_bundle *b = w->b;
    if (!(w->damping = gal_bundle_damping_modal(b, m->damping_ratio, 0))) return gal_error_status();
    int n = w->n = b->ndof, nb = w->nb = basis < n - 1 ? basis : n - 1;
    if ((st = gal_bundle_eval(b, NULL, NULL, 1))) return st;
    w->K0 = gal_csc_clone(b->K), w->M0 = gal_csc_clone(b->M), w->chol = gal_chol_alloc(b->K);
    if (w->K0 && w->M0) { /* the clones are the pattern: the values at the no-wind equilibrium */
        memcpy(w->K0->val, b->K->val, (size_t)b->K->nnz * sizeof(double));
        memcpy(w->M0->val, b->M->val, (size_t)b->M->nnz * sizeof(double));
    }
    gal_loads base = m->loads;
    base.u = NULL, base.nt = 0, base.ramp_time = 0, base.reverse_time = 0;
    if ((st = gal_bundle_loads_init(&w->bl, b, &base, m->sc.wind.air_density, m->sc.bundle.wake_factor))) return st;
    size_t b2 = (size_t)nb * nb;
    w->phi = malloc((size_t)n * nb * sizeof(double)), w->omega = malloc((size_t)nb * sizeof(double));
    w->Ka = malloc(b2 * sizeof(double)), w->Ca = malloc(b2 * sizeof(double)), w->Cs = malloc(b2 * sizeof(double));
    w->f = malloc((size_t)n * sizeof(double)), w->fp = malloc((size_t)n * sizeof(double));
    w->fm = malloc((size_t)n * sizeof(double)), w->z = malloc((size_t)n * sizeof(double));
    w->v = malloc((size_t)n * sizeof(double)), w->mdiag = malloc((size_t)n * sizeof(double));
    w->st = malloc((size_t)b->nstate * sizeof(double)), w->s0 = malloc((size_t)b->nstate * sizeof(double));
    w->scratch = malloc(gal_bundle_classify_scratch(b) * sizeof(double));
    if (!w->K0 || !w->M0 || !w->chol || !w->phi || !w->omega || !w->Ka || !w->Ca || !w->Cs || !w->f || !w->fp ||
        !w->fm || !w->z || !w->v || !w->mdiag || !w->st || !w->s0 || !w->scratch)
        return gal_error(GAL_ENOMEM, "bundle onset: out of memory for %d dofs", n);
    for (int j = 0; j < n; j++) w->mdiag[j] = w->M0->val[w->M0->diag[j]];
    memcpy(w->s0, b->state, (size_t)b->nstate * sizeof(double));
    return GAL_OK;
}

int gal_bundle_onset(const gal_model *m, const gal_onset_opts *o, gal_onset *out)
{
    double t0 = gal_wall_time();
    memset(out, 0, sizeof *out);
    if (!m->loads.table) return gal_error(GAL_EINPUT, "bundle onset: no aerodynamic table");
    if (!(o->speed_step > 0) || !(o->speed_min >= 0) || !(o->speed_max >= o->speed_min) ||
        (o->speed_max - o->speed_min) / o->speed_step > 1e5)
        return gal_error(GAL_EINPUT, "bundle onset: wind speeds %g to %g m/s by %g: allowed 0 <= speed_min <= "
                         "speed_max, step > 0, at most 1e5 steps", o->speed_min, o->speed_max, o->speed_step);
    ows w;
    int st = setup(&w, m, o->basis);
    int nm = o->nmodes < w.nb ? o->nmodes : w.nb;
    gal_onset_track *tr = st ? NULL : gal_onset_track_alloc(w.n, w.nb, nm, w.mdiag);
    if (!st && !tr) st = gal_error_status();
    out->nspeed = (int)floor((o->speed_max - o->speed_min) / o->speed_step + 1e-9) + 1;
    out->nmodes = nm, out->basis = w.nb, out->speed_max = o->speed_max, out->fold_speed = NAN;
    out->sp = calloc((size_t)out->nspeed, sizeof *out->sp);
    out->m = calloc((size_t)out->nspeed * (nm > 0 ? nm : 1), sizeof *out->m);
    if (!st && (!out->sp || !out->m)) st = gal_error(GAL_ENOMEM, "bundle onset: out of memory");
    double mass = m->sc.conductor.mass_per_length + (m->sc.ice.present ? m->sc.ice.mass_per_length : 0);
    double tol = st ? 0 : 1e-6 * fmax(w.b->horizontal_tension, 1.0) / w.b->rod[0]->p.elements;
    for (int i = 0; i < out->nspeed && !st; i++) {
        gal_onset_speed *sp = out->sp + i;
        sp->speed = o->speed_min + i * o->speed_step;
        if (equilibrium(&w, sp->speed, tol)) {
            if (i == 0) st = GAL_EFAIL;
            break; /* the rest is not reached (ok = 0) */
        }
        st = at_speed(&w, mass, sp);
        if (!st) st = gal_onset_track_speed(tr, w.phi, w.omega, w.Ka, w.Ca, w.Cs, shares, &w, sp, out, i);
        sp->ok = !st;
    }
    gal_onset_track_free(tr);
    ows_clear(&w);
    if (st) { gal_onset_clear(out); return st; }
    gal_onset_conclude(out);
    out->wall_time_s = gal_wall_time() - t0;
    return GAL_OK;
}

int gal_bundle_scene_onset(const gal_scene *sc, gal_onset *O)
{
    int st;
    gal_model *m = gal_model_alloc(sc, &st);
    if (!st) {
        gal_onset_opts o;
        gal_onset_default_opts(&o);
        o.speed_min = sc->stability.speed_min, o.speed_max = sc->stability.speed_max;
        o.speed_step = sc->stability.speed_step;
        st = gal_bundle_onset(m, &o, O);
    }
    gal_model_free(m);
    return st;
}
