/* bundle.h: the explicit bundle model ([bundle] model = explicit; README "Bundles"): one rod
 * (gal_rod) per sub-conductor at its place on the bundle circle, joined at each spacer by a rigid
 * spacer frame and clamped at the yokes; its statics and its modes.
 *
 * Rigid spacers are exact constraints, eliminated: a spacer has 6 dofs (translation u of its centre,
 * rotation phi), the node of sub-conductor k it holds is x_k = u + R p_k (p_k its offset on the
 * bundle circle, R the spacer's rotation) and that node's twist (the mean of its two edges' twist
 * angles) follows the spacer's rotation about the sub-conductor's tangent t_k: the edge after the
 * node is eliminated as theta_i = 2 psi_k - theta_{i-1}, psi_k the accumulated t_k . dphi. Every
 * other dof of every rod is a dof of the assembled system. The assembled tangent is T^T K_r T over
 * the rods (T the linear map from the system's dofs to each rod's free dofs at the current state)
 * plus the spacers' geometric term (the rod forces at the spacer nodes times the second derivative
 * of R p_k), the mass T^T M_r T plus the spacers' mass and inertia (about the bundle axis as given,
 * half of it about the two axes across: a plane frame). Newton steps rotate the spacers by
 * exp(dphi x).
 *
 * Flexible spacers (bp.spacer_stiffness > 0, src/bundle/arms.c): the spacer nodes are not
 * eliminated but free dofs of their rods, each tied to its clamp point u + R p_k by an arm spring
 * (k on the displacement, k r^2 on the node's twist less psi_k); the frames keep their 6 dofs. */
#ifndef GALLOP_BUNDLE_H
#define GALLOP_BUNDLE_H

#include <stdio.h>

#include "gallop/base/sparse.h"
#include "gallop/modes/modes.h"
#include "gallop/rod/rod.h"
#include "gallop/scene/scene.h"
#include "gallop/statics/statics.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GAL_BUNDLE_MAX 8 /* sub-conductors */

typedef struct gal_bundle_params {
    int subconductors;       /* 2, 3, 4, 6 or 8 */
    double radius;           /* m, of the bundle circle */
    double orientation;      /* rad, of the first sub-conductor from the horizontal */
    int spacers;             /* count, evenly spaced along the sub-conductors (on nodes) */
    const double *positions; /* spacers fractions of the span, increasing, or NULL: evenly spaced
                              * (each on the node nearest it, within GAL_BUNDLE_SNAP of the span) */
    double spacer_mass;      /* kg, of one */
    double spacer_inertia;   /* kg m^2, of one about the bundle axis */
    double spacer_stiffness; /* N/m, flexible spacers: an arm's stiffness at its clamp; 0: rigid */
} gal_bundle_params;

/* The assembled bundle at a state: the rods, their configurations, the spacers' state, the map of
 * each rod's free dofs onto the system's dofs and the system's tangent and mass patterns. */
typedef struct gal_bundle {
    gal_bundle_params bp;
    int n, ns;               /* sub-conductors, spacers */
    int nn;                  /* nodes of each rod (the same mesh for all) */
    gal_rod *rod[GAL_BUNDLE_MAX];
    double off[GAL_BUNDLE_MAX][3]; /* offset of each sub-conductor from the bundle axis (0, y, z) */
    int *spnode;             /* ns: the node each spacer holds */
    int *spat;               /* nn: the spacer at each node, or -1 */
    double *state;           /* the configurations (n x nq) then per spacer u (3), R (9), psi (n) */
    int nstate;
    int ndof;                /* the system's dofs: the rods' independent dofs, then 6 per spacer */
    int sp0;                 /* first spacer dof: 3 + nrot per spacer (u, then the rotation) */
    int nrot;                /* rotation dofs of a spacer: 3, or 2 for a twin (gal_bundle_basis) */
    /* the map: free dof d of rod r is sum_e tval[r][4 d + e] z[tidx[r][4 d + e]], e < tcnt[r][d] */
    int *tcnt[GAL_BUNDLE_MAX], *tidx[GAL_BUNDLE_MAX];
    double *tval[GAL_BUNDLE_MAX];
    gal_csc *K, *M;          /* the system's tangent and mass (values of the last assembly) */
    gal_csc *Kr[GAL_BUNDLE_MAX]; /* each rod's tangent (scratch) */
    double *gq;              /* scratch: one rod's gradient (nq) */
    double *grad;            /* ndof: the system's gradient of the last assembly */
    /* the equilibrium's figures (gal_bundle_statics) */
    double horizontal_tension, sag, unstretched_length; /* of sub-conductor 1 */
    double tension_max;      /* N, the largest element tension of all sub-conductors */
    double asymmetry;        /* m, the largest difference between sub-conductors' displacements
                              * from their own supports (0 by symmetry) */
    double residual;         /* N */
    int newton_iterations, length_iterations;
    long factorizations;
    double wall_time_s;
} gal_bundle;

/* The bundle of n rods of parameters p (one sub-conductor; its mesh is refined to a multiple of
 * spacers + 1 elements, at least 2 between spacers) about the configuration q1 (nq of that mesh: one
 * sub-conductor's, on the bundle axis; each rod is it moved by its offset), spacers at rest. NULL
 * with a message on bad input or memory. */
