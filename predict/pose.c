#include "pose.h"

#include <math.h>

void pred_quat_mul(const double a[4], const double b[4], double out[4])
{
    double r[4] = {
        a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1],
        a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
        a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3],
        a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2],
    };
    for (int i = 0; i < 4; i++)
        out[i] = r[i];
}

void pred_quat_conj(const double q[4], double out[4])
{
    out[0] = -q[0];
    out[1] = -q[1];
    out[2] = -q[2];
    out[3] = q[3];
}

double pred_quat_normalize(double q[4])
{
    double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (n == 0.0) {
        q[0] = q[1] = q[2] = 0.0;
        q[3] = 1.0;
        return 0.0;
    }
    for (int i = 0; i < 4; i++)
        q[i] /= n;
    return n;
}

void pred_quat_rotate(const double q[4], const double v[3], double out[3])
{
    /* v' = v + 2w (u x v) + 2 u x (u x v), u = vector part */
    const double* u = q;
    double w = q[3];
    double c[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    double cc[3] = {u[1] * c[2] - u[2] * c[1], u[2] * c[0] - u[0] * c[2], u[0] * c[1] - u[1] * c[0]};
    double r[3];
    for (int i = 0; i < 3; i++)
        r[i] = v[i] + 2.0 * (w * c[i] + cc[i]);
    for (int i = 0; i < 3; i++)
        out[i] = r[i];
}

void pred_quat_exp(const double r[3], double out[4])
{
    double angle = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    /* sin(x/2)/x by its series near zero: exact to double precision below 1e-4 */
    double s = angle < 1e-4 ? 0.5 - angle * angle / 48.0 : sin(0.5 * angle) / angle;
    out[0] = r[0] * s;
    out[1] = r[1] * s;
    out[2] = r[2] * s;
    out[3] = cos(0.5 * angle);
}

void pred_quat_log(const double q[4], double out[3])
{
    double sign = q[3] < 0.0 ? -1.0 : 1.0; /* pick the hemisphere with w >= 0: angle <= pi */
    double v = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    double angle = 2.0 * atan2(v, sign * q[3]);
    double s = v < 1e-12 ? 2.0 * sign : sign * angle / v;
    out[0] = q[0] * s;
    out[1] = q[1] * s;
    out[2] = q[2] * s;
}

void pred_quat_slerp(const double a[4], const double b[4], double u, double out[4])
{
    /* a * exp(u log(b a^-1)): log's w >= 0 hemisphere makes it the shortest
     * arc, and its small-angle series keeps 10 ms steps of slow turns exact
     * where sin()-ratio slerp would fall back to nlerp */
    double inv[4], rel[4], r[3], dq[4];
    pred_quat_conj(a, inv);
    pred_quat_mul(b, inv, rel);
    pred_quat_log(rel, r);
    for (int i = 0; i < 3; i++)
        r[i] *= u;
    pred_quat_exp(r, dq);
    pred_quat_mul(dq, a, out);
    pred_quat_normalize(out);
}

double pred_quat_angle_deg(const double a[4], const double b[4])
{
    double d = fabs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]);
    double ia[4], rel[4];
    pred_quat_conj(a, ia);
    pred_quat_mul(b, ia, rel);
    /* atan2 of the vector part keeps precision for tiny angles, where acos(d) does not */
    double v = sqrt(rel[0] * rel[0] + rel[1] * rel[1] + rel[2] * rel[2]);
    return 2.0 * atan2(v, d) * (1.0 / PRED_DEG);
}

void pred_quat_from_ypr(double yaw, double pitch, double roll, double out[4])
{
    double qy[4] = {0.0, sin(0.5 * yaw), 0.0, cos(0.5 * yaw)};
    double qp[4] = {sin(0.5 * pitch), 0.0, 0.0, cos(0.5 * pitch)};
    double qr[4] = {0.0, 0.0, -sin(0.5 * roll), cos(0.5 * roll)};
    double t[4];
    pred_quat_mul(qy, qp, t);
    pred_quat_mul(t, qr, out);
}

