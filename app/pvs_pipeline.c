#include "pvs_pipeline.h"

#include <assert.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The worker's compute: one PVS method call on the request it was handed. */
static bool compute_pvs(void* user, const void* request, uint32_t** ids, uint32_t* count, void* stats, char* err,
                        size_t err_size)
{
    return pvs_method_compute(user, request, ids, count, stats, err, err_size);
}

/* no_pvs: an empty PVS, no method call. */
static bool compute_empty(void* user, const void* request, uint32_t** ids, uint32_t* count, void* stats, char* err,
                          size_t err_size)
{
    (void)user;
    (void)request;
    (void)stats; /* zeroed by the worker */
    *count = 0;
    *ids = malloc(sizeof **ids);
    if (!*ids)
        snprintf(err, err_size, "out of memory");
    return *ids != NULL;
}

static void slot_release(tv_pvs_slot* s)
{
    tv_pvs_result_free(&s->r);
    free(s->mask);
    memset(s, 0, sizeof *s);
}

static void predicted_at(const tv_pvs_slot* s, double t, pred_pose* out)
{
    double u = (t - s->pred_t0) / s->pred_dt;
    int i = u <= 0 ? 0 : u >= TV_PVS_PREDICTION_STEPS - 1 ? TV_PVS_PREDICTION_STEPS - 2 : (int)u;
    double f = u - i;
    f = f < 0 ? 0 : f > 1 ? 1 : f;
    pred_pose_lerp(&s->predicted[i], &s->predicted[i + 1], f, out);
    out->t = t;
}

bool tv_pvs_pipeline_start(tv_pvs_pipeline* p, const tv_pvs_pipeline_desc* desc, rnd_context* rnd,
                           const scn_scene* scene, const rnd_gpu_scene* gpu, char* err, size_t err_size)
{
    assert(p && desc && rnd && scene && gpu);
    assert(!desc->no_pvs || desc->latency_model == TV_LATENCY_FIXED);
    memset(p, 0, sizeof *p);
    p->desc = *desc;
    if (!(p->desc.latency_factor > 0.0))
        p->desc.latency_factor = 1.0;
    p->triangle_count = scene->triangle_count;
    p->scene = scene;
    p->latency_est_s = desc->latency_model == TV_LATENCY_FIXED ? desc->latency_s : 0.05;
    /* tr's limit whatever the method: a cheap method sizes the same cells */
    if (!(p->desc.viewcell.max_apex_offset_m > 0.0f))
        p->desc.viewcell.max_apex_offset_m = pvs_max_apex_offset(desc->method.tr.near_m);
    pred_predictor_init(&p->predictor, &desc->predictor);
    if (!pred_error_tracker_init(&p->tracker, &(pred_error_tracker_desc){0})) {
        snprintf(err, err_size, "prediction error tracker: out of memory");
        return false;
    }
    p->method = desc->no_pvs ? NULL : pvs_method_create(&desc->method, rnd, scene, gpu, err, err_size);
    p->proxies = calloc(scene->mover_count ? scene->mover_count : 1, sizeof *p->proxies);
    if (!p->proxies)
        snprintf(err, err_size, "out of memory");
    tv_worker_desc wd = {.compute = desc->no_pvs ? compute_empty : compute_pvs, .user = p->method,
                         .stats_size = sizeof(pvs_method_stats), .extra_size = sizeof(pvs_request),
                         .model = desc->latency_model,
                         .fixed_latency_s = desc->latency_s, .factor = p->desc.latency_factor};
    tv_worker_describe(&wd, p->latency_name, sizeof p->latency_name);
    if ((p->method || desc->no_pvs) && p->proxies)
        p->worker = tv_worker_start(&wd, err, err_size);
    if (!p->worker) {
        tv_pvs_pipeline_stop(p);
        return false;
    }
    return true;
}

void tv_pvs_pipeline_observe(tv_pvs_pipeline* p, const pred_pose* sample)
{
    pred_predictor_update(&p->predictor, sample);
    pred_error_tracker_observe(&p->tracker, sample);
    p->last = *sample;
}

void tv_pvs_pipeline_track(tv_pvs_pipeline* p, double t)
{
    for (int h = 0; h < p->tracker.horizon_count; h++) {
        pred_pose pose;
        if (pred_predictor_predict(&p->predictor, t + p->tracker.horizons_s[h], &pose))
            pred_error_tracker_push(&p->tracker, h, &pose);
    }
}

/* The start-up PVS's use window begins at its request (a zero latency_s
 * would mean the viewcell desc's default, 50 ms). */
static const double k_now_s = 1e-9;

/* Latency of a PVS of `frusta` frusta: the fixed model's, or the slowest of
 * the recent per-frustum compute times (a loaded machine's times vary by 2x:
 * an average would size windows the next PVS outlasts) x frusta x factor. */
static double latency_for(const tv_pvs_pipeline* p, int frusta)
{
    if (p->desc.latency_model == TV_LATENCY_FIXED || !p->timed)
        return p->latency_est_s;
    double ms = 0.0;
    for (uint32_t i = 0; i < p->timed && i < TV_PVS_TIMED; i++)
        ms = ms > p->frustum_ms[i] ? ms : p->frustum_ms[i];
    return ms * 1e-3 * frusta * p->desc.latency_factor;
}

/* `first`: the start-up PVS is used from the first frame on, so its window
 * starts at the request instead of one latency later. */
