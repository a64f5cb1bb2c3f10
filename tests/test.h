/* test.h - minimal assertion macros shared by all C tests.
 *
 * A test executable calls TV_TEST_RUN(fn) for each case and returns
 * tv_test_finish(); a failed check prints file:line and the expression,
 * marks the case failed and continues with the next check. With TV_TEST_ONLY
 * set in the environment, only the cases whose name contains it run. A case
 * that cannot run (data absent) calls TV_TEST_SKIP; the program then exits
 * 77, which ctest counts as skipped, unless a check failed. */
#ifndef TRIMVR_TEST_H
#define TRIMVR_TEST_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int tv_test_failures;
static int tv_test_case_failed;
static int tv_test_passed_cases;
static int tv_test_failed_cases;
static int tv_test_skipped_cases;

#define TV_TEST_SKIP(why)                      \
    do {                                       \
        printf("  skip: %s\n", (why));        \
        tv_test_skipped_cases++;               \
    } while (0)

#define TV_CHECK(expr)                                                              \
    do {                                                                            \
        if (!(expr)) {                                                              \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #expr); \
            tv_test_failures++;                                                     \
            tv_test_case_failed = 1;                                                \
        }                                                                           \
    } while (0)

#define TV_CHECK_NEAR(a, b, tol)                                                          \
    do {                                                                                  \
        double tv_a_ = (double)(a), tv_b_ = (double)(b);                                  \
        if (!(fabs(tv_a_ - tv_b_) <= (double)(tol))) {                                    \
            fprintf(stderr, "%s:%d: check failed: %s = %.9g, %s = %.9g, tolerance %g\n",  \
                    __FILE__, __LINE__, #a, tv_a_, #b, tv_b_, (double)(tol));             \
            tv_test_failures++;                                                           \
            tv_test_case_failed = 1;                                                      \
        }                                                                                 \
    } while (0)

#define TV_TEST_RUN(fn)                                      \
    do {                                                     \
        const char* tv_only_ = getenv("TV_TEST_ONLY");       \
        if (tv_only_ && !strstr(#fn, tv_only_))              \
            break;                                           \
        int tv_skipped_before_ = tv_test_skipped_cases;      \
        tv_test_case_failed = 0;                             \
        fn();                                                \
        int tv_skipped_ = tv_test_skipped_cases > tv_skipped_before_; \
        tv_test_skipped_cases = tv_skipped_before_;          \
        if (tv_skipped_ && !tv_test_case_failed) {           \
            tv_test_skipped_cases++;                         \
            printf("skip %s\n", #fn);                        \
        } else if (tv_test_case_failed) {                    \
            tv_test_failed_cases++;                          \
            fprintf(stderr, "FAIL %s\n", #fn);               \
        } else {                                             \
            tv_test_passed_cases++;                          \
            printf("ok   %s\n", #fn);                        \
        }                                                    \
    } while (0)

static inline int tv_test_finish(void)
{
    printf("%d passed, %d failed, %d skipped\n", tv_test_passed_cases, tv_test_failed_cases, tv_test_skipped_cases);
    return tv_test_failures ? 1 : tv_test_skipped_cases ? 77 : 0;
}

#endif
