#include "cli_viewcell.h"

#include <math.h>
#include <string.h>

static void finish(pred_viewcell* vc, float delta, float fov_deg, float fov_pvs_deg)
{
    vc->delta = delta;
    vc->fov_target_deg = fov_deg;
    vc->fov_pvs_deg = fov_pvs_deg;
    vc->z = delta / tanf(0.5f * fov_pvs_deg * (float)PRED_DEG);
    vc->t_end = vc->t_begin + TV_VIEWCELL_WINDOW_S;
    for (int i = 0; i < 3; i++)
        vc->apex[i] = vc->v0[i] - vc->z * vc->forward[i];
}

bool tv_viewcell_make(const float pos[3], const float dir[3], const float* up, float delta, float fov_deg,
                      float fov_pvs_deg, pred_viewcell* out)
{
    /* a float length of inf (components beyond about 1e19) would turn dir into a zero vector */
    float len = sqrtf(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    if (!(len > 0.0f && isfinite(len)) || !(fov_deg > 0.0f && fov_deg < 180.0f) ||
        !(fov_pvs_deg > 0.0f && fov_pvs_deg < TV_VIEWCELL_MAX_FOV_PVS) || !(delta >= 0.0f))
        return false;
    memset(out, 0, sizeof *out);
    /* A unit vector is taken as given, to the last bit: a replay's pvs.csv
     * row then gives its own viewcell, and the PVS can hinge on a bit. */
    float f[3] = {dir[0], dir[1], dir[2]};
    if (fabsf(len - 1.0f) > 1e-6f)
        for (int i = 0; i < 3; i++)
            f[i] = dir[i] / len;
    float ref[3] = {0.0f, 1.0f, 0.0f};
    if (up) {
        for (int i = 0; i < 3; i++)
            ref[i] = up[i];
    } else if (fabsf(f[1]) > 0.999f) { /* looking straight up or down: any horizontal up will do */
        ref[1] = 0.0f;
        ref[2] = 1.0f;
    }
    float rl = sqrtf(ref[0] * ref[0] + ref[1] * ref[1] + ref[2] * ref[2]);
    float d = ref[0] * f[0] + ref[1] * f[1] + ref[2] * f[2];
    float u[3] = {ref[0] - d * f[0], ref[1] - d * f[1], ref[2] - d * f[2]};
    float ul = sqrtf(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    if (!(ul > 1.75e-3f * rl) || !isfinite(ul)) /* sin(0.1 degree): no direction to turn the frustum by */
        return false;
    bool as_given = fabsf(d) <= 1e-6f * rl && fabsf(rl - 1.0f) <= 1e-6f; /* unit and perpendicular */
    for (int i = 0; i < 3; i++) {
        out->v0[i] = pos[i];
        out->forward[i] = f[i];
        out->up[i] = as_given ? ref[i] : u[i] / ul;
    }
    finish(out, delta, fov_deg, fov_pvs_deg);
    return true;
}

void tv_viewcell_at_pose(const pred_pose* head, float delta, float fov_deg, float fov_pvs_deg, pred_viewcell* out)
{
    double f[3], u[3];
    pred_pose_forward(head->q, f);
    pred_pose_up(head->q, u);
    memset(out, 0, sizeof *out);
    out->t_begin = head->t;
    for (int i = 0; i < 3; i++) {
        out->v0[i] = (float)head->p[i];
        out->forward[i] = (float)f[i];
        out->up[i] = (float)u[i];
    }
    finish(out, delta, fov_deg, fov_pvs_deg);
}
