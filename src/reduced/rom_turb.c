/* rom_turb.c: the reduced model's basis in turbulent wind (rom_turb.h): the static responses
 * K0^-1 F(t, q_eq, 0) to the loads the generated wind field will apply, less what the basis holds,
 * compressed by a POD in the mass norm, the twist's part and the translations' apart. */
#include "gallop/reduced/rom_turb.h"
#include "gallop/base/core.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/chol.h"

void dgemm_(const char *ta, const char *tb, const int *m, const int *n, const int *k, const double *alpha,
            const double *a, const int *lda, const double *b, const int *ldb, const double *beta, double *c,
            const int *ldc);
void dsyev_(const char *jobz, const char *uplo, const int *n, double *a, const int *lda, double *w, double *work,
            const int *lwork, int *info);

void gal_rom_turb_default_opts(gal_rom_turb_opts *o)
{
    memset(o, 0, sizeof *o);
    o->sample_s = 0.5;
    o->energy = 1e-3;
    o->max_vectors = 6;
}

/* 1 when free dof d is a twist */
static void twist_mask(const gal_rod *rod, unsigned char *tw)
{
    memset(tw, 0, (size_t)rod->ndof);
    if (rod->p.torsion)
        for (int j = 0; j < rod->p.elements; j++) {
            int d = rod->dof[3 * rod->nn + j];
            if (d >= 0) tw[d] = 1;
        }
}

/* D (n x ns) less its part in V (n x r, V^T M V = I): D -= V (V^T M D), twice; MD: n x ns scratch,
 * P: r x ns scratch. */
static void project_out(const gal_rom *m, double *D, int ns, double *MD, double *P)
{
    int n = m->ndof, r = m->r;
    double one = 1, zero = 0, mone = -1;
    for (int pass = 0; pass < 2 && r > 0; pass++) {
        for (int k = 0; k < ns; k++) gal_rod_mass_mult(m->rod, D + (size_t)k * n, MD + (size_t)k * n);
        dgemm_("T", "N", &r, &ns, &n, &one, m->V, &n, MD, &n, &zero, P, &r);
        dgemm_("N", "N", &n, &ns, &r, &mone, m->V, &n, P, &r, &one, D, &n);
    }
}

/* The snapshots: the static responses to the loads at the equilibrium at rest, every o->sample_s,
 * into D (n x ns); their squared mass norm per part (0 translations, 1 twist) added to whole. */
static int snapshots(const gal_rom *m, const gal_force *F, const gal_rom_turb_opts *o, int ns, const unsigned char *tw,
                     double *D, double whole[2])
{
    const gal_rod *rod = m->rod;
    int n = m->ndof, nq = m->nq, st = GAL_OK;
    double *fq = malloc((size_t)2 * nq * sizeof(double)), *v0 = fq + nq;
    if (!fq) return gal_error(GAL_ENOMEM, "reduced model: out of memory for the wind's load shapes");
    memset(v0, 0, (size_t)nq * sizeof(double));
    for (int k = 0; k < ns && !st; k++) {
        double *d = D + (size_t)k * n;
        memset(fq, 0, (size_t)nq * sizeof(double));
        if ((st = F->eval(F->ctx, o->t0 + k * o->sample_s, m->q_eq, v0, fq))) break;
        gal_rod_gather(rod, fq, d);
        if ((st = gal_chol_solve(m->chol0, d, d))) break;
        for (int i = 0; i < n; i++) whole[tw[i]] += rod->mdiag[i] * d[i] * d[i];
    }
    free(fq);
    return st;
}

/* The symmetric eigenproblem of the k x k matrix G in place (its eigenvectors, ascending
 * eigenvalues into ev). */
static int eigen(double *G, int k, double *ev)
{
    int info = 0, lwork = -1;
    double wq = 0, *work;
    dsyev_("V", "U", &k, G, &k, ev, &wq, &lwork, &info);
    lwork = (int)wq;
    if (info || !(work = malloc((size_t)(lwork > 1 ? lwork : 1) * sizeof(double))))
        return info ? gal_error(GAL_EFAIL, "reduced model: the wind's load shapes: dsyev failed (%d)", info)
                    : gal_error(GAL_ENOMEM, "reduced model: out of memory for the wind's load shapes");
    dsyev_("V", "U", &k, G, &k, ev, work, &lwork, &info);
    free(work);
    return info ? gal_error(GAL_EFAIL, "reduced model: the wind's load shapes: dsyev failed (%d)", info) : GAL_OK;
}

/* Append to E (n x *ne) the POD shapes of the part `part` of D: W = Mdiag^1/2 D over the part's np
 * dofs (np x ns); the eigenvectors of the smaller of W W^T (np x np: the shapes themselves) and
 * W^T W (ns x ns: the method of snapshots, shape D a) by decreasing eigenvalue, until what is left is
 * at most o->energy of whole, at most o->max_vectors; each M-normalized (so that the set-up's cost
 * does not grow as ns^3 with the run's length, nor as np^3 with the mesh). G: scratch of
 * min(np, ns)^2, W: of np ns. */
