/* error.h: the library's status codes, its error messages (library code sets one, the caller
 * prints it), the exit status of a status, and a wall clock. */
#ifndef GALLOP_ERROR_H
#define GALLOP_ERROR_H

#ifdef __cplusplus
extern "C" {
#endif

/* One status enum for the whole library: 0 success, negative failure. */
typedef enum {
    GAL_OK = 0,
    GAL_EINPUT = -1,  /* bad input: scene, table, option (exit 2) */
    GAL_EFAIL = -2,   /* the computation failed: no convergence, lost stability, NaN (exit 1) */
    GAL_ENOMEM = -3,  /* out of memory (exit 1) */
    GAL_EIO = -4      /* a file could not be read or written (exit 2 when reading input) */
} gal_status;

/* The last error message of the calling thread (library code sets it, main prints it); "unknown
 * error" when the thread has set none. Each thread has its own message. */
const char *gal_error_message(void);
/* Set the calling thread's message (printf format; the arguments may include the current
 * message) and return `status` so that callers can `return gal_error(...)`. */
int gal_error(int status, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
void gal_error_clear(void);
/* The status that came with the calling thread's last message (GAL_OK after gal_error_clear):
 * for constructors, which return NULL, so that the caller passes the real status on. */
int gal_error_status(void);
/* Process exit status for a library status: 0, 1 (computation), 2 (input). */
int gal_exit_code(int status);

/* Make GSL's errors gallop errors (GAL_EFAIL with GSL's reason as the thread's message) instead
 * of GSL's default, which aborts the process. Idempotent; the library calls it where it first
 * uses GSL (scene loading, aerodynamic tables, wind fields): the library never aborts. It replaces
 * GSL's process-wide handler: a program that sets its own calls gsl_set_error_handler after. */
void gal_gsl_errors_install(void);

/* Wall-clock seconds from an arbitrary origin (monotonic). */
double gal_wall_time(void);

#ifdef __cplusplus
}
#endif

#endif
