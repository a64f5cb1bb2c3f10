/* method_internal.h - what method.c shares with the per-method files
 * (method_tr.c, method_gt.c, method_sas.c, method_frompoint.c, method_q3vis.c).
 *
 * Every method fills the byte mask `mask` (one byte per triangle) or writes a
 * sorted id list directly; method.c turns masks into lists, times the call
 * and validates the request, so the per-method files hold only the method. */
#ifndef TRIMVR_EVAL_METHOD_INTERNAL_H
#define TRIMVR_EVAL_METHOD_INTERNAL_H

#include "method.h"

typedef struct pvs_method_ops {
    bool renders; /* needs method.c's id target (m->target, m->pixels) */
    /* create and destroy may be NULL (stateless methods); destroy is called
     * when create set m->impl */
    bool (*create)(pvs_method* m, const scn_scene* scene, char* err, size_t err_size);
    void (*destroy)(pvs_method* m);
    /* Either fills m->mask (and leaves *ids NULL) or returns a malloc'ed
     * sorted unique list in *ids / *count. */
    bool (*compute)(pvs_method* m, const pvs_request* req, uint32_t** ids, uint32_t* count,
                    pvs_method_stats* stats, char* err, size_t err_size);
} pvs_method_ops;

extern const pvs_method_ops pvs_method_tr_ops, pvs_method_gt_ops, pvs_method_sas_ops, pvs_method_frompoint_ops,
    pvs_method_q3vis_ops;

struct pvs_method {
    pvs_method_kind kind;
    const pvs_method_ops* ops;
    pvs_method_desc desc;     /* defaults resolved; q3vis_file not kept */
    rnd_context* rnd;
    const rnd_gpu_scene* gpu;
    uint32_t triangle_count;
    uint8_t* mask;            /* triangle_count bytes, cleared before each compute */
    rnd_target* target;       /* gt, sas, frompoint: desc.width x desc.height */
    uint32_t* pixels;         /* id read-back of target */
    void* impl;               /* the method's own state */
    uint32_t* reasons;        /* tr with explain: triangle_count rule masks (pvs_method_reasons) */
    bool joining;             /* inside pvs_method_compute_frusta: reasons accumulate */
};

/* Full-scene id render from `cam` into m->target; marks every id seen in m->mask. */
bool pvs_method_mark_view(pvs_method* m, const rnd_camera* cam, char* err, size_t err_size);

/* A camera at `pos` looking along `forward` (need not be unit) with `up`,
 * vertical FOV fov_y_deg and the method's clip planes. */
rnd_camera pvs_method_camera(const pvs_method* m, const float pos[3], const float forward[3], const float up[3],
                             float fov_y_deg);

/* Vertical FOV of the method's target whose smaller axis spans fov_deg: the
 * image then contains the square PVS frustum of the viewcell (pvs.h's
 * convention for pvs_viewcell.fov_pvs_deg). */
float pvs_method_fov_y(const pvs_method* m, float fov_deg);

#endif
