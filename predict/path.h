/* path.h - head-motion paths: CSV load/save and interpolated sampling.
 *
 * File format (docs/paths.md): CSV; lines starting with '#' are comments
 * anywhere, blank lines are ignored; the first other line is a header naming
 * the columns t,px,py,pz,qx,qy,qz,qw in any order (all required, no others).
 * t is in seconds and strictly increasing, position in metres, orientation a
 * unit quaternion (normalised on load; a norm outside [0.5, 2] is an error).
 * Metadata comments "# scene: <spec>" and "# description: <text>" are kept. */
#ifndef TRIMVR_PRED_PATH_H
#define TRIMVR_PRED_PATH_H

#include "pose.h"

#include <stdbool.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pred_path {
    pred_pose* poses; /* count samples, strictly increasing t; owned */
    size_t count;
    char scene[128];       /* from "# scene:", empty when absent */
    char description[256]; /* from "# description:", empty when absent */
} pred_path;

/* Positions beyond this many metres from the origin are refused: the
 * renderer's float coordinates have no centimetres left there. */
#define PRED_PATH_MAX_COORD_M 1e6

/* Times beyond this many seconds from 0 are refused: a double keeps less than
 * 2 us there, and a 1 ms sensor step from 1e15 s on does not advance the
 * clock (a replay never ends). */
#define PRED_PATH_MAX_TIME_S 1e10

/* Loads `file` into `out` (zeroed first). On failure returns false, leaves
 * `out` empty and writes one line "FILE:LINE: problem" (or "FILE: problem"
 * when no line applies) into err. At least one sample is required. */
bool pred_path_load(const char* file, pred_path* out, char* err, size_t err_size);

/* Writes `path` to `file`: the metadata lines, `extra_comment` (may be NULL;
 * each of its '\n'-separated lines becomes a "# " comment), the header and one
 * row per pose (t and position to 1 us / 1 um, quaternion to 1e-9). A save
 * followed by a load reproduces every value within 1e-6. */
bool pred_path_save(const pred_path* path, const char* file, const char* extra_comment,
                    char* err, size_t err_size);

/* Releases the poses and zeroes the path. Safe on a zeroed path. */
void pred_path_free(pred_path* path);

/* Appends a pose, growing path->poses geometrically; *capacity is the
 * allocated count (0 for a path not yet allocated). False when out of
 * memory (the path is left as it was). */
bool pred_path_append(pred_path* path, size_t* capacity, const pred_pose* pose);

/* Pose at time t: position lerp and shortest-arc slerp between the two
 * surrounding samples, clamped to the first/last sample outside the path's
 * time span; out->t = t. O(log n). Requires path->count >= 1. */
void pred_path_sample(const pred_path* path, double t, pred_pose* out);

/* `in` sampled every 1/rate_hz seconds from its first sample time to its
 * last (pred_path_sample), into `out` (zeroed first; metadata copied). False
 * with a one-line message when rate_hz is not positive or out of memory.
 * Requires in->count >= 1. */
bool pred_path_resample(const pred_path* in, double rate_hz, pred_path* out, char* err, size_t err_size);

/* Last sample time minus first sample time (0 for one sample). */
double pred_path_duration(const pred_path* path);

/* Mean speed (m/s) over the sample intervals moving at min_speed or faster:
 * their summed position steps over their summed durations. min_speed = 0
 * gives distance over duration; a small positive value leaves out stops
 * (walks stop to turn around). 0 when no interval qualifies. */
double pred_path_mean_speed(const pred_path* path, double min_speed);

#ifdef __cplusplus
}
#endif

#endif
