/* statics.h: the sagged static equilibrium of a span by Newton's method (DESIGN.md "The rod",
 * end conditions and equilibrium specification), started from the elastic catenary, with a line
 * search on the energy, a Levenberg shift when the tangent is not positive definite on the way,
 * and load stepping on the bending stiffness for hard cases. */
#ifndef GALLOP_STATICS_H
#define GALLOP_STATICS_H

#include "gallop/statics/catenary.h"
#include "gallop/rod/rod.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum { GAL_BY_TENSION = 0, GAL_BY_SAG = 1, GAL_BY_LENGTH = 2 } gal_statics_spec;

typedef struct gal_statics_opts {
    double force_tol;   /* relative to the force scale max(H, w L0); default 1e-10 */
    int max_newton;     /* per solve; default 50 */
    int max_length_iter;/* outer iterations on L0 for a given H or sag; default 30 */
} gal_statics_opts;

typedef struct gal_equilibrium {
    gal_rod *rod;          /* the discretized span at the final unstretched length (owned) */
    double *q;             /* its configuration (nq) */
    gal_catenary cat;      /* the elastic catenary of the same specification (the start) */
    double horizontal_tension; /* N, reaction at the left support */
    double sag;            /* m, mid-span below the chord */
    double unstretched_length; /* m */
    double tension_left, tension_right, tension_max; /* N */
    double residual;       /* N, max |free force| at the end */
    int newton_iterations; /* in all */
    int length_iterations; /* outer iterations on L0 */
    int load_steps;        /* bending-stiffness continuation steps (0: not needed) */
    int twisted;           /* 1: the untwisted equilibrium was unstable (eccentric ice above the
                            * axis) and this is the twisted one the ice weight turns the span to */
    long factorizations;
    double wall_time_s;
    struct gal_tangent *tangent; /* owned, or NULL: the tangent stiffness at q and the symbolic
                                  * analysis of its pattern that the stability check left, which
                                  * gal_modes_find_eq takes over (src/base/chol.h) */
    struct gal_tangent *k0;      /* owned, or NULL: the same tangent with a copy of its numeric
                                  * factorization (the stability check's, unshifted: a clamped or
                                  * absent twist), kept for the reduced model's set-up (rom.h
                                  * gal_rom_opts.k0), which would otherwise evaluate, analyse and
                                  * factorize it again */
} gal_equilibrium;

void gal_statics_default_opts(gal_statics_opts *o);

/* Solve: `p` describes the span and conductor (its unstretched_length is ignored unless spec is
 * GAL_BY_LENGTH, where `value` is used); the result is written to `eq` (free it with
 * gal_equilibrium_clear). GAL_EFAIL with the reason when there is no (stable) equilibrium. */
int gal_statics_solve(const gal_rod_params *p, gal_statics_spec spec, double value,
                      const gal_statics_opts *opts, gal_equilibrium *eq);
void gal_equilibrium_clear(gal_equilibrium *eq);

/* Equilibrium of the rod under gravity and a dead load fext (configuration-sized, generalized
 * forces on the free dofs), by Newton from q (updated in place): grad U(q) = fext to within
 * force_tol (N). Iterations are added to *iterations. */
int gal_statics_solve_loaded(const gal_rod *rod, double *q, const double *fext, double force_tol, int max_newton,
                            int *iterations);

/* Mid-span sag below the chord of a configuration (quadratic interpolation at x = L/2), m. */
double gal_rod_sag(const gal_rod *rod, const double *q);

#ifdef __cplusplus
}
#endif

#endif
