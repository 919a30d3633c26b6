/* rom_basis.c: the basis of the recomputed reduced model (rom.h): the selected modes and their
 * static modal derivatives theta_ij = -K0^-1 (dK/d eta_j) phi_i, the directional derivative of the
 * tangent by central differences of gal_rod_eval's tangent along phi_j (the two tangents'
 * difference taken entry by entry) and one factorization of K0; then M-orthonormalized (classical
 * Gram-Schmidt twice, as BLAS products) and deflated. Also the model's allocation: its
 * wind-independent set-up (gal_rom_setup_alloc), copied for another wind, then the rest (the loads'
 * sample, the damping, the start); and its reduced matrices. */
#include "gallop/reduced/rom.h"
#include "gallop/base/core.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/chol.h"
#include "gallop/reduced/ecsw.h"
#include "reduced/hyper.h"
#include "reduced/qm.h"

/* the BLAS (column-major) */
void dgemv_(const char *trans, const int *m, const int *n, const double *alpha, const double *a, const int *lda,
            const double *x, const int *incx, const double *beta, double *y, const int *incy);
void dgemm_(const char *ta, const char *tb, const int *m, const int *n, const int *k, const double *alpha,
            const double *a, const int *lda, const double *b, const int *ldb, const double *beta, double *c,
            const int *ldc);

void gal_rom_default_opts(gal_rom_opts *o)
{
    memset(o, 0, sizeof *o);
    o->derivatives = 1;
    o->deflation_tol = 1e-6, o->derivative_floor = 0;
    o->fd_step_m = 1e-3;
    o->h = 0.01;
    o->rho_inf = 1.0;
    o->newton_tol = 1e-8;
    o->max_newton = 20;
    o->hyper = 1, o->hyper_tol = 1e-2, o->hyper_check_tol = 2e-2, o->hyper_twist = 1.5, o->hyper_snapshots = 24;
    o->hyper_snapshots_fine = 0; /* measured, not the default: BENCHMARKS.md, helper setup3 */
    o->hyper_check_interval = 1.0, o->hyper_loads = 1, o->reuse_tangent = 1;
    o->newton_contraction = 0.1, o->newton_kept_max = 3, o->loads_once = 1, o->one_pass = 0;
}

gal_rom *gal_rom_free(gal_rom *m)
{
    if (!m) return NULL;
    if (!m->setup_reused) gal_chol_free(m->chol0); /* else the set-up's */
    free(m->setup_sel);
    gal_rom_hyper_free(m);
    gal_rom_qm_free(m);
    gal_rom_irk_free(m);
    free(m->fr); free(m->fe_prev); free(m->node_dir);
    free(m->V); free(m->omega2); free(m->Cr); free(m->K0r); free(m->q_eq);
    gal_csc_free(m->K0); gal_csc_free(m->K);
    free(m->x); free(m->v); free(m->a); free(m->fi); free(m->fe);
    free(m->q); free(m->vq); free(m->gq); free(m->fq); free(m->wn); free(m->wn2);
    free(m->x1); free(m->v1); free(m->a1); free(m->fi1); free(m->fe1); free(m->fdg); free(m->res); free(m->da);
    free(m->J); free(m->Kr); free(m->piv);
    free(m);
    return NULL;
}

/* u^T M c over the free dofs, with Mu = M u given. */
static double dot(const double *a, const double *b, int n)
{
    double s = 0;
    for (int k = 0; k < n; k++) s += a[k] * b[k];
    return s;
}

/* Append candidate c (overwritten) to the M-orthonormal columns V[0..*r-1] (MV their M-images)
 * unless what is left after orthogonalization is below tol of its M-norm: classical Gram-Schmidt
 * twice (CGS2, as orthogonal to working precision as modified Gram-Schmidt twice), each pass two
 * matrix-vector products p = MV^T c, c -= V p; p: *r scratch. */
