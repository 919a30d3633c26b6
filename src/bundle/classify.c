/* classify.c: a bundle mode's family from the bundle's kinematics (bundle.h). At each station the
 * sub-conductors' displacements d_k are split into the translation of their centroid c (vertical:
 * in the span's plane normal to the axis; horizontal: across it; axial: along it), the rigid
 * rotation psi t x p_k about the axis t (p_k the sub-conductor's offset from the centroid; psi the
 * least-squares fit) and the rest (relative motion: subspan). The three parts are orthogonal in the
 * lumped mass (sum_k of each part against another vanishes), so their kinetic energies add up to
 * the sub-conductors'; the sub-conductors' own twist and the spacers' rotation count as torsional,
 * the spacers' translation with the centroid's. The family is the largest share. */
#include "gallop/bundle/bundle.h"
#include "gallop/base/core.h"
#include "gallop/base/vec3.h"
#include "bundle_impl.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>


/* The centroid of the sub-conductors at node i of the equilibrium. */
static void centroid(const gal_bundle *b, int i, double X[3])
{
    X[0] = X[1] = X[2] = 0;
    for (int r = 0; r < b->n; r++)
        for (int k = 0; k < 3; k++) X[k] += b->state[(size_t)r * b->rod[0]->nq + 3 * i + k] / b->n;
}

/* The normal of the span's plane (chord x mid-span offset of the centroid line; y when straight). */
static void plane_normal(const gal_bundle *b, double bn[3])
{
    double X0[3], X1[3], Xm[3];
    centroid(b, 0, X0), centroid(b, b->nn - 1, X1), centroid(b, b->nn / 2, Xm);
    double ch[3], off[3];
    for (int k = 0; k < 3; k++) ch[k] = X1[k] - X0[k], off[k] = Xm[k] - 0.5 * (X0[k] + X1[k]);
    gal_cross3(ch, off, bn);
    double nb = gal_norm3(bn);
    if (nb < 1e-9 * gal_dot3(ch, ch)) bn[0] = 0, bn[1] = 1, bn[2] = 0;
    else for (int k = 0; k < 3; k++) bn[k] /= nb;
}

/* Node i's parts: adds the kinetic energies (per unit node mass) to ke, the centroid's components
 * and psi to comp (vertical, horizontal, psi, axial), the rest to rem (3 n). */
static void station(const gal_bundle *b, const double *full, int i, const double bn[3], double *ke,
                    double comp[4], double *rem, double tn[3])
{
    int nel = b->nn - 1, a = i > 0 ? i - 1 : 0, c = i < nel ? i + 1 : nel, n = b->n;
    size_t nq = (size_t)b->rod[0]->nq;
    double Xa[3], Xc[3], X[3], t[3], nv[3], cb[3] = {0, 0, 0}, num = 0, den = 0;
    centroid(b, a, Xa), centroid(b, c, Xc), centroid(b, i, X);
    for (int k = 0; k < 3; k++) t[k] = Xc[k] - Xa[k];
    double nt = gal_norm3(t);
    for (int k = 0; k < 3; k++) t[k] /= nt, tn[k] = t[k];
    gal_cross3(t, bn, nv);
    for (int r = 0; r < n; r++)
        for (int k = 0; k < 3; k++) cb[k] += full[r * nq + 3 * i + k] / n;
    for (int r = 0; r < n; r++) {
        double p[3], d[3], pxd[3];
        for (int k = 0; k < 3; k++) p[k] = b->state[r * nq + 3 * i + k] - X[k], d[k] = full[r * nq + 3 * i + k] - cb[k];
        gal_cross3(p, d, pxd);
        double pt = gal_dot3(p, t);
        num += gal_dot3(pxd, t), den += gal_dot3(p, p) - pt * pt;
    }
    double psi = den > 0 ? num / den : 0;
    for (int r = 0; r < n; r++) {
        double p[3], txp[3];
        for (int k = 0; k < 3; k++) p[k] = b->state[r * nq + 3 * i + k] - X[k];
        gal_cross3(t, p, txp);
        for (int k = 0; k < 3; k++) {
            double rot = psi * txp[k], rr = full[r * nq + 3 * i + k] - cb[k] - rot;
            rem[3 * r + k] = rr;
            ke[GAL_FAMILY_TORSIONAL] += rot * rot;
            ke[GAL_FAMILY_SUBSPAN] += rr * rr;
        }
    }
    comp[0] = gal_dot3(cb, nv), comp[1] = gal_dot3(cb, bn), comp[2] = psi, comp[3] = gal_dot3(cb, t);
    ke[GAL_FAMILY_VERTICAL] += n * comp[0] * comp[0];
    ke[GAL_FAMILY_HORIZONTAL] += n * comp[1] * comp[1];
    ke[GAL_FAMILY_AXIAL] += n * comp[3] * comp[3];
}

