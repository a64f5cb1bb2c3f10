/* eval_images.h - the pictures of `trimvr eval`, for its worst viewcell:
 * Figure 1 of the paper (triangles truly visible from the viewcell shaded,
 * false positives blue, the rest grey) from the viewcell centre and from an
 * overview camera behind and above it, and the worst ground-truth view with
 * its false-negative pixels in red. */
#ifndef TRIMVR_EVAL_EVAL_IMAGES_H
#define TRIMVR_EVAL_EVAL_IMAGES_H

#include "ground_truth.h"

#include <stdbool.h>
#include <stdint.h>

typedef struct tv_eval_images {
    bool have;
    pred_viewcell vc;
    pvs_eval_result m;
    uint8_t *pvs, *gt; /* masks of that viewcell */
    uint32_t triangle_count;
} tv_eval_images;

/* Keeps the viewcell if it is worse than the kept one (more false-negative
 * pixels in its worst view, then lower PSNR). False when out of memory. */
bool tv_eval_images_keep_worst(tv_eval_images* w, const pred_viewcell* vc, const pvs_eval_result* m,
                               const uint8_t* pvs_mask, const uint8_t* gt_mask, uint32_t triangle_count);

/* Renders and writes DIR/fig1_eye.png, DIR/fig1_overview.png and
 * DIR/fn_worst.png (desc: the evaluation's sample settings). */
bool tv_eval_images_write(const tv_eval_images* w, rnd_context* ctx, const rnd_gpu_scene* gpu,
                          const scn_scene* scene, const pvs_eval_desc* desc, const char* dir, char* err,
                          size_t err_size);

void tv_eval_images_free(tv_eval_images* w);

/* Figure 1's camera at the viewcell centre v0, along its axis, with the PVS
 * FOV across the image's width (capped at 170 degrees). */
void tv_viewcell_centre_camera(const pred_viewcell* vc, float aspect, rnd_camera* cam);

/* The overview camera of Figure 1: behind and above v0 (by a distance that
 * grows with the scene, 3 to 25 m), looking down at the region in front of
 * it along `forward`; 60 degrees vertical FOV. */
void tv_overview_camera(const scn_scene* scene, const double v0[3], const double forward[3], const double up[3],
                        rnd_camera* cam);

#endif
