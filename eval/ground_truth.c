#include "ground_truth.h"

#include "clock.h"
#include "gt_cache.h"
#include "log.h"
#include "gt_seethrough.h"
#include "image_compare.h"
#include "ssim.h"
#include "stats.h"

#include <assert.h>
#include <cglm/cglm.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <stdio.h>

#define GOLDEN_ANGLE 2.39996322972865332

static void resolve_desc(const pvs_eval_desc* in, const pred_viewcell* vc, pvs_eval_desc* d)
{
    *d = in ? *in : (pvs_eval_desc){0};
    if (!d->samples)
        d->samples = 200;
    if (!d->width || !d->height) {
        d->width = 640;
        d->height = 360;
    }
    if (!(d->eye_fov_h_deg > 0.0f))
        d->eye_fov_h_deg = vc->fov_target_deg;
    if (!(d->near_m > 0.0f))
        d->near_m = 0.05f;
    if (!(d->far_m > d->near_m))
        d->far_m = 500.0f;
}

/* splitmix64: a stateless hash of (seed, sample, dimension) gives every
 * sample its own reproducible jitter, independent of how many were rejected. */
static double jitter(uint32_t seed, uint32_t sample, uint32_t dim)
{
    uint64_t z = ((uint64_t)seed << 40) ^ ((uint64_t)sample << 8) ^ dim;
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

typedef struct cell_frame {
    double v0[3], f[3], u[3], r[3];
    double base_q[4];
} cell_frame;

static cell_frame make_frame(const pred_viewcell* vc)
{
    cell_frame c;
    vec3 f = {vc->forward[0], vc->forward[1], vc->forward[2]}, u = {vc->up[0], vc->up[1], vc->up[2]}, r;
    glm_vec3_normalize(f);
    glm_vec3_crossn(f, u, r);
    glm_vec3_cross(r, f, u);
    for (int i = 0; i < 3; i++) {
        c.v0[i] = vc->v0[i];
        c.f[i] = f[i];
        c.u[i] = u[i];
        c.r[i] = r[i];
    }
    pred_quat_look(c.f, c.u, c.base_q);
    return c;
}

/* Sample i's candidate pose for attempt `shrink` (1, 0.9, 0.81, ...):
 * stratified axial position, alternately on the cone surface and inside,
 * golden-angle azimuths, and yaw/pitch offsets whose extremes are reached by
 * every fourth sample. */
static void candidate(const pred_viewcell* vc, const cell_frame* c, const pvs_eval_desc* d, float eye_fov_v,
                      uint32_t i, uint32_t n, double shrink, double p[3], double q[4])
{
    double a = vc->z * (2.0 * ((i + jitter(d->seed, i, 0)) / n) - 1.0) * shrink;
    double rmax = vc->delta * (1.0 - fabs(a) / (vc->z > 0 ? vc->z : 1.0));
    double r = (i % 2 == 0 ? rmax : rmax * sqrt(jitter(d->seed, i, 1))) * shrink;
    double phi = GOLDEN_ANGLE * i + 2.0 * PRED_PI * jitter(d->seed, i, 2) / n;
    for (int k = 0; k < 3; k++)
        p[k] = c->v0[k] + a * c->f[k] + r * (cos(phi) * c->r[k] + sin(phi) * c->u[k]);

    double alpha = 0.5 * vc->fov_pvs_deg * PRED_DEG;
    double yaw_max = alpha - 0.5 * d->eye_fov_h_deg * PRED_DEG;
    double pitch_max = alpha - 0.5 * eye_fov_v * PRED_DEG;
    yaw_max = yaw_max > 0 ? yaw_max : 0;
    pitch_max = pitch_max > 0 ? pitch_max : 0;
    double sy = 2.0 * jitter(d->seed, i, 3) - 1.0, sp = 2.0 * jitter(d->seed, i, 4) - 1.0;
    if (i % 4 == 1) { /* push to the rotation range's boundary */
        double m = fabs(sy) > fabs(sp) ? fabs(sy) : fabs(sp);
        sy /= m;
        sp /= m;
    }
    double local[4];
    pred_quat_from_ypr(sy * yaw_max * shrink, sp * pitch_max * shrink, 0.0, local);
    pred_quat_mul(c->base_q, local, q);
}

uint32_t pvs_gt_cameras(const pred_viewcell* vc, const pvs_eval_desc* in_desc, rnd_camera* cams, uint32_t n)
{
    assert(vc && cams);
    pvs_eval_desc d;
    resolve_desc(in_desc, vc, &d);
    float aspect = (float)d.width / (float)d.height;
    float fov_v = rnd_fov_y_from_x(d.eye_fov_h_deg, aspect);
    cell_frame c = make_frame(vc);
    uint32_t written = 0;
    for (uint32_t i = 0; i < n; i++) {
        double p[3], q[4];
        bool inside = false;
        /* the cone test is exact but the eye frustum test is conservative;
         * shrink towards the centre until the sample is covered */
        for (int attempt = 0; attempt < 40 && !inside; attempt++) {
            candidate(vc, &c, &d, fov_v, i, n, pow(0.9, attempt) * (1.0 - 1e-4), p, q);
            inside = pred_viewcell_contains(vc, p, q, d.eye_fov_h_deg, fov_v, NULL);
        }
        if (!inside)
            continue;
        rnd_camera* cam = &cams[written++];
        for (int k = 0; k < 3; k++)
            cam->position[k] = (float)p[k];
        for (int k = 0; k < 4; k++)
            cam->orientation[k] = (float)q[k];
        cam->fov_y_deg = fov_v;
        cam->near_m = d.near_m;
        cam->far_m = d.far_m;
    }
    return written;
}

void pvs_unreliable_mask(const scn_scene* scene, const pred_viewcell* vc, uint32_t width, uint32_t height,
                         uint8_t* unreliable)
{
    assert(scene && vc && unreliable && width && height);
    cell_frame c = make_frame(vc);
    double tan_half = tan(0.5 * vc->fov_pvs_deg * PRED_DEG);
    double focal = 0.5 * (width > height ? width : height) / tan_half; /* pixels per unit image plane */
    for (uint32_t t = 0; t < scene->triangle_count; t++) {
        double img[3][2];
        bool in_front = true;
        for (int k = 0; k < 3 && in_front; k++) {
            const float* p = &scene->positions[3 * scene->indices[3 * t + k]];
            double d[3] = {p[0] - c.v0[0], p[1] - c.v0[1], p[2] - c.v0[2]};
            double depth = d[0] * c.f[0] + d[1] * c.f[1] + d[2] * c.f[2];
            if (depth <= 1e-6) {
                in_front = false;
                break;
            }
            img[k][0] = focal * (d[0] * c.r[0] + d[1] * c.r[1] + d[2] * c.r[2]) / depth;
            img[k][1] = focal * (d[0] * c.u[0] + d[1] * c.u[1] + d[2] * c.u[2]) / depth;
        }
        if (!in_front) {
            unreliable[t] = 0;
            continue;
        }
        double ex = img[1][0] - img[0][0], ey = img[1][1] - img[0][1];
        double fx = img[2][0] - img[0][0], fy = img[2][1] - img[0][1];
        double area2 = fabs(ex * fy - ey * fx);
        double longest = 0.0;
        for (int k = 0; k < 3; k++) {
            double dx = img[(k + 1) % 3][0] - img[k][0], dy = img[(k + 1) % 3][1] - img[k][1];
            double len = sqrt(dx * dx + dy * dy);
            longest = len > longest ? len : longest;
        }
        /* smallest altitude = 2 * area / longest edge */
        unreliable[t] = longest <= 0.0 || area2 / longest < 1.0;
    }
}

double pvs_gt_richness_estimate(uint32_t observed, uint32_t once, uint32_t twice, uint32_t views)
{
    assert(views >= 1 && (uint64_t)once + twice <= observed);
    double q1 = once, q2 = twice;
    return observed + (views - 1.0) / views * q1 * (q1 - 1.0) / (2.0 * (q2 + 1.0));
}

typedef struct eval_buffers {
    uint32_t* ids;
    uint32_t* count;     /* per triangle: pixels of the current view, 0 between views */
    uint32_t* seen;      /* the current view's triangles, then ascending */
    uint32_t* seen_px;   /* ... and their pixels */
    uint8_t* views;      /* per triangle: sample views that saw it, saturating */
    uint8_t* full_rgba;
    uint8_t* pvs_rgba;
    uint8_t* unreliable;
    rnd_camera* cams;
    double* full_ms;
    double* pvs_ms;
    double* ssim_scratch;
} eval_buffers;

static void free_buffers(eval_buffers* b)
{
    free(b->ids);
    free(b->count);
    free(b->seen);
    free(b->seen_px);
    free(b->views);
    free(b->full_rgba);
    free(b->pvs_rgba);
    free(b->unreliable);
    free(b->cams);
    free(b->full_ms);
    free(b->pvs_ms);
    free(b->ssim_scratch);
}

static int cmp_u32(const void* a, const void* b)
{
    uint32_t x = *(const uint32_t*)a, y = *(const uint32_t*)b;
    return (x > y) - (x < y);
}

/* The triangles of one id buffer, ascending, with their pixels, into
 * b->seen / b->seen_px; returns how many. */
static uint32_t view_histogram(eval_buffers* b, size_t pixels, uint32_t triangle_count)
{
    uint32_t n = 0;
    for (size_t px = 0; px < pixels; px++) {
        uint32_t id = b->ids[px];
        if (id >= triangle_count)
            continue;
        if (b->count[id]++ == 0)
            b->seen[n++] = id;
    }
    qsort(b->seen, n, sizeof *b->seen, cmp_u32);
    for (uint32_t e = 0; e < n; e++) {
        b->seen_px[e] = b->count[b->seen[e]];
        b->count[b->seen[e]] = 0;
    }
    return n;
}

/* Opens the viewcell's cache entry: true when `rec` now holds its GT.
 * Otherwise rec is empty and, where the file was unusable, a warning says so. */
static bool cache_open(const pvs_eval_desc* d, const scn_scene* scene, const pred_viewcell* vc, uint32_t views,
                       char* file, size_t file_size, char* key, size_t key_size, pvs_gt_record* rec)
{
    char why[256];
    pvs_gt_cache_key(d->gt_cache_scene, vc, d, key, key_size);
    pvs_gt_cache_file(d->gt_cache_dir, key, file, file_size);
    if (pvs_gt_cache_load(file, key, scene->triangle_count, rec, why, sizeof why)) {
        if (rec->views == views) {
            tv_log(TV_LOG_INFO, "gt cache: read %s", file);
            return true;
        }
        snprintf(why, sizeof why, "%u views, %u expected", rec->views, views);
        pvs_gt_record_free(rec);
    }
    if (why[0])
        tv_log(TV_LOG_WARN, "gt cache: %s rejected (%s); recomputing", file, why);
    return false;
}

static void set_metrics(const scn_scene* scene, const uint8_t* pvs_mask, const uint8_t* gt,
                        const eval_buffers* b, uint32_t views, pvs_eval_result* out)
{
    uint32_t pvs = 0, gtc = 0, fp = 0, fn = 0, gt_rel = 0, fp_rel = 0, fn_rel = 0, once = 0, twice = 0;
    const uint8_t* unreliable = b->unreliable;
    for (uint32_t t = 0; t < scene->triangle_count; t++) {
        bool in_p = pvs_mask[t] != 0, in_g = gt[t] != 0;
        pvs += in_p;
        gtc += in_g;
        once += b->views[t] == 1;
        twice += b->views[t] == 2;
        fp += in_p && !in_g;
        fn += in_g && !in_p;
        if (!unreliable[t]) {
            gt_rel += in_g;
            fp_rel += in_p && !in_g;
            fn_rel += in_g && !in_p;
        }
    }
    out->scene_tris = scene->triangle_count;
    out->pvs_tris = pvs;
    out->gt_tris = gtc;
    out->fp_tris = fp;
    out->fn_tris = fn;
    out->gt_tris_reliable = gt_rel;
    double sc = scene->triangle_count ? (double)scene->triangle_count : 1.0;
    out->pvs_fraction = pvs / sc;
    out->gt_fraction = gtc / sc;
    out->fp_rate = gtc ? (double)fp / gtc : 0.0;
    out->fn_rate = gtc ? (double)fn / gtc : 0.0;
    out->fp_rate_reliable = gt_rel ? (double)fp_rel / gt_rel : 0.0;
    out->fn_rate_reliable = gt_rel ? (double)fn_rel / gt_rel : 0.0;
    out->gt_once = once;
    out->gt_twice = twice;
    out->gt_est_tris = pvs_gt_richness_estimate(gtc, once, twice, views);
    out->gt_completeness = out->gt_est_tris > 0.0 ? gtc / out->gt_est_tris : 1.0;
}

bool pvs_evaluate(rnd_context* ctx, const rnd_gpu_scene* gpu, const scn_scene* scene, const pred_viewcell* vc,
                  const uint8_t* pvs_mask, const uint32_t* pvs_ids, uint32_t pvs_count,
                  const pvs_eval_desc* in_desc, uint8_t* gt_mask, pvs_eval_result* out, char* err,
                  size_t err_size)
{
    assert(ctx && gpu && scene && vc && pvs_mask && out);
    double t0 = tv_now_ms();
    pvs_eval_desc d;
    resolve_desc(in_desc, vc, &d);
    memset(out, 0, sizeof *out);
    size_t pixels = (size_t)d.width * d.height, tris = scene->triangle_count ? scene->triangle_count : 1;
    size_t seen_max = pixels < tris ? pixels : tris;
    eval_buffers b = {
        .ids = malloc(pixels * sizeof(uint32_t)),
        .count = calloc(tris, sizeof(uint32_t)),
        .seen = malloc(seen_max * sizeof(uint32_t)),
        .seen_px = malloc(seen_max * sizeof(uint32_t)),
        .views = calloc(tris, 1),
        .full_rgba = malloc(pixels * 4),
        .pvs_rgba = malloc(pixels * 4),
        .unreliable = malloc(tris),
        .cams = malloc(d.samples * sizeof(rnd_camera)),
        .full_ms = malloc(d.samples * sizeof(double)),
        .pvs_ms = malloc(d.samples * sizeof(double)),
        .ssim_scratch = malloc(rnd_ssim_scratch_count(d.width, d.height) * sizeof(double)),
    };
    uint8_t* gt = gt_mask ? gt_mask : calloc(tris, 1);
    rnd_target* target = NULL;
    gt_seethrough see = {0};
    pvs_gt_record rec = {0};
    char key[2048], file[4400];
    bool ok = false;
    if (!b.ids || !b.count || !b.seen || !b.seen_px || !b.views || !b.full_rgba || !b.pvs_rgba || !b.unreliable ||
        !b.cams || !b.full_ms || !b.pvs_ms || !b.ssim_scratch || !gt || !gt_seethrough_init(&see, scene, pixels)) {
        snprintf(err, err_size, "ground truth: out of memory");
        goto done;
    }
    memset(gt, 0, scene->triangle_count);
    target = rnd_target_create(ctx, d.width, d.height, err, err_size);
    if (!target)
        goto done;
    pvs_unreliable_mask(scene, vc, d.width, d.height, b.unreliable);
    uint32_t n = pvs_gt_cameras(vc, &d, b.cams, d.samples);
    if (n == 0) {
        snprintf(err, err_size, "ground truth: no sample view fits the viewcell (delta %.3g m, fov %.3g deg)",
                 vc->delta, vc->fov_pvs_deg);
        goto done;
    }
    assert(!d.gt_cache_dir || d.gt_cache_scene);
    bool caching = d.gt_cache_dir && !see.blend_count && !(d.pose && scene->mover_count);
    if (d.gt_cache_dir && !caching)
        tv_log(TV_LOG_INFO, "gt cache: not used: the scene has %s", see.blend_count ? "see-through triangles" : "movers");
    bool cached = caching && cache_open(&d, scene, vc, n, file, sizeof file, key, sizeof key, &rec);
    double sum_sq = 0.0, fn_sum = 0.0, fn_rel_sum = 0.0, fn_dyn_sum = 0.0, gt_sum_ms = 0.0, ssim_sum = 0.0;
    uint32_t first_dynamic = scene->triangle_count - scene->dynamic_triangle_count, pvs_drawn = 0;
    out->psnr_min_db = INFINITY;
    for (uint32_t s = 0; s < n; s++) {
        rnd_draw_stats full_st, pvs_st;
        size_t fn = 0, fn_rel = 0;
        const uint32_t *seen = b.seen, *seen_px = b.seen_px;
        uint32_t seen_count;
        if (cached) {
            seen = rec.ids + rec.view_first[s];
            seen_px = rec.pixels + rec.view_first[s];
            seen_count = rec.view_first[s + 1] - rec.view_first[s];
        } else {
            if (d.pose && scene->mover_count) { /* golden-ratio times: every prefix spreads over the window */
                double u = fmod((s + 0.5) * 0.6180339887498949, 1.0);
                if (!(gpu = d.pose(d.pose_user, vc->t_begin + u * (vc->t_end - vc->t_begin), err, err_size)))
                    goto done;
            }
            double ts = tv_now_ms();
            bool drawn = rnd_draw(ctx, target, gpu, &b.cams[s], NULL, 0, &full_st) &&
                         rnd_target_read_ids(ctx, target, b.ids);
            gt_sum_ms += tv_now_ms() - ts; /* the ground truth's own cost: one id render per sample */
            if (!drawn || !rnd_target_read_color(ctx, target, b.full_rgba)) {
                snprintf(err, err_size, "ground truth: drawing sample view %u failed (Vulkan error logged)", s);
                goto done;
            }
            b.full_ms[s] = full_st.cpu_ms;
            if (see.blend_count &&
                !gt_seethrough_sample(&see, ctx, target, gpu, &b.cams[s], pixels, pvs_mask, b.unreliable,
                                      scene->triangle_count, b.ids, gt, &fn, &fn_rel)) {
                snprintf(err, err_size, "ground truth: the see-through pass of sample view %u failed (Vulkan error logged)", s);
                goto done;
            }
            seen_count = view_histogram(&b, pixels, scene->triangle_count);
            if (caching && !pvs_gt_record_add_view(&rec, seen, seen_px, seen_count)) {
                snprintf(err, err_size, "ground truth: out of memory");
                goto done;
            }
        }
        for (uint32_t e = 0; e < seen_count; e++) {
            uint32_t id = seen[e];
            gt[id] = 1;
            b.views[id] += b.views[id] < UINT8_MAX;
            if (!pvs_mask[id]) {
                fn += seen_px[e];
                fn_rel += b.unreliable[id] ? 0 : seen_px[e];
                fn_dyn_sum += id >= first_dynamic ? seen_px[e] : 0;
            }
        }
        fn_sum += (double)fn;
        fn_rel_sum += (double)fn_rel;
        if ((double)fn > out->fng_pixels_max)
            out->fng_pixels_max = (double)fn;
        /* With a cached GT, a view without FN pixels renders the same with
         * the PVS (gt_cache.h): no images to compare, one PVS draw timed. */
        bool compare = !cached || fn > 0;
        if (compare && cached && (!rnd_draw(ctx, target, gpu, &b.cams[s], NULL, 0, &full_st) ||
                                  !rnd_target_read_color(ctx, target, b.full_rgba))) {
            snprintf(err, err_size, "ground truth: drawing sample view %u failed (Vulkan error logged)", s);
            goto done;
        }
        if ((compare || pvs_drawn == 0) &&
            (!rnd_draw(ctx, target, gpu, &b.cams[s], pvs_ids, pvs_count, &pvs_st) ||
             (compare && !rnd_target_read_color(ctx, target, b.pvs_rgba)))) {
            snprintf(err, err_size, "ground truth: drawing sample view %u failed (Vulkan error logged)", s);
            goto done;
        }
        if (compare || pvs_drawn == 0)
            b.pvs_ms[pvs_drawn++] = pvs_st.cpu_ms;
        double psnr = compare ? rnd_psnr_rgb8(b.full_rgba, b.pvs_rgba, pixels, 4) : INFINITY;
        if (psnr < out->psnr_min_db || s == 0) {
            out->psnr_min_db = psnr;
            out->worst_view = s;
        }
        if (isfinite(psnr)) /* back to the mean squared error the PSNR came from */
            sum_sq += 255.0 * 255.0 / pow(10.0, psnr / 10.0);
        double ssim = compare ? rnd_ssim_rgb8(b.full_rgba, b.pvs_rgba, d.width, d.height, 4, b.ssim_scratch) : 1.0;
        ssim_sum += ssim;
        out->ssim_min = s == 0 ? ssim : fmin(out->ssim_min, ssim);
    }
    set_metrics(scene, pvs_mask, gt, &b, n, out);
    out->samples = n;
    out->fng_pixels_mean = fn_sum / n;
    out->fng_reliable_pixels_mean = fn_rel_sum / n;
    out->fng_dynamic_pixels_mean = fn_dyn_sum / n;
    out->fng_fraction_mean = out->fng_pixels_mean / (double)pixels;
    double mse = sum_sq / n;
    out->psnr_mean_db = mse > 0.0 ? 10.0 * log10(255.0 * 255.0 / mse) : INFINITY;
    out->ssim_mean = ssim_sum / n;
    out->full_render_ms = cached ? rec.full_render_ms : tv_percentile(b.full_ms, n, 50.0);
    out->pvs_render_ms = tv_percentile(b.pvs_ms, pvs_drawn, 50.0);
    out->gt_ms = cached ? rec.gt_ms : gt_sum_ms; /* what the GT cost to sample, also when read back */
    if (caching && !cached) {
        rec.gt_ms = out->gt_ms;
        rec.full_render_ms = out->full_render_ms;
        char why[512];
        if (pvs_gt_cache_store(file, key, &rec, why, sizeof why))
            tv_log(TV_LOG_INFO, "gt cache: wrote %s", file);
        else
            tv_log(TV_LOG_WARN, "gt cache: %s", why);
    }
    ok = true;
done:
    if (target)
        rnd_target_destroy(ctx, target);
    if (!gt_mask)
        free(gt);
    gt_seethrough_free(&see);
    pvs_gt_record_free(&rec);
    free_buffers(&b);
    out->eval_ms = tv_now_ms() - t0;
    return ok;
}
