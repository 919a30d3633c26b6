/* identify.c: identification of the reduced restoring force by implicit condensation (static modal
 * load cases on the full rod) and a least-squares fit of its quadratic and cubic coefficients
 * (reduced.h). */
#include "gallop/reduced/reduced.h"
#include "gallop/base/core.h"

#include <float.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_multifit.h>
#include <gsl/gsl_vector.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "reduced/internal.h"

/* The model's arrays, its basis (the selected modes of md) and its monomial index. */
static gal_reduced *alloc_model(const gal_rod *rod, const gal_modes *md, const int *sel, int r, int nobs)
{
    gal_reduced *rm = calloc(1, sizeof *rm);
    if (!rm) return NULL;
    int n = rod->ndof;
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
    int c = 0;
    for (int j = 0; j < r; j++)
        for (int k = j; k < r; k++) rm->m2[2 * c] = j, rm->m2[2 * c + 1] = k, c++;
    c = 0;
    for (int j = 0; j < r; j++)
        for (int k = j; k < r; k++)
            for (int l = k; l < r; l++) rm->m3[3 * c] = j, rm->m3[3 * c + 1] = k, rm->m3[3 * c + 2] = l, c++;
    return rm;
}

/* The reference modal amplitude of each mode (its largest translation amplitude_m, or twist
 * amplitude_rad for a torsional mode) and the linear part of each observation. */
static void references(gal_reduced *rm, const gal_rod *rod, const gal_reduced_opts *o, const gal_obs *obs_in)
{
    int n = rm->ndof, r = rm->r;
    for (int i = 0; i < r; i++) {
        double big_t = 0, big_r = 0;
        for (int j = 0; j < n; j++) {
            double v = fabs(rm->phi[(size_t)i * n + j]);
            if (rod->free_q[j] < 3 * rod->nn) big_t = fmax(big_t, v);
            else big_r = fmax(big_r, v);
        }
        rm->eta_ref[i] = rm->family[i] == GAL_FAMILY_TORSIONAL && big_r > 0 ? o->amplitude_rad / big_r
                                                                               : o->amplitude_m / big_t;
    }
    for (int k = 0; k < rm->nobs; k++) {
        rm->obs[k] = obs_in[k];
        for (int e = 0; e < 2; e++) {
            int qi = obs_in[k].q[e], j = qi >= 0 ? rod->dof[qi] : -1;
            if (j < 0) continue;
            for (int i = 0; i < r; i++) rm->obs_lin[k * r + i] += obs_in[k].w[e] * rm->phi[(size_t)i * n + j];
        }
    }
}

/* The identification's data: the load cases (in units of the reference amplitudes), the modal
 * amplitudes reached, the modal forces found and the observations at each. */
typedef struct {
    int n;               /* load cases */
    double *cases;       /* n x r */
    double *eta;         /* n x r: responses */
    double *frc;         /* n x r: modal forces */
    double *obs;         /* n x nobs */
} ident;

static void ident_free(ident *id)
{
    free(id->cases); free(id->eta); free(id->frc); free(id->obs);
}

/* Every mode alone at 8 amplitudes, every pair at 4 sign combinations, every triple at 2. */
static int ident_alloc(ident *id, int r, int nobs)
{
    memset(id, 0, sizeof *id);
    int cap = 8 * r + 4 * r * (r - 1) / 2 + 2 * r * (r - 1) * (r - 2) / 6 + 1;
    double *cases = id->cases = malloc((size_t)cap * r * sizeof(double));
    if (!cases) return gal_error(GAL_ENOMEM, "reduced: out of memory");
    int nc = 0;
    static const double singles[8] = {1.0, -1.0, 0.75, -0.75, 0.5, -0.5, 0.25, -0.25};
    for (int i = 0; i < r; i++)
        for (int s = 0; s < 8; s++) {
            double *c = cases + (size_t)nc++ * r;
            memset(c, 0, (size_t)r * sizeof(double));
            c[i] = singles[s];
        }
    for (int i = 0; i < r; i++)
        for (int j = i + 1; j < r; j++)
            for (int s = 0; s < 4; s++) {
                double *c = cases + (size_t)nc++ * r;
                memset(c, 0, (size_t)r * sizeof(double));
                c[i] = (s & 1) ? -0.7 : 0.7;
                c[j] = (s & 2) ? -0.7 : 0.7;
            }
    for (int i = 0; i < r; i++)
        for (int j = i + 1; j < r; j++)
            for (int k = j + 1; k < r; k++)
                for (int s = 0; s < 2; s++) {
                    double *c = cases + (size_t)nc++ * r;
                    memset(c, 0, (size_t)r * sizeof(double));
                    c[i] = c[j] = c[k] = s ? -0.6 : 0.6;
                }
    id->n = nc;
    id->eta = malloc((size_t)nc * r * sizeof(double));
    id->frc = malloc((size_t)nc * r * sizeof(double));
    id->obs = malloc((size_t)nc * (nobs > 0 ? nobs : 1) * sizeof(double));
    if (!id->eta || !id->frc || !id->obs) return gal_error(GAL_ENOMEM, "reduced: out of memory for %d load cases", nc);
    return GAL_OK;
}

