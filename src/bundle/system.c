/* system.c: the explicit bundle's assembled system (bundle.h): the rods on the bundle circle, the
 * spacers' state, the elimination of the spacer nodes (the map T from the system's dofs to each
 * rod's free dofs), the sparse patterns, the spacers' rotation steps. */
#include "gallop/bundle/bundle.h"
#include "gallop/base/core.h"
#include "bundle_impl.h"
#include "gallop/base/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int gal_bundle_elements(int elements, int spacers)
{
    int g = spacers + 1, per = (elements + g - 1) / g;
    return (per < 2 ? 2 : per) * g;
}

/* Spacer sp's node on a mesh of N elements (bp->positions given). */
static int snap_node(const gal_bundle_params *bp, int sp, int N)
{
    return (int)floor(bp->positions[sp] * N + 0.5);
}

/* 1 when every spacer of bp->positions sits within GAL_BUNDLE_SNAP of a node of N elements, with at
 * least 2 elements in every sub-span (the supports at nodes 0 and N). */
static int snap_fits(const gal_bundle_params *bp, int N)
{
    int prev = 0;
    for (int sp = 0; sp <= bp->spacers; sp++) {
        int k = sp < bp->spacers ? snap_node(bp, sp, N) : N;
        if (k - prev < 2) return 0;
        if (sp < bp->spacers && !(fabs((double)k / N - bp->positions[sp]) <= GAL_BUNDLE_SNAP)) return 0;
        prev = k;
    }
    return 1;
}

int gal_bundle_mesh(int elements, const gal_bundle_params *bp)
{
    if (!bp->positions || bp->spacers <= 0) return gal_bundle_elements(elements, bp->spacers);
    int top = elements > 1000 ? elements : 1000;
    for (int N = elements > 2 ? elements : 2; N <= top; N++)
        if (snap_fits(bp, N)) return N;
    return 0;
}

int gal_bundle_subspan_elements(int elements, const gal_bundle_params *bp)
{
    int N = gal_bundle_mesh(elements, bp), ns = bp->spacers, prev = 0, few = N;
    if (N <= 0 || !bp->positions || ns <= 0) return N > 0 ? N / (ns + 1) : 0;
    for (int sp = 0; sp <= ns; sp++) {
        int k = sp < ns ? snap_node(bp, sp, N) : N;
        if (k - prev < few) few = k - prev;
        prev = k;
    }
    return few;
}

gal_bundle *gal_bundle_free(gal_bundle *b)
{
    if (!b) return NULL;
    for (int r = 0; r < GAL_BUNDLE_MAX; r++) {
        gal_rod_free(b->rod[r]);
        free(b->tcnt[r]), free(b->tidx[r]), free(b->tval[r]);
        gal_csc_free(b->Kr[r]);
    }
    free(b->spnode), free(b->spat), free(b->state), free(b->gq), free(b->grad);
    gal_csc_free(b->K), gal_csc_free(b->M);
    free(b);
    return NULL;
}

/* R = exp(w x), Rodrigues' formula (row-major 3 x 3). */
void gal_bundle_expmap(const double w[3], double R[9])
{
    double th = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    double a = th > 1e-8 ? sin(th) / th : 1 - th * th / 6;
    double c = th > 1e-8 ? (1 - cos(th)) / (th * th) : 0.5 - th * th / 24;
    double K[9] = {0, -w[2], w[1], w[2], 0, -w[0], -w[1], w[0], 0};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double k2 = 0;
            for (int l = 0; l < 3; l++) k2 += K[3 * i + l] * K[3 * l + j];
            R[3 * i + j] = (i == j) + a * K[3 * i + j] + c * k2;
        }
}

/* The unit tangent of rod r at interior node i (the chord of its two edges). */
void gal_bundle_tangent(const gal_bundle *b, const double *q, int i, double t[3])
{
    double s = 0;
    for (int c = 0; c < 3; c++) t[c] = q[3 * (i + 1) + c] - q[3 * (i - 1) + c], s += t[c] * t[c];
    s = sqrt(s);
    for (int c = 0; c < 3; c++) t[c] /= s;
    (void)b;
}

/* The spacer's rotation dofs w: the rotation is sum_j w_j E_j. Three (E = I) but for a twin: the
 * rotation about the line of its two clamps moves neither sub-conductor (they are held at points,
 * their bending rotation free), so it is no dof; E are the spacer's axis and the normal to both. */
