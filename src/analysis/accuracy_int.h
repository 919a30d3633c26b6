/* accuracy_int.h: what the files of the accuracy analysis share (accuracy.c, accuracy_dyn.c). */
#ifndef GALLOP_ACCURACY_INT_H
#define GALLOP_ACCURACY_INT_H

#include "gallop/analysis/accuracy.h"

/* |a - b| / |b|; +inf when either is not finite, 0 when equal */
double gal_acc_relerr(double a, double b);
/* a new row of study s (value printf-formatted); NULL when out of memory */
gal_acc_row *gal_acc_row_add(gal_acc_result *r, gal_acc_study s, const char *setting, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
/* one line per setting on stderr when o->progress */
void gal_acc_progress(const gal_acc_opts *o, const gal_acc_row *w);

/* the dynamic studies (accuracy_dyn.c); sc has the sampling of the scene's own run */
int gal_acc_study_modes(const gal_scene *sc, const gal_acc_opts *o, gal_acc_result *r);
/* full-model time steps T/10 .. T/160, T the shortest selected period, s */
int gal_acc_study_time_step(const gal_scene *sc, const gal_acc_opts *o, gal_acc_result *r, double T);
/* full-model simulation.newton_tolerance 1e-3 .. 1e-10 (the reference) at the scene's step */
int gal_acc_study_newton_tol(const gal_scene *sc, const gal_acc_opts *o, gal_acc_result *r);
/* the front study (accuracy_front.c, accuracy_pareto.c): r->front */
int gal_acc_study_front(const gal_scene *sc, const gal_acc_opts *o, gal_acc_result *r);
int gal_acc_study_effects(const gal_scene *sc, const gal_acc_opts *o, gal_acc_result *r);

#endif
