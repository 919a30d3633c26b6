/* onset.c: the galloping onset of the coupled aeroelastic system over a range of wind speeds:
 * mean-wind equilibrium by continuation, linearization on a modal basis, eigenvalues, modes
 * followed over the speeds, onset, divergence and folds (issue 15). */
#include "onset_internal.h"
#include "gallop/analysis/stability.h"
#include "gallop/base/core.h"
#include "gallop/base/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define DEG (180.0 / GAL_PI)

void gal_onset_default_opts(gal_onset_opts *o)
{
    memset(o, 0, sizeof *o);
    o->speed_min = GAL_ONSET_SPEED_MIN;
    o->speed_max = GAL_ONSET_SPEED_MAX;
    o->speed_step = GAL_ONSET_SPEED_STEP;
    o->basis = GAL_ONSET_BASIS;
    o->nmodes = GAL_ONSET_NMODES;
}

void gal_onset_clear(gal_onset *r)
{
    free(r->sp);
    free(r->m);
    memset(r, 0, sizeof *r);
}

struct gal_onset_track {
    int n, nb, N, nm, lwork, nq, nev, ncand;
    int ntors; /* torsional modes appended to the basis above its lowest nb - ntors modes */
    double *phi, *omega, *Ka, *Ca, *Cs, *Kt, *Ct, *A, *wr, *wi, *VR, *work;
    double *cre, *cim, *clr, *cli; /* candidates: physical shapes (n x N) and eigenvalues */
    double *pre, *pim, *pf;        /* followed modes at the previous speed: shapes, frequency */
    double *score, *full, *mdiag, *q, *qprev, *tmp;
    int *used;
};
typedef struct gal_onset_track work;

static void work_free(work *w)
{
    double *p[] = {w->phi, w->omega, w->Ka, w->Ca, w->Cs, w->Kt, w->Ct, w->A, w->wr, w->wi, w->VR, w->work, w->cre,
                   w->cim, w->clr, w->cli, w->pre, w->pim, w->pf, w->score, w->full, w->mdiag, w->q, w->qprev, w->tmp};
    for (size_t k = 0; k < sizeof p / sizeof p[0]; k++) free(p[k]);
    free(w->used);
}

/* The work of n dofs (nq of the full configuration), nb basis modes, nm followed; w->mdiag unset. */
static int work_alloc_n(work *w, int ndof, int nq, int nb, int nm)
{
    memset(w, 0, sizeof *w);
    size_t n = (size_t)ndof, N = 2 * (size_t)nb, b2 = (size_t)nb * nb;
    w->n = ndof, w->nb = nb, w->N = (int)N, w->nm = nm, w->nq = nq, w->lwork = (int)(8 * N + 64);
    w->phi = malloc(n * nb * sizeof(double)), w->omega = malloc(nb * sizeof(double));
    w->Ka = malloc(b2 * sizeof(double)), w->Ca = malloc(b2 * sizeof(double)), w->Cs = malloc(b2 * sizeof(double));
    w->Kt = malloc(b2 * sizeof(double)), w->Ct = malloc(b2 * sizeof(double)), w->A = malloc(N * N * sizeof(double));
    w->wr = malloc(N * sizeof(double)), w->wi = malloc(N * sizeof(double)), w->VR = malloc(N * N * sizeof(double));
    w->work = malloc((size_t)w->lwork * sizeof(double));
    w->cre = malloc(n * N * sizeof(double)), w->cim = malloc(n * N * sizeof(double));
    w->clr = malloc(N * sizeof(double)), w->cli = malloc(N * sizeof(double));
    w->pre = malloc(n * nm * sizeof(double)), w->pim = malloc(n * nm * sizeof(double)), w->pf = malloc(nm * sizeof(double));
    w->score = malloc((size_t)nm * N * sizeof(double)), w->full = malloc(2 * n * sizeof(double) + 2 * (size_t)nq * sizeof(double));
    w->mdiag = malloc(n * sizeof(double)), w->q = malloc((size_t)nq * sizeof(double));
    w->qprev = malloc((size_t)nq * sizeof(double)), w->tmp = malloc(N * sizeof(double));
    w->used = malloc(N * sizeof(int));
    double *p[] = {w->phi, w->omega, w->Ka, w->Ca, w->Cs, w->Kt, w->Ct, w->A, w->wr, w->wi, w->VR, w->work, w->cre,
                   w->cim, w->clr, w->cli, w->pre, w->pim, w->pf, w->score, w->full, w->mdiag, w->q, w->qprev, w->tmp};
    for (size_t k = 0; k < sizeof p / sizeof p[0]; k++)
        if (!p[k]) return gal_error(GAL_ENOMEM, "onset: out of memory for a basis of %d modes", nb);
    if (!w->used) return gal_error(GAL_ENOMEM, "onset: out of memory");
    return GAL_OK;
}

