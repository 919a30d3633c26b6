/* modes_impl.h: the modes stage's shared internals: one context per configuration (the tangent
 * evaluated once, one symbolic analysis) from which ARPACK runs at several shifts draw. */
#ifndef GALLOP_MODES_IMPL_H
#define GALLOP_MODES_IMPL_H

#include "gallop/modes/modes.h"

#include "base/chol.h"

typedef struct gal_modes_ctx {
    const gal_rod *rod;
    const double *q;
    gal_csc K0;      /* the tangent stiffness at q (upper triangle; rod->K's pattern, own values) */
    double *start;   /* ndof: ARPACK's deterministic start vector */
    gal_chol *chol;  /* analysed once; factorized once per run */
    double *full;    /* nq scratch */
    double *comp;    /* 4 max(nodes, elements) scratch (the symmetry test) */
    double *y, *z;   /* ndof scratch each (residuals) */
    struct modes_ws *ws; /* ARPACK's arrays, kept for the next run when large enough */
    int spare;       /* columns a run from below allocates beyond its modes (for those appended) */
    int capacity;    /* the columns the last run from below allocated */
} gal_modes_ctx;

/* The context about q; t (or NULL): a tangent handed over (the statics' at the equilibrium), whose
 * values and analysis the context takes when they are rod's at q (else it evaluates and analyses). */
int gal_modes_ctx_init(gal_modes_ctx *c, const gal_rod *rod, const double *q, gal_tangent *t);
void gal_modes_ctx_clear(gal_modes_ctx *c);

/* One ARPACK shift-invert run: nev modes of the context. below = 1: the shift is chosen below the
 * lowest mode and K - sigma M must be positive definite (the lowest nev modes, classified);
 * below = 0: the nev modes nearest to sigma, with each mode's rank among all modes
 * (gal_mode.index) from the count of negative pivots of K - sigma M (Sylvester's law of inertia),
 * left unclassified (gal_modes_classify those kept). out as gal_modes_solve fills it. */
int gal_modes_run(gal_modes_ctx *c, int nev, double sigma, int below, gal_modes *out);

/* Family, shares and symmetry of mode k of out (found[] counts it). */
void gal_modes_classify(gal_modes_ctx *c, gal_modes *out, int k);

/* ARPACK's Krylov basis size for nev modes of n dofs. */
int gal_modes_ncv(int nev, int n);

#endif
