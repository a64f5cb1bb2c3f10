/* method_omni.c - the PVS of a multi-frustum viewcell (pred_viewcell.frusta >
 * 1, the all-directions case): the union of the method's PVSs of each
 * frustum. Conservative because every frustum's double cone holds every eye
 * of the window and the frusta together hold every ray direction, so a
 * triangle seen along any ray from any of those eyes is in the PVS of the
 * frustum holding that ray (docs/prediction.md, "All directions"). */
#include "method_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

bool pvs_method_compute_frusta(pvs_method* m, const pvs_request* req, uint32_t** ids, uint32_t* count,
                               pvs_method_stats* stats, char* err, size_t err_size)
{
    uint8_t* seen = calloc(m->triangle_count ? m->triangle_count : 1, 1);
    if (!seen) {
        snprintf(err, err_size, "%s: out of memory", pvs_method_name(m->kind));
        return false;
    }
    pvs_method_stats sum = {0};
    bool ok = true;
    if (m->reasons)
        memset(m->reasons, 0, sizeof(uint32_t) * m->triangle_count);
    m->joining = true;
    for (int i = 0; ok && i < req->vc.frusta; i++) {
        pvs_request one = *req;
        pred_viewcell_frustum(&req->vc, i, &one.vc);
        uint32_t* part = NULL;
        uint32_t n = 0;
        pvs_method_stats st = {0};
        ok = pvs_method_compute(m, &one, &part, &n, &st, err, err_size);
        for (uint32_t k = 0; ok && k < n; k++)
            seen[part[k]] = 1;
        free(part);
        sum.total_ms += st.total_ms;
        sum.views += st.views;
        sum.tr = st.tr; /* the last frustum's phases: they do not add up across frusta */
    }
    m->joining = false;
    uint32_t n = 0;
    for (uint32_t t = 0; ok && t < m->triangle_count; t++)
        n += seen[t];
    uint32_t* list = ok ? malloc((n ? n : 1) * sizeof *list) : NULL;
    if (ok && !list)
        snprintf(err, err_size, "%s: out of memory for %u ids", pvs_method_name(m->kind), n);
    if (list) {
        n = 0;
        for (uint32_t t = 0; t < m->triangle_count; t++)
            if (seen[t])
                list[n++] = t;
        *ids = list;
        *count = n;
        sum.frusta = (uint32_t)req->vc.frusta;
        if (stats)
            *stats = sum;
    }
    free(seen);
    return list != NULL;
}
