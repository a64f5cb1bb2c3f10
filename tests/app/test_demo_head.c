/* Unit tests of the demo's keyboard-and-mouse head (app/demo_head.h):
 * walking speed and direction, diagonal moves, turning, pitch limits, the
 * round trip from a start pose, reset and the speed clamp. */
#include "demo_head.h"
#include "test.h"

#include <math.h>
#include <string.h>

static void forward_of(const tv_head* h, double f[3])
{
    pred_pose p;
    tv_head_pose(h, 0.0, &p);
    pred_pose_forward(p.q, f);
}

static void start_at(tv_head* h, double yaw_deg, double pitch_deg)
{
    pred_pose s;
    memset(&s, 0, sizeof s);
    s.p[0] = 1.0, s.p[1] = 1.7, s.p[2] = -2.0;
    pred_quat_from_ypr(yaw_deg * PRED_DEG, pitch_deg * PRED_DEG, 0.0, s.q);
    tv_head_init(h, &s);
}

static void walks_forward_at_walking_speed(void)
{
    tv_head h;
    start_at(&h, 0.0, 0.0);
    tv_head_input in = {.forward = true};
    for (int i = 0; i < 90; i++)
        tv_head_step(&h, &in, 1.0 / 90.0);
    /* yaw 0 looks down -Z: one second at 1.4 m/s */
    TV_CHECK_NEAR(h.p[0], 1.0, 1e-9);
    TV_CHECK_NEAR(h.p[1], 1.7, 1e-9);
    TV_CHECK_NEAR(h.p[2], -2.0 - TV_HEAD_DEFAULT_SPEED, 1e-9);
    in.fast = true;
    tv_head_step(&h, &in, 1.0);
    TV_CHECK_NEAR(h.p[2], -2.0 - 5.0 * TV_HEAD_DEFAULT_SPEED, 1e-9);
}

static void diagonal_is_no_faster_and_walking_stays_level(void)
{
    tv_head h;
    start_at(&h, 0.0, -40.0); /* looking down: walking must not sink */
    tv_head_input in = {.forward = true, .right = true};
    tv_head_step(&h, &in, 1.0);
    double dx = h.p[0] - 1.0, dz = h.p[2] + 2.0;
    TV_CHECK_NEAR(sqrt(dx * dx + dz * dz), TV_HEAD_DEFAULT_SPEED, 1e-9);
    TV_CHECK_NEAR(dx, -dz, 1e-9); /* 45 degrees between forward (-Z) and right (+X) */
    TV_CHECK(dx > 0.0);
    TV_CHECK_NEAR(h.p[1], 1.7, 1e-12);
    tv_head_input rise = {.up = true};
    tv_head_step(&h, &rise, 0.5);
    TV_CHECK_NEAR(h.p[1], 1.7 + 0.5 * TV_HEAD_DEFAULT_SPEED, 1e-9);
}

static void mouse_turns_right_and_pitch_is_clamped(void)
{
    tv_head h;
    start_at(&h, 0.0, 0.0);
    tv_head_input in = {.look_dx = (PRED_PI / 2.0) / TV_HEAD_LOOK_RAD_PER_PIXEL};
    tv_head_step(&h, &in, 1.0 / 90.0);
    double f[3];
    forward_of(&h, f);
    TV_CHECK_NEAR(f[0], 1.0, 1e-9); /* a quarter turn right from -Z faces +X */
    TV_CHECK_NEAR(f[2], 0.0, 1e-9);
    tv_head_input walk = {.forward = true};
    double x0 = h.p[0];
    tv_head_step(&h, &walk, 1.0);
    TV_CHECK_NEAR(h.p[0] - x0, TV_HEAD_DEFAULT_SPEED, 1e-9); /* walks where it looks */
    tv_head_input down = {.look_dy = 1e6};
    tv_head_step(&h, &down, 0.0);
    TV_CHECK_NEAR(h.pitch, -TV_HEAD_MAX_PITCH, 1e-12);
    forward_of(&h, f);
    TV_CHECK(f[1] < -0.99);
    tv_head_input up = {.look_dy = -1e6};
    tv_head_step(&h, &up, 0.0);
    TV_CHECK_NEAR(h.pitch, TV_HEAD_MAX_PITCH, 1e-12);
}

static void start_pose_round_trips_and_reset_restores_it(void)
{
    tv_head h;
    start_at(&h, 35.0, 12.0);
    pred_pose s, p;
    memset(&s, 0, sizeof s);
    pred_quat_from_ypr(35.0 * PRED_DEG, 12.0 * PRED_DEG, 0.0, s.q);
    tv_head_pose(&h, 2.5, &p);
    TV_CHECK_NEAR(p.t, 2.5, 0.0);
    TV_CHECK(pred_quat_angle_deg(p.q, s.q) < 1e-6);
    tv_head_input in = {.forward = true, .look_dx = 300.0, .look_dy = 80.0};
    tv_head_scale_speed(&h, 3.0);
    tv_head_step(&h, &in, 1.0);
    TV_CHECK(fabs(h.p[0] - 1.0) + fabs(h.p[2] + 2.0) > 1.0);
    tv_head_reset(&h);
    tv_head_pose(&h, 0.0, &p);
    TV_CHECK(pred_quat_angle_deg(p.q, s.q) < 1e-6);
    TV_CHECK_NEAR(p.p[0], 1.0, 0.0);
    TV_CHECK_NEAR(p.p[2], -2.0, 0.0);
    TV_CHECK_NEAR(h.speed, TV_HEAD_DEFAULT_SPEED, 0.0);
}

static void speed_scaling_is_clamped(void)
{
    tv_head h;
    start_at(&h, 0.0, 0.0);
    for (int i = 0; i < 100; i++)
        tv_head_scale_speed(&h, 1.25);
    TV_CHECK_NEAR(h.speed, 50.0, 0.0);
    for (int i = 0; i < 100; i++)
        tv_head_scale_speed(&h, 0.8);
    TV_CHECK_NEAR(h.speed, 0.05, 0.0);
}

int main(void)
{
    TV_TEST_RUN(walks_forward_at_walking_speed);
    TV_TEST_RUN(diagonal_is_no_faster_and_walking_stays_level);
    TV_TEST_RUN(mouse_turns_right_and_pitch_is_clamped);
    TV_TEST_RUN(start_pose_round_trips_and_reset_restores_it);
    TV_TEST_RUN(speed_scaling_is_clamped);
    return tv_test_finish();
}
