/* test_bundle.c: the equivalent bundle model ([bundle] model = equivalent): its differential-stretch
 * term's derivatives against finite differences; the torsional frequencies of twin and quad bundles
 * with many spacers against the rigid-bundle string formula f = (1 / 2L) sqrt((sum H r^2 + sum GJ) /
 * (sum m r^2 + sum I)) taut, and sagged against Irvine's symmetric root; the vertical and horizontal
 * frequencies equal a single sub-conductor's at the same tension; the scene's refusals. */
#include "check.h"
#include "gallop.h"
#include "gallop/model/model.h"
#include "gallop/run/forward.h"
#include "gallop/scene/scene.h"
#include "rod_fd.h"

#include <math.h>
#include <stdlib.h>
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

/* The lowest frequency of a family (Hz) of symmetry sym (-1: any), 0 when none. */
static double first_sym(const gal_data *d, gal_family fam, int sym)
{
    for (int k = 0; k < d->md.n; k++)
        if (d->md.mode[k].family == fam && (sym < 0 || (int)d->md.mode[k].symmetry == sym))
            return d->md.mode[k].omega / (2 * GAL_PI);
    return 0;
}
static double first(const gal_data *d, gal_family fam) { return first_sym(d, fam, -1); }

/* f of the rigid bundle, a taut string of length S under H per sub-conductor, with the spacers'
 * inertia smeared over the chord. */
static double string_torsion(int n, double s, int nsp, double Jsp, double H, double S, double chord)
{
    const double GJ = 200, m = 1.628, I = 0.0001611;
    double R = s / (2 * sin(GAL_PI / n));
    return 1 / (2 * S) * sqrt((n * H * R * R + n * GJ) / (n * m * R * R + n * I + nsp * Jsp / chord));
}

/* The first symmetric root of Irvine's equation tan(x) = x - 4 x^3 / lam2, x in (pi/2, 3 pi/2):
 * the symmetric mode's frequency over the taut string's first, 2 x / pi. */
static double irvine(double lam2)
{
    double lo = 0.5 * GAL_PI + 1e-9, hi = 1.5 * GAL_PI - 1e-9;
    double fhi = sin(hi) - (hi - 4 * hi * hi * hi / lam2) * cos(hi);
    for (int i = 0; i < 200; i++) { /* bisection on sin x - (x - 4 x^3 / lam2) cos x */
        double x = 0.5 * (lo + hi);
        if ((sin(x) - (x - 4 * x * x * x / lam2) * cos(x) > 0) == (fhi > 0)) hi = x;
        else lo = x;
    }
    return 2 * lo / GAL_PI;
}

/* The differential-stretch term (src/rod/bundle_irvine.c) of a twin turned 30 deg (one field) and
 * of a quad (two), on a sagged 3-D curve with random twists and fields: its gradient against
 * finite differences of its energy and its tangent against finite differences of its gradient;
 * the fields' dofs sit after the twists with their inertia on M's diagonal. */
static void test_irvine_derivatives(void)
{
    for (int nf = 1; nf <= 2; nf++) {
        int nel = 12;
        gal_rod_params p = {.length = 100, .height_difference = 10, .elements = nel, .unstretched_length = 101,
                            .EA = 2e4, .EI = 50, .GJ = 300, .mass = 1.5, .polar_inertia = 2e-4, .gravity = 9.81,
                            .torsion = 1, .twist_clamped = 1, .bundle_radius2 = 0.04, .bundle_fields = nf,
                            .bundle_field_k = 3e3, .bundle_field_inertia = 0.07};
        if (nf == 1) p.bundle_field_dir[0][0] = cos(0.5), p.bundle_field_dir[0][1] = sin(0.5);
        else p.bundle_field_dir[0][0] = 1, p.bundle_field_dir[1][1] = 1;
        int nq = gal_rod_nq(&p);
        CHECK(nq == 3 * (nel + 1) + (1 + nf) * nel, "configuration size %d", nq);
        double *q0 = calloc((size_t)nq, sizeof(double)), *q = calloc((size_t)nq, sizeof(double));
        for (int i = 0; i <= nel; i++) {
            double s = (double)i / nel;
            q0[3 * i] = 100 * s, q0[3 * i + 2] = 10 * s - 8 * s * (1 - s);
        }
        gal_rod *rod = gal_rod_alloc(&p, q0);
        CHECK(rod != NULL, "%s", gal_error_message());
        if (!rod) { free(q0), free(q); continue; }
        int k = -1;
        for (int t = 0; t < rod->nterm; t++)
            if (rod->term[t] == &gal_rod_term_bundle_irvine) k = t;
        CHECK(k >= 0, "bundle_irvine on");
        CHECK(rod->ndof == 3 * (nel - 1) + (1 + nf) * nel, "free dofs %d", rod->ndof);
        CHECK(rod->mdiag[rod->dof[3 * rod->nn + nel + 3]] == 0.07 * rod->l0[3], "field inertia on M");
        unsigned long x = 12345 + nf; /* a small LCG: the same perturbation on every platform */
        for (int i = 0; i < nq; i++) {
            x = (x * 6364136223846793005ul + 1442695040888963407ul) & 0xfffffffffffful;
            double u = 2.0 * (double)(x >> 16) / 4294967296.0 - 1;
            q[i] = q0[i] + (rod->dof[i] < 0 ? 0 : 0.5 * u); /* positions by 0.5 m, angles by 0.5 rad */
        }
        double e[4];
        if (k >= 0) {
            rod_fd_errors(rod, k, q, e);
            CHECK(e[0] <= 1e-6 * e[1], "bundle_irvine (%d fields): gradient vs FD: %g of %g", nf, e[0], e[1]);
            CHECK(e[2] <= 1e-5 * e[3], "bundle_irvine (%d fields): tangent vs FD: %g of %g", nf, e[2], e[3]);
            printf("    (bundle_irvine, %d field%s: force error %.2g of %.2g, tangent error %.2g of %.2g)\n", nf,
                   nf > 1 ? "s" : "", e[0], e[1], e[2], e[3]);
        }
        free(q0), free(q);
        gal_rod_free(rod);
    }
}

