/* test_rom_recon.c: the reduced model's reconstruction of the whole rod (q = q_eq + V x, v = V x')
 * and its projection of a whole-rod force (f = V^T g), as the self-check, the exact forces and the
 * loads over every edge use them (rom.c): four columns a pass, but each entry's sum over the columns
 * in order and a column whose coefficient is 0 left out -- the numbers of one column at a time, bit
 * for bit, whatever zeros the coordinates hold and however many columns are left over. */
#include <string.h>

#include "check.h"
#include "gallop.h"
#include "gallop/modes/modes.h"
#include "gallop/reduced/rom.h"
#include "gallop/statics/statics.h"
#include "rom_sagged.h"


/* coordinates with zeros at the given pattern: k % 7 == z0 (in x) and k % 5 == z1 (in x') */
static void coords(gal_rom *m, int z0, int z1)
{
    for (int k = 0; k < m->r; k++) {
        m->x[k] = k % 7 == z0 ? 0 : 0.01 * sin(1.0 + k) / (1 + 0.1 * k);
        m->v[k] = k % 5 == z1 ? 0 : 0.03 * cos(2.0 + 0.7 * k);
    }
}

static void test_reconstruct_and_project_bitwise(void)
{
    gal_equilibrium eq;
    gal_modes md;
    int want[GAL_FAMILY_COUNT] = {3, 2, 1, 0}, sel[16], ns = 0;
    if (sagged_setup_modes(&eq, &md, want, 60, sel, 16, &ns)) {
        CHECK(0, "%s", gal_error_message());
        return;
    }
    gal_rom_opts o;
    gal_rom_default_opts(&o);
    o.hyper = 0, o.h = 0.05; /* every element: the internal force is the whole rod's, projected */
    gal_rom *m = gal_rom_alloc(eq.rod, eq.q, &md, sel, ns, &o, NULL);
    CHECK(m != NULL, "%s", gal_error_message());
    if (!m) { gal_modes_clear(&md); gal_equilibrium_clear(&eq); return; }
    int r = m->r, n = m->ndof, nq = m->nq;
    const int *fq = m->rod->free_q;
    CHECK(r % 4 != 0, "the basis (%d) leaves columns over a pass of four", r);
    double *q = malloc(2 * nq * sizeof(double)), *v = q + nq, *s = malloc(2 * n * sizeof(double)), *sv = s + n;
    double *f = malloc(2 * r * sizeof(double)), *fw = f + r, *g = malloc(nq * sizeof(double));
    int patterns[4][2] = {{-1, -1}, {0, 3}, {2, -1}, {-1, 4}}, bad_q = 0, bad_f = 0;
    for (int p = 0; p < 4; p++) {
        coords(m, patterns[p][0], patterns[p][1]);
        gal_rom_reconstruct(m, q, v);
        memset(s, 0, 2 * n * sizeof(double));
        for (int k = 0; k < r; k++) { /* one column at a time */
            const double *vk = m->V + (size_t)k * n;
            if (m->x[k] != 0) for (int d = 0; d < n; d++) s[d] += vk[d] * m->x[k];
            if (m->v[k] != 0) for (int d = 0; d < n; d++) sv[d] += vk[d] * m->v[k];
        }
        for (int d = 0; d < n; d++) {
            double qd = m->q_eq[fq[d]] + s[d];
            bad_q += memcmp(&q[fq[d]], &qd, sizeof qd) != 0 || memcmp(&v[fq[d]], &sv[d], sizeof(double)) != 0;
        }
        /* the projected internal force against the whole rod's gradient projected a column at a time */
        CHECK(gal_rom_internal_force(m, m->x, f) == GAL_OK, "%s", gal_error_message());
        double U;
        CHECK(gal_rod_eval(m->rod, q, &U, g, NULL) == GAL_OK, "%s", gal_error_message());
        for (int k = 0; k < r; k++) {
            double sk = 0;
            for (int d = 0; d < n; d++) sk += m->V[(size_t)k * n + d] * g[fq[d]];
            fw[k] = sk;
        }
        bad_f += memcmp(f, fw, r * sizeof(double)) != 0;
    }
    printf("    (basis %d, %d entries: 4 patterns of zeros; entries that differ: %d, forces that differ: %d)\n", r, n,
           bad_q, bad_f);
    CHECK(bad_q == 0, "%d reconstructed entries differ from one column at a time", bad_q);
    CHECK(bad_f == 0, "%d projected forces differ from one column at a time", bad_f);
    free(q), free(s), free(f), free(g);
    gal_rom_free(m);
    gal_modes_clear(&md);
    gal_equilibrium_clear(&eq);
}

int main(void)
{
    RUN(test_reconstruct_and_project_bitwise);
    return CHECK_SUMMARY();
}
