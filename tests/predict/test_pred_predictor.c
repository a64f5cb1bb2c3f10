/* Predictors (exactness on constant velocity, analytic error on circular
 * motion, bounded error on jerky motion) and the error tracker. */
#include "error_tracker.h"
#include "predictor.h"
#include "rng.h"
#include "test.h"

#include <stdlib.h>
#include <string.h>

typedef void (*motion_fn)(double t, pred_pose* out, const void* user);

static pred_predictor g_pred; /* 32+ KiB: static, not on the stack */

/* Feeds `fn` at 1 kHz for [0, t_end] (noiseless). */
static void _feed(pred_predictor* p, motion_fn fn, const void* user, double t_end)
{
    for (int i = 0; i <= (int)llround(t_end * 1000.0); i++) {
        pred_pose s;
        fn(0.001 * i, &s, user);
        TV_CHECK(pred_predictor_update(p, &s));
    }
}

static void _errors(const pred_predictor* p, motion_fn fn, const void* user, double t, double h, double* pos,
                    double* rot_deg)
{
    pred_pose predicted, truth;
    TV_CHECK(pred_predictor_predict(p, t + h, &predicted));
    fn(t + h, &truth, user);
    *pos = pred_vec3_dist(predicted.p, truth.p);
    *rot_deg = pred_quat_angle_deg(predicted.q, truth.q);
}

static void _linear_motion(double t, pred_pose* out, const void* user)
{
    (void)user;
    const double w[3] = {0.4 * t, -1.1 * t, 0.7 * t}; /* constant world angular velocity */
    double q0[4];
    pred_quat_from_ypr(0.3, -0.2, 0.1, q0);
    double dq[4];
    pred_quat_exp(w, dq);
    out->t = t;
    out->p[0] = 5.0 + 1.3 * t;
    out->p[1] = 1.7 - 0.2 * t;
    out->p[2] = -30.0 + 0.9 * t;
    pred_quat_mul(dq, q0, out->q);
}

static void test_kind_names(void)
{
    pred_kind k;
    TV_CHECK(pred_kind_from_name("kalman", &k) && k == PRED_KIND_KALMAN);
    TV_CHECK(pred_kind_from_name("cv", &k) && k == PRED_KIND_CV);
    TV_CHECK(pred_kind_from_name("ca", &k) && k == PRED_KIND_CA);
    TV_CHECK(!pred_kind_from_name("lstm", &k));
    TV_CHECK(strcmp(pred_kind_name(PRED_KIND_CA), "ca") == 0);
    pred_predictor_init(&g_pred, &(pred_predictor_desc){0});
    pred_pose out;
    TV_CHECK(!pred_predictor_predict(&g_pred, 1.0, &out)); /* no samples yet */
}

static void test_constant_velocity_is_exact(void)
{
    for (int k = 0; k < PRED_KIND_COUNT; k++) {
        pred_predictor_init(&g_pred, &(pred_predictor_desc){.kind = (pred_kind)k});
        double settle = k == PRED_KIND_KALMAN ? 3.0 : 0.1; /* the filter must converge first */
        _feed(&g_pred, _linear_motion, NULL, settle);
        double pos, rot;
        _errors(&g_pred, _linear_motion, NULL, settle, 0.1, &pos, &rot);
        double tol_pos = k == PRED_KIND_KALMAN ? 1e-5 : 1e-9;
        double tol_rot = k == PRED_KIND_KALMAN ? 1e-3 : 1e-7;
        if (pos > tol_pos || rot > tol_rot)
            fprintf(stderr, "%s: pos %g m rot %g deg\n", pred_kind_name((pred_kind)k), pos, rot);
        TV_CHECK(pos <= tol_pos);
        TV_CHECK(rot <= tol_rot);
    }
}

typedef struct circle {
    double r, v;
} circle;

/* Walking a circle of radius r at speed v, looking along the motion. */
static void _circle_motion(double t, pred_pose* out, const void* user)
{
    const circle* c = user;
    double a = c->v * t / c->r;
    out->t = t;
    out->p[0] = c->r * sin(a);
    out->p[1] = 1.7;
    out->p[2] = -c->r * cos(a) + c->r; /* starts at the origin moving along +X */
    /* direction (cos a, 0, sin a): yaw = -(a) - pi/2 for a head looking down -Z */
    pred_quat_from_ypr(-a - 0.5 * PRED_PI, 0.0, 0.0, out->q);
}

