/* diag_slack.c: what the reduced basis lacks when the conductor goes slack (issue 13, helper slack,
 * session 11; BENCHMARKS.md "The slack conductor and the reduced basis"). The thrown span of
 * tests/test_rom_slack.c (tests/rom/drake_300_turbulent.ini at E elements, steady wind, a half-sine
 * vertical velocity of peak A m/s at t = 0, 4 s). The full model's state at every step (gal_dyn),
 * projected on the reduced model's initial basis V (modes and modal derivatives): the projection
 * error per family (v, h, twist, axial: the node directions at the equilibrium) over the family's
 * largest displacement, and the support tension of the projection against the full state's, for
 * the mass-orthogonal projection and the energy-norm (K0) fit. The same with candidates appended:
 *   lift    the equilibria under the weight and an upward dead load of s times it, s = 0.25 0.5
 *           0.75 0.95 (the lifted catenaries: the support tension falls towards 0), less the
 *           equilibrium (gal_statics_solve_loaded, ten load steps)
 *   drop    the same downwards, s = 0.25 0.5;  blown  the same sideways (+y), s = 0.25 0.5
 *   K0^-1W  the linear static response to the weight
 *   podN    the first N POD vectors (mass-weighted, every 4th step) of the full states' error off
 *           V + K0^-1 W: an oracle, the full run's own
 * Then (PLAIN) the reduced model alone on V + a group (no growth, no check), hyper-reduced or not,
 * and the hybrid "re-expansion in time": the full model from the reduced state while the reduced
 * conductor is below GAL_ROM_SLACK_SHARE, handed back (projected, or its energy-norm fit) once the
 * full support tension is above a share of its static value; and with RUN = 1 the CLI's reduced run
 * (gal_sim_run: growths, checks, the slack reading) and the bridge's (gal_rom_sim_run: growths,
 * checks) with each group added, against the full gal_sim_run. Figures: least and largest support
 * tension, the mid-span vertical excursion down and up.
 * Usage: diag_slack [A [E [RUN [KEY=VALUE]]]]   (built by `make diag`: build/bench/diag_slack 8 40 1;
 * KEY=VALUE: one more scene override, e.g. simulation.time_step=0.0025) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gallop.h"
#include "gallop/base/core.h"
#include "gallop/loads/loads.h"
#include "gallop/reduced/rom.h"
#include "gallop/reduced/rom_sim.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"
#include "gallop/statics/statics.h"
#include "base/chol.h"
#include <gsl/gsl_eigen.h>

#define NS_MAX 4000

static const gal_csc *gK0; /* the tangent at the equilibrium: the energy-norm projection */

/* the K0-orthogonal projection of u on the columns of V (n x r) into pu: the basis's best fit in
 * the energy norm (what a Galerkin statics picks) */
static void kproject(const double *V, int n, int r, const double *u, double *pu)
{
    double *KV = malloc((size_t)n * r * sizeof(double)), *G = malloc((size_t)r * (r + 1) * sizeof(double));
    double *Ku = malloc((size_t)n * sizeof(double)), *c = malloc((size_t)r * sizeof(double));
    for (int j = 0; j < r; j++) gal_csc_symv(gK0, V + (size_t)j * n, KV + (size_t)j * n);
    gal_csc_symv(gK0, u, Ku);
    for (int i = 0; i < r; i++) {
        for (int j = 0; j < r; j++) {
            double t = 0;
            for (int d = 0; d < n; d++) t += V[(size_t)i * n + d] * KV[(size_t)j * n + d];
            G[i * (r + 1) + j] = t;
        }
        double t = 0;
        for (int d = 0; d < n; d++) t += V[(size_t)i * n + d] * Ku[d];
        G[i * (r + 1) + r] = t;
    }
    for (int k = 0; k < r; k++) { /* Gauss, partial pivoting */
        int p = k;
        for (int i = k + 1; i < r; i++)
            if (fabs(G[i * (r + 1) + k]) > fabs(G[p * (r + 1) + k])) p = i;
        for (int j = 0; j <= r; j++) { double t = G[k * (r + 1) + j]; G[k * (r + 1) + j] = G[p * (r + 1) + j], G[p * (r + 1) + j] = t; }
        for (int i = k + 1; i < r; i++) {
            double f = G[i * (r + 1) + k] / G[k * (r + 1) + k];
            for (int j = k; j <= r; j++) G[i * (r + 1) + j] -= f * G[k * (r + 1) + j];
        }
    }
    for (int k = r - 1; k >= 0; k--) {
        double t = G[k * (r + 1) + r];
        for (int j = k + 1; j < r; j++) t -= G[k * (r + 1) + j] * c[j];
        c[k] = t / G[k * (r + 1) + k];
    }
    memset(pu, 0, (size_t)n * sizeof(double));
    for (int k = 0; k < r; k++)
        for (int d = 0; d < n; d++) pu[d] += c[k] * V[(size_t)k * n + d];
    free(KV), free(G), free(Ku), free(c);
}

