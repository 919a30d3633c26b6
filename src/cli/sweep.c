/* cli/sweep.c: `gallop sweep SCENE --vary section.key=LIST [--vary ...] [--model reduced|full]
 * [--continuation] [--set section.key=value]... [-o DIR]` (issue 18): the scene run over the
 * product grid of the varied keys (run/sweep.h), alone or as the ranks of `mpirun -n N gallop
 * sweep` (sweep_par.h); each case committed on its own in DIR/cases/ and skipped by a rerun that
 * finds it (same fingerprint); rank 0 writes DIR/sweep.csv and DIR/summary.json from the
 * committed cases (output/sweepreport.h). Only this command initializes MPI. */
#define _POSIX_C_SOURCE 200809L
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "gallop.h"
#include "gallop/output/sweepreport.h"
#include "gallop/run/sweep.h"
#include "gallop/scene/scene.h"
#include "sweep_par.h"

typedef struct {
    const gal_cli_command *c;
    gal_cli_args a;
    const char *path, *outdir;     /* outdir: dir[] */
    char dir[GAL_PATH_MAX], casedir[GAL_PATH_MAX + 8];
    const char *const *user;       /* the --set values */
    int nuser;
    gal_model_kind kind;
    gal_sweep_grid g;
    gal_par *par;
    gal_sweep_onset_cache cache;
    gal_sweep_setup_cache setup;   /* the spans' equilibria and modes, kept between cases */
    gal_scene sc;                  /* the case being loaded (one unit at a time per process) */
    int nomem;
} sweep;

static int fail(const char *what, int st)
{
    fprintf(stderr, "gallop sweep: %s%s\n", what, gal_error_message());
    return gal_exit_code(st);
}

/* The scene of case c into S->sc. */
static int load_case(sweep *S, const gal_sweep_case *c)
{
    char buf[GAL_SWEEP_MAX_AXES][GAL_SWEEP_KEY_MAX + GAL_SWEEP_VALUE_MAX];
    const char *sets[GAL_CLI_MAX_VALS + GAL_SWEEP_MAX_AXES];
    int n = gal_sweep_case_sets(&S->g, c, S->user, S->nuser, buf, sets);
    return gal_scene_load(&S->sc, S->path, sets, n, NULL);
}

/* A case that could not start (its scene refused: a combination of values the reader rejects). */
static void failed_case(gal_sweep_result *r, int st)
{
    memset(r, 0, sizeof *r);
    r->status = st;
    snprintf(r->message, sizeof r->message, "%s", gal_error_message());
    r->vertical_pp_m = r->horizontal_pp_m = r->twist_pp_deg = r->frequency_hz = r->tension_max_n = NAN;
    r->onset_speed_m_s = r->residual_max = NAN;
    r->valid = -1;
}

/* The unit handed out h-th: the points in the order of the last key fastest (of the keys the units
 * run over: a chain runs along the first), so that ranks at work at the same time take different
 * spans; each span's onset is computed once and kept in DIR/cases for the other ranks. */
static long unit_of(const gal_sweep_grid *g, long h)
{
    int k0 = g->continuation ? 1 : 0, idx[GAL_SWEEP_MAX_AXES];
    for (int k = g->naxes - 1; k >= k0; k--) {
        idx[k] = (int)(h % g->axis[k].n);
        h /= g->axis[k].n;
    }
    long u = 0, stride = 1;
    for (int k = k0; k < g->naxes; k++) {
        u += idx[k] * stride;
        stride *= g->axis[k].n;
    }
    return u;
}

