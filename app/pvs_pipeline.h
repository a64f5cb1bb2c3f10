/* pvs_pipeline.h - the PVS request pipeline of `trimvr replay` and
 * `trimvr demo`: head samples feed the predictor and its online error
 * tracker; a request sizes a viewcell for the next PVS's use window
 * (viewcell.h) and hands it to the asynchronous worker (pvs_worker.h); a
 * finished PVS is taken into use with a triangle mask, and under the
 * measured latency model the next window is sized for the slowest of the
 * recent per-frustum compute times x the request's frusta x latency_factor
 * (a PVS over all directions takes one compute per frustum). A result is
 * taken into use no earlier than its use window begins and is drawn no
 * later than it ends (tv_pvs_pipeline_whole_scene).
 *
 * The clock is the caller's: simulated in the replay, fixed-step or wall
 * seconds in the demo. Calls come in time order: observe the samples up to
 * t, track(t), then step(t). docs/replay.md describes the timeline. */
#ifndef TRIMVR_APP_PVS_PIPELINE_H
#define TRIMVR_APP_PVS_PIPELINE_H

#include "error_tracker.h"
#include "method.h"
#include "predictor.h"
#include "pvs_worker.h"
#include "viewcell.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Head poses predicted at request time over a PVS's use window, to log how
 * far each frame's real pose was from what the viewcell was sized for. */
#define TV_PVS_PREDICTION_STEPS 64

/* Measured latency model: the window of recent per-frustum compute times
 * whose slowest sizes the next request. */
#define TV_PVS_TIMED 8

typedef struct tv_pvs_slot {
    tv_pvs_result r;
    uint8_t* mask; /* r.ids as a triangle_count byte mask */
    uint32_t dynamic_count; /* ids of moving triangles in r.ids */
    pred_pose predicted[TV_PVS_PREDICTION_STEPS];
    double pred_t0, pred_dt;
} tv_pvs_slot;

/* Zero means default. */
typedef struct tv_pvs_pipeline_desc {
    pvs_method_desc method;
    pred_predictor_desc predictor;
    pred_viewcell_desc viewcell; /* policy, limits, display FOVs and ipd */
    tv_latency_model latency_model;
    double latency_s;            /* fixed model: request -> availability */
    double latency_factor;       /* measured model: factor on the compute time; 0: 1 */
    /* Coverage runs: no method is created and every PVS is empty. Under the
     * fixed model the timeline, the sizing and the coverage test are the same
     * as with any method (precondition: latency_model is TV_LATENCY_FIXED). */
    bool no_pvs;
} tv_pvs_pipeline_desc;

typedef struct tv_pvs_pipeline {
    tv_pvs_pipeline_desc desc;
    uint32_t triangle_count;
    const scn_scene* scene; /* its movers' tracks size the proxies */
    pvs_proxy* proxies; /* one per mover, for the request in flight (the worker reads them) */
    pred_predictor predictor;
    pred_error_tracker tracker;
    pvs_method* method;
    tv_worker* worker;
    tv_pvs_slot current;  /* the PVS in use */
    tv_pvs_slot pending;  /* the request in flight (its predictions) */
    pred_pose last;       /* newest observed head sample */
    double latency_est_s; /* fixed model: the latency; measured: until the first PVS is timed */
    double frustum_ms[TV_PVS_TIMED]; /* measured model: the last PVSs' compute times per frustum */
    uint32_t timed;       /* PVSs timed into frustum_ms so far */
    uint32_t adopted;     /* PVSs taken into use so far */
    uint32_t probes;      /* measured model: smallest cells computed instead of a whole-scene one (request) */
    char latency_name[64]; /* "fixed 50.0 ms" / "measured x1.00" */
} tv_pvs_pipeline;

/* Creates the method for `scene` (uploaded as `gpu` on `rnd`) and starts the
 * worker; no PVS yet (tv_pvs_pipeline_first). On failure fills err and
 * leaves nothing allocated. */
bool tv_pvs_pipeline_start(tv_pvs_pipeline* p, const tv_pvs_pipeline_desc* desc, rnd_context* rnd,
                           const scn_scene* scene, const rnd_gpu_scene* gpu, char* err, size_t err_size);

/* One head sensor sample, newer than the previous one. */
void tv_pvs_pipeline_observe(tv_pvs_pipeline* p, const pred_pose* sample);

/* Records the predictions at every tracked horizon from time t, so the
 * adaptive policy's error quantiles follow the motion online. */
void tv_pvs_pipeline_track(tv_pvs_pipeline* p, double t);

/* Computes the first PVS at time t synchronously (a headset shows nothing
 * before it has one); it is in use from t on, so its window starts at t.
 * Under the measured model a second one follows, sized for the first's
 * measured time instead of the 50 ms guess. */
bool tv_pvs_pipeline_first(tv_pvs_pipeline* p, double t, double frame_s, char* err, size_t err_size);

/* One display frame at time t: takes a PVS that is due into use and, when
 * `may_request` and the worker is idle, requests the next one, sized to be
 * in use from its arrival until the one after it arrives plus frame_s.
 * Returns 1 when a PVS was taken into use, 0 when not, -1 on a failed
 * computation or sizing (err filled). */
int tv_pvs_pipeline_step(tv_pvs_pipeline* p, double t, double frame_s, bool may_request, char* err,
                         size_t err_size);

/* Whether the frame at t must draw the whole scene instead of the current
 * PVS: it is a whole-scene one (its sizing's apex lay beyond what a PVS
 * resolves), or t is past the end of the use window it was sized for (its
 * successor is late: the compute outlasted the latency it was sized for).
 * Either way a slow PVS costs drawing, never holes. */
bool tv_pvs_pipeline_whole_scene(const tv_pvs_pipeline* p, double t);

/* The head pose predicted for time t when the current PVS was requested. */
void tv_pvs_pipeline_predicted(const tv_pvs_pipeline* p, double t, pred_pose* out);

/* Waits for the worker and releases everything. Safe on a zeroed struct. */
void tv_pvs_pipeline_stop(tv_pvs_pipeline* p);

#endif