static void orth_append(const gal_rod *rod, double *V, double *MV, int *r, double *c, double *Mc, double tol, double *p)
{
    int n = rod->ndof, one = 1;
    double a = 1, b = 0, mb = -1;
    gal_rod_mass_mult(rod, c, Mc);
    double n0 = sqrt(fmax(dot(c, Mc, n), 0));
    if (!(n0 > 0)) return;
    for (int pass = 0; pass < 2 && *r > 0; pass++) {
        dgemv_("T", &n, r, &a, MV, &n, c, &one, &b, p, &one);
        dgemv_("N", &n, r, &mb, V, &n, p, &one, &a, c, &one);
    }
    gal_rod_mass_mult(rod, c, Mc);
    double n1 = sqrt(fmax(dot(c, Mc, n), 0));
    if (!(n1 > tol * n0)) return;
    for (int d = 0; d < n; d++) V[(size_t)*r * n + d] = c[d] / n1, MV[(size_t)*r * n + d] = Mc[d] / n1;
    (*r)++;
}

/* The tangents Kp, Km at q_eq +- e phi (phi: free-dof sized), e = o.fd_step_m over phi's largest
 * entry, for the central difference dK/d eta phi_i = (Kp - Km) phi_i / (2 e); qp: nq scratch. */
int gal_rom_tangents_along(const gal_rom *m, const double *phi, gal_csc *Kp, gal_csc *Km, double *qp, double *e)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof, st = GAL_OK;
    double mx = 0;
    for (int d = 0; d < n; d++) mx = fmax(mx, fabs(phi[d]));
    *e = m->o.fd_step_m / mx;
    for (int s = 0; s < 2 && !st; s++) {
        memcpy(qp, m->q_eq, (size_t)m->nq * sizeof(double));
        for (int d = 0; d < n; d++) qp[rod->free_q[d]] += (s ? -*e : *e) * phi[d];
        st = gal_rod_eval(rod, qp, NULL, NULL, s ? Km : Kp);
    }
    return st;
}

/* Y = D X for the symmetric D on K's pattern (its upper triangle's values dv) and the k columns of
 * X (n each), in one pass over D; each column summed in gal_csc_symv's order. */
static void symv_multi(const gal_csc *K, const double *dv, const double *X, int k, double *Y)
{
    int n = K->n;
    memset(Y, 0, (size_t)n * k * sizeof(double));
    for (int j = 0; j < n; j++)
        for (int p = K->colptr[j]; p < K->colptr[j + 1]; p++) {
            int i = K->rowind[p];
            double a = dv[p];
            for (int c = 0; c < k; c++) {
                const double *x = X + (size_t)c * n;
                double *y = Y + (size_t)c * n;
                y[i] += a * x[j];
                if (i != j) y[j] += a * x[i];
            }
        }
}

/* The modal derivatives of the nsel modes (columns of V) appended to V: for each j the tangents
 * along phi_j, their difference dK = Kp - Km taken entry by entry (exact, Sterbenz's lemma: the two
 * agree to O(e); the products' difference Kp phi - Km phi added eps |K| |phi| of round-off to
 * |dK phi| ~ 1e-6 |K| |phi|; what remains is the round-off of the tangents' own evaluation), then
 * theta_ij = -K0^-1 dK phi_i / (2 e), i <= j, all i in one pass over dK. With o.derivative_floor > 0
 * those whose M-norm is under that share of the largest one's are left out: on a conductor, the
 * couplings through the twist (whose mass norm is ~1e-3 of the translations'), tiny and real (the
 * same to 4 digits for steps from 1e-2 to 1e-5 m); what Gram-Schmidt leaves of them, normalized,
 * changes with the mesh (iced_gallop, theta of the torsional mode with itself, 8e-9 of the largest:
 * a 4 Hz vertical wave at 40 elements, a spike at the nodes next to the supports, 89 Hz, at 600).
 * Off by default: 1e-4 brings iced_gallop's twist at 600/800 elements within 3.5% but the 40-element
 * 5:1 twist resonance needs them (BENCHMARKS.md, helper basis). scratch: r entries. */
