#include "replay_log.h"

#include "json.h"
#include "stats.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* growable array of doubles for the percentiles */
typedef struct series {
    double* v;
    size_t n, cap;
} series;

static bool series_push(series* s, double x)
{
    if (s->n == s->cap) {
        size_t cap = s->cap ? s->cap * 2 : 256;
        double* v = realloc(s->v, cap * sizeof *v);
        if (!v)
            return false;
        s->v = v;
        s->cap = cap;
    }
    s->v[s->n++] = x;
    return true;
}

struct tv_replay_log {
    FILE *csv, *pvs_csv;
    char csv_name[4200], pvs_csv_name[4200];
    series psnr, ssim, fn, pvs_fraction, static_fraction, dynamic_fraction, dynamic_fn, delta, fov, render_full,
        render_pvs, pvs_ms, pred_pos, pred_rot, pose_age;
    uint64_t rows, misses, identical, coverage_frames, omni_pvs, clamped_pvs, whole_scene_frames, whole_scene_pvs;
    double sum_mse;
};

static const char* k_header =
    "frame,t,eye,px,py,pz,qx,qy,qz,qw,pose_age_ms,"
    "pred_px,pred_py,pred_pz,pred_qx,pred_qy,pred_qz,pred_qw,pred_err_pos_m,pred_err_rot_deg,pred_horizon_ms,"
    "delta_m,fov_pvs_deg,pvs_id,pvs_age_ms,inside_viewcell,miss_reason,pvs_tris,pvs_fraction,"
    "psnr_db,fn_pixels,diff_pixels,pvs_compute_ms,render_pvs_ms,render_full_ms,ssim,rendered,pvs_frusta,whole_scene,"
    "dynamic_pvs_fraction,dynamic_fn_pixels\n";

/* pvs.csv: the viewcell as `trimvr pvs --pos --dir --up --delta --fov-pvs`
 * takes it (docs/replay.md). */
static const char* k_pvs_header =
    "pvs_id,t_request,t_available,t_begin,t_end,v0_x,v0_y,v0_z,forward_x,forward_y,forward_z,up_x,up_y,up_z,"
    "delta_m,fov_pvs_deg,apex_offset_m,frusta,clamped,whole_scene,pvs_tris,compute_ms\n";

static FILE* open_csv(const char* name, const char* header)
{
    FILE* f = fopen(name, "w");
    if (f && (fputs(header, f) < 0 || fflush(f) != 0)) {
        fclose(f);
        return NULL;
    }
    return f;
}

tv_replay_log* tv_replay_log_open(const char* dir, char* err, size_t err_size)
{
    tv_replay_log* log = calloc(1, sizeof *log);
    if (!log) {
        snprintf(err, err_size, "out of memory");
        return NULL;
    }
    snprintf(log->csv_name, sizeof log->csv_name, "%s/frames.csv", dir);
    snprintf(log->pvs_csv_name, sizeof log->pvs_csv_name, "%s/pvs.csv", dir);
    log->csv = open_csv(log->csv_name, k_header);
    log->pvs_csv = log->csv ? open_csv(log->pvs_csv_name, k_pvs_header) : NULL;
    if (!log->pvs_csv) {
        snprintf(err, err_size, "%s: cannot write", log->csv ? log->pvs_csv_name : log->csv_name);
        if (log->csv)
            fclose(log->csv);
        free(log);
        return NULL;
    }
    return log;
}