int gal_bundle_basis(const gal_bundle *b, const double *s, int sp, double E[3][3])
{
    const double *R = SP_R(b, s, sp);
    if (b->nrot == 3) {
        memset(E, 0, 9 * sizeof(double));
        E[0][0] = E[1][1] = E[2][2] = 1.0;
        return 3;
    }
    double e[3], a[3] = {R[0], R[3], R[6]}, d[3], ne = 0; /* a: the body's x axis, the bundle's */
    for (int k = 0; k < 3; k++) d[k] = b->off[1][k] - b->off[0][k];
    for (int k = 0; k < 3; k++) e[k] = R[3 * k] * d[0] + R[3 * k + 1] * d[1] + R[3 * k + 2] * d[2], ne += e[k] * e[k];
    for (int k = 0; k < 3; k++) e[k] /= sqrt(ne), E[0][k] = a[k];
    E[1][0] = e[1] * a[2] - e[2] * a[1], E[1][1] = e[2] * a[0] - e[0] * a[2], E[1][2] = e[0] * a[1] - e[1] * a[0];
    return 2;
}

/* The global indices of the map (fixed) and the number of the system's dofs. */
static void map_indices(gal_bundle *b)
{
    int nd = 0, nr = b->nrot, rigid = !(b->bp.spacer_stiffness > 0);
    for (int r = 0; r < b->n; r++) { /* the independent dofs first */
        const gal_rod *rod = b->rod[r];
        for (int d = 0; d < rod->ndof; d++) {
            int q = rod->free_q[d], dep = q < 3 * b->nn ? b->spat[q / 3] >= 0 : b->spat[q - 3 * b->nn] >= 0;
            dep = dep && rigid; /* flexible spacers: the nodes are free, tied by the arms (arms.c) */
            b->tcnt[r][d] = dep ? 0 : 1;
            if (!dep) b->tidx[r][4 * d] = nd++, b->tval[r][4 * d] = 1.0;
        }
    }
    b->sp0 = nd;
    b->ndof = nd + (3 + nr) * b->ns;
    for (int r = 0; r < b->n; r++) {
        const gal_rod *rod = b->rod[r];
        for (int d = 0; d < rod->ndof; d++) {
            int q = rod->free_q[d], *ix = b->tidx[r] + 4 * d;
            if (b->tcnt[r][d]) continue;
            if (q < 3 * b->nn) { /* x_c = u_c + (dphi x p)_c, dphi = sum_j w_j E_j */
                int u = b->sp0 + (3 + nr) * b->spat[q / 3];
                ix[0] = u + q % 3;
                for (int j = 0; j < nr; j++) ix[1 + j] = u + 3 + j;
                b->tcnt[r][d] = 1 + nr;
            } else { /* theta_i = 2 t . dphi - theta_{i-1} */
                int u = b->sp0 + (3 + nr) * b->spat[q - 3 * b->nn];
                for (int j = 0; j < nr; j++) ix[j] = u + 3 + j;
                ix[nr] = b->tidx[r][4 * rod->dof[q - 1]];
                b->tcnt[r][d] = 1 + nr;
            }
        }
    }
}

/* The map's values at state s: p = R off (the node's offset from the spacer centre), t the
 * sub-conductor's tangent at the node. */
void gal_bundle_map_values(gal_bundle *b, const double *s)
{
    for (int r = 0; r < b->n; r++) {
        const gal_rod *rod = b->rod[r];
        const double *q = s + (size_t)r * rod->nq;
        for (int d = 0; d < rod->ndof; d++) {
            int qi = rod->free_q[d];
            double *v = b->tval[r] + 4 * d, E[3][3];
            if (b->tcnt[r][d] == 1) continue;
            int node = qi < 3 * b->nn ? qi / 3 : qi - 3 * b->nn, sp = b->spat[node];
            int nr = gal_bundle_basis(b, s, sp, E);
            if (qi < 3 * b->nn) {
                const double *R = SP_R(b, s, sp);
                double p[3], exp_[3];
                int c = qi % 3;
                for (int k = 0; k < 3; k++)
                    p[k] = R[3 * k] * b->off[r][0] + R[3 * k + 1] * b->off[r][1] + R[3 * k + 2] * b->off[r][2];
                v[0] = 1.0;
                for (int j = 0; j < nr; j++) {
                    gal_cross3(E[j], p, exp_);
                    v[1 + j] = exp_[c];
                }
            } else {
                double t[3];
                gal_bundle_tangent(b, q, node, t);
                for (int j = 0; j < nr; j++) v[j] = 2 * gal_dot3(t, E[j]);
                v[nr] = -1.0;
            }
        }
    }
}