static int work_alloc(work *w, const gal_rod *rod, int nb, int nm)
{
    int st = work_alloc_n(w, rod->ndof, rod->nq, nb, nm);
    if (!st) gal_rod_mass_diag(rod, w->mdiag);
    return st;
}

void gal_onset_measures(const gal_rod *rod, const double *q, const gal_loads *L, gal_onset_speed *sp)
{
    int nn = rod->nn, nel = rod->p.elements, mid = nn / 2, e = nel / 2;
    double off[3];
    for (int k = 0; k < 3; k++) off[k] = q[3 * mid + k] - 0.5 * (q[k] + q[3 * nel + k]);
    sp->swing_deg = atan2(off[1], -off[2]) * DEG;
    sp->twist_deg = 0;
    if (rod->p.torsion)
        sp->twist_deg = (nel % 2 ? q[3 * nn + e] : 0.5 * (q[3 * nn + e - 1] + q[3 * nn + e])) * DEG;
    double t[3], d1[3], b[3], d[3], c = cos(L->attack_angle), s = sin(L->attack_angle);
    gal_rod_material_frame(rod, q, e, t, d1);
    gal_cross3(t, d1, b);
    for (int k = 0; k < 3; k++) d[k] = c * d1[k] - s * b[k];
    double alpha = gal_aero_alpha(t, d, L->dir), cf[3], dc[3];
    sp->alpha_deg = alpha * DEG;
    gal_aero_eval(L->table, alpha, cf, dc);
    sp->den_hartog = gal_aero_den_hartog(L->table, alpha);
    sp->nigol_dcm = dc[2];
}

/* The basis at configuration q: the lowest nb natural modes of the families asked for, and the
 * classic Den Hartog column from the lowest vertical one. */
static int basis_at(work *w, const gal_rod *rod, const double *q, const gal_loads *L, const gal_damping *C,
                    double mass, unsigned fam, gal_onset_speed *sp)
{
    gal_modes md;
    int k = 0, n = w->n;
    for (;;) {
        int st = gal_modes_solve(rod, q, w->nev, &md);
        if (st) return gal_error(st, "onset: modes at %.4g m/s: %s", sp->speed, gal_error_message());
        k = 0;
        for (int j = 0; j < md.n && k < w->nb; j++) /* the lowest nb - ntors, then the torsional ones above */
            if ((!fam || (fam >> md.mode[j].family & 1u)) &&
                (k < w->nb - w->ntors || md.mode[j].family == GAL_FAMILY_TORSIONAL)) {
                memcpy(w->phi + (size_t)k * n, md.shape + (size_t)j * n, (size_t)n * sizeof(double));
                w->omega[k++] = md.mode[j].omega;
            }
        /* the wind's equilibrium reorders the modes (a torsional one found at rest can lie above the
         * modes asked for here): ask for more, kept for the next speeds, up to every mode */
        if (k == w->nb || w->nev >= n - 1) break;
        gal_modes_clear(&md);
        int more = w->nev + (w->nev / 2 > 20 ? w->nev / 2 : 20);
        w->nev = more < n - 1 ? more : n - 1;
    }
    sp->zeta_vertical = NAN, sp->den_hartog_onset = NAN;
    for (int j = 0; j < md.n; j++)
        if (md.mode[j].family == GAL_FAMILY_VERTICAL) {
            sp->zeta_vertical = gal_damping_ratio(C, md.shape + (size_t)j * n, md.mode[j].omega);
            double a = sp->alpha_deg / DEG;
            sp->den_hartog_onset = gal_stability_onset(L->table, a, mass, sp->zeta_vertical, md.mode[j].omega, L->rho, L->diam);
            break;
        }
    sp->zeta_torsional = NAN, sp->nigol_onset = NAN;
    for (int j = 0; j < md.n && rod->p.torsion; j++)
        if (md.mode[j].family == GAL_FAMILY_TORSIONAL) {
            int e = rod->p.elements / 2;
            double I = rod->edge_inertia[e] / rod->l0[e], wt = md.mode[j].omega;
            sp->zeta_torsional = gal_damping_ratio(C, md.shape + (size_t)j * n, wt);
            sp->nigol_onset = gal_stability_nigol_onset(sp->nigol_dcm, I, wt, sp->zeta_torsional, L->rho, L->diam);
            break;
        }
    gal_modes_clear(&md);
    if (k < w->nb) return gal_error(GAL_EFAIL, "onset: %d of the %d basis modes of the families asked for among %d modes",
                                    k, w->nb, w->nev);
    return GAL_OK;
}