/* Load case c condensed (a combination that folds or slackens the span at full amplitude is taken
 * at a smaller one: the fit only needs the point where it was solved); qc holds its configuration. */
static int solve_case(const gal_rod *rod, const double *q_eq, gal_reduced *rm, gal_kkt_ws *w, ident *id, int c,
                      double tol, double *qc)
{
    int n = rm->ndof, r = rm->r, st;
    const double *cs = id->cases + (size_t)c * r;
    double *fc = id->frc + (size_t)c * r, *ec = id->eta + (size_t)c * r;
    for (double shrink = 1.0; ; shrink *= 0.7) {
        memcpy(qc, q_eq, (size_t)rod->nq * sizeof(double));
        for (int i = 0; i < r; i++) ec[i] = shrink * cs[i] * rm->eta_ref[i], fc[i] = rm->omega2[i] * ec[i];
        for (int j = 0; j < n; j++) {
            double uj = 0;
            for (int i = 0; i < r; i++) uj += rm->phi[(size_t)i * n + j] * ec[i];
            qc[rod->free_q[j]] += uj; /* linear prediction */
        }
        st = gal_kkt_condense(rod, q_eq, rm, w, ec, qc, fc, tol, &rm->newton_iterations);
        if (st == GAL_OK) return GAL_OK;
        if (st == GAL_ENOMEM || shrink < 0.2)
            return gal_error(st, "reduced: identification case %d of %d: %s (reduce "
                             "model.identification_amplitude)", c + 1, id->n, gal_error_message());
        rm->shrunk_cases += shrink == 1.0;
    }
}

/* Every load case condensed on the full rod, and the observations at each. */
static int solve_cases(const gal_rod *rod, const double *q_eq, gal_reduced *rm, ident *id)
{
    int n = rm->ndof, nobs = rm->nobs, st = GAL_OK;
    double *mdiag = malloc((size_t)n * sizeof(double)), *qc = malloc((size_t)rod->nq * sizeof(double));
    gal_kkt_ws w = {0};
    if (!mdiag || !qc || gal_kkt_alloc(&w, rod, rm) != GAL_OK) {
        st = gal_error(GAL_ENOMEM, "reduced: out of memory");
        goto done;
    }
    gal_rod_mass_diag(rod, mdiag);
    double weight = 0;
    for (int j = 0; j < n; j++) weight = fmax(weight, mdiag[j] * 9.81);
    double tol = fmax(1e-9 * weight, 20 * DBL_EPSILON * rod->p.length * rod->p.EA / rod->l0[0]);
    for (int c = 0; c < id->n && !st; c++) {
        if ((st = solve_case(rod, q_eq, rm, &w, id, c, tol, qc))) break;
        for (int k = 0; k < nobs; k++) {
            double v = 0;
            for (int e = 0; e < 2; e++) {
                int qi = rm->obs[k].q[e];
                if (qi >= 0) v += rm->obs[k].w[e] * (qc[qi] - q_eq[qi]);
            }
            id->obs[(size_t)c * nobs + k] = v;
        }
    }
done:
    gal_kkt_free(&w);
    free(mdiag); free(qc);
    return st;
}

/* The least-squares problem: the monomials of each case in scaled variables eta / eta_ref (X),
 * the scale of each monomial in physical units (colscale: the product of the eta_ref of its
 * factors), a right-hand side and the solver's workspace. */
typedef struct {
    gsl_matrix *X, *cov;
    gsl_vector *y, *cf;
    gsl_multifit_linear_workspace *ws;
    double *colscale;
} lsq;

static void lsq_free(lsq *L)
{
    if (L->X) gsl_matrix_free(L->X);
    if (L->y) gsl_vector_free(L->y);
    if (L->cf) gsl_vector_free(L->cf);
    if (L->cov) gsl_matrix_free(L->cov);
    if (L->ws) gsl_multifit_linear_free(L->ws);
    free(L->colscale);
}

