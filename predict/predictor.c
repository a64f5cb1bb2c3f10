#include "predictor.h"

#include <assert.h>
#include <math.h>
#include <string.h>

static const char* const k_names[PRED_KIND_COUNT] = {"cv", "ca", "kalman"};

const char* pred_kind_name(pred_kind kind)
{
    assert(kind >= 0 && kind < PRED_KIND_COUNT);
    return k_names[kind];
}

bool pred_kind_from_name(const char* name, pred_kind* kind)
{
    for (int k = 0; k < PRED_KIND_COUNT; k++) {
        if (strcmp(name, k_names[k]) == 0) {
            *kind = (pred_kind)k;
            return true;
        }
    }
    return false;
}

static double _def(double v, double def)
{
    return v == 0.0 ? def : v;
}

void pred_predictor_init(pred_predictor* p, const pred_predictor_desc* desc)
{
    assert(p && desc && desc->kind >= 0 && desc->kind < PRED_KIND_COUNT);
    memset(p, 0, sizeof *p);
    p->desc = *desc;
    p->desc.window_s = _def(desc->window_s, desc->kind == PRED_KIND_CA ? 0.06 : 0.025);
    p->desc.kf_accel_psd = _def(desc->kf_accel_psd, 0.1);
    p->desc.kf_angaccel_psd = _def(desc->kf_angaccel_psd, 10.0);
    p->desc.kf_pos_sigma = _def(desc->kf_pos_sigma, 0.0002);
    p->desc.kf_rot_sigma_deg = _def(desc->kf_rot_sigma_deg, 0.02);
}

/* ---- least-squares polynomial fit (cv: degree 1, ca: degree 2) ---- */

/* Solves the (n x n) system A x = b for 6 right-hand sides by Gaussian
 * elimination with partial pivoting; false when singular. */
static bool _solve(int n, double A[3][3], double b[3][6])
{
    for (int c = 0; c < n; c++) {
        int piv = c;
        for (int r = c + 1; r < n; r++)
            if (fabs(A[r][c]) > fabs(A[piv][c]))
                piv = r;
        if (fabs(A[piv][c]) < 1e-12)
            return false;
        for (int k = 0; k < 3; k++) {
            double t = A[c][k];
            A[c][k] = A[piv][k];
            A[piv][k] = t;
        }
        for (int k = 0; k < 6; k++) {
            double t = b[c][k];
            b[c][k] = b[piv][k];
            b[piv][k] = t;
        }
        for (int r = 0; r < n; r++) {
            if (r == c)
                continue;
            double f = A[r][c] / A[c][c];
            for (int k = 0; k < 3; k++)
                A[r][k] -= f * A[c][k];
            for (int k = 0; k < 6; k++)
                b[r][k] -= f * b[c][k];
        }
    }
    for (int r = 0; r < n; r++)
        for (int k = 0; k < 6; k++)
            b[r][k] /= A[r][r];
    return true;
}

static void _predict_fit(const pred_predictor* p, double t, pred_pose* out)
{
    const pred_history* h = &p->history;
    const pred_pose* newest = pred_history_get(h, 0);
    double w = p->desc.window_s;
    int n = 0;
    while (n < h->count && newest->t - pred_history_get(h, n)->t <= w + 1e-12)
        n++;
    int terms = p->desc.kind == PRED_KIND_CA ? 3 : 2;
    /* The acceleration term only once the history reaches back past the
     * window: a parabola through the first few milliseconds of noisy samples,
     * carried 60-100 ms ahead, missed by 0.34 m at the start of every trace. */
    if (terms == 3 && n == h->count && newest->t - pred_history_get(h, n - 1)->t < w - 1e-9)
        terms = 2;
    if (terms > n)
        terms = n;
    /* channels 0-2 position, 3-5 rotation vector of q_i * conj(q_newest);
     * time in window units keeps the normal equations well conditioned */
    double A[3][3] = {{0}}, b[3][6] = {{0}};
    double inv_newest[4];
    pred_quat_conj(newest->q, inv_newest);
    for (int i = 0; i < n; i++) {
        const pred_pose* s = pred_history_get(h, i);
        double u = (s->t - newest->t) / w;
        double y[6], rel[4];
        pred_quat_mul(s->q, inv_newest, rel);
        y[0] = s->p[0];
        y[1] = s->p[1];
        y[2] = s->p[2];
        pred_quat_log(rel, y + 3);
        double pw[5] = {1.0, u, u * u, u * u * u, u * u * u * u};
        for (int j = 0; j < terms; j++) {
            for (int k = 0; k < terms; k++)
                A[j][k] += pw[j + k];
            for (int c = 0; c < 6; c++)
                b[j][c] += pw[j] * y[c];
        }
    }
    if (!_solve(terms, A, b)) { /* cannot happen with distinct times; hold the newest pose */
        *out = *newest;
        out->t = t;
        return;
    }
    double u = (t - newest->t) / w;
    double y[6] = {0};
    for (int c = 0; c < 6; c++)
        for (int j = terms - 1; j >= 0; j--)
            y[c] = y[c] * u + b[j][c];
    out->t = t;
    out->p[0] = y[0];
    out->p[1] = y[1];
    out->p[2] = y[2];
    double dq[4];
    pred_quat_exp(y + 3, dq);
    pred_quat_mul(dq, newest->q, out->q);
    pred_quat_normalize(out->q);
}