static int derivatives(gal_rom *m, double *MV, int nsel, double *scratch)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof, nq = m->nq, st = GAL_OK, nnz = rod->K->colptr[n], np = nsel * (nsel + 1) / 2;
    gal_csc *Kp = gal_csc_clone(rod->K), *Km = gal_csc_clone(rod->K);
    double *W = malloc((size_t)(np + 1) * n * sizeof(double)), *qp = malloc((size_t)nq * sizeof(double));
    double *nrm = malloc((size_t)np * sizeof(double)), big = 0;
    if (!Kp || !Km || !W || !qp || !nrm) { st = gal_error(GAL_ENOMEM, "reduced model: out of memory"); goto done; }
    double *Mw = W + (size_t)np * n;
    for (int j = 0, p0 = 0; j < nsel && !st; p0 += ++j) {
        double e;
        if ((st = gal_rom_tangents_along(m, m->V + (size_t)j * n, Kp, Km, qp, &e))) break;
        for (int p = 0; p < nnz; p++) Kp->val[p] -= Km->val[p];
        symv_multi(Kp, Kp->val, m->V, j + 1, W + (size_t)p0 * n);
        for (int i = 0; i <= j && !st; i++) {
            double *w = W + (size_t)(p0 + i) * n;
            for (int d = 0; d < n; d++) w[d] = -w[d] / (2 * e);
            if ((st = gal_chol_solve(m->chol0, w, w))) break;
            gal_rod_mass_mult(rod, w, Mw);
            nrm[p0 + i] = sqrt(fmax(dot(w, Mw, n), 0)), big = fmax(big, nrm[p0 + i]);
        }
    }
    for (int p = 0; p < np && !st; p++)
        if (nrm[p] >= m->o.derivative_floor * big)
            orth_append(rod, m->V, MV, &m->r, W + (size_t)p * n, Mw, m->o.deflation_tol, scratch);
done:
    gal_csc_free(Kp); gal_csc_free(Km);
    free(W); free(qp); free(nrm);
    return st;
}

/* The static load responses appended to V (o.weight_vector, o.wind_vector): K0^-1 W, W the load
 * of the rod's weight terms (gravity and the eccentric ice's moment) at the equilibrium, and
 * K0^-1 F_mean for the mean wind's load fmean (nq, or NULL); each Gram-Schmidted against V as the
 * others. c: 2 ndof + r scratch. */
static int load_vectors(gal_rom *m, double *MV, const double *fmean, double *c)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof, nq = m->nq, st = GAL_OK;
    double *f = calloc((size_t)2 * nq, sizeof(double)), *g = f + nq;
    if (!f) return gal_error(GAL_ENOMEM, "reduced model: out of memory");
    for (int pass = 0; pass < 2 && !st; pass++) {
        if (pass == 0 && !m->o.weight_vector) continue;
        if (pass == 1 && !(m->o.wind_vector && fmean)) continue;
        if (pass == 0) {
            double U = 0;
            memset(f, 0, (size_t)nq * sizeof(double));
            for (int k = 0; k < rod->nterm && !st; k++)
                if (rod->term[k] == &gal_rod_term_gravity || rod->term[k] == &gal_rod_term_ice) {
                    if ((st = gal_rod_eval_term(rod, k, m->q_eq, &U, g, NULL))) break; /* g cleared first */
                    for (int i = 0; i < nq; i++) f[i] += g[i];
                }
        } else memcpy(f, fmean, (size_t)nq * sizeof(double));
        if (st) break;
        gal_rod_gather(rod, f, c);
        if ((st = gal_chol_solve(m->chol0, c, c))) break;
        orth_append(rod, m->V, MV, &m->r, c, c + n, m->o.deflation_tol, c + 2 * n);
    }
    free(f);
    return st;
}

