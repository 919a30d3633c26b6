/* hyper.h: the sample of the hyper-reduced reduced model (ecsw.h), shared by ecsw.c (training,
 * fits, check) and ecsw_eval.c (the evaluations from the sample), and the reduced model's own
 * evaluations (rom.c) used by its step (rom_step.c); not public. */
#ifndef GALLOP_REDUCED_HYPER_H
#define GALLOP_REDUCED_HYPER_H

#include "gallop/reduced/ecsw.h"

/* One sample: elements, weights and, per element, the index of each of its GAL_ROD_ELEMENT_NQ local
 * entries in the union uq (-1: absent, fixed, or not the load's). */
typedef struct gal_rom_hyper_set {
    int n;
    int *elem;
    double *w;
    int *idx;
    int nu;                    /* the sample's free configuration entries */
    int *uq;                   /* nu: their configuration indices */
    double *Vu;                /* nu x r, row-major: V's rows there (the tangent basis's rows at the
                                * last state on the manifold) */
    /* the manifold (qm.h), laid out for loops over the entries: */
    double *Qz;                /* (r + np) x nu: Phi's columns, then Theta's pairs, at the entries */
    double *Tt;                /* r x (r x nu): Tt[j][k nu + u] = Theta_u(k, j) */
    double *Pc;                /* r x nu: P(x) at the entries, column-major (the manifold's), and
                                * the tangent's scratch nu x r (ecsw_eval.c) */
    double *qs;                /* nu: scratch */
    double fit_error;          /* the NNLS residual, relative */
    double *rw;                /* r: the row weights of the fit and the check (1 / RMS of each
                                * coordinate's force over the training states) */
} gal_rom_hyper_set;

/* The training's candidates of each kind on a fine mesh: every element up to this many elements,
 * this many spread over the span above (ecsw_train.c); above it the fits' targets are whole-mesh
 * evaluations, one a training state (gal_rom_opts.hyper_snapshots_fine of them). */
#define GAL_ROM_CANDIDATES 128

typedef struct gal_rom_hyper {
    gal_rom_hyper_set set[2];  /* 0: the rod's energy, 1: the aerodynamic loads */
    int loads;                 /* the loads are sampled (gal_force.element given) */
    int loads_whole;           /* the loads' sample grew past LOADS_WHOLE of the edges (ecsw.c): the
                                * loads over every edge since */
    double *fc, Uc, *Kc;       /* r, J, r x r: the constants that make U_h, its gradient and its
                                * Hessian exact at x = 0: U_h = U_c + f_c.x + x.K_c x/2 + sum w U_e */
    double *F0;                /* r: V^T grad U(q_eq) */
    double amp;                /* m: the training states' largest translation */
    double *emax;              /* nmodes: each mode's largest amplitude in the training states */
    int ns, cap;               /* training states: (x, v, t) rows of 2 r + 1 */
    double *snap;
    double *gu;                /* nq: scratch of the projections */
    double *T;                 /* GAL_ROD_ELEMENT_NQ x r: scratch of the tangent */
    int mirror;                /* mirror pairs share one weight (a symmetric span) */
    int refits;                /* re-samplings after a failed check */
    int set_refits[2];         /* of them, the fits of each sample (0: the rod's, 1: the loads') */
    double check_error;
    long train_element_evals;  /* element evaluations of the fits' candidate columns, in all */
    long train_full_evals;     /* evaluations of the whole rod or loads for the fits' targets */
    /* the sample check's evaluation of the whole rod (and loads) at the state reached, kept for the
     * self-check at the same state (rom_check.c: both come every gal_rom_check_interval) */
    double *whole_g, *whole_f; /* nq: grad U(q) and the loads F(t, q, v) at q = q_eq + V x */
    double *whole_xv;          /* 2 r: the state (x, v) they are of */
    double whole_t;            /* s: its time */
    int whole_has;             /* 0: none held; 1: the gradient; 2: the gradient and the loads */
} gal_rom_hyper;

/* The whole rod's gradient (*g) and loads (*f: NULL when not held) that the last sample check
 * evaluated, when they are of m's current state (t, x, v) exactly; else 0 and *g = *f = NULL. */
int gal_rom_hyper_whole(const gal_rom *m, const double **g, const double **f);

/* b0 = B^T g0 and, when g1, b1 = B^T g1 over the free dofs of the configuration-sized g0, g1 (B: r
 * columns of ndof, the tangent basis), four columns a pass, each sum over the dofs in order
 * (ecsw_project.c: the numbers of one column at a time). */
void gal_rom_project_free(const gal_rom *m, const double *B, const double *g0, const double *g1, double *b0, double *b1);
/* b[s r + k] = V_k^T G_s for ns gathered whole-rod vectors G_s (ndof each) and the model's r
 * columns, V read once for all of them (ecsw_project.c) */
void gal_rom_project_states(const gal_rom *m, const double *G, int ns, double *b);

/* Training state s (deterministic in s) into x and its velocity into v (r each). */
int gal_rom_hyper_training_state(gal_rom *m, int s, double *x, double *v);
/* Fit sample `set` (0: the rod's energy, 1: the loads) by NNLS on the training states held (its
 * candidates' snapshots against the exact targets); the elements with positive weight are kept.
 * On a mirror-symmetric span the columns are mirror pairs (one weight for both): the sampled
 * energy and loads keep the symmetry, and a symmetric motion stays symmetric. */
int gal_rom_hyper_fit(gal_rom *m, int set);
/* Both fits (the loads' when sampled) from one pass over the training states. */
int gal_rom_hyper_fit_all(gal_rom *m);
/* The loads' sample (when m's force has its element split and o.hyper_loads) fitted on the training
 * states held, and both samples' entries: the part of the sample's build that depends on the wind. */
int gal_rom_hyper_loads(gal_rom *m);
/* m's sample of the rod's energy, its constants and training states, copied from `from`'s (of the
 * same basis; the loads' sample empty: gal_rom_hyper_loads next). */
int gal_rom_hyper_copy(gal_rom *m, const gal_rom *from);
/* Element e's gradient at the state in m->q projected on V into col (r), and its Hessian
 * projected, V_e^T H_e V_e (plus the curvature on the manifold), into Kr (r x r). */
int gal_rom_hyper_element_reduced(gal_rom *m, int e, double *col, double *Kr);

/* The reduced internal force at x (energy into m->U1; the reduced tangent into Kr unless NULL) and
 * the reduced loads at (t, x, xd): from the samples when hyper-reduced, else from the whole rod;
 * counted in m's counters (rom.c; used by the step, rom_step.c). */
int gal_rom_eval_internal(gal_rom *m, const double *x, double *f, double *Kr);
int gal_rom_eval_external(gal_rom *m, double t, const double *x, const double *xd, double *f);

/* o.scheme = GAL_ROM_SCHEME_GAUSS2 (rom_irk.c): one step of h (halved on failure); its workspace
 * freed; its stages forgotten (a restart: the next predictor from the state's acceleration). */
int gal_rom_irk_step(gal_rom *m, double h);
void gal_rom_irk_free(gal_rom *m);
void gal_rom_irk_restart(gal_rom *m);

#endif
