/* probes.h: where a run looks at the span (not public): the probes, at fractions of the span, and
 * the tension of an element. */
#ifndef GALLOP_RUN_PROBES_H
#define GALLOP_RUN_PROBES_H

#include "gallop/rod/rod.h"

/* A probe at a fraction of the span: element e and weight xi along the unstretched length (node
 * quantities); edge-centre twist interpolation between edges e0 and e1 with weight w1. */
typedef struct gal_probe {
    int e, e0, e1;
    double xi, w1;
} gal_probe;

gal_probe gal_probe_locate(const gal_rod *rod, double frac);
/* One trace row: the displacements of the probes from the equilibrium (u, configuration-sized),
 * 4 per probe: horizontal (y), vertical (z), along (x) in m, twist in deg. */
void gal_probe_sample(const gal_rod *rod, const gal_probe *pa, int np, const double *u, double *row);
/* Axial tension of element j at q, N. */
double gal_probe_tension(const gal_rod *rod, const double *q, int j);

#endif
