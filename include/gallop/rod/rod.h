/* rod.h: the discrete Cosserat (Kirchhoff) rod of a conductor span (paper Eqs. 1-8; DESIGN.md
 * "The rod"). Nodes carry positions, edges carry one twist angle each; material frames are the
 * reference frames of the equilibrium tangents carried to the current tangents by the minimal
 * rotation, turned by the twist angle. The elastic energy is a function of the configuration
 * alone:
 *   U = sum_e EA/2 (|e|/l0 - 1)^2 l0                        extension (Eq. 5, EA (v3 - 1)^2)
 *     + sum_i EI |kb_i|^2 / lbar_i                          bending, isotropic (B1 = B2 = EI)
 *     + sum_i GJ (theta_i - theta_{i-1} + mref_i)^2 / lbar_i  torsion
 *     + GJ (theta_0^2 / l0_0 + theta_{n-1}^2 / l0_{n-1})      clamped twist at the supports
 *     + sum_i m_i g z_i                                     gravity
 * with kb_i = 2 t_{i-1} x t_i / (1 + t_{i-1} . t_i), lbar_i = l0_{i-1} + l0_i and mref_i the
 * reference twist. The unloaded conductor is straight and untwisted (kbar = 0, twist bar = 0).
 * Eccentric ice adds the weight of its offset centre, sum_j m_i g e l0_j c_z(theta_j), and
 * couples twist and translation in the mass matrix.
 *
 * Each effect is one term (gal_rod_term, one file of src/rod/ each); the rod holds the list of
 * the terms that are on, made when it is allocated, and gal_rod_eval sums over it. */
#ifndef GALLOP_ROD_H
#define GALLOP_ROD_H

#include <stddef.h>

#include "gallop/base/sparse.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct gal_rod_params {
    double length;            /* m, horizontal span L */
    double height_difference; /* m, right support minus left */
    int elements;             /* count */
    double unstretched_length;/* m, L0 */
    double EA;                /* N */
    double EI;                /* N m^2; 0 with bending off */
    double GJ;                /* N m^2/rad */
    double mass;              /* kg/m, conductor plus ice */
    double polar_inertia;     /* kg m^2/m */
    double gravity;           /* m/s^2, 0 with gravity off */
    int torsion;              /* twist unknowns present */
    int twist_clamped;        /* twist held by the clamps at both supports (else free) */
    /* eccentric ice: a line mass ecc_mass (kg/m, part of `mass`) whose centre sits at ecc (m) from
     * the axis, in the section direction at angle ecc_angle (rad) from the reference director,
     * turning with the twist; 0 = none. It couples twist and translation in the mass matrix and
     * its weight twists the section. */
    double ecc_mass;
    double ecc;
    double ecc_angle;
    /* m^2: a bundle carried as one rod (src/rod/bundle.c): the square of the radius at which its
     * sub-conductors sit, whose tension stiffens the twist by T R^2; 0 = a single conductor */
    double bundle_radius2;
    /* the bundle's differential-stretch fields (src/rod/bundle_irvine.c; 0 = none, nothing changes):
     * bundle_fields (1 for a twin, 2 for 3 to 8 sub-conductors) angles per edge, appended to the
     * configuration after the twists, each a rotation of the bundle's section about an axis across
     * the span that moves the sub-conductor at offset p_k (m) axially by u_f . p_k times it; with the
     * stiffness bundle_field_k = EA_sub sum_k (u_f . p_k)^2 (N m^2), the inertia bundle_field_inertia
     * (kg m^2/m) and the directions u_f = (horizontal, vertical) across the span */
    int bundle_fields;
    double bundle_field_k;
    double bundle_field_inertia;
    double bundle_field_dir[2][2];
} gal_rod_params;

struct gal_rod;
struct gal_rod_node; /* the geometry of the two edges at an interior node (src/rod/rod_impl.h) */

/* One term of the rod's energy, in one of two forms:
 *   eval: adds the term's energy (J) to *U, its gradient to grad (over the full configuration;
 *         may be NULL) and its tangent to K->val (the free dofs, on the pattern of rod->K; may be
 *         NULL); GAL_EFAIL with a message on a degenerate configuration;
 *   node: a term of the node stencil at interior node i (bending, torsion): returns its energy
 *         there and adds its gradient to g (8) and Hessian to H (8 x 8; may be NULL) over the
 *         stencil's edge variables e0 = x_i - x_{i-1}, e1 = x_{i+1} - x_i, theta_{i-1}, theta_i.
 *         The node terms that follow each other in the list share one pass over the nodes: the
 *         geometry is computed once per node and their sum assembled once.
 * An eval term also gives its share on one edge j alone (edge: energy, gradient added to g (7) and
 * Hessian to H (7 x 7; may be NULL) over x_j, x_{j+1}, theta_j), for the element split below. */
