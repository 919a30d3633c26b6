/* test_full_damping.c: the damping the full model applies is the structure's (issue 15): a free
 * decay of the full model along a natural mode shows the scene's ratio, at a low and a higher mode
 * of different families, and the same whatever modes the scene selects. */
#include "check.h"
#include "gallop.h"
#include "gallop/full/dynamics.h"
#include "gallop/model/model.h"
#include "gallop/run/forward.h"
#include "gallop/scene/scene.h"

#define ZETA 0.02

typedef struct {
    gal_model *m;
    gal_data *d;
} piped;

/* iced_gallop.ini at 30 elements, the ratio ZETA, the modes selected by `sel` (vertical,
 * horizontal, torsional), through the modes stage. */
static int pipe_init(piped *p, const int sel[3])
{
    char s0[64], s1[64], s2[64], z[64];
    snprintf(s0, sizeof s0, "model.modes_vertical=%d", sel[0]);
    snprintf(s1, sizeof s1, "model.modes_horizontal=%d", sel[1]);
    snprintf(s2, sizeof s2, "model.modes_torsional=%d", sel[2]);
    snprintf(z, sizeof z, "conductor.damping_ratio=%g", ZETA);
    const char *ov[] = {"model.elements=30", s0, s1, s2, z};
    gal_scene sc;
    int st = gal_scene_load(&sc, "data/scenes/iced_gallop.ini", ov, 5, NULL);
    p->m = st ? NULL : gal_model_alloc(&sc, &st);
    p->d = p->m ? gal_data_alloc(p->m) : NULL;
    if (!st) st = p->d ? gal_forward(p->m, p->d, GAL_STAGE_MODES) : GAL_ENOMEM;
    CHECK(st == GAL_OK, "%s", gal_error_message());
    return st;
}

static void pipe_clear(piped *p)
{
    gal_data_free(p->d);
    gal_model_free(p->m);
}

/* phi^T M x over the free dofs of a configuration-sized x (less x0 when given). */
static double modal(const gal_rod *rod, const double *mphi, const double *x, const double *x0)
{
    double s = 0;
    for (int j = 0; j < rod->ndof; j++) {
        int k = rod->free_q[j];
        s += mphi[j] * (x[k] - (x0 ? x0[k] : 0));
    }
    return s;
}

/* The damping ratio of a free decay of the full model started with the velocity of mode `shape`
 * (circular frequency w) under damping C: over n whole damped periods the modal energy falls by
 * exp(-2 zeta w n T_d) exactly for a linear oscillator. */
static double decay_ratio(const gal_data *d, const gal_damping *C, const double *shape, double w)
{
    const gal_rod *rod = d->eq.rod;
    int n = rod->ndof, nq = rod->nq, per = 100, periods = 4;
    double *v0 = calloc((size_t)nq, sizeof(double)), *mphi = malloc((size_t)n * sizeof(double));
    double big = 0;
    for (int j = 0; j < n; j++) big = fmax(big, fabs(shape[j]));
    gal_rod_scatter(rod, shape, v0);
    for (int k = 0; k < nq; k++) v0[k] *= 1e-3 * w / big; /* 1 mm at the largest entry */
    gal_rod_mass_mult(rod, shape, mphi);
    double td = 2 * GAL_PI / (w * sqrt(1 - ZETA * ZETA));
    gal_dyn_opts o;
    gal_dyn_default_opts(&o);
    o.h = td / per, o.damping = C;
    gal_dyn *dy = gal_dyn_alloc(rod, d->eq.q, v0, &o, NULL);
    CHECK(dy != NULL, "%s", gal_error_message());
    double z = NAN;
    if (dy) {
        double e[2];
        for (int pass = 0; pass < 2; pass++) {
            double eta = modal(rod, mphi, dy->q, d->eq.q), deta = modal(rod, mphi, dy->v, NULL);
            e[pass] = 0.5 * (deta * deta + w * w * eta * eta);
            for (int s = 0; pass == 0 && s < per * periods; s++)
                if (gal_dyn_step(dy)) break;
        }
        z = -log(e[1] / e[0]) / (2 * w * periods * td);
    }
    gal_dyn_free(dy);
    free(v0);
    free(mphi);
    return z;
}

static void test_free_decay_ratio(void)
{
    const int sel_a[3] = {3, 2, 1}, sel_b[3] = {1, 0, 0};
    piped a, b;
    if (pipe_init(&a, sel_a)) return;
    if (pipe_init(&b, sel_b)) {
        pipe_clear(&a);
        return;
    }
    const gal_modes *md = &a.d->md;
    int n = md->ndof, probe[2] = {0, -1};
    /* the first mode, and the first of another family above it that selection b leaves out */
    for (int k = 1; k < md->n && probe[1] < 0; k++)
        if (md->mode[k].family != md->mode[0].family && md->mode[k].family != GAL_FAMILY_VERTICAL) probe[1] = k;
    CHECK(probe[1] > 0, "a mode of a second family");
    for (int i = 0; i < 2 && probe[i] >= 0; i++) {
        const gal_mode *mo = &md->mode[probe[i]];
        const double *shape = md->shape + (size_t)probe[i] * n;
        double za = decay_ratio(a.d, a.d->damping, shape, mo->omega);
        double zb = decay_ratio(b.d, b.d->damping, shape, mo->omega);
        printf("    (mode %d, %s, %.4f Hz: free-decay ratio %.6f with %d+%d+%d modes selected, %.6f with %d+%d+%d)\n",
               probe[i] + 1, gal_family_names[mo->family], mo->frequency_hz, za, sel_a[0], sel_a[1], sel_a[2], zb,
               sel_b[0], sel_b[1], sel_b[2]);
        CHECK_REL(za, ZETA, 5e-3);
        CHECK_REL(zb, za, 1e-9);
    }
    pipe_clear(&b);
    pipe_clear(&a);
}

int main(void)
{
    RUN(test_free_decay_ratio);
    return CHECK_SUMMARY();
}
