/* core.h: what every module shares: status codes and errors (error.h) and pi. Output files and
 * the JSON writer are the output stage's (gallop/output/ofile.h, gallop/output/json.h). */
#ifndef GALLOP_CORE_H
#define GALLOP_CORE_H

#include <stdio.h>
#include <stddef.h>

#include "gallop/base/error.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GAL_PI 3.14159265358979323846

#ifdef __cplusplus
}
#endif

#endif
