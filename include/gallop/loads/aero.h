/* aero.h: quasi-steady aerodynamic loads on a conductor section (DESIGN.md "Aerodynamics",
 * paper Eq. 10): coefficient tables C_D, C_L, C_M(alpha) read from CSV, interpolated by periodic
 * cubic splines (GSL), and the load per unit length with its derivative.
 *
 * ---- Angle and sign convention (the same in every table in data/aero/) ----
 * Let t be the unit tangent of the conductor, d1 the section's material reference direction (a
 * unit vector normal to t, fixed in the section: it turns with the twist), and d2 = t x d1.
 * Let w be the relative wind, wind velocity minus conductor velocity, and wn = w - (w.t) t its
 * projection on the plane normal to t, V = |wn|, w^ = wn / V.
 *   - alpha is the angle of the relative wind measured from the reference direction, positive
 *     about t (right hand):  w^ = cos(alpha) d1 + sin(alpha) d2,  alpha = atan2(w^.d2, w^.d1).
 *   - drag    D = 1/2 rho V^2 d   C_D(alpha)  along w^;
 *     lift    L = 1/2 rho V^2 d   C_L(alpha)  along t x w^ (w^ turned +90 degrees about t);
 *     moment  M = 1/2 rho V^2 d^2 C_M(alpha)  about +t (right hand).
 * Example (span along x, t = +x, d1 = +y, d2 = +z): a horizontal wind along +y is alpha = 0;
 * drag acts along +y and positive lift along +z (up). A wind that comes from below (w has a
 * +z component, as when the conductor moves down) has alpha > 0: "nose-up" for a section whose
 * leading edge is at -d1. Turning the section by +theta about t (twist) lowers alpha by theta.
 * With this convention the Den Hartog coefficient is H(alpha) = dC_L/dalpha + C_D (per radian)
 * and a section that moves along its lift direction is aerodynamically undamped (galloping-prone)
 * where H < 0.
 *
 * ---- Table files (CSV) ----
 *   # source: where the numbers come from (at least one such line, before the header)
 *   # any other comment lines
 *   alpha_deg,cd,cl,cm
 *   -180,1.1,0,0
 *   ...
 * alpha in degrees, strictly increasing; the rows span less than 360 degrees (the periodic
 * closure alpha_first + 360 is added) or exactly 360 with the last row equal to the first
 * (within 1e-9). At least 4 distinct angles; every value finite, |c| <= 10. The interpolant is
 * checked too, on 64 points per interval between rows: the spline must stay within |c| <= 10
 * with slopes |dc/dalpha| <= GAL_AERO_MAX_SLOPE; a table whose spline overshoots (rows too close
 * for their values) is refused, naming the two rows. `#` lines and blank lines may appear
 * anywhere. */
#ifndef GALLOP_AERO_H
#define GALLOP_AERO_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define GAL_AERO_MAX_COEF 10.0   /* |C_D|, |C_L|, |C_M| above this are rejected as absurd */
/* |dC/dalpha| (per radian) above this is rejected: 1 per degree, steeper than any measured
 * section (an airfoil's lift slope is 2 pi per rad); the stability sweep samples H = dC_L/dalpha
 * + C_D every degree and would miss a sign change of a steeper slope. */
#define GAL_AERO_MAX_SLOPE 57.29577951308232

/* Which loads gal_aero_load computes (bit flags; the effects aero_drag, aero_lift, aero_moment). */
enum { GAL_AERO_DRAG = 1u, GAL_AERO_LIFT = 2u, GAL_AERO_MOMENT = 4u, GAL_AERO_ALL = 7u };

/* An immutable coefficient table; const functions on it are thread-safe. */
typedef struct gal_aero_table {
    char *path;        /* the file it was read from */
    char *source;      /* the "# source:" lines, joined by "; " */
    int n;             /* number of nodes including the closure alpha[0] + 2 pi */
    double *alpha;     /* rad, n nodes, strictly increasing, alpha[n-1] = alpha[0] + 2 pi */
    double *c[3];      /* C_D, C_L, C_M at the nodes (c[i][n-1] = c[i][0]) */
    void *spline[3];   /* gsl_interp (cspline_periodic) for each coefficient */
    double *poly;      /* per interval i and coefficient k, poly + 4 (3 i + k): the spline's cubic
                        * y_lo, b, c, d as GSL forms them at each evaluation (NULL: GSL evaluates) */
} gal_aero_table;

/* Read a table. NULL on error with gal_error(GAL_EINPUT or GAL_EIO, ...) naming the file, line,
 * column, the value and the allowed range. */
gal_aero_table *gal_aero_table_load(const char *path);
/* The same with the status: GAL_OK (*out set), GAL_EINPUT, GAL_EIO or GAL_ENOMEM (*out NULL). */
int gal_aero_table_read(const char *path, gal_aero_table **out);
/* Build a table from arrays (alpha in degrees, n rows, same rules as the file; `name` is used in
 * messages and as path, `source` must be non-empty). NULL with a message on error. */
