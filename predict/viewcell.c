#include "viewcell.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>

/* Stored as float: grow the sized cell by float rounding at tens of metres so
 * the eyes it was sized for test as covered. */
static const double k_delta_margin_m = 1e-5;
static const double k_alpha_margin_rad = 1e-6;

static float _fdef(float v, float def)
{
    return v == 0.0f ? def : v;
}

static pred_viewcell_desc _resolve(const pred_viewcell_desc* in)
{
    pred_viewcell_desc d = *in;
    d.latency_s = d.latency_s == 0.0 ? 0.05 : d.latency_s;
    d.window_s = d.window_s == 0.0 ? 0.05 : d.window_s;
    d.samples = d.samples ? d.samples : 9;
    d.display_fov_h_deg = _fdef(d.display_fov_h_deg, 60.0f);
    d.display_fov_v_deg = _fdef(d.display_fov_v_deg, 60.0f);
    d.ipd_m = _fdef(d.ipd_m, 0.063f);
    d.fixed_delta_m = _fdef(d.fixed_delta_m, 0.10f);
    d.fixed_fov_pvs_deg = _fdef(d.fixed_fov_pvs_deg, 90.0f);
    d.quantile = _fdef(d.quantile, 0.99f);
    d.min_delta_m = _fdef(d.min_delta_m, 0.02f);
    d.max_delta_m = _fdef(d.max_delta_m, 5.0f);
    d.min_fov_pvs_deg = _fdef(d.min_fov_pvs_deg, fmaxf(d.display_fov_h_deg, d.display_fov_v_deg));
    d.max_fov_pvs_deg = _fdef(d.max_fov_pvs_deg, 150.0f);
    d.warmup_records = d.warmup_records ? d.warmup_records : 50;
    d.warmup_pos_mps = _fdef(d.warmup_pos_mps, 1.0f);
    d.warmup_rot_dps = _fdef(d.warmup_rot_dps, 100.0f);
    d.head_acc_mps2 = _fdef(d.head_acc_mps2, 3.0f);
    d.head_speed_mps = _fdef(d.head_speed_mps, 1.5f);
    d.head_ang_acc_dps2 = _fdef(d.head_ang_acc_dps2, 2100.0f);
    d.head_ang_speed_dps = _fdef(d.head_ang_speed_dps, 400.0f);
    d.predictor_lag_s = _fdef(d.predictor_lag_s, 0.0125f);
    return d;
}

const char* pred_viewcell_miss_name(pred_viewcell_miss miss)
{
    switch (miss) {
    case PRED_VC_COVERED: return "covered";
    case PRED_VC_MISS_AXIAL: return "beyond an apex";
    case PRED_VC_MISS_RADIAL: return "outside the cone";
    case PRED_VC_MISS_FRUSTUM: return "frustum outside the PVS frustum";
    }
    return "?";
}

/* Smallest half-angle alpha of a square frustum holding a rectangular one of
 * half-angles (fh, fv) rotated by up to theta about any axis: every corner
 * direction must stay theta away from each face plane (radians). */
static double _alpha_for_rotation(double fh, double fv, double theta, bool* too_wide)
{
    double th = tan(fh), tv = tan(fv);
    double n = sqrt(1.0 + th * th + tv * tv);
    double sx = sin(theta) * n / sqrt(1.0 + th * th);
    double sy = sin(theta) * n / sqrt(1.0 + tv * tv);
    *too_wide = theta >= 0.5 * PRED_PI || sx > 1.0 || sy > 1.0;
    if (*too_wide)
        return 0.5 * PRED_PI;
    return fmax(fh + asin(sx), fv + asin(sy));
}

static void _store3(float dst[3], const double src[3])
{
    for (int i = 0; i < 3; i++)
        dst[i] = (float)src[i];
}

