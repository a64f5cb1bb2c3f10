/* ground_truth.h - sampled ground truth for a viewcell and the paper's PVS
 * quality metrics (section 6; docs/evaluation.md).
 *
 * The ground truth (GT) of a viewcell is the union of the triangle ids seen in
 * N id-buffer renders from eye poses spread over the viewcell: positions
 * stratified through the double cone (half of them on its surface, so the
 * boundary is covered) and orientations stratified over every rotation whose
 * eye frustum stays inside the PVS frustum. Every sample is checked with
 * pred_viewcell_contains, the same test the replay uses to count viewcell
 * misses, so GT and replay agree on what "inside the viewcell" means.
 *
 * Triangle sets are byte masks indexed by triangle id (1 = in the set): the
 * O(1) membership test the per-pixel metrics need.
 */
#ifndef TRIMVR_EVAL_GROUND_TRUTH_H
#define TRIMVR_EVAL_GROUND_TRUTH_H

#include "render.h"
#include "scene.h"
#include "viewcell.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Zero means default. */
typedef struct pvs_eval_desc {
    uint32_t samples;      /* sample views per viewcell: 200 (the paper's N) */
    uint32_t width, height; /* sample-view resolution: 640 x 360 */
    float eye_fov_h_deg;   /* eye horizontal FOV: the viewcell's fov_target_deg; vertical from the aspect */
    float near_m, far_m;   /* eye clip planes: 0.05 m, 500 m */
    uint32_t seed;         /* sample jitter */
    /* Scenes with movers: sample view s is drawn at its own time of the
     * viewcell's use window [t_begin, t_end] (a low-discrepancy sequence,
     * uncorrelated with the views' positions), on the upload pose() returns
     * for that time (NULL with err filled on failure). NULL: every view at
     * the scene's current pose. */
    const rnd_gpu_scene* (*pose)(void* user, double t, char* err, size_t err_size);
    void* pose_user;
    /* A folder of cached ground truths (gt_cache.h) and the scene's identity
     * there (pvs_gt_scene_id): a viewcell whose GT is cached skips its id
     * renders and draws only the views with FN pixels again; one that is not
     * is computed and written. Both or neither; NULL: no cache. Not used for scenes with
     * see-through triangles or with movers and `pose`. */
    const char* gt_cache_dir;
    const char* gt_cache_scene;
} pvs_eval_desc;

/* Fills `cams[0..n)` with the sample eye cameras of `vc` (deterministic for
 * a given seed). Returns the number written: n, unless rejection sampling
 * could not place every sample (a degenerate viewcell), in which case fewer. */
uint32_t pvs_gt_cameras(const pred_viewcell* vc, const pvs_eval_desc* desc, rnd_camera* cams, uint32_t n);

typedef struct pvs_eval_result {
    uint32_t samples;
    uint32_t scene_tris;          /* SC  */
    uint32_t pvs_tris;            /* TRC */
    uint32_t gt_tris;             /* GTC */
    uint32_t fp_tris, fn_tris;    /* |PVS \ GT|, |GT \ PVS| */
    double pvs_fraction, gt_fraction; /* TRC / SC, GTC / SC */
    double fp_rate, fn_rate;      /* over GTC */
    /* the same without unreliable triangles (FP*, FN*): see pvs_unreliable_mask */
    uint32_t gt_tris_reliable;
    double fp_rate_reliable, fn_rate_reliable;
    /* How complete the sampled GT is: triangles seen in exactly one and
     * exactly two sample views, the Chao2 estimate of how many triangles the
     * views would find without limit (pvs_gt_richness_estimate) and
     * gt_tris / that estimate. */
    uint32_t gt_once, gt_twice;
    double gt_est_tris, gt_completeness;
    double fng_pixels_mean, fng_pixels_max; /* FN pixels per sample view */
    double fng_fraction_mean;     /* FNG / pixels per view */
    double fng_reliable_pixels_mean; /* FNG*: FN pixels of reliable triangles only */
    double fng_dynamic_pixels_mean;  /* FN pixels on moving triangles (scn_scene.dynamic_triangle_count) */
    double psnr_mean_db;          /* PSNR of the mean squared error over all views (+inf if none) */
    double psnr_min_db;           /* worst view */
    uint32_t worst_view;          /* index of the worst-PSNR sample */
    double ssim_mean, ssim_min;   /* SSIM of PVS against full render (eval/ssim.h): mean over views, worst view */
    double gt_ms;                 /* ground-truth cost: the id renders and read-backs of all samples */
    double eval_ms;               /* wall clock of the whole evaluation (GT and PVS renders, metrics) */
    double full_render_ms;        /* median full-scene draw of one sample view */
    double pvs_render_ms;         /* median PVS-subset draw of one sample view */
} pvs_eval_result;

/* Bias-corrected Chao2 estimate of the number of distinct triangles that
 * sample views of the viewcell see, from incidence counts: `observed` seen in
 * `views` views, `once` of them in exactly one view, `twice` in exactly two:
 * observed + (views - 1) / views * once * (once - 1) / (2 * (twice + 1)).
 * Sub-pixel triangles are each seen by few views, so the sampled GT misses
 * some; this says about how many (a lower bound when detection chances vary
 * widely, as they do). Requires once + twice <= observed; views >= 1. */
double pvs_gt_richness_estimate(uint32_t observed, uint32_t once, uint32_t twice, uint32_t views);

/* Marks the triangles that the paper calls unreliable for the eye at the
 * viewcell centre: projected into a `width` x `height` image with the PVS
 * FOV, their smallest altitude is under one pixel, so rasterization may give
 * them zero fragments however long their edges are. Triangles behind the
 * centre are reliable (they can only matter for samples that see them large). */
void pvs_unreliable_mask(const scn_scene* scene, const pred_viewcell* vc, uint32_t width, uint32_t height,
                         uint8_t* unreliable);

/* Renders every sample view of `vc` twice (full scene; PVS subset), builds
 * the GT mask (gt_mask, scene->triangle_count bytes, caller-owned, may be
 * NULL) and fills `out` with the metrics of `pvs_mask` against it.
 * pvs_ids/pvs_count is the same set as a sorted id list (for the subset draw).
 * Returns false with a one-line reason on a Vulkan or memory failure. */
bool pvs_evaluate(rnd_context* ctx, const rnd_gpu_scene* gpu, const scn_scene* scene, const pred_viewcell* vc,
                  const uint8_t* pvs_mask, const uint32_t* pvs_ids, uint32_t pvs_count,
                  const pvs_eval_desc* desc, uint8_t* gt_mask, pvs_eval_result* out, char* err,
                  size_t err_size);

#ifdef __cplusplus
}
#endif

#endif
