/* qm.c: the quadratic manifold of the recomputed reduced model (qm.h): the unnormalized static
 * modal derivatives theta_ij = -K0^-1 (dK/d eta_j) phi_i (central differences of the tangent, one
 * factorization of K0), the manifold q = q_eq + Phi eta + 1/2 Theta(eta, eta), its tangent basis
 * P(eta) = Phi + Theta(eta, .), its curvature term in the reduced tangent, and the projection of a
 * full state onto it (Gauss-Newton in the mass norm). With a mean load (o.static_vectors) the
 * static response K0^-1 F_mean less its modal content is a further linear coordinate, with its
 * modal derivatives like the modes': the quasi-static swing-out under the mean drag that neither
 * the modes nor their derivatives carry. */
#include "reduced/qm.h"
#include "gallop/base/core.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/chol.h"
#include "gallop/model/damping.h"

void gal_rom_qm_free(gal_rom *m)
{
    gal_rom_qm *qm = m->qm;
    if (!qm) return;
    free(qm->pair); free(qm->Th); free(qm->P); free(qm->mono); free(qm->M);
    free(qm->W); free(qm->D); free(qm->Z); free(qm->Zv); free(qm->y); free(qm->wy); free(qm->f0);
    free(qm);
    m->qm = NULL;
}

/* W = B^T M B and D = B^T C B over B = [Phi, Theta] (the manifold's inertia, qm->inertia). */
static int inertia_build(gal_rom *m)
{
    gal_rom_qm *qm = m->qm;
    int n = m->ndof, r = m->nmodes, nz = r + qm->np, st = GAL_OK;
    qm->inertia = 1, qm->nz = nz;
    qm->W = malloc((size_t)nz * nz * sizeof(double));
    qm->D = m->o.damping ? malloc((size_t)nz * nz * sizeof(double)) : NULL;
    qm->Z = malloc((size_t)nz * r * sizeof(double)), qm->Zv = malloc((size_t)nz * r * sizeof(double));
    qm->y = malloc((size_t)nz * sizeof(double)), qm->wy = malloc((size_t)nz * sizeof(double));
    qm->f0 = malloc((size_t)5 * r * sizeof(double));
    if (qm->f0) qm->d0 = qm->f0 + r, qm->f1 = qm->f0 + 2 * r, qm->d1 = qm->f0 + 3 * r, qm->p0 = qm->f0 + 4 * r;
    double *B = malloc((size_t)n * nz * sizeof(double)), *t = malloc((size_t)n * sizeof(double));
    if (!qm->W || (m->o.damping && !qm->D) || !qm->Z || !qm->Zv || !qm->y || !qm->wy || !qm->f0 || !B || !t) {
        free(B); free(t);
        return gal_error(GAL_ENOMEM, "reduced model: out of memory for the manifold's inertia");
    }
    memcpy(B, m->V, (size_t)n * r * sizeof(double));
    memcpy(B + (size_t)n * r, qm->Th, (size_t)n * qm->np * sizeof(double));
    for (int a = 0; a < nz; a++) {
        gal_rod_mass_mult(m->rod, B + (size_t)a * n, t);
        for (int b = 0; b <= a; b++) {
            double s = 0;
            for (int d = 0; d < n; d++) s += t[d] * B[(size_t)b * n + d];
            qm->W[a * nz + b] = qm->W[b * nz + a] = s;
        }
    }
    if (qm->D) st = gal_damping_project(m->o.damping, B, nz, qm->D);
    free(B); free(t);
    return st;
}

/* The static response K0^-1 f (f: configuration-sized) less its part in V's first m->r columns
 * (twice, modified Gram-Schmidt in the mass norm), appended as column m->r when what is left is
 * over tol of its M-norm; w: 3 ndof scratch. */
