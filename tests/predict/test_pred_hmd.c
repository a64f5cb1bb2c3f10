/* Simulated HMD: determinism from the seed, noise statistics, jitter, display
 * clock, eye poses and the pose-history ring buffer. */
#include "hmd.h"
#include "history.h"
#include "test.h"

#include <stdlib.h>
#include <string.h>

/* 2 s straight line at 1 m/s along +X with a constant yaw rate. */
static pred_path _line(void)
{
    pred_path p = {0};
    p.count = 201;
    p.poses = calloc(p.count, sizeof *p.poses);
    for (size_t i = 0; i < p.count; i++) {
        double t = 0.01 * (double)i;
        p.poses[i] = (pred_pose){.t = t, .p = {t, 1.7, 0}};
        pred_quat_from_ypr(0.5 * t, 0, 0, p.poses[i].q);
    }
    return p;
}

static int _collect(const hmd_desc* d, const pred_path* path, pred_pose* out, int cap)
{
    hmd_sim sim;
    hmd_sim_init(&sim, d, path);
    int n = 0;
    while (n < cap && hmd_sim_next(&sim, &out[n]))
        n++;
    return n;
}

static void test_determinism(void)
{
    pred_path path = _line();
    enum { CAP = 3000 };
    pred_pose* a = malloc(CAP * sizeof *a);
    pred_pose* b = malloc(CAP * sizeof *b);
    hmd_desc d = {.seed = 42};
    int na = _collect(&d, &path, a, CAP);
    int nb = _collect(&d, &path, b, CAP);
    TV_CHECK(na == 2001 && na == nb);
    TV_CHECK(memcmp(a, b, (size_t)na * sizeof *a) == 0);
    d.seed = 43;
    nb = _collect(&d, &path, b, CAP);
    TV_CHECK(memcmp(a, b, (size_t)na * sizeof *a) != 0);
    free(a);
    free(b);
    pred_path_free(&path);
}

static void test_noise_statistics(void)
{
    pred_path path = _line();
    enum { CAP = 3000 };
    pred_pose* s = malloc(CAP * sizeof *s);
    hmd_desc d = {.pos_noise_m = 0.001, .rot_noise_deg = 0.1, .jitter_ms = 0.1, .seed = 7};
    int n = _collect(&d, &path, s, CAP);
    double sum2 = 0.0, rot2 = 0.0, jit2 = 0.0;
    for (int i = 0; i < n; i++) {
        pred_pose truth;
        pred_path_sample(&path, s[i].t, &truth); /* the reported time is the measurement time */
        sum2 += (s[i].p[1] - truth.p[1]) * (s[i].p[1] - truth.p[1]);
        double ang = pred_quat_angle_deg(s[i].q, truth.q);
        rot2 += ang * ang;
        double dt = (s[i].t - 0.001 * i) * 1e3;
        jit2 += dt * dt;
    }
    TV_CHECK_NEAR(sqrt(sum2 / n), 0.001, 0.0001);
    /* 3-axis Gaussian: the angle's RMS is sqrt(3) sigma */
    TV_CHECK_NEAR(sqrt(rot2 / n), 0.1 * sqrt(3.0), 0.015);
    TV_CHECK_NEAR(sqrt(jit2 / n), 0.1, 0.01);
    free(s);
    pred_path_free(&path);
}

