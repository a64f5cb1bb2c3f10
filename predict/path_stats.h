/* path_stats.h - motion statistics of a head-motion path (trimvr path info).
 *
 * Speeds are per sample interval (position step or rotation angle over the
 * interval's duration), the "instantaneous" speeds of ../shared/traces'
 * README; every interval counts once whatever its length. */
#ifndef TRIMVR_PRED_PATH_STATS_H
#define TRIMVR_PRED_PATH_STATS_H

#include "path.h"

#include <stdbool.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pred_path_stats {
    size_t samples;
    double duration_s;
    double dt_median_s, dt_max_s;
    double speed_mean, speed_p50, speed_p99;             /* m/s; mean = distance / duration */
    double ang_speed_mean, ang_speed_p50, ang_speed_p99; /* deg/s; mean = total angle / duration */
    double forward_y_mean_abs;                           /* mean |y| of the forward vector: 0 = level gaze */
} pred_path_stats;

/* False with a one-line message when the path has fewer than two samples or
 * memory runs out. */
bool pred_path_stats_compute(const pred_path* path, pred_path_stats* out, char* err, size_t err_size);

#ifdef __cplusplus
}
#endif

#endif
