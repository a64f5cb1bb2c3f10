/* demo_head.h - the demo's head: a walking camera steered by keyboard and
 * mouse (yaw about world +Y, pitch about the head's +X, no roll), in the
 * pose conventions of predict/pose.h. Pure C and window-system free, so the
 * controls are unit-testable. */
#ifndef TRIMVR_APP_DEMO_HEAD_H
#define TRIMVR_APP_DEMO_HEAD_H

#include "pose.h"

#include <stdbool.h>

/* One frame's input: held keys and the mouse travel (pixels) while looking. */
typedef struct tv_head_input {
    bool forward, back, left, right, up, down;
    bool fast;              /* x4 speed while held */
    double look_dx, look_dy; /* +x turns right, +y looks down */
} tv_head_input;

typedef struct tv_head {
    double p[3];
    double yaw, pitch; /* radians, pred_quat_from_ypr's convention */
    double speed;      /* m/s */
    double home_p[3], home_yaw, home_pitch;
} tv_head;

#define TV_HEAD_DEFAULT_SPEED 1.4       /* walking, m/s */
#define TV_HEAD_LOOK_RAD_PER_PIXEL 0.003
#define TV_HEAD_MAX_PITCH 1.50          /* just short of straight up/down */

/* Starts (and sets the reset pose) at `start`; its roll is dropped. */
void tv_head_init(tv_head* h, const pred_pose* start);

/* Moves for dt seconds: forward/back/left/right in the horizontal plane of
 * the current yaw (walking, not flying), up/down along world +Y; then turns. */
void tv_head_step(tv_head* h, const tv_head_input* in, double dt);

/* Back to the start pose and speed. */
void tv_head_reset(tv_head* h);

/* Multiplies the speed by factor, kept within [0.05, 50] m/s. */
void tv_head_scale_speed(tv_head* h, double factor);

/* The current pose, stamped with time t. */
void tv_head_pose(const tv_head* h, double t, pred_pose* out);

#endif