/* Twin (horizontal) or quad of separation s with 40 spacers, sagged or taut (gravity off): without
 * sag the first torsional mode is the rigid-bundle string's; sagged, the antisymmetric one is twice
 * it and the symmetric one Irvine's, lambda_t^2 = lambda^2 (sum_k y_k^2 / n R^2) H R^2 / (H R^2 +
 * GJ), lambda^2 = (m_s g L / H)^2 EA_sub / H with m_s a sub-conductor's mass and its share of
 * the spacers' (the differential-stretch fields of src/rod/bundle_irvine.c). */
static void check_bundle(const char *count, int n, double s, int sagged)
{
    char sub[64], sep[64];
    snprintf(sub, sizeof sub, "bundle.subconductors=%s", count);
    snprintf(sep, sizeof sep, "bundle.separation=%g", s);
    const char *const ov[] = {sub, sep, "bundle.spacers=40", "bundle.spacer_mass=6", "bundle.spacer_inertia=0.4",
                              "model.modes_torsional=2", sagged ? "effects.gravity=on" : "effects.gravity=off"};
    gal_model *m = NULL;
    gal_data *d = modes_of(ov, 7, &m);
    if (!d) return;
    const double H = 25000, L = 300, EA = 2.9e7, GJ = 200, m1 = 1.628;
    double S = d->eq.unstretched_length, f0 = string_torsion(n, s, 40, 0.4, H, S, L);
    double fs = first_sym(d, GAL_FAMILY_TORSIONAL, GAL_SYM_SYMMETRIC);
    double fa = first_sym(d, GAL_FAMILY_TORSIONAL, GAL_SYM_ANTISYMMETRIC);
    if (!sagged) {
        CHECK_REL(fs, f0, 0.005);
        CHECK_REL(fa, 2 * f0, 0.005);
        printf("    (%d taut, 40 spacers: torsional symmetric %.5f, antisymmetric %.5f Hz; string %.5f, %.5f Hz)\n", n,
               fs, fa, f0, 2 * f0);
    } else {
        double R = s / (2 * sin(GAL_PI / n)), ms = m1 + 40 * 6.0 / (n * L);
        double lam2 = pow(ms * GAL_GRAVITY * L / H, 2) * EA / H, share = n == 2 ? 1.0 : 0.5;
        double lt2 = lam2 * share * H * R * R / (H * R * R + GJ), fi = f0 * irvine(lt2);
        CHECK_REL(fs, fi, 0.01);
        CHECK_REL(fa, 2 * f0, 0.01);
        CHECK(fs > 1.5 * f0, "the sag stiffens the symmetric torsion: %g against %g Hz", fs, f0);
        printf("    (%d sagged, 40 spacers: torsional symmetric %.5f Hz, Irvine lambda_t^2 = %.1f %.5f Hz (%+.2f%%); "
               "antisymmetric %.5f Hz, twice the string %.5f Hz (%+.2f%%))\n", n, fs, lt2, fi, 100 * (fs / fi - 1), fa,
               2 * f0, 100 * (fa / (2 * f0) - 1));
    }
    gal_data_free(d);
    gal_model_free(m);
}

/* Twin and quad with many spacers: the torsional frequencies of the rigid bundle, taut and sagged. */
static void test_torsional_frequency(void)
{
    for (int sagged = 0; sagged < 2; sagged++) {
        check_bundle("2", 2, 0.457, sagged);
        check_bundle("4", 4, 0.457, sagged);
    }
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
    RUN(test_irvine_derivatives);
    RUN(test_torsional_frequency);
    RUN(test_translation_as_single);
    RUN(test_refusals);
    return CHECK_SUMMARY();
}
