/* demo_pvs.h - the replay's PVS pipeline driven by a live head: sensor
 * samples at the sensor rate (interpolated between the poses the display
 * loop observes), the predictor and its online error tracker, viewcell
 * sizing for the next PVS's use window, and the asynchronous worker.
 *
 * The clock is the caller's: wall seconds in the interactive demo (worker
 * latency model "measured x1": a PVS is used as soon as it is computed), or
 * a fixed-step clock for reproducible runs (model "fixed": the worker's
 * usual simulated latency, as in `trimvr replay`). */
#ifndef TRIMVR_APP_DEMO_PVS_H
#define TRIMVR_APP_DEMO_PVS_H

#include "app_scene.h"
#include "error_tracker.h"
#include "method.h"
#include "predictor.h"
#include "pvs_worker.h"
#include "viewcell.h"

typedef struct tv_live_pvs_desc {
    pvs_method_desc method;
    pred_predictor_desc predictor;
    pred_viewcell_desc viewcell; /* display FOVs and ipd filled in */
    tv_latency_model latency_model;
    double latency_s;       /* fixed model */
    double sensor_rate_hz;  /* 0: 1000 */
} tv_live_pvs_desc;

typedef struct tv_live_pvs {
    tv_live_pvs_desc desc;
    const tv_app_scene* scene;
    pred_predictor predictor;
    pred_error_tracker tracker;
    pvs_method* method;
    tv_worker* worker;
    tv_pvs_result current; /* the PVS in use */
    uint8_t* mask;         /* current's ids as a triangle_count byte mask */
    pred_pose last;        /* newest observed head pose */
    double latency_est_s;  /* request -> availability, for sizing the window */
    uint32_t adopted;      /* PVSs taken into use so far */
} tv_live_pvs;

/* Creates the method and worker and computes the first PVS synchronously
 * for a head resting at `head` (a headset shows nothing before it has one).
 * On failure prints nothing, fills err and leaves nothing allocated. */
bool tv_live_pvs_start(tv_live_pvs* lp, const tv_live_pvs_desc* desc, const tv_app_scene* scene,
                       const pred_pose* head, char* err, size_t err_size);

/* One display frame at time head->t (after the previous call's): feeds the
 * sensor samples up to it, takes a finished PVS into use, and, unless
 * `frozen`, requests the next one when the worker is idle, sized for a use
 * window of the latency estimate plus frame_s. Returns false on a failed PVS
 * computation (err filled). */
bool tv_live_pvs_update(tv_live_pvs* lp, const pred_pose* head, double frame_s, bool frozen, char* err,
                        size_t err_size);

/* Waits for the worker and releases everything. Safe on a zeroed struct. */
void tv_live_pvs_stop(tv_live_pvs* lp);

#endif
