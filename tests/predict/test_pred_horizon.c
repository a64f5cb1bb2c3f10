/* Viewcell sizing from the prediction horizon: the physical bound, a fast
 * turn after a calm stretch, and the all-directions (omni) viewcell. */
#include "rng.h"
#include "test.h"
#include "viewcell.h"

#include <string.h>

static void test_physical_bound_known_answers(void)
{
    pred_viewcell_desc d = {.policy = PRED_POLICY_ADAPTIVE};
    double pos, rot;
    /* at rest, 100 ms: the acceleration terms, (h + 12.5 ms)^2 */
    pred_viewcell_physical_bound(&d, 0.1, 0.0, 0.0, &pos, &rot);
    TV_CHECK_NEAR(pos, 0.5 * 3.0 * 0.1125 * 0.1125, 1e-6);
    TV_CHECK_NEAR(rot, 0.5 * 2100.0 * 0.1125 * 0.1125, 1e-4);
    /* 300 ms, turning at 50 deg/s: 1050 * 0.3125^2 is below the speed cap (50 + 400) * 0.3 */
    pred_viewcell_physical_bound(&d, 0.3, 1.4, 50.0, &pos, &rot);
    TV_CHECK_NEAR(rot, 0.5 * 2100.0 * 0.3125 * 0.3125, 1e-4);
    TV_CHECK_NEAR(pos, 0.5 * 3.0 * 0.3125 * 0.3125, 1e-6);
    /* a slow head limit: the speed cap (50 + 100) * 0.3 = 45 deg rules */
    pred_viewcell_physical_bound(&(pred_viewcell_desc){.head_ang_speed_dps = 100}, 0.3, 1.4, 50.0, &pos, &rot);
    TV_CHECK_NEAR(rot, 45.0, 1e-4);
    /* 2 s walking at 1.4 m/s: position capped by (1.4 + 1.5) * 2; rotation by a half turn */
    pred_viewcell_physical_bound(&d, 2.0, 1.4, 0.0, &pos, &rot);
    TV_CHECK_NEAR(pos, 5.8, 1e-6);
    TV_CHECK_NEAR(rot, 180.0, 0);
    /* desc values replace the defaults */
    pred_viewcell_physical_bound(&(pred_viewcell_desc){.head_ang_acc_dps2 = 1000, .predictor_lag_s = 0.1}, 0.1, 0, 0,
                                 &pos, &rot);
    TV_CHECK_NEAR(rot, 0.5 * 1000 * 0.2 * 0.2, 1e-4);
}

/* A head held still for 5 s, then turning (about yaw, with constant angular
 * acceleration acc_dps2 from the newest sample on) and sliding sideways at
 * 2.9 m/s^2 (the bound's 3): are both eyes covered over the whole use window? */
static bool _turn_covered(const pred_viewcell* vc, double t_newest, double acc_dps2)
{
    bool all = true;
    for (double t = vc->t_begin; t <= vc->t_end + 1e-9; t += 0.001) {
        double h = t - t_newest;
        pred_pose head = {.t = t, .p = {0.5 * 2.9 * h * h, 1.7, 0}}, eyes[2];
        pred_quat_from_ypr(0.5 * acc_dps2 * h * h * PRED_DEG, 0, 0, head.q);
        pred_eye_poses(&head, 0.063, eyes);
        for (int e = 0; e < 2; e++)
            all = all && pred_viewcell_contains(vc, eyes[e].p, eyes[e].q, 60, 60, NULL);
    }
    return all;
}

/* A head held still for 5 s (samples at 1 kHz up to t = 5 s) whose tracker
 * has seen only calm motion: 1 mm and 0.5 deg errors at every horizon. */
static void _calm_head(pred_predictor* p, pred_error_tracker* tr)
{
    pred_predictor_init(p, &(pred_predictor_desc){.kind = PRED_KIND_CV});
    for (int i = 0; i <= 5000; i++) {
        pred_pose s = {.t = 0.001 * i, .p = {0, 1.7, 0}, .q = {0, 0, 0, 1}};
        pred_predictor_update(p, &s);
    }
    TV_CHECK(pred_error_tracker_init(tr, &(pred_error_tracker_desc){0}));
    for (int i = 0; i < 400; i++)
        for (int h = 0; h < tr->horizon_count; h++)
            pred_error_tracker_record(tr, h, 0.001, 0.5);
}

/* The tracker has seen only calm motion (0.5 deg errors); the physical bound
 * still covers a turn at the bound's acceleration starting right after the
 * request, and a turn 50 % harder than that leaves the cell. */