static double tension_q(const gal_rod *rod, const double *q, int j)
{
    double e[3];
    for (int k = 0; k < 3; k++) e[k] = q[3 * (j + 1) + k] - q[3 * j + k];
    return rod->p.EA * (sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]) / rod->l0[j] - 1);
}

/* mass-norm^2 of y (ndof) per family: v, h, twist, axial */
static void fam(const gal_rod *rod, const double *qeq, const double *y, double f[4])
{
    memset(f, 0, 4 * sizeof(double));
    for (int i = 0; i < rod->nn; i++) {
        int d0 = rod->dof[3 * i];
        if (d0 < 0) continue;
        double t[3], ey[3], nv[3];
        gal_rod_node_directions(rod, qeq, i, t, ey, nv);
        double w = rod->mdiag[d0], a = gal_dot3(nv, y + d0), b = gal_dot3(ey, y + d0), c = gal_dot3(t, y + d0);
        f[0] += w * a * a, f[1] += w * b * b, f[3] += w * c * c;
    }
    if (rod->p.torsion)
        for (int j = 0; j < rod->p.elements; j++) {
            int d = rod->dof[3 * rod->nn + j];
            if (d >= 0) f[2] += rod->mdiag[d] * y[d] * y[d];
        }
}

typedef struct {
    const gal_rod *rod;
    const double *qeq;
    int n, r;
    double *V, *MV; /* n x r, M-orthonormal */
} basis;

static void b_append(basis *b, const double *c0, double tol)
{
    int n = b->n;
    double *c = malloc((size_t)n * sizeof(double)), *Mc = malloc((size_t)n * sizeof(double));
    memcpy(c, c0, (size_t)n * sizeof(double));
    gal_rod_mass_mult(b->rod, c, Mc);
    double n0 = 0;
    for (int d = 0; d < n; d++) n0 += c[d] * Mc[d];
    n0 = sqrt(n0);
    for (int pass = 0; pass < 2; pass++)
        for (int k = 0; k < b->r; k++) {
            double p = 0;
            for (int d = 0; d < n; d++) p += b->MV[(size_t)k * n + d] * c[d];
            for (int d = 0; d < n; d++) c[d] -= p * b->V[(size_t)k * n + d];
        }
    gal_rod_mass_mult(b->rod, c, Mc);
    double n1 = 0;
    for (int d = 0; d < n; d++) n1 += c[d] * Mc[d];
    n1 = sqrt(n1);
    if (n1 > tol * n0) {
        b->V = realloc(b->V, (size_t)n * (b->r + 1) * sizeof(double));
        b->MV = realloc(b->MV, (size_t)n * (b->r + 1) * sizeof(double));
        for (int d = 0; d < n; d++) b->V[(size_t)b->r * n + d] = c[d] / n1, b->MV[(size_t)b->r * n + d] = Mc[d] / n1;
        b->r++;
    }
    free(c), free(Mc);
}

/* project every recorded state on b; print the worst projection error per family and the
 * tension of the projected state against the full one */
