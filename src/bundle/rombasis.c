/* rombasis.c: the explicit bundle's reduced basis (bundle_rom.h): the selected bundle modes, their
 * static modal derivatives from the assembled tangent, the load-dependent vectors of the mean wind
 * (static responses to its load and to the load's derivatives along each mode, the sub-conductors'
 * own twist apart from the rest), M0-orthonormalized with deflation; the damping and the mean loads'
 * Jacobians projected. */
#include "gallop/bundle/bundle_rom.h"
#include "gallop/model/damping.h"
#include "gallop/base/core.h"
#include "bundle_impl.h"
#include "rom_impl.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/chol.h"

/* Append column y to V after M0-orthogonalizing it (twice) against V; dropped when less than the
 * deflation share of its M-norm is left. wrk: ndof. */
static void append(gal_bundle_rom *m, double *y, double *wrk)
{
    int n = m->ndof;
    gal_csc_symv(m->M0, y, wrk);
    double n0 = 0;
    for (int j = 0; j < n; j++) n0 += y[j] * wrk[j];
    if (!(n0 > 0)) return;
    for (int pass = 0; pass < 2; pass++) {
        gal_csc_symv(m->M0, y, wrk);
        for (int c = 0; c < m->r; c++) {
            const double *vc = m->V + (size_t)c * n;
            double p = 0;
            for (int j = 0; j < n; j++) p += vc[j] * wrk[j];
            for (int j = 0; j < n; j++) y[j] -= p * vc[j];
        }
    }
    gal_csc_symv(m->M0, y, wrk);
    double n1 = 0;
    for (int j = 0; j < n; j++) n1 += y[j] * wrk[j];
    if (!(n1 > m->o.deflation_tol * m->o.deflation_tol * n0)) return;
    double *vc = m->V + (size_t)m->r * n;
    for (int j = 0; j < n; j++) vc[j] = y[j] / sqrt(n1);
    m->r++;
}

/* The modal derivatives theta_ij, i <= j, by central differences of the assembled tangent along
 * phi_j (columns 0..nm-1 of V, before orthonormalization changes them: Phi is M-orthonormal). */
static int derivatives(gal_bundle_rom *m, const double *phi, int nm)
{
    gal_bundle *b = m->b;
    int n = m->ndof, st = GAL_OK;
    gal_csc *Kp = gal_csc_clone(b->K);
    double *sp = malloc((size_t)b->nstate * sizeof(double)), *w = malloc((size_t)3 * n * sizeof(double));
    if (!Kp || !sp || !w) st = gal_error(GAL_ENOMEM, "bundle reduced model: out of memory");
    for (int j = 0; j < nm && !st; j++) {
        const double *pj = phi + (size_t)j * n;
        double mx = 0;
        for (int k = 0; k < n; k++) mx = fmax(mx, fabs(pj[k]));
        double eps = m->o.fd_step_m / mx;
        gal_bundle_step(b, b->state, pj, eps, sp);
        if ((st = gal_bundle_eval(b, sp, NULL, 1))) break;
        memcpy(Kp->val, b->K->val, (size_t)b->K->nnz * sizeof(double));
        gal_bundle_step(b, b->state, pj, -eps, sp);
        if ((st = gal_bundle_eval(b, sp, NULL, 1))) break;
        for (int i = 0; i <= j && !st; i++) {
            gal_csc_symv(Kp, phi + (size_t)i * n, w);
            gal_csc_symv(b->K, phi + (size_t)i * n, w + n);
            for (int k = 0; k < n; k++) w[k] = -(w[k] - w[n + k]) / (2 * eps);
            if ((st = gal_chol_solve(m->chol0, w, w + n))) break;
            append(m, w + n, w + 2 * n);
        }
    }
    gal_csc_free(Kp);
    free(sp), free(w);
    return st;
}

void gal_bundle_rom_mean_loads(const gal_bundle_loads *bl, gal_bundle_loads *out)
{
    *out = *bl;
    for (int r = 0; r < GAL_BUNDLE_MAX; r++) {
        gal_loads *L = &out->L[r];
        L->u = L->w = NULL, L->nt = 0, L->ramp_time = 0, L->reverse_time = 0;
    }
}

/* K0^-1 y appended, the rods' independent twist dofs apart from the rest; w: 3 ndof; the whole
 * K0^-1 y into u when not NULL. */
