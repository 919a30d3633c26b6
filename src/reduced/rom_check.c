/* rom_check.c: the reduced model's self-check (rom.h): the full equations' residual
 *   R = M a + C v + grad U(q) - F(t, q, v)
 * at the reconstructed state, turned into the displacement that would correct it, du = K0^-1 R,
 * and split into the families of the motion (vertical: in the plane of the span, normal to the
 * conductor at equilibrium; horizontal: out of that plane; axial: along it; torsional: the twist),
 * each in the mass norm |u|^2 = sum m_d u_d^2 and set against the family's own displacement (so
 * that the axial forces, large and balanced, do not swamp the transverse ones). Also the power
 * along the full velocity, per family, of R, of the load and of the damping force (diagnostics:
 * the reduced equations are the full ones projected on the basis, so R does no work along the
 * reconstructed velocity but for the hyper-reduction's error; BENCHMARKS.md). The correction of one
 * family alone, what a growth adds (gal_rom_residual_family). */
#include "gallop/reduced/rom.h"
#include "gallop/base/core.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/chol.h"
#include "gallop/base/vec3.h"
#include "reduced/hyper.h"

enum { TERM_R, TERM_MA, TERM_CV, TERM_G, TERM_F, NTERM };

/* The first free dof of node i when its three translations are free, else -1. */
static int node_dof(const gal_rod *rod, int i)
{
    int d0 = rod->dof[3 * i];
    return d0 < 0 || rod->dof[3 * i + 1] != d0 + 1 || rod->dof[3 * i + 2] != d0 + 2 ? -1 : d0;
}

/* Each node's unit directions at the equilibrium, axial t, horizontal ey and vertical nv
 * (gal_rod_node_directions at q_eq), 9 a node, made once and kept in m->node_dir; NULL when out of
 * memory (with the message). */
static const double *node_dirs(gal_rom *m)
{
    const gal_rod *rod = m->rod;
    if (m->node_dir) return m->node_dir;
    if (!(m->node_dir = malloc((size_t)9 * rod->nn * sizeof(double)))) {
        gal_error(GAL_ENOMEM, "reduced model: out of memory for the check's directions");
        return NULL;
    }
    for (int i = 0; i < rod->nn; i++) {
        double *e = m->node_dir + 9 * i;
        gal_rod_node_directions(rod, m->q_eq, i, e, e + 3, e + 6);
    }
    return m->node_dir;
}

/* Accumulate sum w y z per family of the free-dof vectors y, z into acc[family] (w: the diagonal
 * weights, 1 when NULL; dir: node_dirs'). */
static void accumulate(const gal_rom *m, const double *dir, const double *y, const double *z, const double *mdiag,
                       double *acc)
{
    const gal_rod *rod = m->rod;
    for (int i = 0; i < rod->nn; i++) {
        int d0 = node_dof(rod, i);
        if (d0 < 0) continue;
        const double *t = dir + 9 * i, *ey = t + 3, *nv = t + 6;
        double yv = gal_dot3(nv, y + d0), yh = gal_dot3(ey, y + d0), ya = gal_dot3(t, y + d0);
        double zv = gal_dot3(nv, z + d0), zh = gal_dot3(ey, z + d0), za = gal_dot3(t, z + d0);
        double w = mdiag ? mdiag[d0] : 1;
        acc[GAL_FAMILY_VERTICAL] += yv * zv * w;
        acc[GAL_FAMILY_HORIZONTAL] += yh * zh * w;
        acc[GAL_FAMILY_AXIAL] += ya * za * w;
    }
    if (rod->p.torsion)
        for (int j = 0; j < rod->p.elements; j++) {
            int d = rod->dof[3 * rod->nn + j];
            if (d >= 0) acc[GAL_FAMILY_TORSIONAL] += y[d] * z[d] * (mdiag ? mdiag[d] : 1);
        }
}

