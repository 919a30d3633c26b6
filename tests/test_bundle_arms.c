/* test_bundle_arms.c: flexible spacers ([bundle] spacer_stiffness, src/bundle/arms.c): a very stiff
 * arm gives the rigid spacers' modes (twin and quad, the lowest 16 within 0.1%, converging as the
 * stiffness grows); a soft one adds the sub-conductors' relative motion along the arms (a subspan
 * mode the rigid spacers forbid) at the hand formula of a string on discrete springs,
 * f^2 = f_h^2 + k (ns + 1) / (4 pi^2 m L), and lowers the torsional frequencies; the statics alike; the
 * key's refusals (a stiffness below 100 N/m but 0, flexible spacers in the equivalent model). */
#include "check.h"
#include "gallop.h"
#include "gallop/model/model.h"
#include "gallop/scene/scene.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const char *const scene = "tests/bundle/drake_twin.ini";
static const double m1 = 1.628, L = 300;

/* The explicit bundle's statics and nev lowest modes, the scene with overrides and a stiffness
 * (NULL: rigid). */
static gal_bundle *modes_of(const char *const *ov, int n, const char *stiff, int nev, gal_modes *md)
{
    const char *all[16];
    int k = 0, st;
    for (int i = 0; i < n; i++) all[k++] = ov[i];
    all[k++] = "bundle.model=explicit";
    if (stiff) all[k++] = stiff;
    gal_scene sc;
    st = gal_scene_load(&sc, scene, all, k, NULL);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (st) return NULL;
    gal_model *m = gal_model_alloc(&sc, &st);
    CHECK(m != NULL, "%s", gal_error_message());
    if (!m) return NULL;
    gal_bundle_params bp;
    gal_bundle_params_of(&sc, &bp);
    gal_bundle *b = NULL;
    st = gal_bundle_statics(&m->rod[0].p, &bp, m->rod[0].spec, m->rod[0].spec_value, NULL, &b);
    if (!st) st = gal_bundle_modes_solve(b, nev, md);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    gal_model_free(m);
    if (st) b = gal_bundle_free(b);
    return b;
}

/* The k-th frequency of a family among md (Hz; 0 when none). */
static double nth(const gal_modes *md, gal_family fam, int k)
{
    for (int i = 0; i < md->n; i++)
        if (md->mode[i].family == fam && k-- == 0) return md->mode[i].frequency_hz;
    return 0;
}

/* The largest relative difference of the lowest nev frequencies, stiff against rigid, and the
 * families alike. */
static double worst_against_rigid(const gal_modes *rig, const gal_modes *flex, int nev)
{
    double w = 0;
    for (int i = 0; i < nev && i < rig->n && i < flex->n; i++) {
        w = fmax(w, fabs(flex->mode[i].frequency_hz / rig->mode[i].frequency_hz - 1));
        CHECK(flex->mode[i].family == rig->mode[i].family, "mode %d: family %d against rigid %d", i + 1,
              (int)flex->mode[i].family, (int)rig->mode[i].family);
    }
    return w;
}

static void stiff_case(const char *count, const char *orient)
{
    const char *const ov[] = {count, orient, "bundle.spacers=9", "bundle.spacer_mass=3", "bundle.spacer_inertia=0.1"};
    const int nev = 16;
    const char *const stiff[] = {"bundle.spacer_stiffness=1e5", "bundle.spacer_stiffness=1e7", "bundle.spacer_stiffness=1e9"};
    gal_modes rig, flex;
    gal_bundle *b = modes_of(ov, 5, NULL, nev, &rig);
    if (!b) return;
    double sag0 = b->sag, w[3];
    gal_bundle_free(b);
    for (int s = 0; s < 3; s++) {
        if (!(b = modes_of(ov, 5, stiff[s], nev, &flex))) { gal_modes_clear(&rig); return; }
        w[s] = worst_against_rigid(&rig, &flex, nev);
        if (s == 2) CHECK_REL(b->sag, sag0, 1e-6);
        gal_bundle_free(b), gal_modes_clear(&flex);
    }
    printf("    (%s: lowest %d frequencies against rigid within %.2e, %.2e, %.2e at 1e5, 1e7, 1e9 N/m)\n", count, nev,
           w[0], w[1], w[2]);
    CHECK(w[2] < 1e-3, "%s: stiff arms (1e9 N/m) within %g of the rigid spacers' frequencies", count, w[2]);
    CHECK(w[1] < 1e-3, "%s: 1e7 N/m within %g", count, w[1]);
    CHECK(w[2] < 0.1 * w[0], "%s: converging with the stiffness (%g at 1e9, %g at 1e5 N/m)", count, w[2], w[0]);
    gal_modes_clear(&rig);
}

/* Very stiff arms: the rigid spacers' modes; a horizontal twin and a quad turned 45 deg. */
static void test_stiff_limit(void)
{
    stiff_case("bundle.subconductors=2", "bundle.orientation=0");
    stiff_case("bundle.subconductors=4", "bundle.orientation=45");
}

