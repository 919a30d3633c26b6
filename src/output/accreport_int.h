/* accreport_int.h: what the accuracy outputs share (accreport.c, accreport_front.c). */
#ifndef GALLOP_ACCREPORT_INT_H
#define GALLOP_ACCREPORT_INT_H

#include <stdio.h>

#include "gallop/analysis/accuracy.h"
#include "gallop/output/json.h"
#include "gallop/output/outset.h"

/* DIR/front.csv of the front study */
int gal_acc_front_csv(gal_outset *o, const gal_acc_result *r);
/* the "front" object of summary.json */
void gal_acc_front_json(gal_json *j, const gal_acc_result *r);
/* the front study's table */
void gal_acc_front_print(FILE *fp, const gal_acc_result *r);

#endif
