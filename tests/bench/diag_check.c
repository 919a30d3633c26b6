/* diag_check.c: the calibration of the reduced model's self-check (rom_check.c, issue 13): per
 * case (scene, elements, modes per family, hyper-reduction on/off) the full model once (cached in
 * CACHE) and the reduced model on its initial basis (no adaptation), its checks every second
 * written raw (per family: |du| and |u| in the mass norm), and its true amplitude errors against
 * the full model on the same steady window. Usage:
 *   diag_check CACHE SCENE ELEMENTS MV MH MT HYPER [DURATION [TOLERANCE]]
 * Prints CASE| (errors), CHK| (t, err[4], disp[4], max), REL| (t, the adaptation's norm per family,
 * its max) and PRB| (t, du and u at mid-span: vertical, horizontal, twist) lines. With TOLERANCE > 0
 * the basis grows past it as in a run (GROW| lines), from the initial basis otherwise. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gallop.h"
#include "gallop/base/core.h"
#include "gallop/reduced/rom_adapt.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"

/* the full run's measures and its window and probes (measured as `gallop compare` measures), cached */
static int full_measures(const char *cache, gal_sim_setup *s, gal_sim_measures *mf, gal_compare_ref *h)
{
    FILE *f = fopen(cache, "rb");
    if (f) {
        int ok = fread(mf, sizeof *mf, 1, f) == 1 && fread(h, sizeof *h, 1, f) == 1;
        fclose(f);
        if (ok) return 0;
    }
    gal_sim_result rf;
    if (gal_sim_run(s, GAL_MODEL_FULL, &rf)) return 1;
    gal_compare_reference(&rf, -1, h);
    gal_compare_measure(&rf, h, mf);
    gal_sim_result_clear(&rf);
    if ((f = fopen(cache, "wb"))) fwrite(mf, sizeof *mf, 1, f), fwrite(h, sizeof *h, 1, f), fclose(f);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 8) return 2;
    char kv[5][64];
    const char *ov[5];
    snprintf(kv[0], 64, "model.elements=%s", argv[3]);
    snprintf(kv[1], 64, "model.modes_vertical=%s", argv[4]);
    snprintf(kv[2], 64, "model.modes_horizontal=%s", argv[5]);
    snprintf(kv[3], 64, "model.modes_torsional=%s", argv[6]);
    snprintf(kv[4], 64, "simulation.duration=%s", argc > 8 ? argv[8] : "300");
    for (int k = 0; k < 5; k++) ov[k] = kv[k];
    gal_scene sc;
    gal_sim_setup s;
    if (gal_scene_load(&sc, argv[2], ov, 5, NULL) || gal_sim_setup_init(&s, &sc, 1)) {
        printf("ERR|%s\n", gal_error_message());
        return 1;
    }
    gal_sim_measures mf, mr;
    gal_compare_ref href;
    if (full_measures(argv[1], &s, &mf, &href)) { printf("ERR|full %s\n", gal_error_message()); return 1; }
    const gal_data *d = s.data;
    const gal_rod *rod = d->eq.rod;
    int sel[64], r = 0;
    double fhi = 0;
    for (int k = 0; k < d->md.n && r < 64; k++)
        if (d->md.mode[k].selected) sel[r++] = k, fhi = fmax(fhi, d->md.mode[k].frequency_hz);
    gal_sim_result res;
    memset(&res, 0, sizeof res);
    res.kind = GAL_MODEL_REDUCED;
    res.nprobe = sc.simulation.nprobes;
    memcpy(res.probe, sc.simulation.probes, sizeof res.probe);
    double dt_out = sc.simulation.output_interval;
    if (!(dt_out > 0)) dt_out = fmin(0.05, 1.0 / (10 * fhi));
    double h = sc.simulation.time_step;
    if (!(h > 0)) h = fmin(dt_out, 1.0 / (40 * fhi));
    int sub = (int)ceil(dt_out / h - 1e-9);
    long ns = (long)floor(sc.simulation.duration / dt_out + 1e-9) + 1;
    res.dt_out = dt_out, res.nsamples = ns;
    res.time = malloc(ns * sizeof(double));
    res.trace = calloc(ns * 4 * res.nprobe, sizeof(double));
    res.tension = calloc(ns * 2, sizeof(double));
    for (long i = 0; i < ns; i++) res.time[i] = i * dt_out;
    gal_rom_opts ro;
    gal_rom_default_opts(&ro);
    ro.h = dt_out / sub, ro.rho_inf = sc.simulation.rho_inf, ro.damping = d->damping;
    ro.hyper = atoi(argv[7]);
    gal_force F = {0};
    if (d->loads.table) F.eval = gal_loads_full, F.element = gal_loads_element, F.ctx = (void *)&d->loads;
    gal_rom_adapt a;
    gal_rom *m;
    int st = gal_rom_adapt_init(&a, &m, rod, d->eq.q, &d->md, sel, r, &ro, &F);
    if (!st) st = gal_rom_start(m, 0.0, d->q_start, d->v_start);
    double next = 0, tol = argc > 9 ? atof(argv[9]) : 0;
    gal_rom_check chk;
    double *du = malloc(3 * (size_t)rod->ndof * sizeof(double)), *vf = du + rod->ndof, *af = vf + rod->ndof;
    double *u = malloc((size_t)rod->ndof * sizeof(double));
    for (long i = 0; i < ns && !st; i++) {
        for (int k = 0; k < sub && i > 0 && !st; k++) st = gal_rom_step(m);
        if (st) break;
        gal_rom_observe(m, res.nprobe, res.probe, res.trace + i * 4 * res.nprobe, res.tension + 2 * i);
        if (m->t >= next - 1e-9) {
            if ((st = gal_rom_adapt_residual(&a, m, &chk, du))) break;
            gal_rom_full_rates(m, vf, af, u);
            int mid = rod->nn / 2, dm = rod->dof[3 * mid], dt = rod->dof[3 * rod->nn + rod->p.elements / 2];
            printf("PRB|%.3f|%.4g|%.4g|%.4g|%.4g|%.4g|%.4g\n", m->t, du[dm + 2], du[dm + 1], dt >= 0 ? du[dt] : 0,
                   u[dm + 2], u[dm + 1], dt >= 0 ? u[dt] : 0);
            printf("CHK|%.3f|%.4g|%.4g|%.4g|%.4g|%.4g|%.4g|%.4g|%.4g|%.4g\n", m->t, chk.err[0], chk.err[1], chk.err[2],
                   chk.err[3], chk.disp[0], chk.disp[1], chk.disp[2], chk.disp[3], chk.max);
            printf("REL|%.3f|%.4g|%.4g|%.4g|%.4g|%.4g\n", m->t, chk.rel[0], chk.rel[1], chk.rel[2], chk.rel[3], chk.max);
            for (int k = 0; k < 3; k++)
                printf("POW%d|%.3f|%.4g|%.4g|%.4g|%.4g\n", k, m->t, chk.power[k][0], chk.power[k][1], chk.power[k][2],
                       chk.power[k][3]);
            if (tol > 0 && chk.max > tol) {
                int g = gal_rom_adapt_grow(&a, &m, &chk, du);
                if (g == GAL_OK) printf("GROW|%.3f|%d|%d\n", m->t, a.ev[a.nevents - 1].family, m->r);
                else if (g != GAL_ROM_ELIMIT) st = g;
                else printf("LIMIT|%.3f|%s\n", m->t, gal_error_message());
            }
            next += 1;
        }
    }
    if (st) { printf("ERR|reduced %s\n", gal_error_message()); return 1; }
    gal_compare_measure(&res, &href, &mr);
    printf("CASE|%s|%s|%s|%s|%s|%s|r=%d|f %.5g %.5g|v %.5g %.5g|h %.5g %.5g|tw %.5g %.5g|T %.6g %.6g\n", argv[2],
           argv[3], argv[4], argv[5], argv[6], argv[7], m->r, mr.frequency_hz[1], mf.frequency_hz[1],
           mr.peak_to_peak[1], mf.peak_to_peak[1], mr.peak_to_peak[0], mf.peak_to_peak[0], mr.peak_to_peak[3],
           mf.peak_to_peak[3], mr.tension_max_steady, mf.tension_max_steady);
    free(du), free(u);
    free(res.time), free(res.trace), free(res.tension);
    gal_rom_free(m);
    gal_rom_adapt_clear(&a);
    gal_sim_setup_clear(&s);
    return 0;
}