/* Error at horizon h of a least-squares line through f(tau) = tau^2/2 sampled
 * at tau = 0, -1 ms, ..., -window: the normal offset of a circle is kappa times it. */
static double _line_fit_error(double window, double h)
{
    double s0 = 0, s1 = 0, s2 = 0, y0 = 0, y1 = 0;
    for (int i = 0; i <= (int)llround(window * 1000.0); i++) {
        double tau = -0.001 * i, f = 0.5 * tau * tau;
        s0 += 1;
        s1 += tau;
        s2 += tau * tau;
        y0 += f;
        y1 += tau * f;
    }
    double det = s0 * s2 - s1 * s1;
    double c0 = (y0 * s2 - y1 * s1) / det, c1 = (s0 * y1 - s1 * y0) / det;
    return 0.5 * h * h - (c0 + c1 * h);
}

static void test_circular_motion_cv_error(void)
{
    const circle c = {.r = 2.0, .v = 1.5};
    const double kappa = c.v * c.v / c.r;
    const double windows[] = {0.001, 0.025};
    const double horizons[] = {0.02, 0.05, 0.1};
    for (int w = 0; w < 2; w++) {
        pred_predictor_init(&g_pred, &(pred_predictor_desc){.kind = PRED_KIND_CV, .window_s = windows[w]});
        _feed(&g_pred, _circle_motion, &c, 1.0);
        for (int h = 0; h < 3; h++) {
            double pos, rot;
            _errors(&g_pred, _circle_motion, &c, 1.0, horizons[h], &pos, &rot);
            double expect = kappa * _line_fit_error(windows[w], horizons[h]);
            if (w == 0) /* two samples: the line is the chord: h^2/2 + hW/2 exactly */
                TV_CHECK_NEAR(_line_fit_error(0.001, horizons[h]),
                              0.5 * horizons[h] * horizons[h] + 0.0005 * horizons[h], 1e-12);
            TV_CHECK_NEAR(pos / expect, 1.0, 0.03);
            TV_CHECK(rot < 1e-6); /* constant yaw rate: exact */
        }
    }
    /* the instantaneous-velocity limit the brief quotes: v^2 h^2 / (2 r) */
    TV_CHECK_NEAR(kappa * _line_fit_error(0.001, 0.05) / (c.v * c.v * 0.05 * 0.05 / (2 * c.r)), 1.0, 0.021);
    /* constant acceleration follows the circle far better */
    double cv_pos, ca_pos, rot;
    _errors(&g_pred, _circle_motion, &c, 1.0, 0.05, &cv_pos, &rot);
    pred_predictor_init(&g_pred, &(pred_predictor_desc){.kind = PRED_KIND_CA});
    _feed(&g_pred, _circle_motion, &c, 1.0);
    _errors(&g_pred, _circle_motion, &c, 1.0, 0.05, &ca_pos, &rot);
    TV_CHECK(ca_pos < 0.1 * cv_pos);
}

/* A head at rest seen through 0.2 mm of sensor noise for the first 4 ms:
 * ca must not carry a parabola through them 100 ms ahead (the one through
 * 0, 0.2, 0.2, 0 mm at 1 ms steps is -200 m/s^2: 1 m off at 100 ms). */
static void test_ca_start_up(void)
{
    pred_predictor_init(&g_pred, &(pred_predictor_desc){.kind = PRED_KIND_CA});
    for (int i = 0; i < 4; i++) {
        pred_pose s = {.t = 0.001 * i, .p = {0.0, 1.7 + (i == 1 || i == 2 ? 2e-4 : 0.0), 0.0}, .q = {0, 0, 0, 1}};
        TV_CHECK(pred_predictor_update(&g_pred, &s));
    }
    pred_pose out;
    TV_CHECK(pred_predictor_predict(&g_pred, 0.103, &out));
    TV_CHECK(fabs(out.p[1] - 1.7) < 0.01); /* the line through them: a few mm at most */
    /* once the samples span the 60 ms window the parabola is back: exact on a free fall */
    pred_predictor_init(&g_pred, &(pred_predictor_desc){.kind = PRED_KIND_CA});
    for (int i = 0; i <= 80; i++) {
        double t = 0.001 * i;
        pred_pose s = {.t = t, .p = {0.0, 1.7 - 4.9 * t * t, 0.0}, .q = {0, 0, 0, 1}};
        TV_CHECK(pred_predictor_update(&g_pred, &s));
    }
    TV_CHECK(pred_predictor_predict(&g_pred, 0.18, &out));
    TV_CHECK_NEAR(out.p[1], 1.7 - 4.9 * 0.18 * 0.18, 1e-6);
}

