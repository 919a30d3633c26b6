/* cli/spectrum.c: `gallop spectrum TRACE.csv`: spectra and galloping measures of any trace
 * (DESIGN.md "Spectra and galloping measures"): a table on stdout, summary.json and psd.csv.
 *
 * Pipeline: read the trace -> envelope and time to steady of every column (whole record) ->
 * steady part [--from, end], or automatic: from the latest time to steady of the columns but not
 * after the middle of the record (and at least 16 samples) -> Welch PSD, peaks and amplitudes of
 * the steady part -> orbit ellipses of the pairs -> files.
 * summary.json: trace, time_column, samples, dt_s, steady_from_s, steady_from_rule ("auto" or
 * "option --from"), steady_samples, segment, segments, frequency_resolution_hz; columns: an
 * object per column with frequency_hz (null when none), peaks_hz, peak_amplitudes, amplitude (of
 * the dominant sine), amplitude_pp, rms, mean, time_to_steady_s (trace time from which the
 * envelope stays within 5% of its final level; null for a constant column); orbit (the first
 * pair: y, z, major_semi_axis, minor_semi_axis, tilt_deg) when there is a pair, orbits (all
 * pairs); wall_time_s. psd.csv: frequency_hz then one PSD column (unit^2/Hz) per column. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "gallop.h"

#define NPEAKS 5   /* peaks reported per column */

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

typedef struct {
    int y, z;             /* data columns of the trace */
    gal_orbit orbit;
} pair;

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

static int ends_with(const char *s, const char *suffix, size_t *prefix)
{
    size_t ls = strlen(s), lx = strlen(suffix);
    if (ls <= lx || strcmp(s + ls - lx, suffix)) return 0;
    *prefix = ls - lx;
    return 1;
}

/* Pairs named <p>_y/<p>_z or <p>_horizontal/<p>_vertical among the selected columns. */
static size_t auto_pairs(const gal_trace *tr, const int *sel, size_t nsel, pair *pairs)
{
    static const char *suf[2][2] = {{"_y", "_z"}, {"_horizontal", "_vertical"}};
    size_t np = 0;
    for (size_t a = 0; a < nsel; a++)
        for (int s = 0; s < 2; s++) {
            size_t lp;
            const char *ya = tr->names[sel[a]];
            if (!ends_with(ya, suf[s][0], &lp)) continue;
            for (size_t b = 0; b < nsel; b++) {
                size_t lq;
                const char *zb = tr->names[sel[b]];
                if (ends_with(zb, suf[s][1], &lq) && lq == lp && !strncmp(ya, zb, lp)) {
                    pairs[np].y = sel[a], pairs[np].z = sel[b];
                    np++;
                    break;
                }
            }
        }
    return np;
}

static void fmt(char *buf, size_t n, double v)
{
    if (isfinite(v)) snprintf(buf, n, "%.6g", v);
    else snprintf(buf, n, "none");
}

static int write_psd(const char *dir, const gal_trace *tr, const int *sel, size_t nsel,
                     const double *psd, size_t nf, double df)
{
    gal_ofile f;
    int st = gal_ofile_open_in(&f, dir, "psd.csv");
    if (st) return st;
    fprintf(f.fp, "frequency_hz");
    for (size_t c = 0; c < nsel; c++) fprintf(f.fp, ",%s", tr->names[sel[c]]);
    fputc('\n', f.fp);
    for (size_t k = 0; k < nf; k++) {
        fprintf(f.fp, "%.10g", (double)k * df);
        for (size_t c = 0; c < nsel; c++) fprintf(f.fp, ",%.10g", psd[c * nf + k]);
        fputc('\n', f.fp);
    }
    return gal_ofile_close(&f, 1);
}

static void json_orbit(gal_json *j, const gal_trace *tr, const pair *p)
{
    gal_json_kv_str(j, "y", tr->names[p->y]);
    gal_json_kv_str(j, "z", tr->names[p->z]);
    gal_json_kv_num(j, "major_semi_axis", p->orbit.major);
    gal_json_kv_num(j, "minor_semi_axis", p->orbit.minor);
    gal_json_kv_num(j, "tilt_deg", p->orbit.tilt_deg);
}

typedef struct {
    size_t i0, nseg, nsegments;
    double df, wall;
    int auto_from;
} run_info;

