/* test_ecsw.c: hyper-reduction of the recomputed reduced model (ecsw.h): the non-negative least
 * squares against known problems, the rod's energy split into elements against gal_rod_eval and
 * finite differences, the loads' element shares against gal_loads_full, and the hyper-reduced
 * reduced forces against the exact projected ones (every weight 1: to round-off; on the training
 * states: to the fit's tolerance; at unseen states: a stated bound; also on a mesh finer than the
 * training's candidates), its tangent against
 * differences of its force, a symmetric span keeping a symmetric motion symmetric, and the
 * re-sampling when the check fails. */
#include "check.h"
#include "gallop.h"
#include "gallop/modes/modes.h"
#include "gallop/reduced/ecsw.h"
#include "gallop/statics/statics.h"
#include "reduced/hyper.h"

/* A known non-negative solution with zeros is recovered; a problem whose least-squares solution
 * has negative entries meets the Kuhn-Tucker conditions. */
static void test_nnls(void)
{
    enum { M = 30, N = 12 };
    double A[M * N], b[M], x[N], xs[N] = {0, 1.5, 0, 0.25, 2, 0, 0, 0.5, 0, 3, 0, 0.1};
    unsigned s = 7;
    for (int k = 0; k < M * N; k++) s = s * 1103515245u + 12345u, A[k] = (double)(s >> 8) / (1u << 24) - 0.3;
    for (int i = 0; i < M; i++) {
        b[i] = 0;
        for (int j = 0; j < N; j++) b[i] += A[j * M + i] * xs[j];
    }
    int it;
    CHECK(gal_nnls(M, N, A, b, 1e-14, 0, x, &it) == GAL_OK, "%s", gal_error_message());
    for (int j = 0; j < N; j++) CHECK_NEAR(x[j], xs[j], 1e-10);
    /* b with a part no non-negative combination reaches: Kuhn-Tucker at the solution */
    for (int i = 0; i < M; i++) b[i] = (i % 3 ? 1.0 : -2.0) - 0.1 * i;
    CHECK(gal_nnls(M, N, A, b, 0, 0, x, &it) == GAL_OK, "%s", gal_error_message());
    double r[M], wmax = 0, wpos = 0;
    for (int i = 0; i < M; i++) {
        r[i] = b[i];
        for (int j = 0; j < N; j++) r[i] -= A[j * M + i] * x[j];
    }
    int npos = 0;
    for (int j = 0; j < N; j++) {
        double w = 0; /* w = A^T r: <= 0 where x = 0, = 0 where x > 0 */
        for (int i = 0; i < M; i++) w += A[j * M + i] * r[i];
        CHECK(x[j] >= 0, "x[%d] = %g", j, x[j]);
        if (x[j] > 0) wpos = fmax(wpos, fabs(w)), npos++;
        else wmax = fmax(wmax, w);
    }
    CHECK(npos > 0 && npos < N, "a solution on the boundary (%d positive)", npos);
    CHECK(wpos < 1e-10 && wmax < 1e-10, "Kuhn-Tucker: |w| on the passive set %g, max w on the active %g", wpos, wmax);
}

typedef struct {
    gal_equilibrium eq;
    gal_modes md;
    int sel[16], r;
} span;

static int make_span(span *s, const gal_rod_params *p, double sag, const int want[GAL_FAMILY_COUNT])
{
    memset(s, 0, sizeof *s);
    if (gal_statics_solve(p, GAL_BY_SAG, sag, NULL, &s->eq) || gal_modes_find(s->eq.rod, s->eq.q, want, 60, &s->md)) {
        CHECK(0, "%s", gal_error_message());
        return 1;
    }
    for (int k = 0; k < s->md.n && s->r < 16; k++)
        if (s->md.mode[k].selected) s->sel[s->r++] = k;
    return 0;
}

static void free_span(span *s)
{
    gal_modes_clear(&s->md);
    gal_equilibrium_clear(&s->eq);
}