/* The scale floor of each translational family (vertical, horizontal, axial; the twist's is
 * rom_adapt.c's, 1 deg): the mass norm, in that family, of the displacement K0^-1 W_f that a load
 * of GAL_ROM_CHECK_LOAD times the span's own weight per node, along the family's direction at each
 * node, would cause (horizontally: the span swung by about that fraction of its sag). Below it a
 * motion is no scale for the residual: a still span's round-off is no alarm, and a residual is an
 * alarm only past the tolerance times the response to that load. 0 without gravity. load, du: n. */
static int scale_floors(gal_rom *m, double *load, double *du, double floor[GAL_FAMILY_COUNT])
{
    const gal_rod *rod = m->rod;
    static const gal_family fam[3] = {GAL_FAMILY_VERTICAL, GAL_FAMILY_HORIZONTAL, GAL_FAMILY_AXIAL};
    if (m->check_floor_set) { /* constants of the model: computed at its first check */
        memcpy(floor, m->check_floor, sizeof m->check_floor);
        return GAL_OK;
    }
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) floor[f] = 0;
    if (!(rod->p.gravity > 0)) return GAL_OK;
    for (int k = 0; k < 3; k++) {
        memset(load, 0, (size_t)m->ndof * sizeof(double));
        for (int i = 0; i < rod->nn; i++) {
            int d0 = node_dof(rod, i);
            if (d0 < 0) continue;
            double e[3][3], w = GAL_ROM_CHECK_LOAD * rod->mdiag[d0] * rod->p.gravity;
            gal_rod_node_directions(m->rod, m->q_eq, i, e[2], e[1], e[0]); /* vertical, horizontal, axial */
            for (int c = 0; c < 3; c++) load[d0 + c] = w * e[k][c];
        }
        int st = gal_chol_solve(m->chol0, load, du);
        if (st) return st;
        double acc[GAL_FAMILY_COUNT] = {0};
        accumulate(m, m->node_dir, du, du, rod->mdiag, acc);
        floor[fam[k]] = sqrt(acc[fam[k]]);
    }
    memcpy(m->check_floor, floor, sizeof m->check_floor);
    m->check_floor_set = 1;
    return GAL_OK;
}

int gal_rom_residual(gal_rom *m, gal_rom_check *chk)
{
    return gal_rom_residual_dir(m, chk, NULL);
}

