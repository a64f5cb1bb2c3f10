/* demo_pvs.c - the live PVS pipeline (the same pieces as replay.c, fed by a
 * head that exists only frame by frame). */
#include "demo_pvs.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static bool compute(void* user, const pred_viewcell* vc, const void* extra, uint32_t** ids, uint32_t* count,
                    void* stats, char* err, size_t err_size)
{
    (void)vc; /* the request carries the same viewcell */
    return pvs_method_compute(user, extra, ids, count, stats, err, err_size);
}

/* Sensor samples between the last observed pose and `head`: the display loop
 * only knows the head once per frame, and the predictor wants the sensor's
 * rate. Linear in position, shortest arc in orientation. */
static void feed(tv_live_pvs* lp, const pred_pose* head)
{
    double dt = 1.0 / lp->desc.sensor_rate_hz;
    int n = (int)((head->t - lp->last.t) / dt);
    for (int i = 1; i <= n; i++) {
        pred_pose s;
        pred_pose_lerp(&lp->last, head, (double)i / (n + 1), &s);
        s.t = lp->last.t + (head->t - lp->last.t) * i / (n + 1);
        pred_predictor_update(&lp->predictor, &s);
        pred_error_tracker_observe(&lp->tracker, &s);
    }
    if (head->t > lp->last.t) {
        pred_predictor_update(&lp->predictor, head);
        pred_error_tracker_observe(&lp->tracker, head);
    }
    lp->last = *head;
    for (int h = 0; h < lp->tracker.horizon_count; h++) {
        pred_pose p;
        if (pred_predictor_predict(&lp->predictor, head->t + lp->tracker.horizons_s[h], &p))
            pred_error_tracker_push(&lp->tracker, h, &p);
    }
}

static bool request(tv_live_pvs* lp, double frame_s, char* err, size_t err_size)
{
    pred_viewcell_desc vd = lp->desc.viewcell;
    vd.latency_s = lp->latency_est_s;
    vd.window_s = lp->latency_est_s + frame_s; /* until the next PVS lands, plus a frame */
    pvs_request req;
    memset(&req, 0, sizeof req);
    double t = lp->last.t;
    if (!pred_viewcell_size(&vd, &lp->predictor, &lp->tracker, t, &req.vc)) {
        snprintf(err, err_size, "no head sample before t = %.3f s", t);
        return false;
    }
    pred_pose a, b;
    pred_predictor_predict(&lp->predictor, req.vc.t_begin, &a);
    pred_predictor_predict(&lp->predictor, req.vc.t_end, &b);
    for (int k = 0; k < 3; k++)
        req.motion[k] = b.p[k] - a.p[k];
    req.current = lp->last;
    req.eye_fov_h_deg = lp->desc.viewcell.display_fov_h_deg;
    tv_worker_submit(lp->worker, &req.vc, &req, t);
    return true;
}

static bool adopt(tv_live_pvs* lp, tv_pvs_result* r, char* err, size_t err_size)
{
    uint32_t tris = lp->scene->scene.triangle_count;
    uint8_t* mask = calloc(tris ? tris : 1, 1);
    if (!mask) {
        tv_pvs_result_free(r);
        snprintf(err, err_size, "out of memory");
        return false;
    }
    for (uint32_t i = 0; i < r->count; i++)
        mask[r->ids[i]] = 1;
    tv_pvs_result_free(&lp->current);
    free(lp->mask);
    lp->current = *r;
    lp->mask = mask;
    lp->adopted++;
    if (lp->desc.latency_model == TV_LATENCY_MEASURED) /* IIR, as the replay's measured model */
        lp->latency_est_s = 0.7 * lp->latency_est_s + 0.3 * r->compute_ms * 1e-3;
    return true;
}

bool tv_live_pvs_start(tv_live_pvs* lp, const tv_live_pvs_desc* desc, const tv_app_scene* scene,
                       const pred_pose* head, char* err, size_t err_size)
{
    memset(lp, 0, sizeof *lp);
    lp->desc = *desc;
    if (lp->desc.sensor_rate_hz <= 0.0)
        lp->desc.sensor_rate_hz = 1000.0;
    lp->scene = scene;
    lp->latency_est_s = desc->latency_model == TV_LATENCY_FIXED ? desc->latency_s : 0.05;
    pred_predictor_init(&lp->predictor, &desc->predictor);
    if (!pred_error_tracker_init(&lp->tracker, &(pred_error_tracker_desc){0})) {
        snprintf(err, err_size, "prediction error tracker: out of memory");
        return false;
    }
    lp->method = pvs_method_create(&desc->method, scene->ctx, &scene->scene, scene->gpu, err, err_size);
    tv_worker_desc wd = {.compute = compute, .user = lp->method, .stats_size = sizeof(pvs_method_stats),
                         .extra_size = sizeof(pvs_request), .model = desc->latency_model,
                         .fixed_latency_s = desc->latency_s, .factor = 1.0};
    if (lp->method)
        lp->worker = tv_worker_start(&wd, err, err_size);
    if (!lp->worker) {
        tv_live_pvs_stop(lp);
        return false;
    }
    /* a resting head: the predictor needs two samples for a velocity */
    pred_pose before = *head;
    before.t -= 0.05;
    lp->last = before;
    pred_predictor_update(&lp->predictor, &before);
    feed(lp, head);
    tv_pvs_result r;
    if (!request(lp, 0.0, err, err_size) || tv_worker_wait(lp->worker, &r, err, err_size) != 1 ||
        !adopt(lp, &r, err, err_size)) {
        tv_live_pvs_stop(lp);
        return false;
    }
    return true;
}

bool tv_live_pvs_update(tv_live_pvs* lp, const pred_pose* head, double frame_s, bool frozen, char* err,
                        size_t err_size)
{
    feed(lp, head);
    tv_pvs_result r;
    int polled = tv_worker_poll(lp->worker, head->t, &r, err, err_size);
    if (polled < 0 || (polled == 1 && !adopt(lp, &r, err, err_size)))
        return false;
    if (!frozen && !tv_worker_busy(lp->worker))
        return request(lp, frame_s, err, err_size);
    return true;
}

void tv_live_pvs_stop(tv_live_pvs* lp)
{
    tv_worker_stop(lp->worker);
    pvs_method_destroy(lp->method);
    tv_pvs_result_free(&lp->current);
    free(lp->mask);
    pred_error_tracker_free(&lp->tracker);
    memset(lp, 0, sizeof *lp);
}