static void test_noiseless_and_clock(void)
{
    pred_path path = _line();
    hmd_sim sim;
    hmd_sim_init(&sim, &(hmd_desc){.noiseless = true}, &path);
    TV_CHECK(sim.desc.display_rate_hz == 90.0 && sim.desc.sensor_rate_hz == 1000.0 && sim.desc.ipd_m == 0.063);
    pred_pose s, truth;
    for (int i = 0; i < 1500; i++) {
        TV_CHECK(hmd_sim_next(&sim, &s));
        pred_path_sample(&path, 0.001 * i, &truth);
        if (fabs(s.t - 0.001 * i) > 1e-12 || pred_vec3_dist(s.p, truth.p) > 1e-12)
            TV_CHECK(false);
    }
    TV_CHECK_NEAR(hmd_display_time(&sim, 9), 0.1, 1e-12);
    TV_CHECK(hmd_display_frame_count(&sim) == 181); /* 0 .. 2 s inclusive at 90 Hz */
    pred_pose eyes[2];
    hmd_eye_poses(&sim, &truth, eyes);
    TV_CHECK_NEAR(pred_vec3_dist(eyes[0].p, eyes[1].p), 0.063, 1e-12);
    /* yaw 0.5 t: head-local +X is (cos, 0, -sin) in world; left eye on the -X side */
    TV_CHECK_NEAR(truth.t, 1.499, 1e-12);
    TV_CHECK_NEAR(eyes[1].p[0] - eyes[0].p[0], 0.063 * cos(0.5 * 1.499), 1e-12);
    TV_CHECK_NEAR(eyes[1].p[2] - eyes[0].p[2], -0.063 * sin(0.5 * 1.499), 1e-12);
    pred_path_free(&path);
}

static void test_history(void)
{
    static pred_history h; /* 32 KiB: keep it off the stack */
    pred_history_clear(&h);
    pred_pose s = {.q = {0, 0, 0, 1}};
    for (int i = 0; i < PRED_HISTORY_CAPACITY + 100; i++) {
        s.t = 0.001 * i;
        s.p[0] = i;
        TV_CHECK(pred_history_push(&h, &s));
    }
    TV_CHECK(h.count == PRED_HISTORY_CAPACITY);
    TV_CHECK(pred_history_get(&h, 0)->p[0] == PRED_HISTORY_CAPACITY + 99);
    TV_CHECK(pred_history_get(&h, PRED_HISTORY_CAPACITY - 1)->p[0] == 100);
    s.t = 0.001 * (PRED_HISTORY_CAPACITY + 99); /* same time: dropped */
    TV_CHECK(!pred_history_push(&h, &s));
    s.t -= 0.0005; /* earlier: dropped */
    TV_CHECK(!pred_history_push(&h, &s));
    TV_CHECK(h.dropped == 2 && pred_history_get(&h, 0)->p[0] == PRED_HISTORY_CAPACITY + 99);
    pred_pose out;
    TV_CHECK(pred_history_interpolate(&h, 0.2005, &out));
    TV_CHECK_NEAR(out.p[0], 200.5, 1e-9);
    TV_CHECK(pred_history_interpolate(&h, 0.1, &out) && out.p[0] == 100.0);
    TV_CHECK(!pred_history_interpolate(&h, 0.0995, &out));
    TV_CHECK(!pred_history_interpolate(&h, 1.0, &out));
}

static void test_jitter_reorders_are_dropped(void)
{
    /* jitter of a full period reorders samples; the history keeps them monotonic */
    pred_path path = _line();
    hmd_sim sim;
    hmd_sim_init(&sim, &(hmd_desc){.jitter_ms = 1.0, .seed = 3}, &path);
    static pred_history h;
    pred_history_clear(&h);
    pred_pose s;
    int n = 0;
    while (hmd_sim_next(&sim, &s)) {
        pred_history_push(&h, &s);
        n++;
    }
    TV_CHECK(h.dropped > 100 && h.dropped < (uint64_t)n / 2);
    bool monotonic = true;
    for (int i = 1; i < h.count; i++)
        monotonic = monotonic && pred_history_get(&h, i)->t < pred_history_get(&h, i - 1)->t;
    TV_CHECK(monotonic);
    pred_path_free(&path);
}

int main(void)
{
    TV_TEST_RUN(test_determinism);
    TV_TEST_RUN(test_noise_statistics);
    TV_TEST_RUN(test_noiseless_and_clock);
    TV_TEST_RUN(test_history);
    TV_TEST_RUN(test_jitter_reorders_are_dropped);
    return tv_test_finish();
}
