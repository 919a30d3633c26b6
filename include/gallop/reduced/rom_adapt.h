/* rom_adapt.h: the recomputed reduced model's adaptation (issue 13): where its self-check
 * (gal_rom_residual) passes the tolerance, the basis grows: the correction of the family whose
 * residual is largest, K0^-1 of that family's part of R at the failing state (rom.h
 * gal_rom_residual_family; or averaged over the orbit from there, GAL_ROM_ORBIT_*), and the next
 * computed mode of that family (with its modal derivatives); a new gal_rom is allocated on the larger basis
 * (gal_rom_alloc, so that whatever it builds is rebuilt) and run again from the run's start to the
 * time of the failing check (gal_rom_adapt_replay_from; the run's drivers do), or else started from
 * the old one's reconstructed full state. Each growth is logged (time, basis, family, what was added). A family's
 * first growth adds the correction alone (a growth can move a resonant limit cycle: the smallest
 * change first); a later one, the correction has not sufficed, adds the mode too. */
#ifndef GALLOP_ROM_ADAPT_H
#define GALLOP_ROM_ADAPT_H

#include "gallop/reduced/rom.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GAL_ROM_EVENTS_MAX 8 /* growths of one run, at most */
#define GAL_ROM_MODES_MAX 24  /* modes in an adapted basis, at most (with their derivatives) */
#define GAL_ROM_BASIS_CAP 90 /* basis vectors of an adapted basis, at most */

enum { GAL_ROM_ADD_CORRECTION = 1, GAL_ROM_ADD_MODE = 2 };

typedef struct gal_rom_event {
    double t_s;             /* s: simulated time of the failing check */
    double residual;        /* its residual (gal_rom_check.max) */
    gal_family family;      /* the family whose residual was largest */
    int basis_before, basis_after;
    int mode_added;         /* index in a->md (the model's modes, or own) of the mode added, or -1 */
    double mode_added_hz;   /* its frequency (0 when none) */
    int corrections;        /* correction directions added (0 to orbit_vectors) */
} gal_rom_event;

typedef struct gal_rom_adapt {
    const gal_rod *rod;
    const double *q_eq;
    const gal_modes *md;    /* the model's modes, or own once more were computed */
    gal_modes own;          /* more modes of a family, computed when the basis needs one that the
                             * model's stage did not compute (gal_modes_find computes only the
                             * modes asked for) */
    gal_rom_opts o;
    gal_force force;
    int policy;             /* GAL_ROM_ADD_* bits; default both */
    int relax;              /* 1 (default): the new stiff directions start quasi-static */
    int orbit_vectors;      /* corrections per growth taken over the orbit: 1 (the mean) or 2 (and the
                             * rest's dominant direction); 0 (default): the failing instant's
                             * family correction, no sampling (GAL_ROM_ORBIT_PERIODS) */
    int sel[GAL_ROM_MODES_MAX], nsel;
    double *extra;          /* ndof x nextra: the correction directions so far */
    int nextra;
    int nevents;
    gal_rom_event ev[GAL_ROM_EVENTS_MAX];
    double amp[GAL_FAMILY_COUNT]; /* the largest mass norm of each family's displacement so far */
    double twist_floor;     /* the mass norm of a 1-deg twist, half-sine along the span */
    int corrected[GAL_FAMILY_COUNT]; /* growths of the family by a correction alone so far */
    const double *q0, *v0; /* the run's start (gal_rom_adapt_replay_from), or NULL: restart in place */
    double replayed_s;      /* s: simulated time run again by the growths so far */
    long orbit_steps;       /* steps the old models ran on to sample the orbit (gal_rom_adapt_grow) */
    long cubic_checks;      /* checks past GAL_ROM_CUBIC_SETTLE_S so far (the cubic part every
                             * GAL_ROM_CUBIC_EVERY-th) */
    int nsel0, nextra0;     /* the initial selection's modes and the caller's extra vectors */
    int third;              /* third-order modal derivatives in the basis (0: none; see below) */
    gal_rom_band band;      /* the model's reduced modes above the damping band (GAL_ROM_BAND_WEIGHT),
                             * for the basis of band.r vectors after band_events growths */
    int band_events;
    /* Optional: called during a growth's replay (gal_rom_adapt_replay_from) at each multiple i of
     * replay_dt (> 0) before the failing check's time, with the grown model there, so that a run's
     * record up to the growth is the grown model's, not the one the check refused. */
    void (*replay_observe)(void *ctx, const gal_rom *m, long i);
    void *replay_ctx;
    double replay_dt;
} gal_rom_adapt;