/* an inclined span with torsion and eccentric ice: every term of the rod is on */
static const gal_rod_params iced = {.length = 150, .height_difference = 20, .elements = 24, .EA = 3e7, .EI = 30,
                                    .GJ = 200, .mass = 2.2, .polar_inertia = 4e-4, .gravity = 9.80665, .torsion = 1,
                                    .twist_clamped = 1, .ecc_mass = 0.6, .ecc = 0.01, .ecc_angle = 2.0};

/* The element split: the sum at weight 1 is gal_rod_eval (energy, gradient, tangent); an element's
 * gradient and Hessian are the differences of its energy and gradient. */
static void element_split(const gal_rod_params *p)
{
    span s;
    int want[GAL_FAMILY_COUNT] = {2, 1, 1, 0};
    if (make_span(&s, p, 4.0, want)) return;
    const gal_rod *rod = s.eq.rod;
    int nq = rod->nq, ne = gal_rod_element_count(rod);
    CHECK(ne == 2 * rod->p.elements - 1, "%d energy elements", ne);
    double *q = malloc(nq * sizeof(double)), *g1 = malloc(nq * sizeof(double)), *g2 = malloc(nq * sizeof(double));
    double *w = malloc(ne * sizeof(double));
    int *el = malloc(ne * sizeof(int));
    gal_csc *K1 = gal_csc_clone(rod->K), *K2 = gal_csc_clone(rod->K);
    for (int k = 0; k < nq; k++) q[k] = s.eq.q[k] + (rod->dof[k] >= 0 ? 0.3 * sin(0.7 * k) : 0);
    for (int e = 0; e < ne; e++) el[e] = e, w[e] = 1;
    double U1, U2;
    CHECK(gal_rod_eval(rod, q, &U1, g1, K1) == GAL_OK, "%s", gal_error_message());
    CHECK(gal_rod_eval_weighted(rod, ne, el, w, q, &U2, g2, K2) == GAL_OK, "%s", gal_error_message());
    double ge = 0, gm = 0, ke = 0, km = 0;
    for (int k = 0; k < nq; k++) ge = fmax(ge, fabs(g1[k] - g2[k])), gm = fmax(gm, fabs(g1[k]));
    for (int k = 0; k < K1->nnz; k++) ke = fmax(ke, fabs(K1->val[k] - K2->val[k])), km = fmax(km, fabs(K1->val[k]));
    CHECK_REL(U2, U1, 1e-12);
    CHECK(ge <= 1e-11 * gm && ke <= 1e-11 * km, "weighted sum vs gal_rod_eval: gradient %g of %g, tangent %g of %g", ge, gm, ke, km);
    int elems[3] = {0, rod->p.elements + 5, rod->p.elements - 1}; /* an end edge, a node, the other end */
    for (int t = 0; t < 3; t++) {
        int e = elems[t], qi[GAL_ROD_ELEMENT_NQ];
        double g[11], H[121], gp[11], gmn[11], Up, Um, Ue, err = 0, herr = 0, hmax = 0, gmax = 0;
        gal_rod_element_q(rod, e, qi);
        gal_rod_element_eval(rod, e, q, &Ue, g, H);
        for (int a = 0; a < 11; a++) {
            if (qi[a] < 0) continue;
            double hq = 1e-6, sv = q[qi[a]];
            q[qi[a]] = sv + hq, gal_rod_element_eval(rod, e, q, &Up, gp, NULL);
            q[qi[a]] = sv - hq, gal_rod_element_eval(rod, e, q, &Um, gmn, NULL);
            q[qi[a]] = sv;
            err = fmax(err, fabs((Up - Um) / (2 * hq) - g[a])), gmax = fmax(gmax, fabs(g[a]));
            for (int b = 0; b < 11; b++) herr = fmax(herr, fabs((gp[b] - gmn[b]) / (2 * hq) - H[b * 11 + a])), hmax = fmax(hmax, fabs(H[b * 11 + a]));
        }
        CHECK(err <= 1e-6 * gmax && herr <= 1e-5 * hmax, "element %d: gradient %g of %g, Hessian %g of %g", e, err, gmax, herr, hmax);
        CHECK(gal_rod_element_mirror(rod, gal_rod_element_mirror(rod, e)) == e, "the mirror of the mirror of %d", e);
    }
    gal_csc_free(K1); gal_csc_free(K2);
    free(q); free(g1); free(g2); free(w); free(el);
    free_span(&s);
}