static void measure(const basis *b, const double *U, const double *tU, int ns, const char *label)
{
    const gal_rod *rod = b->rod;
    int n = b->n, nq = rod->nq, ne = rod->p.elements;
    double *e = malloc((size_t)n * sizeof(double)), *q = malloc((size_t)nq * sizeof(double));
    double emax[4] = {0}, umax[4] = {0}, dTmax = 0, tdT = 0, Tf_min = INFINITY, Tp_at = 0, Tf_max = -INFINITY, Tp_max = 0;
    double Tp_min = INFINITY, dKmax = 0, tdK = 0, Tk_at = 0, Tk_max = 0;
    for (int s = 0; s < ns; s++) {
        const double *u = U + (size_t)s * n;
        memcpy(e, u, (size_t)n * sizeof(double));
        for (int k = 0; k < b->r; k++) {
            double p = 0;
            for (int d = 0; d < n; d++) p += b->MV[(size_t)k * n + d] * u[d];
            for (int d = 0; d < n; d++) e[d] -= p * b->V[(size_t)k * n + d];
        }
        double fe[4], fu[4];
        fam(rod, b->qeq, e, fe), fam(rod, b->qeq, u, fu);
        for (int f = 0; f < 4; f++) emax[f] = fmax(emax[f], sqrt(fe[f])), umax[f] = fmax(umax[f], sqrt(fu[f]));
        /* tensions: full and projected */
        memcpy(q, b->qeq, (size_t)nq * sizeof(double));
        for (int d = 0; d < n; d++) q[rod->free_q[d]] += u[d];
        double Tf = fmin(tension_q(rod, q, 0), tension_q(rod, q, ne - 1));
        double Tfx = fmax(tension_q(rod, q, 0), tension_q(rod, q, ne - 1));
        memcpy(q, b->qeq, (size_t)nq * sizeof(double));
        for (int d = 0; d < n; d++) q[rod->free_q[d]] += u[d] - e[d];
        double Tp = fmin(tension_q(rod, q, 0), tension_q(rod, q, ne - 1));
        double Tpx = fmax(tension_q(rod, q, 0), tension_q(rod, q, ne - 1));
        if (fabs(Tp - Tf) > dTmax) dTmax = fabs(Tp - Tf), tdT = tU[s];
        if (Tf < Tf_min) Tf_min = Tf, Tp_at = Tp;
        if (Tfx > Tf_max) Tf_max = Tfx, Tp_max = Tpx;
        Tp_min = fmin(Tp_min, Tp);
        /* the energy-norm fit's tension */
        kproject(b->V, n, b->r, u, e);
        memcpy(q, b->qeq, (size_t)nq * sizeof(double));
        for (int d = 0; d < n; d++) q[rod->free_q[d]] += e[d];
        double Tk = fmin(tension_q(rod, q, 0), tension_q(rod, q, ne - 1));
        double Tkx = fmax(tension_q(rod, q, 0), tension_q(rod, q, ne - 1));
        if (fabs(Tk - Tf) > dKmax) dKmax = fabs(Tk - Tf), tdK = tU[s];
        if (Tf <= Tf_min) Tk_at = Tk;
        if (Tfx >= Tf_max) Tk_max = Tkx;
    }
    printf("%-10s r %3d | proj. error / largest displacement, per family: v %.2e h %.2e t %.2e a %.2e | "
           "support tension of the projection: at the full least %.0f N: %.0f; at the full largest %.0f: %.0f; "
           "worst |dT| %.0f N at %.2f s\n",
           label, b->r, emax[0] / umax[0], emax[1] / umax[1], emax[2] / fmax(umax[2], 1e-300), emax[3] / umax[3],
           Tf_min, Tp_at, Tf_max, Tp_max, dTmax, tdT);
    printf("%-10s       energy-norm fit: support tension at the full least %.0f, at the full largest %.0f; worst |dT| %.0f N at %.2f s\n",
           "", Tk_at, Tk_max, dKmax, tdK);
    (void)Tp_min;
    free(e), free(q);
}

/* the equilibrium under gravity and a dead load of share s of the weight along dir (z up),
 * less q_eq, into y (ndof) */
