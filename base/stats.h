/* stats.h - small statistics over samples (timings, errors, PSNR). */
#ifndef TRIMVR_STATS_H
#define TRIMVR_STATS_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The p-th percentile (0..100) of values[0..count) by linear interpolation
 * between closest ranks; values is not modified. NaN when count is 0.
 * +inf entries sort last (PSNR of identical images). */
double tv_percentile(const double* values, size_t count, double p);

/* Arithmetic mean; NaN when count is 0. */
double tv_mean(const double* values, size_t count);

/* The two-sided 95 % quantile of Student's t with df degrees of freedom,
 * t(0.975, df): tabulated to 4 decimals up to df 30, beyond that the
 * Cornish-Fisher series in 1/df (error under 1e-4). NaN for df < 1. */
double tv_t975(int df);

/* Half-width of the 95 % t-interval of the mean of values[0..count):
 * t(0.975, count - 1) s / sqrt(count), s the sample standard deviation.
 * NaN when count < 2. */
double tv_mean_ci95(const double* values, size_t count);

/* Half-width of the 95 % interval of a ratio of means R = sum(x) / sum(y)
 * over paired samples, by linearisation (the ratio estimator's standard
 * error, Cochran, Sampling Techniques, 1977, section 6.3):
 * t(0.975, count - 1) sqrt(sum (x_i - R y_i)^2 / (count (count - 1))) / mean(y).
 * NaN when count < 2 or mean(y) is 0. */
double tv_ratio_ci95(const double* x, const double* y, size_t count);

#ifdef __cplusplus
}
#endif

#endif
