/* Camera math: view/projection conventions, FOV conversion, stereo eyes.
 * Pure math (no device), but part of tv_render. */
#include "render.h"
#include "test.h"

#include <math.h>

/* Transforms world point p by the column-major 4x4 m; returns clip xyzw. */
static void transform(const float m[16], const float p[3], float out[4])
{
    for (int r = 0; r < 4; r++)
        out[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r];
}

static void view_of_rotated_camera(void)
{
    /* 90 degrees about +Y: the camera's -Z (forward) points along world -X */
    const float s = sqrtf(0.5f);
    rnd_camera cam = {.position = {1, 2, 3}, .orientation = {0, s, 0, s}, .fov_y_deg = 90, .near_m = 1, .far_m = 10};
    float view[16], v[4];
    rnd_camera_view(&cam, view);
    transform(view, (float[3]){1 - 4, 2, 3}, v);
    TV_CHECK_NEAR(v[0], 0, 1e-5);
    TV_CHECK_NEAR(v[1], 0, 1e-5);
    TV_CHECK_NEAR(v[2], -4, 1e-5);
    /* world -Z is the camera's right (+X) after this rotation */
    transform(view, (float[3]){1, 2, 3 - 1}, v);
    TV_CHECK_NEAR(v[0], 1, 1e-5);
}

static void projection_is_vulkan_clip_space(void)
{
    rnd_camera cam = {.orientation = {0, 0, 0, 1}, .fov_y_deg = 90, .near_m = 1, .far_m = 10};
    float vp[16], c[4];
    rnd_camera_view_proj(&cam, 2.0f, vp);
    /* near plane -> depth 0, far plane -> depth 1 */
    transform(vp, (float[3]){0, 0, -1}, c);
    TV_CHECK_NEAR(c[2] / c[3], 0, 1e-6);
    transform(vp, (float[3]){0, 0, -10}, c);
    TV_CHECK_NEAR(c[2] / c[3], 1, 1e-6);
    /* analytic depth at distance d: far (d - near) / ((far - near) d) */
    transform(vp, (float[3]){0, 0, -4}, c);
    TV_CHECK_NEAR(c[2] / c[3], 10.0 * 3.0 / (9.0 * 4.0), 1e-6);
    /* world up is clip -Y (Vulkan's Y points down); the top edge of a 90
     * degree FOV is y = -1, the right edge of aspect 2 at x = 2 */
    transform(vp, (float[3]){0, 2, -2}, c);
    TV_CHECK_NEAR(c[1] / c[3], -1, 1e-6);
    transform(vp, (float[3]){4, 0, -2}, c);
    TV_CHECK_NEAR(c[0] / c[3], 1, 1e-6);
}

static void fov_conversion(void)
{
    /* tan(y/2) = tan(x/2) / aspect */
    TV_CHECK_NEAR(rnd_fov_y_from_x(90.0f, 2.0f), 2.0 * atan(0.5) * 180.0 / acos(-1.0), 1e-4);
    TV_CHECK_NEAR(rnd_fov_x_from_y(rnd_fov_y_from_x(100.0f, 16.0f / 9.0f), 16.0f / 9.0f), 100.0, 1e-3);
    TV_CHECK_NEAR(rnd_fov_y_from_x(60.0f, 1.0f), 60.0, 1e-4);
}

static void stereo_eyes(void)
{
    const float s = sqrtf(0.5f);
    const float head[3] = {1, 2, 3};
    const float q[4] = {0, s, 0, s}; /* head's +X is world -Z */
    rnd_camera base = {.fov_y_deg = 70, .near_m = 0.05f, .far_m = 50}, left, right;
    rnd_stereo_cameras(head, q, 0.064f, &base, &left, &right);
    TV_CHECK_NEAR(left.position[0], 1, 1e-6);
    TV_CHECK_NEAR(left.position[2], 3 + 0.032, 1e-6);
    TV_CHECK_NEAR(right.position[2], 3 - 0.032, 1e-6);
    TV_CHECK_NEAR(right.position[1], 2, 1e-6);
    for (int i = 0; i < 4; i++) {
        TV_CHECK_NEAR(left.orientation[i], q[i], 1e-6);
        TV_CHECK_NEAR(right.orientation[i], q[i], 1e-6);
    }
    TV_CHECK(left.fov_y_deg == 70 && right.near_m == 0.05f && left.far_m == 50);
}

int main(void)
{
    TV_TEST_RUN(view_of_rotated_camera);
    TV_TEST_RUN(projection_is_vulkan_clip_space);
    TV_TEST_RUN(fov_conversion);
    TV_TEST_RUN(stereo_eyes);
    return tv_test_finish();
}
