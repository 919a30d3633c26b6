/* core.c: status and error messages, timing. */
#define _POSIX_C_SOURCE 200809L
#include "gallop/base/core.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

static char errbuf[2048];

const char *gal_error_message(void) { return errbuf[0] ? errbuf : "unknown error"; }

int gal_error(int status, const char *fmt, ...)
{
    char tmp[sizeof errbuf]; /* the arguments may include the current message */
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(tmp, sizeof tmp, fmt, ap);
    va_end(ap);
    memcpy(errbuf, tmp, sizeof errbuf);
    return status;
}

void gal_error_clear(void) { errbuf[0] = '\0'; }

int gal_exit_code(int status)
{
    if (status == GAL_OK) return 0;
    if (status == GAL_EINPUT || status == GAL_EIO) return 2;
    return 1;
}

double gal_wall_time(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
