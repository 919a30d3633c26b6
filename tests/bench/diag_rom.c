/* diag_rom.c: why the recomputed reduced model misses a span: the full model's trajectory over
 * the second half of the run projected on the reduced basis (V^T M u), the share of the
 * displacement the basis misses per family (mass norm), the computed modes that carry the miss,
 * and the self-check's residual at the projected full states. Usage:
 *   diag_rom SCENE [--set key=value]...   (built by hand like the bench programs) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gallop.h"
#include "gallop/base/core.h"
#include "gallop/full/dynamics.h"
#include "gallop/reduced/rom.h"
#include "gallop/output/simreport.h"
#include "gallop/reduced/rom_sim.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"

/* mass-norm^2 per family (v, h, t, a) of the free-dof vector y, families as in rom_check.c */
static void fam(const gal_rod *rod, const double *qeq, const double *y, double acc[4])
{
    memset(acc, 0, 4 * sizeof(double));
    for (int i = 0; i < rod->nn; i++) {
        int d0 = rod->dof[3 * i];
        if (d0 < 0) continue;
        double t[3], ey[3], nv[3];
        gal_rod_node_directions(rod, qeq, i, t, ey, nv);
        double w = rod->mdiag[d0];
        double yv = gal_dot3(nv, y + d0), yh = gal_dot3(ey, y + d0), ya = gal_dot3(t, y + d0);
        acc[0] += w * yv * yv, acc[1] += w * yh * yh, acc[3] += w * ya * ya;
    }
    if (rod->p.torsion)
        for (int j = 0; j < rod->p.elements; j++) {
            int d = rod->dof[3 * rod->nn + j];
            if (d >= 0) acc[2] += y[d] * y[d] * rod->mdiag[d];
        }
}

static void print_modes(const gal_modes *md, int r)
{
    printf("modes computed %d, in the basis %d:", md->n, r);
    for (int k = 0; k < md->n; k++)
        printf(" %d%s(%c %.3f Hz)", k, md->mode[k].selected ? "*" : "", gal_family_names[md->mode[k].family][0],
               md->mode[k].frequency_hz);
    printf("\n");
}

/* e = u - V V^T M u: the part of the displacement u (free dofs) the basis misses; Mu: work. */
static void miss(const gal_rom *m, const double *u, double *Mu, double *e)
{
    int n = m->ndof;
    gal_rod_mass_mult(m->rod, u, Mu);
    memcpy(e, u, n * sizeof(double));
    for (int j = 0; j < m->r; j++) {
        double x = 0;
        for (int k = 0; k < n; k++) x += m->V[(size_t)j * n + k] * Mu[k];
        for (int k = 0; k < n; k++) e[k] -= x * m->V[(size_t)j * n + k];
    }
}

/* The reduced model with the full run's misses added to its basis (an oracle basis), measured
 * against the full run on its window. */
static void oracle(gal_sim_setup *s, const double *snap, int nsnap)
{
    gal_sim_result rf, rr;
    gal_rom_sim_info info;
    gal_rom_sim_opts o;
    gal_rom_sim_default_opts(&o);
    o.tolerance = 0, o.extra = snap, o.nextra = nsnap;
    if (gal_sim_run(s, GAL_MODEL_FULL, &rf) || gal_rom_sim_run(s, &o, &rr, &info)) {
        fprintf(stderr, "%s\n", gal_error_message());
        return;
    }
    gal_compare_ref h; /* measured as `gallop compare` measures */
    gal_sim_measures mf, mr;
    gal_compare_reference(&rf, -1, &h);
    gal_compare_measure(&rf, &h, &mf);
    gal_compare_measure(&rr, &h, &mr);
    printf("oracle basis %d (+%d misses): f %.4f/%.4f v %.3f/%.3f h %.3f/%.3f tw %.1f/%.1f T %.0f/%.0f res %.3g\n",
           info.basis, nsnap, mr.frequency_hz[1], mf.frequency_hz[1], mr.peak_to_peak[1], mf.peak_to_peak[1],
           mr.peak_to_peak[0], mf.peak_to_peak[0], mr.peak_to_peak[3], mf.peak_to_peak[3], mr.tension_max_steady,
           mf.tension_max_steady, info.residual_max);
    gal_sim_result_clear(&rf);
    gal_sim_result_clear(&rr);
}

