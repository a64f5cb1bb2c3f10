#define _POSIX_C_SOURCE 200809L /* mkdtemp */
/* Unit tests of base/: percentiles (used for every reported median/p99) and
 * the log sink (tests capture validation messages through it). */
#include "fs.h"
#include "log.h"
#include "stats.h"
#include "test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static void test_percentile_known_values(void)
{
    const double v[] = {5, 1, 4, 2, 3};
    TV_CHECK_NEAR(tv_percentile(v, 5, 50), 3.0, 0);
    TV_CHECK_NEAR(tv_percentile(v, 5, 0), 1.0, 0);
    TV_CHECK_NEAR(tv_percentile(v, 5, 100), 5.0, 0);
    TV_CHECK_NEAR(tv_percentile(v, 5, 25), 2.0, 0);
    TV_CHECK_NEAR(tv_percentile(v, 5, 90), 4.6, 1e-12); /* rank 3.6 between 4 and 5 */
    TV_CHECK(v[0] == 5 && v[4] == 3); /* input untouched */
    TV_CHECK(isnan(tv_percentile(v, 0, 50)));
    TV_CHECK_NEAR(tv_mean(v, 5), 3.0, 1e-12);
}

static void test_percentile_with_infinity(void)
{
    /* PSNR of identical frames is +inf: medians must stay meaningful */
    const double v[] = {INFINITY, 40, INFINITY, 50};
    TV_CHECK_NEAR(tv_percentile(v, 4, 0), 40.0, 0);
    TV_CHECK(isinf(tv_percentile(v, 4, 100)));
    TV_CHECK(isinf(tv_percentile(v, 4, 75)));
    TV_CHECK_NEAR(tv_percentile(v, 4, 100.0 / 3.0), 50.0, 1e-9);
}

typedef struct captured {
    int count;
    tv_log_level level;
    char text[128];
} captured;

static void capture(tv_log_level level, const char* message, void* user)
{
    captured* c = user;
    c->count++;
    c->level = level;
    snprintf(c->text, sizeof c->text, "%s", message);
}

static void test_log_sink_and_level(void)
{
    captured c = {0};
    tv_log_set_sink(capture, &c);
    tv_log_set_level(TV_LOG_INFO);
    tv_log(TV_LOG_DEBUG, "hidden %d", 1);
    TV_CHECK(c.count == 0);
    tv_log(TV_LOG_WARN, "value %d", 42);
    TV_CHECK(c.count == 1 && c.level == TV_LOG_WARN && strcmp(c.text, "value 42") == 0);
    tv_log_set_sink(NULL, NULL);
}

static void test_mkdirs(void)
{
    char base[] = "/tmp/tv_fs_XXXXXX";
    TV_CHECK(mkdtemp(base) != NULL);
    char deep[256];
    snprintf(deep, sizeof deep, "%s/a/b/c", base);
    TV_CHECK(tv_mkdirs(deep));
    TV_CHECK(tv_mkdirs(deep)); /* existing folder is fine */
    struct stat st;
    TV_CHECK(stat(deep, &st) == 0 && S_ISDIR(st.st_mode));
    char file[256];
    snprintf(file, sizeof file, "%s/f", base);
    FILE* f = fopen(file, "w");
    TV_CHECK(f != NULL);
    if (f)
        fclose(f);
    char under_file[300];
    snprintf(under_file, sizeof under_file, "%s/x", file);
    TV_CHECK(!tv_mkdirs(under_file)); /* a path through a regular file fails */
    TV_CHECK(!tv_mkdirs(file));
}

/* Student t quantiles against published tables (4 decimals), and both
 * intervals on samples small enough to work by hand. */
static void test_confidence_intervals(void)
{
    TV_CHECK_NEAR(tv_t975(1), 12.7062, 0);
    TV_CHECK_NEAR(tv_t975(4), 2.7764, 0);
    TV_CHECK_NEAR(tv_t975(31), 2.0395, 1e-4);
    TV_CHECK_NEAR(tv_t975(40), 2.0211, 1e-4);
    TV_CHECK_NEAR(tv_t975(60), 2.0003, 1e-4);
    TV_CHECK_NEAR(tv_t975(120), 1.9799, 1e-4);
    TV_CHECK(isnan(tv_t975(0)));
    /* 1..5: mean 3, s^2 = 10 / 4, half-width 2.7764 sqrt(2.5 / 5) */
    const double v[5] = {1, 2, 3, 4, 5};
    TV_CHECK_NEAR(tv_mean_ci95(v, 5), 2.7764 * sqrt(0.5), 1e-12);
    TV_CHECK(isnan(tv_mean_ci95(v, 1)));
    /* x exactly proportional to y: no spread of the ratio */
    const double x[3] = {2, 4, 6}, y[3] = {1, 2, 3};
    TV_CHECK_NEAR(tv_ratio_ci95(x, y, 3), 0.0, 1e-12);
    /* constant y = 2: the ratio's interval is the mean's over 2 */
    const double x4[4] = {1, 2, 3, 6}, two[4] = {2, 2, 2, 2}, zero[4] = {0, 0, 0, 0};
    TV_CHECK_NEAR(tv_ratio_ci95(x4, two, 4), tv_mean_ci95(x4, 4) / 2.0, 1e-12);
    TV_CHECK_NEAR(tv_mean_ci95(x4, 4), 3.1824 * sqrt(14.0 / 3.0 / 4.0), 1e-12);
    TV_CHECK(isnan(tv_ratio_ci95(x4, zero, 4)));
}

int main(void)
{
    TV_TEST_RUN(test_confidence_intervals);
    TV_TEST_RUN(test_percentile_known_values);
    TV_TEST_RUN(test_percentile_with_infinity);
    TV_TEST_RUN(test_log_sink_and_level);
    TV_TEST_RUN(test_mkdirs);
    return tv_test_finish();
}
