/* test_rom_weight.c: the static load responses of the reduced basis (rom.h o.weight_vector,
 * o.wind_vector; rom_basis.c load_vectors): with them on, the basis holds the linear static
 * response to the span's weight K0^-1 W (the node weights and the eccentric ice's moment) and to
 * the mean wind's load K0^-1 F_mean to round-off, each one more vector; without them it does not.
 * W is taken here from the node masses and, for the twist, from central differences of the ice
 * term's energy, not from the library's gradient. The case: iced_gallop at 40 elements with an
 * eccentric accretion (ice.eccentricity = 0.02 m). */
#include "check.h"
#include "sim_fixture.h"
#include "gallop.h"
#include "base/chol.h"
#include "bench/diag_weight.h"

/* The weight's load over the free dofs: m_i g on the vertical entries, the ice moment on the twists
 * by central differences (step 1e-6 rad) of the ice term's energy at q. */
static void weight_load(const gal_rod *rod, const double *q, double *w, double *twist_share)
{
    int nq = rod->nq, ice = -1;
    for (int k = 0; k < rod->nterm; k++)
        if (rod->term[k] == &gal_rod_term_ice) ice = k;
    double *qp = malloc((size_t)nq * sizeof(double)), tw = 0, all = 0;
    memcpy(qp, q, (size_t)nq * sizeof(double));
    memset(w, 0, (size_t)rod->ndof * sizeof(double));
    for (int i = 0; i < rod->nn; i++)
        if (rod->dof[3 * i + 2] >= 0) w[rod->dof[3 * i + 2]] = rod->node_mass[i] * rod->p.gravity;
    for (int j = 0; ice >= 0 && j < rod->p.elements; j++) {
        int k = 3 * rod->nn + j, d = rod->dof[k];
        if (d < 0) continue;
        double Up = 0, Um = 0, e = 1e-6;
        qp[k] = q[k] + e;
        gal_rod_eval_term(rod, ice, qp, &Up, NULL, NULL);
        qp[k] = q[k] - e;
        gal_rod_eval_term(rod, ice, qp, &Um, NULL, NULL);
        qp[k] = q[k];
        w[d] = (Up - Um) / (2 * e);
    }
    for (int d = 0; d < rod->ndof; d++) {
        all += w[d] * w[d];
        if (rod->free_q[d] >= 3 * rod->nn) tw += w[d] * w[d];
    }
    *twist_share = sqrt(tw / all);
    free(qp);
}

static void test_load_vectors_in_basis(void)
{
    const char *ov[] = {"model.elements=40", "ice.eccentricity=0.02"};
    gal_scene sc;
    gal_sim_setup s;
    gal_data *d = forward_fixture(&sc, &s, "data/scenes/iced_gallop.ini", ov, 2);
    if (!d) return;
    const gal_rod *rod = d->eq.rod;
    int n = rod->ndof, nq = rod->nq;
    double *w = malloc((size_t)2 * n * sizeof(double)), *xw = w + n, *fm = calloc((size_t)nq, sizeof(double));
    double twist = 0;
    weight_load(rod, d->eq.q, w, &twist);
    CHECK(twist > 1e-4, "the ice's moment is part of the weight's load: twist share %g", twist);
    CHECK(gal_loads_mean(&d->loads, d->eq.q, fm) == GAL_OK, "%s", gal_error_message());
    gal_rom *m[3] = {NULL, NULL, NULL};
    for (int k = 0; k < 3; k++) {
        gal_rom_opts ro;
        gal_rom_default_opts(&ro);
        ro.weight_vector = k >= 1, ro.wind_vector = k == 2, ro.mean_load = fm;
        m[k] = rom_fixture(&s, &ro);
    }
    if (m[0] && m[1] && m[2]) {
        CHECK(m[1]->r == m[0]->r + 1 && m[2]->r == m[0]->r + 2, "basis sizes %d, %d, %d", m[0]->r, m[1]->r, m[2]->r);
        double *xf = malloc((size_t)n * sizeof(double));
        gal_rod_gather(rod, fm, xf);
        CHECK(gal_chol_solve(m[0]->chol0, w, xw) == GAL_OK && gal_chol_solve(m[0]->chol0, xf, xf) == GAL_OK, "%s",
              gal_error_message());
        double ow[3], of[3];
        for (int k = 0; k < 3; k++) ow[k] = rom_m_share(m[k], xw), of[k] = rom_m_share(m[k], xf);
        printf("    K0^-1 W outside the basis: %.3g (modes and derivatives), %.3g (+ weight), %.3g (+ wind); "
               "K0^-1 F_mean: %.3g, %.3g, %.3g; the weight's twist share %.3g\n", ow[0], ow[1], ow[2], of[0], of[1],
               of[2], twist);
        CHECK(ow[0] > 1e-5 && of[0] > 1e-3 && of[1] > 1e-3, "the modes and derivatives lack them past the deflation: %g, %g, %g", ow[0],
              of[0], of[1]);
        CHECK(ow[1] < 1e-9 && ow[2] < 1e-9, "K0^-1 W is in the basis to round-off: %g, %g", ow[1], ow[2]);
        CHECK(of[2] < 1e-9, "K0^-1 F_mean is in the basis to round-off: %g", of[2]);
        free(xf);
    }
    for (int k = 0; k < 3; k++) gal_rom_free(m[k]);
    free(w), free(fm);
    gal_sim_setup_clear(&s);
}

int main(void)
{
    RUN(test_load_vectors_in_basis);
    return CHECK_SUMMARY();
}
