/* modes.h: natural modes of the span about its equilibrium (DESIGN.md "Modes"): the generalized
 * symmetric problem K phi = w^2 M phi with K the tangent stiffness and M the lumped mass, lowest
 * modes by ARPACK in shift-invert mode (dsaupd_c/dseupd_c, mode 3) with the factorization of
 * K - sigma M from CHOLMOD; shapes mass-normalized; each mode classified by family from its shares
 * of modal kinetic energy and by its symmetry about mid-span. */
#ifndef GALLOP_MODES_H
#define GALLOP_MODES_H

#include "gallop/rod/rod.h"
#include "gallop/statics/statics.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    GAL_FAMILY_VERTICAL,   /* in-plane, normal to the conductor */
    GAL_FAMILY_HORIZONTAL, /* out of the plane of the sagged span */
    GAL_FAMILY_TORSIONAL,
    GAL_FAMILY_AXIAL,      /* along the conductor */
    GAL_FAMILY_SUBSPAN,    /* an explicit bundle's sub-conductors moving relative to each other
                            * between spacers (src/bundle/classify.c; never a single rod's) */
    GAL_FAMILY_COUNT
} gal_family;

typedef enum { GAL_SYM_SYMMETRIC, GAL_SYM_ANTISYMMETRIC, GAL_SYM_NONE } gal_symmetry;

extern const char *const gal_family_names[GAL_FAMILY_COUNT];
extern const char *const gal_symmetry_names[3];

typedef struct gal_mode {
    double omega;          /* rad/s */
    double frequency_hz;   /* Hz */
    gal_family family;
    gal_symmetry symmetry;
    double share[GAL_FAMILY_COUNT]; /* shares of modal kinetic energy, summing to 1 */
    int selected;          /* among the modes the scene asked for */
    int index;             /* rank among all the modes of the span by frequency, from 1 (a search
                            * by family computes a window of them: the ranks then have gaps) */
    gal_symmetry parity;   /* the larger part of the family's component about mid-span, symmetric
                            * or antisymmetric (never none: on an inclined span, where symmetry is
                            * none, the part its dominant half-wave count has) */
    int partner;           /* selected as the torsional partner of the vertical mode of this index
                            * (gal_modes_select); 0: not selected, or among the lowest asked */
} gal_mode;

typedef struct gal_modes {
    int n;                 /* modes computed, by increasing frequency */
    int ndof;
    gal_mode *mode;
    double *shape;         /* ndof x n, column k = mode k over the free dofs, phi^T M phi = 1 */
    int found[GAL_FAMILY_COUNT];    /* computed modes per family */
    int selected[GAL_FAMILY_COUNT]; /* selected per family (at most the number asked) */
    double sigma;          /* the shift, (rad/s)^2 */
    long arpack_restarts, op_applications, factorizations, solves;
    int rounds;            /* ARPACK runs (more modes asked for when a family was short) */
    double wall_time_s;
} gal_modes;

/* The `nev` lowest modes about configuration q (an equilibrium). GAL_EFAIL when K - sigma M is
 * not positive definite (the equilibrium is unstable) or ARPACK fails (its info is reported). */
int gal_modes_solve(const gal_rod *rod, const double *q, int nev, gal_modes *out);
/* The same about the equilibrium the statics found, taking over its tangent and analysis as
 * gal_modes_find_eq does. */
int gal_modes_solve_eq(gal_equilibrium *eq, int nev, gal_modes *out);

/* The torsional partners' band: a selected vertical mode's partner lies within this fraction of its
 * frequency (gal_modes_select). */
#define GAL_PARTNER_BAND 0.5

/* Marks the modes a reduced model takes (README "Modes", "Which modes are selected"): the lowest
 * want[f] of each family f (vertical, horizontal, torsional) and, when want[torsional] >= 1, for
 * each of the selected vertical modes the torsional mode of its parity nearest it in frequency,
 * within GAL_PARTNER_BAND of it, when not selected already (added to the number asked; its
 * `partner` the vertical mode's index). Galloping couples a vertical mode to the torsional modes
 * of its own symmetry (the aerodynamic moment and lift along the span project on a mode of the
 * other symmetry to nothing), most to the nearest in frequency; a bundle's first torsional mode
 * may be the antisymmetric one while the galloping vertical mode is symmetric. md must hold every
 * mode up to gal_modes_partner_top (gal_modes_find and gal_bundle_modes_find see to it). */
void gal_modes_select(gal_modes *md, const int want[GAL_FAMILY_COUNT]);
/* The frequency (Hz) up to which md must hold every mode for gal_modes_select's partners: the
 * highest of the lowest want[vertical] vertical modes of md times 1 + GAL_PARTNER_BAND; 0 when no
 * torsional mode or no vertical one is asked or md holds no vertical mode. */
double gal_modes_partner_top(const gal_modes *md, const int want[GAL_FAMILY_COUNT]);

/* The torsional partner of the selected vertical mode nearest f Hz (the torsional mode of its
 * parity nearest it in frequency within the band, selected or not): its position in md, with the
 * vertical mode's in *v and |f_t / f_v - 1| in *rel; -1 when none. */
int gal_modes_partner_near(const gal_modes *md, double f, int *v, double *rel);

/* Enough modes to hold `want[f]` modes of each family f (vertical, horizontal, torsional; axial
 * ignored), selected by gal_modes_select (the torsional partners computed too). The flexural families from the
 * bottom of the spectrum (more asked until each is found or `max_modes` is reached); the torsional
 * modes above them each by a shift at its estimate from the twist block of K and M, computing only
 * the few modes nearest it (their ranks from the inertia of K - sigma M), checked (a torsional mode
 * nearest its own estimate, with a small residual) or else found from the bottom as the flexural. */
int gal_modes_find(const gal_rod *rod, const double *q, const int want[GAL_FAMILY_COUNT],
                   int max_modes, gal_modes *out);

/* gal_modes_find about the equilibrium the statics found (eq->rod at eq->q): the same modes, to the
 * last bit, without evaluating the tangent or analysing its pattern again: those the statics'
 * stability check left in eq->tangent are taken over (when eq->q is still the configuration they
 * were made at) and eq->tangent is released either way. */
int gal_modes_find_eq(gal_equilibrium *eq, const int want[GAL_FAMILY_COUNT], int max_modes, gal_modes *out);

void gal_modes_clear(gal_modes *m);

#ifdef __cplusplus
}
#endif

#endif