typedef struct gal_rod_term {
    const char *name;   /* the scene's effect: "extension", "bending", ... */
    int (*eval)(const struct gal_rod *rod, const double *q, double *U, double *grad, gal_csc *K);
    double (*node)(const struct gal_rod *rod, int i, const double *q, const struct gal_rod_node *nd,
                   double *g, double (*H)[8]);
    int (*edge)(const struct gal_rod *rod, int j, const double *q, double *U, double *g, double (*H)[7]);
} gal_rod_term;

/* The terms, in the order gal_rod_eval sums them; each is in the list only when it is on:
 *   extension        src/rod/extension.c  always (EA > 0)
 *   bending          src/rod/bending.c    EI > 0 (node)
 *   torsion          src/rod/torsion.c    torsion on (node)
 *   bundle_torsion   src/rod/bundle.c     torsion on and bundle_radius2 > 0 (node)
 *   torsion_clamps   src/rod/torsion.c    torsion on and twist_clamped: the twist held at the supports
 *   bundle_clamps    src/rod/bundle.c     the same, for the bundle's tension (bundle_radius2 > 0)
 *   bundle_irvine    src/rod/bundle_irvine.c  torsion on, twist clamped and bundle_fields > 0: the
 *                    sub-conductors' differential stretch as the bundle twists on a sagged span
 *   ice_eccentricity src/rod/ice.c        eccentric ice (ecc_mass > 0, ecc != 0, torsion) and gravity
 *   gravity          src/rod/gravity.c    gravity != 0 */
extern const gal_rod_term gal_rod_term_extension, gal_rod_term_bending, gal_rod_term_torsion,
    gal_rod_term_torsion_clamps, gal_rod_term_ice, gal_rod_term_gravity, gal_rod_term_bundle_torsion,
    gal_rod_term_bundle_clamps, gal_rod_term_bundle_irvine;
#define GAL_ROD_MAX_TERMS 9

/* The immutable model of a discretized span. The full configuration q holds 3 (elements + 1)
 * node positions (m) followed, when torsion is on, by `elements` twist angles (rad), and then by
 * bundle_fields x `elements` angles (rad) of a bundle's differential-stretch fields (field f of
 * edge j at 3 (elements + 1) + (1 + f) elements + j). */
typedef struct gal_rod {
    gal_rod_params p;
    int nn;             /* nodes = elements + 1 */
    int nq;             /* size of the full configuration */
    int ndof;           /* free degrees of freedom */
    int *dof;           /* nq: index of each configuration entry among the free dofs, or -1 */
    int *free_q;        /* ndof: configuration index of each free dof */
    double *l0;         /* elements: rest lengths, m */
    double *tbar;       /* 3 elements: reference unit tangents */
    double *abar;       /* 3 elements: reference frame first directors (normal to tbar) */
    double *node_mass;  /* nn: lumped translational mass, kg */
    double *edge_inertia; /* elements (1 + bundle_fields): polar moment of inertia of each edge,
                           * then the bundle fields' inertia of each edge, kg m^2 */
    double *q0;         /* nq: the configuration the reference frames were taken from */
    gal_csc *K;         /* the tangent's pattern (values are scratch for gal_rod_tangent) */
    gal_csc *M;         /* the mass matrix on the same pattern: lumped, plus the eccentric ice's
                         * twist-translation coupling (constant, at the reference frames) */
    double *ecc_c;      /* 3 elements: direction of the ice centre at zero twist (or NULL) */
    double *mdiag;      /* ndof: the diagonal of M (the whole of it without eccentric ice) */
    int *slot_node;     /* per interior node: 11 x 11 map local dof pair -> K value index, or -1 */
    int *slot_edge;     /* per edge: 6 x 6 map */
    const gal_rod_term *term[GAL_ROD_MAX_TERMS]; /* the effects that are on, in summation order */
    int nterm;
} gal_rod;

/* Build the model; the reference geometry q0 (nq entries; positions, twists) sets the reference
 * frames (the equilibrium or its catenary start). NULL with a message on bad parameters. */
gal_rod *gal_rod_alloc(const gal_rod_params *p, const double *q0);
/* The size of the full configuration of a rod of parameters p. */
int gal_rod_nq(const gal_rod_params *p);
gal_rod *gal_rod_free(gal_rod *rod);

/* Energy U(q) (J), gradient dU/dq over the full configuration (forces = -grad; the entries of
 * the fixed supports are the support reactions), and the tangent stiffness d2U/dq2 restricted to
 * the free dofs, written into rod->K->val (and also returned in `K` when non-NULL, same pattern).
 * `grad` and `K` may be NULL. Returns GAL_OK, or GAL_EFAIL on a degenerate configuration
 * (zero-length or folded-back element). */