static int modal_eig(work *w, gal_onset_speed *sp);

/* Linearize at q, solve, and leave the candidates (eigenvalues with Im >= 0 and their physical
 * shapes) in w. */
static int linearize(work *w, const gal_rod *rod, const double *q, const gal_loads *L, const gal_damping *C,
                     gal_onset_speed *sp)
{
    int st = gal_onset_aero_matrices(rod, q, L, w->phi, w->nb, w->Ka, w->Ca);
    if (!st) st = gal_damping_project(C, w->phi, w->nb, w->Cs);
    return st ? st : modal_eig(w, sp);
}

/* On the basis w->phi (frequencies w->omega) with w->Ka, w->Ca, w->Cs: K_t's smallest eigenvalue,
 * the linear divergence speed, the state matrix's eigenvalues, the candidates. */
static int modal_eig(work *w, gal_onset_speed *sp)
{
    int nb = w->nb, n = w->n, st;
    for (int j = 0; j < nb * nb; j++) w->Kt[j] = w->Ka[j], w->Ct[j] = w->Cs[j] + w->Ca[j];
    for (int j = 0; j < nb; j++) w->Kt[j + (size_t)j * nb] += w->omega[j] * w->omega[j];
    /* the static stability: smallest real eigenvalue of K_t */
    int info = 0, one = 1;
    double dummy;
    memcpy(w->A, w->Kt, (size_t)nb * nb * sizeof(double));
    dgeev_("N", "N", &nb, w->A, &nb, w->wr, w->wi, &dummy, &one, &dummy, &one, w->work, &w->lwork, &info);
    if (info) return gal_error(GAL_EFAIL, "onset: LAPACK dgeev failed (info %d) on K_t", info);
    double kr = INFINITY, ka = INFINITY;
    for (int j = 0; j < nb; j++) {
        ka = fmin(ka, w->wr[j]);
        if (fabs(w->wi[j]) <= 1e-9 * fabs(w->wr[j])) kr = fmin(kr, w->wr[j]);
    }
    sp->kt_min = isfinite(kr) ? kr : ka;
    /* the linear divergence speed about this configuration: K_t = diag(w^2) + (U'/U)^2 Ka is
     * singular where 1/U'^2 is a real eigenvalue of -diag(w^-2) Ka / U^2 */
    sp->divergence_linear = INFINITY;
    if (sp->speed > 0) {
        double u2 = sp->speed * sp->speed, nu = 0;
        for (int j = 0; j < nb; j++)
            for (int i = 0; i < nb; i++) w->A[i + (size_t)j * nb] = -w->Ka[i + (size_t)j * nb] / (w->omega[i] * w->omega[i] * u2);
        dgeev_("N", "N", &nb, w->A, &nb, w->wr, w->wi, &dummy, &one, &dummy, &one, w->work, &w->lwork, &info);
        if (info) return gal_error(GAL_EFAIL, "onset: LAPACK dgeev failed (info %d) on the divergence problem", info);
        for (int j = 0; j < nb; j++)
            if (fabs(w->wi[j]) <= 1e-9 * fabs(w->wr[j])) nu = fmax(nu, w->wr[j]);
        if (nu > 0) sp->divergence_linear = 1 / sqrt(nu);
    }
    if ((st = gal_onset_state_eig(nb, w->Kt, w->Ct, w->A, w->wr, w->wi, w->VR, w->work, w->lwork))) return st;
    w->ncand = 0;
    for (int k = 0; k < w->N; k++) {
        if (w->wi[k] < 0) continue;
        int c = w->ncand++, cx = w->wi[k] > 0;
        const double *er = w->VR + (size_t)k * w->N, *ei = cx ? er + w->N : NULL;
        double *ur = w->cre + (size_t)c * n, *ui = w->cim + (size_t)c * n;
        memset(ur, 0, (size_t)n * sizeof(double));
        memset(ui, 0, (size_t)n * sizeof(double));
        for (int a = 0; a < nb; a++) {
            const double *p = w->phi + (size_t)a * n;
            for (int j = 0; j < n; j++) {
                ur[j] += er[a] * p[j];
                if (cx) ui[j] += ei[a] * p[j];
            }
        }
        w->clr[c] = w->wr[k], w->cli[c] = w->wi[k];
    }
    return GAL_OK;
}

