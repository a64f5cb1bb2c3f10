/* error_tracker.h - online prediction-error statistics per horizon.
 *
 * For each horizon the caller registers predictions (pose predicted for a
 * target time) and feeds the measured samples; when a sample at or after a
 * prediction's target time arrives, the truth at the target time is
 * interpolated between the last two samples and the position error (m) and
 * rotation error (deg) are recorded. Errors can also be recorded directly
 * (offline evaluation against a known path).
 *
 * Quantiles are exact over a sliding window of the most recent `window`
 * errors (a sorted copy kept by insertion, O(window) per record): exact,
 * simple to test, and it adapts to the motion of the last seconds, which is
 * what an adaptive viewcell wants. The maximum is over all records. Quantile q
 * is the nearest-rank value: the ceil(q*n)-th smallest of the n in the window. */
#ifndef TRIMVR_PRED_ERROR_TRACKER_H
#define TRIMVR_PRED_ERROR_TRACKER_H

#include "pose.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define PRED_MAX_HORIZONS 16

/* Zero means default: horizons 10, 20, ..., 100 ms; window 4096 errors. */
typedef struct pred_error_tracker_desc {
    int horizon_count;
    double horizons_s[PRED_MAX_HORIZONS]; /* strictly increasing, > 0 */
    int window;
} pred_error_tracker_desc;

/* A sliding window of values with a sorted copy. */
typedef struct pred_error_window {
    double* ring;   /* insertion order */
    double* sorted; /* ascending */
    int count, next;
    double max;
    uint64_t total;
} pred_error_window;

typedef struct pred_error_pending {
    pred_pose* items; /* predictions waiting for their target time, FIFO */
    int head, count, cap;
} pred_error_pending;

typedef struct pred_error_tracker {
    int horizon_count;
    double horizons_s[PRED_MAX_HORIZONS];
    int window;
    pred_error_window pos[PRED_MAX_HORIZONS], rot[PRED_MAX_HORIZONS];
    pred_error_pending pending[PRED_MAX_HORIZONS];
    bool have_last;
    pred_pose last; /* newest observed sample */
} pred_error_tracker;

typedef struct pred_error_stats {
    uint64_t count; /* all records, not only the window */
    double p50, p95, p99, max;
} pred_error_stats;

/* Returns false (tracker unusable, nothing allocated) on invalid horizons or
 * out of memory. */
bool pred_error_tracker_init(pred_error_tracker* tr, const pred_error_tracker_desc* desc);
void pred_error_tracker_free(pred_error_tracker* tr);

/* Registers the prediction for horizon `h` (index); predicted->t is its
 * target time. Predictions of one horizon must come in target-time order. */
bool pred_error_tracker_push(pred_error_tracker* tr, int h, const pred_pose* predicted);

/* Feeds a measured sample: resolves every pending prediction whose target
 * time is at or before sample->t (and after the previous sample's). */
void pred_error_tracker_observe(pred_error_tracker* tr, const pred_pose* sample);

/* Records one error pair for horizon h directly. */
void pred_error_tracker_record(pred_error_tracker* tr, int h, double pos_err_m, double rot_err_deg);

/* Nearest-rank quantile q in (0, 1] of the windowed errors of horizon h; 0
 * when nothing was recorded. */
double pred_error_tracker_quantile_pos(const pred_error_tracker* tr, int h, double q);
double pred_error_tracker_quantile_rot(const pred_error_tracker* tr, int h, double q);

/* Quantile q of the errors at an arbitrary horizon: linear between the
 * tracked horizons around it; beyond the last one scaled by (horizon/last)^2,
 * the growth of an extrapolation error under constant acceleration. Below the
 * first horizon: the first horizon's value (conservative). */
void pred_error_tracker_bound(const pred_error_tracker* tr, double horizon_s, double q,
                              double* pos_m, double* rot_deg);

void pred_error_tracker_stats(const pred_error_tracker* tr, int h, pred_error_stats* pos,
                              pred_error_stats* rot);

#ifdef __cplusplus
}
#endif

#endif
