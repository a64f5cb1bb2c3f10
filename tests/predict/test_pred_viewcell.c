/* Viewcell sizing and the coverage test. */
#include "rng.h"
#include "test.h"
#include "viewcell.h"

#include <string.h>

static void _axis_frame(const pred_viewcell* vc, double f[3], double u[3], double r[3])
{
    for (int k = 0; k < 3; k++) {
        f[k] = vc->forward[k];
        u[k] = vc->up[k];
    }
    r[0] = f[1] * u[2] - f[2] * u[1];
    r[1] = f[2] * u[0] - f[0] * u[2];
    r[2] = f[0] * u[1] - f[1] * u[0];
}

/* A fixed cell: v0 (1, 2, 3), looking along yaw 30 / pitch 10, delta 0.2, 90 deg. */
static pred_viewcell _fixed_cell(double q[4])
{
    pred_pose head = {.t = 0, .p = {1, 2, 3}};
    pred_quat_from_ypr(30 * PRED_DEG, 10 * PRED_DEG, 0, head.q);
    memcpy(q, head.q, sizeof head.q);
    pred_viewcell vc;
    pred_viewcell_from_poses(&(pred_viewcell_desc){.policy = PRED_POLICY_FIXED, .fixed_delta_m = 0.2f}, &head, 1, 0,
                             0.0, 0.0, &vc);
    return vc;
}

static void test_fixed_policy(void)
{
    double q[4], f[3];
    pred_viewcell vc = _fixed_cell(q);
    pred_pose_forward(q, f);
    TV_CHECK_NEAR(vc.delta, 0.2, 1e-7);
    TV_CHECK_NEAR(vc.fov_pvs_deg, 90.0, 1e-5);
    TV_CHECK_NEAR(vc.fov_target_deg, 60.0, 0);
    TV_CHECK_NEAR(vc.z, 0.2, 1e-6); /* tan 45 = 1 */
    for (int k = 0; k < 3; k++) {
        TV_CHECK_NEAR(vc.forward[k], f[k], 1e-7);
        TV_CHECK_NEAR(vc.apex[k], vc.v0[k] - vc.z * f[k], 1e-6);
    }
}

static bool _covered_at(const pred_viewcell* vc, const double q[4], double a, double radial, const double dir[3],
                        pred_viewcell_miss* why)
{
    double f[3], u[3], r[3], p[3];
    _axis_frame(vc, f, u, r);
    for (int k = 0; k < 3; k++)
        p[k] = vc->v0[k] + a * f[k] + radial * dir[k];
    return pred_viewcell_contains(vc, p, q, 10.0f, 10.0f, why);
}

static void test_cone_boundary(void)
{
    double q[4], f[3], u[3], r[3];
    pred_viewcell vc = _fixed_cell(q);
    _axis_frame(&vc, f, u, r);
    pred_viewcell_miss why;
    const double e = 1e-4, z = vc.z, delta = vc.delta;
    /* on the axis, both apexes */
    for (int s = -1; s <= 1; s += 2) {
        TV_CHECK(_covered_at(&vc, q, s * (z - e), 0, u, &why));
        TV_CHECK(!_covered_at(&vc, q, s * (z + e), 0, u, &why) && why == PRED_VC_MISS_AXIAL);
    }
    /* off the axis, in several directions, both cones: just in / just out of the slanted surface */
    double dirs[4][3];
    for (int k = 0; k < 3; k++) {
        dirs[0][k] = u[k];
        dirs[1][k] = -r[k];
        dirs[2][k] = (u[k] + r[k]) / sqrt(2.0);
        dirs[3][k] = (0.6 * u[k] - 0.8 * r[k]);
    }
    const double axial[] = {0.0, 0.05, -0.12, 0.19};
    for (int d = 0; d < 4; d++) {
        for (int i = 0; i < 4; i++) {
            double a = axial[i], limit = delta * (1.0 - fabs(a) / z);
            TV_CHECK(_covered_at(&vc, q, a, limit - e, dirs[d], &why));
            TV_CHECK(!_covered_at(&vc, q, a, limit + e, dirs[d], &why) && why == PRED_VC_MISS_RADIAL);
        }
    }
    TV_CHECK(strcmp(pred_viewcell_miss_name(PRED_VC_MISS_RADIAL), "outside the cone") == 0);
}