void pred_viewcell_from_poses(const pred_viewcell_desc* desc_in, const pred_pose* heads, int n, int mid,
                              double pos_err_m, double rot_err_deg, pred_viewcell* out)
{
    assert(desc_in && heads && n >= 1 && mid >= 0 && mid < n && out);
    pred_viewcell_desc d = _resolve(desc_in);
    const pred_pose* c = &heads[mid];
    double f[3], u[3];
    pred_pose_forward(c->q, f);
    pred_pose_up(c->q, u);
    *out = (pred_viewcell){0};
    out->t_begin = heads[0].t;
    out->t_end = heads[n - 1].t;
    out->fov_target_deg = fmaxf(d.display_fov_h_deg, d.display_fov_v_deg);
    out->pos_bound_m = (float)pos_err_m;
    out->rot_bound_deg = (float)rot_err_deg;
    double spread = 0.0;
    for (int i = 0; i < n; i++)
        spread = fmax(spread, pred_quat_angle_deg(c->q, heads[i].q));
    out->rot_spread_deg = (float)spread;

    double alpha, delta;
    out->frusta = 1;
    if (d.policy == PRED_POLICY_FIXED) {
        alpha = 0.5 * d.fixed_fov_pvs_deg * PRED_DEG;
        delta = d.fixed_delta_m;
    } else {
        bool too_wide;
        alpha = _alpha_for_rotation(0.5 * d.display_fov_h_deg * PRED_DEG, 0.5 * d.display_fov_v_deg * PRED_DEG,
                                    (spread + rot_err_deg) * PRED_DEG, &too_wide) + k_alpha_margin_rad;
        double lo = 0.5 * d.min_fov_pvs_deg * PRED_DEG, hi = 0.5 * d.max_fov_pvs_deg * PRED_DEG;
        bool omni = (too_wide || alpha > hi) && !d.single_frustum;
        out->clamped = (too_wide || alpha > hi) && d.single_frustum;
        alpha = omni ? PRED_VC_OMNI_HALF_DEG * PRED_DEG : fmin(fmax(alpha, lo), hi);
        out->frusta = omni ? PRED_VC_OMNI_FRUSTA : 1;
        /* eye e is inside iff a*tan(alpha) + r <= delta (a axial, r radial offset
         * from v0); a ball of radius eps around it adds at most eps/cos(alpha).
         * Omni: every face's cone must hold every eye whatever the face's
         * direction, i.e. the ball of radius max |e - v0| + eps, which a double
         * cone contains iff delta >= radius / cos(alpha) */
        double need = 0.0;
        for (int i = 0; i < n; i++) {
            pred_pose eyes[2];
            pred_eye_poses(&heads[i], d.ipd_m, eyes);
            for (int e = 0; e < 2; e++) {
                double v[3], a = 0.0, r2 = 0.0;
                for (int k = 0; k < 3; k++) {
                    v[k] = eyes[e].p[k] - c->p[k];
                    a += v[k] * f[k];
                }
                for (int k = 0; k < 3; k++)
                    r2 += (v[k] - a * f[k]) * (v[k] - a * f[k]);
                need = fmax(need, omni ? sqrt(a * a + r2) / cos(alpha) : fabs(a) * tan(alpha) + sqrt(r2));
            }
        }
        delta = fmax(need + pos_err_m / cos(alpha) + k_delta_margin_m, d.min_delta_m);
        out->whole_scene =
            delta > d.max_delta_m || (d.max_apex_offset_m > 0.0f && delta / tan(alpha) > d.max_apex_offset_m);
    }
    double z = delta / tan(alpha), apex[3];
    for (int k = 0; k < 3; k++)
        apex[k] = c->p[k] - z * f[k];
    _store3(out->v0, c->p);
    _store3(out->forward, f);
    _store3(out->up, u);
    _store3(out->apex, apex);
    out->delta = (float)delta;
    out->z = (float)z;
    out->fov_pvs_deg = (float)(2.0 * alpha / PRED_DEG);
}

/* Errors recorded at the tracked horizon that bounds `horizon` from above
 * (the last one beyond them), i.e. the data the bound is built from. */
static uint64_t _records_at(const pred_error_tracker* tr, double horizon)
{
    int h = 0;
    while (h < tr->horizon_count - 1 && tr->horizons_s[h] < horizon)
        h++;
    pred_error_stats pos, rot;
    pred_error_tracker_stats(tr, h, &pos, &rot);
    return pos.count;
}