static int write_summary(const char *dir, const char *path, const gal_trace *tr, const int *sel,
                         size_t nsel, const gal_measures *m, const double *tss, const pair *pairs,
                         size_t npairs, const run_info *ri)
{
    gal_ofile f;
    int st = gal_ofile_open_in(&f, dir, "summary.json");
    if (st) return st;
    gal_json j;
    gal_json_begin(&j, f.fp);
    gal_json_kv_str(&j, "trace", path);
    gal_json_kv_str(&j, "time_column", tr->time_name);
    gal_json_kv_int(&j, "samples", (long)tr->n);
    gal_json_kv_num(&j, "dt_s", tr->dt);
    gal_json_kv_num(&j, "steady_from_s", tr->t[ri->i0]);
    gal_json_kv_str(&j, "steady_from_rule", ri->auto_from ? "auto" : "option --from");
    gal_json_kv_int(&j, "steady_samples", (long)(tr->n - ri->i0));
    gal_json_kv_int(&j, "segment", (long)ri->nseg);
    gal_json_kv_int(&j, "segments", (long)ri->nsegments);
    gal_json_kv_num(&j, "frequency_resolution_hz", ri->df);
    gal_json_key(&j, "columns");
    gal_json_obj_begin(&j);
    for (size_t c = 0; c < nsel; c++) {
        gal_json_key(&j, tr->names[sel[c]]);
        gal_json_obj_begin(&j);
        gal_json_kv_num(&j, "frequency_hz", m[c].frequency);
        gal_json_key(&j, "peaks_hz");
        gal_json_arr_begin(&j);
        for (size_t q = 0; q < m[c].npeaks; q++) gal_json_num(&j, m[c].peaks[q].frequency);
        gal_json_arr_end(&j);
        gal_json_key(&j, "peak_amplitudes");
        gal_json_arr_begin(&j);
        for (size_t q = 0; q < m[c].npeaks; q++) gal_json_num(&j, m[c].peaks[q].amplitude);
        gal_json_arr_end(&j);
        gal_json_kv_num(&j, "amplitude", m[c].amplitude);
        gal_json_kv_num(&j, "amplitude_pp", m[c].peak_to_peak);
        gal_json_kv_num(&j, "rms", m[c].rms);
        gal_json_kv_num(&j, "mean", m[c].mean);
        gal_json_kv_num(&j, "time_to_steady_s", tss[c]);
        gal_json_obj_end(&j);
    }
    gal_json_obj_end(&j);
    if (npairs > 0) {
        gal_json_key(&j, "orbit");
        gal_json_obj_begin(&j);
        json_orbit(&j, tr, &pairs[0]);
        gal_json_obj_end(&j);
    }
    gal_json_key(&j, "orbits");
    gal_json_arr_begin(&j);
    for (size_t q = 0; q < npairs; q++) {
        gal_json_obj_begin(&j);
        json_orbit(&j, tr, &pairs[q]);
        gal_json_obj_end(&j);
    }
    gal_json_arr_end(&j);
    gal_json_kv_num(&j, "wall_time_s", ri->wall);
    gal_json_end(&j);
    return gal_ofile_close(&f, 1);
}

static void print_table(const char *path, const gal_trace *tr, const int *sel, size_t nsel,
                        const gal_measures *m, const double *tss, const pair *pairs,
                        size_t npairs, const run_info *ri)
{
    printf("trace %s: %zu samples, dt %.6g s, steady part from %.6g s (%s), Welch %zu x %zu "
           "samples, df %.6g Hz\n", path, tr->n, tr->dt, tr->t[ri->i0],
           ri->auto_from ? "auto" : "--from", ri->nsegments, ri->nseg, ri->df);
    printf("%-20s %12s %12s %12s %12s %12s %12s\n", "column", "mean", "rms", "peak-to-peak",
           "f1 [Hz]", "f2 [Hz]", "t_steady [s]");
    for (size_t c = 0; c < nsel; c++) {
        char b[6][32];
        fmt(b[0], 32, m[c].mean);
        fmt(b[1], 32, m[c].rms);
        fmt(b[2], 32, m[c].peak_to_peak);
        fmt(b[3], 32, m[c].npeaks > 0 ? m[c].peaks[0].frequency : NAN);
        fmt(b[4], 32, m[c].npeaks > 1 ? m[c].peaks[1].frequency : NAN);
        fmt(b[5], 32, tss[c]);
        printf("%-20s %12s %12s %12s %12s %12s %12s\n", tr->names[sel[c]], b[0], b[1], b[2],
               b[3], b[4], b[5]);
    }
    for (size_t q = 0; q < npairs; q++)
        printf("orbit %s,%s: semi-axes %.6g and %.6g, tilt %.4g deg\n", tr->names[pairs[q].y],
               tr->names[pairs[q].z], pairs[q].orbit.major, pairs[q].orbit.minor,
               pairs[q].orbit.tilt_deg);
}

