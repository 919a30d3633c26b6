/* test_rom_band.c: the self-check reads the oscillation that the reduced modes above the damping
 * band carry (rom_adapt.h, gal_rom_band_amplitude). Those vectors are Ritz approximations of modes
 * no structural damping reaches; ringing there leaves almost no residual (data/scenes/iced_gallop.ini
 * at 600 elements rang 2.4 deg of twist at 6.4 Hz, 19% of the twist, with the residual at 0.08;
 * BENCHMARKS.md, issue 13, helper growth2). Here, on iced_gallop at 100 elements: the modes found
 * are those above the band, and the amplitude of a ringing reduced mode is its velocity over its
 * frequency (or its acceleration over the frequency squared, a quarter period on), split by
 * family. */
#include "check.h"
#include "sim_fixture.h"
#include "gallop.h"
#include "gallop/run/sim.h"
#include "gallop/scene/scene.h"

#include <string.h>

/* the high reduced mode with the largest twist share */
static int twist_mode(const gal_rom_band *b)
{
    int k = -1;
    for (int j = 0; j < b->n; j++)
        if (k < 0 || b->share[j * GAL_FAMILY_COUNT + GAL_FAMILY_TORSIONAL] > b->share[k * GAL_FAMILY_COUNT + GAL_FAMILY_TORSIONAL])
            k = j;
    return k;
}

static void band_case(gal_data *d)
{
    gal_rom_opts ro;
    gal_rom_default_opts(&ro);
    ro.h = 0.01, ro.damping = d->damping;
    gal_rom *m = gal_rom_alloc(d->eq.rod, d->eq.q, &d->md, d->sel, d->basis, &ro, NULL);
    CHECK(m != NULL, "%s", gal_error_message());
    if (!m) return;
    CHECK(gal_rom_start(m, 0, d->eq.q, NULL) == GAL_OK, "%s", gal_error_message());
    double band = d->damping->band_hz, w2b = pow(2 * GAL_PI * band, 2);
    gal_rom_band b = {0};
    CHECK(gal_rom_band_init(m, band, &b) == GAL_OK, "%s", gal_error_message());
    CHECK(b.n > 0 && b.n < m->r, "%d of %d reduced modes above %g Hz", b.n, m->r, band);
    for (int k = 0; k < b.n; k++) CHECK(b.w2[k] > w2b, "mode %d at %g Hz", k, sqrt(b.w2[k]) / (2 * GAL_PI));
    int k = twist_mode(&b), r = m->r;
    if (k < 0) { gal_rom_band_clear(&b); gal_rom_free(m); return; }
    const double *sh = b.share + k * GAL_FAMILY_COUNT;
    double om = sqrt(b.w2[k]), amp[GAL_FAMILY_COUNT];
    printf("    %d reduced modes above %.2f Hz; the most torsional at %.3f Hz (twist share %.3f)\n", b.n, band,
           om / (2 * GAL_PI), sh[GAL_FAMILY_TORSIONAL]);
    CHECK(sh[GAL_FAMILY_TORSIONAL] > 0.3, "twist share %g", sh[GAL_FAMILY_TORSIONAL]);
    /* at rest: nothing; ringing at velocity s along the mode (no acceleration): s / omega, by family */
    double s = 0.7, ring = s / om; /* the ringing's mass-norm amplitude below */
    gal_rom_band_amplitude(m, &b, amp);
    for (int f = 0; f < GAL_FAMILY_COUNT; f++)
        CHECK(amp[f] <= 1e-6 * ring, "at rest: %s %g", gal_family_names[f], amp[f]);
    memset(m->a, 0, (size_t)r * sizeof(double));
    for (int i = 0; i < r; i++) m->v[i] = s * b.y[(size_t)k * r + i];
    gal_rom_band_amplitude(m, &b, amp);
    for (int f = 0; f < GAL_FAMILY_COUNT; f++)
        CHECK(fabs(amp[f] - ring * sqrt(sh[f])) <= 1e-10 * ring, "%s: %g against %g", gal_family_names[f], amp[f],
              ring * sqrt(sh[f]));
    /* a quarter period on: the same amplitude read from the acceleration alone */
    for (int i = 0; i < r; i++) m->a[i] = -om * m->v[i], m->v[i] = 0;
    double amp2[GAL_FAMILY_COUNT];
    gal_rom_band_amplitude(m, &b, amp2);
    for (int f = 0; f < GAL_FAMILY_COUNT; f++)
        CHECK(fabs(amp2[f] - amp[f]) <= 1e-10 * ring, "%s: %g against %g a quarter period before", gal_family_names[f],
              amp2[f], amp[f]);
    gal_rom_band_clear(&b);
    gal_rom_free(m);
}

static void test_band(void)
{
    gal_scene sc;
    const char *ov[] = {"model.elements=100"};
    gal_sim_setup s;
    if (sim_fixture(&sc, &s, "data/scenes/iced_gallop.ini", ov, 1)) return;
    CHECK(gal_forward(s.model, s.data, GAL_STAGE_REDUCED) == GAL_OK, "%s", gal_error_message());
    if (s.data->basis > 0) band_case(s.data);
    gal_sim_setup_clear(&s);
}

int main(void)
{
    RUN(test_band);
    return CHECK_SUMMARY();
}