/* Soft arms on a horizontal twin with many spacers: the sub-conductors' relative motion along the
 * arms (the frame still, by symmetry) is each a string on springs k at the ns spacers, a mode the
 * rigid spacers forbid (no subspan mode below their sub-span modes). By hand, for the half-wave of
 * the string's mode j (frequency f_h, the same run's horizontal one; the spacers massless so the
 * two share their mass): the Rayleigh quotient of that shape with the discrete springs,
 * f^2 = f_h^2 + k (ns + 1) / (4 pi^2 m L) (the springs at x_i = i L / (ns + 1) weigh
 * sum sin^2 = (ns + 1) / 2), an upper bound, exact to first order in k (soft arms); and the
 * foundation smeared, k ns / L, below it, which the mode tends to as the arms stiffen against the
 * sub-span (its shape bending between the springs). The torsional frequencies drop with k (the
 * sub-conductors' twist decoupled from the frame's). */
static void test_soft_subspan(void)
{
    const int ns = 19, nev = 24;
    char spc[32];
    snprintf(spc, sizeof spc, "bundle.spacers=%d", ns);
    const char *const ov[] = {spc, "bundle.spacer_mass=0", "bundle.spacer_inertia=0.1", "bundle.orientation=0"};
    const double ks[2] = {100, 1000}, tol[2] = {0.005, 0.03};
    gal_modes rig, md;
    gal_bundle *b = modes_of(ov, 4, NULL, nev, &rig);
    if (!b) return;
    gal_bundle_free(b);
    double fsub_rigid = nth(&rig, GAL_FAMILY_SUBSPAN, 0), ft_prev = nth(&rig, GAL_FAMILY_TORSIONAL, 0);
    CHECK(fsub_rigid == 0 || fsub_rigid > 1.5, "rigid spacers: no subspan mode below 1.5 Hz (%g)", fsub_rigid);
    for (int c = 1; c >= 0; c--) { /* stiffer first: the torsional frequency falls as k does */
        char key[48];
        snprintf(key, sizeof key, "bundle.spacer_stiffness=%g", ks[c]);
        if (!(b = modes_of(ov, 4, key, nev, &md))) break;
        gal_bundle_free(b);
        double add = ks[c] / (4 * GAL_PI * GAL_PI * m1 * L), ft = nth(&md, GAL_FAMILY_TORSIONAL, 0);
        for (int j = 0; j < 2; j++) {
            double fh = nth(&md, GAL_FAMILY_HORIZONTAL, j), fs = nth(&md, GAL_FAMILY_SUBSPAN, j);
            double ray = sqrt(fh * fh + add * (ns + 1)), smear = sqrt(fh * fh + add * ns);
            printf("    (k %g N/m: relative mode %d at %.5f Hz; by hand %.5f Hz (%+.2f%%), smeared %.5f Hz)\n", ks[c],
                   j + 1, fs, ray, 100 * (fs / ray - 1), smear);
            CHECK(fs >= 0.998 * smear && fs <= 1.0005 * ray && fs >= (1 - tol[c]) * ray,
                  "k %g: relative mode %d at %g Hz; by hand %g Hz (within %g below), smeared %g Hz", ks[c], j + 1, fs,
                  ray, tol[c], smear);
        }
        CHECK(ft < ft_prev, "k %g: torsional %g Hz below the stiffer arms' %g Hz", ks[c], ft, ft_prev);
        ft_prev = ft;
        gal_modes_clear(&md);
    }
    gal_modes_clear(&rig);
}

/* The key's refusals: in the range but below the softest flexible spacer; with the equivalent model. */
static void test_refusals(void)
{
    const char *const bad[][3] = {
        {"bundle.spacer_stiffness=50", "bundle.model=explicit", "0 (rigid spacers) or 100 to 1e+09 N/m"},
        {"bundle.spacer_stiffness=2e9", "bundle.model=explicit", "spacer_stiffness <= 1000000000"},
        {"bundle.spacer_stiffness=-1", "bundle.model=explicit", "0 <= spacer_stiffness"},
        {"bundle.spacer_stiffness=1e4", "bundle.model=equivalent", "allowed: model = explicit, or spacer_stiffness = 0"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        const char *ov[3] = {"bundle.spacers=4", bad[i][0], bad[i][1]};
        gal_scene sc;
        int st = gal_scene_load(&sc, scene, ov, 3, NULL);
        CHECK(st == GAL_EINPUT, "%s with %s refused (%d)", bad[i][0], bad[i][1], st);
        CHECK(strstr(gal_error_message(), "spacer_stiffness") && strstr(gal_error_message(), bad[i][2]),
              "%s: the message names the key and %s: %s", bad[i][0], bad[i][2], gal_error_message());
    }
}

int main(void)
{
    RUN(test_refusals);
    RUN(test_stiff_limit);
    RUN(test_soft_subspan);
    return CHECK_SUMMARY();
}