static bool request(tv_pvs_pipeline* p, double t, double frame_s, bool first, char* err, size_t err_size)
{
    pred_viewcell_desc vd = p->desc.viewcell;
    pvs_request req;
    memset(&req, 0, sizeof req);
    /* requests go out back to back: this PVS is in use from its arrival until
     * the next one arrives one latency later, plus a frame of slack. A PVS
     * over all directions takes one compute per frustum: sized again for that
     * latency (the longer horizon keeps it all-directions) */
    for (int frusta = 1;; frusta = req.vc.frusta) {
        double latency = latency_for(p, frusta);
        vd.latency_s = first ? k_now_s : latency;
        vd.window_s = (first ? 2.0 : 1.0) * latency + frame_s;
        if (!pred_viewcell_size(&vd, &p->predictor, &p->tracker, t, &req.vc)) {
            snprintf(err, err_size, "no head sample before t = %.3f s", t);
            return false;
        }
        if (req.vc.frusta == frusta || latency_for(p, req.vc.frusta) == latency)
            break;
    }
    /* A whole-scene answer takes no compute and so adds no timing: under the
     * measured model the estimate that chose it would never fall again, and
     * the loop would stay on the whole scene after a load spike has passed.
     * Instead the smallest cell, sized for no latency and one frame, is
     * computed as a probe: cheap, drawn only inside its (past) window, but
     * timed, so the estimate follows the device again. */
    if (req.vc.whole_scene && !first && p->desc.latency_model == TV_LATENCY_MEASURED && p->timed) {
        pvs_request probe = req;
        vd.latency_s = k_now_s;
        vd.window_s = frame_s;
        if (pred_viewcell_size(&vd, &p->predictor, &p->tracker, t, &probe.vc) && !probe.vc.whole_scene) {
            req = probe;
            p->probes++;
        }
    }
    /* the whole scene needs no compute: in use from its arrival on */
    if (req.vc.whole_scene)
        req.vc.t_begin = t;
    tv_pvs_slot* s = &p->pending;
    s->pred_t0 = t;
    s->pred_dt = (vd.latency_s + vd.window_s + 2.0 * frame_s) / (TV_PVS_PREDICTION_STEPS - 1);
    for (int i = 0; i < TV_PVS_PREDICTION_STEPS; i++)
        pred_predictor_predict(&p->predictor, t + i * s->pred_dt, &s->predicted[i]);
    pred_pose a, b;
    predicted_at(s, req.vc.t_begin, &a);
    predicted_at(s, req.vc.t_end, &b);
    for (int k = 0; k < 3; k++)
        req.motion[k] = b.p[k] - a.p[k];
    req.current = p->last;
    req.eye_fov_h_deg = p->desc.viewcell.display_fov_h_deg;
    /* the proxies stay the pipeline's: the next request waits until the worker is idle */
    req.proxies = p->proxies;
    req.proxy_count = pvs_method_proxies(p->scene, req.vc.t_begin, req.vc.t_end, p->proxies);
    tv_worker_submit(p->worker, &req.vc, &req, t);
    return true;
}

static bool adopt(tv_pvs_pipeline* p, tv_pvs_result* r, char* err, size_t err_size)
{
    tv_pvs_slot next = p->pending;
    next.r = *r;
    next.mask = calloc(p->triangle_count ? p->triangle_count : 1, 1);
    if (!next.mask) {
        tv_pvs_result_free(r);
        snprintf(err, err_size, "out of memory");
        return false;
    }
    uint32_t first_dynamic = p->triangle_count - p->scene->dynamic_triangle_count;
    next.dynamic_count = 0;
    for (uint32_t i = 0; i < r->count; i++) {
        next.mask[r->ids[i]] = 1;
        next.dynamic_count += r->ids[i] >= first_dynamic;
    }
    slot_release(&p->current);
    p->current = next;
    p->adopted++;
    if (!r->vc.whole_scene) /* listing every triangle says nothing about the compute time */
        p->frustum_ms[p->timed++ % TV_PVS_TIMED] = r->compute_ms / (r->vc.frusta > 1 ? r->vc.frusta : 1);
    return true;
}

bool tv_pvs_pipeline_first(tv_pvs_pipeline* p, double t, double frame_s, char* err, size_t err_size)
{
    int computes = p->desc.latency_model == TV_LATENCY_MEASURED ? 2 : 1;
    for (int i = 0; i < computes; i++) {
        tv_pvs_result r;
        if (!request(p, t, frame_s, true, err, err_size) || tv_worker_wait(p->worker, &r, err, err_size) != 1 ||
            !adopt(p, &r, err, err_size))
            return false;
    }
    return true;
}

int tv_pvs_pipeline_step(tv_pvs_pipeline* p, double t, double frame_s, bool may_request, char* err,
                         size_t err_size)
{
    tv_pvs_result r;
    int polled = tv_worker_poll(p->worker, t, &r, err, err_size);
    if (polled < 0 || (polled == 1 && !adopt(p, &r, err, err_size)))
        return -1;
    if (may_request && !tv_worker_busy(p->worker) && !request(p, t, frame_s, false, err, err_size))
        return -1;
    return polled;
}

bool tv_pvs_pipeline_whole_scene(const tv_pvs_pipeline* p, double t)
{
    return p->current.r.vc.whole_scene || t > p->current.r.vc.t_end;
}

void tv_pvs_pipeline_predicted(const tv_pvs_pipeline* p, double t, pred_pose* out)
{
    predicted_at(&p->current, t, out);
}

void tv_pvs_pipeline_stop(tv_pvs_pipeline* p)
{
    tv_worker_stop(p->worker);
    pvs_method_destroy(p->method);
    slot_release(&p->current);
    pred_error_tracker_free(&p->tracker);
    free(p->proxies);
    memset(p, 0, sizeof *p);
}