/* Eye at `p`, orientation = cell orientation turned by `angle_deg` about `axis` (cell frame: 0 up, 1 right). */
static bool _covered_turned(const pred_viewcell* vc, const double q[4], const double p[3], int axis, double angle_deg,
                            float fov_h, float fov_v, pred_viewcell_miss* why)
{
    double f[3], u[3], r[3], rv[3], dq[4], eq[4];
    _axis_frame(vc, f, u, r);
    for (int k = 0; k < 3; k++)
        rv[k] = (axis == 0 ? u[k] : r[k]) * angle_deg * PRED_DEG;
    pred_quat_exp(rv, dq);
    pred_quat_mul(dq, q, eq);
    return pred_viewcell_contains(vc, p, eq, fov_h, fov_v, why);
}

static void test_frustum_boundary(void)
{
    double q[4], f[3], u[3], r[3];
    pred_viewcell vc = _fixed_cell(q);
    _axis_frame(&vc, f, u, r);
    pred_viewcell_miss why;
    /* a 60x60 eye in a 90 deg PVS frustum: a pure yaw or pitch of 15 deg puts
     * its corners on the PVS faces; the eye's position does not matter as long
     * as it is in the cell (on-axis and off-axis eyes alike) */
    double centre[3], off[3];
    for (int k = 0; k < 3; k++) {
        centre[k] = vc.v0[k];
        off[k] = vc.v0[k] + 0.05 * f[k] + 0.1 * r[k] - 0.04 * u[k];
    }
    const double* eyes[2] = {centre, off};
    for (int e = 0; e < 2; e++) {
        for (int axis = 0; axis < 2; axis++) {
            for (int s = -1; s <= 1; s += 2) {
                TV_CHECK(_covered_turned(&vc, q, eyes[e], axis, s * 14.99, 60, 60, &why));
                TV_CHECK(!_covered_turned(&vc, q, eyes[e], axis, s * 15.01, 60, 60, &why) &&
                         why == PRED_VC_MISS_FRUSTUM);
            }
        }
    }
    /* roll: the rectangle, not a cone, is tested. 80x80 fits unrolled (corner
     * tan 0.84 < 1 per axis) but not rolled 45 deg (its diagonal, tan 1.19, lands on an axis) */
    double fr[3], dq[4], eq[4];
    for (int k = 0; k < 3; k++)
        fr[k] = f[k] * 45.0 * PRED_DEG;
    pred_quat_exp(fr, dq);
    pred_quat_mul(dq, q, eq);
    TV_CHECK(pred_viewcell_contains(&vc, centre, q, 80.0f, 80.0f, &why));
    TV_CHECK(!pred_viewcell_contains(&vc, centre, eq, 80.0f, 80.0f, &why) && why == PRED_VC_MISS_FRUSTUM);
    TV_CHECK(pred_viewcell_contains(&vc, centre, eq, 60.0f, 60.0f, &why));
    /* looking backwards */
    TV_CHECK(!_covered_turned(&vc, q, centre, 0, 180.0, 10, 10, &why) && why == PRED_VC_MISS_FRUSTUM);
}

/* Random unit vector. */
static void _rand_dir(tv_rng* rng, double d[3])
{
    double n;
    do {
        for (int k = 0; k < 3; k++)
            d[k] = tv_rng_range(rng, -1, 1);
        n = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    } while (n < 0.1 || n > 1.0);
    for (int k = 0; k < 3; k++)
        d[k] /= n;
}

