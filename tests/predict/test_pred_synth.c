/* Path synthesis: determinism, smoothness, speeds, turn rates, validation. */
#include "path_synth.h"
#include "test.h"

#include <string.h>

static pred_synth_desc _walk(void)
{
    return (pred_synth_desc){.kind = PRED_SYNTH_WALK, .seed = 11, .waypoint_count = 4,
                             .waypoints = {{0, 0}, {20, 0}, {20, 15}, {-5, 15}}};
}

static double _speed(const pred_path* p, size_t i)
{
    return pred_vec3_dist(p->poses[i + 1].p, p->poses[i].p) / (p->poses[i + 1].t - p->poses[i].t);
}

static void test_deterministic(void)
{
    pred_synth_desc d = _walk();
    pred_path a, b, c;
    char err[256];
    TV_CHECK(pred_path_synth(&d, &a, err, sizeof err));
    TV_CHECK(pred_path_synth(&d, &b, err, sizeof err));
    d.seed = 12;
    TV_CHECK(pred_path_synth(&d, &c, err, sizeof err));
    TV_CHECK(a.count == b.count && memcmp(a.poses, b.poses, a.count * sizeof *a.poses) == 0);
    /* the seed changes the head motion, not the route */
    TV_CHECK(a.count == c.count && memcmp(a.poses, c.poses, a.count * sizeof *a.poses) != 0);
    pred_path_free(&a);
    pred_path_free(&b);
    pred_path_free(&c);
}

static void test_walk_geometry_and_smoothness(void)
{
    pred_synth_desc d = _walk();
    d.yaw_osc_amplitude_deg = -1; /* off: yaw follows the walking direction only */
    d.look_amplitude_deg = -1;
    d.bob_amplitude = -1;
    pred_path p;
    char err[256];
    TV_CHECK(pred_path_synth(&d, &p, err, sizeof err));
    TV_CHECK_NEAR(p.poses[0].p[0], 0.0, 1e-12);
    TV_CHECK_NEAR(p.poses[0].p[1], 1.7, 1e-12);
    /* 60 m minus what two 1 m fillets cut, at 1.4 m/s, plus one 1 s ramp-time */
    double length = 60.0 - 2.0 * (2.0 - 0.5 * PRED_PI);
    TV_CHECK_NEAR(pred_path_duration(&p), length / 1.4 + 1.0, 0.011);
    TV_CHECK_NEAR(p.poses[p.count - 1].p[0], -5.0, 1e-3);
    TV_CHECK_NEAR(p.poses[p.count - 1].p[2], 15.0, 1e-3);
    TV_CHECK_NEAR(pred_path_mean_speed(&p, 0.14), 1.4, 0.04);
    double max_speed = 0.0, max_accel = 0.0, max_yaw_error = 0.0;
    for (size_t i = 0; i + 2 < p.count; i++) {
        max_speed = fmax(max_speed, _speed(&p, i));
        /* velocity vector change: smooth corners keep it below v^2/r = 1.96 m/s^2 (+ ramps) */
        double dv[3];
        for (int k = 0; k < 3; k++)
            dv[k] = (p.poses[i + 2].p[k] - 2.0 * p.poses[i + 1].p[k] + p.poses[i].p[k]) * 1e4;
        max_accel = fmax(max_accel, sqrt(dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2]));
        /* head forward (ignoring the fixed 4 deg pitch) points along the motion */
        double f[3], mv[3] = {p.poses[i + 1].p[0] - p.poses[i].p[0], 0, p.poses[i + 1].p[2] - p.poses[i].p[2]};
        double n = hypot(mv[0], mv[2]);
        if (n > 1e-4) {
            pred_pose_forward(p.poses[i].q, f);
            double c = (f[0] * mv[0] + f[2] * mv[2]) / (n * hypot(f[0], f[2]));
            max_yaw_error = fmax(max_yaw_error, acos(fmin(1.0, c)) / PRED_DEG);
        }
    }
    TV_CHECK(max_speed < 1.4 * 1.001);
    TV_CHECK(max_accel < 2.3);
    TV_CHECK(max_accel > 1.9); /* the 1 m fillets at 1.4 m/s do reach v^2/r */
    TV_CHECK(max_yaw_error < 1.0);
    pred_path_free(&p);
}

