/* reduced.c: the reduced model at a state: its restoring force, the expansion that recovers observed
 * full coordinates, and the Galerkin projection it is compared with (reduced.h). Identification:
 * identify.c; the condensation it rests on: condense.c. */
#include "gallop/reduced/reduced.h"
#include "gallop/base/core.h"

#include "reduced/internal.h"

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
void gal_reduced_monomials(const gal_reduced *rm, const double *x, double *mu)
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
    gal_reduced_monomials(rm, eta, mup);
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
    gal_reduced_monomials(rm, eta, mu);
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

