/* compare.c: the figures of `gallop compare` (compare.h): both runs at every probe over the full
 * run's steady window, and per family the probe where the full model moves most. */
#include "gallop/analysis/compare.h"
#include "gallop/base/core.h"
#include "gallop/base/error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* the measures' component of each family: vertical, horizontal, twist */
static const int comp_of[GAL_CMP_FAMILIES] = {1, 0, 3};

static double relerr(double a, double b)
{
    return fabs(a - b) / fmax(fabs(b), 1e-300);
}

/* the relative error of the reduced peak-to-peak a against the full b of family f; NaN when the full
 * model does not move in that family (GAL_CMP_STILL_*) */
static double amplitude_err(double a, double b, int f)
{
    return fabs(b) < (f == GAL_CMP_TWIST ? GAL_CMP_STILL_DEG : GAL_CMP_STILL_M) ? NAN : relerr(a, b);
}

/* the probe of largest peak-to-peak in component comp among *m[0..n); mid-span unless another is
 * larger */
static int largest(const gal_sim_measures *const *m, int n, int mid, int comp)
{
    int best = mid;
    for (int k = 0; k < n; k++)
        if (m[k]->peak_to_peak[comp] > m[best]->peak_to_peak[comp]) best = k;
    return best;
}

/* the window: the full run's steady part at the probe of largest vertical motion */
static int window_from(const gal_sim_result *full, int mid, double *from)
{
    double best = -1;
    for (int k = 0; k < full->nprobe; k++) {
        gal_sim_measures m;
        int st = gal_sim_measure(full, k, -1, &m);
        if (st) return st;
        if (m.peak_to_peak[1] > best || (k == mid && m.peak_to_peak[1] >= best))
            best = m.peak_to_peak[1], *from = m.steady_from_s;
    }
    return GAL_OK;
}

/* peak-to-peak of component comp of probe k over samples [i0, i1) */
static double pp_of(const gal_sim_result *r, int k, int comp, long i0, long i1)
{
    double lo = INFINITY, hi = -INFINITY;
    for (long i = i0; i < i1; i++) {
        double x = r->trace[(size_t)i * 4 * r->nprobe + 4 * k + comp];
        lo = fmin(lo, x), hi = fmax(hi, x);
    }
    return i1 > i0 ? hi - lo : NAN;
}

/* the full run's steadiness over the window, each family at its headline probe (compare.h) */
static void window_drift(const gal_sim_result *full, gal_compare_figures *c)
{
    long n = full->nsamples, i0 = (long)floor(c->full.steady_from_s / full->dt_out + 0.5);
    if (i0 < 0) i0 = 0;
    if (i0 > n) i0 = n;
    long ih = i0 + (n - i0) / 2;
    c->full_steady = 1;
    for (int f = 0; f < GAL_CMP_FAMILIES; f++) {
        int k = c->headline[f];
        double a = pp_of(full, k, comp_of[f], i0, ih), b = pp_of(full, k, comp_of[f], ih, n);
        c->family_first[f] = a, c->family_second[f] = b;
        c->family_drift[f] = fabs(a - b) / fmax(fmax(a, b), 1e-300);
        double floor_abs = 0; /* what the limits allow besides the relative 5% */
        if (f == GAL_CMP_HORIZONTAL)
            floor_abs = GAL_CMP_STEADY_H_OF_V * fmax(c->family_first[GAL_CMP_VERTICAL], c->family_second[GAL_CMP_VERTICAL]);
        else if (f == GAL_CMP_TWIST) floor_abs = GAL_CMP_STEADY_TWIST_DEG;
        /* a NaN drift (an empty window) is not steady, as before */
        c->family_steady[f] = c->family_drift[f] <= GAL_CMP_STEADY_DRIFT || (f != GAL_CMP_VERTICAL && fabs(a - b) <= floor_abs);
        c->full_steady &= c->family_steady[f];
    }
    c->window_pp_first = c->family_first[GAL_CMP_VERTICAL], c->window_pp_second = c->family_second[GAL_CMP_VERTICAL];
    c->window_drift = c->family_drift[GAL_CMP_VERTICAL];
}