static void test_fast_turn_after_calm(void)
{
    pred_predictor p;
    pred_error_tracker tr;
    _calm_head(&p, &tr);
    pred_viewcell_desc desc = {.policy = PRED_POLICY_ADAPTIVE, .latency_s = 0.05, .window_s = 0.061};
    pred_viewcell vc;
    TV_CHECK(pred_viewcell_size(&desc, &p, &tr, 5.0, &vc));
    double h = 0.111 + 0.0125;
    printf("  calm: rotation bound %.2f deg, position %.4f m, PVS FOV %.1f deg, delta %.3f m\n", vc.rot_bound_deg,
           vc.pos_bound_m, vc.fov_pvs_deg, vc.delta);
    TV_CHECK_NEAR(vc.rot_bound_deg, 0.5 * 2100 * h * h, 1e-3);
    TV_CHECK_NEAR(vc.pos_bound_m, 0.5 * 3.0 * h * h, 1e-6);
    TV_CHECK(vc.rot_phys_deg == vc.rot_bound_deg && vc.frusta == 1 && !vc.clamped);
    TV_CHECK(_turn_covered(&vc, 5.0, 2050.0));
    TV_CHECK(!_turn_covered(&vc, 5.0, 3150.0));
    /* once the tracker has seen larger errors than the physical bound, they rule */
    for (int i = 0; i < 400; i++)
        for (int hh = 0; hh < tr.horizon_count; hh++)
            pred_error_tracker_record(&tr, hh, 0.001, 300.0 * tr.horizons_s[hh]);
    TV_CHECK(pred_viewcell_size(&desc, &p, &tr, 5.0, &vc));
    TV_CHECK(vc.rot_bound_deg > 30.0 && vc.rot_phys_deg < 17.0);
    pred_error_tracker_free(&tr);
}

/* Every ray direction lies in one of the omni faces' square frusta. */
static void test_omni_faces_cover_every_direction(void)
{
    pred_pose head = {.p = {2, 1.7, -3}};
    pred_quat_from_ypr(0.7, -0.2, 0.3, head.q);
    pred_pose heads[3] = {head, head, head};
    for (int i = 0; i < 3; i++) /* a half turn over the window */
        pred_quat_from_ypr(0.7 + (i - 1) * 0.5 * PRED_PI, -0.2, 0.3, heads[i].q);
    pred_viewcell vc;
    pred_viewcell_from_poses(&(pred_viewcell_desc){.policy = PRED_POLICY_ADAPTIVE}, heads, 3, 1, 0.01, 2.0, &vc);
    TV_CHECK(vc.frusta == PRED_VC_OMNI_FRUSTA && !vc.clamped);
    /* eyes at ipd/2 from v0, grown by 1 cm: delta = (0.0315 + 0.01) / cos 46 deg */
    TV_CHECK_NEAR(vc.delta, (0.0315 + 0.01) / cos(PRED_VC_OMNI_HALF_DEG * PRED_DEG) + 1e-5, 1e-6);
    TV_CHECK_NEAR(vc.fov_pvs_deg, 2 * PRED_VC_OMNI_HALF_DEG, 1e-4);
    pred_viewcell faces[PRED_VC_OMNI_FRUSTA];
    for (int i = 0; i < PRED_VC_OMNI_FRUSTA; i++) {
        pred_viewcell_frustum(&vc, i, &faces[i]);
        TV_CHECK(faces[i].frusta == 1 && faces[i].delta == vc.delta && faces[i].z == vc.z);
        double fu = 0, ff = 0;
        for (int k = 0; k < 3; k++) {
            fu += faces[i].forward[k] * faces[i].up[k];
            ff += faces[i].forward[k] * vc.forward[k];
            TV_CHECK_NEAR(faces[i].apex[k], vc.v0[k] - vc.z * faces[i].forward[k], 1e-5);
        }
        TV_CHECK_NEAR(fu, 0.0, 1e-6);
        TV_CHECK_NEAR(ff, i == 0 ? 1.0 : i == 1 ? -1.0 : 0.0, 1e-6);
    }
    tv_rng rng;
    tv_rng_seed(&rng, 3, 4);
    double ta = tan(PRED_VC_OMNI_HALF_DEG * PRED_DEG);
    for (int j = 0; j < 20000; j++) {
        double d[3] = {tv_rng_range(&rng, -1, 1), tv_rng_range(&rng, -1, 1), tv_rng_range(&rng, -1, 1)};
        int in = 0;
        for (int i = 0; i < PRED_VC_OMNI_FRUSTA; i++) {
            const float *f = faces[i].forward, *u = faces[i].up;
            float r[3] = {f[1] * u[2] - f[2] * u[1], f[2] * u[0] - f[0] * u[2], f[0] * u[1] - f[1] * u[0]};
            double df = d[0] * f[0] + d[1] * f[1] + d[2] * f[2];
            double dr = d[0] * r[0] + d[1] * r[1] + d[2] * r[2];
            double du = d[0] * u[0] + d[1] * u[1] + d[2] * u[2];
            in += df > 0 && fabs(dr) <= ta * df && fabs(du) <= ta * df;
        }
        TV_CHECK(in >= 1);
    }
}

