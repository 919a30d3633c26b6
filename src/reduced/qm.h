/* qm.h: the quadratic manifold of the recomputed reduced model (rom.h, o.manifold; Jain, Tiso,
 * Rutzmoser & Rixen 2017): q = q_eq + Phi eta + 1/2 Theta(eta, eta), the static modal derivatives
 * theta_ij (unnormalized) as the quadratic term, with tangent basis P(eta) = Phi + Theta(eta, .);
 * shared by rom.c, qm.c and the sampling (ecsw*.c); not public. The pairs i <= j are stored in
 * order p = pair[i nm + j] (= pair[j nm + i]), and the monomials mono_p = c_ij eta_i eta_j, c = 1/2
 * on the diagonal, so that q = q_eq + Phi eta + Theta mono. */
#ifndef GALLOP_REDUCED_QM_H
#define GALLOP_REDUCED_QM_H

#include "gallop/reduced/rom.h"

typedef struct gal_rom_qm {
    int np;              /* pairs nm (nm + 1) / 2 */
    int nstatic;         /* the last nstatic of the nm coordinates: static vectors (gal_rom_qm_static) */
    int *pair;           /* nm x nm */
    double *Th;          /* ndof x np, column-major: theta_p */
    double *P;           /* ndof x nm, column-major: the tangent basis at the last state asked */
    double *mono;        /* np: scratch */
    double *M;           /* r x r scratch of the projection's normal equations */
    /* the inertia of the manifold (o.manifold = 1; 2: dropped, the mass Phi^T M Phi = I): in the
     * coordinates z = (eta, mono) of span [Phi, Theta] (nz = r + np), P(x) = [Phi, Theta] Z(x) */
    int inertia;         /* 1: the reduced mass P^T M P and its convective term */
    int nz;
    double *W;           /* nz x nz: [Phi, Theta]^T M [Phi, Theta] */
    double *D;           /* nz x nz: [Phi, Theta]^T C [Phi, Theta] (NULL: undamped) */
    double *Z, *Zv;      /* nz x r, column-major: Z(x), and Z(v) less the identity (scratch) */
    double *y, *wy;      /* nz: scratch */
    double *f0, *d0;     /* r: the inertia and damping forces at the start of the step */
    double *p0;          /* r: the momentum M(x) v at the start of the step */
    double *f1, *d1;     /* r: the step's inertia and damping terms (rom.c's residual) */
} gal_rom_qm;

/* With o.mean_load and o.static_vectors: the static response K0^-1 F_mean (1: of the whole load;
 * 2: of its out-of-plane, in-plane and twist parts apart) less its content in the selected modes,
 * M-orthonormalized, appended to V as extra linear coordinates of the manifold (nmodes = r grows;
 * omega2 their Rayleigh quotients); MV: the M-images of V's columns. Before gal_rom_qm_build. */
int gal_rom_qm_static(gal_rom *m, double *MV);
/* The modal derivatives of the modes in V's first nmodes columns (called by gal_rom_alloc). */
int gal_rom_qm_build(gal_rom *m);
void gal_rom_qm_free(gal_rom *m);
/* mono (np) of x; with xd (and xdd) their first (second) time derivatives into dmono (ddmono). */
void gal_rom_qm_mono(const gal_rom *m, const double *x, const double *xd, const double *xdd, double *mono,
                     double *dmono, double *ddmono);
/* Full reconstruction over the free dofs: u = Phi x + Theta mono, and its rate P(x) xd when xd. */
void gal_rom_qm_displacement(gal_rom *m, const double *x, const double *xd, double *u, double *ud);
/* P(x) (ndof x r, column-major) into m->qm->P; returns it. */
const double *gal_rom_qm_basis(gal_rom *m, const double *x);
/* Kr += sum_d g_d theta_d(k, l) for the configuration-sized gradient g: the manifold's curvature. */
void gal_rom_qm_curvature(const gal_rom *m, const double *g, double *Kr);
/* The manifold's inertia and damping (qm->inertia): fin = P^T M (P a + Theta(v, v)) = M(x) a +
 * c(x, v), the exact projection of M q'' on the manifold, and fd = P^T C P v (either may be NULL). */
void gal_rom_qm_inertia(gal_rom *m, const double *x, const double *v, const double *a, double *fin, double *fd);
/* At the start of a step (m->x, v, a): f0 = M a + c, d0 and the momentum p0 = M(x) v. */
void gal_rom_qm_begin(gal_rom *m);
/* The inertia and damping terms of rom.c's residual over the step of h to (m->x1, v1, a1) into f1
 * and d1: with rho_inf = 1 f1 = (p1 - p0) / h - g, g the discrete gradient of v0^T M(x) v1 / 2
 * between x0 and x1, so that f1 . (x1 - x0) = T1 - T0 exactly (with the discrete gradient of U:
 * T + U conserved); otherwise the generalized-alpha averages of M a + c and of the damping. */
void gal_rom_qm_end(gal_rom *m, double h);
/* J (r x r, row-major) += cm M(x) + cc (P^T C P + dc/dv): the iteration matrix's inertia and damping. */
void gal_rom_qm_iteration(gal_rom *m, const double *x, const double *v, double cm, double cc, double *J);
/* The kinetic energy v^T M(x) v / 2. */
double gal_rom_qm_kinetic(gal_rom *m, const double *x, const double *v);
/* a from M(x) a = f - c(x, v) - P^T C P v (f: external less internal force, r); 0 or GAL_EFAIL. */
int gal_rom_qm_acceleration(gal_rom *m, const double *x, const double *v, const double *f, double *a);
/* x (and xd when v) on the manifold closest in the mass norm to the full state (q, v). */
int gal_rom_qm_project_state(gal_rom *m, const double *q, const double *v, double *x, double *xd);

/* The tangents at q_eq +- e phi for the modal derivatives' central difference (rom_basis.c);
 * shared by the basis and the manifold. */
int gal_rom_tangents_along(const gal_rom *m, const double *phi, gal_csc *Kp, gal_csc *Km, double *qp, double *e);

#endif
