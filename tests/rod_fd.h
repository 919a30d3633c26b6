/* rod_fd.h: finite-difference checks of the rod's energy terms for the tests (test_rod.c,
 * test_bundle.c, test_bundle_helix.c). Include after check.h and gallop.h. */
#ifndef GALLOP_TESTS_ROD_FD_H
#define GALLOP_TESTS_ROD_FD_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Energy (and gradient, tangent into K) of term k alone, or of the whole rod with k < 0. */
static int rod_fd_eval(const gal_rod *rod, int k, const double *q, double *U, double *g, gal_csc *K)
{
    return k < 0 ? gal_rod_eval(rod, q, U, g, K) : gal_rod_eval_term(rod, k, q, U, g, K);
}

/* Max errors of term k's gradient (the whole rod's with k < 0) against central differences of its
 * energy (every configuration entry) and of its tangent against central differences of its
 * gradient (the free dofs), with the largest gradient and tangent entries: err[4]. */
static void rod_fd_errors(const gal_rod *rod, int k, double *q, double err[4])
{
    int nq = rod->nq, n = rod->ndof;
    double *g = malloc(nq * sizeof(double)), *gp = malloc(nq * sizeof(double)),
           *gm = malloc(nq * sizeof(double)), *col = malloc(n * sizeof(double)),
           *ej = calloc(n, sizeof(double));
    gal_csc *K = gal_csc_clone(rod->K);
    double U;
    CHECK(rod_fd_eval(rod, k, q, &U, g, K) == GAL_OK, "eval term %d: %s", k, gal_error_message());
    memset(err, 0, 4 * sizeof(double));
    for (int i = 0; i < nq; i++) {
        double h = i < 3 * rod->nn ? 1e-5 : 1e-6, save = q[i], Up, Um;
        q[i] = save + h; rod_fd_eval(rod, k, q, &Up, NULL, NULL);
        q[i] = save - h; rod_fd_eval(rod, k, q, &Um, NULL, NULL);
        q[i] = save;
        err[0] = fmax(err[0], fabs((Up - Um) / (2 * h) - g[i]));
        err[1] = fmax(err[1], fabs(g[i]));
    }
    for (int j = 0; j < n; j++) {
        int i = rod->free_q[j];
        double h = i < 3 * rod->nn ? 1e-6 : 1e-7, save = q[i];
        q[i] = save + h; rod_fd_eval(rod, k, q, NULL, gp, NULL);
        q[i] = save - h; rod_fd_eval(rod, k, q, NULL, gm, NULL);
        q[i] = save;
        ej[j] = 1; gal_csc_symv(K, ej, col); ej[j] = 0;
        for (int r = 0; r < n; r++) {
            double fd = (gp[rod->free_q[r]] - gm[rod->free_q[r]]) / (2 * h);
            err[2] = fmax(err[2], fabs(fd - col[r]));
            err[3] = fmax(err[3], fabs(col[r]));
        }
    }
    free(g); free(gp); free(gm); free(col); free(ej);
    gal_csc_free(K);
}

#endif
