/* reduced.c: identification of the reduced restoring force by implicit condensation (static modal
 * load cases on the full rod) and a least-squares fit of its quadratic and cubic coefficients. */
#include "gallop/reduced/reduced.h"
#include "gallop/base/core.h"
#include "gallop/statics/statics.h"

#include "base/chol.h"

#include <float.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_multifit.h>
#include <gsl/gsl_vector.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

void gal_reduced_default_opts(gal_reduced_opts *o)
{
    o->amplitude_m = 2.0;
    o->amplitude_rad = 0.5;
}

gal_reduced *gal_reduced_free(gal_reduced *rm)
{
    if (rm) {
        free(rm->phi); free(rm->omega2); free(rm->mode_index); free(rm->family);
        free(rm->m2); free(rm->m3); free(rm->B); free(rm->A); free(rm->P); free(rm->eta_ref);
        free(rm->obs); free(rm->obs_lin); free(rm->obs_nl);
        free(rm);
    }
    return NULL;
}

/* monomial values: mu[0..n2) quadratic, then cubic, then the pure 4th and 5th powers */
static void monomials(const gal_reduced *rm, const double *x, double *mu)
{
    for (int m = 0; m < rm->n2; m++) mu[m] = x[rm->m2[2 * m]] * x[rm->m2[2 * m + 1]];
    for (int m = 0; m < rm->n3; m++)
        mu[rm->n2 + m] = x[rm->m3[3 * m]] * x[rm->m3[3 * m + 1]] * x[rm->m3[3 * m + 2]];
    double *p = mu + rm->n2 + rm->n3;
    for (int j = 0; j < rm->r; j++) {
        double x2 = x[j] * x[j];
        p[j] = x2 * x2;
        p[rm->r + j] = x2 * x2 * x[j];
    }
}

void gal_reduced_force(const gal_reduced *rm, const double *eta, double *f)
{
    int r = rm->r;
    for (int i = 0; i < r; i++) f[i] = rm->omega2[i] * eta[i];
    /* quadratic: f_i += B_i,(j,k) eta_j eta_k */
    for (int m = 0; m < rm->n2; m++) {
        double mu = eta[rm->m2[2 * m]] * eta[rm->m2[2 * m + 1]];
        for (int i = 0; i < r; i++) f[i] += rm->B[i * rm->n2 + m] * mu;
    }
    for (int m = 0; m < rm->n3; m++) {
        double mu = eta[rm->m3[3 * m]] * eta[rm->m3[3 * m + 1]] * eta[rm->m3[3 * m + 2]];
        for (int i = 0; i < r; i++) f[i] += rm->A[i * rm->n3 + m] * mu;
    }
    /* pure 4th and 5th powers (the strong one-mode softening of a sagged span) */
    for (int j = 0; j < r; j++) {
        double e2 = eta[j] * eta[j], e4 = e2 * e2, e5 = e4 * eta[j];
        for (int i = 0; i < r; i++) f[i] += rm->P[i * 2 * r + j] * e4 + rm->P[i * 2 * r + r + j] * e5;
    }
}

void gal_reduced_observe(const gal_reduced *rm, const double *eta, double *out)
{
    int nc = rm->n2 + rm->n3 + 2 * rm->r;
    double mu[4096];
    double *mup = nc <= 4096 ? mu : malloc((size_t)nc * sizeof(double));
    if (!mup) return;
    monomials(rm, eta, mup);
    for (int o = 0; o < rm->nobs; o++) {
        double u = 0;
        for (int i = 0; i < rm->r; i++) u += rm->obs_lin[o * rm->r + i] * eta[i];
        for (int m = 0; m < nc; m++) u += rm->obs_nl[(size_t)o * nc + m] * mup[m];
        out[o] = u;
    }
    if (mup != mu) free(mup);
}

