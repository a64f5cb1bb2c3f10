/* camera.c - view/projection matrices in Vulkan clip space and stereo eye
 * placement. All math through cglm; matrices are column-major. */
#include "render.h"

#include <cglm/cglm.h>
#include <cglm/clipspace/persp_rh_zo.h> /* Vulkan depth range without CGLM_FORCE_* globals */
#include <math.h>
#include <string.h>

void rnd_camera_view(const rnd_camera* cam, float view[16])
{
    /* camera-to-world = T(position) * R(orientation); view is its inverse */
    versor q;
    glm_quat_init(q, cam->orientation[0], cam->orientation[1], cam->orientation[2], cam->orientation[3]);
    glm_quat_normalize(q);
    mat4 rot_t, out;
    glm_quat_mat4t(q, rot_t);
    vec3 pos = {cam->position[0], cam->position[1], cam->position[2]};
    vec3 t;
    glm_mat4_mulv3(rot_t, pos, 0.0f, t);
    glm_mat4_copy(rot_t, out);
    out[3][0] = -t[0];
    out[3][1] = -t[1];
    out[3][2] = -t[2];
    memcpy(view, out, sizeof out);
}

void rnd_camera_projection(const rnd_camera* cam, float aspect, float proj[16])
{
    mat4 p;
    /* right-handed view space, depth 0..1 (Vulkan) ... */
    glm_perspective_rh_zo(glm_rad(cam->fov_y_deg), aspect, cam->near_m, cam->far_m, p);
    /* ... and +Y down in clip space: flip Y so world up stays up on screen */
    p[1][1] = -p[1][1];
    memcpy(proj, p, sizeof p);
}

void rnd_camera_view_proj(const rnd_camera* cam, float aspect, float view_proj[16])
{
    mat4 v, p, vp;
    rnd_camera_view(cam, (float*)v);
    rnd_camera_projection(cam, aspect, (float*)p);
    glm_mat4_mul(p, v, vp);
    memcpy(view_proj, vp, sizeof vp);
}

float rnd_fov_y_from_x(float fov_x_deg, float aspect)
{
    return glm_deg(2.0f * atanf(tanf(glm_rad(fov_x_deg) * 0.5f) / aspect));
}

float rnd_fov_x_from_y(float fov_y_deg, float aspect)
{
    return glm_deg(2.0f * atanf(tanf(glm_rad(fov_y_deg) * 0.5f) * aspect));
}

void rnd_stereo_cameras(const float head_pos[3], const float head_q[4], float ipd_m, const rnd_camera* base,
                        rnd_camera* left, rnd_camera* right)
{
    versor q;
    glm_quat_init(q, head_q[0], head_q[1], head_q[2], head_q[3]);
    glm_quat_normalize(q);
    vec3 half = {0.5f * ipd_m, 0.0f, 0.0f}, offset;
    glm_quat_rotatev(q, half, offset);
    rnd_camera* eyes[2] = {left, right};
    for (int e = 0; e < 2; e++) {
        *eyes[e] = *base;
        float sign = e == 0 ? -1.0f : 1.0f;
        for (int i = 0; i < 3; i++)
            eyes[e]->position[i] = head_pos[i] + sign * offset[i];
        memcpy(eyes[e]->orientation, q, sizeof q);
    }
}
