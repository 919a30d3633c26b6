/* vec3.h: 3-vector helpers of the whole library (header-only, inline). */
#ifndef GALLOP_BASE_VEC3_H
#define GALLOP_BASE_VEC3_H

#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

static inline double gal_dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static inline double gal_norm3(const double *a) { return sqrt(gal_dot3(a, a)); }
/* r = a x b; r may alias a or b */
static inline void gal_cross3(const double *a, const double *b, double *r)
{
    double t0 = a[1] * b[2] - a[2] * b[1], t1 = a[2] * b[0] - a[0] * b[2], t2 = a[0] * b[1] - a[1] * b[0];
    r[0] = t0, r[1] = t1, r[2] = t2;
}

#ifdef __cplusplus
}
#endif

#endif