/* every term: the iced span, and a bundle carried as one rod (its tension's torsional stiffness) */
static void test_element_split(void)
{
    gal_rod_params p = iced;
    element_split(&p);
    p.bundle_radius2 = 0.04, p.ecc_mass = 0, p.ecc = 0;
    element_split(&p);
}

/* |a - b| / |b - c| in the row weights of sample 0 */
static double rel_err(const gal_rom *m, const double *a, const double *b, const double *c)
{
    const double *rw = m->hyper->set[0].rw;
    double e = 0, d = 0;
    for (int k = 0; k < m->r; k++) e += pow(rw[k] * (a[k] - b[k]), 2), d += pow(rw[k] * (b[k] - c[k]), 2);
    return sqrt(e / d);
}

/* The hyper-reduced force: on the training states within the fit (the NNLS residual bounds each
 * state's error by hyper_tol sqrt(states)), at unseen states of the same scale within 5 hyper_tol;
 * every weight 1 gives the exact projected force; the tangent is the derivative of the force. */
static void hyper_forces(const gal_rod_params *p, int tangent)
{
    span s;
    int want[GAL_FAMILY_COUNT] = {2, 1, 1, 0};
    if (make_span(&s, p, 4.0, want)) return;
    gal_rom_opts o;
    gal_rom_default_opts(&o);
    gal_rom *m = gal_rom_alloc(s.eq.rod, s.eq.q, &s.md, s.sel, s.r, &o, NULL);
    CHECK(m != NULL && m->hyper, "%s", gal_error_message());
    if (!m) { free_span(&s); return; }
    int r = m->r;
    gal_rom_hyper *h = m->hyper;
    double *f = malloc(r * sizeof(double)), *fx = malloc(r * sizeof(double)), *x = calloc(r, sizeof(double));
    double *Kr = malloc((size_t)r * r * sizeof(double)), *fp = malloc(r * sizeof(double)), *fm = malloc(r * sizeof(double));
    double etrain = 0, eunseen = 0;
    for (int k = 0; k < h->ns; k++) {
        const double *xs = h->snap + (size_t)k * (2 * r + 1);
        gal_rom_internal_force(m, xs, f), gal_rom_exact_force(m, xs, fx);
        etrain = fmax(etrain, rel_err(m, f, fx, h->F0));
    }
    /* unseen: each training state's modal part turned to another direction */
    for (int k = 1; k < h->ns; k++) {
        const double *xa = h->snap + (size_t)k * (2 * r + 1), *xb = h->snap + (size_t)(k - 1) * (2 * r + 1);
        for (int i = 0; i < r; i++) x[i] = 0.6 * xa[i] + 0.4 * xb[i];
        gal_rom_internal_force(m, x, f), gal_rom_exact_force(m, x, fx);
        eunseen = fmax(eunseen, rel_err(m, f, fx, h->F0));
    }
    gal_rom_hyper_info hi;
    gal_rom_hyper_get_info(m, &hi);
    printf("    (%d of %d energy elements sampled; force error on the %d training states %.1e, unseen %.1e)\n",
           hi.elements, gal_rod_element_count(s.eq.rod), h->ns, etrain, eunseen);
    CHECK(hi.elements < gal_rod_element_count(s.eq.rod), "a sample (%d)", hi.elements);
    CHECK(etrain <= o.hyper_tol * sqrt(h->ns), "training error %g", etrain);
    CHECK(eunseen <= 5 * o.hyper_tol, "unseen error %g", eunseen);
    /* tangent against central differences of the hyper-reduced force, at a training state */
    memcpy(x, h->snap + (size_t)3 * (2 * r + 1), r * sizeof(double));
    gal_rom_hyper_internal(m, x, f, Kr);
    double terr = 0, tmax = 0;
    for (int j = 0; j < r && tangent; j++) {
        double hj = 1e-5 * (fabs(x[j]) + 1e-3);
        x[j] += hj, gal_rom_internal_force(m, x, fp);
        x[j] -= 2 * hj, gal_rom_internal_force(m, x, fm);
        x[j] += hj;
        for (int i = 0; i < r; i++) terr = fmax(terr, fabs((fp[i] - fm[i]) / (2 * hj) - Kr[i * r + j])), tmax = fmax(tmax, fabs(Kr[i * r + j]));
    }
    CHECK(terr <= 1e-5 * tmax, "hyper-reduced tangent vs differences: %g of %g", terr, tmax);
    /* every weight 1: the exact projected force */
    CHECK(gal_rom_hyper_use_all(m) == GAL_OK, "%s", gal_error_message());
    double eall = 0, fmx = 0;
    for (int k = 0; k < h->ns; k++) {
        const double *xs = h->snap + (size_t)k * (2 * r + 1);
        gal_rom_internal_force(m, xs, f), gal_rom_exact_force(m, xs, fx);
        for (int i = 0; i < r; i++) eall = fmax(eall, fabs(f[i] - fx[i])), fmx = fmax(fmx, fabs(fx[i]));
    }
    CHECK(eall <= 1e-10 * fmx, "every weight 1: %g of %g", eall, fmx);
    free(f); free(fx); free(x); free(Kr); free(fp); free(fm);
    gal_rom_free(m);
    free_span(&s);
}