/* every figure of c over the window from `from` (< 0: the automatic one, window_from) */
static int compare_over(const gal_sim_result *full, const gal_sim_result *red, double from, gal_compare_figures *c)
{
    memset(c, 0, sizeof *c);
    if (full->nprobe != red->nprobe || full->nprobe < 1)
        return gal_error(GAL_EINPUT, "compare: the runs have %d and %d probes", full->nprobe, red->nprobe);
    int mid = gal_sim_mid_probe(full), st = GAL_OK;
    if (from < 0 && (st = window_from(full, mid, &from))) return st;
    c->nprobe = full->nprobe;
    for (int k = 0; k < c->nprobe && !st; k++) {
        gal_compare_probe *p = c->probe + k;
        p->position = full->probe[k];
        st = gal_sim_measure(full, k, from, &p->full);
        if (!st) st = gal_sim_measure(red, k, p->full.steady_from_s, &p->reduced);
        for (int f = 0; f < GAL_CMP_FAMILIES; f++)
            p->err[f] = amplitude_err(p->reduced.peak_to_peak[comp_of[f]], p->full.peak_to_peak[comp_of[f]], f);
        p->frequency_error = isnan(p->err[GAL_CMP_VERTICAL]) ? NAN
                                                              : relerr(p->reduced.frequency_hz[1], p->full.frequency_hz[1]);
    }
    if (st) return st;
    const gal_sim_measures *pm[GAL_MAX_PROBES];
    for (int k = 0; k < c->nprobe; k++) pm[k] = &c->probe[k].full;
    for (int f = 0; f < GAL_CMP_FAMILIES; f++) c->headline[f] = largest(pm, c->nprobe, mid, comp_of[f]);
    const gal_compare_probe *pv = c->probe + c->headline[GAL_CMP_VERTICAL];
    c->full = pv->full, c->reduced = pv->reduced;
    for (int f = GAL_CMP_HORIZONTAL; f < GAL_CMP_FAMILIES; f++) {
        const gal_compare_probe *p = c->probe + c->headline[f];
        int j = comp_of[f];
        c->full.frequency_hz[j] = p->full.frequency_hz[j], c->full.peak_to_peak[j] = p->full.peak_to_peak[j];
        c->reduced.frequency_hz[j] = p->reduced.frequency_hz[j], c->reduced.peak_to_peak[j] = p->reduced.peak_to_peak[j];
        c->full.dominant_hz[j] = p->full.dominant_hz[j], c->full.harmonic[j] = p->full.harmonic[j];
        c->reduced.dominant_hz[j] = p->reduced.dominant_hz[j], c->reduced.harmonic[j] = p->reduced.harmonic[j];
    }
    c->frequency_error = pv->frequency_error;
    c->err_vertical = pv->err[GAL_CMP_VERTICAL];
    c->err_horizontal = c->probe[c->headline[GAL_CMP_HORIZONTAL]].err[GAL_CMP_HORIZONTAL];
    c->err_twist = c->probe[c->headline[GAL_CMP_TWIST]].err[GAL_CMP_TWIST];
    c->amplitude_error = fmax(c->err_vertical, fmax(c->err_horizontal, c->err_twist));
    c->speedup = full->wall_time_s / red->wall_time_s;
    window_drift(full, c);
    c->window_first_from_s = c->full.steady_from_s;
    return GAL_OK;
}

int gal_compare_runs(const gal_sim_result *full, const gal_sim_result *red, double from, gal_compare_figures *c)
{
    int st = compare_over(full, red, from, c);
    if (st || from >= 0 || c->full_steady) return st;
    /* the automatic window, the reference unsteady over it: later starts, while each half of the
     * window holds GAL_CMP_WINDOW_PERIODS periods of the reference's vertical fundamental */
    double t0 = c->full.steady_from_s, tend = full->nsamples * full->dt_out, f = c->full.frequency_hz[1];
    gal_compare_figures *w = malloc(sizeof *w);
    if (!w) return gal_error(GAL_ENOMEM, "out of memory");
    for (int k = 1; k < GAL_CMP_WINDOW_TRIES && !st; k++) {
        double from_k = t0 + k * (tend - t0) / GAL_CMP_WINDOW_STEPS;
        if (!(f > 0) || 0.5 * (tend - from_k) * f < GAL_CMP_WINDOW_PERIODS) break;
        st = compare_over(full, red, from_k, w);
        if (!st && w->full_steady) {
            *c = *w;
            c->window_first_from_s = t0, c->window_moved = 1;
            break;
        }
    }
    free(w);
    return st;
}

int gal_compare_reference(const gal_sim_result *full, double from, gal_compare_ref *h)
{
    memset(h, 0, sizeof *h);
    if (full->nprobe < 1 || full->nprobe > GAL_MAX_PROBES)
        return gal_error(GAL_EINPUT, "compare: a run of %d probes", full->nprobe);
    gal_sim_measures m[GAL_MAX_PROBES];
    const gal_sim_measures *pm[GAL_MAX_PROBES];
    int mid = gal_sim_mid_probe(full), st = GAL_OK;
    if (from < 0 && (st = window_from(full, mid, &from))) return st;
    for (int k = 0; k < full->nprobe && !st; k++) st = gal_sim_measure(full, k, from, m + k), pm[k] = m + k;
    if (st) return st;
    for (int f = 0; f < GAL_CMP_FAMILIES; f++)
        h->headline[f] = largest(pm, full->nprobe, mid, comp_of[f]), h->position[f] = full->probe[h->headline[f]];
    h->from = m[0].steady_from_s;
    return GAL_OK;
}

int gal_compare_measure(const gal_sim_result *r, const gal_compare_ref *h, gal_sim_measures *m)
{
    int k = h->headline[GAL_CMP_VERTICAL], st = gal_sim_measure(r, k, h->from, m);
    for (int f = GAL_CMP_HORIZONTAL; f < GAL_CMP_FAMILIES && !st; f++) {
        if (h->headline[f] == k) continue;
        gal_sim_measures o;
        int j = comp_of[f];
        if ((st = gal_sim_measure(r, h->headline[f], h->from, &o))) break;
        m->frequency_hz[j] = o.frequency_hz[j], m->dominant_hz[j] = o.dominant_hz[j], m->harmonic[j] = o.harmonic[j];
        m->peak_to_peak[j] = o.peak_to_peak[j], m->rms[j] = o.rms[j], m->mean[j] = o.mean[j];
    }
    return st;
}