gal_aero_table *gal_aero_table_make(const char *name, const char *source, int n,
                                    const double *alpha_deg, const double *cd, const double *cl,
                                    const double *cm);
/* Free; accepts NULL; returns NULL. */
gal_aero_table *gal_aero_table_free(gal_aero_table *t);

/* Coefficients at any alpha (rad; wrapped into the period): c = {C_D, C_L, C_M} and
 * dc = d/dalpha per radian (dc may be NULL). */
void gal_aero_eval(const gal_aero_table *t, double alpha_rad, double c[3], double dc[3]);

/* Den Hartog coefficient H = dC_L/dalpha + C_D (per radian) at alpha (rad); < 0: galloping-prone. */
double gal_aero_den_hartog(const gal_aero_table *t, double alpha_rad);

/* Angle of attack (rad, in (-pi, pi]) of the relative wind wrel on the section (tan, d1), as
 * defined above; 0 when the normal part of wrel vanishes. */
double gal_aero_alpha(const double tan[3], const double d1[3], const double wrel[3]);

/* Load per unit length on a section. tan: tangent (normalized inside); d1: reference direction
 * (its part normal to tan is used, normalized); wrel: relative wind (m/s, wind minus conductor
 * velocity, 3D; only its part normal to tan counts); rho: air density (kg/m^3); diam: reference
 * diameter d (m); flags: GAL_AERO_DRAG | GAL_AERO_LIFT | GAL_AERO_MOMENT.
 * Out: f (N/m, 3-vector), *m (N m/m, about +tan; may be NULL). Zero relative wind: zero load.
 * Returns GAL_OK, or GAL_EINPUT (zero tangent, d1 parallel to tan, non-finite input). */
int gal_aero_load(const gal_aero_table *t, const double tan[3], const double d1[3],
                  const double wrel[3], double rho, double diam, unsigned flags, double f[3],
                  double *m);

/* The same load and its analytic derivative with respect to wrel:
 * df[3*i + j] = d f_i / d wrel_j (N s/m^2), dm[j] = d m / d wrel_j. f, m, df, dm may be NULL.
 * With wrel = wind - conductor velocity, the aerodynamic damping matrix (per unit length) of a
 * section moving at velocity u is C_aero = -d f / d u = +df; linearised load f(u) ~ f(0) - df u.
 * At zero relative wind the derivative is zero (the load is quadratic in wrel). */
int gal_aero_load_deriv(const gal_aero_table *t, const double tan[3], const double d1[3],
                        const double wrel[3], double rho, double diam, unsigned flags,
                        double f[3], double *m, double df[9], double dm[3]);

/* ---- The section load as a list of terms (drag, lift, moment) ----
 * The flow at a section, which every term reads: */
typedef struct gal_aero_flow {
    double e3[3];          /* unit tangent */
    double V;              /* m/s, speed of the relative wind's part normal to the tangent */
    double wh[3], lh[3];   /* its direction w^ and the lift direction l^ = e3 x w^ */
    double c[3], dc[3];    /* C_D, C_L, C_M at the angle of attack, and d/dalpha (per radian) */
} gal_aero_flow;

/* What the terms add up to: f = q V^2 g (N/m) and m = q d V^2 cm (N m/m), q = rho d / 2; with the
 * derivative, df = q V G (G row-major, d/dwrel) and dm = q d V Gm. */
typedef struct gal_aero_sum {
    double g[3], cm, G[9], Gm[3];
} gal_aero_sum;

/* One term of the section load: `add` adds its coefficient to s->g or s->cm and, with deriv, its
 * part of s->G or s->Gm. */
typedef struct gal_aero_term {
    const char *name;   /* the scene's effect: "aero_drag", "aero_lift", "aero_moment" */
    unsigned flag;      /* GAL_AERO_DRAG, GAL_AERO_LIFT or GAL_AERO_MOMENT */
    void (*add)(const gal_aero_flow *fl, int deriv, gal_aero_sum *s);
} gal_aero_term;
extern const gal_aero_term gal_aero_term_drag, gal_aero_term_lift, gal_aero_term_moment;

/* The terms that `flags` selects, in the order drag, lift, moment, into list; returns how many. */
int gal_aero_terms(unsigned flags, const gal_aero_term *list[3]);

/* gal_aero_load_deriv summed over the given terms (nterms of them) instead of flags. */
int gal_aero_load_terms(const gal_aero_table *t, const double tan[3], const double d1[3],
                        const double wrel[3], double rho, double diam,
                        const gal_aero_term *const *terms, int nterms, double f[3], double *m,
                        double df[9], double dm[3]);

#ifdef __cplusplus
}
#endif

#endif