static int alloc_state(gal_rom *m, int rmax)
{
    int n = m->ndof, nq = m->nq, r = rmax;
    size_t br = (size_t)r * sizeof(double);
    m->V = malloc((size_t)n * r * sizeof(double));
    m->Cr = malloc(br * r), m->K0r = malloc(br * r), m->J = malloc(br * r), m->Kr = malloc(br * r);
    m->q_eq = malloc((size_t)nq * sizeof(double));
    m->q = malloc((size_t)nq * sizeof(double)), m->vq = calloc(nq, sizeof(double));
    m->gq = malloc((size_t)nq * sizeof(double)), m->fq = malloc((size_t)nq * sizeof(double));
    m->wn = malloc((size_t)n * sizeof(double)), m->wn2 = malloc((size_t)n * sizeof(double));
    m->x = calloc(r, sizeof(double)), m->v = calloc(r, sizeof(double)), m->a = calloc(r, sizeof(double));
    m->fi = calloc(r, sizeof(double)), m->fe = calloc(r, sizeof(double));
    m->x1 = malloc(br), m->v1 = malloc(br), m->a1 = malloc(br), m->fi1 = malloc(br), m->fe1 = malloc(br), m->fdg = malloc(br);
    m->res = malloc(br), m->da = malloc(br), m->piv = malloc((size_t)r * sizeof(int)), m->fr = malloc(br), m->fe_prev = calloc(r, sizeof(double));
    m->K0 = gal_csc_clone(m->rod->K), m->K = gal_csc_clone(m->rod->K);
    if (!m->V || !m->Cr || !m->K0r || !m->J || !m->Kr || !m->q_eq || !m->q || !m->vq || !m->gq || !m->fq ||
        !m->wn || !m->wn2 || !m->x || !m->v || !m->a || !m->fi || !m->fe || !m->x1 || !m->v1 || !m->a1 ||
        !m->fi1 || !m->fe1 || !m->fdg || !m->res || !m->da || !m->piv || !m->K0 || !m->K || !m->fr || !m->fe_prev)
        return gal_error(GAL_ENOMEM, "reduced model: out of memory for a basis of %d", r);
    return GAL_OK;
}

/* Kr = V^T K V (r x r, row-major) for the tangent K; the dots four columns at a time, each summed
 * in order (the round-off of one at a time). */
void gal_rom_project_tangent(const gal_rom *m, const gal_csc *K, double *Kr, double *work)
{
    int n = m->ndof, r = m->r;
    for (int j = 0; j < r; j++) {
        gal_csc_symv(K, m->V + (size_t)j * n, work);
        int i = 0;
        for (; i + 4 <= j + 1; i += 4) {
            const double *a = m->V + (size_t)i * n, *b = a + n, *c = b + n, *e = c + n;
            double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
            for (int d = 0; d < n; d++) s0 += a[d] * work[d], s1 += b[d] * work[d], s2 += c[d] * work[d], s3 += e[d] * work[d];
            Kr[i * r + j] = Kr[j * r + i] = s0, Kr[(i + 1) * r + j] = Kr[j * r + i + 1] = s1;
            Kr[(i + 2) * r + j] = Kr[j * r + i + 2] = s2, Kr[(i + 3) * r + j] = Kr[j * r + i + 3] = s3;
        }
        for (; i <= j; i++) Kr[i * r + j] = Kr[j * r + i] = dot(m->V + (size_t)i * n, work, n);
    }
}

/* K0r = V^T K0 V at the set-up: the r products K0 v_j in one pass over K0 (each as gal_csc_symv
 * sums it), then one dgemm (the upper triangle kept and mirrored: exactly symmetric). */
static int project_K0(gal_rom *m)
{
    int n = m->ndof, r = m->r;
    double one = 1, zero = 0, *KV = malloc((size_t)n * r * sizeof(double));
    if (!KV) return gal_error(GAL_ENOMEM, "reduced model: out of memory");
    symv_multi(m->K0, m->K0->val, m->V, r, KV);
    dgemm_("T", "N", &r, &r, &n, &one, m->V, &n, KV, &n, &zero, m->K0r, &r);
    for (int j = 0; j < r; j++)
        for (int i = 0; i < j; i++) m->K0r[i * r + j] = m->K0r[j * r + i];
    free(KV);
    return GAL_OK;
}

/* The Newton test's force scales: |V^T (node weights in every direction)| and eps L EA/l0 times the
 * largest column sum of |V|. */
static void force_scales(gal_rom *m)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof;
    double fs = 0, cs = 0;
    for (int k = 0; k < m->r; k++) {
        double p = 0, s = 0;
        for (int d = 0; d < n; d++) p += m->V[(size_t)k * n + d] * rod->mdiag[d] * 9.81, s += fabs(m->V[(size_t)k * n + d]);
        fs += p * p, cs = fmax(cs, s);
    }
    m->fscale = sqrt(fs);
    m->ffloor = 20 * 2.2e-16 * fmax(rod->p.length, fabs(rod->p.height_difference)) * rod->p.EA / rod->l0[0] * cs;
}

