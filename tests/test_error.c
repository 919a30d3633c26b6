/* test_error.c: status and error messages (src/base/error.c): the exit status of each status, a
 * message that quotes the current one, and one message per thread (two threads setting
 * different errors each read their own). */
#include "check.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>
#include "gallop.h"

#include <pthread.h>

static void test_exit_codes(void)
{
    CHECK(gal_exit_code(GAL_OK) == 0, "ok");
    CHECK(gal_exit_code(GAL_EINPUT) == 2, "input");
    CHECK(gal_exit_code(GAL_EIO) == 2, "io");
    CHECK(gal_exit_code(GAL_EFAIL) == 1, "fail");
    CHECK(gal_exit_code(GAL_ENOMEM) == 1, "nomem");
}

static void test_message(void)
{
    gal_error_clear();
    CHECK(!strcmp(gal_error_message(), "unknown error"), "%s", gal_error_message());
    CHECK(gal_error(GAL_EINPUT, "inner %d", 7) == GAL_EINPUT, "status returned");
    CHECK(gal_error(GAL_EFAIL, "outer: %s", gal_error_message()) == GAL_EFAIL, "status");
    CHECK(!strcmp(gal_error_message(), "outer: inner 7"), "%s", gal_error_message());
    CHECK(gal_error_status() == GAL_EFAIL, "status kept with the message: %d", gal_error_status());
    gal_error(GAL_ENOMEM, "out of memory");
    CHECK(gal_error_status() == GAL_ENOMEM, "status kept with the message: %d", gal_error_status());
    gal_error_clear();
    CHECK(!strcmp(gal_error_message(), "unknown error"), "%s", gal_error_message());
    CHECK(gal_error_status() == GAL_OK, "cleared: %d", gal_error_status());
}

enum { NTHREADS = 2, ROUNDS = 20000 };

typedef struct {
    int id;
    pthread_barrier_t *start;
    int wrong;          /* rounds in which the thread read another's message */
    int fresh;          /* a new thread starts without a message */
} worker;

static void *work(void *arg)
{
    worker *w = arg;
    char want[64];
    w->fresh = !strcmp(gal_error_message(), "unknown error");
    pthread_barrier_wait(w->start); /* both threads set and read at the same time */
    for (int r = 0; r < ROUNDS; r++) {
        snprintf(want, sizeof want, "thread %d round %d", w->id, r);
        gal_error(GAL_EFAIL, "thread %d round %d", w->id, r);
        if (strcmp(gal_error_message(), want)) w->wrong++;
    }
    return NULL;
}

static void test_per_thread(void)
{
    gal_error(GAL_EINPUT, "main thread");
    pthread_barrier_t start;
    pthread_barrier_init(&start, NULL, NTHREADS);
    pthread_t th[NTHREADS];
    worker w[NTHREADS];
    for (int i = 0; i < NTHREADS; i++) {
        w[i] = (worker){.id = i + 1, .start = &start};
        CHECK(pthread_create(&th[i], NULL, work, &w[i]) == 0, "thread %d", i);
    }
    for (int i = 0; i < NTHREADS; i++) pthread_join(th[i], NULL);
    pthread_barrier_destroy(&start);
    for (int i = 0; i < NTHREADS; i++) {
        CHECK(w[i].fresh, "thread %d started with another thread's message", w[i].id);
        CHECK(w[i].wrong == 0, "thread %d read another's message in %d of %d rounds", w[i].id,
              w[i].wrong, ROUNDS);
    }
    CHECK(!strcmp(gal_error_message(), "main thread"), "the main thread's message became '%s'",
          gal_error_message());
}

/* issue 14: a GSL error is a gallop error (GAL_EFAIL, the reason in the message), never an
 * abort: GSL's default handler would kill this program here. */
static void test_gsl_errors(void)
{
    gal_gsl_errors_install();
    gal_gsl_errors_install(); /* idempotent */
    gal_error_clear();
    double x[4] = {0, 2, 1, 3}, y[4] = {0, 1, 2, 3}; /* x not increasing: GSL_EINVAL */
    gsl_interp *s = gsl_interp_alloc(gsl_interp_linear, 4);
    CHECK(s != NULL, "gsl_interp_alloc");
    int st = gsl_interp_init(s, x, y, 4);
    CHECK(st == GSL_EINVAL, "gsl_interp_init returned %d", st);
    CHECK(strstr(gal_error_message(), "GSL: ") != NULL, "%s", gal_error_message());
    gsl_interp_free(s);
}

int main(void)
{
    RUN(test_gsl_errors);
    RUN(test_exit_codes);
    RUN(test_message);
    RUN(test_per_thread);
    return CHECK_SUMMARY();
}
