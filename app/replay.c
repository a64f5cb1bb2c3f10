#define _POSIX_C_SOURCE 200809L
#include "replay.h"

#include "app_scene.h"
#include "clock.h"
#include "pvs_pipeline.h"
#include "image_compare.h"
#include "interrupt.h"
#include "replay_log.h"
#include "replay_plots.h"
#include "log.h"
#include "ssim.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef struct replay_state {
    const tv_replay_desc* d;
    tv_app_scene s;
    pred_path path;
    hmd_sim sim;
    tv_pvs_pipeline pipe;
    tv_replay_log* log;
    rnd_target* target;
    uint8_t *rgba_full, *rgba_pvs;
    double* ssim_scratch;
    uint32_t* ids_full;
    tv_worst_frame worst;
    pred_pose sample;
    bool have_sample;
    float eye_fov_v;
} replay_state;

/* Feeds every sensor sample up to time t to the PVS pipeline, whose newest
 * one is the latched pose. */
static void feed_samples(replay_state* st, double t)
{
    while (st->have_sample && st->sample.t <= t) {
        tv_pvs_pipeline_observe(&st->pipe, &st->sample);
        st->have_sample = hmd_sim_next(&st->sim, &st->sample);
    }
}

/* One CSV token per coverage result (the predict module's names are prose). */
static const char* miss_token(pred_viewcell_miss why)
{
    switch (why) {
    case PRED_VC_COVERED: return "covered";
    case PRED_VC_MISS_AXIAL: return "axial";
    case PRED_VC_MISS_RADIAL: return "radial";
    case PRED_VC_MISS_FRUSTUM: return "frustum";
    }
    return "unknown";
}

static double pvs_fraction(const replay_state* st)
{
    uint32_t n = st->s.scene.triangle_count;
    return n ? (double)st->pipe.current.r.count / n : 0.0;
}

static bool log_pvs(replay_state* st, char* err, size_t err_size)
{
    const tv_pvs_result* r = &st->pipe.current.r;
    tv_pvs_row row = {.id = r->id, .t_request = r->t_request, .t_available = r->t_available, .vc = &r->vc,
                      .tris = r->count, .compute_ms = r->compute_ms};
    if (tv_replay_log_pvs(st->log, &row))
        return true;
    snprintf(err, err_size, "%s/pvs.csv: write failed", st->d->out_dir);
    return false;
}

/* One frames.csv row for eye e; `render`: draw and compare the images, else
 * a coverage-only row (an uncovered frame that --every skips); `whole`: the
 * frame draws every triangle instead of the PVS. */
