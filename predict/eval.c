#include "eval.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

bool pred_eval_run(const pred_eval_desc* desc, pred_eval_result* out, char* err, size_t err_size)
{
    assert(desc && desc->path && desc->path->count >= 1 && out);
    memset(out, 0, sizeof *out);
    hmd_sim sim;
    hmd_sim_init(&sim, &desc->hmd, desc->path);
    uint64_t frames = hmd_display_frame_count(&sim);
    pred_error_tracker_desc td = desc->horizons;
    td.window = (int)(frames < 16 ? 16 : frames); /* every frame's error stays in the window: exact quantiles */
    pred_error_tracker tracker;
    if (!pred_error_tracker_init(&tracker, &td)) {
        snprintf(err, err_size, "predict-eval: invalid horizons or out of memory");
        return false;
    }
    pred_predictor pred;
    pred_predictor_init(&pred, &desc->predictor);
    double t_end = desc->path->poses[desc->path->count - 1].t;
    pred_pose sample;
    bool have_sample = hmd_sim_next(&sim, &sample);
    for (uint64_t f = 0; f < frames; f++) {
        double tf = hmd_display_time(&sim, f);
        /* late latch: every sample measured up to the refresh is in */
        while (have_sample && sample.t <= tf) {
            out->samples++;
            if (!pred_predictor_update(&pred, &sample))
                out->dropped_samples++;
            have_sample = hmd_sim_next(&sim, &sample);
        }
        if (!pred.history.count)
            continue;
        out->frames++;
        for (int h = 0; h < tracker.horizon_count; h++) {
            double target = tf + tracker.horizons_s[h];
            if (target > t_end)
                continue;
            pred_pose predicted, truth;
            pred_predictor_predict(&pred, target, &predicted);
            pred_path_sample(desc->path, target, &truth);
            pred_error_tracker_record(&tracker, h, pred_vec3_dist(predicted.p, truth.p),
                                      pred_quat_angle_deg(predicted.q, truth.q));
        }
    }
    out->horizon_count = tracker.horizon_count;
    for (int h = 0; h < tracker.horizon_count; h++) {
        out->horizons_s[h] = tracker.horizons_s[h];
        pred_error_tracker_stats(&tracker, h, &out->pos[h], &out->rot[h]);
    }
    pred_error_tracker_free(&tracker);
    return true;
}

void pred_eval_print_header(FILE* f)
{
    fprintf(f, "| path | predictor | horizon ms | pos p50 mm | pos p99 mm | rot p50 deg | rot p99 deg |\n");
    fprintf(f, "|---|---|---:|---:|---:|---:|---:|\n");
}

void pred_eval_print_rows(FILE* f, const char* path_name, pred_kind kind, const pred_eval_result* r)
{
    for (int h = 0; h < r->horizon_count; h++)
        fprintf(f, "| %s | %s | %.0f | %.2f | %.2f | %.3f | %.3f |\n", path_name, pred_kind_name(kind),
                r->horizons_s[h] * 1e3, r->pos[h].p50 * 1e3, r->pos[h].p99 * 1e3, r->rot[h].p50, r->rot[h].p99);
}
