#define _POSIX_C_SOURCE 200809L
#include "pvs_worker.h"

#include "clock.h"

#include <assert.h>
#include <errno.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef enum job_state { JOB_IDLE, JOB_QUEUED, JOB_RUNNING, JOB_DONE } job_state;

struct tv_worker {
    tv_worker_desc desc;
    pthread_t thread;
    pthread_mutex_t mutex;
    pthread_cond_t cond; /* signalled on every state change */
    bool quit;
    uint32_t next_id;

    /* the one job; fields below are guarded by mutex */
    job_state state;
    void* extra; /* extra_size bytes */
    double t_request;
    double started_ms; /* wall clock when the worker picked the job up */
    bool ok;
    tv_pvs_result result;
    char err[512];
};

static void* worker_main(void* arg)
{
    tv_worker* w = arg;
    pthread_mutex_lock(&w->mutex);
    for (;;) {
        while (!w->quit && w->state != JOB_QUEUED)
            pthread_cond_wait(&w->cond, &w->mutex);
        if (w->quit)
            break;
        w->state = JOB_RUNNING;
        w->started_ms = tv_now_ms();
        pthread_cond_broadcast(&w->cond);
        pthread_mutex_unlock(&w->mutex);

        /* the compute runs unlocked: the display loop keeps polling */
        uint32_t* ids = NULL;
        uint32_t count = 0;
        void* stats = calloc(1, w->desc.stats_size ? w->desc.stats_size : 1);
        char err[512] = "";
        double t0 = tv_now_ms();
        bool ok = stats && w->desc.compute(w->desc.user, w->extra, &ids, &count, stats, err, sizeof err);
        double ms = tv_now_ms() - t0;
        if (!stats)
            snprintf(err, sizeof err, "PVS worker: out of memory");

        pthread_mutex_lock(&w->mutex);
        w->ok = ok;
        snprintf(w->err, sizeof w->err, "%s", err);
        w->result.ids = ok ? ids : NULL;
        w->result.count = ok ? count : 0;
        w->result.stats = stats;
        w->result.compute_ms = ms;
        if (!ok)
            free(ids);
        w->state = JOB_DONE;
        pthread_cond_broadcast(&w->cond);
    }
    pthread_mutex_unlock(&w->mutex);
    return NULL;
}

tv_worker* tv_worker_start(const tv_worker_desc* desc, char* err, size_t err_size)
{
    assert(desc && desc->compute);
    tv_worker* w = calloc(1, sizeof *w);
    if (!w) {
        snprintf(err, err_size, "PVS worker: out of memory");
        return NULL;
    }
    w->desc = *desc;
    if (!(w->desc.factor > 0.0))
        w->desc.factor = 1.0;
    if (desc->extra_size) {
        w->extra = calloc(1, desc->extra_size);
        if (!w->extra) {
            snprintf(err, err_size, "PVS worker: out of memory");
            free(w);
            return NULL;
        }
    }
    pthread_mutex_init(&w->mutex, NULL);
    pthread_cond_init(&w->cond, NULL);
    int rc = pthread_create(&w->thread, NULL, worker_main, w);
    if (rc != 0) {
        snprintf(err, err_size, "PVS worker: pthread_create failed: %s", strerror(rc));
        pthread_cond_destroy(&w->cond);
        pthread_mutex_destroy(&w->mutex);
        free(w->extra);
        free(w);
        return NULL;
    }
    return w;
}

void tv_worker_submit(tv_worker* w, const pred_viewcell* vc, const void* extra, double t_request)
{
    pthread_mutex_lock(&w->mutex);
    assert(w->state == JOB_IDLE);
    assert(extra || !w->desc.extra_size);
    if (w->desc.extra_size) /* the worker reads it only while the job runs */
        memcpy(w->extra, extra, w->desc.extra_size);
    w->t_request = t_request;
    memset(&w->result, 0, sizeof w->result);
    w->result.id = w->next_id++;
    w->result.vc = *vc;
    w->result.t_request = t_request;
    w->state = JOB_QUEUED;
    pthread_cond_broadcast(&w->cond);
    pthread_mutex_unlock(&w->mutex);
}

bool tv_worker_busy(const tv_worker* w)
{
    tv_worker* mw = (tv_worker*)w; /* the mutex is not part of the logical state */
    pthread_mutex_lock(&mw->mutex);
    bool busy = mw->state != JOB_IDLE;
    pthread_mutex_unlock(&mw->mutex);
    return busy;
}

