/* predictor.h - head-pose predictors behind one interface.
 *
 *   cv      constant velocity: least-squares line through the samples of the
 *           last window_s seconds (position per axis, orientation as rotation
 *           vectors relative to the newest sample), extrapolated. What Monado
 *           and SteamVR do.
 *   ca      constant acceleration: the same with a parabola.
 *   kalman  a Kalman filter per channel with a constant-velocity model driven
 *           by white acceleration noise; orientation as an error state on the
 *           rotation vector with angular velocity.
 * Equations and measured errors: docs/prediction.md. */
#ifndef TRIMVR_PRED_PREDICTOR_H
#define TRIMVR_PRED_PREDICTOR_H

#include "history.h"

#include <stdbool.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum pred_kind {
    PRED_KIND_CV = 0,
    PRED_KIND_CA = 1,
    PRED_KIND_KALMAN = 2,
    PRED_KIND_COUNT
} pred_kind;

/* Zero means default. */
typedef struct pred_predictor_desc {
    pred_kind kind;
    double window_s;         /* fit window: 0.025 s for cv, 0.06 s for ca */
    double kf_accel_psd;     /* kalman: white-acceleration spectral density, 0.1 m^2/s^3 */
    double kf_angaccel_psd;  /* kalman: same for rotation, 10 rad^2/s^3 */
    double kf_pos_sigma;     /* kalman: measurement noise, 0.0002 m */
    double kf_rot_sigma_deg; /* kalman: measurement noise, 0.02 deg */
} pred_predictor_desc;

/* One filter channel group: values (3 axes) and rates sharing one 2x2
 * covariance, since all axes see the same noise and time steps. */
typedef struct pred_kf_group {
    double rate[3];
    double P[2][2];
} pred_kf_group;

typedef struct pred_predictor {
    pred_predictor_desc desc; /* defaults resolved */
    pred_history history;
    /* kalman state at time kf_t */
    bool kf_started;
    double kf_t;
    double kf_p[3], kf_q[4];
    pred_kf_group kf_pos, kf_rot;
} pred_predictor;

/* "cv", "ca", "kalman" <-> kind. pred_kind_from_name returns false for an unknown name. */
const char* pred_kind_name(pred_kind kind);
bool pred_kind_from_name(const char* name, pred_kind* kind);

void pred_predictor_init(pred_predictor* p, const pred_predictor_desc* desc);

/* Feeds one sensor sample; false (sample ignored) when its time is not after
 * the previous sample's. */
bool pred_predictor_update(pred_predictor* p, const pred_pose* sample);

/* Predicted pose at absolute time t (horizon = t - newest sample time; t may
 * also lie in the past). False before the first sample. */
bool pred_predictor_predict(const pred_predictor* p, double t, pred_pose* out);

#ifdef __cplusplus
}
#endif

#endif
