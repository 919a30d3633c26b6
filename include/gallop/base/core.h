/* core.h: status codes, error reporting and small utilities shared by every module. */
#ifndef GALLOP_CORE_H
#define GALLOP_CORE_H

#include <stdio.h>
#include <stddef.h>

#define GAL_PI 3.14159265358979323846

/* One status enum for the whole library: 0 success, negative failure. */
typedef enum {
    GAL_OK = 0,
    GAL_EINPUT = -1,  /* bad input: scene, table, option (exit 2) */
    GAL_EFAIL = -2,   /* the computation failed: no convergence, lost stability, NaN (exit 1) */
    GAL_ENOMEM = -3,  /* out of memory (exit 1) */
    GAL_EIO = -4      /* a file could not be read or written (exit 2 when reading input) */
} gal_status;

/* The last error message (library code sets it, main prints it). */
const char *gal_error_message(void);
/* Set the message (printf format) and return `status` so that callers can `return gal_error(...)`. */
int gal_error(int status, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
void gal_error_clear(void);
/* Process exit status for a library status: 0, 1 (computation), 2 (input). */
int gal_exit_code(int status);

/* Wall-clock seconds from an arbitrary origin (monotonic). */
double gal_wall_time(void);

#endif
