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

#endif