int gal_rod_eval(const gal_rod *rod, const double *q, double *energy, double *grad, gal_csc *K);
/* The same for rod->term[k] alone (0 <= k < rod->nterm; GAL_EINPUT otherwise). */
int gal_rod_eval_term(const gal_rod *rod, int k, const double *q, double *energy, double *grad,
                      gal_csc *K);

/* The element split of the energy (hyper-reduction: Farhat, Avery, Chapman & Cortial 2014):
 * U = sum_e U_e over the gal_rod_element_count(rod) = 2 elements - 1 energy elements e: for
 * e < elements, the eval terms on edge e (extension, clamped twist, eccentric ice, the weight of
 * node e and, on the last edge, of the last node), over x_e, x_{e+1}, theta_e; for e >= elements,
 * the node terms (bending, torsion) at interior node i = e - elements + 1, over its stencil
 * x_{i-1}, x_i, x_{i+1}, theta_{i-1}, theta_i. The split maps onto itself under the mirror of the
 * span (edge e <-> edge elements-1-e, node i <-> node elements-i). gal_rod_element_q lists the
 * GAL_ROD_ELEMENT_NQ configuration entries of element e in the node stencil's order (-1: absent). */
#define GAL_ROD_ELEMENT_NQ 11
/* 1 when every term of the rod has the element split (bundle_irvine has none: its fields lie outside
 * the 11 entries), 0 otherwise. */
int gal_rod_element_form(const gal_rod *rod);
int gal_rod_element_count(const gal_rod *rod);
/* The mirror image of energy element e. */
int gal_rod_element_mirror(const gal_rod *rod, int e);
void gal_rod_element_q(const gal_rod *rod, int e, int qi[GAL_ROD_ELEMENT_NQ]);
/* U_e (J) into *energy, its gradient into g (11) and Hessian into H (11 x 11, row-major; may be
 * NULL) over the entries of gal_rod_element_q (entries of absent ones are zero). GAL_EFAIL on a
 * degenerate element. */
int gal_rod_element_eval(const gal_rod *rod, int e, const double *q, double *energy, double *g, double *H);
/* The weighted energy sum_k w[k] U_{elem[k]} (n elements), its gradient (configuration-sized,
 * cleared first; may be NULL) and tangent (free dofs, on rod->K's pattern, cleared first; may be
 * NULL): with every element at weight 1 it is gal_rod_eval's. */
int gal_rod_eval_weighted(const gal_rod *rod, int n, const int *elem, const double *w, const double *q,
                          double *energy, double *grad, gal_csc *K);

/* Copy free entries of a configuration-sized vector to/from a dof-sized vector. */
void gal_rod_gather(const gal_rod *rod, const double *full, double *free_part);
void gal_rod_scatter(const gal_rod *rod, const double *free_part, double *full);

/* The diagonal of the mass matrix over the free dofs (kg or kg m^2). */
void gal_rod_mass_diag(const gal_rod *rod, double *mdiag);
/* y = M x over the free dofs. */
void gal_rod_mass_mult(const gal_rod *rod, const double *x, double *y);

/* Axial tension of each element (N) and horizontal tension at the left support (N). */
void gal_rod_tensions(const gal_rod *rod, const double *q, double *tension);

/* Unit tangent t and first material director d1 of edge j (the section's reference direction:
 * the reference director carried to t by the minimal rotation, turned by the edge's twist). */
void gal_rod_material_frame(const gal_rod *rod, const double *q, int j, double t[3], double d1[3]);
/* The same from edge j's frame ta (its unit tangent, then the reference director carried to it:
 * gal_rod_eval_frames' frames + 6 j): the same numbers. */
void gal_rod_material_frame_from(const gal_rod *rod, const double *q, int j, const double ta[6], double t[3],
                                 double d1[3]);
/* gal_rod_eval, and each edge j's unit tangent and reference director carried to it into
 * frames + 6 j (6 elements; what gal_rod_material_frame computes before the twist): with torsion
 * the twist's terms compute them in the same pass, else they are computed after it. */
int gal_rod_eval_frames(const gal_rod *rod, const double *q, double *energy, double *grad, gal_csc *K,
                        double *frames);

/* The directions of the motion families at node i of configuration q (the equilibrium, for the
 * reduced model's self-check): the unit tangent t of the chord of its neighbours (its own node at an
 * end), the horizontal ey (the y axis normal to t) and the in-plane normal nv = t x ey. */
void gal_rod_node_directions(const gal_rod *rod, const double *q, int i, double t[3], double ey[3], double nv[3]);

/* Change the unstretched length (rest lengths and lumped masses follow); reference frames stay. */
void gal_rod_set_unstretched_length(gal_rod *rod, double L0);
#ifdef __cplusplus
}
#endif

#endif
