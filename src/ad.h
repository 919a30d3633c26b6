/* ad.h: forward-mode automatic differentiation to second order for the rod's node stencil.
 * A number carries its value, gradient and (packed, symmetric) Hessian with respect to AD_NV
 * independent variables, so that the stencil energy written once gives exact forces and tangent
 * stiffness (the chain and product rules, applied operation by operation). */
#ifndef GALLOP_AD_H
#define GALLOP_AD_H

#include <math.h>

#define AD_NV 8                          /* e0 (3), e1 (3), theta0, theta1 */
#define AD_NH (AD_NV * (AD_NV + 1) / 2)  /* packed upper triangle, row-major */

typedef struct {
    double v;          /* value */
    double g[AD_NV];   /* d v / d x_a */
    double h[AD_NH];   /* d2 v / d x_a d x_b, a <= b */
} ad;

static inline ad ad_const(double c)
{
    ad r = {0};
    r.v = c;
    return r;
}

static inline ad ad_var(double value, int index)
{
    ad r = ad_const(value);
    r.g[index] = 1.0;
    return r;
}

static inline ad ad_add(ad a, ad b)
{
    for (int i = 0; i < AD_NV; i++) a.g[i] += b.g[i];
    for (int i = 0; i < AD_NH; i++) a.h[i] += b.h[i];
    a.v += b.v;
    return a;
}

static inline ad ad_sub(ad a, ad b)
{
    for (int i = 0; i < AD_NV; i++) a.g[i] -= b.g[i];
    for (int i = 0; i < AD_NH; i++) a.h[i] -= b.h[i];
    a.v -= b.v;
    return a;
}

static inline ad ad_scale(ad a, double s)
{
    for (int i = 0; i < AD_NV; i++) a.g[i] *= s;
    for (int i = 0; i < AD_NH; i++) a.h[i] *= s;
    a.v *= s;
    return a;
}

static inline ad ad_addc(ad a, double c)
{
    a.v += c;
    return a;
}

/* (a b)'' = a'' b + a b'' + a' b'^T + b' a'^T */
static inline ad ad_mul(ad a, ad b)
{
    ad r;
    r.v = a.v * b.v;
    for (int i = 0; i < AD_NV; i++) r.g[i] = a.g[i] * b.v + a.v * b.g[i];
    int k = 0;
    for (int i = 0; i < AD_NV; i++)
        for (int j = i; j < AD_NV; j++, k++)
            r.h[k] = a.h[k] * b.v + a.v * b.h[k] + a.g[i] * b.g[j] + a.g[j] * b.g[i];
    return r;
}

/* f(a) with f' = d1, f'' = d2: f(a)'' = d1 a'' + d2 a' a'^T */
static inline ad ad_chain(ad a, double f, double d1, double d2)
{
    ad r;
    r.v = f;
    for (int i = 0; i < AD_NV; i++) r.g[i] = d1 * a.g[i];
    int k = 0;
    for (int i = 0; i < AD_NV; i++)
        for (int j = i; j < AD_NV; j++, k++) r.h[k] = d1 * a.h[k] + d2 * a.g[i] * a.g[j];
    return r;
}

static inline ad ad_inv(ad a)
{
    double iv = 1.0 / a.v;
    return ad_chain(a, iv, -iv * iv, 2.0 * iv * iv * iv);
}

static inline ad ad_div(ad a, ad b) { return ad_mul(a, ad_inv(b)); }

static inline ad ad_sqrt(ad a)
{
    double s = sqrt(a.v);
    return ad_chain(a, s, 0.5 / s, -0.25 / (s * a.v));
}

static inline ad ad_sq(ad a) { return ad_chain(a, a.v * a.v, 2.0 * a.v, 2.0); }

/* atan2(y, x): d = (x dy - y dx) / r2; second derivatives by the quotient rule on the gradient. */
static inline ad ad_atan2(ad y, ad x)
{
    ad r;
    double r2 = x.v * x.v + y.v * y.v;
    double fy = x.v / r2, fx = -y.v / r2;                     /* first partials */
    double fyy = -2.0 * x.v * y.v / (r2 * r2);                /* d2/dy2 */
    double fxx = 2.0 * x.v * y.v / (r2 * r2);                 /* d2/dx2 */
    double fxy = (y.v * y.v - x.v * x.v) / (r2 * r2);         /* d2/dxdy */
    r.v = atan2(y.v, x.v);
    for (int i = 0; i < AD_NV; i++) r.g[i] = fy * y.g[i] + fx * x.g[i];
    int k = 0;
    for (int i = 0; i < AD_NV; i++)
        for (int j = i; j < AD_NV; j++, k++)
            r.h[k] = fy * y.h[k] + fx * x.h[k] + fyy * y.g[i] * y.g[j] + fxx * x.g[i] * x.g[j] +
                     fxy * (x.g[i] * y.g[j] + y.g[i] * x.g[j]);
    return r;
}

/* ---- 3-vectors of ad numbers ---- */
typedef struct {
    ad c[3];
} ad3;

static inline ad ad3_dot(const ad3 *a, const ad3 *b)
{
    ad r = ad_mul(a->c[0], b->c[0]);
    r = ad_add(r, ad_mul(a->c[1], b->c[1]));
    return ad_add(r, ad_mul(a->c[2], b->c[2]));
}

/* a . c for a constant vector c */
static inline ad ad3_dotc(const ad3 *a, const double c[3])
{
    ad r = ad_scale(a->c[0], c[0]);
    r = ad_add(r, ad_scale(a->c[1], c[1]));
    return ad_add(r, ad_scale(a->c[2], c[2]));
}

static inline void ad3_cross(ad3 *r, const ad3 *a, const ad3 *b)
{
    ad3 t;
    t.c[0] = ad_sub(ad_mul(a->c[1], b->c[2]), ad_mul(a->c[2], b->c[1]));
    t.c[1] = ad_sub(ad_mul(a->c[2], b->c[0]), ad_mul(a->c[0], b->c[2]));
    t.c[2] = ad_sub(ad_mul(a->c[0], b->c[1]), ad_mul(a->c[1], b->c[0]));
    *r = t;
}

static inline void ad3_scale(ad3 *r, const ad3 *a, ad s)
{
    for (int i = 0; i < 3; i++) r->c[i] = ad_mul(a->c[i], s);
}

#endif