static int static_append(gal_rom *m, double *MV, const double *f, double tol, double *w)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof, st;
    double *c = w + n, *Mc = w + 2 * n;
    gal_rod_gather(rod, f, w);
    if ((st = gal_chol_solve(m->chol0, w, c))) return st;
    gal_rod_mass_mult(rod, c, Mc);
    double n0 = 0, n1 = 0;
    for (int d = 0; d < n; d++) n0 += c[d] * Mc[d];
    for (int pass = 0; pass < 2; pass++)
        for (int k = 0; k < m->r; k++) {
            double p = 0;
            for (int d = 0; d < n; d++) p += MV[(size_t)k * n + d] * c[d];
            for (int d = 0; d < n; d++) c[d] -= p * m->V[(size_t)k * n + d];
        }
    gal_rod_mass_mult(rod, c, Mc);
    for (int d = 0; d < n; d++) n1 += c[d] * Mc[d];
    if (!(n0 > 0) || !(n1 > tol * tol * n0)) return GAL_OK;
    n1 = sqrt(n1);
    for (int d = 0; d < n; d++) m->V[(size_t)m->r * n + d] = c[d] / n1, MV[(size_t)m->r * n + d] = Mc[d] / n1;
    m->r++;
    return GAL_OK;
}

/* Which part of the configuration entry qi a family split keeps: 0 the out-of-plane (y)
 * translations, 1 the in-plane (x, z) ones, 2 the twists. */
static int split_part(const gal_rod *rod, int qi)
{
    return qi >= 3 * rod->nn ? 2 : qi % 3 == 1 ? 0 : 1;
}

int gal_rom_qm_static(gal_rom *m, double *MV)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof, nq = m->nq, st = GAL_OK, r0 = m->r, parts = m->o.static_vectors == 2 ? 3 : 1;
    if (!m->o.mean_load || m->o.static_vectors <= 0) return GAL_OK;
    double *w = malloc((size_t)3 * n * sizeof(double)), *f = malloc((size_t)nq * sizeof(double));
    double *om = realloc(m->omega2, (size_t)(m->nmodes + parts) * sizeof(double));
    if (om) m->omega2 = om;
    if (!w || !f || !om) { free(w); free(f); return gal_error(GAL_ENOMEM, "reduced model: out of memory for the static vectors"); }
    for (int p = 0; p < parts && !st; p++) {
        for (int k = 0; k < nq; k++) f[k] = parts == 1 || split_part(rod, k) == p ? m->o.mean_load[k] : 0;
        st = static_append(m, MV, f, 1e-3, w);
    }
    for (int k = r0; k < m->r && !st; k++) { /* the Rayleigh quotient, for the sampling's rates */
        const double *vk = m->V + (size_t)k * n;
        gal_csc_symv(m->K0, vk, w);
        double s = 0;
        for (int d = 0; d < n; d++) s += vk[d] * w[d];
        m->omega2[k] = s;
    }
    if (!st && !m->qm && !(m->qm = calloc(1, sizeof *m->qm))) st = gal_error(GAL_ENOMEM, "reduced model: out of memory");
    if (!st) m->qm->nstatic = m->r - r0;
    m->nmodes = m->r;
    free(w); free(f);
    return st;
}

int gal_rom_qm_build(gal_rom *m)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof, nq = m->nq, nm = m->nmodes, st = GAL_OK;
    if (nm > 64) return gal_error(GAL_EINPUT, "reduced model: the manifold takes at most 64 modes (%d selected)", nm);
    gal_rom_qm *qm = m->qm ? m->qm : calloc(1, sizeof *qm); /* made by gal_rom_qm_static */
    if (!qm) return gal_error(GAL_ENOMEM, "reduced model: out of memory for the manifold");
    m->qm = qm;
    qm->np = nm * (nm + 1) / 2;
    qm->pair = malloc((size_t)nm * nm * sizeof(int));
    qm->Th = malloc((size_t)n * qm->np * sizeof(double)), qm->P = malloc((size_t)n * nm * sizeof(double));
    qm->mono = malloc((size_t)3 * qm->np * sizeof(double)), qm->M = malloc((size_t)nm * nm * sizeof(double));
    gal_csc *Kp = gal_csc_clone(rod->K), *Km = gal_csc_clone(rod->K);
    double *w = malloc((size_t)2 * n * sizeof(double)), *qp = malloc((size_t)nq * sizeof(double));
    if (!qm->pair || !qm->Th || !qm->P || !qm->mono || !qm->M || !Kp || !Km || !w || !qp) {
        st = gal_error(GAL_ENOMEM, "reduced model: out of memory for the manifold");
        goto done;
    }
    for (int j = 0, p = 0; j < nm; j++)
        for (int i = 0; i <= j; i++, p++) qm->pair[i * nm + j] = qm->pair[j * nm + i] = p;
    for (int j = 0; j < nm && !st; j++) {
        double e;
        st = gal_rom_tangents_along(m, m->V + (size_t)j * n, Kp, Km, qp, &e);
        for (int i = 0; i <= j && !st; i++) {
            double *th = qm->Th + (size_t)qm->pair[i * nm + j] * n;
            gal_csc_symv(Kp, m->V + (size_t)i * n, w);
            gal_csc_symv(Km, m->V + (size_t)i * n, w + n);
            for (int d = 0; d < n; d++) w[d] = -(w[d] - w[n + d]) / (2 * e);
            st = gal_chol_solve(m->chol0, w, th);
            { /* less its modal content (M-orthogonal to Phi): the modes' own response stays
               * dynamic, x = Phi^T M u exactly (measured: condor_150 vertical p-p 0.33 m with the
               * modal content on the manifold, 0.474 without, full 0.465) */
                gal_rod_mass_mult(rod, th, w);
                for (int k = 0; k < nm; k++) {
                    double pk = 0;
                    for (int d = 0; d < n; d++) pk += m->V[(size_t)k * n + d] * w[d];
                    for (int d = 0; d < n; d++) th[d] -= pk * m->V[(size_t)k * n + d];
                }
            }
        }
    }
    if (!st && m->o.manifold == 1) st = inertia_build(m);
