/* method_q3vis.c - an OpenArena level's offline cluster PVS (q3vis.h) as a
 * triangle set for a viewcell.
 *
 * Source clusters: those of every leaf whose box meets the viewcell's
 * bounding ball, centred at v0 with radius max(delta, z) (the double cone's
 * farthest points are its apexes, z from v0, and its base rim, delta from
 * v0), so every eye position of the cell is inside a source cluster. The PVS
 * is every triangle touching a leaf of a cluster visible from any source.
 * When the ball meets no cluster leaf (the cell lies in solid space or
 * outside the level) the request fails with that reason: the offline PVS
 * says nothing about such a cell, and a silent full-scene answer would look
 * like a valid (if poor) PVS. */
#include "method_internal.h"
#include "log.h"
#include "q3vis.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct _q3 {
    pvs_q3vis vis;
    pvs_q3vis_tri_map map;
    uint8_t* sources;  /* n_clusters */
    uint8_t* scratch;  /* n_clusters */
} _q3;

static bool _create(pvs_method* m, const scn_scene* scene, char* err, size_t err_size)
{
    if (!m->desc.q3vis_file) {
        snprintf(err, err_size, "q3vis: no .pvs.json file given");
        return false;
    }
    _q3* q = calloc(1, sizeof *q);
    if (!q) {
        snprintf(err, err_size, "q3vis: out of memory");
        return false;
    }
    m->impl = q;
    if (!pvs_q3vis_load(m->desc.q3vis_file, &q->vis, err, err_size) ||
        !pvs_q3vis_map_triangles(&q->vis, scene, &q->map, err, err_size))
        return false;
    q->sources = malloc(q->vis.n_clusters);
    q->scratch = malloc(q->vis.n_clusters);
    if (!q->sources || !q->scratch) {
        snprintf(err, err_size, "q3vis: out of memory");
        return false;
    }
    if (q->map.unclustered)
        tv_log(TV_LOG_INFO, "q3vis: %s: %u of %u triangles touch no cluster leaf (never in a q3vis PVS)",
               m->desc.q3vis_file, q->map.unclustered, q->map.triangle_count);
    return true;
}

static void _destroy(pvs_method* m)
{
    _q3* q = m->impl;
    pvs_q3vis_free(&q->vis);
    pvs_q3vis_tri_map_free(&q->map);
    free(q->sources);
    free(q->scratch);
    free(q);
}

static bool _compute(pvs_method* m, const pvs_request* req, uint32_t** ids, uint32_t* count,
                     pvs_method_stats* stats, char* err, size_t err_size)
{
    (void)stats;
    _q3* q = m->impl;
    const pred_viewcell* vc = &req->vc;
    float radius = fmaxf(vc->delta, vc->z);
    if (pvs_q3vis_clusters_near(&q->vis, vc->v0, radius, q->sources) == 0) {
        snprintf(err, err_size, "q3vis: viewcell at (%.3f, %.3f, %.3f) radius %.3f m lies in no cluster "
                 "(solid space or outside the level)", vc->v0[0], vc->v0[1], vc->v0[2], radius);
        return false;
    }
    *ids = malloc((q->map.triangle_count ? q->map.triangle_count : 1) * sizeof(uint32_t));
    if (!*ids) {
        snprintf(err, err_size, "q3vis: out of memory for %u ids", q->map.triangle_count);
        return false;
    }
    *count = pvs_q3vis_triangles(&q->vis, &q->map, q->sources, q->scratch, *ids);
    return true;
}

const pvs_method_ops pvs_method_q3vis_ops = {.create = _create, .destroy = _destroy, .compute = _compute};