int main(int argc, char **argv)
{
    const char *ov[32];
    int nov = 0, nextra = 0;
    for (int i = 2; i < argc; i++)
        if (!strcmp(argv[i], "--set") && i + 1 < argc) ov[nov++] = argv[++i];
        else if (!strcmp(argv[i], "--extra") && i + 1 < argc) nextra = atoi(argv[++i]);
    gal_scene sc;
    gal_sim_setup s;
    if (argc < 2 || gal_scene_load(&sc, argv[1], ov, nov, NULL) || gal_sim_setup_init(&s, &sc, 1)) {
        fprintf(stderr, "%s\n", gal_error_message());
        return 1;
    }
    gal_data *d = s.data;
    const gal_rod *rod = d->eq.rod;
    const gal_modes *md = &d->md;
    int sel[64], r = 0, n = rod->ndof;
    double fhi = 0;
    for (int k = 0; k < md->n; k++)
        if (md->mode[k].selected) sel[r++] = k, fhi = fmax(fhi, md->mode[k].frequency_hz);
    /* --extra N: the next N computed modes (by frequency, not selected) join the basis */
    for (int k = 0; k < md->n && nextra > 0; k++)
        if (!md->mode[k].selected && md->mode[k].frequency_hz > 0.01) sel[r++] = k, nextra--;
    print_modes(md, r);
    double dt_out = sc.simulation.output_interval > 0 ? sc.simulation.output_interval : fmin(0.05, 1 / (10 * fhi));
    double h = sc.simulation.time_step > 0 ? sc.simulation.time_step : fmin(dt_out, 1 / (40 * fhi));
    h = dt_out / ceil(dt_out / h - 1e-9);
    gal_rom_opts ro;
    gal_rom_default_opts(&ro);
    ro.h = h, ro.damping = d->damping, ro.rho_inf = sc.simulation.rho_inf;
    gal_force F = {0};
    if (d->loads.table) F.eval = gal_loads_full, F.ctx = (void *)&d->loads;
    gal_rom *m = gal_rom_alloc(rod, d->eq.q, md, sel, r, &ro, &F);
    gal_dyn_opts go;
    gal_dyn_default_opts(&go);
    go.h = h, go.rho_inf = sc.simulation.rho_inf, go.damping = d->damping;
    gal_dyn *dyn = gal_dyn_alloc(rod, d->q_start, NULL, &go, &F);
    if (!m || !dyn) { fprintf(stderr, "%s\n", gal_error_message()); return 1; }
    printf("basis %d\n", m->r);
    double *u = malloc(n * sizeof(double)), *Mu = malloc(n * sizeof(double)), *e = malloc(n * sizeof(double));
    double *me = calloc(md->n, sizeof(double));
    double T = sc.simulation.duration, next = T / 2, emax[4] = {0}, ru[4] = {0}, resmax = 0, resf[4] = {0};
    int cnt = 0, nsnap = 0, snapmax = 64;
    double *snap = malloc((size_t)n * snapmax * sizeof(double)), snap_next = T - 8;
    while (dyn->t < T - 1e-9) {
        if (gal_dyn_step(dyn)) { fprintf(stderr, "full: %s\n", gal_error_message()); return 1; }
        if (dyn->t >= snap_next - 1e-9 && nsnap < snapmax) { /* the miss over the last 8 s, every 0.25 s */
            snap_next += 0.25;
            for (int k = 0; k < n; k++) u[k] = dyn->q[rod->free_q[k]] - d->eq.q[rod->free_q[k]];
            miss(m, u, Mu, snap + (size_t)nsnap++ * n);
        }
        if (dyn->t < next - 1e-9) continue;
        next += 1.0;
        for (int k = 0; k < n; k++) u[k] = dyn->q[rod->free_q[k]] - d->eq.q[rod->free_q[k]];
        miss(m, u, Mu, e);
        double ae[4], au[4];
        fam(rod, d->eq.q, e, ae);
        fam(rod, d->eq.q, u, au);
        double tot = au[0] + au[1] + au[2] + au[3];
        for (int f = 0; f < 4; f++) {
            double rel = sqrt(ae[f]) / fmax(sqrt(au[f]), 0.02 * sqrt(tot));
            emax[f] = fmax(emax[f], rel), ru[f] += rel;
        }
        gal_rod_mass_mult(rod, e, Mu);
        for (int k = 0; k < md->n; k++) {
            double c = 0;
            for (int j = 0; j < n; j++) c += md->shape[(size_t)k * n + j] * Mu[j];
            me[k] += c * c;
        }
        gal_rom_start(m, dyn->t, dyn->q, dyn->v);
        gal_rom_check chk;
        gal_rom_residual(m, &chk);
        resmax = fmax(resmax, chk.max);
        for (int f = 0; f < 4; f++) resf[f] = fmax(resf[f], chk.rel[f]);
        cnt++;
    }
    printf("missed share (mass norm, per family, mean/max over %d states): ", cnt);
    for (int f = 0; f < 4; f++) printf("%s %.3f/%.3f  ", gal_family_names[f], ru[f] / cnt, emax[f]);
    printf("\nresidual at the projected full states: max %.3f [v %.3f h %.3f t %.3f a %.3f]\n", resmax, resf[0],
           resf[1], resf[2], resf[3]);
    printf("miss carried by the computed modes (mean squared modal coordinate of the miss, per mode):");
    for (int k = 0; k < md->n; k++) printf(" %d:%.3g", k, me[k] / cnt);
    printf("\n");
    oracle(&s, snap, nsnap);
    return 0;
}