static double mac(const work *w, const double *ar, const double *ai, const double *br, const double *bi)
{
    double re = 0, im = 0, na = 0, nb = 0;
    for (int j = 0; j < w->n; j++) {
        double m = w->mdiag[j];
        re += m * (ar[j] * br[j] + ai[j] * bi[j]);
        im += m * (ar[j] * bi[j] - ai[j] * br[j]);
        na += m * (ar[j] * ar[j] + ai[j] * ai[j]);
        nb += m * (br[j] * br[j] + bi[j] * bi[j]);
    }
    return na > 0 && nb > 0 ? (re * re + im * im) / (na * nb) : 0;
}

/* Assign the candidates to the followed modes (first speed: the lowest |lambda|), record them. */
static void follow(work *w, gal_onset_shares_fn shares, void *ctx, gal_onset *out, int i)
{
    int nm = w->nm, nc = w->ncand, n = w->n;
    for (int c = 0; c < nc; c++) w->used[c] = 0;
    int assigned[64];
    for (int k = 0; k < nm; k++) assigned[k] = -1;
    for (int r = 0; r < nm; r++) {
        int bk = -1, bc = -1;
        double best = -INFINITY;
        for (int k = 0; k < nm; k++) {
            if (assigned[k] >= 0) continue;
            for (int c = 0; c < nc; c++) {
                if (w->used[c]) continue;
                double f = hypot(w->clr[c], w->cli[c]), s;
                if (i == 0) s = -f - 1e-9 * k; /* the lowest, in order */
                else s = mac(w, w->pre + (size_t)k * n, w->pim + (size_t)k * n, w->cre + (size_t)c * n, w->cim + (size_t)c * n) -
                         fabs(w->cli[c] - w->pf[k]) / fmax(fmax(w->pf[k], w->cli[c]), 1e-9);
                if (s > best) best = s, bk = k, bc = c;
            }
        }
        if (bk < 0) break;
        assigned[bk] = bc, w->used[bc] = 1;
    }
    for (int k = 0; k < nm; k++) {
        gal_onset_mode *m = out->m + (size_t)i * nm + k;
        int c = assigned[k];
        if (c < 0) { m->frequency_hz = m->damping_ratio = m->growth_rate = NAN; continue; }
        double lr = w->clr[c], li = w->cli[c], r = hypot(lr, li);
        const double *ur = w->cre + (size_t)c * n, *ui = w->cim + (size_t)c * n;
        m->mac = i == 0 ? 1 : mac(w, w->pre + (size_t)k * n, w->pim + (size_t)k * n, ur, ui);
        m->frequency_hz = li / (2 * GAL_PI);
        m->damping_ratio = r > 0 ? -lr / r : 0;
        m->growth_rate = lr;
        shares(ctx, ur, ui, m->share);
        memcpy(w->pre + (size_t)k * n, ur, (size_t)n * sizeof(double));
        memcpy(w->pim + (size_t)k * n, ui, (size_t)n * sizeof(double));
        w->pf[k] = li;
    }
}

