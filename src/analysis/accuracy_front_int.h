/* accuracy_front_int.h: what the files of the front study share (accuracy_front.c: one
 * configuration's run and the converged reference; accuracy_pareto.c: the choices, the front,
 * the budget, the tolerance and the effects). */
#ifndef GALLOP_ACCURACY_FRONT_INT_H
#define GALLOP_ACCURACY_FRONT_INT_H

#include "gallop/analysis/accuracy.h"
#include "gallop/analysis/compare.h"

/* The study's constants and clock. */
typedef struct acc_study {
    const gal_scene *sc;      /* the user's scene (never changed) */
    const gal_acc_opts *o;
    gal_acc_front *F;
    double t0;                /* wall clock at the start, s */
    int turbulent;
    int fcomp;                /* the translation whose fundamental frequency is scored: 0 horizontal, 1 vertical */
    int own[3];               /* the scene's own modes per family (torsional 0 when torsion is off) */
    double duration;          /* s */
    int have_ref;             /* ref is set (by the first run measured with a detected window) */
    gal_compare_ref ref;      /* the reference's window and probes: every run measured as compare does */
} acc_study;

/* wall time left in the budget, s (+inf without one) */
double gal_acc_budget_left(const acc_study *S);
/* a configuration's label ("full N=80 h=0.0125", "reduced 3/2/1 N=80 h=0.0125", "full tol=1e-06 N=80
 * h=0.0125", "-effect") */
void gal_acc_config_label(const gal_acc_config *c, char *buf, size_t n);
/* Run configuration c (every seed), measure over the reference's steady window (from < 0:
 * detected) into p->value and time it; a failed run keeps its reason in p->failed. */
int gal_acc_config_run(acc_study *S, const gal_acc_config *c, double from, gal_acc_point *p);
/* p->err and p->error against the reference */
void gal_acc_score(const gal_acc_front *F, gal_acc_point *p);
/* a new point (NULL: out of memory) */
gal_acc_point *gal_acc_point_add(gal_acc_front *F);
/* The converged reference (levels 0.. of elements x2, step /2 from the base configuration). */
int gal_acc_reference(acc_study *S, const gal_acc_config *base);
/* The choices around the base, the combined ones, the front, the tolerance and the effects. */
int gal_acc_pareto(acc_study *S, const gal_acc_config *base);
void gal_acc_progress_point(const acc_study *S, const gal_acc_point *p);

#endif
