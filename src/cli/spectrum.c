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

static const char *usage_text =
    "usage: gallop spectrum TRACE.csv [--column NAME]... [--pair Y,Z]... [--from T] [--segment N]\n"
    "                       [-o DIR]\n"
    "  TRACE.csv     header of column names; time column `time`, `t` or `time_s`, else the first;\n"
    "                uniform time step\n"
    "  --column NAME analyse this column (repeatable; default: every column but time)\n"
    "  --pair Y,Z    orbit ellipse of horizontal Y and vertical Z (repeatable; default: the\n"
    "                columns named *_y/*_z or *_horizontal/*_vertical)\n"
    "  --from T      steady part starts at time T, s (default: the latest time to steady of the\n"
    "                columns, but not after the middle of the record)\n"
    "  --segment N   Welch segment, samples (default: largest power of two giving >= 8 segments,\n"
    "                at least 256)\n"
    "  -o DIR        output directory (default: the directory of TRACE.csv + /spectrum)\n"
    "writes DIR/summary.json and DIR/psd.csv; exit status 0 ok, 1 computation failed, 2 bad input\n";

typedef struct {
    const char *path, *outdir;
    const char **columns;
    size_t ncolumns;
    const char **pairs;   /* "Y,Z" */
    size_t npairs;
    double from;          /* NaN: automatic */
    long segment;         /* 0: chosen */
} options;

static int fail(int status)
{
    fprintf(stderr, "gallop spectrum: %s\n", gal_error_message());
    return gal_exit_code(status);
}

/* "--name value" or "--name=value"; returns the value or NULL, advancing *i. */
static const char *opt_value(int argc, char **argv, int *i, const char *name, int *bad)
{
    size_t ln = strlen(name);
    if (strncmp(argv[*i], name, ln) != 0) return NULL;
    if (argv[*i][ln] == '=') return argv[*i] + ln + 1;
    if (argv[*i][ln] != '\0') return NULL;
    if (*i + 1 >= argc) {
        *bad = gal_error(GAL_EINPUT, "option %s needs a value", name);
        return NULL;
    }
    return argv[++*i];
}

static int parse_args(int argc, char **argv, options *o)
{
    o->from = NAN;
    o->columns = calloc((size_t)argc, sizeof *o->columns);
    o->pairs = calloc((size_t)argc, sizeof *o->pairs);
    if (!o->columns || !o->pairs) return gal_error(GAL_ENOMEM, "out of memory");
    for (int i = 1; i < argc; i++) {
        const char *v;
        int bad = 0;
        char *end;
        if ((v = opt_value(argc, argv, &i, "--column", &bad))) {
            o->columns[o->ncolumns++] = v;
        } else if (!bad && (v = opt_value(argc, argv, &i, "--pair", &bad))) {
            o->pairs[o->npairs++] = v;
        } else if (!bad && (v = opt_value(argc, argv, &i, "--from", &bad))) {
            o->from = strtod(v, &end);
            if (!*v || *end || !isfinite(o->from))
                return gal_error(GAL_EINPUT, "--from '%s': a time in s is needed", v);
        } else if (!bad && (v = opt_value(argc, argv, &i, "--segment", &bad))) {
            o->segment = strtol(v, &end, 10);
            if (!*v || *end || o->segment < 8 || o->segment > (1L << 28))
                return gal_error(GAL_EINPUT, "--segment '%s': an integer from 8 to %ld samples",
                                 v, 1L << 28);
        } else if (!bad && (v = opt_value(argc, argv, &i, "-o", &bad))) {
            o->outdir = v;
        } else if (bad) {
            return bad;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            return gal_error(GAL_EINPUT, "unknown option '%s'", argv[i]);
        } else if (o->path) {
            return gal_error(GAL_EINPUT, "one trace only: '%s' and '%s'", o->path, argv[i]);
        } else {
            o->path = argv[i];
        }
    }
    if (!o->path) return gal_error(GAL_EINPUT, "no trace given");
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
    for (int i = 1; i < argc; i++)
        if (!strcmp(argv[i], "-h") || !strcmp(argv[i], "--help")) {
            fputs(usage_text, stdout);
            return 0;
        }
    options o = {0};
    gal_trace *tr = NULL;
    int st = parse_args(argc, argv, &o);
    if (st == GAL_EINPUT) {
        fprintf(stderr, "gallop spectrum: %s\n%s", gal_error_message(), usage_text);
        free(o.columns);
        free(o.pairs);
        return 2;
    }
    if (!st) st = gal_trace_read(o.path, &tr);
    if (!st) st = run(&o, tr, t_start);
    gal_trace_free(tr);
    free(o.columns);
    free(o.pairs);
    return st ? fail(st) : 0;
}