done:
    gal_csc_free(Kp); gal_csc_free(Km);
    free(w); free(qp);
    return st;
}

void gal_rom_qm_mono(const gal_rom *m, const double *x, const double *xd, const double *xdd, double *mono,
                     double *dmono, double *ddmono)
{
    int nm = m->nmodes;
    for (int j = 0, p = 0; j < nm; j++)
        for (int i = 0; i <= j; i++, p++) {
            double c = i == j ? 0.5 : 1.0;
            mono[p] = c * x[i] * x[j];
            if (xd) dmono[p] = c * (xd[i] * x[j] + x[i] * xd[j]);
            if (xd && xdd) ddmono[p] = c * (xdd[i] * x[j] + 2 * xd[i] * xd[j] + x[i] * xdd[j]);
        }
}

void gal_rom_qm_displacement(gal_rom *m, const double *x, const double *xd, double *u, double *ud)
{
    const gal_rom_qm *qm = m->qm;
    int n = m->ndof, nm = m->nmodes, np = qm->np;
    double *mono = qm->mono, *dmono = mono + np;
    gal_rom_qm_mono(m, x, xd, NULL, mono, dmono, NULL);
    for (int d = 0; d < n; d++) {
        double s = 0, sv = 0;
        for (int k = 0; k < nm; k++) {
            s += m->V[(size_t)k * n + d] * x[k];
            if (xd) sv += m->V[(size_t)k * n + d] * xd[k];
        }
        for (int p = 0; p < np; p++) {
            double t = qm->Th[(size_t)p * n + d];
            s += t * mono[p];
            if (xd) sv += t * dmono[p];
        }
        u[d] = s;
        if (xd) ud[d] = sv;
    }
}

const double *gal_rom_qm_basis(gal_rom *m, const double *x)
{
    gal_rom_qm *qm = m->qm;
    int n = m->ndof, nm = m->nmodes;
    memcpy(qm->P, m->V, (size_t)n * nm * sizeof(double));
    for (int k = 0; k < nm; k++) {
        double *pk = qm->P + (size_t)k * n;
        for (int j = 0; j < nm; j++) {
            if (x[j] == 0) continue;
            const double *th = qm->Th + (size_t)qm->pair[k * nm + j] * n;
            for (int d = 0; d < n; d++) pk[d] += th[d] * x[j];
        }
    }
    return qm->P;
}

void gal_rom_qm_curvature(const gal_rom *m, const double *g, double *Kr)
{
    const gal_rom_qm *qm = m->qm;
    int n = m->ndof, nm = m->nmodes;
    for (int j = 0; j < nm; j++)
        for (int i = 0; i <= j; i++) {
            const double *th = qm->Th + (size_t)qm->pair[i * nm + j] * n;
            double s = 0;
            for (int d = 0; d < n; d++) s += th[d] * g[m->rod->free_q[d]];
            Kr[i * nm + j] += s;
            if (i != j) Kr[j * nm + i] += s;
        }
}