/* The samples a growth's replay observes, kept apart until the growth has succeeded and then laid
 * over the run's record (the command line's run and the library's, rom_sim.h): replay_observe =
 * gal_rom_redo_observe with replay_ctx = the gal_rom_redo. A row is the probes' 4 nprobe entries
 * and the 2 support tensions, as gal_rom_observe writes them. */
typedef struct gal_rom_redo {
    int nprobe;
    const double *probe;    /* fractions of the span (not owned) */
    int want_taut;          /* 1: the least taut share over the rows into taut */
    double *row;            /* cap rows, or NULL */
    long n, cap;            /* rows observed by the current replay; room for */
    double taut;            /* the least gal_rom_taut_share over them (want_taut) */
    int failed;             /* out of memory for them: the record keeps the old model's */
} gal_rom_redo;

void gal_rom_redo_init(gal_rom_redo *r, int nprobe, const double *probe, int want_taut);
/* rom_adapt.h replay_observe: the grown model at sample i (i = 0 starts a replay) */
void gal_rom_redo_observe(void *ctx, const gal_rom *m, long i);
/* The rows before sample i over trace (4 nprobe a row) and tension (2 a row); how many were laid
 * (none when out of memory); the rows are then spent (taut is kept). */
long gal_rom_redo_apply(gal_rom_redo *r, long i, double *trace, double *tension);
void gal_rom_redo_clear(gal_rom_redo *r);

/* The adaptation's set-up from the model's (the same arguments as gal_rom_alloc, copied; rod,
 * q_eq, md and o's damping must outlive it) and the model on the initial basis into *m. */
int gal_rom_adapt_init(gal_rom_adapt *a, gal_rom **m, const gal_rod *rod, const double *q_eq, const gal_modes *md,
                       const int *sel, int nsel, const gal_rom_opts *o, const gal_force *force);
void gal_rom_adapt_clear(gal_rom_adapt *a);
/* Grow by running the grown model again from the run's start (q0, v0: full configuration and
 * velocity, nq each; v0 NULL: at rest; not copied, they must outlive a) to the failing check's
 * time, without checks (that stretch was the old model's, checked; the grown model is checked from
 * there on), instead of restarting it from the old model's state at that time. A restart in place
 * starts the new directions off the new model's balance: it rang at its own frequencies (0.2 deg of
 * twist at 6.4 Hz on data/scenes/iced_gallop.ini at 600 elements, read by the next check as 0.16
 * and grown on again), and the ringing seeded a limit cycle 21-31% off in the twist that the same
 * basis run from the start does not reach (BENCHMARKS.md, issue 13, helper growth). Costs the
 * simulated time up to each growth once more (replayed_s). */
void gal_rom_adapt_replay_from(gal_rom_adapt *a, const double *q0, const double *v0);

/* The self-check of *m (gal_rom_residual_dir) in the adaptation's norm: the translations as
 * there (each family against its own displacement, at least 2% of the whole motion's); the twist
 * against GAL_ROM_TWIST_WEIGHT times its running amplitude (the largest over the checks so far,
 * kept across growths, at least a 1-deg half-sine), so that the twist, whose mass norm is ~1e-3
 * of the translations', is measured at all. Calibrated on tests/rom (BENCHMARKS.md). */
