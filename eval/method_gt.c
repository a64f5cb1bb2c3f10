/* method_gt.c - dense ground-truth sampling as a PVS method: the union of
 * the id buffers of the stratified sample views of ground_truth.h, i.e. the
 * set pvs_evaluate compares against (same cameras for the same seed 0),
 * computed at the cost a from-region method must beat. */
#include "ground_truth.h"
#include "method_internal.h"

#include <stdio.h>
#include <stdlib.h>

typedef struct _gt {
    rnd_camera* cams; /* desc.gt_samples */
} _gt;

static bool _create(pvs_method* m, const scn_scene* scene, char* err, size_t err_size)
{
    (void)scene;
    _gt* g = calloc(1, sizeof *g);
    if (g)
        g->cams = malloc(m->desc.gt_samples * sizeof(rnd_camera));
    if (!g || !g->cams) {
        free(g);
        snprintf(err, err_size, "gt: out of memory for %u sample cameras", m->desc.gt_samples);
        return false;
    }
    m->impl = g;
    return true;
}

static void _destroy(pvs_method* m)
{
    _gt* g = m->impl;
    free(g->cams);
    free(g);
}

static bool _compute(pvs_method* m, const pvs_request* req, uint32_t** ids, uint32_t* count,
                     pvs_method_stats* stats, char* err, size_t err_size)
{
    (void)ids, (void)count;
    _gt* g = m->impl;
    pvs_eval_desc d = {.samples = m->desc.gt_samples, .width = m->desc.width, .height = m->desc.height,
                       .eye_fov_h_deg = req->eye_fov_h_deg, .near_m = m->desc.near_m, .far_m = m->desc.far_m};
    uint32_t n = pvs_gt_cameras(&req->vc, &d, g->cams, m->desc.gt_samples);
    if (n == 0) {
        snprintf(err, err_size, "gt: no sample view fits the viewcell (delta %.3g m, fov %.3g deg)", req->vc.delta,
                 req->vc.fov_pvs_deg);
        return false;
    }
    for (uint32_t s = 0; s < n; s++)
        if (!pvs_method_mark_view(m, &g->cams[s], err, err_size))
            return false;
    stats->views = n;
    return true;
}

const pvs_method_ops pvs_method_gt_ops = {.renders = true, .create = _create, .destroy = _destroy,
                                          .compute = _compute};