void gal_reduced_observe_rate(const gal_reduced *rm, const double *eta, const double *deta, double *out,
                              double *rate)
{
    int r = rm->r, nc = rm->n2 + rm->n3 + 2 * r;
    double buf[2 * 4096];
    double *mu = nc <= 4096 ? buf : malloc((size_t)2 * nc * sizeof(double)), *dmu = mu + nc;
    if (!mu) return;
    monomials(rm, eta, mu);
    /* d/dt of each monomial */
    for (int m = 0; m < rm->n2; m++) {
        int j = rm->m2[2 * m], k = rm->m2[2 * m + 1];
        dmu[m] = deta[j] * eta[k] + eta[j] * deta[k];
    }
    for (int m = 0; m < rm->n3; m++) {
        int j = rm->m3[3 * m], k = rm->m3[3 * m + 1], l = rm->m3[3 * m + 2];
        dmu[rm->n2 + m] = deta[j] * eta[k] * eta[l] + eta[j] * deta[k] * eta[l] + eta[j] * eta[k] * deta[l];
    }
    for (int j = 0; j < r; j++) {
        double e2 = eta[j] * eta[j];
        dmu[rm->n2 + rm->n3 + j] = 4 * e2 * eta[j] * deta[j];
        dmu[rm->n2 + rm->n3 + r + j] = 5 * e2 * e2 * deta[j];
    }
    for (int o = 0; o < rm->nobs; o++) {
        const double *L = rm->obs_lin + (size_t)o * r, *C = rm->obs_nl + (size_t)o * nc;
        double u = 0, du = 0;
        for (int i = 0; i < r; i++) u += L[i] * eta[i], du += L[i] * deta[i];
        for (int m = 0; m < nc; m++) u += C[m] * mu[m], du += C[m] * dmu[m];
        out[o] = u;
        if (rate) rate[o] = du;
    }
    if (mu != buf) free(mu);
}

int gal_reduced_projected_force(const gal_reduced *rm, const gal_rod *rod, const double *q_eq,
                                const double *eta, double *f, double *wq, double *wg)
{
    memcpy(wq, q_eq, (size_t)rod->nq * sizeof(double));
    for (int j = 0; j < rm->ndof; j++) {
        double u = 0;
        for (int i = 0; i < rm->r; i++) u += rm->phi[(size_t)i * rm->ndof + j] * eta[i];
        wq[rod->free_q[j]] += u;
    }
    int st = gal_rod_eval(rod, wq, NULL, wg, NULL);
    if (st) return st;
    for (int i = 0; i < rm->r; i++) {
        double s = 0;
        for (int j = 0; j < rm->ndof; j++) s += rm->phi[(size_t)i * rm->ndof + j] * wg[rod->free_q[j]];
        f[i] = s;
    }
    return GAL_OK;
}

/* Static condensation at prescribed modal coordinates: minimize U(q) subject to
 * Phi^T M (q - q_eq) = eta. The multipliers are the reduced restoring force f(eta) (per unit modal
 * mass, since Phi^T M Phi = I); every other dof, the stretching of the cable among them, relaxes.
 * Newton on the KKT system, by its Schur complement on the r multipliers:
 *   [K        -MPhi] [dq  ]     [g - MPhi lam              ]
 *   [(MPhi)^T     0] [dlam] = - [Phi^T M (q - q_eq) - eta]. */
typedef struct {
    gal_csc *K;           /* the tangent stiffness (the stage's own values on the rod's pattern) */
    gal_chol *chol;
    double *g, *r1, *r2, *Y, *S, *x, *mdiag, *MPhi, *dq, *dl, *qt;
} kkt_ws;

/* The workspace of the condensation, with M Phi (r columns of n). */
static int kkt_alloc(kkt_ws *w, const gal_rod *rod, const gal_reduced *rm)
{
    int n = rod->ndof, nq = rod->nq, r = rm->r;
    w->K = gal_csc_clone(rod->K);
    w->chol = w->K ? gal_chol_alloc(w->K) : NULL;
    w->g = malloc((size_t)nq * sizeof(double));
    w->r1 = malloc((size_t)n * sizeof(double)), w->x = malloc((size_t)n * sizeof(double));
    w->r2 = malloc((size_t)r * sizeof(double)), w->dl = malloc((size_t)r * sizeof(double));
    w->S = malloc((size_t)r * r * sizeof(double));
    w->Y = malloc((size_t)n * r * sizeof(double)), w->MPhi = malloc((size_t)n * r * sizeof(double));
    if (!w->K || !w->chol || !w->g || !w->r1 || !w->x || !w->r2 || !w->dl || !w->S || !w->Y || !w->MPhi) return GAL_ENOMEM;
    for (int i = 0; i < r; i++) gal_rod_mass_mult(rod, rm->phi + (size_t)i * n, w->MPhi + (size_t)i * n);
    return GAL_OK;
}

