#include "pvs_viewcell.h"

#include <cglm/cglm.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static bool finite3(const float v[3])
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

const char* pvs_viewcell_invalid(const pvs_viewcell* vc)
{
    vec3 f = {vc->forward[0], vc->forward[1], vc->forward[2]}, u = {vc->up[0], vc->up[1], vc->up[2]}, c;
    if (!finite3(vc->v0) || !finite3(vc->forward) || !finite3(vc->up) || !isfinite(vc->delta) ||
        !isfinite(vc->far_m))
        return "non-finite value";
    glm_vec3_cross(f, u, c);
    return glm_vec3_norm(f) == 0.0f                                         ? "zero forward vector"
           : glm_vec3_norm(c) <= 1e-6f * glm_vec3_norm(f) * glm_vec3_norm(u) ? "up parallel to forward"
           : !(vc->delta >= 0.0f)                                           ? "negative delta"
           : !(vc->fov_pvs_deg > 0.0f && vc->fov_pvs_deg < 180.0f)          ? "fov_pvs_deg outside (0, 180)"
           : !(vc->far_m > 0.0f)                                            ? "far_m <= 0"
                                                                            : NULL;
}

bool pvs_viewcell_from_pred(const pred_viewcell* in, float far_m, pvs_viewcell* out, char* err, size_t err_size)
{
    pvs_viewcell vc = {.delta = in->delta, .fov_target_deg = in->fov_target_deg, .fov_pvs_deg = in->fov_pvs_deg,
                       .far_m = far_m};
    memcpy(vc.v0, in->v0, sizeof vc.v0);
    memcpy(vc.forward, in->forward, sizeof vc.forward);
    memcpy(vc.up, in->up, sizeof vc.up);
    const char* why = pvs_viewcell_invalid(&vc);
    if (!why && !(isfinite(in->z) && in->z >= 0.0f))
        why = "apex offset z negative or non-finite";
    if (why) {
        snprintf(err, err_size, "invalid viewcell: %s", why);
        return false;
    }
    *out = vc;
    return true;
}
