/* method_frompoint.c - from-point occlusion culling of the current pose, as
 * GPU-driven renderers do it: render depth from the newest head pose with
 * the display FOV, build a hierarchical-z pyramid of maximum depths, and keep
 * every triangle whose screen rectangle is not entirely behind it.
 *
 * Granularity: triangles, not octree leaves. A leaf holds up to
 * PVS_OCTREE_DEFAULT_CAP (1024) triangles, so leaf culling would bury the
 * disocclusion errors this baseline exists to show under false positives;
 * per-triangle tests are the tightest a from-point HiZ cull can be, and on
 * the CPU they cost one vertex transform per vertex plus a rectangle test
 * per triangle.
 *
 * Conservative at the pose itself: a triangle that wins a pixel of the full
 * render there has its nearest vertex depth at or in front of that pixel's
 * depth (depth is affine in screen space over an unclipped triangle), and
 * its rectangle, rounded outwards, contains the pixel; a triangle crossing
 * the near plane is kept unless all its vertices lie beyond one frustum
 * plane. Everything else depends on the pose only: what the head uncovers
 * by moving within the viewcell is missing. */
#include "method_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Slack on the depth comparison: the CPU's nearest depth and the GPU's
 * interpolated one differ by float rounding (~1e-7); a larger slack only adds
 * triangles lying within it behind the occluder. */
#define DEPTH_SLACK 1e-6

typedef struct _frompoint {
    uint32_t vertex_count, triangle_count;
    float* positions;   /* copies: the scene is not referenced after create */
    uint32_t* indices;
    double* clip;       /* 4 per vertex, this request's clip coordinates */
    float* hiz;         /* all levels, level 0 = the depth buffer */
    uint32_t levels;
    uint32_t offset[32], w[32], h[32];
} _frompoint;

static bool _create(pvs_method* m, const scn_scene* scene, char* err, size_t err_size)
{
    _frompoint* f = calloc(1, sizeof *f);
    if (!f) {
        snprintf(err, err_size, "frompoint: out of memory");
        return false;
    }
    m->impl = f;
    f->vertex_count = scene->vertex_count;
    f->triangle_count = scene->triangle_count;
    size_t total = 0;
    uint32_t w = m->desc.width, h = m->desc.height;
    for (f->levels = 0;; f->levels++) {
        f->offset[f->levels] = (uint32_t)total;
        f->w[f->levels] = w;
        f->h[f->levels] = h;
        total += (size_t)w * h;
        if (w == 1 && h == 1)
            break;
        w = (w + 1) / 2;
        h = (h + 1) / 2;
    }
    f->levels++;
    f->positions = malloc((size_t)scene->vertex_count * 3 * sizeof(float) + 1);
    f->indices = malloc((size_t)scene->triangle_count * 3 * sizeof(uint32_t) + 1);
    f->clip = malloc((size_t)scene->vertex_count * 4 * sizeof(double) + 1);
    f->hiz = malloc(total * sizeof(float));
    if (!f->positions || !f->indices || !f->clip || !f->hiz) {
        snprintf(err, err_size, "frompoint: out of memory for %u vertices", scene->vertex_count);
        return false;
    }
    memcpy(f->positions, scene->positions, (size_t)scene->vertex_count * 3 * sizeof(float));
    memcpy(f->indices, scene->indices, (size_t)scene->triangle_count * 3 * sizeof(uint32_t));
    return true;
}

static void _destroy(pvs_method* m)
{
    _frompoint* f = m->impl;
    free(f->positions);
    free(f->indices);
    free(f->clip);
    free(f->hiz);
    free(f);
}

/* Level l+1 texel = maximum of its (up to) 2x2 children at level l. */
static void _build_hiz(_frompoint* f)
{
    for (uint32_t l = 0; l + 1 < f->levels; l++) {
        const float* src = f->hiz + f->offset[l];
        float* dst = f->hiz + f->offset[l + 1];
        uint32_t sw = f->w[l], sh = f->h[l];
        for (uint32_t y = 0; y < f->h[l + 1]; y++)
            for (uint32_t x = 0; x < f->w[l + 1]; x++) {
                uint32_t x1 = 2 * x + 1 < sw ? 2 * x + 1 : sw - 1, y1 = 2 * y + 1 < sh ? 2 * y + 1 : sh - 1;
                float a = fmaxf(src[2 * y * sw + 2 * x], src[2 * y * sw + x1]);
                float b = fmaxf(src[y1 * sw + 2 * x], src[y1 * sw + x1]);
                dst[y * f->w[l + 1] + x] = fmaxf(a, b);
            }
    }
}

/* Farthest depth over level-0 pixels [x0, x1] x [y0, y1], from the coarsest
 * level where the rectangle spans at most 2 x 2 texels. */
static float _hiz_max(const _frompoint* f, uint32_t x0, uint32_t x1, uint32_t y0, uint32_t y1)
{
    uint32_t l = 0;
    while (l + 1 < f->levels && ((x1 >> l) - (x0 >> l) > 1 || (y1 >> l) - (y0 >> l) > 1))
        l++;
    const float* t = f->hiz + f->offset[l];
    float d = 0.0f;
    for (uint32_t y = y0 >> l; y <= y1 >> l; y++)
        for (uint32_t x = x0 >> l; x <= x1 >> l; x++)
            d = fmaxf(d, t[y * f->w[l] + x]);
    return d;
}

