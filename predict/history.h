/* history.h - fixed-capacity ring buffer of timestamped poses (sensor samples).
 *
 * Like Monado's relation history: samples must arrive with strictly
 * increasing timestamps; a sample at or before the newest one is dropped
 * (and counted) rather than reordered, because a late sample cannot be
 * trusted to belong to the same tracking stream. */
#ifndef TRIMVR_PRED_HISTORY_H
#define TRIMVR_PRED_HISTORY_H

#include "pose.h"

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define PRED_HISTORY_CAPACITY 512 /* 0.5 s at 1 kHz: more than any fit window */

typedef struct pred_history {
    pred_pose items[PRED_HISTORY_CAPACITY];
    int newest; /* index of the newest sample */
    int count;
    uint64_t dropped; /* non-monotonic samples rejected */
} pred_history;

/* Empties the history (zeroing the struct does the same). */
void pred_history_clear(pred_history* h);

/* Appends a sample, overwriting the oldest when full. Returns false (and
 * counts a drop) when sample->t is not after the newest sample's time. */
bool pred_history_push(pred_history* h, const pred_pose* sample);

/* Sample `age` steps back from the newest (age 0 = newest); 0 <= age < count. */
const pred_pose* pred_history_get(const pred_history* h, int age);

/* Pose at time t interpolated between the two samples around it (lerp and
 * slerp); false when t lies outside the held time span. */
bool pred_history_interpolate(const pred_history* h, double t, pred_pose* out);

#ifdef __cplusplus
}
#endif

#endif