/* Solve the SPD nm x nm system A y = b in place (Cholesky, A overwritten); 0 on success. */
static int spd_solve(double *A, int p, double *b)
{
    for (int j = 0; j < p; j++) {
        double d = A[j * p + j];
        for (int k = 0; k < j; k++) d -= A[j * p + k] * A[j * p + k];
        if (!(d > 0)) return -1;
        A[j * p + j] = sqrt(d);
        for (int i = j + 1; i < p; i++) {
            double s = A[i * p + j];
            for (int k = 0; k < j; k++) s -= A[i * p + k] * A[j * p + k];
            A[i * p + j] = s / A[j * p + j];
        }
    }
    for (int i = 0; i < p; i++) {
        for (int k = 0; k < i; k++) b[i] -= A[i * p + k] * b[k];
        b[i] /= A[i * p + i];
    }
    for (int i = p - 1; i >= 0; i--) {
        for (int k = i + 1; k < p; k++) b[i] -= A[k * p + i] * b[k];
        b[i] /= A[i * p + i];
    }
    return 0;
}

/* A = P^T M P and b = P^T M y (y over the free dofs; t: scratch of ndof). */
static void normal_equations(gal_rom *m, const double *P, const double *y, double *A, double *b, double *t)
{
    int n = m->ndof, nm = m->nmodes;
    for (int i = 0; i < nm; i++) {
        gal_rod_mass_mult(m->rod, P + (size_t)i * n, t);
        double s = 0;
        for (int d = 0; d < n; d++) s += t[d] * y[d];
        b[i] = s;
        for (int j = 0; j <= i; j++) {
            const double *pj = P + (size_t)j * n;
            double a = 0;
            for (int d = 0; d < n; d++) a += t[d] * pj[d];
            A[i * nm + j] = A[j * nm + i] = a;
        }
    }
}

int gal_rom_qm_project_state(gal_rom *m, const double *q, const double *v, double *x, double *xd)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof, nm = m->nmodes, st = GAL_OK;
    double *u = m->wn, *res = m->wn2, *A = m->qm->M, b[64], *t = malloc((size_t)n * sizeof(double));
    if (!t) return gal_error(GAL_ENOMEM, "reduced model: out of memory");
    if (nm > 64) { free(t); return gal_error(GAL_EINPUT, "reduced model: the manifold takes at most 64 modes"); }
    for (int d = 0; d < n; d++) u[d] = q[rod->free_q[d]] - m->q_eq[rod->free_q[d]];
    memset(x, 0, (size_t)nm * sizeof(double));
    for (int it = 0; it < 30 && !st; it++) { /* Gauss-Newton on |u - u(x)|_M */
        gal_rom_qm_displacement(m, x, NULL, res, NULL);
        double rn = 0, un = 0;
        for (int d = 0; d < n; d++) res[d] = u[d] - res[d], rn += res[d] * res[d] * rod->mdiag[d], un += u[d] * u[d] * rod->mdiag[d];
        normal_equations(m, gal_rom_qm_basis(m, x), res, A, b, t);
        if (spd_solve(A, nm, b)) st = gal_error(GAL_EFAIL, "reduced model: the manifold's basis is singular");
        double dn = 0, xn = 0;
        for (int k = 0; k < nm && !st; k++) x[k] += b[k], dn += b[k] * b[k], xn += x[k] * x[k];
        if (dn <= 1e-24 * xn || rn <= 1e-28 * un || un == 0) break;
    }
    if (!st && xd) {
        for (int d = 0; d < n; d++) u[d] = v ? v[rod->free_q[d]] : 0;
        normal_equations(m, gal_rom_qm_basis(m, x), u, A, xd, t);
        if (spd_solve(A, nm, xd)) st = gal_error(GAL_EFAIL, "reduced model: the manifold's basis is singular");
    }
    free(t);
    return st;
}

/* Z(x) (nz x r, column-major; unit: with the identity of the eta rows): P_k = phi_k + sum_j
 * theta_kj x_j, so that P(x) = [Phi, Theta] Z(x) and Theta(v, v) = [Phi, Theta] Z(v)_0 v. */