static int lsq_alloc(lsq *L, const gal_reduced *rm, const ident *id)
{
    int r = rm->r, nc = rm->n2 + rm->n3 + 2 * r;
    memset(L, 0, sizeof *L);
    L->X = gsl_matrix_alloc((size_t)id->n, (size_t)nc);
    L->y = gsl_vector_alloc((size_t)id->n), L->cf = gsl_vector_alloc((size_t)nc);
    L->cov = gsl_matrix_alloc((size_t)nc, (size_t)nc);
    L->ws = gsl_multifit_linear_alloc((size_t)id->n, (size_t)nc);
    L->colscale = malloc((size_t)nc * sizeof(double));
    double *xs = malloc((size_t)r * sizeof(double)), *mu = malloc((size_t)nc * sizeof(double));
    if (!L->X || !L->y || !L->cf || !L->cov || !L->ws || !L->colscale || !xs || !mu) {
        free(xs); free(mu);
        return gal_error(GAL_ENOMEM, "reduced: out of memory for %d load cases", id->n);
    }
    for (int c = 0; c < id->n; c++) {
        for (int i = 0; i < r; i++) xs[i] = id->eta[(size_t)c * r + i] / rm->eta_ref[i];
        gal_reduced_monomials(rm, xs, mu);
        for (int m = 0; m < nc; m++) gsl_matrix_set(L->X, (size_t)c, (size_t)m, mu[m]);
    }
    double *cs = L->colscale;
    for (int m = 0; m < rm->n2; m++) cs[m] = rm->eta_ref[rm->m2[2 * m]] * rm->eta_ref[rm->m2[2 * m + 1]];
    for (int m = 0; m < rm->n3; m++)
        cs[rm->n2 + m] = rm->eta_ref[rm->m3[3 * m]] * rm->eta_ref[rm->m3[3 * m + 1]] * rm->eta_ref[rm->m3[3 * m + 2]];
    for (int j = 0; j < r; j++) {
        cs[rm->n2 + rm->n3 + j] = pow(rm->eta_ref[j], 4);
        cs[rm->n2 + rm->n3 + r + j] = pow(rm->eta_ref[j], 5);
    }
    free(xs); free(mu);
    return GAL_OK;
}

/* The force fit: f_i - w_i^2 eta_i = sum B mu2 + sum A mu3 + sum P mu45, mode by mode. */
static void fit_force(gal_reduced *rm, const ident *id, lsq *L)
{
    int r = rm->r;
    double ss_res = 0, ss_tot = 0;
    for (int i = 0; i < r; i++) {
        double fscale = rm->omega2[i] * rm->eta_ref[i];
        for (int c = 0; c < id->n; c++) {
            double e = id->eta[(size_t)c * r + i];
            gsl_vector_set(L->y, (size_t)c, (id->frc[(size_t)c * r + i] - rm->omega2[i] * e) / fscale);
        }
        double chisq;
        size_t rank;
        gsl_multifit_linear_tsvd(L->X, L->y, 1e-12, L->cf, L->cov, &chisq, &rank, L->ws);
        const double *cs = L->colscale;
        for (int m = 0; m < rm->n2; m++) rm->B[i * rm->n2 + m] = gsl_vector_get(L->cf, (size_t)m) * fscale / cs[m];
        for (int m = 0; m < rm->n3; m++)
            rm->A[i * rm->n3 + m] = gsl_vector_get(L->cf, (size_t)(rm->n2 + m)) * fscale / cs[rm->n2 + m];
        for (int m = 0; m < 2 * r; m++)
            rm->P[i * 2 * r + m] = gsl_vector_get(L->cf, (size_t)(rm->n2 + rm->n3 + m)) * fscale / cs[rm->n2 + rm->n3 + m];
        ss_res += chisq;
        for (int c = 0; c < id->n; c++) ss_tot += pow(id->frc[(size_t)c * r + i] / fscale, 2);
    }
    rm->fit_residual = ss_tot > 0 ? sqrt(ss_res / ss_tot) : 0;
}

/* The expansion: observed u - Phi eta, fitted the same way. */
static void fit_expansion(gal_reduced *rm, const ident *id, lsq *L, double uscale)
{
    int r = rm->r, nobs = rm->nobs, nc = rm->n2 + rm->n3 + 2 * r;
    for (int k = 0; k < nobs; k++) {
        for (int c = 0; c < id->n; c++) {
            double lin = 0;
            for (int i = 0; i < r; i++) lin += rm->obs_lin[k * r + i] * id->eta[(size_t)c * r + i];
            gsl_vector_set(L->y, (size_t)c, (id->obs[(size_t)c * nobs + k] - lin) / uscale);
        }
        double chisq;
        size_t rank;
        gsl_multifit_linear_tsvd(L->X, L->y, 1e-12, L->cf, L->cov, &chisq, &rank, L->ws);
        for (int m = 0; m < nc; m++)
            rm->obs_nl[(size_t)k * nc + m] = gsl_vector_get(L->cf, (size_t)m) * uscale / L->colscale[m];
    }
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
    gal_reduced *rm = alloc_model(rod, md, sel, r, nobs);
    if (!rm) return NULL;
    references(rm, rod, &o, obs_in);
    ident id;
    lsq L = {0};
    int st = ident_alloc(&id, r, nobs);
    if (!st) {
        rm->load_cases = id.n;
        st = solve_cases(rod, q_eq, rm, &id);
    }
    if (!st) st = lsq_alloc(&L, rm, &id);
    if (!st) {
        fit_force(rm, &id, &L);
        fit_expansion(rm, &id, &L, o.amplitude_m);
    }
    lsq_free(&L);
    ident_free(&id);
    rm->build_time_s = gal_wall_time() - t0;
    if (st) return gal_reduced_free(rm);
    return rm;
}
