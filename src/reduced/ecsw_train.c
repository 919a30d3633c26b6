/* ecsw_train.c: the training states of the hyper-reduced reduced model (ecsw.h): the selected
 * modes at random amplitudes and directions at the scale of the motion, the modal-derivative
 * coordinates relaxed quasi-statically by Newton on their block of the exact reduced tangent. */
#include "gallop/reduced/ecsw.h"
#include "gallop/base/core.h"

#include <math.h>
#include <string.h>

#include "reduced/hyper.h"

/* x -> a small deterministic generator (xorshift64*), uniform in (0, 1) */
static double unif(unsigned long long *s)
{
    *s ^= *s >> 12, *s ^= *s << 25, *s ^= *s >> 27;
    return ((*s * 2685821657736338717ULL) >> 11) * (1.0 / 9007199254740992.0) + 1e-17;
}

static double gauss(unsigned long long *s)
{
    return sqrt(-2 * log(unif(s))) * cos(2 * GAL_PI * unif(s));
}

int gal_rom_exact_force(gal_rom *m, const double *x, double *f)
{
    const gal_rod *rod = m->rod;
    int n = m->ndof;
    int st = gal_rod_eval(rod, gal_rom_reconstruct_q(m, x), NULL, m->gq, NULL);
    if (st) return st;
    const double *B = gal_rom_basis_at(m, x);
    for (int k = 0; k < m->r; k++) {
        double s = 0;
        for (int d = 0; d < n; d++) s += B[(size_t)k * n + d] * m->gq[rod->free_q[d]];
        f[k] = s;
    }
    return GAL_OK;
}

/* Cholesky of the SPD block A (p x p, row-major, in place); 0 on success. */
static int chol(double *A, int p)
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
    return 0;
}

static void chol_solve(const double *L, int p, double *b)
{
    for (int i = 0; i < p; i++) {
        for (int k = 0; k < i; k++) b[i] -= L[i * p + k] * b[k];
        b[i] /= L[i * p + i];
    }
    for (int i = p - 1; i >= 0; i--) {
        for (int k = i + 1; k < p; k++) b[i] -= L[k * p + i] * b[k];
        b[i] /= L[i * p + i];
    }
}

/* Training state s: the modes at a random amplitude and direction, each mode's largest
 * translation up to the sag (at least 1% of the span) and its largest twist up to hyper_twist;
 * the modal-derivative coordinates relaxed quasi-statically (below) so that their force is the
 * equilibrium's; a velocity of the same scale in the modes. */
int gal_rom_hyper_training_state(gal_rom *m, int s, double *x, double *v)
{
    gal_rom_hyper *h = m->hyper;
    const gal_rod *rod = m->rod;
    int n = m->ndof, r = m->r, nm = m->nmodes, nd = r - nm;
    unsigned long long seed = 0x9E3779B97F4A7C15ULL * (unsigned long long)(s + 1);
    double u[64], uu = 0, a = s == 0 ? 0.1 : 0.1 + 1.1 * unif(&seed);
    for (int k = 0; k < nm && k < 64; k++) u[k] = gauss(&seed), uu += u[k] * u[k];
    memset(x, 0, (size_t)r * sizeof(double));
    memset(v, 0, (size_t)r * sizeof(double));
    for (int k = 0; k < nm && k < 64; k++) {
        const double *vk = m->V + (size_t)k * n;
        double st = 0, sr = 0;
        for (int d = 0; d < n; d++) {
            int qi = rod->free_q[d];
            if (qi < 3 * rod->nn) st = fmax(st, fabs(vk[d]));
            else sr = fmax(sr, fabs(vk[d]));
        }
        double emax = INFINITY;
        if (st > 0) emax = h->amp / st;
        if (sr > 0) emax = fmin(emax, m->o.hyper_twist / sr);
        x[k] = a * u[k] / sqrt(uu) * emax;
        v[k] = sqrt(m->omega2[k]) * emax * a * gauss(&seed) / sqrt((double)nm);
    }
    /* Newton on the modal-derivative block of the exact reduced tangent, the step halved while
     * it does not reduce the force (the stretching stiffens fast) */
    double b[256], *J = h->Jdd, fn = INFINITY;
    for (int it = 0; it < 8 && nd > 0; it++) {
        int st = gal_rod_eval(rod, gal_rom_reconstruct_q(m, x), NULL, m->gq, m->K);
        if (st) return st;
        double fn1 = 0;
        for (int i = 0; i < nd; i++) {
            const double *vi = m->V + (size_t)(nm + i) * n;
            double sum = 0;
            for (int d = 0; d < n; d++) sum += vi[d] * m->gq[rod->free_q[d]];
            b[i] = h->F0[nm + i] - sum, fn1 += b[i] * b[i] / fmax(m->K0r[(nm + i) * r + nm + i], 1e-300);
        }
        if (fn1 < 1e-20 * fn || fn1 == 0) break;
        fn = fn1;
        for (int j = 0; j < nd; j++) {
            gal_csc_symv(m->K, m->V + (size_t)(nm + j) * n, m->wn);
            for (int i = 0; i <= j; i++) {
                const double *vi = m->V + (size_t)(nm + i) * n;
                double sum = 0;
                for (int d = 0; d < n; d++) sum += vi[d] * m->wn[d];
                J[i * nd + j] = J[j * nd + i] = sum;
            }
        }
        if (chol(J, nd)) break; /* not positive: keep the state reached */
        chol_solve(J, nd, b);
        for (int i = 0; i < nd; i++) x[nm + i] += b[i];
    }
    return GAL_OK;
}

