/* demo_view.c - eye rendering modes, the check, the viewcell overlay. */
#include "demo_view.h"

#include "image_compare.h"
#include "pose.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

bool tv_eye_renderer_init(tv_eye_renderer* r, rnd_context* ctx, uint32_t width, uint32_t height, char* err,
                          size_t err_size)
{
    memset(r, 0, sizeof *r);
    size_t pixels = (size_t)width * height;
    r->width = width;
    r->height = height;
    r->target = rnd_target_create(ctx, width, height, err, err_size);
    r->rgba = malloc(pixels * 4);
    r->rgba_full = malloc(pixels * 4);
    r->ids = malloc(pixels * sizeof *r->ids);
    if (r->target && r->rgba && r->rgba_full && r->ids)
        return true;
    if (r->target)
        snprintf(err, err_size, "out of memory for %ux%u eye images", width, height);
    tv_eye_renderer_free(r, ctx);
    return false;
}

void tv_eye_renderer_free(tv_eye_renderer* r, rnd_context* ctx)
{
    if (r->target)
        rnd_target_destroy(ctx, r->target);
    free(r->rgba);
    free(r->rgba_full);
    free(r->ids);
    memset(r, 0, sizeof *r);
}

bool tv_eye_render(tv_eye_renderer* r, rnd_context* ctx, const rnd_gpu_scene* gpu, const rnd_camera* cam,
                   tv_eye_mode mode, const uint32_t* pvs_ids, uint32_t pvs_count, const uint8_t* pvs_mask,
                   uint32_t triangle_count, uint32_t first_dynamic, bool check, tv_eye_check* out)
{
    size_t pixels = (size_t)r->width * r->height;
    bool full = mode != TV_EYE_PVS || check;
    bool need_ids = mode == TV_EYE_FN || check;
    if (full && (!rnd_draw(ctx, r->target, gpu, cam, NULL, 0, NULL) ||
                 !rnd_target_read_color(ctx, r->target, r->rgba_full) ||
                 (need_ids && !rnd_target_read_ids(ctx, r->target, r->ids))))
        return false;
    if ((mode == TV_EYE_PVS || check) && (!rnd_draw(ctx, r->target, gpu, cam, pvs_ids, pvs_count, NULL) ||
                                          !rnd_target_read_color(ctx, r->target, r->rgba)))
        return false;
    if (check) {
        out->psnr_db = rnd_psnr_rgb8(r->rgba_full, r->rgba, pixels, 4);
        out->fn_pixels = rnd_count_fn_pixels(r->ids, pixels, pvs_mask, triangle_count);
        out->dynamic_fn_pixels = rnd_count_fn_pixels_from(r->ids, pixels, pvs_mask, triangle_count, first_dynamic);
    }
    if (mode != TV_EYE_PVS)
        memcpy(r->rgba, r->rgba_full, pixels * 4);
    if (mode == TV_EYE_FN)
        rnd_colour_false_negatives(r->rgba, r->ids, pixels, pvs_mask, triangle_count, r->rgba, 4);
    return true;
}

void tv_mark_seen(const tv_eye_renderer* r, uint8_t* seen, uint32_t triangle_count)
{
    size_t pixels = (size_t)r->width * r->height;
    for (size_t i = 0; i < pixels; i++)
        if (r->ids[i] < triangle_count)
            seen[r->ids[i]] = 1;
}

bool tv_overview_render(tv_eye_renderer* r, rnd_context* ctx, const rnd_gpu_scene* gpu, const rnd_camera* cam,
                        const uint8_t* seen, const uint8_t* pvs_mask, uint32_t triangle_count)
{
    if (!rnd_draw(ctx, r->target, gpu, cam, NULL, 0, NULL) || !rnd_target_read_color(ctx, r->target, r->rgba) ||
        !rnd_target_read_ids(ctx, r->target, r->ids))
        return false;
    rnd_colour_figure1(r->rgba, r->ids, (size_t)r->width * r->height, seen, pvs_mask, triangle_count, r->rgba, 4);
    return true;
}

/* Clip coordinates of a world point (column-major matrix). */
static void to_clip(const float m[16], const double p[3], double out[4])
{
    for (int i = 0; i < 4; i++)
        out[i] = m[i] * p[0] + m[4 + i] * p[1] + m[8 + i] * p[2] + m[12 + i];
}

/* A world segment, clipped against the near side (w > epsilon) and drawn. */
static void segment(const tv_canvas* c, const float m[16], const double a[3], const double b[3], const uint8_t rgb[3])
{
    const double eps = 1e-3;
    double ca[4], cb[4];
    to_clip(m, a, ca);
    to_clip(m, b, cb);
    if (ca[3] < eps && cb[3] < eps)
        return;
    if (ca[3] < eps || cb[3] < eps) {
        double* behind = ca[3] < eps ? ca : cb;
        const double* front = ca[3] < eps ? cb : ca;
        double t = (eps - front[3]) / (behind[3] - front[3]);
        for (int i = 0; i < 4; i++)
            behind[i] = front[i] + t * (behind[i] - front[i]);
    }
    /* Vulkan clip space has +Y down, like the image rows */
    tv_draw_line(c, (float)((ca[0] / ca[3] * 0.5 + 0.5) * c->width), (float)((ca[1] / ca[3] * 0.5 + 0.5) * c->height),
                 (float)((cb[0] / cb[3] * 0.5 + 0.5) * c->width), (float)((cb[1] / cb[3] * 0.5 + 0.5) * c->height),
                 rgb);
}

void tv_draw_viewcell(const tv_canvas* c, const rnd_camera* cam, const pred_viewcell* vc, const uint8_t rgb[3])
{
    float m[16];
    rnd_camera_view_proj(cam, (float)c->width / (float)c->height, m);
    double f[3], u[3], s[3], front[3], back[3];
    for (int k = 0; k < 3; k++) {
        f[k] = vc->forward[k];
        u[k] = vc->up[k];
    }
    s[0] = f[1] * u[2] - f[2] * u[1];
    s[1] = f[2] * u[0] - f[0] * u[2];
    s[2] = f[0] * u[1] - f[1] * u[0];
    for (int k = 0; k < 3; k++) {
        front[k] = vc->v0[k] + vc->z * f[k];
        back[k] = vc->v0[k] - vc->z * f[k];
    }
    enum { RIM = 48, GENERATORS = 8 };
    double prev[3];
    for (int i = 0; i <= RIM; i++) {
        double a = 2.0 * PRED_PI * i / RIM, p[3];
        for (int k = 0; k < 3; k++)
            p[k] = vc->v0[k] + vc->delta * (cos(a) * u[k] + sin(a) * s[k]);
        if (i > 0)
            segment(c, m, prev, p, rgb);
        if (i < RIM && i % (RIM / GENERATORS) == 0) {
            segment(c, m, p, front, rgb);
            segment(c, m, p, back, rgb);
        }
        memcpy(prev, p, sizeof prev);
    }
}
