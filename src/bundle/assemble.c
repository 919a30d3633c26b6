/* assemble.c: the explicit bundle's energy, gradient, tangent and mass (bundle.h): each rod's
 * through the map T (T^T g, T^T K T, T^T M T), the spacers' weight, mass and inertia, and the
 * geometric stiffness of the spacers' rotation. */
#include "gallop/bundle/bundle.h"
#include "gallop/base/core.h"
#include "bundle_impl.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef gal_bundle_sink sink;
#define put gal_bundle_put

void gal_bundle_put(gal_bundle_sink *k, int I, int J, double v)
{
    if (I > J) { int t = I; I = J; J = t; }
    if (k->pairs) { k->pairs[k->np++] = (long)J * k->ndof + I; return; }
    int p = gal_csc_find(k->G, I, J);
    if (p >= 0) k->G->val[p] += v;
}

/* G += T_r^T A T_r for rod r's symmetric A (upper triangle): an off-diagonal entry (i, j) of A is
 * A(i, j) and A(j, i), whose images on G's diagonal count twice. */
static void congruence(const gal_bundle *b, int r, const gal_csc *A, sink *k)
{
    const int *cnt = b->tcnt[r], *idx = b->tidx[r];
    const double *tv = b->tval[r];
    for (int j = 0; j < A->n; j++)
        for (int p = A->colptr[j]; p < A->colptr[j + 1]; p++) {
            int i = A->rowind[p];
            double v = A->val[p];
            if (!k->pairs && v == 0) continue;
            for (int a = 0; a < cnt[i]; a++)
                for (int c = i == j ? a : 0; c < cnt[j]; c++) {
                    int I = idx[4 * i + a], J = idx[4 * j + c];
                    double w = v * tv[4 * i + a] * tv[4 * j + c];
                    put(k, I, J, i != j && I == J ? 2 * w : w);
                }
        }
}

static int cmp_long(const void *a, const void *b)
{
    long x = *(const long *)a, y = *(const long *)b;
    return (x > y) - (x < y);
}

/* The system's pattern: the rods' through T, the spacers' 6 x 6 blocks, the flexible spacers' arms. */
int gal_bundle_pattern(gal_bundle *b)
{
    long cap = 36L * b->ns + b->ndof + 144L * b->ns * b->n;
    for (int r = 0; r < b->n; r++) cap += 16L * b->rod[r]->K->nnz;
    sink k = {NULL, malloc((size_t)cap * sizeof(long)), 0, b->ndof};
    gal_csc *G = calloc(1, sizeof *G);
    if (!k.pairs || !G) { free(k.pairs), free(G); return GAL_ENOMEM; }
    for (int r = 0; r < b->n; r++) congruence(b, r, b->rod[r]->K, &k);
    for (int sp = 0; sp < b->ns; sp++)
        for (int a = 0; a < 3 + b->nrot; a++)
            for (int c = a; c < 3 + b->nrot; c++) put(&k, b->sp0 + (3 + b->nrot) * sp + a, b->sp0 + (3 + b->nrot) * sp + c, 0);
    for (int d = 0; d < b->ndof; d++) put(&k, d, d, 0);
    if (b->bp.spacer_stiffness > 0) gal_bundle_arms(b, b->state, NULL, &k);
    qsort(k.pairs, (size_t)k.np, sizeof(long), cmp_long);
    long nu = 0;
    for (long p = 0; p < k.np; p++)
        if (nu == 0 || k.pairs[p] != k.pairs[nu - 1]) k.pairs[nu++] = k.pairs[p];
    int n = b->ndof;
    G->n = n, G->nnz = (int)nu;
    G->colptr = calloc((size_t)n + 1, sizeof(int)), G->rowind = malloc((size_t)nu * sizeof(int));
    G->val = calloc((size_t)nu, sizeof(double)), G->diag = malloc((size_t)n * sizeof(int));
    if (!G->colptr || !G->rowind || !G->val || !G->diag) { free(k.pairs); gal_csc_free(G); return GAL_ENOMEM; }
    for (long p = 0; p < nu; p++) {
        int J = (int)(k.pairs[p] / n), I = (int)(k.pairs[p] % n);
        G->colptr[J + 1]++;
        G->rowind[p] = I;
        if (I == J) G->diag[J] = (int)p;
    }
    for (int j = 0; j < n; j++) G->colptr[j + 1] += G->colptr[j];
    free(k.pairs);
    b->K = G;
    b->M = gal_csc_clone(G);
    return b->M ? GAL_OK : GAL_ENOMEM;
}

