/* rom_redo.c: a growth's replayed samples laid over a run's record (rom_adapt.h gal_rom_redo). */
#include "gallop/reduced/rom_adapt.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void gal_rom_redo_init(gal_rom_redo *r, int nprobe, const double *probe, int want_taut)
{
    memset(r, 0, sizeof *r);
    r->nprobe = nprobe, r->probe = probe, r->want_taut = want_taut, r->taut = 1;
}

void gal_rom_redo_observe(void *ctx, const gal_rom *m, long i)
{
    gal_rom_redo *r = ctx;
    long w = 4L * r->nprobe + 2;
    if (i == 0) r->n = 0, r->taut = 1, r->failed = 0;
    if (r->failed) return;
    if (i >= r->cap) {
        long cap = 2 * i + 64;
        double *p = realloc(r->row, (size_t)cap * w * sizeof(double));
        if (!p) { r->failed = 1; return; }
        r->row = p, r->cap = cap;
    }
    double *row = r->row + (size_t)i * w;
    gal_rom_observe(m, r->nprobe, r->probe, row, row + 4 * r->nprobe);
    if (r->want_taut) r->taut = fmin(r->taut, gal_rom_taut_share(m));
    if (i + 1 > r->n) r->n = i + 1;
}

long gal_rom_redo_apply(gal_rom_redo *r, long i, double *trace, double *tension)
{
    int np = r->nprobe;
    long w = 4L * np + 2, k = 0;
    for (; k < r->n && k < i && !r->failed; k++) {
        memcpy(trace + (size_t)k * 4 * np, r->row + (size_t)k * w, (size_t)4 * np * sizeof(double));
        memcpy(tension + 2 * k, r->row + (size_t)k * w + 4 * np, 2 * sizeof(double));
    }
    r->n = 0, r->failed = 0;
    return k;
}

void gal_rom_redo_clear(gal_rom_redo *r)
{
    free(r->row);
    r->row = NULL, r->n = r->cap = 0;
}
