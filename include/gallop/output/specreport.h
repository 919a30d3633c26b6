/* specreport.h: the outputs of `gallop spectrum`: summary.json, psd.csv and a table.
 * summary.json: trace, time_column, samples, dt_s, steady_from_s, steady_from_rule ("auto" or
 * "option --from"), steady_samples, segment, segments, frequency_resolution_hz; columns: an
 * object per column with frequency_hz (null when none), peaks_hz, peak_amplitudes, amplitude (of
 * the dominant sine), amplitude_pp, rms, mean, time_to_steady_s (trace time from which the
 * envelope reaches its final band, spectrum.h gal_spectrum_steady_time; null for a constant
 * column or one still growing); peaks: only lines 10 dB above the local noise floor; orbit (the first
 * pair: y, z, major_semi_axis, minor_semi_axis, tilt_deg) when there is a pair, orbits (all
 * pairs); wall_time_s. psd.csv: frequency_hz then one PSD column (unit^2/Hz) per column, named
 * <column>2_per_hz for a unit suffix _m, _deg, _n, _rad (p0.5_vertical_m2_per_hz), else <column>_psd. */
#ifndef GALLOP_OUTPUT_SPECREPORT_H
#define GALLOP_OUTPUT_SPECREPORT_H

#include <stdio.h>

#include "gallop/analysis/trace_spectrum.h"

#ifdef __cplusplus
extern "C" {
#endif

/* DIR/psd.csv and DIR/summary.json of the analysis s of the trace tr read from trace_path. */
int gal_trace_spectrum_write(const char *dir, const char *trace_path, const gal_trace *tr,
                             const gal_trace_spectrum *s, double wall_time_s);
/* The table of `gallop spectrum`: one line per column, one per orbit. */
void gal_trace_spectrum_print(FILE *fp, const char *trace_path, const gal_trace *tr, const gal_trace_spectrum *s);

#ifdef __cplusplus
}
#endif

#endif