/* Jerky motion: per axis, acceleration +-A switching at random 20-80 ms intervals. */
typedef struct jerky {
    double A;
    int segments;
    double t[400], a[400][3], p[400][3], v[400][3];
} jerky;

static void _jerky_build(jerky* j, double A, uint64_t seed)
{
    tv_rng rng;
    tv_rng_seed(&rng, seed, 1);
    j->A = A;
    j->segments = 400;
    double t = 0.0, p[3] = {0, 1.7, 0}, v[3] = {0.5, 0, -0.3};
    for (int s = 0; s < j->segments; s++) {
        j->t[s] = t;
        double dur = tv_rng_range(&rng, 0.02, 0.08);
        for (int k = 0; k < 3; k++) {
            j->a[s][k] = tv_rng_uniform(&rng) < 0.5 ? -A : A;
            j->p[s][k] = p[k];
            j->v[s][k] = v[k];
            p[k] += v[k] * dur + 0.5 * j->a[s][k] * dur * dur;
            v[k] += j->a[s][k] * dur;
        }
        t += dur;
    }
}

static void _jerky_motion(double t, pred_pose* out, const void* user)
{
    const jerky* j = user;
    int s = 0;
    while (s + 1 < j->segments && j->t[s + 1] <= t)
        s++;
    double dt = t - j->t[s];
    out->t = t;
    for (int k = 0; k < 3; k++)
        out->p[k] = j->p[s][k] + j->v[s][k] * dt + 0.5 * j->a[s][k] * dt * dt;
    out->q[0] = out->q[1] = out->q[2] = 0.0;
    out->q[3] = 1.0;
}

static void test_jerky_motion_bound(void)
{
    static jerky j;
    _jerky_build(&j, 8.0, 99);
    /* two-sample line: |error| <= A (h^2/2 + h W / 2) per axis for |accel| <= A */
    const double W = 0.001, h = 0.05, bound = j.A * (0.5 * h * h + 0.5 * h * W);
    pred_predictor_init(&g_pred, &(pred_predictor_desc){.kind = PRED_KIND_CV, .window_s = W});
    double worst = 0.0;
    for (int i = 0; i <= 10000; i++) {
        pred_pose s, predicted, truth;
        _jerky_motion(0.001 * i, &s, &j);
        pred_predictor_update(&g_pred, &s);
        if (i < 2)
            continue;
        pred_predictor_predict(&g_pred, s.t + h, &predicted);
        _jerky_motion(s.t + h, &truth, &j);
        for (int k = 0; k < 3; k++)
            worst = fmax(worst, fabs(predicted.p[k] - truth.p[k]));
    }
    TV_CHECK(worst <= bound * (1.0 + 1e-9));
    TV_CHECK(worst > 0.5 * bound); /* the bound is nearly reached: the test has teeth */
}