static void test_hyper_forces(void)
{
    hyper_forces(&iced, 1);
}

/* A mesh finer than the candidates (ecsw_train.c: 128 of each kind of element): the same bounds
 * with the fit on the candidates against the assembled targets, and on a level span the mirror
 * pairs. */
static void test_candidates(void)
{
    gal_rod_params p = iced;
    p.elements = 300;
    hyper_forces(&p, 0); /* (the tangent's differences are not that accurate on this mesh, with
                          * every element as candidate too: 8 of 75000; it is the same code) */
    p.height_difference = 0, p.ecc_mass = 0, p.ecc = 0;
    span s;
    int want[GAL_FAMILY_COUNT] = {2, 1, 1, 0};
    if (make_span(&s, &p, 4.0, want)) return;
    gal_rom_opts o;
    gal_rom_default_opts(&o);
    gal_rom *m = gal_rom_alloc(s.eq.rod, s.eq.q, &s.md, s.sel, s.r, &o, NULL);
    CHECK(m != NULL, "%s", gal_error_message());
    if (!m) { free_span(&s); return; }
    const gal_rom_hyper_set *S = &m->hyper->set[0];
    int pairs = 1;
    for (int k = 0; k < S->n; k++) {
        int me = gal_rod_element_mirror(m->rod, S->elem[k]), found = 0;
        for (int j = 0; j < S->n; j++) found |= S->elem[j] == me && S->w[j] == S->w[k];
        pairs &= found;
    }
    CHECK(m->hyper->mirror && pairs && S->fit_error <= o.hyper_tol, "mirror pairs of equal weight, fit %g", S->fit_error);
    gal_rom_free(m);
    free_span(&s);
}

/* The training's cost against the mesh (issue 13: the set-up at 1000 elements at most 3x its cost
 * at 100): above 128 elements the element evaluations of the candidate columns do not grow with
 * the mesh (128 of each kind of element per training state) and the targets take one evaluation of
 * the whole rod per training state; up to 128 elements every element is a candidate and there is
 * no whole-rod evaluation. */
