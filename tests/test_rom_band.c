/* test_rom_band.c: the self-check reads the oscillation that the reduced modes above the damping
 * band carry (rom_adapt.h, gal_rom_band_amplitude, GAL_ROM_BAND_WEIGHT). Those vectors are Ritz approximations of modes
 * no structural damping reaches; ringing there leaves almost no residual (data/scenes/iced_gallop.ini
 * at 600 elements rang 2.4 deg of twist at 6.4 Hz, 19% of the twist, with the residual at 0.08;
 * BENCHMARKS.md, issue 13, helper growth2). Here, on iced_gallop at 100 elements: the modes found
 * are those above the band, and the amplitude of a ringing reduced mode is its velocity over its
 * frequency (or its acceleration over the frequency squared, a quarter period on), split by
 * family; once the basis holds the third-order set, the adaptation's check takes the twist's part,
 * weighted, as the torsional residual from GAL_ROM_CUBIC_SETTLE_S on, grows on it by the rod's
 * torsional modes to the cap and refuses it there (tests/rom/partridge_180_dshape.ini rang 2.3 deg
 * at 11.7 Hz, 21% of its twist, with the residual at 0.01; helpers partridge and ring2). */
#include "check.h"
#include "sim_fixture.h"
#include "gallop.h"
#include "gallop/reduced/rom_adapt.h"
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

/* v along the most torsional of m's reduced modes above the band (the modes into *b), a = 0; that
 * mode's index, or -1. */
static int ring_along(gal_rom *m, double band_hz, gal_rom_band *b, double s)
{
    CHECK(gal_rom_band_init(m, band_hz, b) == GAL_OK, "%s", gal_error_message());
    int k = twist_mode(b), r = m->r;
    if (k < 0) return -1;
    memset(m->a, 0, (size_t)r * sizeof(double));
    for (int i = 0; i < r; i++) m->v[i] = s * b->y[(size_t)k * r + i];
    return k;
}

/* The adaptation's check on the same span ringing along its most torsional high mode: on the
 * initial basis nothing is read (a grown rod mode rings while a transient decays); once the basis
 * holds the third-order set, from GAL_ROM_CUBIC_SETTLE_S on, chk.ring is the twist's ringing over
 * the twist's scale times GAL_ROM_BAND_WEIGHT and the torsional residual at least that; a trip by
 * it grows the basis to the cap (the ringing growth), and one at the cap is refused
 * (GAL_ROM_ELIMIT, the model kept) with its own message. */