/* One unit: a case, or a chain up and down the first key, each case from its predecessor's state. */
static void run_unit(void *ctx, long h)
{
    sweep *S = ctx;
    const gal_sweep_grid *g = &S->g;
    long u = unit_of(g, h);
    double *q = NULL, *v = NULL;
    int nq = 0;
    uint64_t prev = 0;
    for (int pos = 0; pos < g->unit_cases; pos++) {
        gal_sweep_case c;
        gal_sweep_case_of(g, u, pos, &c);
        gal_sweep_result r;
        double *q1 = NULL, *v1 = NULL;
        int nq1 = 0, computed = 0;
        uint64_t fp = 0;
        int st = load_case(S, &c);
        if (!st) st = gal_sweep_fingerprint(&S->sc, S->kind, c.branch, prev, &fp);
        if (st) {
            failed_case(&r, st);
        } else if (!gal_sweep_record_read(S->outdir, fp, &r, g->continuation ? &q1 : NULL, &v1, &nq1)) {
            computed = 1;
            if (gal_sweep_case_run(&S->sc, S->kind, q, v, nq, &S->cache, &S->setup, &r, g->continuation ? &q1 : NULL,
                                   &v1, &nq1))
                S->nomem = 1;
            if (gal_sweep_record_write(S->outdir, fp, &r, q1, v1, nq1))
                fprintf(stderr, "gallop sweep: case %ld: %s\n", c.row + 1, gal_error_message());
        }
        free(q), free(v);
        q = q1, v = v1, nq = nq1, prev = fp;
        gal_par_case_done(S->par, computed ? (GAL_PAR_SETUP_COMPUTED + r.setup_reused) | r.rom_setup << GAL_PAR_ROM_SHIFT : 0,
                          computed ? r.setup_time_s : 0);
    }
    free(q), free(v);
}

/* rank 0: every row from the committed records, in order (the chains' fingerprints again) */
static int collect(sweep *S, gal_sweep_result *rows, double *case_time, long *failed)
{
    const gal_sweep_grid *g = &S->g;
    *case_time = 0, *failed = 0;
    for (long u = 0; u < g->nunits; u++) {
        uint64_t prev = 0;
        for (int pos = 0; pos < g->unit_cases; pos++) {
            gal_sweep_case c;
            gal_sweep_case_of(g, u, pos, &c);
            uint64_t fp = 0;
            int st = load_case(S, &c);
            if (!st) st = gal_sweep_fingerprint(&S->sc, S->kind, c.branch, prev, &fp);
            if (st) failed_case(rows + c.row, st);
            else if (!gal_sweep_record_read(S->outdir, fp, rows + c.row, NULL, NULL, NULL))
                return gal_error(GAL_EIO, "%s/cases: the record of case %ld is missing (a rank failed to write it)",
                                 S->outdir, c.row + 1);
            prev = fp;
            *case_time += rows[c.row].wall_time_s;
            *failed += rows[c.row].status != 0;
        }
    }
    return GAL_OK;
}

/* The options beyond SCENE, --set and -o: the grid and the model. */
static int options(sweep *S)
{
    const char *const *vary;
    int nv = gal_cli_values(S->c, &S->a, "vary", &vary), st = GAL_OK;
    if (nv == 0) return gal_error(GAL_EINPUT, "no --vary given; allowed: one to %d --vary section.key=LIST",
                                  GAL_SWEEP_MAX_AXES);
    if (nv > GAL_SWEEP_MAX_AXES)
        return gal_error(GAL_EINPUT, "%d --vary given; allowed: one to %d", nv, GAL_SWEEP_MAX_AXES);
    for (int k = 0; !st && k < nv; k++) st = gal_sweep_axis_parse(&S->g.axis[S->g.naxes++], vary[k]);
    const char *const *flag;
    if (!st) st = gal_sweep_grid_init(&S->g, gal_cli_values(S->c, &S->a, "continuation", &flag) > 0);
    const char *model = gal_cli_value(S->c, &S->a, "model");
    S->kind = model && !strcmp(model, "full") ? GAL_MODEL_FULL : GAL_MODEL_REDUCED;
    if (!st && model && strcmp(model, "full") && strcmp(model, "reduced"))
        st = gal_error(GAL_EINPUT, "--model %s; allowed: reduced, full", model);
    S->nuser = gal_cli_values(S->c, &S->a, "set", &S->user);
    S->path = S->a.operand;
    if (!st && gal_sweep_explicit_bundle(&S->sc)) { /* the explicit bundle: its full model, from rest */
        if (S->g.continuation)
            st = gal_error(GAL_EINPUT, "%s: --continuation with [bundle] model = explicit: the explicit bundle's "
                           "runs start at rest; allowed: no --continuation, or model = equivalent", S->path);
        else if (S->kind != GAL_MODEL_FULL)
            fprintf(stderr, "gallop sweep: [bundle] model = explicit: every case runs the explicit bundle's full "
                    "model (it has no reduced model in a sweep)\n");
        S->kind = GAL_MODEL_FULL;
        if (!st) gal_cli_bundle_mesh_warning(&S->sc, "sweep"); /* the scene's mesh, before --vary */
    }
    if (!st) st = gal_sweep_grid_check(&S->g, S->path, S->user, S->nuser);
    return st;
}