static int scaled_weight(const gal_rod *rod, const double *q0, double s, const double *dir, double *y)
{
    int nq = rod->nq, it = 0;
    double *q = malloc((size_t)nq * sizeof(double)), *f = calloc(nq, sizeof(double));
    memcpy(q, q0, (size_t)nq * sizeof(double));
    for (int i = 0; i < rod->nn; i++)
        for (int c = 0; c < 3; c++) f[3 * i + c] = s * rod->node_mass[i] * 9.81 * dir[c];
    /* load stepping: ten steps */
    int st = 0;
    double *fs = malloc((size_t)nq * sizeof(double));
    for (int k = 1; k <= 10 && !st; k++) {
        for (int i = 0; i < nq; i++) fs[i] = f[i] * k / 10.0;
        st = gal_statics_solve_loaded(rod, q, fs, 1e-6, 100, &it);
    }
    if (!st)
        for (int d = 0; d < rod->ndof; d++) y[d] = q[rod->free_q[d]] - q0[rod->free_q[d]];
    else printf("scaled weight %g: %s\n", s, gal_error_message());
    double T = fmin(tension_q(rod, q, 0), tension_q(rod, q, rod->p.elements - 1));
    printf("  static, weight x (1 %+g) along (%g %g %g): support tension %.0f N, %d Newton\n", s, dir[0], dir[1], dir[2],
           T, it);
    free(q), free(f), free(fs);
    return st;
}

/* The reduced model alone (no adaptation, no check) on V + the nx vectors X, hyper-reduced or not,
 * every step from the thrown start; with back > 0 a hybrid: while the reduced conductor is below
 * GAL_ROM_SLACK_SHARE the full model runs from its reconstructed state, handing back (the state
 * projected, gal_rom_start) once the full support tension is above back of its static value. */
static void plain(gal_data *d, double h, const double *X, int nx, int hyper, double back, int kfit, const double *ref, const char *label)
{
    const gal_rod *rod = d->eq.rod;
    int nq = rod->nq, mid = rod->nn / 2, ne = rod->p.elements;
    gal_rom_opts ro;
    gal_rom_default_opts(&ro);
    ro.hyper = hyper, ro.h = h, ro.damping = d->damping, ro.extra = X, ro.nextra = nx;
    gal_force F = {gal_loads_full, (void *)&d->loads, gal_loads_element, gal_loads_full_framed};
    gal_rom *m = gal_rom_alloc(rod, d->eq.q, &d->md, d->sel, d->basis, &ro, &F);
    if (!m || gal_rom_start(m, 0, d->q_start, d->v_start)) { printf("PLAIN %s: %s\n", label, gal_error_message()); return; }
    double *q = malloc((size_t)2 * nq * sizeof(double)), *v = q + nq, T0 = tension_q(rod, d->eq.q, 0);
    double T[2] = {INFINITY, -INFINITY}, z[2] = {INFINITY, -INFINITY};
    gal_dyn *dy = NULL;
    gal_dyn_opts dop;
    gal_dyn_default_opts(&dop);
    dop.h = h, dop.damping = d->damping;
    int st = 0, switches = 0;
    long fullsteps = 0;
    while (!st && (dy ? dy->t : m->t) < 4 - 1e-9) {
        double t0, t1, zz;
        if (dy) {
            st = gal_dyn_step(dy), fullsteps++;
            t0 = tension_q(rod, dy->q, 0), t1 = tension_q(rod, dy->q, ne - 1), zz = dy->q[3 * mid + 2];
            if (fmin(t0, t1) > back * T0) {
                if (kfit) { /* hand back the basis's energy-norm fit of the displacement */
                    int n = rod->ndof;
                    double *u = malloc((size_t)2 * n * sizeof(double)), *pu = u + n;
                    for (int k = 0; k < n; k++) u[k] = dy->q[rod->free_q[k]] - d->eq.q[rod->free_q[k]];
                    kproject(m->V, n, m->r, u, pu);
                    memcpy(q, d->eq.q, (size_t)nq * sizeof(double));
                    for (int k = 0; k < n; k++) q[rod->free_q[k]] += pu[k];
                    free(u);
                    gal_rom_start(m, dy->t, q, dy->v);
                } else
                gal_rom_start(m, dy->t, dy->q, dy->v);
                dy = gal_dyn_free(dy);
            }
        } else {
            st = gal_rom_step(m);
            t0 = gal_rom_element_tension(m, 0), t1 = gal_rom_element_tension(m, ne - 1), zz = gal_rom_entry(m, 3 * mid + 2, 0);
            if (back > 0 && gal_rom_taut_share(m) < GAL_ROM_SLACK_SHARE) {
                gal_rom_reconstruct(m, q, v);
                dy = gal_dyn_alloc(rod, q, v, &dop, &F);
                if (!dy) { st = 1; break; }
                dy->t = m->t, switches++;
            }
        }
        T[0] = fmin(T[0], fmin(t0, t1)), T[1] = fmax(T[1], fmax(t0, t1));
        zz -= d->eq.q[3 * mid + 2];
        z[0] = fmin(z[0], zz), z[1] = fmax(z[1], zz);
    }
    if (st) printf("PLAIN %s: failed: %s\n", label, gal_error_message());
    printf("PLAIN %-12s r %d hyper %d: T %.0f .. %.0f N (largest %+.1f%%), mid-node z %.3f .. %.3f m (%+.1f%%, %+.1f%%)",
           label, m->r, hyper, T[0], T[1], 100 * (T[1] - ref[1]) / ref[1], z[0], z[1], 100 * (z[0] - ref[2]) / fabs(ref[2]),
           100 * (z[1] - ref[3]) / fabs(ref[3]));
    if (back > 0) printf("; %d hand-overs, %ld full steps of %ld", switches, fullsteps, (long)(4 / h + 0.5));
    printf("\n");
    gal_dyn_free(dy);
    gal_rom_free(m);
    free(q);
}