static void kkt_free(kkt_ws *w)
{
    gal_chol_free(w->chol);
    gal_csc_free(w->K);
    free(w->g); free(w->r1); free(w->x); free(w->r2); free(w->dl); free(w->S); free(w->Y); free(w->MPhi);
}

static int solve_small(double *A, double *b, int r)
{
    /* Gaussian elimination with partial pivoting (r <= 40), A destroyed, b := A^-1 b */
    for (int c = 0; c < r; c++) {
        int p = c;
        for (int a = c + 1; a < r; a++) if (fabs(A[a * r + c]) > fabs(A[p * r + c])) p = a;
        if (!(fabs(A[p * r + c]) > 0)) return GAL_EFAIL;
        if (p != c) {
            for (int k = 0; k < r; k++) { double t = A[c * r + k]; A[c * r + k] = A[p * r + k]; A[p * r + k] = t; }
            double t = b[c]; b[c] = b[p]; b[p] = t;
        }
        for (int a = c + 1; a < r; a++) {
            double f = A[a * r + c] / A[c * r + c];
            for (int k = c; k < r; k++) A[a * r + k] -= f * A[c * r + k];
            b[a] -= f * b[c];
        }
    }
    for (int a = r - 1; a >= 0; a--) {
        double s = b[a];
        for (int k = a + 1; k < r; k++) s -= A[a * r + k] * b[k];
        b[a] = s / A[a * r + a];
    }
    return GAL_OK;
}

static int condense(const gal_rod *rod, const double *q_eq, const gal_reduced *rm, kkt_ws *w, const double *eta,
                    double *q, double *lam, double ftol, long *iters)
{
    int n = rod->ndof, nq = rod->nq, r = rm->r, st;
    for (int it = 0; it < 60; it++) {
        if ((st = gal_rod_eval(rod, q, NULL, w->g, w->K))) return st;
        double rn1 = 0, rn2 = 0;
        for (int j = 0; j < n; j++) {
            double s = w->g[rod->free_q[j]];
            for (int i = 0; i < r; i++) s -= w->MPhi[(size_t)i * n + j] * lam[i];
            w->r1[j] = s;
            rn1 = fmax(rn1, fabs(s));
        }
        for (int i = 0; i < r; i++) {
            double s = -eta[i];
            for (int j = 0; j < n; j++) s += w->MPhi[(size_t)i * n + j] * (q[rod->free_q[j]] - q_eq[rod->free_q[j]]);
            w->r2[i] = s;
            rn2 = fmax(rn2, fabs(s) / rm->eta_ref[i]);
        }
        if (!isfinite(rn1) || !isfinite(rn2)) return gal_error(GAL_EFAIL, "reduced: condensation diverged");
        if (rn1 <= ftol && rn2 <= 1e-10) return GAL_OK;
        (*iters)++;
        if ((st = gal_chol_factor(w->chol, w->K, 0, NULL)))
            return gal_error(GAL_EFAIL, "reduced: the stiffness is not positive definite at a prescribed modal "
                             "amplitude (the span buckles or goes slack there): %s", gal_error_message());
        /* Y = K^-1 M Phi, S = (M Phi)^T Y, x = K^-1 r1 */
        for (int i = 0; i < r; i++)
            if ((st = gal_chol_solve(w->chol, w->MPhi + (size_t)i * n, w->Y + (size_t)i * n))) return st;
        if ((st = gal_chol_solve(w->chol, w->r1, w->x))) return st;
        for (int a = 0; a < r; a++) {
            double s = 0;
            for (int j = 0; j < n; j++) s += w->MPhi[(size_t)a * n + j] * w->x[j];
            w->dl[a] = s - w->r2[a]; /* S dlam = (M Phi)^T K^-1 r1 - r2 */
            for (int b = 0; b < r; b++) {
                double t = 0;
                for (int j = 0; j < n; j++) t += w->MPhi[(size_t)a * n + j] * w->Y[(size_t)b * n + j];
                w->S[a * r + b] = t;
            }
        }
        if ((st = solve_small(w->S, w->dl, r))) return gal_error(GAL_EFAIL, "reduced: singular modal constraint");
        /* dq = -x + Y dlam */
        for (int j = 0; j < n; j++) {
            double s = -w->x[j];
            for (int i = 0; i < r; i++) s += w->Y[(size_t)i * n + j] * w->dl[i];
            q[rod->free_q[j]] += s;
        }
        for (int i = 0; i < r; i++) lam[i] += w->dl[i];
    }
    (void)nq;
    return gal_error(GAL_EFAIL, "reduced: the condensation did not converge in 60 Newton iterations");
}

