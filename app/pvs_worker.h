/* pvs_worker.h - the asynchronous PVS: a worker thread that owns PVS
 * computation, and the latency model that decides when, on the simulated
 * clock, a result becomes usable.
 *
 * The display loop submits at most one request at a time (tv_worker_submit)
 * and polls (tv_worker_poll) once per display frame. A result computed for a
 * request made at t_request becomes available at
 *   t_request + fixed_latency_s                       (TV_LATENCY_FIXED), or
 *   max(t_request + measured compute time * factor,    (TV_LATENCY_MEASURED),
 *       the viewcell's t_begin)
 * Neither side blocks the other except when the display loop reaches a
 * simulated time at which the result is, or may be, due while the worker is
 * still computing: then tv_worker_poll waits in wall time until it is known
 * whether the result is due. With the fixed model, runs are reproducible. */
#ifndef TRIMVR_APP_PVS_WORKER_H
#define TRIMVR_APP_PVS_WORKER_H

#include "viewcell.h"

#include <stdbool.h>
#include <stdint.h>

/* Computes the PVS of one request on the worker thread. `extra` is the
 * request (extra_size bytes, copied at submit, carrying its viewcell; NULL
 * when extra_size is 0). On success fills a malloc'ed sorted id list (*ids,
 * *count; the worker takes ownership) and method-specific statistics into
 * stats (opaque to the worker, stats_size bytes). On failure returns false
 * with a one-line message in err. */
typedef bool (*tv_pvs_compute_fn)(void* user, const void* extra, uint32_t** ids, uint32_t* count, void* stats,
                                  char* err, size_t err_size);

typedef enum tv_latency_model {
    TV_LATENCY_FIXED = 0,
    TV_LATENCY_MEASURED = 1
} tv_latency_model;

typedef struct tv_worker_desc {
    tv_pvs_compute_fn compute;
    void* user;
    size_t stats_size;     /* bytes of the method's statistics struct */
    size_t extra_size;     /* bytes of the per-request data passed to compute */
    tv_latency_model model;
    double fixed_latency_s; /* TV_LATENCY_FIXED */
    double factor;          /* TV_LATENCY_MEASURED: device factor on the measured time */
} tv_worker_desc;

/* A finished PVS, as the display loop uses it. */
typedef struct tv_pvs_result {
    uint32_t id;          /* request sequence number, from 0 */
    pred_viewcell vc;     /* the viewcell it was computed for */
    uint32_t* ids;        /* sorted triangle ids; owned by the holder */
    uint32_t count;
    double t_request;     /* simulated request time */
    double t_available;   /* simulated availability time */
    double compute_ms;    /* wall-clock compute time on the worker */
    void* stats;          /* stats_size bytes; owned by the holder */
} tv_pvs_result;

typedef struct tv_worker tv_worker;

/* Starts the worker thread. NULL (message in err) if the thread cannot start. */
tv_worker* tv_worker_start(const tv_worker_desc* desc, char* err, size_t err_size);

/* Asks for the PVS of a request at simulated time t_request; `extra`
 * (extra_size bytes, may be NULL when that is 0) is copied, `vc` is kept as
 * the result's (tv_pvs_result.vc). Precondition: no request in
 * flight (tv_worker_busy() is false). Never blocks on the compute. */
void tv_worker_submit(tv_worker* w, const pred_viewcell* vc, const void* extra, double t_request);

/* True from tv_worker_submit until the result has been handed out by poll. */
bool tv_worker_busy(const tv_worker* w);

/* Called by the display loop at simulated time `now`. If the in-flight
 * result is available at `now`, moves it into *out and returns 1. Returns 0
 * when nothing is due yet, -1 when the computation failed (message in err;
 * the request is dropped). Waits in wall time only while it cannot yet be
 * decided whether the result is due. */
int tv_worker_poll(tv_worker* w, double now, tv_pvs_result* out, char* err, size_t err_size);

/* Blocks until the in-flight result (if any) is computed and returns it as
 * poll would, ignoring its availability time: used to obtain the very first
 * PVS before the display starts. Returns 0 when no request is in flight. */
int tv_worker_wait(tv_worker* w, tv_pvs_result* out, char* err, size_t err_size);

/* Finishes the in-flight computation (its result is discarded), stops and
 * joins the thread, and frees the worker. NULL is a no-op. */
void tv_worker_stop(tv_worker* w);

/* Frees a result's arrays. */
void tv_pvs_result_free(tv_pvs_result* r);

/* "fixed 50 ms" / "measured x1.00": the model as the log states it. */
void tv_worker_describe(const tv_worker_desc* desc, char* out, size_t out_size);

#endif