/* 1 when t is the rod's tangent at m->q_eq with its factorization (gal_rom_opts.k0). */
static int k0_fits(const gal_rom *m, const gal_tangent *t)
{
    const gal_rod *rod = m->rod;
    return t && t->K && t->K->val && t->chol && t->chol->L && t->nq == rod->nq && t->K->n == rod->K->n &&
           t->K->nnz == rod->K->nnz && t->chol->n == rod->ndof && t->L0 == rod->p.unstretched_length &&
           !memcmp(t->q, m->q_eq, (size_t)rod->nq * sizeof(double));
}

/* K0 at the equilibrium and its factorization into m->K0, m->chol0: the handed-over ones
 * (o.k0, the statics' stability check: the same numbers) or evaluated, analysed and factorized. */
static int tangent_at_equilibrium(gal_rom *m)
{
    const gal_rod *rod = m->rod;
    const gal_tangent *t = m->o.k0;
    m->o.k0 = NULL; /* not kept past the build */
    if (k0_fits(m, t)) {
        memcpy(m->K0->val, t->K->val, (size_t)rod->K->nnz * sizeof(double));
        return (m->chol0 = gal_chol_clone(t->chol)) ? GAL_OK : GAL_ENOMEM;
    }
    int st = gal_rod_eval(rod, m->q_eq, NULL, m->gq, m->K0);
    if (st) return st;
    if (!(m->chol0 = gal_chol_alloc(rod->K))) return GAL_ENOMEM;
    if (gal_chol_factor(m->chol0, m->K0, 0, NULL))
        return gal_error(GAL_EFAIL, "reduced model: the tangent at the equilibrium is not positive definite (%s)", gal_error_message());
    return GAL_OK;
}

/* The set-up that does not depend on the loads, the damping or the step (m->rod, m->o filled;
 * m->force empty, or the loads when known: then their sample is trained in the same pass as the
 * rod's): K0 and its factorization, the basis, V^T K0 V, the force scales and the rod's sample. */
static int build_setup(gal_rom *m, const double *q_eq, const gal_modes *md, const int *sel, int nsel)
{
    const gal_rod *rod = m->rod;
    int st = GAL_OK;
    m->ndof = rod->ndof, m->nq = rod->nq, m->nmodes = nsel;
    int n = m->ndof, rmax = nsel + (m->o.derivatives ? nsel * (nsel + 1) / 2 : 0) + (m->o.nextra > 0 ? m->o.nextra : 0);
    if (m->o.manifold) rmax += 3; /* the static vectors (qm.h) */
    else rmax += (m->o.weight_vector != 0) + (m->o.wind_vector && m->o.mean_load); /* load_vectors */
    double *MV = malloc((size_t)n * rmax * sizeof(double)), *c = malloc(((size_t)2 * n + rmax) * sizeof(double));
    m->omega2 = malloc((size_t)nsel * sizeof(double)), m->setup_sel = malloc((size_t)nsel * sizeof(int));
    if (!MV || !c || !m->omega2 || !m->setup_sel) st = gal_error(GAL_ENOMEM, "reduced model: out of memory");
    if (!st) st = alloc_state(m, rmax);
    if (st) goto done;
    m->setup_shape = md->shape, m->setup_nsel = nsel;
    memcpy(m->setup_sel, sel, (size_t)nsel * sizeof(int));
    memcpy(m->q_eq, q_eq, (size_t)m->nq * sizeof(double));
    if ((st = tangent_at_equilibrium(m))) goto done;
    for (int k = 0; k < nsel; k++) {
        if (sel[k] < 0 || sel[k] >= md->n) { st = gal_error(GAL_EINPUT, "reduced model: mode %d not computed", sel[k]); goto done; }
        m->omega2[k] = md->mode[sel[k]].omega * md->mode[sel[k]].omega;
        memcpy(c, md->shape + (size_t)sel[k] * n, (size_t)n * sizeof(double));
        int r0 = m->r;
        orth_append(rod, m->V, MV, &m->r, c, c + n, 1e-3, c + 2 * n);
        if (m->r == r0) { st = gal_error(GAL_EFAIL, "reduced model: mode %d repeats the others", sel[k]); goto done; }
    }
    if (m->o.manifold && m->o.nextra > 0) {
        st = gal_error(GAL_EINPUT, "reduced model: the quadratic manifold takes no extra basis vectors");
        goto done;
    }
    if (m->o.manifold && (st = gal_rom_qm_static(m, MV))) goto done;
    const double *fmean = m->o.mean_load;
    m->o.mean_load = NULL; /* not owned */
    if (m->o.derivatives && (st = m->o.manifold ? gal_rom_qm_build(m) : derivatives(m, MV, nsel, c + 2 * n))) goto done;
    if (!m->o.manifold && (st = load_vectors(m, MV, fmean, c))) goto done;
    for (int k = 0; k < m->o.nextra; k++) {
        memcpy(c, m->o.extra + (size_t)k * n, (size_t)n * sizeof(double));
        orth_append(rod, m->V, MV, &m->r, c, c + n, m->o.deflation_tol, c + 2 * n);
    }
    m->o.extra = NULL; /* not owned: not kept past the build */
    if ((st = project_K0(m))) goto done;
    force_scales(m);
    /* the sample (ecsw.h); a rod with a term that has no element split (an equivalent bundle's
     * differential-stretch fields, src/rod/bundle_irvine.c) is projected exactly */
    if (m->o.hyper && gal_rod_element_form(rod)) st = gal_rom_hyper_build(m);
done:
    free(MV); free(c);
    return st;
}

