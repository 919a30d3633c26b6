/* test_rod.c: the discrete rod's forces against finite differences of its energy, its tangent
 * stiffness against finite differences of its forces, and invariances. */
#include "check.h"
#include "gallop.h"
#include "gallop/rod/rod.h"
#include "rod_fd.h"
#include "rod/rod_impl.h"

#include <gsl/gsl_rng.h>

static int ice_next; /* the next random rod carries eccentric ice */

/* A rod on a random 3-D curve near a sagged chord, with random twists. */
static double bundle_next; /* the next random_rod's bundle_radius2 */
static gal_rod *random_rod(int nel, int torsion, int clamped, double EA, double EI, double **q,
                           gsl_rng *r)
{
    gal_rod_params p = {.length = 100, .height_difference = 10, .elements = nel,
                        .unstretched_length = 101, .EA = EA, .EI = EI, .GJ = 300,
                        .mass = 1.5, .polar_inertia = 2e-4, .gravity = 9.81,
                        .torsion = torsion, .twist_clamped = clamped};
    p.bundle_radius2 = bundle_next;
    if (ice_next) p.ecc_mass = 0.5, p.ecc = 0.01, p.ecc_angle = 2.5, p.mass += 0.5;
    int nq = 3 * (nel + 1) + (torsion ? nel : 0);
    double *q0 = calloc((size_t)nq, sizeof(double));
    *q = calloc((size_t)nq, sizeof(double));
    for (int i = 0; i <= nel; i++) {
        double s = (double)i / nel;
        q0[3 * i] = 100 * s;
        q0[3 * i + 2] = 10 * s - 8 * s * (1 - s);
    }
    gal_rod *rod = gal_rod_alloc(&p, q0);
    for (int k = 0; k < nq; k++) (*q)[k] = q0[k];
    /* perturb the free entries: positions by up to 0.5 m, twists by up to 1 rad */
    for (int d = 0; d < rod->ndof; d++) {
        int k = rod->free_q[d];
        (*q)[k] += (k < 3 * (nel + 1) ? 0.5 : 1.0) * (2 * gsl_rng_uniform(r) - 1);
    }
    free(q0);
    return rod;
}

static void check_derivatives(int torsion, int clamped, double EA, double EI)
{
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 7);
    double *q;
    gal_rod *rod = random_rod(12, torsion, clamped, EA, EI, &q, r);
    CHECK(rod != NULL, "alloc: %s", gal_error_message());
    if (!rod) return;
    int nq = rod->nq, n = rod->ndof;
    double *g = malloc(nq * sizeof(double)), *gp = malloc(nq * sizeof(double)),
           *gm = malloc(nq * sizeof(double));
    double U;
    CHECK(gal_rod_eval(rod, q, &U, g, rod->K) == GAL_OK, "eval");
    gal_csc *K = gal_csc_clone(rod->K);
    memcpy(K->val, rod->K->val, K->nnz * sizeof(double));

    /* forces: central differences of the energy over every configuration entry (supports too:
     * their gradient is the support reaction) */
    double maxerr = 0, maxg = 0;
    for (int k = 0; k < nq; k++) {
        double h = k < 3 * rod->nn ? 1e-5 : 1e-6, save = q[k], Up, Um;
        q[k] = save + h; gal_rod_eval(rod, q, &Up, NULL, NULL);
        q[k] = save - h; gal_rod_eval(rod, q, &Um, NULL, NULL);
        q[k] = save;
        double fd = (Up - Um) / (2 * h);
        maxerr = fmax(maxerr, fabs(fd - g[k]));
        maxg = fmax(maxg, fabs(g[k]));
    }
    CHECK(maxerr <= 1e-6 * maxg, "gradient vs FD of energy: max error %g, max |g| %g", maxerr, maxg);

    /* tangent: columns by central differences of the gradient */
    double *col = malloc(n * sizeof(double)), *ej = calloc(n, sizeof(double));
    double kerr = 0, kmax = 0;
    for (int j = 0; j < n; j++) {
        int k = rod->free_q[j];
        double h = k < 3 * rod->nn ? 1e-6 : 1e-7, save = q[k];
        q[k] = save + h; gal_rod_eval(rod, q, NULL, gp, NULL);
        q[k] = save - h; gal_rod_eval(rod, q, NULL, gm, NULL);
        q[k] = save;
        ej[j] = 1; gal_csc_symv(K, ej, col); ej[j] = 0;
        for (int i = 0; i < n; i++) {
            double fd = (gp[rod->free_q[i]] - gm[rod->free_q[i]]) / (2 * h);
            kerr = fmax(kerr, fabs(fd - col[i]));
            kmax = fmax(kmax, fabs(col[i]));
        }
    }
    CHECK(kerr <= 1e-5 * kmax, "tangent vs FD of forces: max error %g, max |K| %g", kerr, kmax);
    printf("    (torsion %d, clamped %d, EI %g: force error %.2g of %.2g, tangent error %.2g of %.2g)\n",
           torsion, clamped, EI, maxerr, maxg, kerr, kmax);
    free(col); free(ej); free(g); free(gp); free(gm); free(q);
    gal_csc_free(K);
    gal_rod_free(rod);
    gsl_rng_free(r);
}