static int append_static(gal_bundle_rom *m, const double *y, double *w, double *u)
{
    gal_bundle *b = m->b;
    const gal_rod *rod = b->rod[0];
    int n = m->ndof, st;
    double *tw = w, *rest = w + n;
    if ((st = gal_chol_solve(m->chol0, y, rest))) return st;
    if (u) memcpy(u, rest, (size_t)n * sizeof(double));
    memset(tw, 0, (size_t)n * sizeof(double));
    for (int r = 0; r < b->n; r++)
        for (int d = 0; d < rod->ndof; d++)
            if (b->tcnt[r][d] == 1 && rod->free_q[d] >= 3 * b->nn) {
                int j = b->tidx[r][4 * d];
                tw[j] = rest[j], rest[j] = 0;
            }
    append(m, tw, w + 2 * n);
    append(m, rest, w + 2 * n);
    return GAL_OK;
}

/* The mean load at the state s and velocity v into f (the map's values set at s). */
static int mean_load(gal_bundle_rom *m, const double *s, const double *v, double *f)
{
    memset(f, 0, (size_t)m->ndof * sizeof(double));
    gal_bundle_map_values(m->b, s);
    return gal_bundle_loads_eval((void *)m->o.mean_loads, m->b, 0.0, s, v, f);
}

/* The load-dependent vectors (o.load_vectors) from the modes phi (nm columns). */
static int load_vectors(gal_bundle_rom *m, const double *phi, int nm)
{
    gal_bundle *b = m->b;
    int n = m->ndof, st;
    double *w = malloc((size_t)6 * n * sizeof(double)), *sp = malloc((size_t)b->nstate * sizeof(double));
    if (!w || !sp) {
        free(w), free(sp);
        return gal_error(GAL_ENOMEM, "bundle reduced model: out of memory");
    }
    double *f0 = w + 3 * n, *f1 = w + 4 * n, *v = w + 5 * n;
    memset(v, 0, (size_t)n * sizeof(double));
    /* the mean load's first two load-dependent Ritz vectors, K0^-1 F and K0^-1 M0 K0^-1 F: the
     * second carries the inertia of the response to the ramped wind */
    if (!(st = mean_load(m, b->state, v, f0))) st = append_static(m, f0, w, f1);
    if (!st) gal_csc_symv(m->M0, f1, f0), st = append_static(m, f0, w, NULL);
    for (int i = 0; i < nm && m->o.load_vectors > 1 && !st; i++) {
        const double *p = phi + (size_t)i * n;
        double mx = 0;
        for (int k = 0; k < n; k++) mx = fmax(mx, fabs(p[k]));
        double eps = m->o.fd_step_m / mx; /* the displacement's derivative, then the velocity's */
        gal_bundle_step(b, b->state, p, eps, sp);
        if ((st = mean_load(m, sp, v, f1))) break;
        gal_bundle_step(b, b->state, p, -eps, sp);
        if ((st = mean_load(m, sp, v, f0))) break;
        for (int k = 0; k < n; k++) f1[k] = (f1[k] - f0[k]) / (2 * eps);
        if ((st = append_static(m, f1, w, NULL))) break;
        for (int k = 0; k < n; k++) v[k] = eps * p[k];
        if ((st = mean_load(m, b->state, v, f1))) break;
        for (int k = 0; k < n; k++) v[k] = -eps * p[k];
        if ((st = mean_load(m, b->state, v, f0))) break;
        memset(v, 0, (size_t)n * sizeof(double));
        for (int k = 0; k < n; k++) f1[k] = (f1[k] - f0[k]) / (2 * eps);
        st = append_static(m, f1, w, NULL);
    }
    free(w), free(sp);
    return st;
}

/* The mean loads' reduced Jacobians at the equilibrium, by central differences along each basis
 * vector: Kl = -V^T dF/ds V, Cl = -V^T dF/dv V (row-major, r x r), for the iteration matrix. */