static double availability(const tv_worker* w, double compute_ms)
{
    if (w->desc.model == TV_LATENCY_FIXED)
        return w->t_request + w->desc.fixed_latency_s;
    /* a PVS faster than its sizing assumed waits for its use window: before
     * it the eyes are not where the viewcell was sized for */
    double t = w->t_request + compute_ms * 1e-3 * w->desc.factor;
    return t > w->result.vc.t_begin ? t : w->result.vc.t_begin;
}

/* Hands the finished job out. Called with the mutex held, state DONE. */
static int take_result(tv_worker* w, tv_pvs_result* out, char* err, size_t err_size)
{
    int rc = 1;
    if (w->ok) {
        *out = w->result;
        out->t_available = availability(w, w->result.compute_ms);
    } else {
        snprintf(err, err_size, "%s", w->err);
        free(w->result.stats);
        rc = -1;
    }
    memset(&w->result, 0, sizeof w->result);
    w->state = JOB_IDLE;
    return rc;
}

static void wait_until_ms(tv_worker* w, double deadline_ms)
{
    struct timespec now;
    clock_gettime(CLOCK_REALTIME, &now);
    double wait_ms = deadline_ms - tv_now_ms();
    if (wait_ms < 0.05)
        wait_ms = 0.05;
    long long ns = (long long)now.tv_nsec + (long long)(wait_ms * 1e6);
    struct timespec until = {.tv_sec = now.tv_sec + (time_t)(ns / 1000000000LL), .tv_nsec = (long)(ns % 1000000000LL)};
    pthread_cond_timedwait(&w->cond, &w->mutex, &until);
}

int tv_worker_poll(tv_worker* w, double now, tv_pvs_result* out, char* err, size_t err_size)
{
    pthread_mutex_lock(&w->mutex);
    int rc = 0;
    for (;;) {
        if (w->state == JOB_IDLE)
            break;
        if (w->state == JOB_DONE) {
            if (!w->ok || availability(w, w->result.compute_ms) <= now)
                rc = take_result(w, out, err, err_size);
            break;
        }
        if (w->desc.model == TV_LATENCY_FIXED) {
            if (availability(w, 0.0) > now)
                break; /* not due yet: keep displaying the current PVS */
            pthread_cond_wait(&w->cond, &w->mutex); /* due: the display waits for it */
            continue;
        }
        /* measured: due iff the compute finishes within (now - t_request) / factor */
        double budget_ms = (now - w->t_request) * 1e3 / w->desc.factor;
        if (w->state == JOB_QUEUED) {
            if (budget_ms <= 0.0)
                break;
            pthread_cond_wait(&w->cond, &w->mutex);
            continue;
        }
        double elapsed = tv_now_ms() - w->started_ms;
        if (elapsed > budget_ms)
            break; /* it will finish later than `now` allows: not due */
        wait_until_ms(w, w->started_ms + budget_ms);
    }
    pthread_mutex_unlock(&w->mutex);
    return rc;
}

int tv_worker_wait(tv_worker* w, tv_pvs_result* out, char* err, size_t err_size)
{
    pthread_mutex_lock(&w->mutex);
    while (w->state == JOB_QUEUED || w->state == JOB_RUNNING)
        pthread_cond_wait(&w->cond, &w->mutex);
    int rc = w->state == JOB_DONE ? take_result(w, out, err, err_size) : 0;
    pthread_mutex_unlock(&w->mutex);
    return rc;
}

void tv_worker_stop(tv_worker* w)
{
    if (!w)
        return;
    pthread_mutex_lock(&w->mutex);
    while (w->state == JOB_QUEUED || w->state == JOB_RUNNING)
        pthread_cond_wait(&w->cond, &w->mutex);
    if (w->state == JOB_DONE) {
        free(w->result.ids);
        free(w->result.stats);
    }
    w->quit = true;
    pthread_cond_broadcast(&w->cond);
    pthread_mutex_unlock(&w->mutex);
    pthread_join(w->thread, NULL);
    pthread_cond_destroy(&w->cond);
    pthread_mutex_destroy(&w->mutex);
    free(w->extra);
    free(w);
}

void tv_pvs_result_free(tv_pvs_result* r)
{
    free(r->ids);
    free(r->stats);
    memset(r, 0, sizeof *r);
}

void tv_worker_describe(const tv_worker_desc* desc, char* out, size_t out_size)
{
    if (desc->model == TV_LATENCY_FIXED)
        snprintf(out, out_size, "fixed %.1f ms", desc->fixed_latency_s * 1e3);
    else
        snprintf(out, out_size, "measured x%.2f", desc->factor > 0.0 ? desc->factor : 1.0);
}
