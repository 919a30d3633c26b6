/* sweep_par.h: the hand-out of a sweep's units of work to the processes that run it (sweep_par.c):
 * one process alone, or the ranks of `mpirun -n N gallop sweep` (built with MPI: GAL_MPI). Units
 * are handed out dynamically, one at a time, by rank 0, which runs units itself on a second thread
 * while its main thread answers the other ranks (MPI_THREAD_FUNNELED: only the main thread calls
 * MPI). Rank 0 counts the finished cases and shows the progress on stderr. */
#ifndef GALLOP_CLI_SWEEP_PAR_H
#define GALLOP_CLI_SWEEP_PAR_H

typedef struct gal_par gal_par;

/* The processes of this run: MPI initialized (built with MPI), else one. NULL when out of memory
 * or MPI fails (a message on stderr). */
gal_par *gal_par_init(void);
int gal_par_rank(const gal_par *p);
int gal_par_size(const gal_par *p);
/* Finalize MPI; accepts NULL; returns NULL. */
gal_par *gal_par_free(gal_par *p);

/* One unit of work; it calls gal_par_case_done after each of its cases. */
typedef void (*gal_par_unit_fn)(void *ctx, long unit);
/* A case finished: computed now with its own set-up (GAL_PAR_SETUP_COMPUTED), with its span's
 * equilibrium, modes and damping from an earlier case of its process (GAL_PAR_SETUP_REUSED), with
 * the equilibrium and modes but its damping built anew (GAL_PAR_SETUP_REUSED_MODES), or found
 * committed by an earlier run (0); setup_time_s: its set-up's wall time (gal_sweep_result). */
enum { GAL_PAR_SETUP_COMPUTED = 1, GAL_PAR_SETUP_REUSED = 2, GAL_PAR_SETUP_REUSED_MODES = 3 };
/* how may carry the reduced model's own set-up above these bits (gal_sweep_result.rom_setup: 1
 * computed, 2 reused) */
#define GAL_PAR_ROM_SHIFT 2
void gal_par_case_done(gal_par *p, int how, double setup_time_s);
/* Rank 0, after gal_par_run: of the cases computed by all ranks, those that computed their
 * equilibrium and modes, those that reused them, those that built their damping (their own
 * set-up's or anew), and the set-ups' wall time in all (s). */
void gal_par_setups(const gal_par *p, long *computed, long *reused, long *damping, double *time_s);
/* Rank 0, after gal_par_run: the reduced model's own set-ups computed and reused by all ranks. */
void gal_par_rom_setups(const gal_par *p, long *computed, long *reused);

/* Units 0 .. nunits-1 (ncases cases in all) run over every process, each exactly once. Returns,
 * on rank 0, when every unit is finished (the others return when no unit is left for them);
 * *computed (rank 0): the cases computed by all ranks. Progress lines on rank 0's stderr. */
void gal_par_run(gal_par *p, long nunits, long ncases, gal_par_unit_fn fn, void *ctx, long *computed);

#endif