/* The correlation of the dominant family's component with its mirror image about mid-span (1:
 * symmetric, -1: antisymmetric). */
static double mirror(const gal_bundle *b, int fam, const double *comp, const double *rem)
{
    int nn = b->nn, n = b->n;
    double num = 0, den = 0;
    for (int i = 0; i < nn; i++) {
        int j = nn - 1 - i;
        if (fam == GAL_FAMILY_SUBSPAN) {
            for (int r = 0; r < n; r++)
                for (int k = 0; k < 3; k++) {
                    double x = rem[3 * (n * i + r) + k];
                    num += x * (k == 0 ? -1 : 1) * rem[3 * (n * j + r) + k], den += x * x;
                }
        } else {
            double sg = fam == GAL_FAMILY_AXIAL ? -1.0 : 1.0;
            num += comp[4 * i + fam] * sg * comp[4 * j + fam], den += comp[4 * i + fam] * comp[4 * i + fam];
        }
    }
    return den > 0 ? num / den : 0;
}

size_t gal_bundle_classify_scratch(const gal_bundle *b)
{
    return (size_t)b->n * b->rod[0]->nq + b->rod[0]->ndof + (size_t)4 * b->nn + (size_t)3 * b->n * b->nn;
}

void gal_bundle_classify(const gal_bundle *b, const double *z, double *full, gal_mode *md)
{
    int n = b->n, nn = b->nn, nq = b->rod[0]->nq, nd = b->rod[0]->ndof;
    memset(full, 0, gal_bundle_classify_scratch(b) * sizeof(double));
    double *fr = full + (size_t)n * nq, *comp = fr + nd, *rem = comp + 4 * nn;
    for (int r = 0; r < n; r++) {
        gal_bundle_map(b, r, z, fr);
        gal_rod_scatter(b->rod[r], fr, full + (size_t)r * nq);
    }
    double bn[3], ke[GAL_FAMILY_COUNT] = {0}, t[3];
    plane_normal(b, bn);
    for (int i = 0; i < nn; i++) {
        double k1[GAL_FAMILY_COUNT] = {0}, m = b->rod[0]->node_mass[i];
        station(b, full, i, bn, k1, comp + 4 * i, rem + (size_t)3 * n * i, t);
        for (int f = 0; f < GAL_FAMILY_COUNT; f++) ke[f] += m * k1[f];
        int sp = b->spat[i];
        if (sp < 0) continue;
        const double *u = z + b->sp0 + (3 + b->nrot) * sp;
        double nv[3], w[3] = {0, 0, 0}, E[3][3], J = b->bp.spacer_inertia, ms = b->bp.spacer_mass;
        int nr = gal_bundle_basis(b, b->state, sp, E);
        for (int j = 0; j < nr; j++)
            for (int k = 0; k < 3; k++) w[k] += u[3 + j] * E[j][k];
        double wt = gal_dot3(w, t);
        gal_cross3(t, bn, nv);
        ke[GAL_FAMILY_VERTICAL] += ms * gal_dot3(u, nv) * gal_dot3(u, nv);
        ke[GAL_FAMILY_HORIZONTAL] += ms * gal_dot3(u, bn) * gal_dot3(u, bn);
        ke[GAL_FAMILY_AXIAL] += ms * gal_dot3(u, t) * gal_dot3(u, t);
        ke[GAL_FAMILY_TORSIONAL] += J * wt * wt + 0.5 * J * (gal_dot3(w, w) - wt * wt);
    }
    for (int r = 0; r < n; r++)
        for (int j = 0; j < nn - 1; j++) {
            double th = full[(size_t)r * nq + 3 * nn + j];
            ke[GAL_FAMILY_TORSIONAL] += b->rod[r]->edge_inertia[j] * th * th;
        }
    double tot = 0;
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) tot += ke[f];
    int fam = 0;
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) {
        md->share[f] = tot > 0 ? ke[f] / tot : 0;
        if (md->share[f] > md->share[fam]) fam = f;
    }
    md->family = (gal_family)fam;
    double r = mirror(b, fam, comp, rem);
    md->symmetry = r > 0.9 ? GAL_SYM_SYMMETRIC : r < -0.9 ? GAL_SYM_ANTISYMMETRIC : GAL_SYM_NONE;
    md->parity = r >= 0 ? GAL_SYM_SYMMETRIC : GAL_SYM_ANTISYMMETRIC; /* the larger part's */
}