static long train_counts_fine(int elements, int fine, long *full, int *ns)
{
    gal_rod_params p = iced;
    p.elements = elements;
    span s;
    int want[GAL_FAMILY_COUNT] = {2, 1, 1, 0};
    if (make_span(&s, &p, 4.0, want)) return -1;
    gal_rom_opts o;
    gal_rom_default_opts(&o);
    o.hyper_snapshots_fine = fine;
    gal_rom *m = gal_rom_alloc(s.eq.rod, s.eq.q, &s.md, s.sel, s.r, &o, NULL);
    CHECK(m != NULL, "%s", gal_error_message());
    long ev = -1;
    if (m) {
        gal_rom_hyper_info hi;
        gal_rom_hyper_get_info(m, &hi);
        ev = hi.train_element_evals, *full = hi.train_full_evals, *ns = hi.snapshots;
    }
    gal_rom_free(m);
    free_span(&s);
    return ev;
}

static long train_counts(int elements, long *full, int *ns)
{
    return train_counts_fine(elements, 0, full, ns);
}

static void test_training_counts(void)
{
    long f0, f1, f2;
    int n0, n1, n2;
    long e0 = train_counts(60, &f0, &n0), e1 = train_counts(260, &f1, &n1), e2 = train_counts(520, &f2, &n2);
    printf("    (element evaluations of the training: %ld at 60 elements, %ld at 260, %ld at 520; whole-rod: %ld, %ld, %ld)\n",
           e0, e1, e2, f0, f1, f2);
    CHECK(e0 == (long)n0 * (2 * 60 - 1) && f0 == 0, "60 elements: every element a candidate, %ld, %ld", e0, f0);
    CHECK(e1 > 0 && e2 > 0 && e2 <= e1 + 2L * n2 && e1 <= (long)n1 * (2 * 128 + 4), "candidates: %ld at 260, %ld at 520", e1, e2);
    CHECK(f1 == n1 && f2 == n2, "one whole-rod evaluation a training state: %ld of %d, %ld of %d", f1, n1, f2, n2);
    /* the training states: hyper_snapshots at every mesh by default; with hyper_snapshots_fine,
     * that many above the candidates' count of elements (128), where each costs the whole mesh */
    gal_rom_opts o;
    gal_rom_default_opts(&o);
    CHECK(n0 == o.hyper_snapshots && n1 == o.hyper_snapshots && n2 == o.hyper_snapshots, "training states %d, %d, %d",
          n0, n1, n2);
    long f3, f4, f5;
    int n3, n4, n5, fine = o.hyper_snapshots / 2;
    train_counts_fine(128, fine, &f3, &n3), train_counts_fine(129, fine, &f4, &n4), train_counts_fine(520, fine, &f5, &n5);
    CHECK(n3 == o.hyper_snapshots && f3 == 0, "hyper_snapshots_fine %d: %d training states at 128 elements", fine, n3);
    CHECK(n4 == fine && n5 == fine && f4 == n4 && f5 == n5,
          "hyper_snapshots_fine %d: %d and %d training states at 129 and 520 elements (whole-rod evaluations %ld, %ld)",
          fine, n4, n5, f4, f5);
}