typedef struct { const gal_rod *rod; const double *q; double *full; } rod_shares_ctx;

static void rod_shares(void *ctx, const double *ure, const double *uim, double share[3])
{
    rod_shares_ctx *c = ctx;
    gal_onset_shares(c->rod, c->q, ure, uim, c->full, share);
}

/* Onset (lowest zero crossing of a followed mode's damping ratio), divergence, fold. */
void gal_onset_conclude(gal_onset *out)
{
    int nm = out->nmodes;
    for (int i = 0; i < out->nspeed; i++)
        if (!out->sp[i].ok) {
            out->sp[i].swing_deg = out->sp[i].twist_deg = out->sp[i].alpha_deg = NAN;
            for (int k = 0; k < nm; k++) out->m[(size_t)i * nm + k].damping_ratio = NAN;
        }
    out->onset_speed = out->divergence_speed = out->restable_speed = NAN;
    out->onset_mode = -1;
    double zprev = NAN, uprev = NAN; /* the least damping ratio over the modes at the last speed solved */
    for (int i = 0; i < out->nspeed; i++) {
        const gal_onset_speed *s1 = out->sp + i, *s0 = i > 0 ? s1 - 1 : NULL;
        if (!s1->ok) continue;
        if (isnan(out->divergence_speed) && s0 && s0->ok && s0->kt_min > 0 && s1->kt_min <= 0) {
            /* the linear estimate about the last stable configuration when it falls in the bracket
             * (exact on a path that does not move), else the interpolated kt_min */
            double ud = s0->divergence_linear;
            out->divergence_speed = ud >= s0->speed && ud <= s1->speed ? ud
                : s0->speed + (s1->speed - s0->speed) * s0->kt_min / (s0->kt_min - s1->kt_min);
        }
        double z = INFINITY;
        for (int k = 0; k < nm; k++) z = fmin(z, out->m[(size_t)i * nm + k].damping_ratio);
        if (z <= 0) out->restable_speed = NAN;
        else if (zprev <= 0) out->restable_speed = uprev + (s1->speed - uprev) * zprev / (zprev - z);
        zprev = z, uprev = s1->speed;
        for (int k = 0; k < nm; k++) {
            const gal_onset_mode *m1 = out->m + (size_t)i * nm + k, *m0 = i > 0 ? m1 - nm : NULL;
            if (!(m1->damping_ratio <= 0) || !(m1->frequency_hz > 0)) continue;
            double u = s1->speed, a = 1;
            if (m0 && s0->ok && m0->damping_ratio > 0) {
                a = m0->damping_ratio / (m0->damping_ratio - m1->damping_ratio);
                u = s0->speed + a * (s1->speed - s0->speed);
            } else if (i > 0) continue; /* not a crossing: already unstable before */
            if (isnan(out->onset_speed) || u < out->onset_speed) {
                out->onset_speed = u, out->onset_mode = k;
                const gal_onset_mode *lo = m0 && s0->ok ? m0 : m1;
                out->onset_frequency_hz = lo->frequency_hz + a * (m1->frequency_hz - lo->frequency_hz);
                for (int f = 0; f < 3; f++) out->onset_share[f] = lo->share[f] + a * (m1->share[f] - lo->share[f]);
            }
        }
    }
}

