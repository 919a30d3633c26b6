/* test_rom_rates.c: the rates the reduced model's self-check uses (gal_rom_full_rates, rom.h): the
 * acceleration is the reduced equations' own at the state (V^T M a = fe - Cr v - fi), not the
 * generalized-alpha's a, which lags it by the step's truncation error (undamped with rho_inf = 1:
 * the lag of the stiff coordinates never decays). Hyper-reduced (the default) and every element. */
#include "check.h"
#include "gallop.h"
#include "gallop/modes/modes.h"
#include "gallop/reduced/rom.h"
#include "gallop/statics/statics.h"
#include "rom_sagged.h"


/* Free vibration from a large displacement of every mode, a Rayleigh damping, `steps` steps; then
 * V^T M a (a from gal_rom_full_rates) against fe - Cr v - fi at the state (no loads: fe = 0). */
static void rates_at(int hyper)
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
    gal_damping *C = gal_damping_rayleigh_alloc(eq.rod, eq.q, 0.05, 0.002);
    o.damping = C, o.hyper = hyper, o.h = 0.05;
    gal_rom *m = gal_rom_alloc(eq.rod, eq.q, &md, sel, ns, &o, NULL);
    CHECK(m != NULL, "%s", gal_error_message());
    if (!m) { gal_damping_free(C); gal_modes_clear(&md); gal_equilibrium_clear(&eq); return; }
    int r = m->r, n = m->ndof, nq = m->nq;
    double *q = malloc(nq * sizeof(double)), *vf = malloc(3 * n * sizeof(double)), *af = vf + n, *u = af + n;
    double *Ma = malloc(n * sizeof(double)), *fi = malloc(r * sizeof(double));
    for (int k = 0; k < m->nmodes; k++) m->x[k] = 0.3 * sqrt(sagged.mass * sagged.length) / (k + 1);
    gal_rom_reconstruct(m, q, NULL);
    CHECK(gal_rom_start(m, 0, q, NULL) == GAL_OK, "%s", gal_error_message());
    for (int s = 0; s < 40; s++) CHECK(gal_rom_step(m) == GAL_OK, "%s", gal_error_message());
    gal_rom_full_rates(m, vf, af, u);
    gal_rod_mass_mult(eq.rod, af, Ma);
    CHECK(gal_rom_internal_force(m, m->x, fi) == GAL_OK, "%s", gal_error_message());
    double err = 0, lag = 0, scale = 0;
    for (int k = 0; k < r; k++) {
        double pa = 0, cv = 0;
        for (int d = 0; d < n; d++) pa += m->V[(size_t)k * n + d] * Ma[d];
        for (int j = 0; j < r; j++) cv += m->Cr[k * r + j] * m->v[j];
        double want_a = -cv - fi[k];
        err = fmax(err, fabs(pa - want_a)), lag = fmax(lag, fabs(m->a[k] - want_a)), scale = fmax(scale, fabs(want_a));
    }
    printf("    (%s, basis %d: V^T M a off by %.1e of %.2e; the integrator's a by %.1e)\n",
           hyper ? "sampled elements" : "every element", r, err, scale, lag);
    CHECK(err <= 1e-9 * scale, "V^T M a vs fe - Cr v - fi: %g of %g", err, scale);
    free(q), free(vf), free(Ma), free(fi);
    gal_rom_free(m);
    gal_damping_free(C);
    gal_modes_clear(&md);
    gal_equilibrium_clear(&eq);
}

static void test_rates_sampled(void) { rates_at(1); }
static void test_rates_every_element(void) { rates_at(0); }

int main(void)
{
    RUN(test_rates_sampled);
    RUN(test_rates_every_element);
    return CHECK_SUMMARY();
}