gal_bundle *gal_bundle_alloc(const gal_rod_params *p, const gal_bundle_params *bp, const double *q1);
gal_bundle *gal_bundle_free(gal_bundle *b);
/* The elements of the refined mesh for `elements` asked and `spacers` evenly spaced. */
int gal_bundle_elements(int elements, int spacers);
#define GAL_BUNDLE_SNAP 1e-3 /* largest distance of a spacer from its node, fraction of the span */
/* The refined mesh for `elements` asked and bp's spacers: evenly spaced as gal_bundle_elements;
 * at bp->positions the smallest count >= elements with every spacer within GAL_BUNDLE_SNAP of the
 * span of a node and at least 2 elements in every sub-span (0 if none up to 1000 or elements). */
int gal_bundle_mesh(int elements, const gal_bundle_params *bp);
/* The galloping runs' mesh rule (README "Bundles", BENCHMARKS "coarse saturated twin"): elements in
 * every sub-span between spacers (and supports); below it a twin turning ~100 deg p-p had its
 * full model's rotation 17-21% low. */
#define GAL_BUNDLE_SUBSPAN_ELEMENTS 6
/* The fewest elements of any sub-span of the mesh gal_bundle_mesh(elements, bp) (0 if none). */
int gal_bundle_subspan_elements(int elements, const gal_bundle_params *bp);

/* Energy, gradient (b->grad) and, when K is nonzero, the tangent (b->K) and mass (b->M) at the
 * state s (b->state when NULL). */
int gal_bundle_eval(gal_bundle *b, const double *s, double *energy, int tangent);
/* s_out = s advanced by the system step dz (spacers rotated by exp(dz_phi x)). */
void gal_bundle_step(const gal_bundle *b, const double *s, const double *dz, double alpha, double *s_out);
/* The rods' configurations of the state s, per rod r: s + r * nq. */
double *gal_bundle_q(const gal_bundle *b, double *s, int r);
/* The rod r's free-dof vector of a system vector z (the linear map T). */
void gal_bundle_map(const gal_bundle *b, int r, const double *z, double *rod_free);
/* y += T_r^T rod_free: rod r's free-dof vector (forces) onto the system's dofs. */
void gal_bundle_map_add_t(const gal_bundle *b, int r, const double *rod_free, double *y);

/* The equilibrium under gravity: each sub-conductor with the span's specification (horizontal
 * tension, sag or unstretched length of one sub-conductor) and the spacers' weight, by Newton on
 * the assembled system from the single sub-conductor's equilibrium (which it is, by symmetry,
 * without spacer weight), with a secant iteration on the common unstretched length. *out is the
 * bundle at its equilibrium. */
int gal_bundle_statics(const gal_rod_params *p, const gal_bundle_params *bp, gal_statics_spec spec,
                       double value, const gal_statics_opts *opts, gal_bundle **out);

/* The nev lowest modes of the assembled system about its equilibrium (ARPACK shift-invert with
 * CHOLMOD), shapes over the system's dofs, mass-normalized, classified by the bundle's kinematics:
 * at each station the sub-conductors' motion is split (mass-orthogonally) into the translation of
 * their centroid (vertical, horizontal, axial), the rigid rotation about it (torsional, with the
 * sub-conductors' own twist and the spacers' rotation) and the rest (subspan). */
int gal_bundle_modes_solve(gal_bundle *b, int nev, gal_modes *out);
/* Enough modes for want[f] of vertical, horizontal and torsional (more asked while one is short,
 * up to max_modes); the lowest want[f] of each are marked selected. */
int gal_bundle_modes_find(gal_bundle *b, const int want[GAL_FAMILY_COUNT], int max_modes, gal_modes *out);

/* The bundle's parameters of a resolved scene ([bundle]). */
void gal_bundle_params_of(const gal_scene *sc, gal_bundle_params *bp);

/* The explicit bundle of a model (its rod: one sub-conductor, model.c): statics, then the modes the
 * model selects. *out and md are the caller's (gal_bundle_free, gal_modes_clear) on success. */
struct gal_model;
int gal_bundle_solve_model(const struct gal_model *m, gal_bundle **out, gal_modes *md);

/* The equivalent model's measured domain (README "Bundles", "When the equivalent model is good
 * enough"): a bundle whose selected vertical mode has its torsional partner within this fraction of
 * its frequency couples them near resonance and rotates by tens of degrees, where the equivalent
 * rod's amplitudes were 22% to 50% off the explicit model's (outside it: within 6%). */
#define GAL_EQUIVALENT_NEAR 0.05
/* 1 when the scene is an equivalent bundle outside that domain for a galloping at f_gallop Hz (the
 * selected vertical mode nearest it has its partner within GAL_EQUIVALENT_NEAR), with the warning in
 * msg (len bytes): the modes, their frequencies and what to do; 0 otherwise (msg empty). md: the
 * scene's modes, selected (gal_modes_find). */
int gal_bundle_equivalent_outside(const gal_scene *sc, const gal_modes *md, double f_gallop, char *msg, size_t len);

/* `gallop modes` of an explicit bundle: the table on fp and the files in dir (README "Bundles":
 * modes.csv and summary.json as a single rod's with share_subspan, equilibrium.csv and shapes.csv
 * with a column `sub`, the sub-conductor, 1 to n). */
void gal_bundle_report_table(FILE *fp, const gal_scene *sc, const gal_bundle *b, const gal_modes *md,
                             const int want[GAL_FAMILY_COUNT], double wall);
int gal_bundle_report(const char *dir, const gal_scene *sc, const gal_bundle *b, const gal_modes *md,
                      const int want[GAL_FAMILY_COUNT], double wall);

#ifdef __cplusplus
}
#endif

#endif