static void test_stop_and_turn(void)
{
    /* an out-and-back: the walker stops, turns on the spot, walks back */
    pred_synth_desc d = {.kind = PRED_SYNTH_WALK, .waypoint_count = 3, .waypoints = {{0, 0}, {0, 6}, {0, 0}}};
    pred_path p;
    char err[256];
    TV_CHECK(pred_path_synth(&d, &p, err, sizeof err));
    double max_z = 0.0, max_x = 0.0;
    for (size_t i = 0; i < p.count; i++) {
        max_z = fmax(max_z, p.poses[i].p[2]);
        max_x = fmax(max_x, fabs(p.poses[i].p[0]));
    }
    TV_CHECK_NEAR(max_z, 6.0, 1e-9); /* reaches the turning point exactly */
    TV_CHECK(max_x < 1e-9);          /* and never leaves the line */
    TV_CHECK_NEAR(p.poses[p.count - 1].p[2], 0.0, 0.02);
    pred_path_free(&p);
}

static void test_lookaround_rates(void)
{
    pred_synth_desc d = {.kind = PRED_SYNTH_LOOKAROUND, .seed = 5, .waypoint_count = 1,
                         .waypoints = {{3, -2}}, .sample_rate = 500};
    pred_path p;
    char err[256];
    TV_CHECK(pred_path_synth(&d, &p, err, sizeof err));
    TV_CHECK_NEAR(pred_path_duration(&p), 15.0, 1e-9);
    double peak = 0.0, max_off = 0.0;
    for (size_t i = 0; i + 1 < p.count; i++) {
        double rate = pred_quat_angle_deg(p.poses[i].q, p.poses[i + 1].q) / (p.poses[i + 1].t - p.poses[i].t);
        peak = fmax(peak, rate);
        max_off = fmax(max_off, hypot(p.poses[i].p[0] - 3.0, p.poses[i].p[2] + 2.0));
    }
    /* peaks drawn in [150, 250] deg/s; yaw and pitch together add a little */
    TV_CHECK(peak > 150.0 && peak < 280.0);
    TV_CHECK(max_off <= 0.015 * sqrt(2.0) + 1e-9);
    TV_CHECK(pred_path_mean_speed(&p, 0.0) < 0.05);
    pred_path_free(&p);
}

static void test_invalid(void)
{
    pred_path p;
    char err[256];
    pred_synth_desc d = {.kind = PRED_SYNTH_WALK, .waypoint_count = 1};
    TV_CHECK(!pred_path_synth(&d, &p, err, sizeof err) && strstr(err, "waypoints"));
    d = (pred_synth_desc){.kind = PRED_SYNTH_WALK, .waypoint_count = 3, .waypoints = {{0, 0}, {1, 1}, {1, 1}}};
    TV_CHECK(!pred_path_synth(&d, &p, err, sizeof err) && strstr(err, "coincide"));
    d = _walk();
    d.speed = -1.0;
    TV_CHECK(!pred_path_synth(&d, &p, err, sizeof err) && strstr(err, "positive"));
    d = _walk();
    d.waypoints[1][0] = NAN;
    TV_CHECK(!pred_path_synth(&d, &p, err, sizeof err) && strstr(err, "non-finite"));
    TV_CHECK(p.poses == NULL);
}

int main(void)
{
    TV_TEST_RUN(test_deterministic);
    TV_TEST_RUN(test_walk_geometry_and_smoothness);
    TV_TEST_RUN(test_stop_and_turn);
    TV_TEST_RUN(test_lookaround_rates);
    TV_TEST_RUN(test_invalid);
    return tv_test_finish();
}