#define GAL_ROM_TWIST_WEIGHT 1.5
/* The check also reads the basis's next term (gal_rom_cubic: the third-order part of the static
 * response along the modes' displacement, outside the basis) in the vertical and horizontal
 * families against the same scales, over GAL_ROM_CUBIC_SHARE, and takes it as the family's
 * residual where it is larger (so that it trips past that share of the tolerance): the
 * instantaneous residual cannot see a basis that lacks the cubic coupling (the reduced equations
 * are the full ones projected on it, and the missing shape is held at a consistent, wrong orbit:
 * tests/rom/grosbeak_300_soft_gj twist 46% off with the residual at 0.098; BENCHMARKS.md). Read
 * from GAL_ROM_CUBIC_SETTLE_S of simulated time on: a span swung by the wind's ramp overshoots
 * its mean swing at first. Its corrections and modes do not add that coupling (they made
 * grosbeak worse); what does is the coupling itself: the first check tripped by the cubic part
 * rebuilds the basis as the initial one (the selected modes, their modal derivatives, the caller's
 * extra vectors; the growths' corrections and modes dropped) plus the third-order modal derivatives
 * of the selected modes, -K0^-1 (d2K/d eta_j d eta_k) phi_i for i <= j <= k (nsel (nsel+1)(nsel+2)/6
 * vectors, 56 for 6 modes), and runs it again from the start; a set past GAL_ROM_BASIS_CAP, and
 * any later trip (cubic or not; but the band's, GAL_ROM_BAND_WEIGHT), is not grown on
 * (GAL_ROM_ELIMIT): a correction or mode grown past
 * the third-order set left grosbeak_300_soft_gj at 80 elements valid and 7.3% off in twist. Spans whose check never reads the cubic part
 * past the share are untouched. Calibrated on tests/rom/ and the shipped and hard scenes
 * (BENCHMARKS.md, helpers misses2 and soft). */
#define GAL_ROM_CUBIC_SHARE 0.3
/* With the third-order set the cubic growth adds the rod's torsional modes above the structural
 * damping's band up to GAL_ROM_THIRD_TORSION times the highest selected torsional mode's frequency
 * (within GAL_ROM_THIRD_TORSION_SLACK; not selected ones; lowest first, within GAL_ROM_BASIS_CAP):
 * the set's twist reaches those harmonics, and without the rod's own modes the basis holds them
 * only as Ritz vectors mixed with stiff translations, whose frequency swings with the tension and
 * which ring undamped, fed by the rod's nonlinear internal force (tests/rom/partridge_180_dshape.ini:
 * a reduced mode at ~12 Hz, 0.93 of the rod's third torsional mode at 10.6 Hz, 2.3 deg of ringing,
 * the twist 21-25% off and refused by GAL_ROM_BAND_WEIGHT's reading; with the modes to 24.7 Hz, the
 * 6 of the 7 up to 8x that the cap keeps, valid and 0.1-1.1% off at 100 and 125 elements; up to 3x
 * or 5x the frequency, 5.2% or 3.7% off at 125). Below the band the modal damping holds them and they are not added: on
 * grosbeak_300_soft_gj (torsional modes every 0.589 Hz, 8x = 4.71 Hz, under the 5-Hz band: nothing
 * added) adding them made it worse (1.2-2.4 Hz: twist 7.8% off, horizontal 18.5%; its 5.30-Hz 9th,
 * which 9x would add: twist 0.90% against 0.17%). BENCHMARKS.md, issue 13, helper ring. */
#define GAL_ROM_THIRD_TORSION 8.0
#define GAL_ROM_THIRD_TORSION_SLACK 0.02
#define GAL_ROM_CUBIC_SETTLE_S 20.0
/* Read at every this-th check: it costs two tangents of the whole rod, about twice the residual
 * (tests/bench/bench_rom_step.c: 119 us against 59 at 100 elements); the orbit it watches repeats. */
