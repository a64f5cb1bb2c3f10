/* demo_head.c - the keyboard-and-mouse head. */
#include "demo_head.h"

#include <math.h>
#include <string.h>

void tv_head_init(tv_head* h, const pred_pose* start)
{
    memset(h, 0, sizeof *h);
    double f[3];
    pred_pose_forward(start->q, f);
    for (int k = 0; k < 3; k++)
        h->home_p[k] = start->p[k];
    /* yaw 0 looks down -Z and positive yaw turns towards -X */
    h->home_yaw = atan2(-f[0], -f[2]);
    h->home_pitch = asin(f[1] < -1.0 ? -1.0 : f[1] > 1.0 ? 1.0 : f[1]);
    tv_head_reset(h);
}

void tv_head_reset(tv_head* h)
{
    memcpy(h->p, h->home_p, sizeof h->p);
    h->yaw = h->home_yaw;
    h->pitch = h->home_pitch;
    h->speed = TV_HEAD_DEFAULT_SPEED;
}

void tv_head_scale_speed(tv_head* h, double factor)
{
    h->speed *= factor;
    h->speed = h->speed < 0.05 ? 0.05 : h->speed > 50.0 ? 50.0 : h->speed;
}

void tv_head_step(tv_head* h, const tv_head_input* in, double dt)
{
    double step = h->speed * (in->fast ? 4.0 : 1.0) * dt;
    double fwd[3] = {-sin(h->yaw), 0.0, -cos(h->yaw)}, right[3] = {cos(h->yaw), 0.0, -sin(h->yaw)};
    double along = (in->forward ? 1.0 : 0.0) - (in->back ? 1.0 : 0.0);
    double side = (in->right ? 1.0 : 0.0) - (in->left ? 1.0 : 0.0);
    double rise = (in->up ? 1.0 : 0.0) - (in->down ? 1.0 : 0.0);
    double norm = sqrt(along * along + side * side + rise * rise);
    if (norm > 0.0) /* diagonal moves are no faster */
        for (int k = 0; k < 3; k++)
            h->p[k] += step * (along * fwd[k] + side * right[k] + (k == 1 ? rise : 0.0)) / norm;
    h->yaw -= in->look_dx * TV_HEAD_LOOK_RAD_PER_PIXEL;
    h->pitch -= in->look_dy * TV_HEAD_LOOK_RAD_PER_PIXEL;
    h->pitch = h->pitch < -TV_HEAD_MAX_PITCH ? -TV_HEAD_MAX_PITCH : h->pitch > TV_HEAD_MAX_PITCH ? TV_HEAD_MAX_PITCH : h->pitch;
}

void tv_head_pose(const tv_head* h, double t, pred_pose* out)
{
    out->t = t;
    memcpy(out->p, h->p, sizeof out->p);
    pred_quat_from_ypr(h->yaw, h->pitch, 0.0, out->q);
}