static void check_case(gal_data *d)
{
    gal_rom_opts ro;
    gal_force F;
    gal_rom_adapt a;
    gal_rom *m = NULL;
    gal_rom_check chk;
    gal_rom_band b = {0};
    int t = GAL_FAMILY_TORSIONAL, n = d->eq.rod->ndof, k;
    double *du = malloc((size_t)n * sizeof(double)), amp[GAL_FAMILY_COUNT], band = d->damping->band_hz, s = 0.7;
    int st = du ? adapt_fixture(d, &ro, &F, &a, &m) : GAL_ENOMEM;
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (st) { free(du); return; }
    CHECK(gal_rom_start(m, 0, d->eq.q, NULL) == GAL_OK, "%s", gal_error_message());
    /* the initial basis: not read */
    CHECK((k = ring_along(m, band, &b, s)) >= 0, "no high mode");
    if (k < 0) goto done;
    m->t = GAL_ROM_CUBIC_SETTLE_S + 1;
    CHECK(gal_rom_adapt_residual(&a, m, &chk, du) == GAL_OK, "%s", gal_error_message());
    CHECK(chk.ring == 0, "read %g on the initial basis", chk.ring);
    /* a cubic trip: the third-order set grown */
    chk.cubic[GAL_FAMILY_VERTICAL] = 0.5;
    chk.rel[GAL_FAMILY_VERTICAL] = chk.max = chk.cubic[GAL_FAMILY_VERTICAL] / GAL_ROM_CUBIC_SHARE;
    st = gal_rom_adapt_grow(&a, &m, &chk, du);
    CHECK(st == GAL_OK && a.third > 0, "status %d (%s), third %d", st, gal_error_message(), a.third);
    if (st) goto done;
    int r = m->r;
    CHECK((k = ring_along(m, band, &b, s)) >= 0, "no high mode on %d vectors", r);
    if (k < 0) goto done;
    gal_rom_band_amplitude(m, &b, amp);
    m->t = GAL_ROM_CUBIC_SETTLE_S - 1;
    CHECK(gal_rom_adapt_residual(&a, m, &chk, du) == GAL_OK, "%s", gal_error_message());
    CHECK(chk.ring == 0, "read %g before %g s", chk.ring, GAL_ROM_CUBIC_SETTLE_S);
    m->t = GAL_ROM_CUBIC_SETTLE_S + 1;
    CHECK(gal_rom_adapt_residual(&a, m, &chk, du) == GAL_OK, "%s", gal_error_message());
    double want = GAL_ROM_BAND_WEIGHT * amp[t] / chk.scale[t];
    printf("    %d vectors: ringing %.3g (mass norm) along the %.3f-Hz mode, read %.4g of the twist's scale, "
           "weighted\n", r, amp[t], sqrt(b.w2[k]) / (2 * GAL_PI), chk.ring);
    CHECK(want > 0.1 && fabs(chk.ring - want) <= 1e-12 * want, "ring %g against %g", chk.ring, want);
    CHECK(chk.rel[t] >= chk.ring && chk.max >= chk.rel[t], "torsional %g, max %g, ring %g", chk.rel[t], chk.max, chk.ring);
    /* a trip by the ringing: the basis grows by the rod's torsional modes it lacks, to the cap
     * (rom_adapt.h; test_rom_third_torsion.c checks which); at the cap, refused, the model kept, its
     * own message */
    for (int f = 0; f < GAL_FAMILY_COUNT; f++) chk.rel[f] = f == t ? chk.ring : 0;
    chk.max = chk.ring;
    st = gal_rom_adapt_grow(&a, &m, &chk, du);
    CHECK(st == GAL_OK && m->r == GAL_ROM_BASIS_CAP && a.nevents == 2 && a.ev[1].corrections == m->r - r,
          "status %d (%s), basis %d -> %d", st, gal_error_message(), r, m->r);
    if (st) goto done;
    gal_rom *m0 = m;
    r = m->r;
    st = gal_rom_adapt_grow(&a, &m, &chk, du);
    CHECK(st == GAL_ROM_ELIMIT && m == m0 && m->r == r && a.nevents == 2, "status %d, basis %d -> %d", st, r, m->r);
    CHECK(strstr(gal_error_message(), "rings undamped") != NULL, "message: %s", gal_error_message());
    /* a trip by the torsional residual itself: refused as any past the set, with that message */
    chk.rel[t] = chk.max = 2 * chk.ring;
    st = gal_rom_adapt_grow(&a, &m, &chk, du);
    CHECK(st == GAL_ROM_ELIMIT && strstr(gal_error_message(), "rings undamped") == NULL, "status %d (%s)", st,
          gal_error_message());
done:
    gal_rom_band_clear(&b);
    gal_rom_free(m);
    gal_rom_adapt_clear(&a);
    free(du);
}

static void test_band(void)
{
    gal_scene sc;
    const char *ov[] = {"model.elements=100"};
    gal_sim_setup s;
    if (sim_fixture(&sc, &s, "data/scenes/iced_gallop.ini", ov, 1)) return;
    CHECK(gal_forward(s.model, s.data, GAL_STAGE_REDUCED) == GAL_OK, "%s", gal_error_message());
    if (s.data->basis > 0) band_case(s.data), check_case(s.data);
    gal_sim_setup_clear(&s);
}

int main(void)
{
    RUN(test_band);
    return CHECK_SUMMARY();
}