/* EA small so that bending and torsion are not hidden behind extension, then a real conductor */
static void test_derivatives_bending_torsion(void) { check_derivatives(1, 1, 1.0, 50.0); }
static void test_derivatives_torsion_only(void) { check_derivatives(1, 1, 1.0, 0.0); }
static void test_derivatives_free_twist(void) { check_derivatives(1, 0, 1.0, 50.0); }
static void test_derivatives_bending_only(void) { check_derivatives(0, 1, 1.0, 50.0); }
static void test_derivatives_conductor(void) { check_derivatives(1, 1, 1e6, 50.0); }
static void test_derivatives_cable(void) { check_derivatives(0, 1, 1e6, 0.0); }

/* A rigid rotation of a stretched, bent rod (gravity off) leaves its energy alone. (With torsion the
 * twist angles are measured from frames fixed in space, so a rotation of the positions alone is not
 * a rigid motion of the material frames.) */
static void test_rigid_rotation_invariance(void)
{
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 3);
    double *q;
    gal_rod *rod = random_rod(10, 0, 1, 1e6, 20.0, &q, r);
    rod->p.gravity = 0;
    double U0, U1;
    gal_rod_eval(rod, q, &U0, NULL, NULL);
    /* rotate all nodes by 20 degrees about x (the tangents move off their reference: the
     * reference twist must follow) */
    double c = cos(0.35), s = sin(0.35);
    for (int i = 0; i < rod->nn; i++) {
        double y = q[3 * i + 1], z = q[3 * i + 2];
        q[3 * i + 1] = c * y - s * z;
        q[3 * i + 2] = s * y + c * z;
    }
    gal_rod_eval(rod, q, &U1, NULL, NULL);
    CHECK_REL(U1, U0, 1e-10);
    free(q);
    gal_rod_free(rod);
    gsl_rng_free(r);
}

/* Twist energies of a straight rod: uniform twist with free ends, GJ phi^2 / (2 Lc) over the
 * length Lc between the end edges' centres; a rigid rotation c held by clamps: 2 GJ c^2 / l0. */
static void test_uniform_twist_energy(void)
{
    int nel = 20;
    gal_rod_params p = {.length = 10, .elements = nel, .unstretched_length = 10, .EA = 1e6,
                        .EI = 0, .GJ = 250, .mass = 1, .polar_inertia = 1e-4, .torsion = 1,
                        .twist_clamped = 0};
    double *q = calloc(4 * nel + 3, sizeof(double));
    for (int i = 0; i <= nel; i++) q[3 * i] = 10.0 * i / nel;
    gal_rod *rod = gal_rod_alloc(&p, q);
    double phi = 2.0, U;
    for (int j = 0; j < nel; j++) q[3 * (nel + 1) + j] = phi * j / (nel - 1);
    gal_rod_eval(rod, q, &U, NULL, NULL);
    CHECK_REL(U, p.GJ * phi * phi / (2 * 10.0 * (nel - 1) / nel), 1e-12);
    gal_rod_free(rod);
    p.twist_clamped = 1;
    rod = gal_rod_alloc(&p, q);
    for (int j = 0; j < nel; j++) q[3 * (nel + 1) + j] = 0.3;
    gal_rod_eval(rod, q, &U, NULL, NULL);
    CHECK_REL(U, 2 * p.GJ * 0.3 * 0.3 / (10.0 / nel), 1e-12);
    free(q);
    gal_rod_free(rod);
}

/* Every term on, on a curved and twisted configuration: each term's gradient against finite
 * differences of its own energy, its tangent against finite differences of its gradient, and the
 * terms sum to the whole. */