/* The torsional modes the basis needs above its lowest nb: the twist of a mode of either symmetry
 * needs a torsional mode of that symmetry (a 450-m span's first antisymmetric torsional mode is its
 * 34th: without it the antisymmetric vertical modes cannot twist, and the onset was 1.8% high).
 * Out: *nt torsional modes to append (up to GAL_ONSET_TORSIONAL less those among the lowest nb),
 * *nev the modes to solve for (their rank at no wind, with a margin for the shift under wind). */
static int torsional_extension(const gal_rod *rod, const double *q_eq, const gal_onset_opts *o, int nb, int *nt, int *nev)
{
    *nt = 0;
    if (!rod->p.torsion || (o->families && !(o->families >> GAL_FAMILY_TORSIONAL & 1u))) return GAL_OK;
    int probe = 3 * nb + 40 < rod->ndof - 1 ? 3 * nb + 40 : rod->ndof - 1, last = -1;
    gal_modes md;
    int st = gal_modes_solve(rod, q_eq, probe, &md);
    if (st) return gal_error(st, "onset: modes at no wind: %s", gal_error_message());
    for (int j = 0, found = 0; j < md.n && found < GAL_ONSET_TORSIONAL; j++)
        if (md.mode[j].family == GAL_FAMILY_TORSIONAL) {
            found++, last = j;
            if (j >= nb) ++*nt;
        }
    gal_modes_clear(&md);
    int need = last + 11 < rod->ndof - 1 ? last + 11 : rod->ndof - 1;
    if (*nt && need > *nev) *nev = need;
    return GAL_OK;
}

int gal_onset_analyse(const gal_rod *rod, const double *q_eq, const gal_loads *L, const gal_damping *C, double mass,
                      const gal_onset_opts *o, gal_onset *out)
{
    double t0 = gal_wall_time();
    memset(out, 0, sizeof *out);
    if (!L->table) return gal_error(GAL_EINPUT, "onset: no aerodynamic table");
    if (!(o->speed_step > 0) || !(o->speed_min >= 0) || !(o->speed_max >= o->speed_min) ||
        (o->speed_max - o->speed_min) / o->speed_step > 1e5)
        return gal_error(GAL_EINPUT, "onset: wind speeds %g to %g m/s by %g: allowed 0 <= speed_min <= speed_max, "
                         "step > 0, at most 1e5 steps", o->speed_min, o->speed_max, o->speed_step);
    int nb = o->basis < rod->ndof - 1 ? o->basis : rod->ndof - 1, nm = o->nmodes < nb ? o->nmodes : nb;
    if (nb < 1 || nm < 1 || nm > 64) return gal_error(GAL_EINPUT, "onset: basis %d and modes followed %d: allowed "
                                                      "1 <= modes <= basis, modes <= 64", o->basis, o->nmodes);
    int nt = 0, nev = o->families ? (3 * nb + 20 < rod->ndof - 1 ? 3 * nb + 20 : rod->ndof - 1) : nb;
    int st = torsional_extension(rod, q_eq, o, nb, &nt, &nev);
    work w;
    if (!st) st = work_alloc(&w, rod, nb + nt, nm);
    else memset(&w, 0, sizeof w);
    w.nev = nev, w.ntors = nt;
    nb += nt;
    out->nspeed = (int)floor((o->speed_max - o->speed_min) / o->speed_step + 1e-9) + 1;
    out->nmodes = nm, out->basis = nb, out->speed_max = o->speed_max;
    out->sp = calloc((size_t)out->nspeed + 1, sizeof *out->sp); /* row 0: before the first speed */
    out->m = calloc((size_t)out->nspeed * nm, sizeof *out->m);
    if (!st && (!out->sp || !out->m)) st = gal_error(GAL_ENOMEM, "onset: out of memory");
    gal_loads Ls = *L;
    Ls.u = NULL, Ls.nt = 0, Ls.ramp_time = 0, Ls.reverse_time = 0, Ls.rod = rod;
    double H = 0, *u = NULL, *Q = NULL;
    int *ok = NULL, *fold = NULL;
    if (!st) {
        double *g = calloc((size_t)rod->nq, sizeof(double));
        if (g && !gal_rod_eval(rod, q_eq, NULL, g, NULL)) H = fabs(g[0]);
        free(g);
        u = malloc((size_t)out->nspeed * sizeof(double));
        Q = malloc((size_t)out->nspeed * rod->nq * sizeof(double));
        ok = malloc(2 * (size_t)out->nspeed * sizeof(int));
        if (!u || !Q || !ok) st = gal_error(GAL_ENOMEM, "onset: out of memory for %d speeds", out->nspeed);
        else fold = ok + out->nspeed;
    }
    double tol = o->static_tol > 0 ? o->static_tol : 1e-6 * fmax(H, 1.0) / rod->p.elements;
    for (int i = 0; !st && i < out->nspeed; i++) u[i] = o->speed_min + i * o->speed_step;
    if (!st) st = gal_onset_static_path(rod, q_eq, &Ls, tol, out->nspeed, u, Q, ok, fold, &out->fold_speed);
    for (int i = 0; i < out->nspeed && !st; i++) {
        gal_onset_speed *sp = out->sp + 1 + i;
        sp->speed = Ls.speed = u[i];
        if (!ok[i]) continue;
        memcpy(w.q, Q + (size_t)i * rod->nq, (size_t)rod->nq * sizeof(double));
        gal_onset_measures(rod, w.q, &Ls, sp);
        sp->fold = fold[i];
        st = basis_at(&w, rod, w.q, &Ls, C, mass, o->families, sp);
        if (!st) st = linearize(&w, rod, w.q, &Ls, C, sp);
        rod_shares_ctx rc = {rod, w.q, w.full};
        if (!st) follow(&w, rod_shares, &rc, out, i);
        sp->ok = !st;
    }
    free(u); free(Q); free(ok);
    if (out->sp) memmove(out->sp, out->sp + 1, (size_t)out->nspeed * sizeof *out->sp);
    work_free(&w);
    if (st) { gal_onset_clear(out); return st; }
    double fs = out->fold_speed;
    gal_onset_conclude(out);
    out->fold_speed = fs;
    out->wall_time_s = gal_wall_time() - t0;
    return GAL_OK;
}

