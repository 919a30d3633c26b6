/* numfmt.h: printf's "%.9g" and "%d" without printf's per-number cost, for the large CSVs (the
 * modes' shapes.csv): the same characters as printf for every double, checked in
 * tests/test_numfmt.c against snprintf. */
#ifndef GALLOP_NUMFMT_H
#define GALLOP_NUMFMT_H

/* Writes x as "%.9g" at buf (room for 24 characters), no terminator; returns the length. */
int gal_fmt_g9(char *buf, double x);
/* Writes i as "%d"; returns the length. */
int gal_fmt_int(char *buf, int i);

#endif
