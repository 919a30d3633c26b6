/* diag_weight.c: how much of the static load responses the reduced basis of modes and modal
 * derivatives already holds (BENCHMARKS.md "The weight's and the mean wind's static responses in
 * the reduced basis", helper weight, session 11). For the scene at its selection and the given mesh:
 * x = K0^-1 f for f the weight's load (gravity and eccentric-ice terms at the equilibrium) and the
 * mean wind's (gal_loads_mean), and for the default basis and the basis with o.weight_vector and
 * o.wind_vector on:
 *   M       the mass-norm share of x outside span V (V^T M V = I)
 *   energy  1 - (V^T f)^T K0r^-1 (V^T f) / (x^T f): the share of the static compliance the reduced
 *           statics misses (the linear static sag error of the reduced model)
 * Usage: build/bench/diag_weight SCENE ELEMENTS */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gallop.h"
#include "gallop/reduced/rom.h"
#include "gallop/run/forward.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"
#include "base/chol.h"

#include "diag_weight.h"

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: %s SCENE ELEMENTS\n", argv[0]);
        return 2;
    }
    char el[64];
    snprintf(el, sizeof el, "model.elements=%s", argv[2]);
    const char *ov[] = {el};
    gal_scene sc;
    gal_sim_setup s;
    if (gal_scene_load(&sc, argv[1], ov, 1, "data/conductors.csv") || gal_sim_setup_init(&s, &sc, 1) ||
        gal_forward(s.model, s.data, GAL_STAGE_REDUCED)) {
        fprintf(stderr, "%s: %s\n", argv[1], gal_error_message());
        return 1;
    }
    gal_data *d = s.data;
    const gal_rod *rod = d->eq.rod;
    int n = rod->ndof, nq = rod->nq, st = 0;
    double *fq = calloc((size_t)3 * nq, sizeof(double)), *g = fq + nq, *fm = g + nq;
    double *F = malloc((size_t)4 * n * sizeof(double)), *X = F + 2 * n;
    for (int k = 0; k < rod->nterm && !st; k++)
        if (rod->term[k] == &gal_rod_term_gravity || rod->term[k] == &gal_rod_term_ice) {
            double U = 0;
            st = gal_rod_eval_term(rod, k, d->eq.q, &U, g, NULL);
            for (int i = 0; i < nq; i++) fq[i] += g[i];
        }
    if (!st && d->loads.table) st = gal_loads_mean(&d->loads, d->eq.q, fm);
    gal_rod_gather(rod, fq, F), gal_rod_gather(rod, fm, F + n);
    gal_rom *m[2] = {NULL, NULL};
    for (int k = 0; k < 2 && !st; k++) {
        gal_rom_opts ro;
        gal_rom_default_opts(&ro);
        ro.weight_vector = ro.wind_vector = k, ro.mean_load = fm, ro.damping = d->damping;
        gal_force Fo = {gal_loads_full, (void *)&d->loads, gal_loads_element, gal_loads_full_framed};
        if (!(m[k] = gal_rom_alloc(rod, d->eq.q, &d->md, d->sel, d->basis, &ro, &Fo))) st = 1;
    }
    for (int j = 0; j < 2 && !st; j++) st = gal_chol_solve(m[0]->chol0, F + (size_t)j * n, X + (size_t)j * n);
    if (st) {
        fprintf(stderr, "%s: %s\n", argv[1], gal_error_message());
        return 1;
    }
    for (int k = 0; k < 2; k++)
        printf("%s %s basis %d%s: K0^-1 W outside: M %.3g energy %.3g; K0^-1 F_mean outside: M %.3g energy %.3g\n",
               argv[1], argv[2], m[k]->r, k ? " (weight and wind vectors)" : " (default)", rom_m_share(m[k], X),
               rom_energy_share(m[k], F, X), rom_m_share(m[k], X + n), rom_energy_share(m[k], F + n, X + n));
    gal_rom_free(m[0]), gal_rom_free(m[1]);
    free(fq), free(F);
    gal_sim_setup_clear(&s);
    return 0;
}
