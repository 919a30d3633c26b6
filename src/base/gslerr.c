/* gslerr.c: GSL's errors as gallop errors: GSL's default handler aborts the process; the one
 * installed here records the error as the calling thread's gallop message (GAL_EFAIL) and
 * returns, so the GSL function returns its error code and the library reports it (error.h). */
#include "gallop/base/error.h"

#include <stdatomic.h>

#include <gsl/gsl_errno.h>

static void handler(const char *reason, const char *file, int line, int gsl_errno)
{
    gal_error(GAL_EFAIL, "GSL: %s (%s, %s:%d)", reason ? reason : "error", gsl_strerror(gsl_errno),
              file ? file : "?", line);
}

void gal_gsl_errors_install(void)
{
    static atomic_int installed;
    if (atomic_exchange(&installed, 1)) return;
    gsl_set_error_handler(handler);
}
