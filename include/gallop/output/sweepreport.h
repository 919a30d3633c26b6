/* sweepreport.h: the files of `gallop sweep` (issue 18): each finished case committed on its own
 * in DIR/cases/ (sweeprec.c), so that a rerun of an interrupted sweep skips it, and at the end
 * DIR/sweep.csv and DIR/summary.json as one output set (sweepreport.c).
 *
 * A case's record is DIR/cases/<fingerprint>.case (text: its figures to 17 digits, its status and
 * message) and, for a continuation, DIR/cases/<fingerprint>.state (its final configuration and
 * velocity, nq doubles each, native byte order): the state is written first, the record last, each
 * to a temporary file renamed into place after fsync; the record is the commit. The fingerprint
 * is the resolved scene of the case (record.h's scene hash: the file, the --set and the varied
 * values), the bytes of its aero table, the model, the branch and the fingerprint of the case it
 * continues from: a case of a changed scene has another name and is computed anew, never resumed. */
#ifndef GALLOP_OUTPUT_SWEEPREPORT_H
#define GALLOP_OUTPUT_SWEEPREPORT_H

#include <stdint.h>

#include "gallop/run/sweep.h"

#ifdef __cplusplus
extern "C" {
#endif

int gal_sweep_fingerprint(const gal_scene *sc, gal_model_kind kind, gal_sweep_branch branch, uint64_t prev,
                          uint64_t *fp);

/* DIR/cases, made if needed. */
int gal_sweep_cases_dir(const char *dir);
/* Commit case fp: its state first when q is given (nq entries of q and of v), then its record. */
int gal_sweep_record_write(const char *dir, uint64_t fp, const gal_sweep_result *r, const double *q,
                           const double *v, int nq);
/* Case fp as committed: 1 found (r filled; *q, *v malloc'ed with *nq entries when q is given and
 * the case has a state, else NULL), 0 absent or incomplete (then it is computed again). */
int gal_sweep_record_read(const char *dir, uint64_t fp, gal_sweep_result *r, double **q, double **v, int *nq);

/* What the summary says of the run besides the rows. */
typedef struct gal_sweep_totals {
    const char *model;               /* "reduced" or "full" */
    int ranks;                       /* processes that ran cases */
    long computed, resumed, failed;  /* cases */
    double wall_time_s;              /* the whole sweep */
    double case_time_s;              /* sum of the cases' wall times (this run's and the resumed) */
    long setups_computed, setups_reused; /* this run's cases: equilibrium and modes computed, or
                                      * another case's of the same span (run/sweep.h) */
    long damping_computed;           /* ... that built their structural damping (own set-up, or
                                      * another damping ratio than the set-up they reused) */
    double setup_time_s;             /* this run's set-ups' wall time in all */
    long reduced_setups_computed, reduced_setups_reused; /* this run's reduced cases: the reduced
                                      * model's own wind-independent set-up computed, or another
                                      * case's of the same span */
} gal_sweep_totals;

/* DIR/sweep.csv (one row per case, in row order) and DIR/summary.json (the grid, the totals, per
 * varied key where the vertical amplitude jumps: galloping_from), one output set. rows: ncases. */
int gal_sweep_write(const char *dir, const gal_scene *sc, const gal_sweep_grid *g, const gal_sweep_result *rows,
                    const gal_sweep_totals *t);

#ifdef __cplusplus
}
#endif

#endif
