/* cli/blas.c: how many threads the BLAS may start (a deliberate choice, README "BLAS threads").
 * gallop's matrices are sparse (CHOLMOD) and its dense BLAS work is small, so one BLAS thread
 * costs little time, and an OpenBLAS thread pool has a failure mode gallop cannot accept: under a
 * memory limit (ulimit -v) its threads' buffers fail to allocate and the process hangs at exit
 * in blas_memory_alloc instead of exiting with gallop's "out of memory". So gallop uses ONE BLAS
 * thread unless GALLOP_BLAS_THREADS says otherwise (or OPENBLAS_NUM_THREADS is set by the user).
 * OpenBLAS reads OPENBLAS_NUM_THREADS when it is loaded, before main, and starts its threads
 * then (setting the count later need not stop them). So main re-executes gallop once
 * (/proc/self/exe) with OPENBLAS_NUM_THREADS set; if that fails, openblas_set_num_threads (a weak
 * symbol: absent with another BLAS) is the fallback.
 * One thread is not enough under a memory limit: OpenBLAS maps a 128 MB buffer per thread on its
 * first large call and, when the mapping fails, retries forever (measured: ulimit -v 250000,
 * 20000 elements, stuck in dgemv_ from ARPACK). So, when the address space is limited, main
 * checks that the limit leaves room for that buffer (else exit 1, a message about memory) and
 * makes the BLAS map it at once (one matrix-vector product large enough to need it): later calls
 * reuse it, and gallop's own allocations fail cleanly ("out of memory", exit 1). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include "cli.h"

void openblas_set_num_threads(int n) __attribute__((weak));
void dgemv_(const char *trans, const int *m, const int *n, const double *alpha, const double *a, const int *lda,
            const double *x, const int *incx, const double *beta, double *y, const int *incy);

#define BLAS_BUFFER_MB 160.0   /* OpenBLAS's buffer (128 MB) and a margin */

/* the thread count asked for: GALLOP_BLAS_THREADS (1 to 256), else 1 */
static int wanted(void)
{
    const char *g = getenv("GALLOP_BLAS_THREADS");
    char *end;
    long v = g ? strtol(g, &end, 10) : 1;
    if (!g || end == g || *end || v < 1 || v > 256) v = 1;
    return (int)v;
}

void gal_cli_blas_threads(char **argv)
{
    if (getenv("OPENBLAS_NUM_THREADS")) return;   /* the user's (or our re-execution's) choice */
    char buf[8];
    int n = wanted();
    snprintf(buf, sizeof buf, "%d", n);
    if (setenv("OPENBLAS_NUM_THREADS", buf, 1) == 0) execv("/proc/self/exe", argv);
    /* no re-execution: at least the calls run on n threads */
    if (openblas_set_num_threads) openblas_set_num_threads(n);
}

/* the address space the limit leaves, MB (infinite when there is no limit) */
static double headroom_mb(void)
{
    struct rlimit rl;
    if (getrlimit(RLIMIT_AS, &rl) != 0 || rl.rlim_cur == RLIM_INFINITY) return 1e300;
    long pages = 0, page = sysconf(_SC_PAGESIZE);
    FILE *fp = fopen("/proc/self/statm", "r");
    if (fp) {
        if (fscanf(fp, "%ld", &pages) != 1) pages = 0;
        fclose(fp);
    }
    return ((double)rl.rlim_cur - (double)pages * (double)page) / 1048576.0;
}

int gal_cli_blas_reserve(void)
{
    double room = headroom_mb();
    if (room >= 1e299) return 0;
    if (room < BLAS_BUFFER_MB) {
        fprintf(stderr, "gallop: out of memory: the address-space limit (ulimit -v) leaves %.0f MB, the BLAS "
                "needs about %.0f MB; raise the limit\n", room, BLAS_BUFFER_MB);
        return 1;
    }
    enum { M = 1024 };   /* large enough for OpenBLAS to take its buffer, not its stack */
    static double a[M], x[1] = {1}, y[M];
    const int m = M, n = 1, one = 1;
    const double alpha = 1, beta = 0;
    dgemv_("N", &m, &n, &alpha, a, &m, x, &one, &beta, y, &one);
    return 0;
}
