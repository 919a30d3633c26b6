/* force.h: the two callbacks through which external loads reach the equations of motion (paper
 * Eq. 9, the right-hand side F): generalized forces on the whole configuration (the full model)
 * and a distributed load at one point of the span (the reduced model's quadrature, and the full
 * model's element centres). The physics (src/loads/) implements them and the integrators
 * (src/full/, src/reduced/) call them; neither depends on the other. */
#ifndef GALLOP_MODEL_FORCE_H
#define GALLOP_MODEL_FORCE_H

#ifdef __cplusplus
extern "C" {
#endif

/* External generalized forces: add F(t, q, v) to f (configuration-sized; entries of fixed dofs are
 * ignored). v is configuration-sized too (zero at fixed dofs). Returns a status. */
typedef struct gal_force {
    int (*eval)(void *ctx, double t, const double *q, const double *v, double *f);
    void *ctx;
    /* optional: the share of element j alone, f[0..6] on x_j, x_{j+1}, theta_j (set, not added);
     * eval's result is the sum of these over the elements (hyper-reduction samples them) */
    int (*element)(void *ctx, double t, const double *q, const double *v, int j, double f[7]);
    /* optional: eval given the rod's edge frames at q (frames + 6 j: edge j's unit tangent and
     * carried reference director, gal_rod_eval_frames'), the same numbers as eval: a caller that
     * evaluates the rod at the same q hands them over instead of having them computed again */
    int (*eval_framed)(void *ctx, double t, const double *q, const double *v, const double *frames, double *f);
} gal_force;

/* A distributed load per unit length at a point of the span (N/m and N m/m): position r, velocity
 * rdot, unit tangent tan, section reference direction d1, at time t and span abscissa x. Both models
 * evaluate their loads through it. */
typedef struct gal_pointload {
    int (*eval)(void *ctx, double t, double x, const double r[3], const double rdot[3],
                const double tan[3], const double d1[3], double f[3], double *m);
    void *ctx;
} gal_pointload;

#ifdef __cplusplus
}
#endif

#endif