bool tv_replay_log_row(tv_replay_log* log, const tv_frame_row* r)
{
    const pred_pose* p = &r->pose;
    const pred_pose* q = &r->predicted;
    /* psnr_db,fn_pixels,diff_pixels, the two render times and ssim: empty on a coverage-only row */
    char image[160] = ",,", render[96] = ",,", dynamic_fn[32] = "";
    if (r->rendered) {
        snprintf(image, sizeof image, "%.3f,%llu,%llu", isinf(r->psnr_db) ? INFINITY : r->psnr_db,
                 (unsigned long long)r->fn_pixels, (unsigned long long)r->diff_pixels);
        snprintf(render, sizeof render, "%.3f,%.3f,%.6f", r->render_pvs_ms, r->render_full_ms, r->ssim);
        snprintf(dynamic_fn, sizeof dynamic_fn, "%llu", (unsigned long long)r->dynamic_fn_pixels);
    }
    int n = fprintf(log->csv,
                    "%llu,%.6f,%s,%.6f,%.6f,%.6f,%.7f,%.7f,%.7f,%.7f,%.3f,"
                    "%.6f,%.6f,%.6f,%.7f,%.7f,%.7f,%.7f,%.6f,%.4f,%.3f,"
                    "%.4f,%.3f,%u,%.3f,%d,%s,%u,%.6f,"
                    "%s,%.3f,%s,%d,%d,%d,%.6f,%s\n",
                    (unsigned long long)r->frame, r->t, r->eye == 0 ? "left" : "right", p->p[0], p->p[1], p->p[2],
                    p->q[0], p->q[1], p->q[2], p->q[3], r->pose_age_ms, q->p[0], q->p[1], q->p[2], q->q[0], q->q[1],
                    q->q[2], q->q[3], r->pred_err_pos_m, r->pred_err_rot_deg, r->pred_horizon_ms, r->delta_m,
                    r->fov_pvs_deg, r->pvs_id, r->pvs_age_ms, r->inside ? 1 : 0, r->miss_reason, r->pvs_tris,
                    r->pvs_fraction, image, r->pvs_compute_ms, render, r->rendered ? 1 : 0, r->pvs_frusta,
                    r->whole_scene ? 1 : 0, r->dynamic_pvs_fraction, dynamic_fn);
    /* flushing every row is what lets an interrupted replay keep its log */
    if (n < 0 || fflush(log->csv) != 0)
        return false;
    if (!r->rendered)
        return true;
    log->rows++;
    if (isinf(r->psnr_db))
        log->identical++;
    else
        log->sum_mse += 255.0 * 255.0 / pow(10.0, r->psnr_db / 10.0);
    if (!isnan(r->ssim) && !series_push(&log->ssim, r->ssim))
        return false;
    return series_push(&log->psnr, r->psnr_db) && series_push(&log->fn, (double)r->fn_pixels) &&
           series_push(&log->static_fraction, r->static_pvs_fraction) &&
           series_push(&log->dynamic_fraction, r->dynamic_pvs_fraction) &&
           series_push(&log->dynamic_fn, (double)r->dynamic_fn_pixels) && series_push(&log->render_full, r->render_full_ms) &&
           series_push(&log->render_pvs, r->render_pvs_ms) && series_push(&log->pose_age, r->pose_age_ms);
}

void tv_replay_log_coverage(tv_replay_log* log, bool covered, bool whole_scene, double pvs_fraction, double delta_m,
                            double fov_pvs_deg)
{
    log->coverage_frames++;
    log->misses += !covered;
    log->whole_scene_frames += whole_scene;
    series_push(&log->pvs_fraction, pvs_fraction);
    if (!whole_scene) {
        series_push(&log->delta, delta_m);
        series_push(&log->fov, fov_pvs_deg);
    }
}

bool tv_replay_log_pvs(tv_replay_log* log, const tv_pvs_row* r)
{
    const pred_viewcell* vc = r->vc;
    /* %.9g: a float's every digit, so the viewcell is computed again bit for bit */
    int n = fprintf(log->pvs_csv,
                    "%u,%.6f,%.6f,%.6f,%.6f,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,"
                    "%d,%d,%d,%u,%.3f\n",
                    r->id, r->t_request, r->t_available, vc->t_begin, vc->t_end, vc->v0[0], vc->v0[1], vc->v0[2],
                    vc->forward[0], vc->forward[1], vc->forward[2], vc->up[0], vc->up[1], vc->up[2], vc->delta,
                    vc->fov_pvs_deg, vc->z, vc->frusta, vc->clamped ? 1 : 0, vc->whole_scene ? 1 : 0, r->tris,
                    vc->whole_scene ? 0.0 : r->compute_ms);
    if (vc->whole_scene)
        log->whole_scene_pvs++;
    else {
        series_push(&log->pvs_ms, r->compute_ms);
        log->omni_pvs += vc->frusta > 1;
        log->clamped_pvs += vc->clamped;
    }
    return n >= 0 && fflush(log->pvs_csv) == 0;
}

void tv_replay_log_prediction(tv_replay_log* log, double pos_err_m, double rot_err_deg)
{
    series_push(&log->pred_pos, pos_err_m);
    series_push(&log->pred_rot, rot_err_deg);
}

double tv_replay_log_worst_psnr(const tv_replay_log* log)
{
    return tv_percentile(log->psnr.v, log->psnr.n, 0.0);
}

static void free_series(tv_replay_log* log)
{
    series* all[] = {&log->psnr,       &log->ssim,        &log->fn,         &log->pvs_fraction,
                     &log->static_fraction, &log->dynamic_fraction, &log->dynamic_fn,
                     &log->delta,      &log->fov,         &log->render_full, &log->render_pvs,
                     &log->pvs_ms,     &log->pred_pos,    &log->pred_rot,   &log->pose_age};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; i++)
        free(all[i]->v);
}