void pred_viewcell_physical_bound(const pred_viewcell_desc* desc, double horizon_s, double speed_mps,
                                  double ang_speed_dps, double* pos_m, double* rot_deg)
{
    assert(desc && pos_m && rot_deg && horizon_s >= 0.0);
    pred_viewcell_desc d = _resolve(desc);
    double hl = horizon_s + d.predictor_lag_s;
    *pos_m = fmin(0.5 * d.head_acc_mps2 * hl * hl, (speed_mps + d.head_speed_mps) * horizon_s);
    *rot_deg = fmin(fmin(0.5 * d.head_ang_acc_dps2 * hl * hl, (ang_speed_dps + d.head_ang_speed_dps) * horizon_s),
                    180.0);
}

/* Speeds of the predicted motion at the newest sample (finite difference
 * over 10 ms of the prediction: what the predictor extrapolates with). */
static void _current_speeds(const pred_predictor* p, double t, double* speed, double* ang_speed)
{
    const double dt = 0.01;
    pred_pose a, b;
    pred_predictor_predict(p, t, &a);
    pred_predictor_predict(p, t + dt, &b);
    *speed = pred_vec3_dist(a.p, b.p) / dt;
    *ang_speed = pred_quat_angle_deg(a.q, b.q) / dt;
}

bool pred_viewcell_size(const pred_viewcell_desc* desc, const pred_predictor* predictor,
                        const pred_error_tracker* tracker, double t_request, pred_viewcell* out)
{
    assert(desc && predictor && out);
    if (!predictor->history.count)
        return false;
    pred_viewcell_desc d = _resolve(desc);
    int n = d.samples < 2 ? 2 : d.samples;
    pred_pose* heads = malloc((size_t)n * sizeof *heads);
    if (!heads)
        return false;
    double t0 = t_request + d.latency_s;
    for (int i = 0; i < n; i++)
        pred_predictor_predict(predictor, t0 + d.window_s * i / (n - 1), &heads[i]);
    double t_newest = pred_history_get(&predictor->history, 0)->t;
    double horizon = t0 + d.window_s - t_newest;
    double speed, ang_speed, pos_phys, rot_phys;
    _current_speeds(predictor, t_newest, &speed, &ang_speed);
    pred_viewcell_physical_bound(&d, horizon, speed, ang_speed, &pos_phys, &rot_phys);
    /* the tracker says how well the predictor did on the motion so far; the
     * physical bound covers what that motion did not show (a fast turn after
     * a calm stretch): each bound is the larger of the two */
    double pos_err = pos_phys, rot_err = rot_phys;
    if (tracker) {
        double pos_q, rot_q;
        pred_error_tracker_bound(tracker, horizon, d.quantile, &pos_q, &rot_q);
        pos_err = fmax(pos_err, pos_q);
        rot_err = fmax(rot_err, rot_q);
        if (_records_at(tracker, horizon) < (uint64_t)d.warmup_records) {
            pos_err = fmax(pos_err, d.warmup_pos_mps * horizon);
            rot_err = fmax(rot_err, d.warmup_rot_dps * horizon);
        }
    }
    /* with an even count no sample sits at the middle: size around the nearer-to-middle one */
    pred_viewcell_from_poses(&d, heads, n, n / 2, pos_err, rot_err, out);
    out->pos_phys_m = (float)pos_phys;
    out->rot_phys_deg = (float)rot_phys;
    free(heads);
    return true;
}

/* The viewcell's axes in double, re-orthonormalised (they are stored as
 * float): forward f, up u, right r = f x u. */
static void _frame(const pred_viewcell* vc, double f[3], double u[3], double r[3])
{
    double uf = 0.0;
    for (int k = 0; k < 3; k++) {
        f[k] = vc->forward[k];
        u[k] = vc->up[k];
    }
    double fn = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (int k = 0; k < 3; k++)
        f[k] /= fn;
    for (int k = 0; k < 3; k++)
        uf += u[k] * f[k];
    for (int k = 0; k < 3; k++)
        u[k] -= uf * f[k];
    double un = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (int k = 0; k < 3; k++)
        u[k] /= un;
    r[0] = f[1] * u[2] - f[2] * u[1];
    r[1] = f[2] * u[0] - f[0] * u[2];
    r[2] = f[0] * u[1] - f[1] * u[0];
}

