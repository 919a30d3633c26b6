/* test_bundle_select.c: which modes a reduced model takes (src/modes/select.c, gal_modes_select):
 * the rule on made-up spectra (the lowest asked of each family, each selected vertical mode's
 * torsional partner of its parity, within the band, added to the number asked; none when no
 * torsional mode is asked); the Drake twin with 40 spacers under the quad's ice, in both models
 * with the default 2/2/1 modes, selects its symmetric torsional mode (0.439 Hz, next to the
 * symmetric vertical one at 0.428 Hz) besides the first torsional, the antisymmetric one (the
 * selection before it took the first alone, and the reduced twin missed the full one's galloping
 * by 18% vertical and 72% in rotation: README "Bundles"), also inclined (by parity); the single
 * iced Drake selects as before; the equivalent bundle's domain (gal_bundle_equivalent_outside). */
#include "check.h"
#include "gallop.h"
#include "gallop/bundle/bundle.h"
#include "gallop/model/model.h"
#include "gallop/scene/scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *const twin[] = {"bundle.spacers=40", "bundle.spacer_mass=6", "bundle.spacer_inertia=0.4",
                                   "ice.mass_per_length=0.6", "ice.aero_table=data/aero/iced_d_shape.csv",
                                   "ice.attack_angle=20", "wind.speed=10", "wind.yaw=90", "model.elements=80", NULL,
                                   NULL};

/* A made-up spectrum: families, parities and frequencies (Hz) of n modes. */
static void spectrum(gal_modes *md, gal_mode *m, int n, const int *fam, const int *par, const double *f)
{
    memset(md, 0, sizeof *md);
    md->n = n, md->mode = m;
    for (int k = 0; k < n; k++) {
        memset(m + k, 0, sizeof *m);
        m[k].family = (gal_family)fam[k], m[k].parity = m[k].symmetry = (gal_symmetry)par[k];
        m[k].frequency_hz = f[k], m[k].index = k + 1;
    }
}

static void test_rule(void)
{
    enum { V = GAL_FAMILY_VERTICAL, H = GAL_FAMILY_HORIZONTAL, T = GAL_FAMILY_TORSIONAL, S = GAL_SYM_SYMMETRIC,
           A = GAL_SYM_ANTISYMMETRIC };
    /* the twin's: H s, V a, H a, T a, V s, T s, H s, V s, T s */
    const int fam[] = {H, V, H, T, V, T, H, V, T}, par[] = {S, A, S, A, S, S, S, S, S};
    const double f[] = {0.162, 0.322, 0.324, 0.339, 0.428, 0.439, 0.486, 0.578, 0.585};
    gal_mode m[9];
    gal_modes md;
    spectrum(&md, m, 9, fam, par, f);
    int want[GAL_FAMILY_COUNT] = {2, 2, 1, 0, 0};
    gal_modes_select(&md, want);
    int sel[9];
    for (int k = 0; k < 9; k++) sel[k] = m[k].selected;
    const int expect[9] = {1, 1, 1, 1, 1, 1, 0, 0, 0};
    for (int k = 0; k < 9; k++) CHECK(sel[k] == expect[k], "mode %d selected %d, expected %d", k + 1, sel[k], expect[k]);
    CHECK(m[3].partner == 0 && m[5].partner == 5, "partners %d %d (0 and 5 expected)", m[3].partner, m[5].partner);
    CHECK(md.selected[T] == 2 && md.selected[V] == 2 && md.selected[H] == 2, "selected %d %d %d", md.selected[V],
          md.selected[H], md.selected[T]);
    CHECK_REL(gal_modes_partner_top(&md, want), 1.5 * 0.428, 1e-12);
    /* no torsional mode asked: none added */
    want[T] = 0;
    gal_modes_select(&md, want);
    CHECK(!m[3].selected && !m[5].selected && md.selected[T] == 0, "torsional selected with none asked");
    CHECK(gal_modes_partner_top(&md, want) == 0, "a band with no torsional mode asked");
    /* the partner outside the band (the symmetric torsional at 0.65 Hz, 52% above 0.428): none */
    double f2[9];
    memcpy(f2, f, sizeof f2);
    f2[5] = 0.428 * (1 + GAL_PARTNER_BAND) + 0.001, f2[6] = 0.70, f2[7] = 0.75, f2[8] = 0.80;
    spectrum(&md, m, 9, fam, par, f2);
    want[T] = 1;
    gal_modes_select(&md, want);
    CHECK(!m[5].selected && md.selected[T] == 1, "a partner beyond the band selected");
    /* parity, not nearness alone: both vertical modes symmetric, the torsional mode nearest the
     * second (0.439 Hz) antisymmetric: the symmetric one nearest (the first, selected) suffices */
    const int par3[] = {S, S, S, S, S, A, S, S, S};
    spectrum(&md, m, 9, fam, par3, f);
    gal_modes_select(&md, want);
    CHECK(m[3].selected && m[3].partner == 0, "the lowest torsional");
    CHECK(!m[5].selected && !m[8].selected && md.selected[T] == 1,
          "torsional modes of the other parity or farther taken: %d %d", m[5].selected, m[8].selected);
}