static bool log_eye(replay_state* st, uint64_t frame, double t_frame, double t_submit, int e, const pred_pose* eye,
                    const pred_pose* predicted_eye, pred_viewcell_miss why, bool render, bool whole, char* err,
                    size_t err_size)
{
    const tv_pvs_slot* cur = &st->pipe.current;
    const scn_scene* scene = &st->s.scene;
    size_t pixels = (size_t)st->d->width * st->d->height;
    rnd_draw_stats full_st = {0}, pvs_st = {0};
    if (render) {
        /* movers at the frame's submit time, the clock the PVS windows are measured on */
        const rnd_gpu_scene* gpu = tv_app_scene_at(&st->s, t_submit, err, err_size);
        if (!gpu)
            return false;
        rnd_camera cam = tv_camera_at_pose(eye, st->eye_fov_v, st->d->near_m, st->d->far_m);
        if (!rnd_draw(st->s.ctx, st->target, gpu, &cam, NULL, 0, &full_st) ||
            !rnd_target_read_color(st->s.ctx, st->target, st->rgba_full) ||
            !rnd_target_read_ids(st->s.ctx, st->target, st->ids_full) ||
            !rnd_draw(st->s.ctx, st->target, gpu, &cam, whole ? NULL : cur->r.ids, whole ? 0 : cur->r.count,
                      &pvs_st) ||
            !rnd_target_read_color(st->s.ctx, st->target, st->rgba_pvs)) {
            snprintf(err, err_size, "rendering frame %llu failed (Vulkan error logged)", (unsigned long long)frame);
            return false;
        }
    }
    tv_frame_row row = {
        .frame = frame,
        .t = t_frame,
        .eye = e,
        .pose = *eye,
        .pose_age_ms = (t_submit - st->pipe.last.t) * 1e3,
        .predicted = *predicted_eye,
        .pred_err_pos_m = pred_vec3_dist(eye->p, predicted_eye->p),
        .pred_err_rot_deg = pred_quat_angle_deg(eye->q, predicted_eye->q),
        .pred_horizon_ms = (t_submit - cur->r.t_request) * 1e3,
        .delta_m = cur->r.vc.delta,
        .fov_pvs_deg = cur->r.vc.fov_pvs_deg,
        .pvs_id = cur->r.id,
        .pvs_age_ms = (t_submit - cur->r.t_request) * 1e3,
        .inside = why == PRED_VC_COVERED,
        .miss_reason = miss_token(why),
        .pvs_tris = whole ? scene->triangle_count : cur->r.count,
        .pvs_fraction = whole ? 1.0 : pvs_fraction(st),
        .static_pvs_fraction = whole ? 1.0
                                     : (double)(cur->r.count - cur->dynamic_count) /
                                           (scene->triangle_count - scene->dynamic_triangle_count),
        .dynamic_pvs_fraction = whole ? 1.0
                                : scene->dynamic_triangle_count
                                    ? (double)cur->dynamic_count / scene->dynamic_triangle_count
                                    : 0.0,
        .pvs_compute_ms = cur->r.compute_ms,
        .rendered = render,
        .pvs_frusta = cur->r.vc.frusta,
        .whole_scene = whole,
    };
    if (render) {
        row.psnr_db = rnd_psnr_rgb8(st->rgba_full, st->rgba_pvs, pixels, 4);
        row.fn_pixels = whole ? 0 : rnd_count_fn_pixels(st->ids_full, pixels, cur->mask, scene->triangle_count);
        row.dynamic_fn_pixels =
            whole ? 0
                  : rnd_count_fn_pixels_from(st->ids_full, pixels, cur->mask, scene->triangle_count,
                                             scene->triangle_count - scene->dynamic_triangle_count);
        row.diff_pixels = rnd_count_diff_pixels(st->rgba_full, st->rgba_pvs, pixels, 4, 0);
        /* GPU time where the device has timestamps: on a single-queue device
         * the wall clock would include waiting behind the PVS worker's work */
        row.render_pvs_ms = pvs_st.gpu_ms >= 0.0 ? pvs_st.gpu_ms : pvs_st.cpu_ms;
        row.render_full_ms = full_st.gpu_ms >= 0.0 ? full_st.gpu_ms : full_st.cpu_ms;
        row.ssim = rnd_ssim_rgb8(st->rgba_full, st->rgba_pvs, st->d->width, st->d->height, 4, st->ssim_scratch);
        if (!whole)
            tv_worst_frame_offer(&st->worst, row.psnr_db, frame, e, st->rgba_full, st->rgba_pvs, st->ids_full,
                                 cur->mask, st->s.scene.triangle_count);
    }
    if (!tv_replay_log_row(st->log, &row)) {
        snprintf(err, err_size, "%s/frames.csv: write failed", st->d->out_dir);
        return false;
    }
    return true;
}

static void progress(const replay_state* st, uint64_t frame, uint64_t frames, double wall0)
{
    if (!st->d->progress)
        return;
    int width = 30, done = (int)(width * (frame + 1) / frames);
    double elapsed = (tv_now_ms() - wall0) * 1e-3;
    double eta = frame + 1 < frames ? elapsed * (double)(frames - frame - 1) / (double)(frame + 1) : 0.0;
    fprintf(stderr, "\r[%.*s%*s] %3d%% frame %llu/%llu, PVS %u, %.0f s left ", done,
            "##############################", width - done, "", (int)(100 * (frame + 1) / frames),
            (unsigned long long)frame + 1, (unsigned long long)frames, st->pipe.current.r.id, eta);
    if (frame + 1 == frames)
        fputc('\n', stderr);
}