/* A full turn during the use window: a head spinning at 720 deg/s with a
 * 500 ms window. The viewcell goes omni and covers every eye of the turn,
 * in any orientation at those positions; an eye 2 delta away is not. */
static void test_full_turn_is_covered(void)
{
    pred_predictor p;
    pred_predictor_init(&p, &(pred_predictor_desc){.kind = PRED_KIND_CV});
    const double rate = 4.0 * PRED_PI; /* rad/s */
    for (int i = 0; i <= 1000; i++) {
        pred_pose s = {.t = 0.001 * i, .p = {1, 1.7, 2}};
        pred_quat_from_ypr(rate * s.t, 0, 0, s.q);
        pred_predictor_update(&p, &s);
    }
    pred_viewcell_desc desc = {.policy = PRED_POLICY_ADAPTIVE, .latency_s = 0.1, .window_s = 0.5};
    pred_viewcell vc;
    TV_CHECK(pred_viewcell_size(&desc, &p, NULL, 1.0, &vc));
    printf("  full turn: %d frusta, delta %.3f m, rotation bound %.1f deg\n", vc.frusta, vc.delta, vc.rot_bound_deg);
    TV_CHECK(vc.frusta == PRED_VC_OMNI_FRUSTA && !vc.clamped);
    tv_rng rng;
    tv_rng_seed(&rng, 5, 6);
    int missed = 0, tested = 0;
    for (double t = vc.t_begin; t <= vc.t_end + 1e-9; t += 0.002) {
        pred_pose head = {.t = t, .p = {1, 1.7, 2}}, eyes[2];
        pred_quat_from_ypr(rate * t, 0, 0, head.q);
        pred_eye_poses(&head, 0.063, eyes);
        for (int e = 0; e < 2; e++) {
            double q[4] = {tv_rng_range(&rng, -1, 1), tv_rng_range(&rng, -1, 1), tv_rng_range(&rng, -1, 1),
                           tv_rng_range(&rng, -1, 1)};
            pred_quat_normalize(q);
            missed += !pred_viewcell_contains(&vc, eyes[e].p, eyes[e].q, 60, 60, NULL);
            missed += !pred_viewcell_contains(&vc, eyes[e].p, q, 60, 60, NULL);
            tested += 2;
        }
    }
    TV_CHECK(tested > 500 && missed == 0);
    pred_viewcell_miss why;
    double far[3] = {vc.v0[0] + 2 * vc.delta, vc.v0[1], vc.v0[2]};
    TV_CHECK(!pred_viewcell_contains(&vc, far, (double[4]){0, 0, 0, 1}, 60, 60, &why) && why != PRED_VC_COVERED);
    /* with single_frustum the same window clamps the FOV and says so */
    desc.single_frustum = true;
    TV_CHECK(pred_viewcell_size(&desc, &p, NULL, 1.0, &vc));
    TV_CHECK(vc.frusta == 1 && vc.clamped && vc.fov_pvs_deg == 150.0f);
}

/* Sideways distance (m) at h after the newest sample of a head at rest that
 * accelerates at 2.9 m/s^2 up to 1.4 m/s (inside the bound's 3 m/s^2 and
 * 1.5 m/s), and its yaw (deg) turning at 2050 deg/s^2 up to 390 deg/s. */
static void _burst(double h, double* x, double* yaw)
{
    const double a = 2.9, v = 1.4, aa = 2050.0, w = 390.0;
    *x = h < v / a ? 0.5 * a * h * h : v * (h - 0.5 * v / a);
    *yaw = h < w / aa ? 0.5 * aa * h * h : w * (h - 0.5 * w / aa);
}

/* A device whose PVS takes 0.6 s: the window is [0.6, 1.2 s] after the
 * request. A head still for 5 s (the tracker saw 0.5 deg errors) then starts
 * walking sideways and turning as fast as the physical bound allows: the
 * viewcell goes all-directions with delta = the bound / cos 46 deg, far
 * above the 0.5 m the sizing once clamped to, and covers every eye of the
 * window in its real orientation; the same burst leaves a 0.5 m cell. */
