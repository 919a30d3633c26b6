/* trace_spectrum.h: the spectral analysis of a whole trace (DESIGN.md "Spectra and galloping
 * measures", `gallop spectrum`), built on spectrum.h:
 *   envelope and time to steady of every chosen column (whole record) -> the steady part
 *   [from, end], or automatic: from the latest time to steady of the columns but not after the
 *   middle of the record (and at least GAL_TRACE_MIN_SAMPLES samples) -> Welch PSD, peaks and
 *   amplitudes of the steady part -> orbit ellipses of the (horizontal, vertical) pairs. */
#ifndef GALLOP_TRACE_SPECTRUM_H
#define GALLOP_TRACE_SPECTRUM_H

#include <stddef.h>

#include "gallop/analysis/spectrum.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GAL_TRACE_NPEAKS 5   /* peaks reported per column */

/* A horizontal (y) and vertical (z) data column of a trace and their orbit ellipse. */
typedef struct gal_trace_pair {
    int y, z;
    gal_orbit orbit;
} gal_trace_pair;

typedef struct gal_trace_spectrum {
    size_t nsel;
    int *sel;               /* owned: the data columns analysed */
    gal_measures *m;        /* owned: nsel measures of the steady part */
    double *tss;            /* owned: nsel trace times (s) from which the envelope stays within 5%
                             * of its final level; NaN for a constant column */
    size_t nf;              /* Welch bins */
    double *psd;            /* owned: nsel x nf, unit^2/Hz */
    double df;              /* Hz */
    size_t npairs;
    gal_trace_pair *pairs;  /* owned: the pairs with their orbits */
    size_t i0;              /* first sample of the steady part */
    size_t nseg, nsegments; /* Welch segment (samples) and segments averaged */
    int auto_from;          /* 1: the steady part was found, 0: given */
    int coarse;             /* the segment is below 1/200 of the steady part: coarse peaks */
} gal_trace_spectrum;

/* Analyse columns sel[0..nsel) and pairs[0..npairs) of tr. from: start of the steady part (trace
 * time, s), NaN for automatic; segment: Welch segment in samples, 0 for
 * gal_spectrum_segment_choose. GAL_EINPUT (message naming --from or --segment) when `from` is
 * outside the trace, the steady part is too short or the segment longer than it. *s is filled
 * (free with gal_trace_spectrum_clear, also after a failure). */
int gal_trace_spectrum_run(const gal_trace *tr, const int *sel, size_t nsel, const gal_trace_pair *pairs,
                           size_t npairs, double from, long segment, gal_trace_spectrum *s);
void gal_trace_spectrum_clear(gal_trace_spectrum *s);

/* Pairs named <p>_y/<p>_z or <p>_horizontal/<p>_vertical among the columns sel[0..nsel), in the
 * order of the y columns; pairs must hold 2 nsel. Returns their number. */
size_t gal_trace_auto_pairs(const gal_trace *tr, const int *sel, size_t nsel, gal_trace_pair *pairs);

#ifdef __cplusplus
}
#endif

#endif