void gal_bundle_map(const gal_bundle *b, int r, const double *z, double *rod_free)
{
    const gal_rod *rod = b->rod[r];
    for (int d = 0; d < rod->ndof; d++) {
        double v = 0;
        for (int e = 0; e < b->tcnt[r][d]; e++) v += b->tval[r][4 * d + e] * z[b->tidx[r][4 * d + e]];
        rod_free[d] = v;
    }
}

void gal_bundle_map_add_t(const gal_bundle *b, int r, const double *rod_free, double *y)
{
    const gal_rod *rod = b->rod[r];
    for (int d = 0; d < rod->ndof; d++)
        for (int e = 0; e < b->tcnt[r][d]; e++) y[b->tidx[r][4 * d + e]] += b->tval[r][4 * d + e] * rod_free[d];
}

double *gal_bundle_q(const gal_bundle *b, double *s, int r)
{
    return s + (size_t)r * b->rod[0]->nq;
}

/* The dependent entries of the rods' configurations from the spacers' state. */
static void dependents(const gal_bundle *b, double *s)
{
    int nn = b->nn;
    if (b->bp.spacer_stiffness > 0) return; /* flexible: the nodes are the system's dofs */
    for (int sp = 0; sp < b->ns; sp++) {
        int i = b->spnode[sp];
        const double *u = SP_U(b, s, sp), *R = SP_R(b, s, sp), *psi = SP_PSI(b, s, sp);
        for (int r = 0; r < b->n; r++) {
            double *q = gal_bundle_q(b, s, r);
            for (int k = 0; k < 3; k++)
                q[3 * i + k] = u[k] + R[3 * k] * b->off[r][0] + R[3 * k + 1] * b->off[r][1] + R[3 * k + 2] * b->off[r][2];
            q[3 * nn + i] = 2 * psi[r] - q[3 * nn + i - 1];
        }
    }
}

void gal_bundle_step(const gal_bundle *b, const double *s, const double *dz, double alpha, double *out)
{
    if (out != s) memcpy(out, s, (size_t)b->nstate * sizeof(double));
    for (int r = 0; r < b->n; r++) {
        const gal_rod *rod = b->rod[r];
        double *q = gal_bundle_q(b, out, r);
        for (int d = 0; d < rod->ndof; d++)
            if (b->tcnt[r][d] == 1) q[rod->free_q[d]] += alpha * dz[b->tidx[r][4 * d]];
    }
    for (int sp = 0; sp < b->ns; sp++) {
        const double *z = dz + b->sp0 + (3 + b->nrot) * sp;
        double E[3][3], w[3] = {0, 0, 0}, X[9], Rn[9];
        int nr = gal_bundle_basis(b, s, sp, E); /* the basis before the step */
        for (int j = 0; j < nr; j++)
            for (int k = 0; k < 3; k++) w[k] += alpha * z[3 + j] * E[j][k];
        double *u = SP_U(b, out, sp), *R = SP_R(b, out, sp), *psi = SP_PSI(b, out, sp);
        for (int k = 0; k < 3; k++) u[k] += alpha * z[k];
        gal_bundle_expmap(w, X);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                Rn[3 * i + j] = X[3 * i] * R[j] + X[3 * i + 1] * R[3 + j] + X[3 * i + 2] * R[6 + j];
        memcpy(R, Rn, sizeof Rn);
        for (int r = 0; r < b->n; r++) { /* the tangent before the step: psi += t . dphi */
            double t[3];
            gal_bundle_tangent(b, gal_bundle_q(b, (double *)s, r), b->spnode[sp], t);
            psi[r] += gal_dot3(t, w);
        }
    }
    dependents(b, out);
}