/* The analysis proper, once the trace is read and the columns chosen. */
static int analyse(const options *o, const gal_trace *tr, const int *sel, size_t nsel, pair *pairs,
                   size_t npairs, const char *outdir, double t_start)
{
    size_t n = tr->n;
    double dt = tr->dt;
    run_info ri = {0};
    double *env = malloc(n * sizeof *env), *tss = malloc(nsel * sizeof *tss);
    gal_measures *m = calloc(nsel, sizeof *m);
    double *psd = NULL;
    gal_hilbert *h = gal_spectrum_hilbert_alloc(n);
    gal_welch *w = NULL;
    int st = (!env || !tss || !m) ? gal_error(GAL_ENOMEM, "out of memory") : h ? GAL_OK : GAL_EFAIL;

    /* ---- time to steady of every column, from the envelope ---- */
    size_t imid = n / 2, iauto = 0;
    int any = 0;
    for (size_t c = 0; !st && c < nsel; c++) {
        double ts;
        st = gal_spectrum_envelope(h, tr->x[sel[c]], GAL_SPECTRUM_ENVELOPE_BAND, env);
        if (!st) st = gal_spectrum_steady_time(env, n, dt, 0.05, &ts, NULL);
        if (st) break;
        tss[c] = tr->t[0] + ts;
        if (isfinite(ts)) {
            size_t is = (size_t)llround(ts / dt);
            if (is > imid) is = imid;
            if (is > iauto) iauto = is;
            any = 1;
        }
    }
    /* ---- the steady part ---- */
    if (!st) {
        ri.auto_from = isnan(o->from);
        if (ri.auto_from) {
            ri.i0 = any ? iauto : imid;
            if (n - ri.i0 < GAL_TRACE_MIN_SAMPLES) ri.i0 = n - GAL_TRACE_MIN_SAMPLES;
        } else {
            double r = (o->from - tr->t[0]) / dt;
            if (r < -1e-6 || o->from > tr->t[n - 1])
                st = gal_error(GAL_EINPUT, "--from %g s is outside the trace (%g to %g s)",
                               o->from, tr->t[0], tr->t[n - 1]);
            else
                ri.i0 = r <= 0 ? 0 : (size_t)ceil(r - 1e-6);
        }
    }
    size_t ns = n - ri.i0;
    if (!st && ns < GAL_TRACE_MIN_SAMPLES)
        st = gal_error(GAL_EINPUT, "the steady part from %g s has %zu samples, at least %d needed",
                       tr->t[ri.i0], ns, GAL_TRACE_MIN_SAMPLES);
    if (!st) {
        ri.nseg = o->segment > 0 ? (size_t)o->segment : gal_spectrum_segment_choose(ns);
        if (ri.nseg > ns)
            st = gal_error(GAL_EINPUT, "--segment %zu is longer than the steady part (%zu samples)",
                           ri.nseg, ns);
        else if (ri.nseg * 200 < ns)
            fprintf(stderr, "gallop spectrum: warning: --segment %zu is below 1/200 of the steady "
                    "part (%zu samples): peak frequencies are coarse\n", ri.nseg, ns);
    }
    if (!st) {
        w = gal_spectrum_welch_alloc(ri.nseg);
        if (!w) st = GAL_EFAIL;
    }
    size_t nf = w ? gal_spectrum_welch_nfreq(w) : 0;
    if (!st && !(psd = malloc(nf * nsel * sizeof *psd))) st = gal_error(GAL_ENOMEM, "out of memory");
    /* ---- spectra and measures of the steady part ---- */
    for (size_t c = 0; !st && c < nsel; c++)
        st = gal_spectrum_measure(w, tr->x[sel[c]] + ri.i0, ns, dt, NPEAKS, psd + c * nf, &m[c]);
    for (size_t q = 0; !st && q < npairs; q++)
        st = gal_spectrum_orbit(tr->x[pairs[q].y] + ri.i0, tr->x[pairs[q].z] + ri.i0, ns,
                                &pairs[q].orbit);
    if (!st) {
        ri.nsegments = (ns - ri.nseg) / (ri.nseg / 2) + 1;
        ri.df = 1 / (ri.nseg * dt);
        ri.wall = gal_wall_time() - t_start;
        st = gal_mkdirs(outdir);
    }
    if (!st) st = write_psd(outdir, tr, sel, nsel, psd, nf, ri.df);
    if (!st) st = write_summary(outdir, o->path, tr, sel, nsel, m, tss, pairs, npairs, &ri);
    if (!st) print_table(o->path, tr, sel, nsel, m, tss, pairs, npairs, &ri);
    gal_spectrum_hilbert_free(h);
    gal_spectrum_welch_free(w);
    free(env);
    free(tss);
    free(m);
    free(psd);
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
    int *sel = NULL;
    pair *pairs = NULL;
    char *outdir = NULL;
    size_t nsel = 0, npairs = 0;
    int st = parse_args(argc, argv, &o);
    if (st == GAL_EINPUT) {
        fprintf(stderr, "gallop spectrum: %s\n%s", gal_error_message(), usage_text);
        free(o.columns);
        free(o.pairs);
        return 2;
    }
    if (!st) st = gal_trace_read(o.path, &tr);
    /* ---- columns and pairs ---- */
    if (!st) {
        sel = malloc((tr->ncol + o.ncolumns) * sizeof *sel);
        pairs = malloc((2 * (tr->ncol + o.ncolumns) + o.npairs + 1) * sizeof *pairs);
        if (!sel || !pairs) st = gal_error(GAL_ENOMEM, "out of memory");
    }
    for (size_t i = 0; !st && i < o.ncolumns; i++) {
        int c = gal_trace_column(tr, o.columns[i]);
        if (c < 0)
            st = gal_error(GAL_EINPUT, "%s: no column '%s' (time column '%s')", o.path,
                           o.columns[i], tr->time_name);
        else {
            size_t k = 0;
            while (k < nsel && sel[k] != c) k++;
            if (k == nsel) sel[nsel++] = c;   /* each column once */
        }
    }
    if (!st && o.ncolumns == 0)
        for (size_t c = 0; c < tr->ncol; c++) sel[nsel++] = (int)c;
    for (size_t i = 0; !st && i < o.npairs; i++) {
        const char *comma = strchr(o.pairs[i], ',');
        char name[512];
        size_t ly = comma ? (size_t)(comma - o.pairs[i]) : 0;
        if (!comma || ly == 0 || ly >= sizeof name || !comma[1]) {
            st = gal_error(GAL_EINPUT, "--pair '%s': two column names Y,Z are needed", o.pairs[i]);
            break;
        }
        memcpy(name, o.pairs[i], ly);
        name[ly] = '\0';
        int y = gal_trace_column(tr, name), z = gal_trace_column(tr, comma + 1);
        if (y < 0 || z < 0)
            st = gal_error(GAL_EINPUT, "--pair '%s': %s: no column '%s'", o.pairs[i], o.path,
                           y < 0 ? name : comma + 1);
        else
            pairs[npairs].y = y, pairs[npairs].z = z, npairs++;
    }
    if (!st && o.npairs == 0) npairs = auto_pairs(tr, sel, nsel, pairs);
    /* ---- output directory: -o, else next to the trace ---- */
    if (!st) {
        if (o.outdir) {
            outdir = strdup(o.outdir);
        } else {
            const char *slash = strrchr(o.path, '/');
            size_t ld = slash ? (size_t)(slash - o.path) : 0;
            outdir = malloc(ld + 16);
            if (outdir) {
                if (!slash) snprintf(outdir, ld + 16, "spectrum");
                else if (ld == 0) snprintf(outdir, ld + 16, "/spectrum");
                else snprintf(outdir, ld + 16, "%.*s/spectrum", (int)ld, o.path);
            }
        }
        if (!outdir) st = gal_error(GAL_ENOMEM, "out of memory");
    }
    if (!st) st = analyse(&o, tr, sel, nsel, pairs, npairs, outdir, t_start);
    gal_trace_free(tr);
    free(sel);
    free(pairs);
    free(outdir);
    free(o.columns);
    free(o.pairs);
    return st ? fail(st) : 0;
}