/* The rest of the model on its set-up: the options o (the set-up's kept), the loads, the damping
 * Cr = V^T C V, the step's constants, the loads' sample (unless trained with the rod's: the set-up
 * built with the loads known), and the start at rest at q_eq. */
static int finish(gal_rom *m, const gal_rom_opts *o, const gal_force *force, double t0, int trained)
{
    gal_rom_opts keep = m->o;
    if (o) m->o = *o;
    m->o.mean_load = NULL, m->o.extra = NULL, m->o.nextra = keep.nextra, m->o.setup = NULL, m->o.k0 = NULL;
    if (force) m->force = *force;
    int r = m->r, st = GAL_OK;
    memset(m->Cr, 0, (size_t)r * r * sizeof(double));
    if (m->o.damping && (st = gal_damping_project(m->o.damping, m->V, r, m->Cr))) return st; /* symmetric */
    double rho = m->o.rho_inf;
    m->am = (2 * rho - 1) / (rho + 1), m->af = rho / (rho + 1);
    m->gamma = 0.5 - m->am + m->af, m->beta = 0.25 * (1 - m->am + m->af) * (1 - m->am + m->af);
    if (m->hyper && !trained && (st = gal_rom_hyper_loads(m))) return st;
    gal_rom_reconstruct_at(m, NULL, NULL); /* every entry of m->q: the sample's evaluations write only theirs */
    if ((st = gal_rom_start(m, 0.0, m->q_eq, NULL))) return st;
    m->build_time_s = gal_wall_time() - t0;
    return GAL_OK;
}

/* Whether the set-up s is the one gal_rom_alloc would compute for these arguments. */
static int setup_matches(const gal_rom *s, const gal_rod *rod, const double *q_eq, const gal_modes *md, const int *sel,
                         int nsel, const gal_rom_opts *o)
{
    const gal_rom_opts *a = &s->o;
    for (int k = 0; k < nsel && s->setup_shape == md->shape && s->setup_nsel == nsel; k++)
        if (sel[k] < 0 || sel[k] >= md->n || s->omega2[k] != md->mode[sel[k]].omega * md->mode[sel[k]].omega) return 0;
    return s->rod == rod && s->setup_shape == md->shape && s->setup_nsel == nsel && !s->qm && !o->manifold &&
           !memcmp(s->setup_sel, sel, (size_t)nsel * sizeof(int)) && o->nextra <= 0 && a->nextra <= 0 &&
           !memcmp(s->q_eq, q_eq, (size_t)rod->nq * sizeof(double)) && a->derivatives == o->derivatives &&
           a->weight_vector == o->weight_vector && !o->wind_vector && !a->wind_vector &&
           a->deflation_tol == o->deflation_tol && a->derivative_floor == o->derivative_floor && a->fd_step_m == o->fd_step_m && a->hyper == o->hyper &&
           a->hyper_tol == o->hyper_tol && a->hyper_twist == o->hyper_twist && a->hyper_snapshots == o->hyper_snapshots &&
           a->hyper_snapshots_fine == o->hyper_snapshots_fine;
}

