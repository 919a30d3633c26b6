/* cli/spectrum.c: `gallop spectrum TRACE.csv`: spectra and galloping measures of any trace
 * (DESIGN.md "Spectra and galloping measures"): parse the options, read the trace, choose the
 * columns and pairs, then the analysis (analysis/trace_spectrum.h), the files and the table
 * (output/specreport.h: summary.json and psd.csv). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "gallop.h"
#include "gallop/analysis/trace_spectrum.h"
#include "gallop/output/specreport.h"

typedef struct {
    const char *path, *outdir;
    const char *const *columns;
    size_t ncolumns;
    const char *const *pairs;   /* "Y,Z" */
    size_t npairs;
    double from;          /* NaN: automatic */
    long segment;         /* 0: chosen */
} options;

static int fail(int status)
{
    fprintf(stderr, "gallop spectrum: %s\n", gal_error_message());
    return gal_exit_code(status);
}

/* the parsed arguments into the options */
static int get_options(const gal_cli_command *c, const gal_cli_args *a, options *o)
{
    const char *v;
    char *end;
    o->from = NAN;
    o->path = a->operand;
    o->outdir = gal_cli_value(c, a, "output");
    o->ncolumns = (size_t)gal_cli_values(c, a, "column", &o->columns);
    o->npairs = (size_t)gal_cli_values(c, a, "pair", &o->pairs);
    if ((v = gal_cli_value(c, a, "from"))) {
        o->from = strtod(v, &end);
        if (!*v || *end || !isfinite(o->from)) return gal_error(GAL_EINPUT, "--from '%s': a time in s is needed", v);
    }
    if ((v = gal_cli_value(c, a, "segment"))) {
        o->segment = strtol(v, &end, 10);
        if (!*v || *end || o->segment < 8 || o->segment > (1L << 28))
            return gal_error(GAL_EINPUT, "--segment '%s': an integer from 8 to %ld samples", v, 1L << 28);
    }
    return GAL_OK;
}

/* --column NAME...: the selected data columns, each once (default: every one) */
static int select_columns(const options *o, const gal_trace *tr, int *sel, size_t *nsel)
{
    *nsel = 0;
    for (size_t i = 0; i < o->ncolumns; i++) {
        int c = gal_trace_column(tr, o->columns[i]);
        if (c < 0)
            return gal_error(GAL_EINPUT, "%s: no column '%s' (time column '%s')", o->path, o->columns[i],
                             tr->time_name);
        size_t k = 0;
        while (k < *nsel && sel[k] != c) k++;
        if (k == *nsel) sel[(*nsel)++] = c;   /* each column once */
    }
    if (o->ncolumns == 0)
        for (size_t c = 0; c < tr->ncol; c++) sel[(*nsel)++] = (int)c;
    return GAL_OK;
}

/* --pair Y,Z...: the orbit pairs (default: found by their names) */
static int select_pairs(const options *o, const gal_trace *tr, const int *sel, size_t nsel,
                        gal_trace_pair *pairs, size_t *npairs)
{
    *npairs = 0;
    for (size_t i = 0; i < o->npairs; i++) {
        const char *comma = strchr(o->pairs[i], ',');
        char name[512];
        size_t ly = comma ? (size_t)(comma - o->pairs[i]) : 0;
        if (!comma || ly == 0 || ly >= sizeof name || !comma[1])
            return gal_error(GAL_EINPUT, "--pair '%s': two column names Y,Z are needed", o->pairs[i]);
        memcpy(name, o->pairs[i], ly);
        name[ly] = '\0';
        int y = gal_trace_column(tr, name), z = gal_trace_column(tr, comma + 1);
        if (y < 0 || z < 0)
            return gal_error(GAL_EINPUT, "--pair '%s': %s: no column '%s'", o->pairs[i], o->path,
                             y < 0 ? name : comma + 1);
        pairs[*npairs].y = y, pairs[*npairs].z = z, (*npairs)++;
    }
    if (o->npairs == 0) *npairs = gal_trace_auto_pairs(tr, sel, nsel, pairs);
    return GAL_OK;
}

/* -o DIR, else the directory of the trace + /spectrum; malloc'ed */
static char *output_dir(const options *o)
{
    if (o->outdir) return strdup(o->outdir);
    const char *slash = strrchr(o->path, '/');
    size_t ld = slash ? (size_t)(slash - o->path) : 0;
    char *outdir = malloc(ld + 16);
    if (outdir) {
        if (!slash) snprintf(outdir, ld + 16, "spectrum");
        else if (ld == 0) snprintf(outdir, ld + 16, "/spectrum");
        else snprintf(outdir, ld + 16, "%.*s/spectrum", (int)ld, o->path);
    }
    return outdir;
}

/* the trace read: columns, pairs, analysis, files, table */
static int run(const options *o, const gal_trace *tr, double t_start)
{
    int *sel = malloc((tr->ncol + o->ncolumns) * sizeof *sel);
    gal_trace_pair *pairs = malloc((2 * (tr->ncol + o->ncolumns) + o->npairs + 1) * sizeof *pairs);
    char *outdir = output_dir(o);
    size_t nsel = 0, npairs = 0;
    gal_trace_spectrum s = {0};
    int st = (!sel || !pairs || !outdir) ? gal_error(GAL_ENOMEM, "out of memory") : GAL_OK;
    if (!st) st = select_columns(o, tr, sel, &nsel);
    if (!st) st = select_pairs(o, tr, sel, nsel, pairs, &npairs);
    if (!st) st = gal_trace_spectrum_run(tr, sel, nsel, pairs, npairs, o->from, o->segment, &s);
    if (!st && s.coarse)
        fprintf(stderr, "gallop spectrum: warning: --segment %zu is below 1/200 of the steady "
                "part (%zu samples): peak frequencies are coarse\n", s.nseg, tr->n - s.i0);
    if (!st) st = gal_trace_spectrum_write(outdir, o->path, tr, &s, gal_wall_time() - t_start);
    if (!st) gal_trace_spectrum_print(stdout, o->path, tr, &s);
    gal_trace_spectrum_clear(&s);
    free(sel);
    free(pairs);
    free(outdir);
    return st;
}

int gal_cli_spectrum(int argc, char **argv)
{
    double t_start = gal_wall_time();
    const gal_cli_command *c = gal_cli_command_find("spectrum");
    gal_cli_args args;
    int rc = gal_cli_parse(c, argc, argv, &args);
    if (rc) return rc;
    options o = {0};
    gal_trace *tr = NULL;
    int st = get_options(c, &args, &o);
    if (st == GAL_EINPUT) {
        fprintf(stderr, "gallop spectrum: %s\n", gal_error_message());
        gal_cli_usage(stderr, c);
        return 2;
    }
    char *outdir = st ? NULL : output_dir(&o);
    if (!st && !outdir) st = gal_error(GAL_ENOMEM, "out of memory");
    if (!st && (st = gal_outset_check(outdir)) != GAL_OK) { /* before any computation */
        fprintf(stderr, "gallop spectrum: -o: %s\n", gal_error_message());
        free(outdir);
        return 2;
    }
    free(outdir);
    if (!st) st = gal_trace_read(o.path, &tr);
    if (!st) st = run(&o, tr, t_start);
    gal_trace_free(tr);
    return st ? fail(st) : 0;
}
