/* path_synth.h - synthetic head-motion paths (walks, runs, seated look-arounds).
 *
 * Deterministic: the same desc (seed included) gives bitwise the same path.
 * docs/paths.md describes the motion model; docs/prediction.md why it looks
 * like this (head-turn rates of real users). */
#ifndef TRIMVR_PRED_PATH_SYNTH_H
#define TRIMVR_PRED_PATH_SYNTH_H

#include "path.h"

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define PRED_SYNTH_MAX_WAYPOINTS 64

typedef enum pred_synth_kind {
    /* Walk (or run) along a polyline of ground waypoints: corners become
     * circular fillets (continuous velocity); corners sharper than
     * stop_turn_deg become a stop, a turn on the spot and a restart. The head
     * yaw follows the walking direction plus a sinusoidal oscillation and
     * occasional look-arounds (out, hold, back); the eye height bobs at the
     * step frequency. */
    PRED_SYNTH_WALK = 0,
    /* Seated look-around at waypoints[0]: tiny positional sway, and a
     * sequence of fast yaw/pitch sweeps whose peak rate is drawn from
     * [peak_rate_min_deg, peak_rate_max_deg]. */
    PRED_SYNTH_LOOKAROUND = 1,
} pred_synth_kind;

/* Zero means default for every number; a negative amplitude disables that
 * motion component. */
typedef struct pred_synth_desc {
    pred_synth_kind kind;
    int waypoint_count;                            /* >= 2 for WALK, >= 1 for LOOKAROUND */
    double waypoints[PRED_SYNTH_MAX_WAYPOINTS][2]; /* ground x, z (metres) */
    double floor_y;                                /* 0 */
    double eye_height;                             /* 1.7 m above the floor */
    double sample_rate;                            /* 100 Hz */
    uint64_t seed;                                 /* 0 is a valid seed */

    /* WALK */
    double speed;                  /* 1.4 m/s cruising speed */
    double accel_time;             /* 1.0 s smooth (cosine) ramp from rest to speed and back */
    double corner_radius;          /* 1.0 m fillet radius (shrunk to fit short segments) */
    double stop_turn_deg;          /* 150: sharper corners stop and turn on the spot */
    double turn_rate_deg;          /* 120 deg/s peak body turn when stopped */
    double yaw_osc_amplitude_deg;  /* 8 deg sinusoidal head yaw around the walking direction */
    double yaw_osc_period;         /* 3.5 s */
    double look_interval;          /* 5 s mean gap between look-arounds */
    double look_amplitude_deg;     /* 60 deg maximum look-around yaw */
    double look_hold;              /* 0.6 s at the turned-away position */
    double bob_amplitude;          /* 0.02 m vertical bob at full speed */
    double step_frequency;         /* 1.9 Hz steps (one bob per step) */

    /* LOOKAROUND */
    double duration;               /* 15 s */
    double base_yaw_deg;           /* 0: looks down -Z; sweeps are around this */
    double sway_amplitude;         /* 0.015 m */
    double yaw_range_deg;          /* 110: yaw targets in [-range, range] */
    double pitch_min_deg;          /* -35 */
    double pitch_max_deg;          /* 25 */
    double hold_min, hold_max;     /* 0.3 s, 1.2 s between sweeps */

    /* both kinds: peak angular rate of each sweep / look-around */
    double peak_rate_min_deg;      /* 150 deg/s */
    double peak_rate_max_deg;      /* 250 deg/s */

    const char* scene;       /* copied into the path's scene field; may be NULL */
    const char* description; /* copied into the path's description; may be NULL */
} pred_synth_desc;

/* Designated initialisers of a run (the bundled runs, automatic runs):
 * 3 m/s, a bigger bob at a higher step rate, and fewer, smaller
 * look-arounds than walks (runners watch where they go). */
#define PRED_SYNTH_RUN_GAIT .speed = 3.0, .step_frequency = 2.8, .bob_amplitude = 0.035, \
                            .look_interval = 7.0, .look_amplitude_deg = 35.0

/* Synthesises a path into `out` (zeroed first; free with pred_path_free).
 * Returns false with a one-line message for invalid input (too few
 * waypoints, repeated waypoints, non-positive speed, ...). */
bool pred_path_synth(const pred_synth_desc* desc, pred_path* out, char* err, size_t err_size);

#ifdef __cplusplus
}
#endif

#endif
