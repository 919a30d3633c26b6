/* cigre.h: the outputs of a galloping study as CIGRE Technical Brochure 322 ("State of the art of
 * conductor galloping", 2007) reports them: the galloping ellipse of a point of the span, the
 * clearance it leaves to a neighbouring phase, the dynamic support tensions, and the brochure's
 * empirical amplitude envelope for single conductors. */
#ifndef GALLOP_ANALYSIS_CIGRE_H
#define GALLOP_ANALYSIS_CIGRE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The galloping ellipse of a probe over a window: the principal axes of the orbit (the
 * covariance of the horizontal y and vertical z displacements, as gal_spectrum_orbit), the
 * peak-to-peak extent of the orbit along each axis, the tilt of the major axis from the horizontal
 * (deg, in (-90, 90], positive towards +z) and the centre (the middle of the extents, m from the
 * equilibrium). The ellipse with these axes, tilt and centre encloses the orbit's extremes. */
typedef struct gal_ellipse {
    double major_pp, minor_pp;   /* m, peak to peak */
    double tilt_deg;             /* deg */
    double centre_y, centre_z;   /* m, from the equilibrium: horizontal (downwind), up */
} gal_ellipse;

int gal_cigre_ellipse(const double *y, const double *z, size_t n, gal_ellipse *e);

/* The clearance the ellipse leaves to a point (py, pz) (m, offsets from this conductor's
 * equilibrium at the same point of the span: a neighbouring phase at rest): the distance from the
 * point to the ellipse's boundary, negative when the point is inside the ellipse. */
double gal_cigre_clearance(const gal_ellipse *e, double py, double pz);

/* The empirical envelope of galloping peak-to-peak amplitude for single conductors,
 * A / D = 80 ln(L / (500 D)) (L span, D conductor diameter, m; A in m; 0 where L < 500 D), as
 * given by Lilien & Havard (2000) and CIGRE TB 322 (2007) section 4; the source string below. */
double gal_cigre_envelope_single(double span_m, double diameter_m);
extern const char *const gal_cigre_envelope_source;

/* The dynamic support tensions of a run (nsamples x 2, left and right): the range over the run,
 * the static tension (the start state's, sample 0), the ratios to it and to the rated strength
 * (rts_n; NaN when unknown gives NaN). */
typedef struct gal_tension_range {
    double min_n, max_n;            /* N, both supports, whole run */
    double static_n;                /* N, the larger support tension at the start */
    double max_over_static;         /* - */
    double max_over_rts;            /* -, NaN without a rated strength */
} gal_tension_range;

void gal_cigre_tensions(const double *tension, long nsamples, double rts_n, gal_tension_range *t);

#ifdef __cplusplus
}
#endif

#endif
