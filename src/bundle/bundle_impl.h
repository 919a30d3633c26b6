/* bundle_impl.h: what the files of src/bundle/ share: the spacers' place in the state vector and
 * the assembly's helpers. */
#ifndef GALLOP_BUNDLE_IMPL_H
#define GALLOP_BUNDLE_IMPL_H

#include "gallop/bundle/bundle.h"

/* spacer sp's centre u (3), rotation R (9, row-major) and the sub-conductors' accumulated twist
 * at its node (n), after the rods' configurations in the state s */
#define SP_BASE(b, s, sp) ((s) + (size_t)(b)->n * (b)->rod[0]->nq + (size_t)(sp) * (12 + (b)->n))
#define SP_U(b, s, sp) (SP_BASE(b, s, sp))
#define SP_R(b, s, sp) (SP_BASE(b, s, sp) + 3)
#define SP_PSI(b, s, sp) (SP_BASE(b, s, sp) + 12)

void gal_bundle_expmap(const double w[3], double R[9]);
void gal_bundle_tangent(const gal_bundle *b, const double *q, int i, double t[3]);
void gal_bundle_map_values(gal_bundle *b, const double *s);
int gal_bundle_pattern(gal_bundle *b);
/* The system's tangent being assembled (upper triangle): gal_bundle_put adds v to the entry (I, J)
 * of G, or (pairs not NULL) records the pair for the pattern. */
typedef struct gal_bundle_sink {
    gal_csc *G;
    long *pairs;
    long np;
    long ndof;
} gal_bundle_sink;
void gal_bundle_put(gal_bundle_sink *k, int I, int J, double v);
/* E^T H E onto spacer sp's rotation dofs (H 3 x 3 on the rotation vector) */
void gal_bundle_put_rot(const gal_bundle *b, const double *s, int sp, const double H[3][3], gal_bundle_sink *k);
/* the geometric stiffness of spacer sp's rotation from the force f on sub-conductor r's point */
void gal_bundle_geometric(const gal_bundle *b, const double *s, int sp, int r, const double f[3], gal_bundle_sink *k);
/* Flexible spacers (arms.c): the arms' energy at the state s, their gradient added to grad (when
 * not NULL) and their tangent to k (when not NULL; its pattern when k->pairs). */
double gal_bundle_arms(const gal_bundle *b, const double *s, double *grad, gal_bundle_sink *k);

/* spacer sp's rotation basis E[0..nrot-1] at state s; returns nrot */
int gal_bundle_basis(const gal_bundle *b, const double *s, int sp, double E[3][3]);

/* a mode's family and symmetry (classify.c), with a scratch of gal_bundle_classify_scratch doubles */
size_t gal_bundle_classify_scratch(const gal_bundle *b);
void gal_bundle_classify(const gal_bundle *b, const double *z, double *scratch, gal_mode *md);

/* Sub-conductor r's run of a bundle run as a single rod's result (its probes and tensions, the
 * rest shared with res->c), for the measures (simwrite.c); free out->trace and out->tension. */
struct gal_bundle_sim_result;
struct gal_sim_result;
int gal_bundle_sim_sub(const struct gal_bundle_sim_result *res, int r, struct gal_sim_result *out);

#endif