/* rank 0, after the cases: the files and a line on stdout */
static int finish(sweep *S, long computed, double t0)
{
    gal_sweep_result *rows = calloc((size_t)S->g.ncases, sizeof *rows);
    if (!rows) return fail("", gal_error(GAL_ENOMEM, "out of memory"));
    gal_sweep_totals t = {S->kind == GAL_MODEL_FULL ? "full" : "reduced", gal_par_size(S->par), computed, 0, 0, 0, 0,
                          0, 0, 0, 0, 0, 0};
    t.resumed = S->g.ncases - computed;
    gal_par_setups(S->par, &t.setups_computed, &t.setups_reused, &t.damping_computed, &t.setup_time_s);
    gal_par_rom_setups(S->par, &t.reduced_setups_computed, &t.reduced_setups_reused);
    int st = collect(S, rows, &t.case_time_s, &t.failed);
    gal_scene base;
    if (!st) st = gal_scene_load(&base, S->path, S->user, S->nuser, NULL);
    if (!st) strcpy(base.output.directory, S->outdir);
    t.wall_time_s = gal_wall_time() - t0;
    if (!st) st = gal_sweep_write(S->outdir, &base, &S->g, rows, &t);
    if (!st) {
        printf("%ld cases (%ld computed, %ld resumed, %ld failed) on %d rank%s in %.1f s\nfiles: %s/{sweep.csv,"
               "summary.json,cases/}\n", S->g.ncases, t.computed, t.resumed, t.failed, t.ranks, t.ranks > 1 ? "s" : "",
               t.wall_time_s, S->outdir);
        for (long r = 0; r < S->g.ncases; r++)
            if (rows[r].status) fprintf(stderr, "gallop sweep: case %ld failed: %s\n", r + 1, rows[r].message);
    }
    free(rows);
    if (st) return fail("", st);
    return t.failed ? 1 : 0;
}

/* Ranks other than 0 check the same input silently: one message, not one per rank. */
static int quiet(int rank)
{
    if (rank == 0) return -1;
    fflush(stderr);
    int saved = dup(2), devnull = open("/dev/null", O_WRONLY);
    if (devnull >= 0) dup2(devnull, 2), close(devnull);
    return saved;
}

static void loud(int saved)
{
    if (saved < 0) return;
    fflush(stderr);
    dup2(saved, 2);
    close(saved);
}

int gal_cli_sweep(int argc, char **argv)
{
    double t0 = gal_wall_time();
    sweep *S = calloc(1, sizeof *S);
    if (!S) return fail("", gal_error(GAL_ENOMEM, "out of memory"));
    S->c = gal_cli_command_find("sweep");
    if (!(S->par = gal_par_init())) {
        free(S);
        return 1;
    }
    int rank = gal_par_rank(S->par), saved = quiet(rank);
    int rc = gal_cli_parse(S->c, argc, argv, &S->a), st;
    if (!rc) rc = gal_cli_scene(S->c, &S->a, &S->sc, &S->outdir);
    if (!rc) S->outdir = strcpy(S->dir, S->outdir); /* S->sc is each case's in turn */
    if (!rc && (st = options(S))) rc = fail("", st);
    loud(saved);
    if (!rc && (st = gal_sweep_cases_dir(S->outdir))) rc = fail("", st);
    snprintf(S->casedir, sizeof S->casedir, "%s/cases", S->dir);
    S->cache.dir = S->casedir;
    if (!rc) {
        long computed = 0;
        gal_par_run(S->par, S->g.nunits, S->g.ncases, run_unit, S, &computed);
        if (rank == 0) rc = finish(S, computed, t0);
        if (S->nomem) rc = fail("", gal_error(GAL_ENOMEM, "out of memory in a case"));
    }
    gal_par_free(S->par);
    gal_sweep_setup_cache_clear(&S->setup);
    gal_sweep_grid_clear(&S->g);
    free(S);
    return rc;
}
