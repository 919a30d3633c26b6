/* onset_internal.h: the pieces of the onset analysis shared by onset.c and onset_linear.c. */
#ifndef GALLOP_ONSET_INTERNAL_H
#define GALLOP_ONSET_INTERNAL_H

#include "gallop/analysis/onset.h"

/* LAPACK */
void dgeev_(const char *jobvl, const char *jobvr, const int *n, double *a, const int *lda, double *wr, double *wi,
            double *vl, const int *ldvl, double *vr, const int *ldvr, double *work, const int *lwork, int *info);

/* Eigenvalues (wr, wi) and right eigenvectors VR (2n x 2n, LAPACK's packing of complex pairs) of
 * the state matrix [0 I; -Kt -Ct] (n x n each, column-major); A (4 n^2) and work (lwork) are
 * scratch. VR may be NULL (values only). GAL_EFAIL when dgeev fails. */
int gal_onset_state_eig(int n, const double *Kt, const double *Ct, double *A, double *wr, double *wi, double *VR,
                        double *work, int lwork);

/* Kinetic-energy shares (vertical, horizontal, torsional; the rest is axial) of the complex shape
 * ure + i uim (free dofs) about configuration q, in the local frames of modes.c (tangent, normal
 * to the span's plane, in-plane normal). full: 2 nq scratch. */
void gal_onset_shares(const gal_rod *rod, const double *q, const double *ure, const double *uim, double *full,
                      double share[3]);

/* The generalized loads of element j at (q, v) (gal_loads_full's distribution): g[0..2] on node j,
 * g[3..5] on node j+1, g[6] on the element's twist (0 with torsion off). */
int gal_onset_elem_load(const gal_loads *L, const gal_rod *rod, const double *q, const double *v, int j, double g[7]);
/* Central difference of element j's loads with respect to x[idx] (x is q or v; step h): col[0..6]. */
int gal_onset_elem_column(const gal_loads *L, const gal_rod *rod, double *q, double *v, int j, double *x, int idx,
                          double h, double *col);
/* The finite-difference steps of the aerodynamic derivatives: positions (m), twists (rad). */
#define GAL_ONSET_HX(rod) (1e-5 * fmax((rod)->p.length / (rod)->p.elements, 1e-3))
#define GAL_ONSET_HT 1e-6

/* ---- the mean-wind equilibrium path (onset_static.c) ---- */

/* The equilibrium under the mean wind at each of ns speeds u[0] < u[1] < ... (m/s), followed from
 * the no-wind equilibrium q_eq by pseudo-arclength continuation in (q, U) with Newton on the full
 * tangent K(q) - dF/dq (UMFPACK). A speed is reached along the path of a rising wind: where the
 * path turns back (a fold: the static tangent is singular there), the solution jumps to the branch
 * the path reaches when it rises past that speed again. Out: Q (ns x nq configurations), ok[i]
 * (found), fold[i] (the path folded between speed i-1 and i), *fold_speed (the first fold, NaN:
 * none). GAL_OK (speeds the path never reaches have ok = 0), GAL_ENOMEM, GAL_EFAIL (not even the
 * first speed). */
int gal_onset_static_path(const gal_rod *rod, const double *q_eq, const gal_loads *L, double tol, int ns,
                          const double *u, double *Q, int *ok, int *fold, double *fold_speed);

#endif