#define GAL_ROM_CUBIC_EVERY 3
/* And, once the basis holds the third-order set, the twist's ringing in the reduced modes above the
 * structural damping's band (rom.h gal_rom_band_amplitude: the amplitude a mode ringing at its
 * frequency has, from the velocity and the acceleration) against the twist's scale, times
 * GAL_ROM_BAND_WEIGHT, from GAL_ROM_CUBIC_SETTLE_S on, taken as the torsional residual where larger
 * (gal_rom_check.ring). The third-order vectors are stiff (Rayleigh frequencies to ~300 Hz) and no
 * rod modes: a Ritz vector among them that rings is nearly an eigenvector of the reduced equations,
 * its residual small while the twist it carries is not the full model's (no damping stops it):
 * tests/rom/partridge_180_dshape.ini at 100 elements rang 2.3 deg of twist at 11.7 Hz (the full
 * model 0.003 deg) and ended 21% off in twist with the residual at 0.004-0.05; the reading there
 * 0.13-0.37 (125 elements up to 0.42, 14 m/s 0.27 at its trip), grosbeak_300_soft_gj's third-order set (within)
 * 0.036-0.058 at 100 and 125 elements. Not read on a basis without that set: a grown torsional mode
 * (a rod mode) rings while a growth's transient decays, and a run that ends within read 0.23-0.56
 * there (partridge at 40 elements and at 150 m; BENCHMARKS.md, issue 13, helper partridge). A trip
 * by it grows the basis by the rod's own torsional modes above the band that it does not hold (M-norm
 * outside it over GAL_ROM_RING_OUTSIDE; a mode the basis holds reads ~1e-15, a mode computed again
 * ~1e-3), lowest first, as many as GAL_ROM_BASIS_CAP leaves room for beside the basis's vectors
 * (after deflation), and runs it again from the start, as the cubic growth does; with no room or no
 * such mode the run is refused (GAL_ROM_ELIMIT). The ringing Ritz vectors are the rod's torsional
 * harmonics the cap kept out of the cubic growth (tests/rom/drake_300_turbulent.ini at 125
 * elements rang at 11.3 Hz, its 11.23-Hz torsional mode left out; ibis_250_turbulent at 14.17 Hz,
 * its 13.98-Hz one) or higher ones (partridge_180_dshape at 14 m/s, at 25 and 37 Hz with the modes
 * to 28 Hz in): the modes up to the ringing's frequency alone left partridge refused by its
 * residual (0.103) and 9.7% off in twist; to the cap (90 vectors, modes to 66 Hz) valid and within
 * 0.1% (BENCHMARKS.md, issue 13, helper ring2). Past the third-order set nothing else is grown. */
#define GAL_ROM_BAND_WEIGHT 0.5
#define GAL_ROM_RING_OUTSIDE 1e-2
int gal_rom_adapt_residual(gal_rom_adapt *a, gal_rom *m, gal_rom_check *chk, double *du);

/* Grow the basis of *m after the check chk (du: its correction direction, ndof) failed at the
 * state of *m: *m is replaced by the model on the larger basis, started at the same time from the
 * same reconstructed state, counters carried over. GAL_OK when it grew; GAL_ELIMIT (nothing
 * changed, with a message saying what reached its bound) when it cannot grow; another status on
 * failure. */
/* With orbit_vectors > 0 the correction a growth adds is taken over the orbit, not at the failing
 * instant: the check's residual direction du and more, the old model run on from the check (its
 * reconstructed state there kept for a restart in place) over GAL_ROM_ORBIT_PERIODS periods of the
 * basis's lowest mode, sampled GAL_ROM_ORBIT_PER_PERIOD times per period of its highest (at most
 * GAL_ROM_ORBIT_SAMPLES samples), each the tripping family's correction alone
 * (gal_rom_residual_family) without its part in the old basis; added: their mean, Hann-weighted
 * over the window so that it does not depend on the phase the sampling starts at (and with
 * orbit_vectors = 2, also the dominant direction of the rest: their POD in the check's norm, per
 * family, mass-weighted over the failing check's scales). The grown basis then does not depend on
 * the instant the check trips (tests/test_rom_orbit.c). Not the default (0: the failing instant's
 * family correction): measured on main's family-alone correction it changes
 * data/scenes/iced_gallop.ini at 400-1200 elements by at most 0.2 points (both within 0.7% with
 * either BLAS thread count), and on tests/hard/twist_accumulation (a growth at t = 0, the wind there
 * at once, the window then a transient of several turns) it ends valid at 210 deg p-p where the
 * full model turns past 360 (refused with the default); orbit_vectors = 2 left
 * tests/rom/grosbeak_300_soft_gj valid 21% off in twist (BENCHMARKS.md, issue 13, helper orbit).
 * The sampling's steps count in the model's steps (and in orbit_steps). */
#define GAL_ROM_ORBIT_PERIODS 4.0
#define GAL_ROM_ORBIT_PER_PERIOD 4
#define GAL_ROM_ORBIT_SAMPLES 64
#define GAL_ROM_ORBIT_VECTORS 0 /* the default of orbit_vectors (0, 1 or 2) */
#define GAL_ROM_ELIMIT 1 /* positive: not an error of the computation */
int gal_rom_adapt_grow(gal_rom_adapt *a, gal_rom **m, const gal_rom_check *chk, const double *du);

#ifdef __cplusplus
}
#endif

#endif