static void test_derivatives_per_term(void)
{
    static const char *const want[] = {"extension", "bending", "torsion", "torsion_clamps",
                                       "ice_eccentricity", "gravity"};
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 11);
    double *q;
    ice_next = 1;
    gal_rod *rod = random_rod(12, 1, 1, 1.0, 50.0, &q, r);
    ice_next = 0;
    CHECK(rod && rod->nterm == 6, "six terms expected, %d", rod ? rod->nterm : -1);
    if (!rod || rod->nterm != 6) return;
    double Usum = 0, U;
    for (int k = 0; k < rod->nterm; k++) {
        CHECK(strcmp(rod->term[k]->name, want[k]) == 0, "term %d is %s, %s expected", k,
              rod->term[k]->name, want[k]);
        double e[4];
        rod_fd_errors(rod, k, q, e);
        CHECK(e[0] <= 1e-6 * e[1], "%s: gradient vs FD of its energy: error %g of %g",
              rod->term[k]->name, e[0], e[1]);
        CHECK(e[2] <= 1e-5 * e[3], "%s: tangent vs FD of its gradient: error %g of %g",
              rod->term[k]->name, e[2], e[3]);
        printf("    (%s: force error %.2g of %.2g, tangent error %.2g of %.2g)\n",
               rod->term[k]->name, e[0], e[1], e[2], e[3]);
        gal_rod_eval_term(rod, k, q, &U, NULL, NULL);
        Usum += U;
    }
    gal_rod_eval(rod, q, &U, NULL, NULL);
    CHECK_REL(Usum, U, 1e-12);
    CHECK(gal_rod_eval_term(rod, 6, q, &U, NULL, NULL) == GAL_EINPUT, "term out of range");
    free(q);
    gal_rod_free(rod);
    gsl_rng_free(r);
}

/* A bundle carried as one rod: its tension-twist terms' gradients and tangents against finite
 * differences, on a stretched (so that the tension stiffens) and twisted configuration; and the
 * stiffness they add to a uniform twist equals T R^2 (the bundle's torsional stiffness from the
 * sub-conductors' tension). */
static void test_bundle_terms(void)
{
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 5);
    double *q;
    bundle_next = 0.04; /* R = 0.2 m */
    gal_rod *rod = random_rod(12, 1, 1, 2e4, 50.0, &q, r);
    bundle_next = 0;
    CHECK(rod && rod->nterm == 7, "seven terms expected, %d", rod ? rod->nterm : -1);
    if (!rod || rod->nterm != 7) return;
    CHECK(rod->term[3] == &gal_rod_term_bundle_torsion && rod->term[5] == &gal_rod_term_bundle_clamps,
          "bundle terms in place");
    for (int k = 3; k <= 5; k += 2) {
        double e[4];
        rod_fd_errors(rod, k, q, e);
        CHECK(e[0] <= 1e-6 * e[1], "%s: gradient vs FD of its energy: error %g of %g",
              rod->term[k]->name, e[0], e[1]);
        CHECK(e[2] <= 1e-5 * e[3], "%s: tangent vs FD of its gradient: error %g of %g",
              rod->term[k]->name, e[2], e[3]);
        printf("    (%s: force error %.2g of %.2g, tangent error %.2g of %.2g)\n",
               rod->term[k]->name, e[0], e[1], e[2], e[3]);
    }
    /* a straight rod stretched by eps and twisted uniformly by phi over its length: the two
     * terms' energy is T R^2 phi^2 / (2 L0) (T = EA eps) */
    int nel = rod->p.elements, nn = rod->nn;
    double eps = 0.01, phi = 0.3, L0 = rod->p.unstretched_length, U0, U1;
    for (int i = 0; i < nn; i++) {
        double s = (double)i / nel;
        q[3 * i] = 100 * s, q[3 * i + 1] = 0, q[3 * i + 2] = 10 * s;
    }
    double chord = sqrt(100.0 * 100.0 + 10.0 * 10.0);
    for (int j = 0; j < nel; j++) rod->l0[j] = chord / (1 + eps) / nel;
    L0 = chord / (1 + eps);
    /* element j's twist at its centre, phi (j + 1/2) / nel, clamped 0 at both supports: not a
     * uniform rate at the ends; take the interior nodes' share and the clamps' share together */
    for (int j = 0; j < nel; j++) q[3 * nn + j] = 0;
    gal_rod_eval_term(rod, 3, q, &U0, NULL, NULL);
    CHECK(fabs(U0) < 1e-12, "untwisted: no bundle energy (%g)", U0);
    for (int j = 0; j < nel; j++) q[3 * nn + j] = phi * sin(GAL_PI * (j + 0.5) / nel);
    double Un, Uc;
    gal_rod_eval_term(rod, 3, q, &Un, NULL, NULL);
    gal_rod_eval_term(rod, 5, q, &Uc, NULL, NULL);
    U1 = Un + Uc;
    /* continuous: T R^2 / 2 int (phi pi / L0 cos(pi s/L0))^2 ds = T R^2 phi^2 pi^2 / (4 L0) */
    double T = rod->p.EA * eps, want = T * 0.04 * phi * phi * GAL_PI * GAL_PI / (4 * L0);
    CHECK_REL(U1, want, 0.02);
    printf("    (bundle twist energy %.6g J, continuous %.6g J)\n", U1, want);
    free(q);
    gal_rod_free(rod);
    gsl_rng_free(r);
}

