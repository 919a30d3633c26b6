/* rom_orbit.c: a growth's correction taken over the orbit (rom_adapt.h, gal_rom_adapt.orbit_vectors:
 * an option, off by default): the failing family's correction sampled along the old model's run
 * on, weighed in the check's norm, and its Hann-weighted mean and dominant direction. */
#include "gallop/reduced/rom_adapt.h"
#include "gallop/base/core.h"
#include "gallop/base/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "reduced/adapt.h"

static int node_dof(const gal_rod *rod, int i)
{
    int d0 = rod->dof[3 * i];
    return d0 < 0 || rod->dof[3 * i + 1] != d0 + 1 || rod->dof[3 * i + 2] != d0 + 2 ? -1 : d0;
}

/* y in the check's norm (chk's scales): yw with |yw|^2 = sum over families of y's mass norm in the
 * family over its scale squared (each node's translation split along the equilibrium's vertical,
 * horizontal and axial directions; the dofs that the check does not read weigh 0). */
static void weigh(const gal_rom_adapt *a, const gal_rom_check *chk, const double *y, double *yw)
{
    const gal_rod *rod = a->rod;
    double s[GAL_FAMILY_COUNT];
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) s[f] = chk->scale[f] > 0 ? 1 / chk->scale[f] : 0;
    memset(yw, 0, (size_t)rod->ndof * sizeof(double));
    for (int i = 0; i < rod->nn; i++) {
        int d0 = node_dof(rod, i);
        if (d0 < 0) continue;
        double t[3], ey[3], nv[3], w = sqrt(rod->mdiag[d0]);
        gal_rod_node_directions(rod, a->q_eq, i, t, ey, nv);
        yw[d0] = w * s[GAL_FAMILY_VERTICAL] * gal_dot3(nv, y + d0);
        yw[d0 + 1] = w * s[GAL_FAMILY_HORIZONTAL] * gal_dot3(ey, y + d0);
        yw[d0 + 2] = w * s[GAL_FAMILY_AXIAL] * gal_dot3(t, y + d0);
    }
    if (rod->p.torsion)
        for (int j = 0; j < rod->p.elements; j++) {
            int d = rod->dof[3 * rod->nn + j];
            if (d >= 0) yw[d] = sqrt(rod->mdiag[d]) * s[GAL_FAMILY_TORSIONAL] * y[d];
        }
}

void dsyev_(const char *jobz, const char *uplo, const int *n, double *a, const int *lda, double *w, double *work,
            const int *lwork, int *info);

/* The orbit's sampling (rom_adapt.h): its window, GAL_ROM_ORBIT_PERIODS periods of the basis's lowest
 * mode, and the steps between samples (GAL_ROM_ORBIT_PER_PERIOD samples per period of its highest
 * mode, at most GAL_ROM_ORBIT_SAMPLES over the window); the number of samples into *ns. */
static long orbit_sampling(const gal_rom_adapt *a, double h, int *ns)
{
    double flo = INFINITY, fhi = 0;
    for (int j = 0; j < a->nsel; j++) {
        double f = a->md->mode[a->sel[j]].frequency_hz;
        if (f >= 0.01) flo = fmin(flo, f), fhi = fmax(fhi, f);
    }
    double w = isfinite(flo) ? GAL_ROM_ORBIT_PERIODS / flo : 1.0;
    double n = fmin(ceil(w * GAL_ROM_ORBIT_PER_PERIOD * fhi), GAL_ROM_ORBIT_SAMPLES - 1);
    long every = lround(w / (fmax(n, 1) * h));
    if (every < 1) every = 1;
    *ns = (int)fmin(ceil(w / (every * h)), GAL_ROM_ORBIT_SAMPLES - 1) + 1;
    return every;
}

/* The samples of the orbit into Y (n x N, each family f's correction alone, gal_rom_residual_family,
 * without its part in old's basis) and Yw (the same in the check's norm): from du (the failing
 * check's) and the residual directions of old run on,
 * `every` steps apart; their number (a step or residual that fails ends the sampling: the samples
 * so far; -1: out of memory). work: n + old->r. */