void pred_pose_forward(const double q[4], double out[3])
{
    const double f[3] = {0.0, 0.0, -1.0};
    pred_quat_rotate(q, f, out);
}

void pred_pose_up(const double q[4], double out[3])
{
    const double u[3] = {0.0, 1.0, 0.0};
    pred_quat_rotate(q, u, out);
}

void pred_pose_right(const double q[4], double out[3])
{
    const double r[3] = {1.0, 0.0, 0.0};
    pred_quat_rotate(q, r, out);
}

void pred_eye_poses(const pred_pose* head, double ipd, pred_pose eyes[2])
{
    double right[3];
    pred_pose_right(head->q, right);
    for (int e = 0; e < 2; e++) {
        double s = (e == 0 ? -0.5 : 0.5) * ipd;
        eyes[e] = *head;
        for (int i = 0; i < 3; i++)
            eyes[e].p[i] = head->p[i] + s * right[i];
    }
}

void pred_pose_lerp(const pred_pose* a, const pred_pose* b, double u, pred_pose* out)
{
    pred_pose r;
    r.t = a->t + u * (b->t - a->t);
    for (int i = 0; i < 3; i++)
        r.p[i] = a->p[i] + u * (b->p[i] - a->p[i]);
    pred_quat_slerp(a->q, b->q, u, r.q);
    *out = r;
}

double pred_vec3_dist(const double a[3], const double b[3])
{
    double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return sqrt(dx * dx + dy * dy + dz * dz);
}

void pred_quat_look(const double forward[3], const double up[3], double q[4])
{
    double f[3] = {forward[0], forward[1], forward[2]}, u[3], r[3];
    double fl = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (int i = 0; i < 3; i++)
        f[i] /= fl;
    /* right = f x up, then up = right x f: an orthonormal camera frame */
    r[0] = f[1] * up[2] - f[2] * up[1];
    r[1] = f[2] * up[0] - f[0] * up[2];
    r[2] = f[0] * up[1] - f[1] * up[0];
    double rl = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (int i = 0; i < 3; i++)
        r[i] /= rl;
    u[0] = r[1] * f[2] - r[2] * f[1];
    u[1] = r[2] * f[0] - r[0] * f[2];
    u[2] = r[0] * f[1] - r[1] * f[0];
    double m[3][3] = {{r[0], u[0], -f[0]}, {r[1], u[1], -f[1]}, {r[2], u[2], -f[2]}};
    double trace = m[0][0] + m[1][1] + m[2][2];
    if (trace > 0.0) {
        double s = sqrt(trace + 1.0) * 2.0;
        q[3] = 0.25 * s;
        q[0] = (m[2][1] - m[1][2]) / s;
        q[1] = (m[0][2] - m[2][0]) / s;
        q[2] = (m[1][0] - m[0][1]) / s;
    } else if (m[0][0] > m[1][1] && m[0][0] > m[2][2]) {
        double s = sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]) * 2.0;
        q[3] = (m[2][1] - m[1][2]) / s;
        q[0] = 0.25 * s;
        q[1] = (m[0][1] + m[1][0]) / s;
        q[2] = (m[0][2] + m[2][0]) / s;
    } else if (m[1][1] > m[2][2]) {
        double s = sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]) * 2.0;
        q[3] = (m[0][2] - m[2][0]) / s;
        q[0] = (m[0][1] + m[1][0]) / s;
        q[1] = 0.25 * s;
        q[2] = (m[1][2] + m[2][1]) / s;
    } else {
        double s = sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]) * 2.0;
        q[3] = (m[1][0] - m[0][1]) / s;
        q[0] = (m[0][2] + m[2][0]) / s;
        q[1] = (m[1][2] + m[2][1]) / s;
        q[2] = 0.25 * s;
    }
    pred_quat_normalize(q);
}