bool tv_replay_log_finish(tv_replay_log* log, const char* dir, const tv_replay_meta* m, FILE* table, char* err,
                          size_t err_size)
{
    struct {
        double psnr_mean, psnr_min, psnr_p5, ssim_mean, ssim_p5, fn_mean, fn_max, pvs_fraction, delta, fov, pvs_ms, pvs_ms_median,
            full_ms, pvs_render_ms, pred_pos_p99, pred_rot_p99, pose_age, static_fraction, dynamic_fraction, dynamic_fn;
    } sm = {
        /* PSNR of the mean squared error: identical frames (PSNR +inf) count as zero error */
        .psnr_mean = log->rows == 0 ? NAN
                     : log->sum_mse > 0.0 ? 10.0 * log10(255.0 * 255.0 / (log->sum_mse / (double)log->rows))
                                          : INFINITY,
        .psnr_min = tv_percentile(log->psnr.v, log->psnr.n, 0.0),
        .psnr_p5 = tv_percentile(log->psnr.v, log->psnr.n, 5.0),
        .ssim_mean = tv_mean(log->ssim.v, log->ssim.n),
        .ssim_p5 = tv_percentile(log->ssim.v, log->ssim.n, 5.0),
        .fn_mean = tv_mean(log->fn.v, log->fn.n),
        .fn_max = tv_percentile(log->fn.v, log->fn.n, 100.0),
        .pvs_fraction = tv_mean(log->pvs_fraction.v, log->pvs_fraction.n),
        .delta = tv_mean(log->delta.v, log->delta.n),
        .fov = tv_mean(log->fov.v, log->fov.n),
        .pvs_ms = tv_mean(log->pvs_ms.v, log->pvs_ms.n),
        .pvs_ms_median = tv_percentile(log->pvs_ms.v, log->pvs_ms.n, 50.0),
        .full_ms = tv_mean(log->render_full.v, log->render_full.n),
        .pvs_render_ms = tv_mean(log->render_pvs.v, log->render_pvs.n),
        .pred_pos_p99 = tv_percentile(log->pred_pos.v, log->pred_pos.n, 99.0),
        .pred_rot_p99 = tv_percentile(log->pred_rot.v, log->pred_rot.n, 99.0),
        .pose_age = tv_mean(log->pose_age.v, log->pose_age.n),
        .static_fraction = tv_mean(log->static_fraction.v, log->static_fraction.n),
        .dynamic_fraction = tv_mean(log->dynamic_fraction.v, log->dynamic_fraction.n),
        .dynamic_fn = tv_mean(log->dynamic_fn.v, log->dynamic_fn.n),
    };

    char name[4200];
    snprintf(name, sizeof name, "%s/summary.json", dir);
    FILE* f = fopen(name, "w");
    bool ok = f != NULL;
    if (f) {
        fprintf(f, "{\n");
        fprintf(f, "  \"scene\": \"%s\",\n  \"path\": \"%s\",\n  \"method\": \"%s\",\n", m->scene, m->path, m->method);
        fprintf(f, "  \"predictor\": \"%s\",\n  \"policy\": \"%s\",\n", m->predictor, m->policy);
        fprintf(f, "  \"latency_model\": \"%s\",\n", m->latency_model);
        fprintf(f, "  \"scene_tris\": %u,\n  \"width\": %u,\n  \"height\": %u,\n", m->scene_tris, m->width, m->height);
        fprintf(f, "  \"eye_fov_deg\": %.3f,\n", m->eye_fov_deg);
        fprintf(f, "  \"display_frames\": %llu,\n", (unsigned long long)m->display_frames);
        fprintf(f, "  \"interrupted\": %s,\n", m->interrupted ? "true" : "false");
        fprintf(f, "  \"frames\": %llu,\n", (unsigned long long)log->rows);
        fprintf(f, "  \"identical_frames\": %llu,\n", (unsigned long long)log->identical);
        fprintf(f, "  \"coverage_frames\": %llu,\n", (unsigned long long)log->coverage_frames);
        fprintf(f, "  \"viewcell_miss_frames\": %llu,\n", (unsigned long long)log->misses);
        fprintf(f, "  \"pvs_count\": %zu,\n", log->pvs_ms.n);
        fprintf(f, "  \"omni_pvs_count\": %llu,\n", (unsigned long long)log->omni_pvs);
        fprintf(f, "  \"clamped_pvs_count\": %llu,\n", (unsigned long long)log->clamped_pvs);
        fprintf(f, "  \"whole_scene_pvs_count\": %llu,\n", (unsigned long long)log->whole_scene_pvs);
        fprintf(f, "  \"whole_scene_frames\": %llu,\n", (unsigned long long)log->whole_scene_frames);
        fprintf(f, "  \"probe_pvs_count\": %u,\n", m->probe_requests);
        const struct {
            const char* key;
            double v;
        } nums[] = {
            {"psnr_mean_db", sm.psnr_mean},          {"psnr_min_db", sm.psnr_min},
            {"psnr_p5_db", sm.psnr_p5},              {"ssim_mean", sm.ssim_mean},
            {"ssim_p5", sm.ssim_p5},                 {"fn_pixels_mean", sm.fn_mean},
            {"fn_pixels_max", sm.fn_max},            {"pvs_fraction_mean", sm.pvs_fraction},
            {"delta_mean_m", sm.delta},              {"fov_pvs_mean_deg", sm.fov},
            {"pvs_ms_mean", sm.pvs_ms},              {"pvs_ms_median", sm.pvs_ms_median},
            {"render_full_ms_mean", sm.full_ms},     {"render_pvs_ms_mean", sm.pvs_render_ms},
            {"pred_err_pos_p99_m", sm.pred_pos_p99}, {"pred_err_rot_p99_deg", sm.pred_rot_p99},
            {"pose_age_ms_mean", sm.pose_age},       {"wall_s", m->wall_s},
            {"static_pvs_fraction_mean", sm.static_fraction},
            {"dynamic_pvs_fraction", sm.dynamic_fraction},
            {"dynamic_fn_pixels_mean", sm.dynamic_fn},
        };
        size_t count = sizeof nums / sizeof nums[0];
        for (size_t i = 0; i < count; i++) {
            fputs("  ", f);
            tv_json_num(f, nums[i].key, nums[i].v, i + 1 < count ? ",\n" : "\n");
        }
        fprintf(f, "}\n");
        ok = fclose(f) == 0;
    }
    if (!ok)
        snprintf(err, err_size, "%s: cannot write", name);
    if (table) {
        fprintf(table, "\n trimvr replay: %s along %s\n", m->scene, m->path);
        fprintf(table, " method %s, predictor %s, policy %s, latency %s, %ux%u, eye FOV %.0f deg\n", m->method,
                m->predictor, m->policy, m->latency_model, m->width, m->height, m->eye_fov_deg);
        fprintf(table, " -------------------------------------------------------------------\n");
        fprintf(table, " frames evaluated      %8llu   (of %llu display frames, %llu identical)\n",
                (unsigned long long)log->rows, (unsigned long long)m->display_frames,
                (unsigned long long)log->identical);
        if (log->rows) { /* an interrupted run may have none: no means to print */
            fprintf(table, " PSNR mean / p5 / min  %8.2f / %.2f / %.2f dB\n", sm.psnr_mean, sm.psnr_p5, sm.psnr_min);
            fprintf(table, " SSIM mean / p5        %8.4f / %.4f\n", sm.ssim_mean, sm.ssim_p5);
            fprintf(table, " FN pixels mean / max  %8.2f / %.0f\n", sm.fn_mean, sm.fn_max);
        }
        fprintf(table, " viewcell misses       %8llu of %llu display frames (every frame checked)\n",
                (unsigned long long)log->misses, (unsigned long long)log->coverage_frames);
        fprintf(table, " whole scene drawn     %8llu display frames (%llu whole-scene PVSs, %u probes)\n",
                (unsigned long long)log->whole_scene_frames, (unsigned long long)log->whole_scene_pvs,
                m->probe_requests);
        if (log->rows) {
            fprintf(table, " PVS size              %8.2f %% of %u triangles\n", 100.0 * sm.pvs_fraction, m->scene_tris);
            if (m->dynamic_tris)
                fprintf(table, " movers: PVS / FN px   %8.2f %% of %u moving triangles (static %.2f %%) / %.2f mean\n",
                        100.0 * sm.dynamic_fraction, m->dynamic_tris, 100.0 * sm.static_fraction, sm.dynamic_fn);
            fprintf(table, " delta / PVS FOV       %8.3f m / %.1f deg (means)\n", sm.delta, sm.fov);
        }
        fprintf(table, " PVS compute           %8.1f ms mean over %zu PVSs (%llu over all directions, %llu clamped)\n",
                sm.pvs_ms, log->pvs_ms.n, (unsigned long long)log->omni_pvs, (unsigned long long)log->clamped_pvs);
        if (log->rows) {
            fprintf(table, " render full / PVS     %8.2f / %.2f ms mean\n", sm.full_ms, sm.pvs_render_ms);
            fprintf(table, " prediction p99        %8.4f m / %.3f deg\n", sm.pred_pos_p99, sm.pred_rot_p99);
        }
        fprintf(table, " wall time             %8.1f s\n", m->wall_s);
    }
    fclose(log->csv);
    fclose(log->pvs_csv);
    free_series(log);
    free(log);
    return ok;
}
