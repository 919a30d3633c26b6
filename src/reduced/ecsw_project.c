/* ecsw_project.c: the projections of whole-rod vectors on the reduced basis that the training and
 * the checks share (hyper.h): the free part of one or two gathered vectors on a basis, the exact
 * reduced force at a reduced state, and a batch of training states' targets on the model's basis.
 * Each sum runs over the entries in order, so that every one of them has the round-off of one
 * column at a time. */
#include "gallop/reduced/ecsw.h"
#include "gallop/base/core.h"

#include "reduced/hyper.h"

/* b0 = B^T (free part of g0) over B's r columns (and b1 of g1 when given), four columns at a time
 * in one pass over the entries; each sum runs over the entries in order, so the round-off is that
 * of one column at a time (gal_rom_exact_force's). */
static void project_free(const gal_rom *m, const double *B, const double *g0, const double *g1, double *b0, double *b1)
{
    const int *fq = m->rod->free_q;
    int n = m->ndof, r = m->r, k = 0;
    for (; k + 4 <= r; k += 4) {
        const double *c0 = B + (size_t)k * n, *c1 = c0 + n, *c2 = c1 + n, *c3 = c2 + n;
        double s0 = 0, s1 = 0, s2 = 0, s3 = 0, t0 = 0, t1 = 0, t2 = 0, t3 = 0;
        for (int d = 0; d < n; d++) {
            double a = g0[fq[d]];
            s0 += c0[d] * a, s1 += c1[d] * a, s2 += c2[d] * a, s3 += c3[d] * a;
            if (!g1) continue;
            double e = g1[fq[d]];
            t0 += c0[d] * e, t1 += c1[d] * e, t2 += c2[d] * e, t3 += c3[d] * e;
        }
        b0[k] = s0, b0[k + 1] = s1, b0[k + 2] = s2, b0[k + 3] = s3;
        if (g1) b1[k] = t0, b1[k + 1] = t1, b1[k + 2] = t2, b1[k + 3] = t3;
    }
    for (; k < r; k++) {
        const double *c0 = B + (size_t)k * n;
        double s0 = 0, t0 = 0;
        for (int d = 0; d < n; d++) {
            s0 += c0[d] * g0[fq[d]];
            if (g1) t0 += c0[d] * g1[fq[d]];
        }
        b0[k] = s0;
        if (g1) b1[k] = t0;
    }
}

void gal_rom_project_free(const gal_rom *m, const double *B, const double *g0, const double *g1, double *b0, double *b1)
{
    project_free(m, B, g0, g1, b0, b1);
}

int gal_rom_exact_force(gal_rom *m, const double *x, double *f)
{
    int st = gal_rod_eval(m->rod, gal_rom_reconstruct_q(m, x), NULL, m->gq, NULL);
    if (st) return st;
    project_free(m, gal_rom_basis_at(m, x), m->gq, NULL, f, NULL);
    return GAL_OK;
}

/* b[s r + k] = V_k^T G_s for the ns gathered vectors G_s (n each) and V's r columns: four columns
 * against two states at a time (eight independent sums), in one pass over those columns (V read
 * once, not once a state); each sum runs over the entries in order, the round-off of
 * project_free's (gal_rom_exact_force's). */
void gal_rom_project_states(const gal_rom *m, const double *G, int ns, double *b)
{
    int n = m->ndof, r = m->r, k = 0;
    for (; k + 4 <= r; k += 4) {
        const double *c0 = m->V + (size_t)k * n, *c1 = c0 + n, *c2 = c1 + n, *c3 = c2 + n;
        for (int s = 0; s < ns; s += 2) {
            const double *g = G + (size_t)s * n, *h = s + 1 < ns ? g + n : g; /* an odd last: twice */
            double s0 = 0, s1 = 0, s2 = 0, s3 = 0, t0 = 0, t1 = 0, t2 = 0, t3 = 0;
            for (int d = 0; d < n; d++) {
                double a = g[d], e = h[d];
                s0 += c0[d] * a, s1 += c1[d] * a, s2 += c2[d] * a, s3 += c3[d] * a;
                t0 += c0[d] * e, t1 += c1[d] * e, t2 += c2[d] * e, t3 += c3[d] * e;
            }
            double *bs = b + (size_t)s * r + k;
            bs[0] = s0, bs[1] = s1, bs[2] = s2, bs[3] = s3;
            if (s + 1 < ns) bs[r] = t0, bs[r + 1] = t1, bs[r + 2] = t2, bs[r + 3] = t3;
        }
    }
    for (; k < r; k++) { /* the last columns one at a time, against four states at a time */
        const double *c0 = m->V + (size_t)k * n;
        int s = 0;
        for (; s + 4 <= ns; s += 4) {
            const double *g0 = G + (size_t)s * n, *g1 = g0 + n, *g2 = g1 + n, *g3 = g2 + n;
            double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
            for (int d = 0; d < n; d++) s0 += c0[d] * g0[d], s1 += c0[d] * g1[d], s2 += c0[d] * g2[d], s3 += c0[d] * g3[d];
            b[(size_t)s * r + k] = s0, b[(size_t)(s + 1) * r + k] = s1;
            b[(size_t)(s + 2) * r + k] = s2, b[(size_t)(s + 3) * r + k] = s3;
        }
        for (; s < ns; s++) {
            const double *g = G + (size_t)s * n;
            double s0 = 0;
            for (int d = 0; d < n; d++) s0 += c0[d] * g[d];
            b[(size_t)s * r + k] = s0;
        }
    }
}