static int _cmp(const void* a, const void* b)
{
    double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

static void test_tracker_quantiles(void)
{
    pred_error_tracker tr;
    TV_CHECK(pred_error_tracker_init(&tr, &(pred_error_tracker_desc){.window = 100}));
    TV_CHECK(tr.horizon_count == 10 && fabs(tr.horizons_s[9] - 0.1) < 1e-12);
    tv_rng rng;
    tv_rng_seed(&rng, 5, 0);
    double values[1000], ref[100], all_max = 0.0;
    for (int i = 0; i < 1000; i++) {
        /* drifting distribution: the window must forget old values */
        values[i] = tv_rng_uniform(&rng) * (1.0 + i / 100.0) + (i == 123 ? 50.0 : 0.0);
        all_max = fmax(all_max, values[i]);
        pred_error_tracker_record(&tr, 3, values[i], 2.0 * values[i]);
        if (i % 97 == 0 || i == 999) {
            int n = i + 1 < 100 ? i + 1 : 100;
            memcpy(ref, values + (i + 1 - n), (size_t)n * sizeof *ref);
            qsort(ref, (size_t)n, sizeof *ref, _cmp);
            const double qs[] = {0.01, 0.5, 0.95, 0.99, 1.0};
            for (int q = 0; q < 5; q++) {
                int rank = (int)ceil(qs[q] * n);
                TV_CHECK(pred_error_tracker_quantile_pos(&tr, 3, qs[q]) == ref[rank - 1]);
                TV_CHECK(pred_error_tracker_quantile_rot(&tr, 3, qs[q]) == 2.0 * ref[rank - 1]);
            }
        }
    }
    pred_error_stats pos, rot;
    pred_error_tracker_stats(&tr, 3, &pos, &rot);
    TV_CHECK(pos.count == 1000 && pos.max == all_max && rot.max == 2.0 * all_max);
    TV_CHECK(pos.p50 <= pos.p95 && pos.p95 <= pos.p99 && pos.p99 <= pos.max);
    pred_error_tracker_stats(&tr, 0, &pos, &rot);
    TV_CHECK(pos.count == 0 && pos.p99 == 0.0);
    pred_error_tracker_free(&tr);
    TV_CHECK(!pred_error_tracker_init(&tr, &(pred_error_tracker_desc){.horizon_count = 2, .horizons_s = {0.02, 0.01}}));
}

static void test_tracker_observe(void)
{
    /* truth moves along +X at 1 m/s, sampled every 1 ms; predictions are off by
     * 1 cm and 2 degrees and target times between samples */
    pred_error_tracker tr;
    TV_CHECK(pred_error_tracker_init(&tr, &(pred_error_tracker_desc){.horizon_count = 2, .horizons_s = {0.01, 0.05}}));
    double q2[4];
    pred_quat_from_ypr(2.0 * PRED_DEG, 0, 0, q2);
    for (int i = 0; i < 300; i++) {
        double t = 0.001 * i;
        for (int h = 0; h < 2; h++) {
            double target = t + tr.horizons_s[h] + 0.0004;
            pred_pose p = {.t = target, .p = {target, 0.01, 0}, .q = {q2[0], q2[1], q2[2], q2[3]}};
            TV_CHECK(pred_error_tracker_push(&tr, h, &p));
        }
        pred_pose truth = {.t = t, .p = {t, 0, 0}, .q = {0, 0, 0, 1}};
        pred_error_tracker_observe(&tr, &truth);
    }
    pred_error_stats pos, rot;
    for (int h = 0; h < 2; h++) {
        pred_error_tracker_stats(&tr, h, &pos, &rot);
        TV_CHECK(pos.count == (h == 0 ? 289u : 249u)); /* resolved once a later sample arrives */
        TV_CHECK_NEAR(pos.p50, 0.01, 1e-12);
        TV_CHECK_NEAR(pos.max, 0.01, 1e-12);
        TV_CHECK_NEAR(rot.p99, 2.0, 1e-9);
    }
    TV_CHECK(tr.pending[1].count == 51);
    /* bound: exact at a horizon, linear between, quadratic growth past the last */
    pred_error_tracker_record(&tr, 1, 0.03, 4.0);
    double p, r;
    pred_error_tracker_bound(&tr, 0.05, 1.0, &p, &r);
    TV_CHECK_NEAR(p, 0.03, 1e-12);
    pred_error_tracker_bound(&tr, 0.03, 1.0, &p, &r);
    TV_CHECK_NEAR(p, 0.02, 1e-12);
    TV_CHECK_NEAR(r, 3.0, 1e-9);
    pred_error_tracker_bound(&tr, 0.1, 1.0, &p, &r);
    TV_CHECK_NEAR(p, 0.12, 1e-12);
    pred_error_tracker_bound(&tr, 0.001, 1.0, &p, &r);
    TV_CHECK_NEAR(p, 0.01, 1e-12);
    pred_error_tracker_free(&tr);
}

int main(void)
{
    TV_TEST_RUN(test_kind_names);
    TV_TEST_RUN(test_constant_velocity_is_exact);
    TV_TEST_RUN(test_circular_motion_cv_error);
    TV_TEST_RUN(test_ca_start_up);
    TV_TEST_RUN(test_jerky_motion_bound);
    TV_TEST_RUN(test_tracker_quantiles);
    TV_TEST_RUN(test_tracker_observe);
    return tv_test_finish();
}