static int alloc_arrays(gal_bundle *b)
{
    int nq = b->rod[0]->nq, nd = b->rod[0]->ndof;
    b->nstate = b->n * nq + b->ns * (12 + b->n);
    b->state = calloc((size_t)b->nstate, sizeof(double));
    b->gq = malloc((size_t)nq * sizeof(double));
    b->spnode = malloc((size_t)(b->ns + 1) * sizeof(int));
    b->spat = malloc((size_t)b->nn * sizeof(int));
    if (!b->state || !b->gq || !b->spnode || !b->spat) return GAL_ENOMEM;
    for (int r = 0; r < b->n; r++) {
        b->tcnt[r] = malloc((size_t)nd * sizeof(int));
        b->tidx[r] = malloc((size_t)4 * nd * sizeof(int));
        b->tval[r] = calloc((size_t)4 * nd, sizeof(double));
        b->Kr[r] = gal_csc_clone(b->rod[r]->K);
        if (!b->tcnt[r] || !b->tidx[r] || !b->tval[r] || !b->Kr[r]) return GAL_ENOMEM;
    }
    return GAL_OK;
}

/* The rods on the bundle circle (each the single one moved by its offset) and the spacers' state. */
static int place(gal_bundle *b, const gal_rod_params *p, const double *q1)
{
    int nq = 3 * b->nn + (p->torsion ? p->elements : 0);
    double *qk = malloc((size_t)nq * sizeof(double));
    if (!qk) return gal_error(GAL_ENOMEM, "bundle: out of memory");
    for (int r = 0; r < b->n; r++) {
        double a = b->bp.orientation + 2 * GAL_PI * r / b->n;
        b->off[r][0] = 0, b->off[r][1] = b->bp.radius * cos(a), b->off[r][2] = b->bp.radius * sin(a);
        memcpy(qk, q1, (size_t)nq * sizeof(double));
        for (int i = 0; i < b->nn; i++)
            for (int k = 0; k < 3; k++) qk[3 * i + k] += b->off[r][k];
        if (!(b->rod[r] = gal_rod_alloc(p, qk))) {
            free(qk);
            return gal_error_status() == GAL_ENOMEM ? GAL_ENOMEM : GAL_EINPUT;
        }
    }
    free(qk);
    return GAL_OK;
}

gal_bundle *gal_bundle_alloc(const gal_rod_params *p, const gal_bundle_params *bp, const double *q1)
{
    int n = bp->subconductors, ns = bp->spacers, g = ns + 1, at = bp->positions && ns > 0;
    if (n < 2 || n > GAL_BUNDLE_MAX || ns < 0 || !(bp->radius > 0) || !p->torsion ||
        (at ? !snap_fits(bp, p->elements) : (p->elements % g || p->elements / g < 2))) {
        gal_error(GAL_EINPUT, "bundle: %d sub-conductors (allowed 2 to %d), radius %g m (> 0), torsion %s (on), "
                  "%d elements for %d spacers (allowed: %s, at least 2 between spacers)", n, GAL_BUNDLE_MAX,
                  bp->radius, p->torsion ? "on" : "off", p->elements, ns,
                  at ? "each spacer within 1e-3 of the span of a node" : "a multiple of spacers + 1");
        return NULL;
    }
    gal_bundle *b = calloc(1, sizeof *b);
    if (!b) return NULL;
    b->bp = *bp, b->n = n, b->ns = ns, b->nn = p->elements + 1, b->nrot = n == 2 ? 2 : 3;
    int st = place(b, p, q1);
    if (!st && alloc_arrays(b)) st = gal_error(GAL_ENOMEM, "bundle: out of memory");
    if (st) return gal_bundle_free(b);
    int nq = b->rod[0]->nq, per = p->elements / g;
    for (int i = 0; i < b->nn; i++) b->spat[i] = -1;
    for (int sp = 0; sp < ns; sp++) {
        b->spnode[sp] = at ? snap_node(bp, sp, p->elements) : (sp + 1) * per;
        b->spat[b->spnode[sp]] = sp;
    }
    for (int r = 0; r < n; r++) memcpy(b->state + (size_t)r * nq, b->rod[r]->q0, (size_t)nq * sizeof(double));
    for (int sp = 0; sp < ns; sp++) {
        double *u = SP_U(b, b->state, sp), *R = SP_R(b, b->state, sp);
        for (int k = 0; k < 3; k++) u[k] = q1[3 * b->spnode[sp] + k];
        R[0] = R[4] = R[8] = 1.0;
    }
    dependents(b, b->state);
    map_indices(b);
    gal_bundle_map_values(b, b->state);
    if (gal_bundle_pattern(b) || !(b->grad = calloc((size_t)b->ndof, sizeof(double)))) {
        gal_error(GAL_ENOMEM, "bundle: out of memory for the patterns of %d dofs", b->ndof);
        return gal_bundle_free(b);
    }
    return b;
}