static int load_jacobians(gal_bundle_rom *m)
{
    gal_bundle *b = m->b;
    int n = m->ndof, r = m->r, st = GAL_OK;
    double *w = malloc((size_t)3 * n * sizeof(double)), *sp = malloc((size_t)b->nstate * sizeof(double));
    double *y = malloc((size_t)2 * r * sizeof(double));
    m->Kl = calloc((size_t)r * r, sizeof(double)), m->Cl = calloc((size_t)r * r, sizeof(double));
    if (!w || !sp || !y || !m->Kl || !m->Cl) st = gal_error(GAL_ENOMEM, "bundle reduced model: out of memory");
    double *f0 = w, *f1 = w + n, *v = w + 2 * n;
    for (int c = 0; c < r && !st; c++) {
        const double *p = m->V + (size_t)c * n;
        double mx = 0;
        for (int k = 0; k < n; k++) mx = fmax(mx, fabs(p[k]));
        double eps = m->o.fd_step_m / mx;
        memset(v, 0, (size_t)n * sizeof(double));
        gal_bundle_step(b, b->state, p, eps, sp);
        if ((st = mean_load(m, sp, v, f1))) break;
        gal_bundle_step(b, b->state, p, -eps, sp);
        if ((st = mean_load(m, sp, v, f0))) break;
        for (int k = 0; k < n; k++) f1[k] = -(f1[k] - f0[k]) / (2 * eps);
        gal_bundle_rom_project(m, f1, y);
        for (int k = 0; k < n; k++) v[k] = eps * p[k];
        if ((st = mean_load(m, b->state, v, f1))) break;
        for (int k = 0; k < n; k++) v[k] = -eps * p[k];
        if ((st = mean_load(m, b->state, v, f0))) break;
        for (int k = 0; k < n; k++) f1[k] = -(f1[k] - f0[k]) / (2 * eps);
        gal_bundle_rom_project(m, f1, y + r);
        for (int k = 0; k < r; k++) m->Kl[k * r + c] = y[k], m->Cl[k * r + c] = y[r + k];
    }
    free(w), free(sp), free(y);
    return st;
}

/* The inertia of the static vectors: K0^-1 M0 u appended for every basis vector u past the modes
 * (the modal derivatives' and the load vectors' next Krylov vector: without them the residual's
 * correction K0^-1 R keeps a part along the static vectors' own inertia, K0^-1 M0 u, which no column
 * carries; the quad bundle's vertical residual 0.029 -> 0.0002 in the mass norm at t = 477 s). */
static int inertia_vectors(gal_bundle_rom *m)
{
    int n = m->ndof, r0 = m->r, st = GAL_OK;
    double *y = malloc((size_t)3 * n * sizeof(double));
    if (!y) return gal_error(GAL_ENOMEM, "bundle reduced model: out of memory");
    for (int c = m->nmodes; c < r0 && !st; c++) {
        gal_csc_symv(m->M0, m->V + (size_t)c * n, y);
        if (!(st = gal_chol_solve(m->chol0, y, y + n))) append(m, y + n, y + 2 * n);
    }
    free(y);
    return st;
}

/* The basis: the selected modes, then the modal derivatives, the load vectors and their inertia;
 * the damping projected. */
int gal_bundle_rom_basis(gal_bundle_rom *m, const gal_modes *md)
{
    int n = m->ndof, nm = 0, st;
    for (int k = 0; k < md->n; k++) nm += md->mode[k].selected != 0;
    if (nm == 0) return gal_error(GAL_EINPUT, "bundle reduced model: no bundle mode selected (model.modes_*)");
    int nlv = !m->o.mean_loads ? 0 : m->o.load_vectors > 1 ? 4 + 4 * nm : m->o.load_vectors > 0 ? 4 : 0;
    int rmax = nm + (m->o.derivatives ? nm * (nm + 1) / 2 : 0) + nlv;
    if (m->o.inertia_vectors) rmax = nm + 2 * (rmax - nm);
    double *phi = malloc((size_t)nm * n * sizeof(double)), *w = malloc((size_t)2 * n * sizeof(double));
    if (!phi || !w || (st = gal_bundle_rom_alloc_state(m, rmax))) {
        free(phi), free(w);
        return phi && w ? st : gal_error(GAL_ENOMEM, "bundle reduced model: out of memory");
    }
    for (int k = 0, c = 0; k < md->n; k++)
        if (md->mode[k].selected) memcpy(phi + (size_t)c++ * n, md->shape + (size_t)k * n, (size_t)n * sizeof(double));
    for (int c = 0; c < nm; c++) {
        memcpy(w, phi + (size_t)c * n, (size_t)n * sizeof(double));
        append(m, w, w + n);
    }
    m->nmodes = m->r;
    st = m->o.derivatives ? derivatives(m, phi, nm) : GAL_OK;
    if (!st && nlv > 0) st = load_vectors(m, phi, nm);
    if (!st && m->o.inertia_vectors) st = inertia_vectors(m);
    free(phi), free(w);
    if (!st && m->o.mean_loads) st = load_jacobians(m);
    if (st) return st;
    if (m->o.damping) return gal_damping_project(m->o.damping, m->V, m->r, m->Cr); /* the full model's C */
    gal_bundle_rom_project_matrix(m, m->K0, m->Cr);
    for (int k = 0; k < m->r * m->r; k++) m->Cr[k] *= m->o.beta;
    for (int k = 0; k < m->r; k++) m->Cr[k * m->r + k] += m->o.alpha;
    return GAL_OK;
}

