/* trace_spectrum.c: the spectral analysis of a whole trace (trace_spectrum.h): times to steady,
 * the steady part, Welch spectra and measures of every column, orbits of the pairs. */
#include "gallop/analysis/trace_spectrum.h"
#include "gallop/base/core.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void gal_trace_spectrum_clear(gal_trace_spectrum *s)
{
    free(s->sel);
    free(s->m);
    free(s->tss);
    free(s->psd);
    free(s->pairs);
    memset(s, 0, sizeof *s);
}

/* Time to steady of every column from its envelope (trace time in s->tss); *iauto: the latest
 * one as a sample index, but not after the middle of the record; *any: one was found. */
static int steady_times(const gal_trace *tr, gal_trace_spectrum *s, size_t *iauto, int *any)
{
    size_t n = tr->n, imid = n / 2;
    double *env = malloc(n * sizeof *env);
    gal_hilbert *h = gal_spectrum_hilbert_alloc(n);
    int st = !env ? gal_error(GAL_ENOMEM, "out of memory") : h ? GAL_OK : GAL_EFAIL;
    *iauto = 0, *any = 0;
    for (size_t c = 0; !st && c < s->nsel; c++) {
        double ts;
        st = gal_spectrum_envelope(h, tr->x[s->sel[c]], GAL_SPECTRUM_ENVELOPE_BAND, env);
        if (!st) st = gal_spectrum_steady_time(env, n, tr->dt, 0.05, &ts, NULL);
        if (st) break;
        s->tss[c] = tr->t[0] + ts;
        if (isfinite(ts)) {
            size_t is = (size_t)llround(ts / tr->dt);
            if (is > imid) is = imid;
            if (is > *iauto) *iauto = is;
            *any = 1;
        }
    }
    gal_spectrum_hilbert_free(h);
    free(env);
    return st;
}

/* The steady part (s->i0) and the Welch segment (s->nseg). */
static int steady_part(const gal_trace *tr, double from, long segment, size_t iauto, int any,
                       gal_trace_spectrum *s)
{
    size_t n = tr->n;
    double dt = tr->dt;
    s->auto_from = isnan(from);
    if (s->auto_from) {
        s->i0 = any ? iauto : n / 2;
        if (n - s->i0 < GAL_TRACE_MIN_SAMPLES) s->i0 = n - GAL_TRACE_MIN_SAMPLES;
    } else {
        double r = (from - tr->t[0]) / dt;
        if (r < -1e-6 || from > tr->t[n - 1])
            return gal_error(GAL_EINPUT, "--from %g s is outside the trace (%g to %g s)", from, tr->t[0],
                             tr->t[n - 1]);
        s->i0 = r <= 0 ? 0 : (size_t)ceil(r - 1e-6);
    }
    size_t ns = n - s->i0;
    if (ns < GAL_TRACE_MIN_SAMPLES)
        return gal_error(GAL_EINPUT, "the steady part from %g s has %zu samples, at least %d needed",
                         tr->t[s->i0], ns, GAL_TRACE_MIN_SAMPLES);
    s->nseg = segment > 0 ? (size_t)segment : gal_spectrum_segment_choose(ns);
    if (s->nseg > ns)
        return gal_error(GAL_EINPUT, "--segment %zu is longer than the steady part (%zu samples)", s->nseg, ns);
    s->coarse = s->nseg * 200 < ns;
    return GAL_OK;
}

/* Spectra and measures of the steady part, orbits of the pairs. */
static int spectra(const gal_trace *tr, gal_trace_spectrum *s)
{
    size_t ns = tr->n - s->i0;
    gal_welch *w = gal_spectrum_welch_alloc(s->nseg);
    if (!w) return GAL_EFAIL;
    s->nf = gal_spectrum_welch_nfreq(w);
    int st = GAL_OK;
    if (!(s->psd = malloc(s->nf * s->nsel * sizeof *s->psd))) st = gal_error(GAL_ENOMEM, "out of memory");
    for (size_t c = 0; !st && c < s->nsel; c++)
        st = gal_spectrum_measure(w, tr->x[s->sel[c]] + s->i0, ns, tr->dt, GAL_TRACE_NPEAKS, s->psd + c * s->nf,
                                  &s->m[c]);
    for (size_t q = 0; !st && q < s->npairs; q++)
        st = gal_spectrum_orbit(tr->x[s->pairs[q].y] + s->i0, tr->x[s->pairs[q].z] + s->i0, ns,
                                &s->pairs[q].orbit);
    if (!st) {
        s->nsegments = (ns - s->nseg) / (s->nseg / 2) + 1;
        s->df = 1 / (s->nseg * tr->dt);
    }
    gal_spectrum_welch_free(w);
    return st;
}

int gal_trace_spectrum_run(const gal_trace *tr, const int *sel, size_t nsel, const gal_trace_pair *pairs,
                           size_t npairs, double from, long segment, gal_trace_spectrum *s)
{
    memset(s, 0, sizeof *s);
    s->nsel = nsel, s->npairs = npairs;
    s->sel = malloc((nsel ? nsel : 1) * sizeof *s->sel);
    s->tss = malloc((nsel ? nsel : 1) * sizeof *s->tss);
    s->m = calloc(nsel ? nsel : 1, sizeof *s->m);
    s->pairs = malloc((npairs ? npairs : 1) * sizeof *s->pairs);
    if (!s->sel || !s->tss || !s->m || !s->pairs) return gal_error(GAL_ENOMEM, "out of memory");
    if (nsel) memcpy(s->sel, sel, nsel * sizeof *sel);
    if (npairs) memcpy(s->pairs, pairs, npairs * sizeof *pairs);
    size_t iauto;
    int any;
    int st = steady_times(tr, s, &iauto, &any);
    if (!st) st = steady_part(tr, from, segment, iauto, any, s);
    if (!st) st = spectra(tr, s);
    return st;
}

static int ends_with(const char *s, const char *suffix, size_t *prefix)
{
    size_t ls = strlen(s), lx = strlen(suffix);
    if (ls <= lx || strcmp(s + ls - lx, suffix)) return 0;
    *prefix = ls - lx;
    return 1;
}

size_t gal_trace_auto_pairs(const gal_trace *tr, const int *sel, size_t nsel, gal_trace_pair *pairs)
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
