/* viewcell.h - double-cone viewcell and widened PVS frustum from predictions.
 *
 * A PVS requested at t_r is used during [t_r + L, t_r + L + W]. The viewcell
 * is the double cone of the Trim Regions paper (section 3.4): base disc of
 * radius delta through v0 perpendicular to `forward`, apexes v0 -+ z*forward
 * with z = delta / tan(alpha). The PVS is computed from the rear apex
 * v* = `apex` through a square frustum of full angle fov_pvs = 2*alpha (both
 * horizontally and vertically) about `forward`, rolled to `up`.
 *
 * An eye is covered when it lies inside the double cone and its (rectangular)
 * view frustum lies inside that square PVS frustum; docs/prediction.md
 * derives the sizing so that every predicted eye of the window is covered,
 * with margins for the tracked prediction errors and for how far a head can
 * physically deviate from its current motion within the horizon.
 *
 * When the rotation the window must allow exceeds what one frustum of at most
 * max_fov_pvs can hold, the viewcell covers every direction instead
 * (frusta = PRED_VC_OMNI_FRUSTA): six cube-face frusta of half-angle
 * PRED_VC_OMNI_HALF_DEG about +-forward, +-right, +-up, each with its own
 * double cone around v0, all of them containing the ball of radius
 * delta cos(alpha) that holds every eye of the window. The PVS is the union
 * of the per-frustum PVSs (pred_viewcell_frustum gives frustum i). */
#ifndef TRIMVR_PRED_VIEWCELL_H
#define TRIMVR_PRED_VIEWCELL_H

#include "error_tracker.h"
#include "predictor.h"

#include <stdbool.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum pred_policy {
    PRED_POLICY_FIXED = 0,    /* delta and fov_pvs as given */
    PRED_POLICY_ADAPTIVE = 1, /* from the predicted motion plus error quantiles */
} pred_policy;

/* Zero means default. */
typedef struct pred_viewcell_desc {
    pred_policy policy;
    double latency_s;        /* L: 0.05 s */
    double window_s;         /* W: 0.05 s */
    int samples;             /* predicted poses over the window: 9 */
    float display_fov_h_deg; /* per-eye display FOV: 60 (the paper's target) */
    float display_fov_v_deg; /* 60 */
    float ipd_m;             /* 0.063 */
    float fixed_delta_m;     /* FIXED: 0.10 m */
    float fixed_fov_pvs_deg; /* FIXED: 90 */
    float quantile;          /* ADAPTIVE: 0.99 of the tracked errors */
    float min_delta_m;       /* ADAPTIVE: 0.02 m */
    /* ADAPTIVE: the largest cell a PVS is computed for. A sizing that needs a
     * larger delta, or an apex (z = delta / tan alpha behind v0) farther than
     * max_apex_offset_m, gives the whole scene as the PVS instead of a smaller
     * cell (whole_scene): a slow PVS costs size, never holes.
     * max_delta_m 0: 5 m (the largest delta at which tr was measured
     * conservative, docs/prediction.md); max_apex_offset_m 0: no limit (the
     * replay sets pvs_max_apex_offset, the PVS depth buffer's limit). */
    float max_delta_m;
    float max_apex_offset_m;
    float min_fov_pvs_deg;   /* ADAPTIVE: the larger display angle */
    float max_fov_pvs_deg;   /* ADAPTIVE: 150 */
    /* ADAPTIVE warm-up: until the tracker holds warmup_records errors at the
     * sizing horizon, the error bounds are at least these rates times the
     * horizon (a predictor that has just started extrapolates sensor noise,
     * and an empty tracker would otherwise claim zero error). */
    int warmup_records;      /* 50 */
    float warmup_pos_mps;    /* 1.0 m/s */
    float warmup_rot_dps;    /* 100 deg/s */
    /* ADAPTIVE physical bound (pred_viewcell_physical_bound): the error bounds
     * are at least how far a head can move / turn away from its current motion
     * within the horizon h: min(acc/2 (h + lag)^2, (current speed + max speed) h).
     * Defaults: fitted to the p99.9 deviation of recorded heads (docs/prediction.md). */
    float head_acc_mps2;      /* 3 m/s^2 */
    float head_speed_mps;     /* 1.5 m/s */
    float head_ang_acc_dps2;  /* 2100 deg/s^2 */
    float head_ang_speed_dps; /* 400 deg/s */
    float predictor_lag_s;    /* 0.0125 s: the cv line fit's half window */
    bool single_frustum;      /* ADAPTIVE: clamp to max_fov_pvs instead of going omni */
} pred_viewcell_desc;

#define PRED_VC_OMNI_FRUSTA 6
#define PRED_VC_OMNI_HALF_DEG 46.0 /* 45 + 1 deg of overlap between neighbouring faces */