static uint32_t _outcode(const double c[4])
{
    return (c[0] < -c[3]) | (c[0] > c[3]) << 1 | (c[1] < -c[3]) << 2 | (c[1] > c[3]) << 3 | (c[2] < 0.0) << 4 |
           (c[2] > c[3]) << 5;
}

static bool _triangle_passes(const _frompoint* f, const double* c[3], uint32_t width, uint32_t height)
{
    uint32_t all = 0x3f, any_near = 0;
    for (int v = 0; v < 3; v++) {
        uint32_t code = _outcode(c[v]);
        all &= code;
        any_near |= code & 0x10;
    }
    if (all)
        return false; /* every vertex beyond one frustum plane */
    if (any_near)
        return true; /* crosses the near plane: no finite screen rectangle */
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY, zmin = INFINITY;
    for (int v = 0; v < 3; v++) {
        double x = (c[v][0] / c[v][3] + 1.0) * 0.5 * width, y = (c[v][1] / c[v][3] + 1.0) * 0.5 * height;
        xmin = fmin(xmin, x), xmax = fmax(xmax, x);
        ymin = fmin(ymin, y), ymax = fmax(ymax, y);
        zmin = fmin(zmin, c[v][2] / c[v][3]);
    }
    /* pixels whose centre (i + 0.5) may lie in [min, max], rounded outwards */
    double x0 = floor(xmin - 0.5), x1 = ceil(xmax - 0.5), y0 = floor(ymin - 0.5), y1 = ceil(ymax - 0.5);
    if (x1 < 0.0 || y1 < 0.0 || x0 > width - 1.0 || y0 > height - 1.0)
        return false;
    uint32_t px0 = x0 < 0.0 ? 0 : (uint32_t)x0, py0 = y0 < 0.0 ? 0 : (uint32_t)y0;
    uint32_t px1 = x1 > width - 1.0 ? width - 1 : (uint32_t)x1, py1 = y1 > height - 1.0 ? height - 1 : (uint32_t)y1;
    return zmin - DEPTH_SLACK <= (double)_hiz_max(f, px0, px1, py0, py1);
}

static bool _compute(pvs_method* m, const pvs_request* req, uint32_t** ids, uint32_t* count,
                     pvs_method_stats* stats, char* err, size_t err_size)
{
    (void)ids, (void)count;
    _frompoint* f = m->impl;
    const pred_pose* pose = &req->current;
    double qn = sqrt(pose->q[0] * pose->q[0] + pose->q[1] * pose->q[1] + pose->q[2] * pose->q[2] +
                     pose->q[3] * pose->q[3]);
    if (!(fabs(qn - 1.0) < 1e-3) || !isfinite(pose->p[0] + pose->p[1] + pose->p[2])) {
        snprintf(err, err_size, "frompoint: the request's current pose is not set (orientation norm %g)", qn);
        return false;
    }
    float aspect = (float)m->desc.width / (float)m->desc.height;
    rnd_camera cam = {.position = {(float)pose->p[0], (float)pose->p[1], (float)pose->p[2]},
                      .orientation = {(float)(pose->q[0] / qn), (float)(pose->q[1] / qn), (float)(pose->q[2] / qn),
                                      (float)(pose->q[3] / qn)},
                      .fov_y_deg = rnd_fov_y_from_x(req->eye_fov_h_deg, aspect),
                      .near_m = m->desc.near_m,
                      .far_m = m->desc.far_m};
    if (!rnd_draw(m->rnd, m->target, m->gpu, &cam, NULL, 0, NULL) ||
        !rnd_target_read_depth(m->rnd, m->target, f->hiz)) {
        snprintf(err, err_size, "frompoint: depth render failed (Vulkan error logged)");
        return false;
    }
    _build_hiz(f);
    float vp[16];
    rnd_camera_view_proj(&cam, aspect, vp);
    for (uint32_t v = 0; v < f->vertex_count; v++) {
        const float* p = &f->positions[3 * v];
        for (int r = 0; r < 4; r++)
            f->clip[4 * v + r] =
                (double)vp[r] * p[0] + (double)vp[4 + r] * p[1] + (double)vp[8 + r] * p[2] + (double)vp[12 + r];
    }
    for (uint32_t t = 0; t < f->triangle_count; t++) {
        const double* c[3] = {&f->clip[4 * f->indices[3 * t]], &f->clip[4 * f->indices[3 * t + 1]],
                              &f->clip[4 * f->indices[3 * t + 2]]};
        m->mask[t] = _triangle_passes(f, c, m->desc.width, m->desc.height);
    }
    stats->views = 1;
    return true;
}

const pvs_method_ops pvs_method_frompoint_ops = {.renders = true, .create = _create, .destroy = _destroy,
                                                 .compute = _compute};