/* The loads' element shares add up to gal_loads_full. */
static void test_load_elements(void)
{
    gal_scene sc;
    if (gal_scene_load(&sc, "tests/rom/condor_150_taut_dshape.ini", NULL, 0, "data/conductors.csv")) {
        CHECK(0, "%s", gal_error_message());
        return;
    }
    gal_sim_setup su;
    if (gal_sim_setup_init(&su, &sc, 1)) { CHECK(0, "%s", gal_error_message()); return; }
    const gal_loads *L = &su.data->loads;
    const gal_rod *rod = su.data->eq.rod;
    int nq = rod->nq, nn = rod->nn;
    double *q = malloc(nq * sizeof(double)), *v = calloc(nq, sizeof(double)), *f = calloc(nq, sizeof(double)), *fs = calloc(nq, sizeof(double));
    for (int k = 0; k < nq; k++) q[k] = su.data->eq.q[k] + 0.2 * sin(0.3 * k), v[k] = rod->dof[k] >= 0 ? 0.5 * cos(0.2 * k) : 0;
    gal_loads_full((void *)L, 30.0, q, v, f);
    for (int j = 0; j < rod->p.elements; j++) {
        double fe[7];
        gal_loads_element((void *)L, 30.0, q, v, j, fe);
        for (int k = 0; k < 6; k++) fs[3 * j + k] += fe[k];
        fs[3 * nn + j] += fe[6];
    }
    double e = 0, mx = 0;
    for (int k = 0; k < nq; k++) e = fmax(e, fabs(f[k] - fs[k])), mx = fmax(mx, fabs(f[k]));
    CHECK(mx > 0 && e <= 1e-12 * mx, "element loads vs gal_loads_full: %g of %g", e, mx);
    free(q); free(v); free(f); free(fs);
    gal_sim_setup_clear(&su);
}

/* On a level span without eccentric ice the sample is made of mirror pairs (one weight each), and
 * a check below the sample's error re-samples with the state among the training states. */
static void test_mirror_and_resample(void)
{
    span s;
    int want[GAL_FAMILY_COUNT] = {2, 1, 1, 0};
    gal_rod_params p = iced;
    p.height_difference = 0, p.ecc_mass = 0, p.ecc = 0;
    if (make_span(&s, &p, 4.0, want)) return;
    gal_rom_opts o;
    gal_rom_default_opts(&o);
    gal_rom *m = gal_rom_alloc(s.eq.rod, s.eq.q, &s.md, s.sel, s.r, &o, NULL);
    CHECK(m != NULL, "%s", gal_error_message());
    if (!m) { free_span(&s); return; }
    const gal_rom_hyper_set *S = &m->hyper->set[0];
    int pairs = 1;
    for (int k = 0; k < S->n; k++) {
        int me = gal_rod_element_mirror(m->rod, S->elem[k]), found = 0;
        for (int j = 0; j < S->n; j++) found |= S->elem[j] == me && S->w[j] == S->w[k];
        pairs &= found;
    }
    CHECK(m->hyper->mirror && pairs, "mirror pairs of equal weight");
    /* a state far outside the training scale: the check fails, the model re-samples */
    int ns = m->hyper->ns;
    for (int k = 0; k < m->nmodes; k++) m->x[k] = 3 * m->hyper->snap[(size_t)5 * (2 * m->r + 1) + k];
    double err;
    m->o.hyper_check_tol = 1e-9;
    CHECK(gal_rom_hyper_check(m, &err) == GAL_OK, "%s", gal_error_message());
    CHECK(err > 1e-9 && m->hyper->refits == 1 && m->hyper->ns == ns + 1, "error %g, refits %d", err, m->hyper->refits);
    double err2;
    m->o.hyper_check_tol = 1;
    CHECK(gal_rom_hyper_check(m, &err2) == GAL_OK, "%s", gal_error_message());
    printf("    (a state at 3x the training scale: error %.1e before re-sampling, %.1e after)\n", err, err2);
    CHECK(err2 <= o.hyper_tol * sqrt(m->hyper->ns), "the state, now a training state, within the fit: %g", err2);
    gal_rom_free(m);
    free_span(&s);
}

int main(void)
{
    RUN(test_nnls);
    RUN(test_element_split);
    RUN(test_hyper_forces);
    RUN(test_candidates);
    RUN(test_training_counts);
    RUN(test_load_elements);
    RUN(test_mirror_and_resample);
    return CHECK_SUMMARY();
}