int gal_rom_residual_dir(gal_rom *m, gal_rom_check *chk, double *du)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof, st = GAL_OK;
    memset(chk, 0, sizeof *chk);
    const double *dir = node_dirs(m);
    if (!dir) return GAL_ENOMEM;
    double *w = calloc((size_t)(NTERM + 3) * n, sizeof(double));
    if (!w) return gal_error(GAL_ENOMEM, "reduced model: out of memory for the residual");
    double *y[NTERM], *vf = w + NTERM * n, *af = vf + n, *u = af + n;
    for (int k = 0; k < NTERM; k++) y[k] = w + (size_t)k * n;
    /* the full velocity, acceleration and displacement over the free dofs */
    gal_rom_full_rates(m, vf, af, u);
    gal_rod_mass_mult(rod, af, y[TERM_MA]);
    if (m->o.damping) gal_damping_apply(m->o.damping, vf, y[TERM_CV]); /* y is zeroed */
    const double *wg, *wf; /* the sample check's at this state, when it came at the same step */
    gal_rom_hyper_whole(m, &wg, &wf);
    if (!wg || (!wf && m->force.eval)) gal_rom_reconstruct(m, NULL, NULL); /* into m->q, m->vq */
    if (wg) memcpy(m->gq, wg, (size_t)m->nq * sizeof(double));
    else if ((st = gal_rod_eval(rod, m->q, NULL, m->gq, NULL))) goto done;
    if (wf) memcpy(m->fq, wf, (size_t)m->nq * sizeof(double));
    else {
        memset(m->fq, 0, (size_t)m->nq * sizeof(double));
        if (m->force.eval && (st = m->force.eval(m->force.ctx, m->t, m->q, m->vq, m->fq))) goto done;
    }
    gal_rod_gather(rod, m->gq, y[TERM_G]);
    gal_rod_gather(rod, m->fq, y[TERM_F]);
    for (int d = 0; d < n; d++) y[TERM_R][d] = y[TERM_MA][d] + y[TERM_CV][d] + y[TERM_G][d] - y[TERM_F][d];
    accumulate(m, dir, y[TERM_R], vf, NULL, chk->power[0]);
    accumulate(m, dir, y[TERM_F], vf, NULL, chk->power[1]);
    accumulate(m, dir, y[TERM_CV], vf, NULL, chk->power[2]);
    /* du = K0^-1 R and the displacement u = V x */
    if ((st = gal_chol_solve(m->chol0, y[TERM_R], y[TERM_R]))) goto done;
    if (du) memcpy(du, y[TERM_R], (size_t)n * sizeof(double));
    memcpy(y[TERM_MA], u, (size_t)n * sizeof(double));
    double acc[2][GAL_FAMILY_COUNT] = {{0}}, total = 0;
    accumulate(m, dir, y[TERM_R], y[TERM_R], rod->mdiag, acc[0]);
    accumulate(m, dir, y[TERM_MA], y[TERM_MA], rod->mdiag, acc[1]);
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) total += acc[1][f];
    double floor[GAL_FAMILY_COUNT];
    if ((st = scale_floors(m, y[TERM_G], y[TERM_F], floor))) goto done;
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) {
        double scale = fmax(fmax(sqrt(acc[1][f]), 0.02 * sqrt(total)), floor[f]);
        chk->err[f] = sqrt(acc[0][f]), chk->disp[f] = sqrt(acc[1][f]), chk->scale[f] = scale;
        chk->rel[f] = scale > 0 ? sqrt(acc[0][f]) / scale : 0;
        chk->max = fmax(chk->max, chk->rel[f]);
    }
done:
    free(w);
    return st;
}

int gal_rom_residual_family(gal_rom *m, const double *du, gal_family f, double *df)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof;
    double *R = malloc((size_t)n * sizeof(double));
    if (!R) return gal_error(GAL_ENOMEM, "reduced model: out of memory for the correction");
    gal_csc_symv(m->K0, du, R); /* the residual again, R = K0 du */
    for (int i = 0; i < rod->nn; i++) { /* each node's translation: its part along f's direction */
        int d0 = node_dof(rod, i);
        if (d0 < 0) { /* partly fixed: in no family, as in the check */
            for (int c = 0; c < 3; c++)
                if (rod->dof[3 * i + c] >= 0) R[rod->dof[3 * i + c]] = 0;
            continue;
        }
        double e[3][3], keep[3] = {0, 0, 0};
        gal_rod_node_directions(rod, m->q_eq, i, e[2], e[1], e[0]); /* vertical, horizontal, axial */
        int k = f == GAL_FAMILY_VERTICAL ? 0 : f == GAL_FAMILY_HORIZONTAL ? 1 : f == GAL_FAMILY_AXIAL ? 2 : -1;
        if (k >= 0) {
            double s = gal_dot3(e[k], R + d0);
            for (int c = 0; c < 3; c++) keep[c] = s * e[k][c];
        }
        memcpy(R + d0, keep, sizeof keep);
    }
    for (int d = 0; d < n; d++) /* the twist */
        if (rod->free_q[d] >= 3 * rod->nn && f != GAL_FAMILY_TORSIONAL) R[d] = 0;
    int st = gal_chol_solve(m->chol0, R, df);
    free(R);
    return st;
}

/* y += s D2K[w, w] w for w = Phi eta (D2K by central differences of the tangent over a translation
 * of GAL_ROM_CUBIC_STEP along w / wmax, wmax its largest translation); w: n of scratch, m->fq and
 * m->K the scratch of the configuration and of the tangents. */
