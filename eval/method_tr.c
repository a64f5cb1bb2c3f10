/* method_tr.c - the Trim Regions PVS (pvs.h) behind the method interface. */
#include "method_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static bool _create(pvs_method* m, const scn_scene* scene, char* err, size_t err_size)
{
    m->impl = pvs_create(m->rnd, scene, m->gpu, &m->desc.tr, err, err_size);
    return m->impl != NULL;
}

static void _destroy(pvs_method* m)
{
    pvs_destroy(m->impl);
}

static bool _compute(pvs_method* m, const pvs_request* req, uint32_t** ids, uint32_t* count,
                     pvs_method_stats* stats, char* err, size_t err_size)
{
    pvs_viewcell vc;
    pvs_result r;
    if (!pvs_viewcell_from_pred(&req->vc, m->desc.far_m, &vc, err, err_size) ||
        !pvs_compute_dynamic(m->impl, &vc, req->proxies, req->proxy_count, &r, err, err_size))
        return false;
    /* the context's list lives only until its next compute: the caller owns a copy */
    *ids = malloc((r.count ? r.count : 1) * sizeof(uint32_t));
    if (!*ids) {
        snprintf(err, err_size, "tr: out of memory for %u ids", r.count);
        return false;
    }
    memcpy(*ids, r.ids, (size_t)r.count * sizeof(uint32_t));
    for (uint32_t i = 0; m->reasons && i < r.count; i++)
        m->reasons[r.ids[i]] |= r.reasons[i];
    *count = r.count;
    stats->tr = r.stats;
    return true;
}

const pvs_method_ops pvs_method_tr_ops = {.create = _create, .destroy = _destroy, .compute = _compute};