static int pod_part(const gal_rom *m, const double *D, int ns, const unsigned char *tw, int part, double whole,
                    const gal_rom_turb_opts *o, double *E, int *ne, double *G, double *W, double *out, double *left)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof, np = 0, st;
    int *idx = malloc((size_t)n * sizeof(int));
    double *ev = malloc((size_t)(ns > n ? ns : n) * sizeof(double)), one = 1, zero = 0, tot = 0;
    if (!idx || !ev) { free(idx); free(ev); return gal_error(GAL_ENOMEM, "reduced model: out of memory for the wind's load shapes"); }
    for (int i = 0; i < n; i++)
        if (tw[i] == part) idx[np++] = i;
    for (int k = 0; k < ns; k++)
        for (int a = 0; a < np; a++) W[(size_t)k * np + a] = sqrt(rod->mdiag[idx[a]]) * D[(size_t)k * n + idx[a]];
    int byshape = np <= ns, k = byshape ? np : ns;
    if (byshape) dgemm_("N", "T", &np, &np, &ns, &one, W, &np, W, &np, &zero, G, &np);
    else dgemm_("T", "N", &ns, &ns, &np, &one, W, &np, W, &np, &zero, G, &ns);
    for (int c = 0; c < k; c++) tot += G[(size_t)c * k + c];
    *out = whole > 0 ? tot / whole : 0;
    st = k > 0 ? eigen(G, k, ev) : GAL_OK;
    double rest = tot;
    for (int c = k - 1, kept = 0; !st && c >= 0 && kept < o->max_vectors && rest > o->energy * whole; c--, kept++) {
        if (!(ev[c] > 0)) break;
        double *e = E + (size_t)*ne * n, s = 0;
        memset(e, 0, (size_t)n * sizeof(double));
        for (int a = 0; a < np; a++) {
            double v = 0;
            if (byshape) v = G[(size_t)c * k + a] / sqrt(rod->mdiag[idx[a]]);
            else
                for (int j = 0; j < ns; j++) v += D[(size_t)j * n + idx[a]] * G[(size_t)c * k + j];
            e[idx[a]] = v, s += rod->mdiag[idx[a]] * v * v;
        }
        if (!(s > 0)) break;
        for (int a = 0; a < np; a++) e[idx[a]] /= sqrt(s);
        (*ne)++, rest -= ev[c];
    }
    *left = whole > 0 ? fmax(rest, 0) / whole : 0;
    free(idx); free(ev);
    return st;
}

int gal_rom_turb_vectors(const gal_rom *m, const gal_force *force, const gal_rom_turb_opts *o, double **extra,
                         int *nextra, gal_rom_turb_info *info)
{
    gal_rom_turb_opts od;
    if (!o) gal_rom_turb_default_opts(&od), o = &od;
    gal_rom_turb_info in;
    memset(&in, 0, sizeof in);
    *extra = NULL, *nextra = 0;
    if (!force || !force->eval || !(o->sample_s > 0) || !(o->t1 >= o->t0) || o->max_vectors < 1) {
        if (info) *info = in;
        return GAL_OK;
    }
    int n = m->ndof, ns = (int)floor((o->t1 - o->t0) / o->sample_s + 1e-9) + 1, r = m->r, ne = 0, st;
    size_t big = (size_t)n * ns;
    unsigned char *tw = malloc((size_t)n);
    double *D = malloc(big * sizeof(double)), *W = malloc(big * sizeof(double));
    size_t g = (size_t)(n < ns ? n : ns) * (n < ns ? n : ns) + (size_t)r * (ns > 12 ? ns : 12); /* pod_part, project_out */
    double *G = malloc(g * sizeof(double));
    double *E = malloc((size_t)2 * o->max_vectors * n * sizeof(double)), whole[2] = {0, 0};
    if (!tw || !D || !W || !G || !E) st = gal_error(GAL_ENOMEM, "reduced model: out of memory for the wind's load shapes");
    else {
        twist_mask(m->rod, tw);
        st = snapshots(m, force, o, ns, tw, D, whole);
    }
    if (!st) project_out(m, D, ns, W, G);
    int ntrans = 0;
    for (int part = 0; part < 2 && !st; part++) {
        st = pod_part(m, D, ns, tw, part, whole[part], o, E, &ne, G, W, &in.outside[part], &in.left[part]);
        if (part == 0) ntrans = ne;
    }
    in.snapshots = ns;
    /* the kept shapes M-orthonormal and M-orthogonal to V (the parts are disjoint but M may couple
     * them: ice eccentricity): project out V again, then Gram-Schmidt among them */
    if (!st && ne > 0) {
        project_out(m, E, ne, W, G);
        int k = 0;
        for (int c = 0; c < ne; c++) {
            double *e = E + (size_t)c * n;
            for (int pass = 0; pass < 2; pass++)
                for (int j = 0; j < k; j++) {
                    const double *f = E + (size_t)j * n;
                    gal_rod_mass_mult(m->rod, f, W);
                    double s = 0;
                    for (int i = 0; i < n; i++) s += W[i] * e[i];
                    for (int i = 0; i < n; i++) e[i] -= s * f[i];
                }
            gal_rod_mass_mult(m->rod, e, W);
            double s = 0;
            for (int i = 0; i < n; i++) s += W[i] * e[i];
            if (!(s > 1e-12)) continue;
            double *dst = E + (size_t)k * n;
            for (int i = 0; i < n; i++) dst[i] = e[i] / sqrt(s);
            in.vectors[c < ntrans ? 0 : 1]++;
            k++;
        }
        ne = k;
    }
    free(tw); free(D); free(W); free(G);
    if (st || ne == 0) free(E), E = NULL, ne = 0;
    *extra = E, *nextra = ne;
    if (info) *info = in;
    return st;
}

int gal_rom_turb_basis(const gal_rom *m, const gal_force *force, double duration, double **extra, int *nextra)
{
    gal_rom_turb_opts o;
    gal_rom_turb_default_opts(&o);
    o.t1 = duration;
    return gal_rom_turb_vectors(m, force, &o, extra, nextra, NULL);
}