static int cubic_add(gal_rom *m, const double *eta, double s, double *w, double *y, double *ky)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof, st = GAL_OK;
    double wmax = 0;
    memset(w, 0, (size_t)n * sizeof(double));
    for (int k = 0; k < m->nmodes; k++)
        for (int d = 0; d < n; d++) w[d] += eta[k] * m->V[(size_t)k * n + d];
    for (int d = 0; d < n; d++)
        if (rod->free_q[d] < 3 * rod->nn) wmax = fmax(wmax, fabs(w[d]));
    if (!(wmax > 0)) return GAL_OK;
    for (int d = 0; d < n; d++) w[d] /= wmax;
    double e = GAL_ROM_CUBIC_STEP, c = s * wmax * wmax * wmax / (e * e);
    gal_csc_symv(m->K0, w, ky);
    for (int d = 0; d < n; d++) y[d] -= 2 * c * ky[d];
    for (int sg = -1; sg <= 1 && !st; sg += 2) {
        memcpy(m->fq, m->q_eq, (size_t)m->nq * sizeof(double));
        for (int d = 0; d < n; d++) m->fq[rod->free_q[d]] += sg * e * w[d];
        if ((st = gal_rod_eval(rod, m->fq, NULL, NULL, m->K))) break;
        gal_csc_symv(m->K, w, ky);
        for (int d = 0; d < n; d++) y[d] += c * ky[d];
    }
    return st;
}

int gal_rom_cubic(gal_rom *m, const double *eta, double err[GAL_FAMILY_COUNT])
{
    const gal_rod *rod = m->rod;
    int n = m->ndof, st = GAL_OK;
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) err[f] = 0;
    if (m->qm || m->nmodes < 1) return GAL_OK; /* the manifold carries its own higher terms */
    const double *dir = node_dirs(m);
    if (!dir) return GAL_ENOMEM;
    double *w = calloc((size_t)3 * n + m->r, sizeof(double)), *c = w + n, *y = c + n, *p = y + n;
    if (!w) return gal_error(GAL_ENOMEM, "reduced model: out of memory for the cubic check");
    if ((st = cubic_add(m, eta, -1.0 / 6, w, c, y)) || (st = gal_chol_solve(m->chol0, c, c))) goto done;
    gal_rom_deflate(m, c, y, p);
    double acc[GAL_FAMILY_COUNT] = {0};
    accumulate(m, dir, c, c, rod->mdiag, acc);
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) err[f] = sqrt(acc[f]);
done:
    free(w);
    return st;
}

/* The tension of element j at the configuration q (all nq entries). */
static double tension_at(const gal_rod *rod, const double *q, int j)
{
    double e[3];
    for (int k = 0; k < 3; k++) e[k] = q[3 * (j + 1) + k] - q[3 * j + k];
    return rod->p.EA * (sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]) / rod->l0[j] - 1);
}

double gal_rom_taut_share(const gal_rom *m)
{
    const gal_rod *rod = m->rod;
    int end[2] = {0, rod->p.elements - 1};
    double share = 1;
    for (int k = 0; k < 2; k++) {
        double t0 = tension_at(rod, m->q_eq, end[k]);
        if (t0 > 0) share = fmin(share, gal_rom_element_tension(m, end[k]) / t0);
    }
    return share;
}

void gal_rom_deflate(const gal_rom *m, double *y, double *Mc, double *p)
{
    int n = m->ndof;
    gal_rod_mass_mult(m->rod, y, Mc);
    int k = 0;
    for (; k + 4 <= m->r; k += 4) { /* p = V^T Mc four columns a pass, each sum over d in order */
        const double *v0 = m->V + (size_t)k * n, *v1 = v0 + n, *v2 = v1 + n, *v3 = v2 + n;
        double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
        for (int d = 0; d < n; d++) s0 += v0[d] * Mc[d], s1 += v1[d] * Mc[d], s2 += v2[d] * Mc[d], s3 += v3[d] * Mc[d];
        p[k] = s0, p[k + 1] = s1, p[k + 2] = s2, p[k + 3] = s3;
    }
    for (; k < m->r; k++) {
        double s = 0;
        for (int d = 0; d < n; d++) s += m->V[(size_t)k * n + d] * Mc[d];
        p[k] = s;
    }
    for (int k = 0; k < m->r; k++)
        for (int d = 0; d < n; d++) y[d] -= p[k] * m->V[(size_t)k * n + d];
}