static void test_adaptive_alpha_is_tight(void)
{
    /* no translation; rotation bound theta: every eye turned by <= theta about
     * any axis is covered, and a PVS frustum 0.3 deg narrower misses some */
    pred_pose head = {.p = {0, 1.7, 0}};
    pred_quat_from_ypr(0.4, 0.1, 0.0, head.q);
    const double theta = 15.0;
    pred_viewcell vc;
    pred_viewcell_from_poses(&(pred_viewcell_desc){.policy = PRED_POLICY_ADAPTIVE, .min_delta_m = 0.001f}, &head, 1, 0,
                             0.0, theta, &vc);
    double t = tan(30 * PRED_DEG), n = sqrt(1 + 2 * t * t);
    double alpha = 30.0 + asin(sin(theta * PRED_DEG) * n / sqrt(1 + t * t)) / PRED_DEG;
    TV_CHECK_NEAR(vc.fov_pvs_deg, 2.0 * alpha, 1e-3); /* 93.6, not the paper's 60 + 2*15 */
    pred_viewcell narrower = vc;
    narrower.fov_pvs_deg -= 0.3f;
    narrower.z = (float)(narrower.delta / tan(0.5 * narrower.fov_pvs_deg * PRED_DEG));
    tv_rng rng;
    tv_rng_seed(&rng, 1, 2);
    int missed_wide = 0, missed_narrow = 0;
    double eye[3] = {vc.v0[0], vc.v0[1], vc.v0[2]};
    for (int i = 0; i < 20000; i++) {
        double axis[3], dq[4], eq[4];
        _rand_dir(&rng, axis);
        for (int k = 0; k < 3; k++)
            axis[k] *= theta * PRED_DEG;
        pred_quat_exp(axis, dq);
        pred_quat_mul(dq, head.q, eq);
        missed_wide += !pred_viewcell_contains(&vc, eye, eq, 60, 60, NULL);
        missed_narrow += !pred_viewcell_contains(&narrower, eye, eq, 60, 60, NULL);
    }
    TV_CHECK(missed_wide == 0);
    TV_CHECK(missed_narrow > 0);
}

/* Predicted head poses over a 50 ms window: 3 m/s forward, yawing at 120 deg/s, pitching. */
static void _window_heads(pred_pose heads[9])
{
    for (int i = 0; i < 9; i++) {
        double t = 0.00625 * i;
        heads[i] = (pred_pose){.t = t, .p = {3.0 * t, 1.7 + 0.2 * t, -0.5 * t}};
        pred_quat_from_ypr(120 * PRED_DEG * t, -40 * PRED_DEG * t, 5 * PRED_DEG * t, heads[i].q);
    }
}

static void test_sizing_covers_predicted_eyes(void)
{
    pred_pose heads[9];
    _window_heads(heads);
    const double pos_err = 0.01, rot_err = 2.0;
    pred_viewcell vc;
    pred_viewcell_desc desc = {.policy = PRED_POLICY_ADAPTIVE, .display_fov_h_deg = 70, .display_fov_v_deg = 60};
    pred_viewcell_from_poses(&desc, heads, 9, 4, pos_err, rot_err, &vc);
    TV_CHECK(!vc.clamped);
    TV_CHECK_NEAR(vc.fov_target_deg, 70.0, 0);
    TV_CHECK(vc.rot_spread_deg > 3.0 && vc.rot_spread_deg < 4.0);
    TV_CHECK_NEAR(vc.z, vc.delta / tan(0.5 * vc.fov_pvs_deg * PRED_DEG), 1e-6);
    /* every predicted eye, and eyes displaced by up to pos_err and turned by up
     * to rot_err from them, are covered */
    tv_rng rng;
    tv_rng_seed(&rng, 9, 9);
    int missed = 0, tested = 0;
    for (int i = 0; i < 9; i++) {
        pred_pose eyes[2];
        pred_eye_poses(&heads[i], 0.063, eyes);
        for (int e = 0; e < 2; e++) {
            missed += !pred_viewcell_contains(&vc, eyes[e].p, eyes[e].q, 70, 60, NULL);
            tested++;
            for (int j = 0; j < 200; j++) {
                double d[3], p[3], w[3], dq[4], q[4];
                _rand_dir(&rng, d);
                for (int k = 0; k < 3; k++)
                    p[k] = eyes[e].p[k] + pos_err * 0.999 * d[k];
                _rand_dir(&rng, w);
                for (int k = 0; k < 3; k++)
                    w[k] *= rot_err * 0.999 * PRED_DEG;
                pred_quat_exp(w, dq);
                pred_quat_mul(dq, eyes[e].q, q);
                missed += !pred_viewcell_contains(&vc, p, q, 70, 60, NULL);
                tested++;
            }
        }
    }
    TV_CHECK(tested == 18 * 201 && missed == 0);
    /* and the cell is not needlessly large: 5% smaller misses some predicted eye */
    pred_viewcell smaller = vc;
    smaller.delta *= 0.95f;
    smaller.z = (float)(smaller.delta / tan(0.5 * smaller.fov_pvs_deg * PRED_DEG));
    missed = 0;
    for (int i = 0; i < 9; i++) {
        pred_pose eyes[2];
        pred_eye_poses(&heads[i], 0.063, eyes);
        for (int e = 0; e < 2; e++) {
            for (int j = 0; j < 200; j++) {
                double d[3], p[3];
                _rand_dir(&rng, d);
                for (int k = 0; k < 3; k++)
                    p[k] = eyes[e].p[k] + pos_err * d[k];
                missed += !pred_viewcell_contains(&smaller, p, eyes[e].q, 70, 60, NULL);
            }
        }
    }
    TV_CHECK(missed > 0);
    /* no clamp: a 1 m error bound makes delta at least 1 m / cos alpha; a
     * delta or apex limit below it gives the whole scene, which covers any eye */
    pred_viewcell_from_poses(&desc, heads, 9, 4, 1.0, rot_err, &vc);
    TV_CHECK(!vc.clamped && !vc.whole_scene && vc.delta >= 1.0 / cos(0.5 * vc.fov_pvs_deg * PRED_DEG));
    pred_viewcell sized = vc;
    pred_viewcell_desc limited = desc;
    limited.max_apex_offset_m = 0.99f * sized.z;
    pred_viewcell_from_poses(&limited, heads, 9, 4, 1.0, rot_err, &vc);
    TV_CHECK(vc.whole_scene &&
             pred_viewcell_contains(&vc, (double[3]){1e3, 0, 0}, (double[4]){0, 0, 0, 1}, 60, 60, NULL));
    limited = desc;
    limited.max_delta_m = 0.99f * sized.delta;
    pred_viewcell_from_poses(&limited, heads, 9, 4, 1.0, rot_err, &vc);
    TV_CHECK(vc.whole_scene && vc.delta == sized.delta);
}