static bool run_loop(replay_state* st, uint64_t frames, char* err, size_t err_size)
{
    const tv_replay_desc* d = st->d;
    double cpu_s = d->cpu_ms * 1e-3;
    double frame_s = 1.0 / st->sim.desc.display_rate_hz;
    double wall0 = tv_now_ms();
    /* a signal stops the run between frames: every row written is complete */
    for (uint64_t k = 0; k < frames && !tv_interrupted(); k++) {
        double t_frame = hmd_display_time(&st->sim, k);
        double t_submit = t_frame + cpu_s;
        /* late latching: the pose is the newest sample at submit time;
         * without it, the newest at the frame's start */
        feed_samples(st, d->no_late_latch ? t_frame : t_submit);
        pred_pose head = st->pipe.last;
        feed_samples(st, t_submit);
        tv_pvs_pipeline_track(&st->pipe, t_submit);

        int stepped = tv_pvs_pipeline_step(&st->pipe, t_submit, frame_s, true, err, err_size);
        if (stepped < 0)
            return false;
        if (stepped == 1 && !log_pvs(st, err, err_size))
            return false;

        pred_pose predicted_head;
        tv_pvs_pipeline_predicted(&st->pipe, t_submit, &predicted_head);
        tv_replay_log_prediction(st->log, pred_vec3_dist(head.p, predicted_head.p),
                                 pred_quat_angle_deg(head.q, predicted_head.q));
        /* coverage is cheap geometry: every display frame, whatever --every says */
        pred_pose eyes[2], predicted_eyes[2];
        pred_viewcell_miss why[2] = {PRED_VC_COVERED, PRED_VC_COVERED};
        hmd_eye_poses(&st->sim, &head, eyes);
        const pred_viewcell* vc = &st->pipe.current.r.vc;
        bool whole = tv_pvs_pipeline_whole_scene(&st->pipe, t_submit), covered = true;
        for (int e = 0; e < 2 && !whole; e++)
            covered &= pred_viewcell_contains(vc, eyes[e].p, eyes[e].q, d->viewcell.display_fov_h_deg,
                                              st->eye_fov_v, &why[e]);
        tv_replay_log_coverage(st->log, covered, whole, whole ? 1.0 : pvs_fraction(st), vc->delta, vc->fov_pvs_deg);
        bool render = !d->coverage_only && k % (uint64_t)d->every == 0;
        if (render || !covered) {
            hmd_eye_poses(&st->sim, &predicted_head, predicted_eyes);
            for (int e = 0; e < 2; e++)
                if (!log_eye(st, k, t_frame, t_submit, e, &eyes[e], &predicted_eyes[e], why[e], render, whole,
                             err, err_size))
                    return false;
        }
        progress(st, k, frames, wall0);
    }
    return true;
}

static bool setup(replay_state* st, char* err, size_t err_size)
{
    const tv_replay_desc* d = st->d;
    size_t pixels = (size_t)d->width * d->height;
    hmd_sim_init(&st->sim, &d->hmd, &st->path);
    st->eye_fov_v = rnd_fov_y_from_x(d->viewcell.display_fov_h_deg, (float)d->width / (float)d->height);
    tv_pvs_pipeline_desc pd = {.method = d->method, .predictor = d->predictor, .viewcell = d->viewcell,
                               .latency_model = d->latency_model, .latency_s = d->latency_s,
                               .latency_factor = d->latency_factor, .no_pvs = d->coverage_only};
    if (!tv_pvs_pipeline_start(&st->pipe, &pd, st->s.ctx, &st->s.scene, st->s.gpu, err, err_size))
        return false;
    st->target = rnd_target_create(st->s.ctx, d->width, d->height, err, err_size);
    st->rgba_full = malloc(pixels * 4);
    st->rgba_pvs = malloc(pixels * 4);
    st->ids_full = malloc(pixels * sizeof(uint32_t));
    st->ssim_scratch = malloc(rnd_ssim_scratch_count(d->width, d->height) * sizeof(double));
    if (!st->target || !st->rgba_full || !st->rgba_pvs || !st->ids_full || !st->ssim_scratch ||
        !tv_worst_frame_init(&st->worst, d->width, d->height)) {
        if (!err[0])
            snprintf(err, err_size, "out of memory");
        return false;
    }
    st->log = tv_replay_log_open(d->out_dir, err, err_size);
    return st->log != NULL;
}