/* The twin's modes in model `model` (explicit or equivalent) with the default selection, with one
 * more override (or NULL). */
static int twin_modes(const char *model, const char *extra, gal_modes *out)
{
    char kv[64];
    const char *ov[16];
    int n = 0;
    while (twin[n]) ov[n] = twin[n], n++;
    snprintf(kv, sizeof kv, "bundle.model=%s", model);
    ov[n++] = kv;
    if (extra) ov[n++] = extra;
    gal_scene sc;
    int st = gal_scene_load(&sc, "tests/bundle/drake_twin.ini", ov, n, NULL);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (st) return st;
    gal_model *m = gal_model_alloc(&sc, &st);
    CHECK(m != NULL, "%s", gal_error_message());
    if (!m) return st;
    if (!strcmp(model, "explicit")) {
        gal_bundle *b = NULL;
        st = gal_bundle_solve_model(m, &b, out);
        gal_bundle_free(b);
    } else {
        gal_data *d = gal_data_alloc(m);
        st = d ? gal_forward(m, d, GAL_STAGE_MODES) : GAL_ENOMEM;
        if (!st) { /* the modes' table, without the shapes */
            *out = d->md;
            out->mode = malloc((size_t)out->n * sizeof(gal_mode)), out->shape = NULL;
            if (out->mode) memcpy(out->mode, d->md.mode, (size_t)out->n * sizeof(gal_mode));
            else st = GAL_ENOMEM;
        }
        gal_data_free(d);
    }
    CHECK(st == GAL_OK, "%s", gal_error_message());
    gal_model_free(m);
    return st;
}

/* The selected torsional modes: the antisymmetric first one and the symmetric partner of the
 * symmetric vertical mode (at f_v within 5%). */
static void twin_selects(const char *model)
{
    gal_modes md;
    if (twin_modes(model, NULL, &md)) return;
    int ta = -1, ts = -1, vs = -1;
    for (int k = 0; k < md.n; k++) {
        const gal_mode *m = md.mode + k;
        if (!m->selected) continue;
        if (m->family == GAL_FAMILY_TORSIONAL && m->symmetry == GAL_SYM_ANTISYMMETRIC) ta = k;
        if (m->family == GAL_FAMILY_TORSIONAL && m->symmetry == GAL_SYM_SYMMETRIC) ts = k;
        if (m->family == GAL_FAMILY_VERTICAL && m->symmetry == GAL_SYM_SYMMETRIC) vs = k;
    }
    printf("    %s: torsional selected %d (asked 1)", model, md.selected[GAL_FAMILY_TORSIONAL]);
    if (ta >= 0 && ts >= 0 && vs >= 0)
        printf(": antisymmetric %.4f Hz, symmetric %.4f Hz beside the symmetric vertical %.4f Hz\n",
               md.mode[ta].frequency_hz, md.mode[ts].frequency_hz, md.mode[vs].frequency_hz);
    else
        printf("\n");
    CHECK(ta >= 0 && ts >= 0 && vs >= 0, "%s twin: antisymmetric %d, symmetric torsional %d, symmetric vertical %d "
          "selected", model, ta, ts, vs);
    CHECK(md.selected[GAL_FAMILY_TORSIONAL] == 2 && md.selected[GAL_FAMILY_VERTICAL] == 2 &&
          md.selected[GAL_FAMILY_HORIZONTAL] == 2, "%s twin: %d %d %d selected", model,
          md.selected[GAL_FAMILY_VERTICAL], md.selected[GAL_FAMILY_HORIZONTAL], md.selected[GAL_FAMILY_TORSIONAL]);
    if (ta >= 0 && ts >= 0 && vs >= 0) {
        CHECK(md.mode[ta].frequency_hz < md.mode[ts].frequency_hz, "the first torsional is the antisymmetric one");
        CHECK(md.mode[ts].partner == md.mode[vs].index, "partner %d, vertical %d", md.mode[ts].partner,
              md.mode[vs].index);
        CHECK(fabs(md.mode[ts].frequency_hz / md.mode[vs].frequency_hz - 1) < 0.05, "%.4f against %.4f Hz",
              md.mode[ts].frequency_hz, md.mode[vs].frequency_hz);
    }
    gal_modes_clear(&md);
}

static void test_twin_explicit(void) { twin_selects("explicit"); }

/* Inclined (200 m up over 300 m): no mode is symmetric or antisymmetric any more (symmetry none),
 * the partner is found by parity, the larger part's (README "Which modes are selected"). */
