/* error.c: error messages (one per thread), exit status of a status, wall-clock time. */
#define _POSIX_C_SOURCE 200809L
#include "gallop/base/error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

/* one message per thread (C11): a thread that fails reads its own message, whatever the others do */
static _Thread_local char errbuf[2048];
static _Thread_local int errstatus; /* the status that came with the message */

const char *gal_error_message(void) { return errbuf[0] ? errbuf : "unknown error"; }

int gal_error(int status, const char *fmt, ...)
{
    char tmp[sizeof errbuf]; /* the arguments may include the current message */
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(tmp, sizeof tmp, fmt, ap);
    va_end(ap);
    memcpy(errbuf, tmp, sizeof errbuf);
    errstatus = status;
    return status;
}

void gal_error_clear(void) { errbuf[0] = '\0', errstatus = GAL_OK; }

int gal_error_status(void) { return errstatus; }

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