/* E^T H E over the spacer's rotation dofs (H 3 x 3 on the rotation vector). */
void gal_bundle_put_rot(const gal_bundle *b, const double *s, int sp, const double H[3][3], gal_bundle_sink *k)
{
    double E[3][3];
    int nr = gal_bundle_basis(b, s, sp, E), ph = b->sp0 + (3 + b->nrot) * sp + 3;
    for (int i = 0; i < nr; i++)
        for (int j = i; j < nr; j++) {
            double v = 0;
            for (int a = 0; a < 3; a++)
                for (int c = 0; c < 3; c++) v += E[i][a] * H[a][c] * E[j][c];
            put(k, ph + i, ph + j, v);
        }
}

/* The geometric stiffness of spacer sp's rotation from the force f (the energy's gradient) on the
 * point x = u + exp(phi x) p of sub-conductor r (p = R off_r): d2x/dphi_a dphi_b at phi = 0 is
 * (e_a (e_b . p) + e_b (e_a . p)) / 2 - p delta_ab, so H_ab = (f_a p_b + f_b p_a) / 2 - (f . p) delta_ab. */
void gal_bundle_geometric(const gal_bundle *b, const double *s, int sp, int r, const double f[3], gal_bundle_sink *k)
{
    const double *R = SP_R(b, s, sp);
    double p[3], gp = 0, H[3][3];
    for (int a = 0; a < 3; a++)
        p[a] = R[3 * a] * b->off[r][0] + R[3 * a + 1] * b->off[r][1] + R[3 * a + 2] * b->off[r][2];
    for (int a = 0; a < 3; a++) gp += f[a] * p[a];
    for (int a = 0; a < 3; a++)
        for (int c = 0; c < 3; c++) H[a][c] = 0.5 * (f[a] * p[c] + f[c] * p[a]) - (a == c) * gp;
    gal_bundle_put_rot(b, s, sp, H, k);
}

/* Rigid spacers: the geometric stiffness from rod r's forces g at their nodes. */
static void geometric(gal_bundle *b, int r, const double *s, const double *g)
{
    sink k = {b->K, NULL, 0, b->ndof};
    for (int sp = 0; sp < b->ns; sp++) gal_bundle_geometric(b, s, sp, r, g + 3 * b->spnode[sp], &k);
}

/* The spacers: weight (energy and gradient), mass and inertia R diag(J, J/2, J/2) R^T (a plane
 * frame: about the axes across, half its inertia about the bundle's axis). */
static void spacers(gal_bundle *b, const double *s, double *U, int tangent)
{
    double m = b->bp.spacer_mass, J = b->bp.spacer_inertia, g = b->rod[0]->p.gravity;
    double Jb[3] = {J, 0.5 * J, 0.5 * J};
    sink k = {b->M, NULL, 0, b->ndof};
    for (int sp = 0; sp < b->ns; sp++) {
        int u = b->sp0 + (3 + b->nrot) * sp;
        *U += m * g * SP_U(b, s, sp)[2];
        b->grad[u + 2] += m * g;
        if (!tangent) continue;
        const double *R = SP_R(b, s, sp);
        double H[3][3];
        for (int a = 0; a < 3; a++) {
            put(&k, u + a, u + a, m);
            for (int c = 0; c < 3; c++) {
                H[a][c] = 0;
                for (int l = 0; l < 3; l++) H[a][c] += R[3 * a + l] * Jb[l] * R[3 * c + l];
            }
        }
        gal_bundle_put_rot(b, s, sp, H, &k);
    }
}

int gal_bundle_eval(gal_bundle *b, const double *s, double *energy, int tangent)
{
    if (!s) s = b->state;
    gal_bundle_map_values(b, s);
    memset(b->grad, 0, (size_t)b->ndof * sizeof(double));
    if (tangent) {
        memset(b->K->val, 0, (size_t)b->K->nnz * sizeof(double));
        memset(b->M->val, 0, (size_t)b->M->nnz * sizeof(double));
    }
    double E = 0;
    for (int r = 0; r < b->n; r++) {
        const gal_rod *rod = b->rod[r];
        double U;
        int st = gal_rod_eval(rod, s + (size_t)r * rod->nq, &U, b->gq, tangent ? b->Kr[r] : NULL);
        if (st) return st;
        E += U;
        for (int d = 0; d < rod->ndof; d++) {
            double v = b->gq[rod->free_q[d]];
            for (int e = 0; e < b->tcnt[r][d]; e++) b->grad[b->tidx[r][4 * d + e]] += b->tval[r][4 * d + e] * v;
        }
        if (tangent) {
            sink kk = {b->K, NULL, 0, b->ndof}, km = {b->M, NULL, 0, b->ndof};
            congruence(b, r, b->Kr[r], &kk);
            congruence(b, r, rod->M, &km);
            if (!(b->bp.spacer_stiffness > 0)) geometric(b, r, s, b->gq);
        }
    }
    spacers(b, s, &E, tangent);
    if (b->bp.spacer_stiffness > 0) {
        sink kk = {b->K, NULL, 0, b->ndof};
        E += gal_bundle_arms(b, s, b->grad, tangent ? &kk : NULL);
    }
    if (energy) *energy = E;
    return GAL_OK;
}