static void zfill(const gal_rom *m, const double *x, double *Z, int unit)
{
    const gal_rom_qm *qm = m->qm;
    int r = m->nmodes, nz = qm->nz;
    memset(Z, 0, (size_t)nz * r * sizeof(double));
    for (int k = 0; k < r; k++) {
        double *zk = Z + (size_t)k * nz;
        if (unit) zk[k] = 1;
        for (int j = 0; j < r; j++) zk[r + qm->pair[k * r + j]] += x[j];
    }
}

/* out = Z^T A y (A nz x nz symmetric) */
static void zt_sym(const gal_rom *m, const double *A, const double *y, double *out)
{
    gal_rom_qm *qm = m->qm;
    int r = m->nmodes, nz = qm->nz;
    for (int a = 0; a < nz; a++) {
        double s = 0;
        for (int b = 0; b < nz; b++) s += A[a * nz + b] * y[b];
        qm->wy[a] = s;
    }
    for (int k = 0; k < r; k++) {
        double s = 0;
        for (int a = 0; a < nz; a++) s += qm->Z[(size_t)k * nz + a] * qm->wy[a];
        out[k] = s;
    }
}

/* y = Z a (+ Zv b when b) */
static void zmul(const gal_rom *m, const double *a, const double *b)
{
    gal_rom_qm *qm = m->qm;
    int r = m->nmodes, nz = qm->nz;
    memset(qm->y, 0, (size_t)nz * sizeof(double));
    for (int k = 0; k < r; k++)
        for (int c = 0; c < nz; c++) qm->y[c] += qm->Z[(size_t)k * nz + c] * a[k] + (b ? qm->Zv[(size_t)k * nz + c] * b[k] : 0);
}

void gal_rom_qm_inertia(gal_rom *m, const double *x, const double *v, const double *a, double *fin, double *fd)
{
    gal_rom_qm *qm = m->qm;
    zfill(m, x, qm->Z, 1);
    if (fin) {
        zfill(m, v, qm->Zv, 0);
        zmul(m, a, v);
        zt_sym(m, qm->W, qm->y, fin);
    }
    if (fd && qm->D) {
        zmul(m, v, NULL);
        zt_sym(m, qm->D, qm->y, fd);
    } else if (fd) memset(fd, 0, (size_t)m->nmodes * sizeof(double));
}

void gal_rom_qm_iteration(gal_rom *m, const double *x, const double *v, double cm, double cc, double *J)
{
    gal_rom_qm *qm = m->qm;
    int r = m->nmodes, nz = qm->nz;
    zfill(m, x, qm->Z, 1), zfill(m, v, qm->Zv, 0);
    for (int k = 0; k < r; k++) { /* column k: cm W Z_k + cc (D Z_k + 2 W Zv_k) */
        const double *zk = qm->Z + (size_t)k * nz, *vk = qm->Zv + (size_t)k * nz;
        for (int a = 0; a < nz; a++) {
            double s = 0;
            for (int b = 0; b < nz; b++)
                s += qm->W[a * nz + b] * (cm * zk[b] + 2 * cc * vk[b]) + (qm->D ? cc * qm->D[a * nz + b] * zk[b] : 0);
            qm->wy[a] = s;
        }
        for (int i = 0; i < r; i++) {
            double s = 0;
            for (int a = 0; a < nz; a++) s += qm->Z[(size_t)i * nz + a] * qm->wy[a];
            J[i * r + k] += s;
        }
    }
}

double gal_rom_qm_kinetic(gal_rom *m, const double *x, const double *v)
{
    gal_rom_qm *qm = m->qm;
    int nz = qm->nz;
    zfill(m, x, qm->Z, 1);
    zmul(m, v, NULL);
    double T = 0;
    for (int a = 0; a < nz; a++)
        for (int b = 0; b < nz; b++) T += qm->y[a] * qm->W[a * nz + b] * qm->y[b];
    return 0.5 * T;
}

int gal_rom_qm_acceleration(gal_rom *m, const double *x, const double *v, const double *f, double *a)
{
    gal_rom_qm *qm = m->qm;
    int r = m->nmodes;
    double *A = qm->M;
    memset(a, 0, (size_t)r * sizeof(double));
    gal_rom_qm_inertia(m, x, v, a, qm->f0, qm->d0); /* c(x, v) and the damping */
    for (int k = 0; k < r; k++) a[k] = f[k] - qm->f0[k] - qm->d0[k];
    memset(A, 0, (size_t)r * r * sizeof(double));
    gal_rom_qm_iteration(m, x, v, 1, 0, A);
    if (spd_solve(A, r, a)) return gal_error(GAL_EFAIL, "reduced model: the manifold's mass is singular");
    return GAL_OK;
}

