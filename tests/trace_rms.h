/* trace_rms.h: the RMS difference of two runs' traces over a window, relative to the reference's
 * own RMS about its mean there (test_rom_order and tests/bench/diag_order: the observed order of a
 * time step). */
#ifndef GALLOP_TESTS_TRACE_RMS_H
#define GALLOP_TESTS_TRACE_RMS_H

#include <math.h>

#include "gallop/run/sim.h"

/* RMS of a - b over [t0, t1] for trace column c at probe 0, over b's RMS about its mean there */
static inline double rms_error(const gal_sim_result *a, const gal_sim_result *b, int c, double t0, double t1)
{
    int w = 4 * b->nprobe;
    long n = 0;
    double mean = 0, e = 0, s = 0;
    for (long i = 0; i < b->nsamples && i < a->nsamples; i++)
        if (b->time[i] >= t0 && b->time[i] <= t1) mean += b->trace[i * w + c], n++;
    if (n == 0) return NAN;
    mean /= (double)n;
    for (long i = 0; i < b->nsamples && i < a->nsamples; i++) {
        if (!(b->time[i] >= t0 && b->time[i] <= t1)) continue;
        double x = a->trace[i * w + c], y = b->trace[i * w + c];
        e += (x - y) * (x - y), s += (y - mean) * (y - mean);
    }
    return sqrt(e / s);
}

#endif
