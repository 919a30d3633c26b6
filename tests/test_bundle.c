/* test_bundle.c: the equivalent bundle model ([bundle] model = equivalent): the first torsional
 * frequency of twin and quad bundles with many spacers against the rigid-bundle string formula
 * f = (1 / 2L) sqrt((sum H r^2 + sum GJ) / (sum m r^2 + sum I)); the vertical and horizontal
 * frequencies equal a single sub-conductor's at the same tension; the scene's refusals. */
#include "check.h"
#include "gallop.h"
#include "gallop/model/model.h"
#include "gallop/run/forward.h"
#include "gallop/scene/scene.h"

#include <math.h>
#include <string.h>

static const char *const scene = "tests/bundle/drake_twin.ini";

/* The modes of the scene with overrides; NULL (and a failed check) on failure. */
static gal_data *modes_of(const char *const *ov, int n, gal_model **mp)
{
    gal_scene sc;
    int st = gal_scene_load(&sc, scene, ov, n, NULL);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (st) return NULL;
    gal_model *m = gal_model_alloc(&sc, &st);
    CHECK(m && st == GAL_OK, "%s", gal_error_message());
    if (!m) return NULL;
    gal_data *d = gal_data_alloc(m);
    st = d ? gal_forward(m, d, GAL_STAGE_MODES) : GAL_ENOMEM;
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (st) {
        gal_data_free(d);
        gal_model_free(m);
        return NULL;
    }
    *mp = m;
    return d;
}

/* The lowest frequency of a family (Hz), 0 when none. */
static double first(const gal_data *d, gal_family fam)
{
    for (int k = 0; k < d->md.n; k++)
        if (d->md.mode[k].family == fam) return d->md.mode[k].omega / (2 * GAL_PI);
    return 0;
}

/* f of the rigid bundle, a taut string of length S under H per sub-conductor, with the spacers'
 * inertia smeared over the chord. */
static double string_torsion(int n, double s, int nsp, double Jsp, double H, double S, double chord)
{
    const double GJ = 200, m = 1.628, I = 0.0001611;
    double R = s / (2 * sin(GAL_PI / n));
    return 1 / (2 * S) * sqrt((n * H * R * R + n * GJ) / (n * m * R * R + n * I + nsp * Jsp / chord));
}

static void check_bundle(const char *count, int n, double s)
{
    char sub[64], sep[64];
    snprintf(sub, sizeof sub, "bundle.subconductors=%s", count);
    snprintf(sep, sizeof sep, "bundle.separation=%g", s);
    const char *const ov[] = {sub, sep, "bundle.spacers=40", "bundle.spacer_mass=6",
                              "bundle.spacer_inertia=0.4"};
    gal_model *m = NULL;
    gal_data *d = modes_of(ov, 5, &m);
    if (!d) return;
    double S = d->eq.unstretched_length, f = first(d, GAL_FAMILY_TORSIONAL);
    double want = string_torsion(n, s, 40, 0.4, 25000, S, 300);
    CHECK_REL(f, want, 0.005);
    printf("    (%d sub-conductors, separation %g m, 40 spacers: first torsional %.5f Hz, string %.5f Hz, "
           "%+.2f%%)\n", n, s, f, want, 100 * (f / want - 1));
    gal_data_free(d);
    gal_model_free(m);
}

/* Twin and quad with many spacers: the torsional frequency of the rigid bundle. */
static void test_torsional_frequency(void)
{
    check_bundle("2", 2, 0.457);
    check_bundle("4", 4, 0.457);
}

/* Without spacer mass, a bundle's vertical and horizontal frequencies are one sub-conductor's at
 * the same tension (n times the mass, n times the tension); its torsional one is far lower than a
 * single conductor's (the tension at radius R against the inertia m R^2). */
static void test_translation_as_single(void)
{
    const char *const quad[] = {"bundle.subconductors=4"};
    gal_model *mq = NULL, *m1 = NULL;
    gal_data *dq = modes_of(quad, 1, &mq);
    gal_scene sc;
    /* the single conductor: the same file without its [bundle] (given keys are refused with one) */
    int st = gal_scene_load(&sc, "tests/bundle/drake_single.ini", NULL, 0, NULL);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    gal_data *d1 = NULL;
    if (st == GAL_OK && (m1 = gal_model_alloc(&sc, &st)) && (d1 = gal_data_alloc(m1)))
        CHECK(gal_forward(m1, d1, GAL_STAGE_MODES) == GAL_OK, "%s", gal_error_message());
    if (dq && d1) {
        for (int fam = GAL_FAMILY_VERTICAL; fam <= GAL_FAMILY_HORIZONTAL; fam++)
            CHECK_REL(first(dq, (gal_family)fam), first(d1, (gal_family)fam), 1e-6);
        double tq = first(dq, GAL_FAMILY_TORSIONAL), t1 = first(d1, GAL_FAMILY_TORSIONAL);
        CHECK(tq > 0 && tq < 0.2 * t1, "bundle torsion %g Hz far below the single's %g Hz", tq, t1);
        printf("    (quad: vertical %.5f, horizontal %.5f, torsional %.5f Hz; single: %.5f, %.5f, %.5f Hz)\n",
               first(dq, GAL_FAMILY_VERTICAL), first(dq, GAL_FAMILY_HORIZONTAL), tq,
               first(d1, GAL_FAMILY_VERTICAL), first(d1, GAL_FAMILY_HORIZONTAL), t1);
    }
    gal_data_free(dq), gal_model_free(mq);
    gal_data_free(d1), gal_model_free(m1);
}

/* What a bundle cannot be is refused with the key named. */
static void test_refusals(void)
{
    static const char *const bad[][2] = {
        {"bundle.subconductors=5", "subconductors"},
        {"bundle.subconductors=0", "subconductors"},
        {"effects.torsion=off", "torsion"},
        {"bundle.separation=0", "separation"},
        {"bundle.subconductors=1", "separation"}, /* a bundle's key with one sub-conductor */
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        gal_scene sc;
        const char *ov[] = {bad[i][0]};
        int st = gal_scene_load(&sc, scene, ov, 1, NULL);
        CHECK(st == GAL_EINPUT, "%s refused (%d)", bad[i][0], st);
        CHECK(strstr(gal_error_message(), bad[i][1]) != NULL, "%s: message names %s: %s", bad[i][0],
              bad[i][1], gal_error_message());
    }
}

int main(void)
{
    RUN(test_torsional_frequency);
    RUN(test_translation_as_single);
    RUN(test_refusals);
    return CHECK_SUMMARY();
}