/* A run's least and largest support tension, and the vertical displacement's at probe pz. */
static void extremes(const gal_sim_result *r, int pz, double T[2], double z[2])
{
    T[0] = z[0] = INFINITY, T[1] = z[1] = -INFINITY;
    for (long i = 0; i < r->nsamples; i++) {
        T[0] = fmin(T[0], fmin(r->tension[2 * i], r->tension[2 * i + 1]));
        T[1] = fmax(T[1], fmax(r->tension[2 * i], r->tension[2 * i + 1]));
        double zz = r->trace[(size_t)i * 4 * r->nprobe + 4 * pz + 1];
        z[0] = fmin(z[0], zz), z[1] = fmax(z[1], zz);
    }
}

int main(int argc, char **argv)
{
    double A = argc > 1 ? atof(argv[1]) : 8;
    int E = argc > 2 ? atoi(argv[2]) : 40;
    int dorun = argc > 3 ? atoi(argv[3]) : 1;
    char el[64];
    snprintf(el, sizeof el, "model.elements=%d", E);
    const char *ov[] = {el, "simulation.duration=4", "wind.turbulence=none", "model.on_invalid=warn", argc > 4 ? argv[4] : NULL};
    gal_scene sc;
    gal_sim_setup s;
    if (gal_scene_load(&sc, "tests/rom/drake_300_turbulent.ini", ov, argc > 4 ? 5 : 4, "data/conductors.csv") ||
        gal_sim_setup_init(&s, &sc, 1)) {
        fprintf(stderr, "%s\n", gal_error_message());
        return 1;
    }
    gal_data *d = s.data;
    const gal_rod *rod = d->eq.rod;
    int nq = rod->nq, nn = rod->nn, n = rod->ndof;
    double *q = malloc((size_t)2 * nq * sizeof(double)), *v = q + nq;
    memcpy(q, d->q_start, (size_t)nq * sizeof(double));
    memset(v, 0, (size_t)nq * sizeof(double));
    double x0 = q[0], L = q[3 * (nn - 1)] - x0;
    for (int i = 0; i < nn; i++) v[3 * i + 2] = A * sin(GAL_PI * (q[3 * i] - x0) / L);
    if (gal_data_start_from(s.model, d, q, v) || gal_forward(s.model, d, GAL_STAGE_REDUCED)) {
        fprintf(stderr, "%s\n", gal_error_message());
        return 1;
    }
    /* the full run, every step */
    gal_dyn_opts dop;
    gal_dyn_default_opts(&dop);
    dop.h = sc.simulation.time_step > 0 ? sc.simulation.time_step : 0.005, dop.damping = d->damping;
    gal_force F = {gal_loads_full, (void *)&d->loads, gal_loads_element, gal_loads_full_framed};
    gal_dyn *dy = gal_dyn_alloc(rod, d->q_start, d->v_start, &dop, &F);
    double *U = malloc((size_t)n * NS_MAX * sizeof(double)), tU[NS_MAX];
    int ns = 0;
    const double *qeq = d->eq.q;
    double Tmin = INFINITY, Tmax = -INFINITY, zmin = INFINITY, zmax = -INFINITY;
    int mid = nn / 2;
    while (dy && dy->t < 4 - 1e-9 && ns < NS_MAX) {
        if (gal_dyn_step(dy)) { fprintf(stderr, "%s\n", gal_error_message()); return 1; }
        for (int k = 0; k < n; k++) U[(size_t)ns * n + k] = dy->q[rod->free_q[k]] - qeq[rod->free_q[k]];
        tU[ns++] = dy->t;
        double T0 = tension_q(rod, dy->q, 0), T1 = tension_q(rod, dy->q, rod->p.elements - 1);
        Tmin = fmin(Tmin, fmin(T0, T1)), Tmax = fmax(Tmax, fmax(T0, T1));
        zmin = fmin(zmin, dy->q[3 * mid + 2] - qeq[3 * mid + 2]), zmax = fmax(zmax, dy->q[3 * mid + 2] - qeq[3 * mid + 2]);
    }
    printf("A %g m/s, %d elements: full, %d steps: support tension %.0f .. %.0f N (static %.0f), mid-span z %.3f .. %.3f m\n",
           A, E, ns, Tmin, Tmax, tension_q(rod, qeq, 0), zmin, zmax);
    gal_dyn_free(dy);

    /* the initial basis (as the reduced run builds it) */
    gal_rom_opts ro;
    gal_rom_default_opts(&ro);
    ro.hyper = 0;
    gal_rom *m = gal_rom_alloc(rod, qeq, &d->md, d->sel, d->basis, &ro, NULL);
    if (!m) { fprintf(stderr, "%s\n", gal_error_message()); return 1; }
    gK0 = m->K0;
    basis b0 = {rod, qeq, n, 0, NULL, NULL};
    for (int k = 0; k < m->r; k++) b_append(&b0, m->V + (size_t)k * n, 1e-6);
    measure(&b0, U, tU, ns, "modes+md");
    basis bm = {rod, qeq, n, 0, NULL, NULL};
    for (int k = 0; k < m->nmodes; k++) b_append(&bm, m->V + (size_t)k * n, 1e-6);
    measure(&bm, U, tU, ns, "modes");

    /* candidates: lifted and heavier catenaries, vertical and horizontal */
    static const double sh[] = {0.25, 0.5, 0.75, 0.95};
    double zdir[3] = {0, 0, 1}, ydir[3] = {0, 1, 0};
    double *S = malloc((size_t)n * 32 * sizeof(double));
    int nS = 0, nlift = 0;
    for (int k = 0; k < 4; k++)
        if (!scaled_weight(rod, qeq, sh[k], zdir, S + (size_t)nS * n)) nS++;
    nlift = nS;
    for (int k = 0; k < 2; k++)
        if (!scaled_weight(rod, qeq, -sh[k], zdir, S + (size_t)nS * n)) nS++;
    int ndrop = nS;
    for (int k = 0; k < 2; k++)
        if (!scaled_weight(rod, qeq, sh[k], ydir, S + (size_t)nS * n)) nS++;
    int nlin = nS; /* the linear static response to the weight, K0^-1 W */
    {
        double *w = S + (size_t)nS * n;
        for (int dd = 0; dd < n; dd++) w[dd] = 0;
        for (int i = 0; i < rod->nn; i++)
            if (rod->dof[3 * i + 2] >= 0) w[rod->dof[3 * i + 2]] = rod->node_mass[i] * 9.81;
        if (!gal_chol_solve(m->chol0, w, w)) nS++;
    }
    /* the oracle: the POD (mass-weighted, every 4th step) of the full states' error off V + K0^-1 W */
    int npod = 0;
    {
        basis bk = b0;
        bk.V = malloc((size_t)n * b0.r * sizeof(double)), bk.MV = malloc((size_t)n * b0.r * sizeof(double));
        memcpy(bk.V, b0.V, (size_t)n * b0.r * sizeof(double)), memcpy(bk.MV, b0.MV, (size_t)n * b0.r * sizeof(double));
        b_append(&bk, S + (size_t)nlin * n, 1e-6);
        int m4 = ns / 4;
        double *Ee = malloc((size_t)n * m4 * sizeof(double)), *Me = malloc((size_t)n * m4 * sizeof(double));
        for (int j = 0; j < m4; j++) {
            double *e = Ee + (size_t)j * n;
            const double *u = U + (size_t)(4 * j) * n;
            memcpy(e, u, (size_t)n * sizeof(double));
            for (int k = 0; k < bk.r; k++) {
                double p = 0;
                for (int dd = 0; dd < n; dd++) p += bk.MV[(size_t)k * n + dd] * u[dd];
                for (int dd = 0; dd < n; dd++) e[dd] -= p * bk.V[(size_t)k * n + dd];
            }
            gal_rod_mass_mult(rod, e, Me + (size_t)j * n);
        }
        gsl_matrix *C = gsl_matrix_alloc(m4, m4), *Z = gsl_matrix_alloc(m4, m4);
        gsl_vector *ev = gsl_vector_alloc(m4);
        for (int i = 0; i < m4; i++)
            for (int j = 0; j < m4; j++) {
                double t = 0;
                for (int dd = 0; dd < n; dd++) t += Ee[(size_t)i * n + dd] * Me[(size_t)j * n + dd];
                gsl_matrix_set(C, i, j, t);
            }
        gsl_eigen_symmv_workspace *ws = gsl_eigen_symmv_alloc(m4);
        gsl_eigen_symmv(C, ev, Z, ws);
        gsl_eigen_symmv_sort(ev, Z, GSL_EIGEN_SORT_VAL_DESC);
        double tot = 0;
        for (int i = 0; i < m4; i++) tot += fmax(gsl_vector_get(ev, i), 0);
        printf("POD of the error off V + K0^-1 W: shares");
        for (int k = 0; k < 12; k++) printf(" %.3f", gsl_vector_get(ev, k) / tot);
        printf("\n");
        for (int k = 0; k < 12 && k < m4; k++) {
            double *y = S + (size_t)(nlin + 1 + k) * n;
            memset(y, 0, (size_t)n * sizeof(double));
            for (int j = 0; j < m4; j++)
                for (int dd = 0; dd < n; dd++) y[dd] += gsl_matrix_get(Z, j, k) * Ee[(size_t)j * n + dd];
            double f[4];
            fam(rod, qeq, y, f);
            double ft = f[0] + f[1] + f[2] + f[3];
            if (k < 3) printf("  POD %d: family shares v %.3f h %.3f t %.3f a %.3f\n", k + 1, f[0] / ft, f[1] / ft, f[2] / ft, f[3] / ft);
            npod++;
        }
        gsl_matrix_free(C), gsl_matrix_free(Z), gsl_vector_free(ev), gsl_eigen_symmv_free(ws);
        free(Ee), free(Me);
    }
    basis bl = b0;
    bl.V = malloc((size_t)n * b0.r * sizeof(double)), bl.MV = malloc((size_t)n * b0.r * sizeof(double));
    memcpy(bl.V, b0.V, (size_t)n * b0.r * sizeof(double)), memcpy(bl.MV, b0.MV, (size_t)n * b0.r * sizeof(double));
    for (int k = 0; k < nlift; k++) {
        b_append(&bl, S + (size_t)k * n, 1e-6);
        char lab[32];
        snprintf(lab, sizeof lab, "+lift%d", k + 1);
        measure(&bl, U, tU, ns, lab);
    }
    for (int k = nlift; k < ndrop; k++) b_append(&bl, S + (size_t)k * n, 1e-6);
    measure(&bl, U, tU, ns, "+drop");
    for (int k = ndrop; k < nlin; k++) b_append(&bl, S + (size_t)k * n, 1e-6);
    measure(&bl, U, tU, ns, "+blown");
    {
        basis bk = b0;
        bk.V = malloc((size_t)n * b0.r * sizeof(double)), bk.MV = malloc((size_t)n * b0.r * sizeof(double));
        memcpy(bk.V, b0.V, (size_t)n * b0.r * sizeof(double)), memcpy(bk.MV, b0.MV, (size_t)n * b0.r * sizeof(double));
        b_append(&bk, S + (size_t)nlin * n, 1e-6);
        measure(&bk, U, tU, ns, "+K0^-1W");
        b_append(&bk, S, 1e-6);
        measure(&bk, U, tU, ns, "+lift1");
    }

    {
        double ref[4] = {Tmin, Tmax, zmin, zmax}, hh = dop.h;
        plain(d, hh, NULL, 0, 1, 0, 0, ref, "base");
        plain(d, hh, NULL, 0, 0, 0, 0, ref, "base");
        plain(d, hh, S + (size_t)nlin * n, 1, 1, 0, 0, ref, "K0^-1W");
        plain(d, hh, S + (size_t)nlin * n, 1, 0, 0, 0, ref, "K0^-1W");
        plain(d, hh, S + (size_t)nlin * n, 1 + npod, 0, 0, 0, ref, "W+pod12");
        plain(d, hh, NULL, 0, 1, 0.5, 0, ref, "hybrid.5");
        plain(d, hh, NULL, 0, 1, 0.8, 0, ref, "hybrid.8");
        plain(d, hh, NULL, 0, 1, 0.5, 1, ref, "hybridK.5");
        plain(d, hh, NULL, 0, 1, 0.8, 1, ref, "hybridK.8");
        plain(d, hh, S + (size_t)nlin * n, 1, 1, 0.8, 1, ref, "W+hybridK.8");
    }
    if (dorun) {
        gal_sim_result rf, rr;
        if (gal_sim_run(&s, GAL_MODEL_FULL, &rf)) { fprintf(stderr, "%s\n", gal_error_message()); return 1; }
        int pz = -1;
        for (int k = 0; k < rf.nprobe; k++)
            if (fabs(rf.probe[k] - 0.5) < 1e-9) pz = k;
        if (pz < 0) pz = 0;
        double fT[2], fz[2], T[2], z[2];
        extremes(&rf, pz, fT, fz);
        printf("RUN full: T %.0f .. %.0f N, probe %.2f vertical %.3f .. %.3f m\n", fT[0], fT[1], rf.probe[pz], fz[0], fz[1]);
        if (!gal_sim_run(&s, GAL_MODEL_REDUCED, &rr)) { /* the CLI's path (integrator_rom.c) */
            extremes(&rr, pz, T, z);
            printf("SIM reduced basis %d->%d: T %.0f .. %.0f N (largest %+.1f%%), vertical %.3f .. %.3f m (%+.1f%%, %+.1f%%), "
                   "residual %.3f, valid %d %s\n", rr.basis_start, rr.basis, T[0], T[1], 100 * (T[1] - fT[1]) / fT[1], z[0], z[1],
                   100 * (z[0] - fz[0]) / fabs(fz[0]), 100 * (z[1] - fz[1]) / fabs(fz[1]), rr.residual_max, rr.valid, rr.invalid_why);
            gal_sim_result_clear(&rr);
        } else printf("SIM reduced: %s\n", gal_error_message());
        static const char *gl[] = {"base", "lift.25", "lift.95", "lift", "K0^-1W", "blown", "W+pod2", "W+pod4", "W+pod8", "W+pod12"};
        int gn[] = {0, 1, 1, nlift, 1, 2, 3, 5, 9, 1 + npod}, g0[] = {0, 0, 3, 0, nlin, ndrop, nlin, nlin, nlin, nlin};
        for (int g = 0; g < 10; g++) {
            gal_rom_sim_opts o;
            gal_rom_sim_info info;
            gal_rom_sim_default_opts(&o);
            o.extra = gn[g] ? S + (size_t)g0[g] * n : NULL, o.nextra = gn[g];
            if (gal_rom_sim_run(&s, &o, &rr, &info)) { printf("RUN %s: %s\n", gl[g], gal_error_message()); continue; }
            extremes(&rr, pz, T, z);
            printf("RUN %-9s basis %d->%d: T %.0f .. %.0f N (largest %+.1f%%), vertical %.3f .. %.3f m (%+.1f%%, %+.1f%%), "
                   "residual %.3f, taut share %.3f, valid %d\n",
                   gl[g], info.basis_start, info.basis, T[0], T[1], 100 * (T[1] - fT[1]) / fT[1], z[0], z[1],
                   100 * (z[0] - fz[0]) / fabs(fz[0]), 100 * (z[1] - fz[1]) / fabs(fz[1]), info.residual_max,
                   info.taut_share, info.valid);
            gal_sim_result_clear(&rr);
        }
        gal_sim_result_clear(&rf);
    }
    return 0;
}