/* M(x) v into p (r) */
static void momentum(gal_rom *m, const double *x, const double *v, double *p)
{
    zfill(m, x, m->qm->Z, 1);
    zmul(m, v, NULL);
    zt_sym(m, m->qm->W, m->qm->y, p);
}

void gal_rom_qm_begin(gal_rom *m)
{
    gal_rom_qm *qm = m->qm;
    gal_rom_qm_inertia(m, m->x, m->v, m->a, qm->f0, qm->d0);
    momentum(m, m->x, m->v, qm->p0);
}

/* g_j = d/dx_j of phi(x) = (Z(x) v0)^T W (Z(x) v1) / 2 at x (r entries); phi into *ph */
static void phi_grad(gal_rom *m, const double *x, const double *v0, const double *v1, double *g, double *ph)
{
    gal_rom_qm *qm = m->qm;
    int r = m->nmodes, nz = qm->nz;
    double *y0 = qm->y, *w1 = qm->wy;
    zfill(m, x, qm->Z, 1);
    zmul(m, v1, NULL); /* y = Z v1 */
    for (int a = 0; a < nz; a++) {
        double s = 0;
        for (int b = 0; b < nz; b++) s += qm->W[a * nz + b] * y0[b];
        w1[a] = s;       /* W Z v1 */
    }
    zmul(m, v0, NULL);  /* y = Z v0 */
    double *w0 = qm->Zv, p = 0; /* scratch: W Z v0 */
    for (int a = 0; a < nz; a++) {
        double s = 0;
        for (int b = 0; b < nz; b++) s += qm->W[a * nz + b] * y0[b];
        w0[a] = s, p += y0[a] * w1[a];
    }
    *ph = 0.5 * p;
    /* d(Z v)/dx_j = sum_k v_k e_(r + pair(k, j)) */
    for (int j = 0; j < r; j++) {
        double s = 0;
        for (int k = 0; k < r; k++) {
            int c = r + qm->pair[k * r + j];
            s += v0[k] * w1[c] + v1[k] * w0[c];
        }
        g[j] = 0.5 * s;
    }
}

void gal_rom_qm_end(gal_rom *m, double h)
{
    gal_rom_qm *qm = m->qm;
    int r = m->nmodes;
    double am = m->am, af = m->af;
    if (m->o.rho_inf != 1.0) {
        gal_rom_qm_inertia(m, m->x1, m->v1, m->a1, qm->f1, qm->d1);
        for (int i = 0; i < r; i++)
            qm->f1[i] = (1 - am) * qm->f1[i] + am * qm->f0[i], qm->d1[i] = (1 - af) * qm->d1[i] + af * qm->d0[i];
        return;
    }
    double g[64], xm[64] = {0}, ph0, ph1, phm, gd = 0, dd = 0; /* r <= 64 (gal_rom_qm_build) */
    gal_rom_qm_inertia(m, m->x1, m->v1, m->a1, NULL, qm->d1);
    for (int i = 0; i < r; i++) qm->d1[i] = 0.5 * (qm->d1[i] + qm->d0[i]), xm[i] = 0.5 * (m->x[i] + m->x1[i]);
    phi_grad(m, m->x, m->v, m->v1, g, &ph0);
    phi_grad(m, m->x1, m->v, m->v1, g, &ph1);
    phi_grad(m, xm, m->v, m->v1, g, &phm);
    for (int i = 0; i < r; i++) {
        double dx = m->x1[i] - m->x[i];
        gd += g[i] * dx, dd += dx * dx;
    }
    if (dd > 0) /* Gonzalez's correction along dx: g . dx = phi(x1) - phi(x0) */
        for (int i = 0; i < r; i++) g[i] += (ph1 - ph0 - gd) / dd * (m->x1[i] - m->x[i]);
    momentum(m, m->x1, m->v1, qm->f1);
    for (int i = 0; i < r; i++) qm->f1[i] = (qm->f1[i] - qm->p0[i]) / h - g[i];
}