static void test_burst_after_calm_at_long_latency(void)
{
    pred_predictor p;
    pred_error_tracker tr;
    _calm_head(&p, &tr);
    pred_viewcell_desc desc = {.policy = PRED_POLICY_ADAPTIVE, .latency_s = 0.6, .window_s = 0.6111,
                               .max_apex_offset_m = 31.7f};
    pred_viewcell vc;
    TV_CHECK(pred_viewcell_size(&desc, &p, &tr, 5.0, &vc));
    /* at rest: min(3/2 (h + 12.5 ms)^2, 1.5 h) at h = 1.2111 s is the speed cap */
    double h = 1.2111;
    printf("  burst: %d frusta, delta %.3f m, position bound %.3f m\n", vc.frusta, vc.delta, vc.pos_bound_m);
    TV_CHECK_NEAR(vc.pos_bound_m, 1.5 * h, 1e-5);
    TV_CHECK(vc.frusta == PRED_VC_OMNI_FRUSTA && !vc.whole_scene);
    /* the eyes sit ipd/2 from v0: delta = (0.0315 + bound) / cos 46 deg */
    TV_CHECK_NEAR(vc.delta, (0.0315 + 1.5 * h) / cos(PRED_VC_OMNI_HALF_DEG * PRED_DEG) + 1e-5, 1e-4);
    pred_viewcell small = vc;
    small.delta = 0.5f;
    small.z = small.delta / (float)tan(0.5 * small.fov_pvs_deg * PRED_DEG);
    int missed = 0, missed_small = 0;
    for (double t = vc.t_begin; t <= vc.t_end + 1e-9; t += 0.005) {
        double x, yaw;
        _burst(t - 5.0, &x, &yaw);
        pred_pose head = {.t = t, .p = {x, 1.7, 0}}, eyes[2];
        pred_quat_from_ypr(yaw * PRED_DEG, 0, 0, head.q);
        pred_eye_poses(&head, 0.063, eyes);
        for (int e = 0; e < 2; e++) {
            missed += !pred_viewcell_contains(&vc, eyes[e].p, eyes[e].q, 60, 60, NULL);
            missed_small += !pred_viewcell_contains(&small, eyes[e].p, eyes[e].q, 60, 60, NULL);
        }
    }
    TV_CHECK(missed == 0 && missed_small > 0);
    pred_error_tracker_free(&tr);
}

/* A horizon longer than any PVS resolves: 10 s of latency on a head at
 * rest makes delta 1.5 m/s x 20 s / cos 46 deg = 43 m, an apex 42 m behind
 * v0, beyond the 31.7 m limit: the viewcell is the whole scene, which covers
 * an eye anywhere; without the limit it is that 43 m cell. */
static void test_huge_horizon_is_whole_scene(void)
{
    pred_predictor p;
    pred_predictor_init(&p, &(pred_predictor_desc){.kind = PRED_KIND_CV});
    for (int i = 0; i <= 1000; i++)
        pred_predictor_update(&p, &(pred_pose){.t = 0.001 * i, .p = {0, 1.7, 0}, .q = {0, 0, 0, 1}});
    pred_viewcell_desc desc = {.policy = PRED_POLICY_ADAPTIVE, .latency_s = 10.0, .window_s = 10.0,
                               .max_apex_offset_m = 31.7f};
    pred_viewcell vc;
    TV_CHECK(pred_viewcell_size(&desc, &p, NULL, 1.0, &vc));
    TV_CHECK(vc.whole_scene && vc.frusta == PRED_VC_OMNI_FRUSTA && vc.z > 31.7f);
    TV_CHECK_NEAR(vc.delta, (0.0315 + 1.5 * 20.0) / cos(PRED_VC_OMNI_HALF_DEG * PRED_DEG) + 1e-5, 1e-3);
    pred_viewcell_miss why = PRED_VC_MISS_AXIAL;
    TV_CHECK(pred_viewcell_contains(&vc, (double[3]){500, 1.7, -80}, (double[4]){0, 0.6, 0, 0.8}, 60, 60, &why) &&
             why == PRED_VC_COVERED);
    /* the default 5 m delta limit alone also says whole scene; without either it is that 43 m cell */
    desc.max_apex_offset_m = 0.0f;
    TV_CHECK(pred_viewcell_size(&desc, &p, NULL, 1.0, &vc) && vc.whole_scene);
    desc.max_delta_m = 100.0f;
    TV_CHECK(pred_viewcell_size(&desc, &p, NULL, 1.0, &vc));
    TV_CHECK(!vc.whole_scene && vc.delta > 43.0f);
}

int main(void)
{
    TV_TEST_RUN(test_physical_bound_known_answers);
    TV_TEST_RUN(test_fast_turn_after_calm);
    TV_TEST_RUN(test_omni_faces_cover_every_direction);
    TV_TEST_RUN(test_full_turn_is_covered);
    TV_TEST_RUN(test_burst_after_calm_at_long_latency);
    TV_TEST_RUN(test_huge_horizon_is_whole_scene);
    return tv_test_finish();
}