/* ---- the eigen-sweep on another discretization (onset.h) ---- */

gal_onset_track *gal_onset_track_alloc(int n, int nb, int nm, const double *mdiag)
{
    work *w = malloc(sizeof *w);
    if (!w) { gal_error(GAL_ENOMEM, "onset: out of memory"); return NULL; }
    if (nb < 1 || nm < 1 || nm > nb || nm > 64 || nb > n) {
        free(w);
        gal_error(GAL_EINPUT, "onset: basis %d and modes followed %d of %d dofs: allowed 1 <= modes <= basis <= dofs, "
                  "modes <= 64", nb, nm, n);
        return NULL;
    }
    if (work_alloc_n(w, n, 1, nb, nm)) { work_free(w); free(w); return NULL; }
    memcpy(w->mdiag, mdiag, (size_t)n * sizeof(double));
    return w;
}

gal_onset_track *gal_onset_track_free(gal_onset_track *t)
{
    if (t) work_free(t);
    free(t);
    return NULL;
}

int gal_onset_track_speed(gal_onset_track *w, const double *phi, const double *omega, const double *Ka,
                          const double *Ca, const double *Cs, gal_onset_shares_fn shares, void *ctx,
                          gal_onset_speed *sp, gal_onset *out, int i)
{
    size_t nb = (size_t)w->nb;
    memcpy(w->phi, phi, (size_t)w->n * nb * sizeof(double));
    memcpy(w->omega, omega, nb * sizeof(double));
    memcpy(w->Ka, Ka, nb * nb * sizeof(double));
    memcpy(w->Ca, Ca, nb * nb * sizeof(double));
    memcpy(w->Cs, Cs, nb * nb * sizeof(double));
    int st = modal_eig(w, sp);
    if (!st) follow(w, shares, ctx, out, i);
    return st;
}