/* An effect that is off is not in the list: a cable (no bending, no torsion, no gravity) has the
 * extension alone; a free twist has no clamp term. */
static void test_term_list(void)
{
    gal_rod_params p = {.length = 10, .elements = 4, .unstretched_length = 10, .EA = 1e6,
                        .mass = 1, .polar_inertia = 1e-4, .GJ = 1};
    double q[15 + 4] = {0};
    for (int i = 0; i <= 4; i++) q[3 * i] = 2.5 * i;
    gal_rod *rod = gal_rod_alloc(&p, q);
    CHECK(rod && rod->nterm == 1 && rod->term[0] == &gal_rod_term_extension, "extension alone");
    gal_rod_free(rod);
    p.torsion = 1, p.gravity = 9.81, p.ecc_mass = 0.1, p.ecc = 0.01;
    rod = gal_rod_alloc(&p, q);
    CHECK(rod && rod->nterm == 4 && rod->term[1] == &gal_rod_term_torsion &&
          rod->term[2] == &gal_rod_term_ice && rod->term[3] == &gal_rod_term_gravity,
          "extension, torsion (free ends), ice, gravity");
    gal_rod_free(rod);
}


/* The node pass (gal_rod_node_pass) computes each edge's geometry and twist frame data once for
 * its two nodes; the same gradient and tangent, bit for bit, as each node evaluated alone with
 * every quantity computed there (gal_rod_node_local over gal_rod_node_geometry), assembled in
 * the same order: on a rod with bending and torsion (clamped and free), torsion alone, and a
 * bundle's twist terms, gradient alone and with the tangent; with torsion the edge frames it hands
 * out (gal_rod_eval_frames, to the loads) are gal_rod_edge_frame's, bit for bit. */