int gal_reduced_condensed_force(const gal_reduced *rm, const gal_rod *rod, const double *q_eq, const double *eta, double *f)
{
    int n = rod->ndof, nq = rod->nq, r = rm->r, st;
    kkt_ws w = {0};
    double *q = malloc((size_t)nq * sizeof(double));
    if (kkt_alloc(&w, rod, rm) != GAL_OK || !q) {
        st = gal_error(GAL_ENOMEM, "reduced: out of memory");
    } else {
        memcpy(q, q_eq, (size_t)nq * sizeof(double));
        for (int j = 0; j < n; j++) {
            double u = 0;
            for (int i = 0; i < r; i++) u += rm->phi[(size_t)i * n + j] * eta[i];
            q[rod->free_q[j]] += u;
        }
        for (int i = 0; i < r; i++) f[i] = rm->omega2[i] * eta[i];
        double tol = 20 * DBL_EPSILON * rod->p.length * rod->p.EA / rod->l0[0];
        long it = 0;
        st = condense(rod, q_eq, rm, &w, eta, q, f, fmax(tol, 1e-9), &it);
    }
    kkt_free(&w); free(q);
    return st;
}

gal_reduced *gal_reduced_build(const gal_rod *rod, const double *q_eq, const gal_modes *md, const int *sel,
                               int r, const gal_obs *obs_in, int nobs, const gal_reduced_opts *o_in)
{
    double t0 = gal_wall_time();
    gal_reduced_opts o;
    if (o_in) o = *o_in;
    else gal_reduced_default_opts(&o);
    if (r < 1 || r > 40) {
        gal_error(GAL_EINPUT, "reduced: %d basis modes; allowed 1 to 40", r);
        return NULL;
    }
    gal_reduced *rm = calloc(1, sizeof *rm);
    if (!rm) return NULL;
    int n = rod->ndof, nq = rod->nq;
    rm->r = r, rm->ndof = n;
    rm->n2 = r * (r + 1) / 2;
    rm->n3 = r * (r + 1) * (r + 2) / 6;
    int nc = rm->n2 + rm->n3 + 2 * r;
    rm->phi = malloc((size_t)n * r * sizeof(double));
    rm->omega2 = malloc((size_t)r * sizeof(double));
    rm->mode_index = malloc((size_t)r * sizeof(int));
    rm->family = malloc((size_t)r * sizeof(gal_family));
    rm->m2 = malloc((size_t)2 * rm->n2 * sizeof(int));
    rm->m3 = malloc((size_t)3 * rm->n3 * sizeof(int));
    rm->B = calloc((size_t)r * rm->n2, sizeof(double));
    rm->A = calloc((size_t)r * rm->n3, sizeof(double));
    rm->P = calloc((size_t)r * 2 * r, sizeof(double));
    rm->eta_ref = malloc((size_t)r * sizeof(double));
    rm->nobs = nobs;
    rm->obs = malloc((size_t)(nobs > 0 ? nobs : 1) * sizeof(gal_obs));
    rm->obs_lin = calloc((size_t)(nobs > 0 ? nobs : 1) * r, sizeof(double));
    rm->obs_nl = calloc((size_t)(nobs > 0 ? nobs : 1) * nc, sizeof(double));
    if (!rm->phi || !rm->omega2 || !rm->mode_index || !rm->family || !rm->m2 || !rm->m3 || !rm->B ||
        !rm->A || !rm->P || !rm->eta_ref || !rm->obs || !rm->obs_lin || !rm->obs_nl) {
        gal_error(GAL_ENOMEM, "reduced: out of memory");
        return gal_reduced_free(rm);
    }
    for (int i = 0; i < r; i++) {
        const gal_mode *m = md->mode + sel[i];
        memcpy(rm->phi + (size_t)i * n, md->shape + (size_t)sel[i] * n, (size_t)n * sizeof(double));
        rm->omega2[i] = m->omega * m->omega;
        rm->mode_index[i] = sel[i];
        rm->family[i] = m->family;
    }
    {
        int c = 0;
        for (int j = 0; j < r; j++)
            for (int k = j; k < r; k++) rm->m2[2 * c] = j, rm->m2[2 * c + 1] = k, c++;
        c = 0;
        for (int j = 0; j < r; j++)
            for (int k = j; k < r; k++)
                for (int l = k; l < r; l++) rm->m3[3 * c] = j, rm->m3[3 * c + 1] = k, rm->m3[3 * c + 2] = l, c++;
    }
    /* reference modal amplitude of each mode: its largest translation amplitude_m (or twist
     * amplitude_rad for a torsional mode) */
    for (int i = 0; i < r; i++) {
        double big_t = 0, big_r = 0;
        for (int j = 0; j < n; j++) {
            double v = fabs(rm->phi[(size_t)i * n + j]);
            if (rod->free_q[j] < 3 * rod->nn) big_t = fmax(big_t, v);
            else big_r = fmax(big_r, v);
        }
        rm->eta_ref[i] = rm->family[i] == GAL_FAMILY_TORSIONAL && big_r > 0 ? o.amplitude_rad / big_r
                                                                              : o.amplitude_m / big_t;
    }
    for (int k = 0; k < nobs; k++) {
        rm->obs[k] = obs_in[k];
        for (int e = 0; e < 2; e++) {
            int qi = obs_in[k].q[e], j = qi >= 0 ? rod->dof[qi] : -1;
            if (j < 0) continue;
            for (int i = 0; i < r; i++) rm->obs_lin[k * r + i] += obs_in[k].w[e] * rm->phi[(size_t)i * n + j];
        }
    }

    /* ---- load cases (in units of the reference amplitudes) ---- */
    int cap = 8 * r + 4 * r * (r - 1) / 2 + 2 * r * (r - 1) * (r - 2) / 6 + 1;
    double *cases = malloc((size_t)cap * r * sizeof(double));
    int nc_cases = 0;
    static const double singles[8] = {1.0, -1.0, 0.75, -0.75, 0.5, -0.5, 0.25, -0.25};
    for (int i = 0; i < r; i++)
        for (int s = 0; s < 8; s++) {
            double *c = cases + (size_t)nc_cases++ * r;
            memset(c, 0, (size_t)r * sizeof(double));
            c[i] = singles[s];
        }
    for (int i = 0; i < r; i++)
        for (int j = i + 1; j < r; j++)
            for (int s = 0; s < 4; s++) {
                double *c = cases + (size_t)nc_cases++ * r;
                memset(c, 0, (size_t)r * sizeof(double));
                c[i] = (s & 1) ? -0.7 : 0.7;
                c[j] = (s & 2) ? -0.7 : 0.7;
            }
    for (int i = 0; i < r; i++)
        for (int j = i + 1; j < r; j++)
            for (int k = j + 1; k < r; k++)
                for (int s = 0; s < 2; s++) {
                    double *c = cases + (size_t)nc_cases++ * r;
                    memset(c, 0, (size_t)r * sizeof(double));
                    c[i] = c[j] = c[k] = s ? -0.6 : 0.6;
                }
    rm->load_cases = nc_cases;

    double *mdiag = malloc((size_t)n * sizeof(double)), *fq = NULL;
    double *qc = malloc((size_t)nq * sizeof(double));
    double *eta = malloc((size_t)nc_cases * r * sizeof(double));   /* responses */
    double *frc = malloc((size_t)nc_cases * r * sizeof(double));   /* applied modal forces */
    double *obs = malloc((size_t)nc_cases * (nobs > 0 ? nobs : 1) * sizeof(double));
    gsl_matrix *X = gsl_matrix_alloc((size_t)nc_cases, (size_t)nc);
    gsl_vector *y = gsl_vector_alloc((size_t)nc_cases), *cf = gsl_vector_alloc((size_t)nc);
    gsl_matrix *cov = gsl_matrix_alloc((size_t)nc, (size_t)nc);
    gsl_multifit_linear_workspace *ws = gsl_multifit_linear_alloc((size_t)nc_cases, (size_t)nc);
    int st = GAL_OK;
    if (!cases || !mdiag || !qc || !eta || !frc || !obs || !X || !y || !cf || !cov || !ws) {
        st = gal_error(GAL_ENOMEM, "reduced: out of memory for %d load cases", nc_cases);
        goto done;
    }
    gal_rod_mass_diag(rod, mdiag);
    kkt_ws w = {0};
    if (kkt_alloc(&w, rod, rm) != GAL_OK) {
        st = gal_error(GAL_ENOMEM, "reduced: out of memory");
    } else {
        double weight = 0;
        for (int j = 0; j < n; j++) weight = fmax(weight, mdiag[j] * 9.81);
        double tol = fmax(1e-9 * weight, 20 * DBL_EPSILON * rod->p.length * rod->p.EA / rod->l0[0]);
        for (int c = 0; c < nc_cases && !st; c++) {
            const double *cs = cases + (size_t)c * r;
            double *fc = frc + (size_t)c * r, *ec = eta + (size_t)c * r;
            /* a combination that folds or slackens the span at full amplitude is taken at a
             * smaller one (the fit only needs the point where it was solved) */
            for (double shrink = 1.0; ; shrink *= 0.7) {
                memcpy(qc, q_eq, (size_t)nq * sizeof(double));
                for (int i = 0; i < r; i++) ec[i] = shrink * cs[i] * rm->eta_ref[i], fc[i] = rm->omega2[i] * ec[i];
                for (int j = 0; j < n; j++) {
                    double uj = 0;
                    for (int i = 0; i < r; i++) uj += rm->phi[(size_t)i * n + j] * ec[i];
                    qc[rod->free_q[j]] += uj; /* linear prediction */
                }
                st = condense(rod, q_eq, rm, &w, ec, qc, fc, tol, &rm->newton_iterations);
                if (st == GAL_OK) break;
                if (st == GAL_ENOMEM || shrink < 0.2) {
                    st = gal_error(st, "reduced: identification case %d of %d: %s (reduce "
                                   "model.identification_amplitude)", c + 1, nc_cases, gal_error_message());
                    break;
                }
                rm->shrunk_cases += shrink == 1.0;
            }
            if (st) break;
            for (int k = 0; k < nobs; k++) {
                double v = 0;
                for (int e = 0; e < 2; e++) {
                    int qi = obs_in[k].q[e];
                    if (qi >= 0) v += obs_in[k].w[e] * (qc[qi] - q_eq[qi]);
                }
                obs[(size_t)c * nobs + k] = v;
            }
        }
    }
    kkt_free(&w);
    if (st) goto done;

    /* ---- fit: f_i - w_i^2 eta_i = sum B mu2 + sum A mu3, in scaled variables eta / eta_ref ---- */
    {
        double *xs = malloc((size_t)r * sizeof(double)), *mu = malloc((size_t)nc * sizeof(double));
        double *colscale = malloc((size_t)nc * sizeof(double));
        if (!xs || !mu || !colscale) { free(xs); free(mu); free(colscale); st = gal_error(GAL_ENOMEM, "reduced: out of memory"); goto done; }
        for (int c = 0; c < nc_cases; c++) {
            for (int i = 0; i < r; i++) xs[i] = eta[(size_t)c * r + i] / rm->eta_ref[i];
            monomials(rm, xs, mu);
            for (int m = 0; m < nc; m++) gsl_matrix_set(X, (size_t)c, (size_t)m, mu[m]);
        }
        /* scale of monomial m in physical units: product of the eta_ref of its factors */
        for (int m = 0; m < rm->n2; m++) colscale[m] = rm->eta_ref[rm->m2[2 * m]] * rm->eta_ref[rm->m2[2 * m + 1]];
        for (int m = 0; m < rm->n3; m++)
            colscale[rm->n2 + m] = rm->eta_ref[rm->m3[3 * m]] * rm->eta_ref[rm->m3[3 * m + 1]] * rm->eta_ref[rm->m3[3 * m + 2]];
        for (int j = 0; j < r; j++) {
            colscale[rm->n2 + rm->n3 + j] = pow(rm->eta_ref[j], 4);
            colscale[rm->n2 + rm->n3 + r + j] = pow(rm->eta_ref[j], 5);
        }
        double ss_res = 0, ss_tot = 0;
        for (int i = 0; i < r; i++) {
            double fscale = rm->omega2[i] * rm->eta_ref[i];
            for (int c = 0; c < nc_cases; c++) {
                double e = eta[(size_t)c * r + i];
                gsl_vector_set(y, (size_t)c, (frc[(size_t)c * r + i] - rm->omega2[i] * e) / fscale);
            }
            double chisq;
            size_t rank;
            gsl_multifit_linear_tsvd(X, y, 1e-12, cf, cov, &chisq, &rank, ws);
            for (int m = 0; m < rm->n2; m++) rm->B[i * rm->n2 + m] = gsl_vector_get(cf, (size_t)m) * fscale / colscale[m];
            for (int m = 0; m < rm->n3; m++)
                rm->A[i * rm->n3 + m] = gsl_vector_get(cf, (size_t)(rm->n2 + m)) * fscale / colscale[rm->n2 + m];
            for (int m = 0; m < 2 * r; m++)
                rm->P[i * 2 * r + m] = gsl_vector_get(cf, (size_t)(rm->n2 + rm->n3 + m)) * fscale / colscale[rm->n2 + rm->n3 + m];
            ss_res += chisq;
            for (int c = 0; c < nc_cases; c++) ss_tot += pow(frc[(size_t)c * r + i] / fscale, 2);
        }
        rm->fit_residual = ss_tot > 0 ? sqrt(ss_res / ss_tot) : 0;
        /* expansion: observed u - Phi eta, fitted the same way */
        for (int k = 0; k < nobs; k++) {
            double uscale = o.amplitude_m;
            for (int c = 0; c < nc_cases; c++) {
                double lin = 0;
                for (int i = 0; i < r; i++) lin += rm->obs_lin[k * r + i] * eta[(size_t)c * r + i];
                gsl_vector_set(y, (size_t)c, (obs[(size_t)c * nobs + k] - lin) / uscale);
            }
            double chisq;
            size_t rank;
            gsl_multifit_linear_tsvd(X, y, 1e-12, cf, cov, &chisq, &rank, ws);
            for (int m = 0; m < nc; m++) rm->obs_nl[(size_t)k * nc + m] = gsl_vector_get(cf, (size_t)m) * uscale / colscale[m];
        }
        free(xs); free(mu); free(colscale);
    }
done:
    free(cases); free(mdiag); free(fq); free(qc); free(eta); free(frc); free(obs);
    if (X) gsl_matrix_free(X);
    if (y) gsl_vector_free(y);
    if (cf) gsl_vector_free(cf);
    if (cov) gsl_matrix_free(cov);
    if (ws) gsl_multifit_linear_free(ws);
    rm->build_time_s = gal_wall_time() - t0;
    if (st) return gal_reduced_free(rm);
    return rm;
}
