#include "umbra.h"

#include "trim_width.h"

#include <assert.h>
#include <math.h>

float pvs_umbra_corner_depth(float depth, float width, float far_width, float far_dist)
{
    assert(width >= 0.0f && far_width >= width && far_dist > 0.0f);
    if (depth >= far_dist)
        return far_dist;
    float a = far_width * far_dist / (far_dist - depth);
    float d = a > width ? a * depth / (a - width) : far_dist;
    return fminf(fmaxf(d, depth), far_dist);
}

bool pvs_umbra_quad_make(const pvs_view* view, const float e0[3], const float e1[3], const float inside[3],
                         const float width[2], const float far_width[2], pvs_umbra_quad* out)
{
    assert(view && e0 && e1 && inside && out && width && far_width);
    pvs_view_frame f = pvs_view_frame_make(view);
    float i0[2], i1[2], ii[2], d[2];
    if ((d[0] = pvs_view_project(view, &f, e0, i0)) <= 0.0f || (d[1] = pvs_view_project(view, &f, e1, i1)) <= 0.0f ||
        pvs_view_project(view, &f, inside, ii) <= 0.0f)
        return false;
    float t[2] = {i1[0] - i0[0], i1[1] - i0[1]};
    float len = sqrtf(t[0] * t[0] + t[1] * t[1]);
    if (len == 0.0f)
        return false;
    float n[2] = {-t[1] / len, t[0] / len};
    float side = n[0] * (ii[0] - i0[0]) + n[1] * (ii[1] - i0[1]);
    if (side == 0.0f)
        return false;
    if (side > 0.0f) { /* n must point away from the occluder */
        n[0] = -n[0];
        n[1] = -n[1];
    }
    const float* ends[2] = {i0, i1};
    for (int k = 0; k < 2; k++) {
        for (int c = 0; c < 2; c++)
            out->extruded[k][c] = ends[k][c] - width[k] * n[c];
    }
    for (int a = 0; a < 3; a++) {
        out->corner[0][a] = e0[a];
        out->corner[1][a] = e1[a];
        for (int k = 0; k < 2; k++) {
            float depth = pvs_umbra_corner_depth(d[1 - k], width[1 - k], far_width[1 - k], view->far_dist);
            out->corner[2 + k][a] = view->apex[a] + depth * (f.forward[a] + out->extruded[1 - k][0] * f.right[a] +
                                                             out->extruded[1 - k][1] * f.up[a]);
        }
    }
    return true;
}

float pvs_umbra_far_depth(const pvs_depth_bound* b, float delta, float tan_alpha, const float e0[3],
                          const float e1[3])
{
    assert(b && b->cells && e0 && e1);
    float i[2][2], d[2];
    if ((d[0] = pvs_view_project(&b->view, &b->frame, e0, i[0])) < b->view.near_dist ||
        (d[1] = pvs_view_project(&b->view, &b->frame, e1, i[1])) < b->view.near_dist)
        return b->view.far_dist;
    pvs_trim_params p = {.delta = delta, .tan_half_fov = tan_alpha, .far_dist = b->view.far_dist,
                         .focal_px = b->focal_px};
    float s = fmaxf(hypotf(i[0][0], i[0][1]), hypotf(i[1][0], i[1][1]));
    float reach = pvs_trim_reach_px(&p, fminf(d[0], d[1]), s);
    if (isinf(reach))
        return b->view.far_dist;
    float px[2][2];
    pvs_depth_bound_pixel(b, i[0], px[0]);
    pvs_depth_bound_pixel(b, i[1], px[1]);
    reach += 1.0f; /* the GPU's projection rounds differently */
    return pvs_depth_bound_query(b, fminf(px[0][0], px[1][0]) - reach, fminf(px[0][1], px[1][1]) - reach,
                                 fmaxf(px[0][0], px[1][0]) + reach, fmaxf(px[0][1], px[1][1]) + reach);
}