static void check_pass_bitwise(int torsion, int clamped, double EI, double R2, unsigned long seed)
{
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, seed);
    double *q;
    bundle_next = R2;
    gal_rod *rod = random_rod(15, torsion, clamped, 2e4, EI, &q, r);
    bundle_next = 0;
    CHECK(rod != NULL, "alloc: %s", gal_error_message());
    if (!rod) return;
    int k0 = 0, k1, nq = rod->nq, nnz = rod->K->nnz, bad = 0;
    while (k0 < rod->nterm && !rod->term[k0]->node) k0++;
    for (k1 = k0; k1 < rod->nterm && rod->term[k1]->node; k1++) {}
    CHECK(k1 > k0, "a run of node terms");
    double *g = calloc(nq, sizeof(double)), *gr = calloc(nq, sizeof(double)), *fr = calloc(6 * rod->p.elements, sizeof(double));
    gal_csc *K = gal_csc_clone(rod->K), *Kr = gal_csc_clone(rod->K);
    for (int withK = 0; withK < 2; withK++) {
        double U = 0, Ur = 0;
        memset(g, 0, nq * sizeof(double)), memset(gr, 0, nq * sizeof(double));
        memset(K->val, 0, nnz * sizeof(double)), memset(Kr->val, 0, nnz * sizeof(double));
        int framed = 0, fbad = 0;
        CHECK(gal_rod_node_pass(rod, rod->term + k0, k1 - k0, q, &U, g, withK ? K : NULL, fr, &framed) == GAL_OK, "pass");
        CHECK(framed == torsion, "edge frames handed out (%d) with the twist's terms (%d)", framed, torsion);
        for (int j = 0; j < rod->p.elements && framed; j++) { /* each edge's frame, as computed alone */
            double ta[6];
            gal_rod_edge_frame(rod, q, j, ta);
            for (int k = 0; k < 6; k++) fbad += !(fr[6 * j + k] == ta[k]);
        }
        CHECK(fbad == 0, "%d edge frame entries differ from gal_rod_edge_frame's", fbad);
        for (int i = 1; i <= rod->nn - 2; i++) {
            double g11[NL] = {0}, H11[NL * NL] = {0};
            int qi[NL];
            CHECK(gal_rod_node_local(rod, rod->term + k0, k1 - k0, i, q, &Ur, g11, withK ? H11 : NULL) == GAL_OK, "local");
            gal_rod_node_q(rod, i, qi);
            for (int a = 0; a < NL; a++)
                if (qi[a] >= 0) gr[qi[a]] += g11[a];
            const int *sm = rod->slot_node + (size_t)(i - 1) * NL * NL;
            for (int ab = 0; withK && ab < NL * NL; ab++)
                if (sm[ab] >= 0) Kr->val[sm[ab]] += H11[ab];
        }
        for (int k = 0; k < nq; k++) bad += !(g[k] == gr[k]);
        for (int p = 0; p < nnz; p++) bad += !(K->val[p] == Kr->val[p]);
        CHECK(bad == 0, "%s: %d entries differ from the nodes evaluated alone", withK ? "tangent" : "gradient", bad);
        CHECK_REL(U, Ur, 1e-13);
    }
    printf("    (torsion %d, clamped %d, EI %g, R^2 %g: %d node terms, bit for bit)\n", torsion, clamped, EI, R2, k1 - k0);
    free(g), free(gr), free(fr), free(q), gal_csc_free(K), gal_csc_free(Kr);
    gal_rod_free(rod);
    gsl_rng_free(r);
}

static void test_node_pass_bitwise(void)
{
    check_pass_bitwise(1, 1, 50.0, 0, 11);
    check_pass_bitwise(1, 0, 50.0, 0, 12);
    check_pass_bitwise(1, 1, 0.0, 0, 13);
    check_pass_bitwise(0, 1, 50.0, 0, 14);
    check_pass_bitwise(1, 1, 50.0, 0.04, 15);
}

/* The fold-back check of the node stencil: a turn of the rod at node 5 whose cosine is -0.998
 * between edges of lengths 1 and 2 m is a sharp bend, evaluated; at -0.9995 the rod folds back
 * on itself there, refused with the node. */
static void test_fold_back(void)
{
    gal_rod_params p = {.length = 10, .elements = 10, .unstretched_length = 10, .EA = 1e6, .EI = 50,
                        .mass = 1, .polar_inertia = 1e-4, .GJ = 1};
    double q0[33] = {0}, q[33];
    for (int i = 0; i <= 10; i++) q0[3 * i] = i;
    gal_rod *rod = gal_rod_alloc(&p, q0);
    CHECK(rod != NULL, "alloc: %s", gal_error_message());
    if (!rod) return;
    for (int pass = 0; pass < 2; pass++) {
        double c = pass ? -0.9995 : -0.998, s = sqrt(1 - c * c), U;
        memcpy(q, q0, sizeof q);
        for (int i = 6; i <= 10; i++) q[3 * i] = 5 + 2 * (i - 5) * c, q[3 * i + 1] = 2 * (i - 5) * s;
        int st = gal_rod_eval(rod, q, &U, NULL, NULL);
        if (!pass) CHECK(st == GAL_OK, "a sharp bend (cos %g) evaluated: %s", c, gal_error_message());
        else
            CHECK(st == GAL_EFAIL && strstr(gal_error_message(), "node 5"), "folded back at node 5 (cos %g): %d, %s", c,
                  st, gal_error_message());
    }
    gal_rod_free(rod);
}

int main(void)
{
    RUN(test_derivatives_bending_torsion);
    RUN(test_derivatives_torsion_only);
    RUN(test_derivatives_free_twist);
    RUN(test_derivatives_bending_only);
    RUN(test_derivatives_conductor);
    RUN(test_derivatives_cable);
    RUN(test_rigid_rotation_invariance);
    RUN(test_uniform_twist_energy);
    RUN(test_derivatives_per_term);
    RUN(test_term_list);
    RUN(test_bundle_terms);
    RUN(test_node_pass_bitwise);
    RUN(test_fold_back);
    return CHECK_SUMMARY();
}