typedef struct pred_viewcell {
    float v0[3];
    float forward[3]; /* unit */
    float up[3];      /* unit, perpendicular to forward */
    float delta;      /* base radius (m) */
    float fov_target_deg; /* larger of the display's two angles */
    float fov_pvs_deg;    /* 2*alpha */
    float apex[3];        /* v* = v0 - z*forward */
    float z;              /* delta / tan(alpha) */
    double t_begin, t_end; /* use window */
    /* the sizing's terms, for logs */
    float pos_bound_m;    /* translation-error bound used */
    float rot_bound_deg;  /* rotation-error bound used */
    float rot_spread_deg; /* largest predicted rotation away from the window middle */
    float pos_phys_m;     /* the physical bounds at the sizing horizon (included in the bounds above) */
    float rot_phys_deg;
    int frusta;           /* 1: the frustum above; PRED_VC_OMNI_FRUSTA: every direction (delta,
                             z, apex, fov_pvs_deg are then frustum 0's, the one about forward) */
    bool clamped;         /* ADAPTIVE: the rotation needed more than max_fov_pvs and single_frustum
                             was set: the FOV was clamped (not conservative) */
    bool whole_scene;     /* ADAPTIVE: the sized apex lies beyond max_apex_offset: the PVS is every
                             triangle (delta, z, apex are the sizing's, for the logs) and every
                             eye is covered */
} pred_viewcell;

typedef enum pred_viewcell_miss {
    PRED_VC_COVERED = 0,
    PRED_VC_MISS_AXIAL,   /* |(e - v0).f| > z: beyond an apex */
    PRED_VC_MISS_RADIAL,  /* too far from the axis for its axial offset */
    PRED_VC_MISS_FRUSTUM, /* a corner of the eye's frustum leaves the PVS frustum */
} pred_viewcell_miss;

const char* pred_viewcell_miss_name(pred_viewcell_miss miss);

/* Sizes a viewcell from head poses predicted over the use window
 * (heads[0..n-1], heads[mid] at the window middle) and error bounds.
 * ADAPTIVE: alpha is the smallest half-angle for which the display frustum,
 * rotated by up to (spread + rot_err_deg) in any direction, stays inside the
 * square PVS frustum; delta is the smallest base radius for which every
 * predicted eye, grown by a ball of radius pos_err_m, lies in the double cone.
 * FIXED: delta and fov_pvs from the desc; the errors are only recorded. */
void pred_viewcell_from_poses(const pred_viewcell_desc* desc, const pred_pose* heads, int n, int mid,
                              double pos_err_m, double rot_err_deg, pred_viewcell* out);

/* Physical bound at horizon h (s) for a head now moving at speed_mps and
 * turning at ang_speed_dps: the larger deviation from its constant-velocity
 * extrapolation it can reach, min(acc/2 (h + lag)^2, (speed + max speed) h),
 * for position (m) and rotation (deg, at most 180). */
void pred_viewcell_physical_bound(const pred_viewcell_desc* desc, double horizon_s, double speed_mps,
                                  double ang_speed_dps, double* pos_m, double* rot_deg);

/* Predicts the window's poses with `predictor` and sizes the viewcell; the
 * error bounds are the larger of the tracker's `quantile` and the physical
 * bound (at the head's current speeds), both at the horizon from the newest
 * sample to the window end, and at least the warm-up prior while the
 * tracker has too few records there (tracker may be NULL: physical bound
 * only). False when the predictor has no samples yet. */
bool pred_viewcell_size(const pred_viewcell_desc* desc, const pred_predictor* predictor,
                        const pred_error_tracker* tracker, double t_request, pred_viewcell* out);

/* Frustum i (0 <= i < vc->frusta) of a viewcell as a single-frustum one:
 * a copy for frusta == 1; for an omni viewcell the cube face about forward,
 * -forward, right, -right, up, -up (i = 0..5) with the same v0 and delta. */
void pred_viewcell_frustum(const pred_viewcell* vc, int i, pred_viewcell* out);

/* Coverage test of one eye: pose (position, orientation head-local -> world)
 * and its display FOV (full angles, degrees). `why` (may be NULL) receives
 * the first failed condition. An omni viewcell covers an eye inside every
 * one of its double cones, whatever the eye's orientation: every ray from
 * there lies in one of the faces' frusta. A whole-scene viewcell covers
 * every eye. */
bool pred_viewcell_contains(const pred_viewcell* vc, const double eye_p[3], const double eye_q[4],
                            float eye_fov_h_deg, float eye_fov_v_deg, pred_viewcell_miss* why);

#ifdef __cplusplus
}
#endif

#endif
