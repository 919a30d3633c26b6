/* rod_impl.h: what the files of the rod share inside src/rod/ (not public): the stencil sizes,
 * the tangent's pattern and slot maps, the node stencil of bending and torsion, the mass matrix,
 * the eccentric ice's set-up and the parallel transport of frames. */
#ifndef GALLOP_ROD_IMPL_H
#define GALLOP_ROD_IMPL_H

#include "gallop/rod/rod.h"

#define NL 11   /* node stencil: x_{i-1}, x_i, x_{i+1} (9), theta_{i-1}, theta_i */
#define EL 6    /* edge: x_j, x_{j+1} */

/* Configuration indices of the node stencil at interior node i (-1 for absent twists). */
void gal_rod_node_q(const gal_rod *rod, int i, int *qi);
/* The node stencil widened by a bundle's differential-stretch fields (src/rod/bundle_irvine.c):
 * gal_rod_node_q's NL entries, then a_{f,i-1}, a_{f,i} per field f; returns the count. */
#define GAL_ROD_AUX_NL (NL + 4)
int gal_rod_aux_q(const gal_rod *rod, int i, int *qi);
/* The tangent's pattern (rod->K) and the slot maps of the node and edge stencils. */
int gal_rod_pattern_build(gal_rod *rod);

typedef double gal_m33[3][3];
/* The geometry of the node stencil at interior node i: the edges e0 = x_i - x_{i-1} and
 * e1 = x_{i+1} - x_i, their lengths n0, n1 and unit tangents t0, t1, c = t0 . t1, the projections
 * P0 = I - t0 t0^T, P1 = I - t1 t1^T and lbar = l0_{i-1} + l0_i. With tw > 0 (filled by
 * gal_rod_node_pass for the twist's terms, each edge once for its two nodes) also each edge's
 * reference director carried to its tangent, A = transport(tbar, abar, t), the half-angle vector
 * gB = g(tbar, t) and, with tw == 2, Y = DB P, DB its derivative along t: the same numbers the
 * twist strain and its Hessian would compute at the node (src/rod/torsion.c). */
typedef struct gal_rod_node {
    double e0[3], e1[3], t0[3], t1[3], n0, n1, c, lbar;
    double P0[3][3], P1[3][3];
    int tw;
    double A0[3], A1[3], gB0[3], gB1[3];
    gal_m33 Y0, Y1;
} gal_rod_node;
/* The twist strain m = theta1 - theta0 + mref at a node (src/rod/torsion.c), its gradient gm over
 * (e0, e1, theta0, theta1), and the half-angle vectors with their derivatives that its Hessian
 * needs (filled when hess; DB0, DB1 only when the node carries no Y0, Y1: nd->tw != 2). */
typedef struct gal_rod_twist {
    double m, gm[8], gA[3], gB0[3], gB1[3];
    gal_m33 DAu, DAv, DB0, DB1;
} gal_rod_twist;
void gal_rod_twist_strain(const gal_rod *rod, int i, const double *q, const gal_rod_node *nd,
                          int hess, gal_rod_twist *s);
/* H += 2 kt (gm gm^T + m d2m), d2m the symmetrized second derivative of mref over (e0, e1). */
void gal_rod_twist_hessian(const gal_rod_node *nd, gal_rod_twist *s, double kt,
                           double (*H)[8]);

/* The geometry of the node stencil at interior node i (src/rod/node.c; tw = 0); GAL_EFAIL with a
 * message when the rod folds back on itself there. */
int gal_rod_node_geometry(const gal_rod *rod, int i, const double *q, gal_rod_node *nd);
/* The half-angle rotation vector g(u, v) = u x v / (1 + u . v) between unit vectors and its
 * derivatives Du = dg/du, Dv = dg/dv (each may be NULL; src/rod/torsion.c). */
void gal_rod_halfrot(const double *u, const double *v, double *g, gal_m33 Du, gal_m33 Dv);
/* C = A B (3 x 3; C may be A or B). */
void gal_rod_mul33(gal_m33 A, gal_m33 B, gal_m33 C);

/* One pass over the interior nodes for the node terms t[0..nt-1]: per node the geometry (GAL_EFAIL
 * with a message when the rod folds back on itself), the sum of the terms' energies, gradients
 * and Hessians (H when K != NULL), assembled into *U, grad (may be NULL) and K->val (may be NULL).
 * With frames != NULL and a twist term among t, each edge's frame (gal_rod_edge_frame's numbers,
 * computed there for the twist) into frames + 6 j, and *framed = 1. */
int gal_rod_node_pass(const gal_rod *rod, const gal_rod_term *const *t, int nt, const double *q,
                      double *U, double *grad, gal_csc *K, double *frames, int *framed);

/* The node terms t[0..nt-1] at interior node i alone: energy added to *U, gradient to g11 and
 * Hessian to H11 (11 x 11 row-major; may be NULL) over the stencil's node variables (the order of
 * gal_rod_node_q). */
int gal_rod_node_local(const gal_rod *rod, const gal_rod_term *const *t, int nt, int i, const double *q,
                       double *U, double *g11, double *H11);

/* The mass matrix rod->M and its diagonal rod->mdiag from the current rest lengths. */
void gal_rod_mass_build(gal_rod *rod);
/* Eccentric ice (src/rod/ice.c): the directions of the ice centre (rod->ecc_c, left NULL without
 * eccentric ice; GAL_ENOMEM) and its twist-translation coupling added to rod->M. */
int gal_rod_ice_init(gal_rod *rod);
void gal_rod_ice_mass(gal_rod *rod);

/* The reference frames (rod->tbar, rod->abar) from the reference geometry q0; GAL_EINPUT with a
 * message on a zero-length element. */
int gal_rod_frames_init(gal_rod *rod, const double *q0);
/* Parallel transport of a (normal to tb) from unit tangent tb to unit tangent t. */
void gal_rod_transport(const double *tb, const double *a, const double *t, double *r);
/* Edge j's unit tangent ta[0..2] and its reference director carried to it, ta[3..5] (frames.c). */
void gal_rod_edge_frame(const gal_rod *rod, const double *q, int j, double ta[6]);

/* The list of the terms that are on (rod->term, rod->nterm) from the parameters. */
void gal_rod_terms_init(gal_rod *rod);

#endif