static int orbit_samples(gal_rom_adapt *a, gal_rom *old, const gal_rom_check *chk, const double *du, int f, int N,
                         long every, double *Y, double *Yw, double *work)
{
    int n = old->ndof, ns = 0, st = GAL_OK;
    gal_rom_check c;
    for (ns = 0; ns < N; ns++) {
        double *y = Y + (size_t)ns * n;
        if (ns == 0) memcpy(y, du, (size_t)n * sizeof(double));
        else {
            for (long k = 0; k < every && !st; k++) st = gal_rom_step(old);
            if (st || (st = gal_rom_residual_dir(old, &c, y))) break;
        }
        if (gal_rom_residual_family(old, y, (gal_family)f, y)) return -1; /* out of memory */
        gal_rom_deflate(old, y, work, work + n);
        weigh(a, chk, y, Yw + (size_t)ns * n);
    }
    return ns;
}

/* The orbit's corrections (rom_adapt.h) into dir (n x *K, each unit in the mass norm; *K: 1 or 2
 * in, how many out): the Hann-weighted mean of the samples and the dominant direction of the
 * rest (their weighted POD in the check's norm, when it carries more than round-off). old is left
 * where the sampling ended (its counters count the steps). */
int gal_rom_adapt_orbit_correction(gal_rom_adapt *a, gal_rom *old, const gal_rom_check *chk, const double *du, int f,
                                   int *K, double *dir)
{
    int n = old->ndof, N, info = 0, lw = 8 * GAL_ROM_ORBIT_SAMPLES;
    long every = orbit_sampling(a, old->o.h, &N);
    size_t nn = (size_t)N * n;
    double *Y = malloc((2 * nn + 3 * (size_t)n + old->r + (size_t)N * N + 2 * (size_t)N + lw) * sizeof(double));
    if (!Y) return gal_error(GAL_ENOMEM, "reduced model: out of memory");
    double *Yw = Y + nn, *work = Yw + nn, *ybar = work + n + old->r, *ywbar = ybar + n, *C = ywbar + n;
    double *hw = C + (size_t)N * N, *ev = hw + N, *wk = ev + N, hs = 0, e0 = 0;
    int ns = orbit_samples(a, old, chk, du, f, N, every, Y, Yw, work);
    if (ns < 0) { free(Y); return GAL_EFAIL; }
    for (int i = 0; i < ns; i++) {
        double si = sin(3.14159265358979323846 * (i + 0.5) / ns);
        hw[i] = si * si, hs += hw[i];
    }
    memset(ybar, 0, 2 * (size_t)n * sizeof(double));
    for (int i = 0; i < ns; i++)
        for (int d = 0; d < n; d++) ybar[d] += hw[i] / hs * Y[(size_t)i * n + d], ywbar[d] += hw[i] / hs * Yw[(size_t)i * n + d];
    for (int i = 0; i < ns; i++)
        for (int d = 0; d < n; d++) Y[(size_t)i * n + d] -= ybar[d], Yw[(size_t)i * n + d] -= ywbar[d];
    for (int d = 0; d < n; d++) e0 += ywbar[d] * ywbar[d];
    for (int i = 0; i < ns && *K > 1; i++) /* the rest's weighted correlation in the check's norm */
        for (int j = 0; j <= i; j++) {
            double sum = 0;
            for (int d = 0; d < n; d++) sum += Yw[(size_t)i * n + d] * Yw[(size_t)j * n + d];
            C[i * ns + j] = C[j * ns + i] = sum * sqrt(hw[i] * hw[j]) / hs;
        }
    if (*K > 1 && ns > 1) dsyev_("V", "U", &ns, C, &ns, ev, wk, &lw, &info);
    int k = 1;
    memcpy(dir, ybar, (size_t)n * sizeof(double));
    if (*K > 1 && ns > 1 && !info && ev[ns - 1] > 1e-12 * (e0 + ev[ns - 1])) {
        const double *v = C + (size_t)(ns - 1) * ns; /* the largest eigenvalue's vector */
        double *d1 = dir + n;
        memset(d1, 0, (size_t)n * sizeof(double));
        for (int i = 0; i < ns; i++)
            for (int d = 0; d < n; d++) d1[d] += v[i] * sqrt(hw[i]) * Y[(size_t)i * n + d];
        k = 2;
    }
    for (int c = 0; c < k; c++) {
        double *dk = dir + (size_t)c * n, nm = 0;
        gal_rod_mass_mult(old->rod, dk, work);
        for (int d = 0; d < n; d++) nm += dk[d] * work[d];
        if (nm > 0)
            for (int d = 0; d < n; d++) dk[d] /= sqrt(nm);
    }
    *K = k;
    free(Y);
    return GAL_OK;
}
