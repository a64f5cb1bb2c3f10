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

#ifdef __cplusplus
}
#endif

#endif