/* A model on a copy of the set-up s (its factorization of K0 borrowed), not finished. */
static gal_rom *copy_setup(const gal_rom *s)
{
    gal_rom *m = calloc(1, sizeof *m);
    if (!m) { gal_error(GAL_ENOMEM, "reduced model: out of memory"); return NULL; }
    m->rod = s->rod, m->o = s->o, m->ndof = s->ndof, m->nq = s->nq, m->r = s->r, m->nmodes = s->nmodes;
    m->fscale = s->fscale, m->ffloor = s->ffloor, m->ufloor = s->ufloor;
    m->setup_shape = s->setup_shape, m->setup_nsel = s->setup_nsel;
    int n = m->ndof, r = m->r, st = alloc_state(m, r);
    m->omega2 = malloc((size_t)m->nmodes * sizeof(double)), m->setup_sel = malloc((size_t)s->setup_nsel * sizeof(int));
    if (!st && (!m->omega2 || !m->setup_sel)) st = gal_error(GAL_ENOMEM, "reduced model: out of memory");
    if (!st) {
        memcpy(m->V, s->V, (size_t)n * r * sizeof(double)), memcpy(m->K0r, s->K0r, (size_t)r * r * sizeof(double));
        memcpy(m->q_eq, s->q_eq, (size_t)m->nq * sizeof(double));
        memcpy(m->omega2, s->omega2, (size_t)m->nmodes * sizeof(double));
        memcpy(m->setup_sel, s->setup_sel, (size_t)s->setup_nsel * sizeof(int));
        memcpy(m->K0->val, s->K0->val, (size_t)s->K0->colptr[s->K0->n] * sizeof(double));
        m->chol0 = s->chol0, m->setup_reused = 1;
        if (s->hyper) st = gal_rom_hyper_copy(m, s);
    }
    return st ? gal_rom_free(m) : m;
}

gal_rom *gal_rom_setup_alloc(const gal_rod *rod, const double *q_eq, const gal_modes *md, const int *sel, int nsel,
                             const gal_rom_opts *o)
{
    if (nsel < 1) { gal_error(GAL_EINPUT, "reduced model: no modes selected"); return NULL; }
    if (o && o->manifold) { gal_error(GAL_EINPUT, "reduced model: the quadratic manifold has no shared set-up"); return NULL; }
    gal_rom *m = calloc(1, sizeof *m);
    if (!m) { gal_error(GAL_ENOMEM, "reduced model: out of memory"); return NULL; }
    m->rod = rod;
    if (o) m->o = *o;
    else gal_rom_default_opts(&m->o);
    m->o.setup = NULL, m->o.damping = NULL;
    return build_setup(m, q_eq, md, sel, nsel) ? gal_rom_free(m) : m;
}

gal_rom *gal_rom_alloc(const gal_rod *rod, const double *q_eq, const gal_modes *md, const int *sel, int nsel,
                       const gal_rom_opts *o, const gal_force *force)
{
    double t0 = gal_wall_time();
    if (nsel < 1) { gal_error(GAL_EINPUT, "reduced model: no modes selected"); return NULL; }
    gal_rom_opts od;
    if (!o) gal_rom_default_opts(&od), o = &od;
    gal_rom *m = NULL;
    int trained = 0; /* the loads' sample trained with the rod's */
    if (o->setup && setup_matches(o->setup, rod, q_eq, md, sel, nsel, o)) {
        if (!(m = copy_setup(o->setup))) return NULL;
    } else {
        if (!(m = calloc(1, sizeof *m))) { gal_error(GAL_ENOMEM, "reduced model: out of memory"); return NULL; }
        m->rod = rod, m->o = *o;
        if (force) m->force = *force; /* both samples from one pass over the training states */
        if (build_setup(m, q_eq, md, sel, nsel)) return gal_rom_free(m);
        trained = 1;
    }
    return finish(m, o, force, t0, trained) ? gal_rom_free(m) : m;
}