void pred_viewcell_frustum(const pred_viewcell* vc, int i, pred_viewcell* out)
{
    assert(vc && out && i >= 0 && i < (vc->frusta > 1 ? vc->frusta : 1));
    *out = *vc;
    out->frusta = 1;
    if (vc->frusta <= 1)
        return;
    double f[3], u[3], r[3];
    _frame(vc, f, u, r);
    /* faces: +-forward and +-right keep up; +-up take forward as their up */
    const double* axis[3] = {f, r, u};
    const double* face_up = i < 4 ? u : f;
    double sign = (i & 1) ? -1.0 : 1.0;
    for (int k = 0; k < 3; k++) {
        double fk = sign * axis[i / 2][k];
        out->forward[k] = (float)fk;
        out->up[k] = (float)face_up[k];
        out->apex[k] = (float)(vc->v0[k] - vc->z * fk);
    }
}

/* Position part of the coverage test: inside the double cone. */
static pred_viewcell_miss _cone_miss(const pred_viewcell* vc, const double eye_p[3], double f[3], double u[3],
                                     double r[3])
{
    double v[3], a = 0.0, r2 = 0.0;
    _frame(vc, f, u, r);
    for (int k = 0; k < 3; k++)
        v[k] = eye_p[k] - vc->v0[k];
    for (int k = 0; k < 3; k++)
        a += v[k] * f[k];
    for (int k = 0; k < 3; k++)
        r2 += (v[k] - a * f[k]) * (v[k] - a * f[k]);
    a = fabs(a);
    if (a > vc->z)
        return PRED_VC_MISS_AXIAL;
    if (sqrt(r2) > vc->delta * (1.0 - a / vc->z))
        return PRED_VC_MISS_RADIAL;
    return PRED_VC_COVERED;
}

bool pred_viewcell_contains(const pred_viewcell* vc, const double eye_p[3], const double eye_q[4],
                            float eye_fov_h_deg, float eye_fov_v_deg, pred_viewcell_miss* why)
{
    double f[3], u[3], r[3];
    pred_viewcell_miss miss = PRED_VC_COVERED;
    if (vc->whole_scene) {
        if (why)
            *why = miss;
        return true;
    }
    if (vc->frusta > 1) {
        for (int i = 0; i < vc->frusta && !miss; i++) {
            pred_viewcell face;
            pred_viewcell_frustum(vc, i, &face);
            miss = _cone_miss(&face, eye_p, f, u, r);
        }
    } else if (!(miss = _cone_miss(vc, eye_p, f, u, r))) {
        /* inside the double cone means inside the PVS frustum from v*; a frustum
         * with its apex inside stays inside iff its edge directions do */
        double ta = tan(0.5 * vc->fov_pvs_deg * PRED_DEG);
        double th = tan(0.5 * eye_fov_h_deg * PRED_DEG), tv = tan(0.5 * eye_fov_v_deg * PRED_DEG);
        for (int corner = 0; corner < 4 && !miss; corner++) {
            double local[3] = {(corner & 1) ? th : -th, (corner & 2) ? tv : -tv, -1.0}, d[3];
            pred_quat_rotate(eye_q, local, d);
            double df = d[0] * f[0] + d[1] * f[1] + d[2] * f[2];
            double dr = d[0] * r[0] + d[1] * r[1] + d[2] * r[2];
            double du = d[0] * u[0] + d[1] * u[1] + d[2] * u[2];
            if (!(df > 0.0) || fabs(dr) > ta * df || fabs(du) > ta * df)
                miss = PRED_VC_MISS_FRUSTUM;
        }
    }
    if (why)
        *why = miss;
    return miss == PRED_VC_COVERED;
}
