/* method.h - every way trimvr can produce a PVS, behind one interface, so the
 * replay, `trimvr eval` and `trimvr bench` run them on the same viewcells.
 *
 *   tr         the Trim Regions PVS (pvs.h): from-region, the project's method
 *   gt         dense ground-truth sampling: union of the id buffers of N views
 *              spread over the viewcell (ground_truth.h); the cost a
 *              from-region method must beat
 *   sas        the paper's competitor: union of exact visible sets rendered at
 *              points linearly extrapolated along the predicted motion, one
 *              sample per 5 cm of delta
 *   frompoint  from-point occlusion culling for the current pose only
 *              (hierarchical-z from the current depth, as GPU-driven renderers
 *              do): shows the disocclusion errors a from-region PVS prevents
 *   q3vis      OpenArena levels only: the level's own offline cluster PVS
 *              (<level>.pvs.json) turned into a triangle set
 *
 * A method object is used by one thread at a time (the PVS worker); several
 * may exist on one rnd_context. */
#ifndef TRIMVR_EVAL_METHOD_H
#define TRIMVR_EVAL_METHOD_H

#include "pvs.h"
#include "render.h"
#include "scene.h"
#include "viewcell.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum pvs_method_kind {
    PVS_METHOD_TR = 0,
    PVS_METHOD_GT,
    PVS_METHOD_SAS,
    PVS_METHOD_FROMPOINT,
    PVS_METHOD_Q3VIS,
    PVS_METHOD_COUNT
} pvs_method_kind;

/* "tr", "gt", "sas", "frompoint", "q3vis" <-> kind. */
const char* pvs_method_name(pvs_method_kind kind);
bool pvs_method_from_name(const char* name, pvs_method_kind* kind);

/* Zero means default. */
typedef struct pvs_method_desc {
    pvs_method_kind kind;
    pvs_desc tr;              /* tr: resolution (0: width x height below), k, octree settings */
    uint32_t width, height;   /* gt, sas, frompoint: id-buffer resolution; 640 x 360 */
    uint32_t gt_samples;      /* gt: views per viewcell; 200 */
    float sas_spacing_m;      /* sas: one sample per this much of delta; 0.05 */
    float near_m, far_m;      /* eye clip planes; 0.05, 500 */
    const char* q3vis_file;   /* q3vis: path of <level>.pvs.json (required for q3vis) */
} pvs_method_desc;

/* What a method may use to compute one PVS. */
typedef struct pvs_request {
    pred_viewcell vc;      /* the viewcell (all methods) */
    double motion[3];      /* predicted head displacement over the use window, m (sas:
                              samples on v0 + s * motion, s in [-1/2, 1/2]) */
    pred_pose current;     /* newest head pose at request time (frompoint; a zero
                              orientation is refused) */
    float eye_fov_h_deg;   /* display FOV of the eyes; 0: vc.fov_target_deg */
    const pvs_proxy* proxies; /* the scene's movers over the use window [vc.t_begin, vc.t_end]:
                                 tr sorts them in (pvs_compute_dynamic); every other method adds
                                 every proxy's ids (conservative); the caller keeps them alive
                                 until the compute returns */
    uint32_t proxy_count;
} pvs_request;

typedef struct pvs_method_stats {
    double total_ms;       /* wall clock of pvs_method_compute */
    uint32_t views;        /* id-buffer views rendered (gt, sas, frompoint) */
    uint32_t frusta;       /* frusta whose PVSs were joined (1, or vc.frusta when more) */
    pvs_stats tr;          /* tr only: per-phase timings, layers, k-buffer use */
} pvs_method_stats;

typedef struct pvs_method pvs_method;

/* Fills one proxy per mover of `scene` (mover_count entries): the box it
 * sweeps over [t0, t1] (scn_mover_bounds) and its triangle ids. Returns the
 * count. */
uint32_t pvs_method_proxies(const scn_scene* scene, double t0, double t1, pvs_proxy* out);

/* Creates a method for `scene` (uploaded as `gpu` on `rnd`). NULL with a
 * one-line reason on failure (for q3vis: a missing or malformed .pvs.json
 * names the file). */
pvs_method* pvs_method_create(const pvs_method_desc* desc, rnd_context* rnd, const scn_scene* scene,
                              const rnd_gpu_scene* gpu, char* err, size_t err_size);

void pvs_method_destroy(pvs_method* m);

pvs_method_kind pvs_method_kind_of(const pvs_method* m);

/* Computes the PVS of `req` as a malloc'ed, sorted, unique id list (*ids,
 * *count; the caller frees *ids). stats may be NULL. Fails (false, *ids
 * NULL, "METHOD: reason" in err) on an invalid viewcell, a frompoint request
 * without a current pose, a q3vis viewcell in no cluster, or a Vulkan or
 * memory failure. docs/evaluation.md ("Baselines") describes each method.
 * A viewcell of several frusta (req->vc.frusta > 1: every direction) gets
 * the union of the PVSs of its frusta (pvs_method_compute_frusta); a
 * whole-scene one (req->vc.whole_scene) every triangle, stats->frusta 0. */
bool pvs_method_compute(pvs_method* m, const pvs_request* req, uint32_t** ids, uint32_t* count,
                        pvs_method_stats* stats, char* err, size_t err_size);

/* tr created with desc.tr.explain: per triangle, the TV_REASON_* bits
 * (shaders/pvs_shared.h) of the rules that put it in the last PVS computed
 * (ORed over the frusta of a multi-frustum viewcell; 0: not in it). NULL for
 * other methods and without explain. Owned by the method. */
const uint32_t* pvs_method_reasons(const pvs_method* m);

/* The union over the frusta of req->vc (pred_viewcell_frustum), one
 * pvs_method_compute each; stats->frusta says how many. */
bool pvs_method_compute_frusta(pvs_method* m, const pvs_request* req, uint32_t** ids, uint32_t* count,
                               pvs_method_stats* stats, char* err, size_t err_size);

#ifdef __cplusplus
}
#endif

#endif
