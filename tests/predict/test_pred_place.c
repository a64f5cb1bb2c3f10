/* Placement of a recorded trace in a scene (predict/trace_place.h): the
 * reference lands on the anchor, the reference forward gets the requested
 * heading, heights follow the eye-height rule, and the trace moves rigidly. */
#include "test.h"
#include "trace_place.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A small trace starting at (1, 0.2, 3) looking 30 degrees left of -Z and
 * 10 degrees down, walking and turning; median height 0.3. */
static void make_trace(pred_path* p)
{
    memset(p, 0, sizeof *p);
    p->count = 5;
    p->poses = calloc(p->count, sizeof *p->poses);
    for (size_t i = 0; i < p->count; i++) {
        pred_pose* s = &p->poses[i];
        s->t = 0.1 * (double)i;
        s->p[0] = 1.0 - 0.3 * (double)i;
        s->p[1] = 0.2 + 0.05 * (double)i;
        s->p[2] = 3.0 - 0.4 * (double)i;
        pred_quat_from_ypr((30.0 + 5.0 * (double)i) * PRED_DEG, -10.0 * PRED_DEG, 0.0, s->q);
    }
}

static double yaw_deg_of(const double q[4])
{
    double f[3];
    pred_pose_forward(q, f);
    return atan2(-f[0], -f[2]) / PRED_DEG;
}

static void test_start_lands_on_anchor(void)
{
    pred_path p, orig;
    make_trace(&p);
    make_trace(&orig);
    double yaw;
    double ref[3];
    pred_trace_reference(&p, PRED_PLACE_START, ref, &yaw);
    TV_CHECK_NEAR(yaw / PRED_DEG, 30.0, 1e-9);
    pred_placement pl = {.anchor = {10.0, 5.0, -4.0}, .heading_deg = 90.0};
    TV_CHECK(pred_trace_place(&p, &pl));
    TV_CHECK_NEAR(p.poses[0].p[0], 10.0, 1e-12);
    TV_CHECK_NEAR(p.poses[0].p[1], 5.0, 1e-12);
    TV_CHECK_NEAR(p.poses[0].p[2], -4.0, 1e-12);
    TV_CHECK_NEAR(yaw_deg_of(p.poses[0].q), 90.0, 1e-9);
    /* the turn is +60 degrees about +Y: every heading moves by 60, pitch stays */
    TV_CHECK_NEAR(yaw_deg_of(p.poses[4].q), 110.0, 1e-9);
    double f[3];
    pred_pose_forward(p.poses[4].q, f);
    TV_CHECK_NEAR(f[1], -sin(10.0 * PRED_DEG), 1e-12);
    /* the first step (-0.3, +0.05, -0.4) turned by 60 degrees: x' = x cos + z sin, z' = -x sin + z cos */
    double c = cos(60.0 * PRED_DEG), s = sin(60.0 * PRED_DEG);
    TV_CHECK_NEAR(p.poses[1].p[0] - p.poses[0].p[0], -0.3 * c + -0.4 * s, 1e-12);
    TV_CHECK_NEAR(p.poses[1].p[1] - p.poses[0].p[1], 0.05, 1e-12);
    TV_CHECK_NEAR(p.poses[1].p[2] - p.poses[0].p[2], 0.3 * s + -0.4 * c, 1e-12);
    /* rigid: pairwise distances and relative rotations are unchanged */
    for (size_t i = 1; i < p.count; i++) {
        TV_CHECK_NEAR(pred_vec3_dist(p.poses[i].p, p.poses[0].p), pred_vec3_dist(orig.poses[i].p, orig.poses[0].p),
                      1e-12);
        TV_CHECK_NEAR(pred_quat_angle_deg(p.poses[i].q, p.poses[0].q),
                      pred_quat_angle_deg(orig.poses[i].q, orig.poses[0].q), 1e-6);
        TV_CHECK_NEAR(p.poses[i].t, orig.poses[i].t, 0.0);
    }
    pred_path_free(&p);
    pred_path_free(&orig);
}

static void test_centroid_and_eye_height(void)
{
    pred_path p;
    make_trace(&p);
    pred_placement pl = {.anchor = {-2.0, 1.0, 7.0}, .heading_deg = -45.0, .ref = PRED_PLACE_CENTROID,
                         .eye_height_m = 1.7, .height_offset_m = 0.1};
    TV_CHECK_NEAR(pred_trace_median_height(&p), 0.3, 1e-12);
    TV_CHECK(pred_trace_place(&p, &pl));
    double c[3], yaw;
    pred_trace_reference(&p, PRED_PLACE_CENTROID, c, &yaw);
    TV_CHECK_NEAR(c[0], -2.0, 1e-12);
    TV_CHECK_NEAR(c[2], 7.0, 1e-12);
    TV_CHECK_NEAR(yaw / PRED_DEG, -45.0, 1e-9); /* the mean heading (40 deg before) gets the requested one */
    TV_CHECK_NEAR(pred_trace_median_height(&p), 1.0 + 1.7 + 0.1, 1e-12);
    TV_CHECK_NEAR(p.poses[0].p[1], 2.8 - 0.1, 1e-12); /* 0.1 below the median before and after */
    pred_path_free(&p);
}

static void test_format(void)
{
    pred_placement pl = {.anchor = {1.0, 0.0, -2.5}, .heading_deg = 90.0, .eye_height_m = 1.7};
    char buf[256];
    pred_placement_format(&pl, buf, sizeof buf);
    TV_CHECK(strcmp(buf, "placement: anchor=1.000,0.000,-2.500 heading=90.00 ref=start eye-height=1.700 "
                         "height-offset=0.000") == 0);
}

int main(void)
{
    TV_TEST_RUN(test_start_lands_on_anchor);
    TV_TEST_RUN(test_centroid_and_eye_height);
    TV_TEST_RUN(test_format);
    return tv_test_finish();
}
