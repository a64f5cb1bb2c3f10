#include "eval_images.h"

#include "image_compare.h"
#include "image_io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

bool tv_eval_images_keep_worst(tv_eval_images* w, const pred_viewcell* vc, const pvs_eval_result* m,
                               const uint8_t* pvs_mask, const uint8_t* gt_mask, uint32_t triangle_count)
{
    if (w->have && (m->fng_pixels_max < w->m.fng_pixels_max ||
                    (m->fng_pixels_max == w->m.fng_pixels_max && !(m->psnr_min_db < w->m.psnr_min_db))))
        return true;
    if (!w->pvs) {
        w->pvs = malloc(triangle_count ? triangle_count : 1);
        w->gt = malloc(triangle_count ? triangle_count : 1);
        if (!w->pvs || !w->gt)
            return false;
    }
    memcpy(w->pvs, pvs_mask, triangle_count);
    memcpy(w->gt, gt_mask, triangle_count);
    w->vc = *vc;
    w->m = *m;
    w->triangle_count = triangle_count;
    w->have = true;
    return true;
}

void tv_eval_images_free(tv_eval_images* w)
{
    free(w->pvs);
    free(w->gt);
    memset(w, 0, sizeof *w);
}

typedef enum colouring { COLOUR_FIGURE1, COLOUR_FALSE_NEGATIVES } colouring;

static bool render_classified(const tv_eval_images* w, rnd_context* ctx, rnd_target* target,
                              const rnd_gpu_scene* gpu, const rnd_camera* cam, colouring mode, const char* file,
                              uint8_t* rgba, uint32_t* ids, uint8_t* rgb, char* err, size_t err_size)
{
    uint32_t width = rnd_target_width(target), height = rnd_target_height(target);
    if (!rnd_draw(ctx, target, gpu, cam, NULL, 0, NULL) || !rnd_target_read_color(ctx, target, rgba) ||
        !rnd_target_read_ids(ctx, target, ids)) {
        snprintf(err, err_size, "%s: rendering failed (Vulkan error logged)", file);
        return false;
    }
    size_t pixels = (size_t)width * height;
    if (mode == COLOUR_FIGURE1)
        rnd_colour_figure1(rgba, ids, pixels, w->gt, w->pvs, w->triangle_count, rgb, 3);
    else
        rnd_colour_false_negatives(rgba, ids, pixels, w->pvs, w->triangle_count, rgb, 3);
    return scn_image_write_png(file, rgb, width, height, 3, err, err_size);
}

static void look_camera(const double pos[3], const double forward[3], const double up[3], float fov_y,
                        rnd_camera* cam)
{
    double q[4];
    pred_quat_look(forward, up, q);
    for (int i = 0; i < 3; i++)
        cam->position[i] = (float)pos[i];
    for (int i = 0; i < 4; i++)
        cam->orientation[i] = (float)q[i];
    cam->fov_y_deg = fov_y;
    cam->near_m = 0.05f;
    cam->far_m = 2000.0f;
}

void tv_viewcell_centre_camera(const pred_viewcell* vc, float aspect, rnd_camera* cam)
{
    double p[3] = {vc->v0[0], vc->v0[1], vc->v0[2]}, f[3] = {vc->forward[0], vc->forward[1], vc->forward[2]},
           u[3] = {vc->up[0], vc->up[1], vc->up[2]};
    look_camera(p, f, u, rnd_fov_y_from_x(fminf(vc->fov_pvs_deg, 170.0f), aspect), cam);
}

void tv_overview_camera(const scn_scene* scene, const double v0[3], const double forward[3], const double up[3],
                        rnd_camera* cam)
{
    float extent = fmaxf(fmaxf(scene->bounds_max[0] - scene->bounds_min[0], scene->bounds_max[1] - scene->bounds_min[1]),
                         scene->bounds_max[2] - scene->bounds_min[2]);
    double back = fmin(fmax(0.08 * extent, 3.0), 25.0); /* far enough to see the region, near enough to read it */
    double p[3], dir[3];
    for (int i = 0; i < 3; i++) {
        p[i] = v0[i] - back * forward[i] + 0.8 * back * up[i];
        dir[i] = v0[i] + 1.5 * back * forward[i] - p[i];
    }
    look_camera(p, dir, up, 60.0f, cam);
}

bool tv_eval_images_write(const tv_eval_images* w, rnd_context* ctx, const rnd_gpu_scene* gpu,
                          const scn_scene* scene, const pvs_eval_desc* desc, const char* out_dir, char* err,
                          size_t err_size)
{
    if (!w->have)
        return true;
    uint32_t width = desc->width ? desc->width : 640, height = desc->height ? desc->height : 360;
    uint32_t samples = desc->samples ? desc->samples : 200;
    size_t pixels = (size_t)width * height;
    uint8_t* rgba = malloc(pixels * 4);
    uint8_t* rgb = malloc(pixels * 3);
    uint32_t* ids = malloc(pixels * sizeof *ids);
    rnd_camera* cams = malloc(samples * sizeof *cams);
    rnd_target* target = rgba && rgb && ids && cams ? rnd_target_create(ctx, width, height, err, err_size) : NULL;
    bool ok = target != NULL;
    if (!ok && !err[0])
        snprintf(err, err_size, "out of memory");
    const pred_viewcell* vc = &w->vc;
    double f[3] = {vc->forward[0], vc->forward[1], vc->forward[2]}, u[3] = {vc->up[0], vc->up[1], vc->up[2]};
    float aspect = (float)width / (float)height;
    char file[4200];
    if (ok) { /* Figure 1 from the viewcell centre, with the PVS FOV: what the PVS was computed for */
        rnd_camera cam;
        tv_viewcell_centre_camera(vc, aspect, &cam);
        snprintf(file, sizeof file, "%s/fig1_eye.png", out_dir);
        ok = render_classified(w, ctx, target, gpu, &cam, COLOUR_FIGURE1, file, rgba, ids, rgb, err, err_size);
    }
    if (ok) {
        rnd_camera cam;
        double v0[3] = {vc->v0[0], vc->v0[1], vc->v0[2]};
        tv_overview_camera(scene, v0, f, u, &cam);
        snprintf(file, sizeof file, "%s/fig1_overview.png", out_dir);
        ok = render_classified(w, ctx, target, gpu, &cam, COLOUR_FIGURE1, file, rgba, ids, rgb, err, err_size);
    }
    if (ok) { /* the evaluation's worst sample view, false negatives red */
        uint32_t n = pvs_gt_cameras(vc, desc, cams, samples);
        uint32_t view = w->m.worst_view < n ? w->m.worst_view : 0;
        snprintf(file, sizeof file, "%s/fn_worst.png", out_dir);
        ok = n > 0 && render_classified(w, ctx, target, gpu, &cams[view], COLOUR_FALSE_NEGATIVES, file, rgba, ids,
                                        rgb, err, err_size);
    }
    if (target)
        rnd_target_destroy(ctx, target);
    free(rgba);
    free(rgb);
    free(ids);
    free(cams);
    return ok;
}
