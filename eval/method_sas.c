/* method_sas.c - the paper's SAS competitor [Mueller et al. 2018]: a
 * from-region PVS approximated by the union of exact visible sets rendered
 * at viewpoints linearly extrapolated along the predicted motion.
 *
 * Samples: n = max(1, ceil(delta / sas_spacing_m)) + 1 points evenly on the
 * segment v0 + s * motion, s in [-1/2, 1/2], both ends included. The segment is
 * centred on the viewcell centre rather than starting at the current pose:
 * v0 is the predicted position at the middle of the use window and `motion`
 * the displacement over that window, so the samples are SAS's first-order
 * prediction of every position the PVS will be used from, and SAS is judged
 * on the same window and the same ground truth as the from-region methods.
 * Each sample looks along the viewcell axis with the PVS FOV on the smaller
 * image axis, so its image contains the viewcell's square PVS frustum, the
 * same frustum tr covers: SAS widens the view, it does not sample rotations. */
#include "method_internal.h"

#include <math.h>

static bool _compute(pvs_method* m, const pvs_request* req, uint32_t** ids, uint32_t* count,
                     pvs_method_stats* stats, char* err, size_t err_size)
{
    (void)ids, (void)count;
    const pred_viewcell* vc = &req->vc;
    double steps = ceil(vc->delta / m->desc.sas_spacing_m);
    uint32_t n = (steps > 1.0 ? (uint32_t)fmin(steps, 1e6) : 1u) + 1u;
    float fov_y = pvs_method_fov_y(m, vc->fov_pvs_deg);
    for (uint32_t i = 0; i < n; i++) {
        double s = (double)i / (double)(n - 1) - 0.5;
        float p[3];
        for (int k = 0; k < 3; k++)
            p[k] = (float)(vc->v0[k] + s * req->motion[k]);
        rnd_camera cam = pvs_method_camera(m, p, vc->forward, vc->up, fov_y);
        if (!pvs_method_mark_view(m, &cam, err, err_size))
            return false;
    }
    stats->views = n;
    return true;
}

const pvs_method_ops pvs_method_sas_ops = {.renders = true, .compute = _compute};