static void test_size_from_predictor(void)
{
    static pred_predictor p;
    pred_predictor_init(&p, &(pred_predictor_desc){.kind = PRED_KIND_CV});
    pred_viewcell vc;
    pred_viewcell_desc desc = {.policy = PRED_POLICY_ADAPTIVE, .latency_s = 0.03, .window_s = 0.04};
    TV_CHECK(!pred_viewcell_size(&desc, &p, NULL, 0.0, &vc));
    /* constant velocity and yaw rate: CV predicts exactly, so the true eyes of the window are covered */
    for (int i = 0; i <= 200; i++) {
        pred_pose s = {.t = 0.001 * i, .p = {1.4 * 0.001 * i, 1.7, 0}};
        pred_quat_from_ypr(-PRED_PI / 2 + 1.5 * s.t, 0, 0, s.q);
        pred_predictor_update(&p, &s);
    }
    TV_CHECK(pred_viewcell_size(&desc, &p, NULL, 0.2, &vc));
    TV_CHECK_NEAR(vc.t_begin, 0.23, 1e-12);
    TV_CHECK_NEAR(vc.t_end, 0.27, 1e-12);
    TV_CHECK_NEAR(vc.v0[0], 1.4 * 0.25, 1e-6);
    for (int i = 0; i <= 40; i++) {
        pred_pose head = {.t = 0.23 + 0.001 * i, .p = {1.4 * (0.23 + 0.001 * i), 1.7, 0}}, eyes[2];
        pred_quat_from_ypr(-PRED_PI / 2 + 1.5 * head.t, 0, 0, head.q);
        pred_eye_poses(&head, 0.063, eyes);
        for (int e = 0; e < 2; e++)
            TV_CHECK(pred_viewcell_contains(&vc, eyes[e].p, eyes[e].q, 60, 60, NULL));
    }
}

int main(void)
{
    TV_TEST_RUN(test_fixed_policy);
    TV_TEST_RUN(test_cone_boundary);
    TV_TEST_RUN(test_frustum_boundary);
    TV_TEST_RUN(test_adaptive_alpha_is_tight);
    TV_TEST_RUN(test_sizing_covers_predicted_eyes);
    TV_TEST_RUN(test_size_from_predictor);
    return tv_test_finish();
}
