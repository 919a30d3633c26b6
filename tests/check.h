/* check.h: the test harness. Each tests/test_<module>.c is one program made of test functions;
 * a test passes when none of its CHECKs failed. The program prints one line per test and a
 * "#summary P F" line that tests/run.sh adds up. */
#ifndef GALLOP_CHECK_H
#define GALLOP_CHECK_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int check_passed, check_failed, check_current_failed;
static const char *check_current;

/* Assert a condition; on failure print where and a message, and mark the test failed. */
#define CHECK(cond, ...)                                                                  \
    do {                                                                                  \
        if (!(cond)) {                                                                    \
            printf("    %s:%d: check failed: %s: ", __FILE__, __LINE__, #cond);          \
            printf(__VA_ARGS__);                                                          \
            printf("\n");                                                                 \
            check_current_failed = 1;                                                     \
        }                                                                                 \
    } while (0)

/* |a - b| <= tol, printing both values. */
#define CHECK_NEAR(a, b, tol)                                                                  \
    do {                                                                                       \
        double ca_ = (a), cb_ = (b), ct_ = (tol);                                             \
        if (!(fabs(ca_ - cb_) <= ct_)) {                                                       \
            printf("    %s:%d: %s = %.12g, %s = %.12g, |diff| %.3g > %.3g\n", __FILE__,        \
                   __LINE__, #a, ca_, #b, cb_, fabs(ca_ - cb_), ct_);                          \
            check_current_failed = 1;                                                          \
        }                                                                                      \
    } while (0)

/* |a - b| <= rtol |b| */
#define CHECK_REL(a, b, rtol)                                                                  \
    do {                                                                                       \
        double ca_ = (a), cb_ = (b), ct_ = (rtol);                                            \
        if (!(fabs(ca_ - cb_) <= ct_ * fabs(cb_))) {                                           \
            printf("    %s:%d: %s = %.12g, %s = %.12g, rel. diff %.3g > %.3g\n", __FILE__,     \
                   __LINE__, #a, ca_, #b, cb_, fabs(ca_ - cb_) / fabs(cb_), ct_);              \
            check_current_failed = 1;                                                          \
        }                                                                                      \
    } while (0)

#define RUN(fn)                                                                   \
    do {                                                                          \
        check_current = #fn;                                                      \
        check_current_failed = 0;                                                 \
        fn();                                                                     \
        if (check_current_failed) check_failed++, printf("  FAIL %s\n", #fn);     \
        else check_passed++, printf("  ok   %s\n", #fn);                          \
        fflush(stdout);                                                           \
    } while (0)

#define CHECK_SUMMARY()                                                    \
    (printf("#summary %d %d\n", check_passed, check_failed), check_failed ? 1 : 0)

#endif