/* The first PVS is computed before the display starts (a headset shows
 * nothing until it has one); its request time is the first frame's. With the
 * measured latency model the first compute only times the machine: its
 * window assumed 50 ms, so a second one, sized for the measured latency,
 * is what the display starts with. */
static bool first_pvs(replay_state* st, char* err, size_t err_size)
{
    double t0 = hmd_display_time(&st->sim, 0) + st->d->cpu_ms * 1e-3;
    st->have_sample = hmd_sim_next(&st->sim, &st->sample);
    feed_samples(st, t0);
    if (!tv_pvs_pipeline_first(&st->pipe, t0, 1.0 / st->sim.desc.display_rate_hz, err, err_size))
        return false;
    return log_pvs(st, err, err_size);
}

static void teardown(replay_state* st)
{
    tv_pvs_pipeline_stop(&st->pipe);
    if (st->target)
        rnd_target_destroy(st->s.ctx, st->target);
    free(st->rgba_full);
    free(st->rgba_pvs);
    free(st->ids_full);
    free(st->ssim_scratch);
    tv_worst_frame_free(&st->worst);
}

int tv_replay_run(const tv_replay_desc* d)
{
    char err[768] = "";
    replay_state st;
    memset(&st, 0, sizeof st);
    st.d = d;
    double wall0 = tv_now_ms();
    const char* spec;
    int status = tv_app_load_path(d->path, d->scene, &st.path, &spec);
    if (status != 0)
        return status;
    tv_interrupt_install(); /* a signal during the scene load stops the run before the first frame */
    if (!tv_app_scene_open_out(spec, d->out_dir, &st.s)) {
        pred_path_free(&st.path);
        return 1;
    }
    tv_replay_remove_outputs(d->out_dir);
    bool ok = setup(&st, err, sizeof err) && first_pvs(&st, err, sizeof err);
    uint64_t frames = hmd_display_frame_count(&st.sim);
    if (d->max_frames && d->max_frames < frames)
        frames = d->max_frames;
    ok = ok && run_loop(&st, frames, err, sizeof err);
    if (!ok)
        tv_log(TV_LOG_ERROR, "%s", err);
    int sig = tv_interrupted();
    if (sig && d->progress)
        fputc('\n', stderr); /* end the progress bar's line */
    if (st.log) {
        tv_replay_meta meta = {
            .scene = spec,
            .path = d->path,
            .method = pvs_method_name(d->method.kind),
            .predictor = pred_kind_name(d->predictor.kind),
            .policy = d->viewcell.policy == PRED_POLICY_FIXED ? "fixed" : "adaptive",
            .latency_model = st.pipe.latency_name,
            .scene_tris = st.s.scene.triangle_count,
            .dynamic_tris = st.s.scene.dynamic_triangle_count,
            .width = d->width,
            .height = d->height,
            .eye_fov_deg = d->viewcell.display_fov_h_deg,
            .display_frames = frames,
            .probe_requests = st.pipe.probes,
            .wall_s = (tv_now_ms() - wall0) * 1e-3,
            .interrupted = sig != 0,
        };
        char ferr[512] = "";
        if (!tv_replay_log_finish(st.log, d->out_dir, &meta, ok ? stdout : NULL, ferr, sizeof ferr)) {
            tv_log(TV_LOG_ERROR, "%s", ferr);
            ok = false;
        }
        if (ok && !tv_worst_frame_write(&st.worst, d->out_dir, ferr, sizeof ferr)) {
            tv_log(TV_LOG_ERROR, "%s", ferr);
            ok = false;
        }
        if (ok && d->plots && !sig)
            tv_replay_plots(d->out_dir);
    }
    if (ok && sig)
        tv_log(TV_LOG_ERROR, "interrupted by signal %d: %s/summary.json (\"interrupted\": true) and frames.csv hold "
               "the frames evaluated so far", sig, d->out_dir);
    teardown(&st);
    if (!tv_app_scene_close(&st.s))
        ok = false;
    pred_path_free(&st.path);
    return !ok ? 1 : sig ? tv_interrupt_status(sig) : 0;
}
