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
    int *pair;           /* nm x nm */
    double *Th;          /* ndof x np, column-major: theta_p */
    double *P;           /* ndof x nm, column-major: the tangent basis at the last state asked */
    double *mono;        /* np: scratch */
    double *M;           /* r x r scratch of the projection's normal equations */
} gal_rom_qm;

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
/* x (and xd when v) on the manifold closest in the mass norm to the full state (q, v). */
int gal_rom_qm_project_state(gal_rom *m, const double *q, const double *v, double *x, double *xd);

#endif
