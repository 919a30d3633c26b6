/* rom_turb.h: the reduced model's basis in turbulent wind (issue 13; src/reduced/rom_turb.c). A
 * turbulent wind field is generated before the run (windfield.h), so the loads it will apply are
 * known at the set-up: every o.sample_s over the run, the load F(t, q_eq, 0) at the equilibrium at
 * rest (the mean wind's and the turbulence's, uncentred) has a static response K0^-1 F (a
 * load-dependent Ritz vector, Wilson, Yuan & Dickens 1982). What the basis V already holds is taken
 * out (d - V V^T M d) and what is left is compressed by a POD in the mass norm (the method of
 * snapshots: the eigenvectors of the snapshots' Gram matrix), the twist's part and the
 * translations' apart (the twist's mass norm is ~1e-3 of the translations': together its shapes
 * would be lost): by decreasing share, while what is left of the part is above o.energy of the
 * part's whole squared norm (V's share included), at most o.max_vectors of each. Appended to the
 * basis up front (gal_rom_opts.extra), they carry the spatial content of the turbulent loads that
 * the self-check otherwise added mid-run (corrections and the torsional modes at 2.8-7.0 Hz in the
 * first seconds, each a rebuild and a restart; BENCHMARKS.md, helper turb). On drake_300_turbulent
 * and iced_gallop_turbulent the modes and modal derivatives miss 6-14% of the twist's static
 * responses (3-4 vectors leave 1e-4) and 5e-7 of the translations' (none kept at the default
 * energy: the translations' shapes are rough, and 5-6 of them took the energy's sample from 30 to
 * 70 elements of 100, twice the cost of a step). */
#ifndef GALLOP_ROM_TURB_H
#define GALLOP_ROM_TURB_H

#include "gallop/reduced/rom.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct gal_rom_turb_opts {
    double t0, t1;          /* s: the run's span of time the snapshots cover */
    double sample_s;        /* s: between snapshots; default 0.5 */
    double energy;          /* stop when what the kept shapes leave of a part is at most this share
                             * of the part's whole squared mass norm; default 1e-3 */
    int max_vectors;        /* per part (twist, translations); default 6 */
} gal_rom_turb_opts;

void gal_rom_turb_default_opts(gal_rom_turb_opts *o);

/* What the vectors came from (diagnostics; summary lines). */
typedef struct gal_rom_turb_info {
    int snapshots;
    int vectors[2];         /* kept: translations, twist */
    double outside[2];      /* the snapshots' squared mass norm outside V over their whole, per part */
    double left[2];         /* ... and what the kept vectors leave of that outside part */
} gal_rom_turb_info;

/* The load-dependent Ritz vectors of the loads `force` over [o.t0, o.t1] for the model m (its rod,
 * q_eq, basis V and factor of K0 are read: a set-up, gal_rom_setup_alloc, does): *extra (ndof x
 * *nextra, column-major, M-orthonormal and M-orthogonal to V; the caller frees it; NULL when
 * *nextra is 0). info may be NULL. */
int gal_rom_turb_vectors(const gal_rom *m, const gal_force *force, const gal_rom_turb_opts *o, double **extra,
                         int *nextra, gal_rom_turb_info *info);

/* The vectors of a run of `duration` s with the default options (t0 = 0, t1 = duration). */
int gal_rom_turb_basis(const gal_rom *m, const gal_force *force, double duration, double **extra, int *nextra);

#ifdef __cplusplus
}
#endif

#endif