void dsyev_(const char *jobz, const char *uplo, const int *n, double *a, const int *lda, double *w, double *work,
            const int *lwork, int *info);

void gal_rom_band_clear(gal_rom_band *b)
{
    free(b->y);
    memset(b, 0, sizeof *b);
}

int gal_rom_band_init(gal_rom *m, double band_hz, gal_rom_band *b)
{
    int r = m->r, n = m->ndof, lw = 64 * r, info = 0;
    gal_rom_band_clear(b);
    const double *dir = node_dirs(m);
    if (!dir) return GAL_ENOMEM;
    double *A = malloc(((size_t)r * r + r + lw + n) * sizeof(double));
    b->y = malloc((size_t)r * (r + 1 + GAL_FAMILY_COUNT) * sizeof(double));
    if (!A || !b->y) {
        free(A);
        gal_rom_band_clear(b);
        return gal_error(GAL_ENOMEM, "reduced model: out of memory");
    }
    double *w = A + (size_t)r * r, *wk = w + r, *u = wk + lw;
    memcpy(A, m->K0r, (size_t)r * r * sizeof(double));
    dsyev_("V", "U", &r, A, &r, w, wk, &lw, &info);
    if (info) {
        free(A);
        gal_rom_band_clear(b);
        return gal_error(GAL_EFAIL, "reduced model: the reduced modes: dsyev failed (%d)", info);
    }
    int nh = 0; /* the reduced modes above the band, kept: shape y, omega^2, family shares */
    for (int k = 0; k < r; k++) {
        if (!(w[k] > 0) || sqrt(w[k]) / (2 * GAL_PI) <= band_hz) continue;
        const double *y = A + (size_t)k * r;
        double fam[GAL_FAMILY_COUNT] = {0}, tot = 0;
        memset(u, 0, (size_t)n * sizeof(double));
        for (int i = 0; i < r; i++)
            for (int d = 0; d < n; d++) u[d] += y[i] * m->V[(size_t)i * n + d];
        accumulate(m, dir, u, u, m->rod->mdiag, fam);
        for (int f = 0; f < GAL_FAMILY_COUNT; f++) tot += fam[f];
        memcpy(b->y + (size_t)nh * r, y, (size_t)r * sizeof(double));
        b->y[(size_t)r * r + nh] = w[k];
        for (int f = 0; f < GAL_FAMILY_COUNT; f++)
            b->y[(size_t)r * (r + 1) + (size_t)nh * GAL_FAMILY_COUNT + f] = tot > 0 ? fam[f] / tot : 0;
        nh++;
    }
    b->r = r, b->n = nh;
    b->w2 = b->y + (size_t)r * r, b->share = b->y + (size_t)r * (r + 1);
    free(A);
    return GAL_OK;
}

void gal_rom_band_amplitude(const gal_rom *m, const gal_rom_band *b, double amp[GAL_FAMILY_COUNT])
{
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) amp[f] = 0;
    for (int k = 0; k < b->n; k++) {
        const double *y = b->y + (size_t)k * b->r;
        double cd = 0, ca = 0;
        for (int i = 0; i < b->r; i++) cd += y[i] * m->v[i], ca += y[i] * m->a[i];
        double e = cd * cd / b->w2[k] + ca * ca / (b->w2[k] * b->w2[k]);
        for (int f = 0; f < GAL_FAMILY_COUNT; f++) amp[f] += e * b->share[(size_t)k * GAL_FAMILY_COUNT + f];
    }
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) amp[f] = sqrt(amp[f]);
}