/* ---- Kalman filter ---- */

/* Time update of one group: P = F P F^T + Q for F = [1 dt; 0 1] and white
 * acceleration of spectral density psd. */
static void _kf_time_update(pred_kf_group* g, double dt, double psd)
{
    double (*P)[2] = g->P;
    double p00 = P[0][0] + dt * (P[1][0] + P[0][1]) + dt * dt * P[1][1];
    double p01 = P[0][1] + dt * P[1][1];
    double p11 = P[1][1];
    P[0][0] = p00 + psd * dt * dt * dt / 3.0;
    P[0][1] = P[1][0] = p01 + psd * dt * dt / 2.0;
    P[1][1] = p11 + psd * dt;
}

/* Measurement update of one group (measuring the value with variance r):
 * returns the gains for value and rate and shrinks P. */
static void _kf_gain(pred_kf_group* g, double r, double K[2])
{
    double (*P)[2] = g->P;
    double s = P[0][0] + r;
    K[0] = P[0][0] / s;
    K[1] = P[1][0] / s;
    double p00 = P[0][0], p01 = P[0][1];
    P[0][0] -= K[0] * p00;
    P[0][1] -= K[0] * p01;
    P[1][0] -= K[1] * p00;
    P[1][1] -= K[1] * p01;
}

static void _kf_start(pred_kf_group* g, double r, double rate_sigma)
{
    memset(g, 0, sizeof *g);
    g->P[0][0] = r;
    g->P[1][1] = rate_sigma * rate_sigma;
}

static void _kf_update(pred_predictor* p, const pred_pose* z)
{
    const pred_predictor_desc* d = &p->desc;
    double rp = d->kf_pos_sigma * d->kf_pos_sigma;
    double rr = (d->kf_rot_sigma_deg * PRED_DEG) * (d->kf_rot_sigma_deg * PRED_DEG);
    if (!p->kf_started) {
        p->kf_started = true;
        p->kf_t = z->t;
        memcpy(p->kf_p, z->p, sizeof p->kf_p);
        memcpy(p->kf_q, z->q, sizeof p->kf_q);
        /* a head at rest or walking: rates start at zero with a generous spread */
        _kf_start(&p->kf_pos, rp, 2.0);
        _kf_start(&p->kf_rot, rr, 3.0);
        return;
    }
    double dt = z->t - p->kf_t;
    p->kf_t = z->t;
    double step[3], dq[4], K[2];
    for (int i = 0; i < 3; i++) {
        p->kf_p[i] += p->kf_pos.rate[i] * dt;
        step[i] = p->kf_rot.rate[i] * dt;
    }
    pred_quat_exp(step, dq);
    pred_quat_mul(dq, p->kf_q, p->kf_q);
    _kf_time_update(&p->kf_pos, dt, d->kf_accel_psd);
    _kf_time_update(&p->kf_rot, dt, d->kf_angaccel_psd);

    _kf_gain(&p->kf_pos, rp, K);
    for (int i = 0; i < 3; i++) {
        double innovation = z->p[i] - p->kf_p[i];
        p->kf_p[i] += K[0] * innovation;
        p->kf_pos.rate[i] += K[1] * innovation;
    }
    double inv[4], rel[4], innovation[3], corr[3];
    pred_quat_conj(p->kf_q, inv);
    pred_quat_mul(z->q, inv, rel);
    pred_quat_log(rel, innovation);
    _kf_gain(&p->kf_rot, rr, K);
    for (int i = 0; i < 3; i++) {
        corr[i] = K[0] * innovation[i];
        p->kf_rot.rate[i] += K[1] * innovation[i];
    }
    pred_quat_exp(corr, dq);
    pred_quat_mul(dq, p->kf_q, p->kf_q);
    pred_quat_normalize(p->kf_q);
}

static void _predict_kf(const pred_predictor* p, double t, pred_pose* out)
{
    double h = t - p->kf_t, step[3], dq[4];
    out->t = t;
    for (int i = 0; i < 3; i++) {
        out->p[i] = p->kf_p[i] + p->kf_pos.rate[i] * h;
        step[i] = p->kf_rot.rate[i] * h;
    }
    pred_quat_exp(step, dq);
    pred_quat_mul(dq, p->kf_q, out->q);
    pred_quat_normalize(out->q);
}

bool pred_predictor_update(pred_predictor* p, const pred_pose* sample)
{
    if (!pred_history_push(&p->history, sample))
        return false;
    if (p->desc.kind == PRED_KIND_KALMAN)
        _kf_update(p, sample);
    return true;
}

bool pred_predictor_predict(const pred_predictor* p, double t, pred_pose* out)
{
    if (!p->history.count)
        return false;
    if (p->desc.kind == PRED_KIND_KALMAN)
        _predict_kf(p, t, out);
    else
        _predict_fit(p, t, out);
    return true;
}
