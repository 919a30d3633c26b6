/* accreport.h: the outputs of `gallop accuracy`: accuracy.csv, summary.json, a table. */
#ifndef GALLOP_OUTPUT_ACCREPORT_H
#define GALLOP_OUTPUT_ACCREPORT_H

#include <stdio.h>

#include "gallop/analysis/accuracy.h"
#include "gallop/scene/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* DIR/accuracy.csv (study,setting,value,error,wall_time_s,chosen) and DIR/summary.json. */
int gal_accuracy_write(const char *dir, const gal_scene *sc, const gal_acc_result *r);
/* A table on fp. */
void gal_accuracy_print(FILE *fp, const gal_acc_result *r);

#ifdef __cplusplus
}
#endif

#endif