static void test_twin_inclined(void)
{
    gal_modes md;
    if (twin_modes("explicit", "span.height_difference=200", &md)) return;
    int partners = 0, none = 0;
    for (int k = 0; k < md.n; k++) {
        const gal_mode *m = md.mode + k;
        none += m->selected && m->symmetry == GAL_SYM_NONE;
        if (!m->partner) continue;
        partners++;
        for (int i = 0; i < md.n; i++)
            if (md.mode[i].index == m->partner)
                CHECK(md.mode[i].family == GAL_FAMILY_VERTICAL && md.mode[i].parity == m->parity &&
                      fabs(m->frequency_hz / md.mode[i].frequency_hz - 1) < 0.05, "partner %.4f Hz of %.4f Hz",
                      m->frequency_hz, md.mode[i].frequency_hz);
    }
    printf("    inclined: %d selected modes of symmetry none, %d partner\n", none, partners);
    CHECK(none >= 2 && partners == 1 && md.selected[GAL_FAMILY_TORSIONAL] == 2, "none %d, partners %d, torsional %d",
          none, partners, md.selected[GAL_FAMILY_TORSIONAL]);
    gal_modes_clear(&md);
}
static void test_twin_equivalent(void) { twin_selects("equivalent"); }

/* A single iced Drake: its torsional modes (2.1 Hz, 4.2 Hz) are far above its vertical ones (0.46
 * to 1.01 Hz): the first torsional alone, as before. */
static void test_single(void)
{
    gal_scene sc;
    int st = gal_scene_load(&sc, "data/scenes/iced_gallop.ini", NULL, 0, NULL);
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (st) return;
    gal_model *m = gal_model_alloc(&sc, &st);
    gal_data *d = m ? gal_data_alloc(m) : NULL;
    st = d ? gal_forward(m, d, GAL_STAGE_MODES) : GAL_ENOMEM;
    CHECK(st == GAL_OK, "%s", gal_error_message());
    if (!st) {
        int partners = 0;
        for (int k = 0; k < d->md.n; k++) partners += d->md.mode[k].partner != 0;
        CHECK(d->md.selected[GAL_FAMILY_TORSIONAL] == 1 && partners == 0, "torsional %d, partners %d",
              d->md.selected[GAL_FAMILY_TORSIONAL], partners);
    }
    gal_data_free(d), gal_model_free(m);
}

/* The equivalent model's domain (gal_bundle_equivalent_outside, README "Bundles"): the twin of
 * quad_bundle_gallop.ini with 8 spacers, galloping at 0.43 Hz next to its symmetric vertical mode
 * (0.461 Hz) whose symmetric torsional partner is at 0.461 Hz, is outside (measured: its amplitude
 * 39% off the explicit model's); the quad, its partner 11% below, is inside (within 2%), unless it
 * galloped in its third vertical mode (1.001 Hz, its partner at 1.021 Hz); an explicit bundle and
 * a single conductor never. */
static void test_domain(void)
{
    const char *const sets[3][2] = {{"bundle.subconductors=2", "bundle.spacers=8"}, {"bundle.spacers=6", NULL},
                                    {"wind.speed=10", NULL}};
    const char *const path[3] = {"data/scenes/quad_bundle_gallop.ini", "data/scenes/quad_bundle_gallop.ini",
                                 "data/scenes/iced_gallop.ini"};
    const double fg[3][2] = {{0.43, 0.43}, {0.4368, 1.0}, {0.46, 0.46}};
    const int expect[3][2] = {{1, 1}, {0, 1}, {0, 0}};
    for (int c = 0; c < 3; c++) {
        gal_scene sc;
        int n = sets[c][1] ? 2 : 1;
        if (gal_scene_load(&sc, path[c], sets[c], n, NULL) != GAL_OK) {
            CHECK(0, "%s", gal_error_message());
            continue;
        }
        int st;
        gal_model *m = gal_model_alloc(&sc, &st);
        gal_data *d = m ? gal_data_alloc(m) : NULL;
        st = d ? gal_forward(m, d, GAL_STAGE_MODES) : GAL_ENOMEM;
        CHECK(st == GAL_OK, "%s", gal_error_message());
        for (int k = 0; k < 2 && !st; k++) {
            char msg[640];
            int out = gal_bundle_equivalent_outside(&sc, &d->md, fg[c][k], msg, sizeof msg);
            printf("    %s %s at %.4f Hz: %s\n", sets[c][0], sets[c][1] ? sets[c][1] : "", fg[c][k],
                   out ? "outside" : "inside");
            CHECK(out == expect[c][k] && (out == (msg[0] != 0)), "case %d at %g Hz: %d (%s)", c, fg[c][k], out, msg);
            gal_scene sx = sc; /* an explicit bundle: never */
            sx.bundle.explicit_model = 1;
            CHECK(!gal_bundle_equivalent_outside(&sx, &d->md, fg[c][k], msg, sizeof msg), "explicit: %s", msg);
        }
        gal_data_free(d), gal_model_free(m);
    }
}

int main(void)
{
    RUN(test_rule);
    RUN(test_twin_explicit);
    RUN(test_twin_equivalent);
    RUN(test_twin_inclined);
    RUN(test_single);
    RUN(test_domain);
    return CHECK_SUMMARY();
}
