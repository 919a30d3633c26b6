/* catenary.h: the elastic catenary (Irvine, Cable Structures, 1981, Ch. 1): the exact static
 * shape of an extensible, perfectly flexible cable under its own weight between two supports,
 * in terms of the unstretched (Lagrangian) arc length s from the left support:
 *   x(s) = H s / EA + (H / w) [asinh((V0 + w s) / H) - asinh(V0 / H)]
 *   z(s) = (V0 s + w s^2 / 2) / EA + (1 / w) [sqrt(H^2 + (V0 + w s)^2) - sqrt(H^2 + V0^2)]
 * with H the horizontal tension, V0 the vertical component of the tension at the left support
 * (negative when the cable leaves it downwards) and w the weight per unstretched length.
 * It is the Newton start of the rod's equilibrium and the reference its tests compare against. */
#ifndef GALLOP_CATENARY_H
#define GALLOP_CATENARY_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct gal_catenary {
    double L, h;   /* m: span (horizontal) and height difference */
    double w;      /* N/m: weight per unstretched length (0: no gravity, a straight line) */
    double EA;     /* N */
    double H;      /* N: horizontal tension */
    double V0;     /* N: vertical tension component at the left support */
    double L0;     /* m: unstretched length */
} gal_catenary;

/* Solve for the two unknowns of H, V0, L0 given `H` (spec 0), the mid-span sag below the chord
 * (spec 1) or `L0` (spec 2); L, h, w, EA are set by the caller. GAL_EINPUT if there is no such
 * cable (e.g. a sag without gravity), GAL_EFAIL if the iteration does not converge. */
int gal_catenary_solve(gal_catenary *c, int spec, double value);

/* Position (x, z) at unstretched arc length s, and the tension there (N). */
void gal_catenary_point(const gal_catenary *c, double s, double *x, double *z, double *tension);

/* Mid-span sag below the chord at x = L/2 (m). */
double gal_catenary_sag(const gal_catenary *c);

#ifdef __cplusplus
}
#endif

#endif
