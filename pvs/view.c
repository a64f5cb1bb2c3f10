#include "view.h"

#include <assert.h>
#include <math.h>

#include <cglm/cglm.h>

pvs_view_frame pvs_view_frame_make(const pvs_view* view)
{
    assert(view->fov_y_deg > 0.0f && view->fov_y_deg < 180.0f);
    assert(view->near_dist > 0.0f && view->far_dist > view->near_dist);
    pvs_view_frame f;
    vec3 fwd = {view->forward[0], view->forward[1], view->forward[2]};
    vec3 up = {view->up[0], view->up[1], view->up[2]};
    assert(glm_vec3_norm(fwd) > 0.0f);
    glm_vec3_normalize(fwd);
    vec3 right;
    glm_vec3_cross(fwd, up, right);
    assert(glm_vec3_norm(right) > 1e-6f * glm_vec3_norm(up));
    glm_vec3_normalize(right);
    glm_vec3_cross(right, fwd, up);
    glm_vec3_copy(fwd, f.forward);
    glm_vec3_copy(right, f.right);
    glm_vec3_copy(up, f.up);
    f.tan_half_y = tanf(glm_rad(view->fov_y_deg) * 0.5f);
    f.tan_half_x = f.tan_half_y * (view->aspect > 0.0f ? view->aspect : 1.0f);
    return f;
}

float pvs_view_project(const pvs_view* view, const pvs_view_frame* frame, const float p[3],
                       float image[2])
{
    vec3 d = {p[0] - view->apex[0], p[1] - view->apex[1], p[2] - view->apex[2]};
    float depth = glm_vec3_dot(d, (float*)frame->forward);
    if (depth > 0.0f) {
        image[0] = glm_vec3_dot(d, (float*)frame->right) / depth;
        image[1] = glm_vec3_dot(d, (float*)frame->up) / depth;
    }
    return depth;
}
