/* trace_place.h - putting a recorded trace into a scene.
 *
 * Recorded traces have arbitrary origins and headings (HoloLens: the start
 * pose; Quest: relative to the start; OptiTrack: the capture volume's floor
 * and axes). A placement moves and turns the whole trace rigidly, a
 * rotation about +Y followed by a translation, so its shape, speeds and the
 * prediction errors on it are unchanged:
 *
 *   reference    the trace's start sample (position and forward direction),
 *                or its centroid and mean horizontal forward direction;
 *   anchor       where the reference point lands horizontally (x, z);
 *   heading      the yaw the reference forward direction gets, in degrees
 *                counter-clockwise seen from above, 0 looking down -Z and
 *                90 down -X (pred_quat_from_ypr's yaw);
 *   height       without eye_height_m the reference point lands at anchor y;
 *                with it the trace's median head height lands eye_height_m
 *                above anchor y (anchor on the floor); height_offset_m is
 *                added in both cases. */
#ifndef TRIMVR_PRED_TRACE_PLACE_H
#define TRIMVR_PRED_TRACE_PLACE_H

#include "path.h"

#include <stdbool.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum pred_place_ref {
    PRED_PLACE_START = 0,
    PRED_PLACE_CENTROID
} pred_place_ref;

/* Zero is the identity for a trace that starts at the origin looking down -Z. */
typedef struct pred_placement {
    double anchor[3];
    double heading_deg;
    pred_place_ref ref;
    double eye_height_m;    /* > 0: median head height above anchor y */
    double height_offset_m;
} pred_placement;

/* The reference point and the yaw (radians, heading convention above) of the
 * reference forward direction. The yaw is 0 when the forward direction is
 * vertical (start) or the horizontal forwards cancel (centroid).
 * Requires path->count >= 1. */
void pred_trace_reference(const pred_path* path, pred_place_ref ref, double point[3], double* yaw);

/* Median head height (position y) over the samples. Requires count >= 1. */
double pred_trace_median_height(const pred_path* path);

/* Applies `pl` to every sample of `path` in place. False (path untouched) only
 * when out of memory for the median height. */
bool pred_trace_place(pred_path* path, const pred_placement* pl);

/* "placement: anchor=X,Y,Z heading=DEG ref=start|centroid eye-height=M
 * height-offset=M" for the path file's comment; returns snprintf's count. */
int pred_placement_format(const pred_placement* pl, char* buf, size_t size);

#ifdef __cplusplus
}
#endif

#endif
