/* gt_seethrough.h - the ground truth's see-through pass. The renderer's ids
 * and depth name the nearest surface, SCN_ALPHA_BLEND triangles included,
 * but those hide nothing (scene.h), so a sample view's id render would miss
 * what lies behind a window. For scenes
 * with such triangles, each sample view also renders the opaque triangles
 * alone (the ids the metrics use) and then peels the see-through ones: it
 * renders those left, takes every one nearer than the opaque depth at some
 * pixel as visible and drops it, and repeats until a render finds none
 * (at most GT_SEETHROUGH_MAX_PEELS renders).
 *
 * Exact for the triangles: a see-through triangle visible at a pixel is
 * found once those in front of it there are dropped. The pixel counts are
 * a lower bound: a dropped triangle is not looked for again at the pixels
 * where another see-through triangle covered it.
 */
#ifndef TRIMVR_EVAL_GT_SEETHROUGH_H
#define TRIMVR_EVAL_GT_SEETHROUGH_H

#include "render.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#define GT_SEETHROUGH_MAX_PEELS 16u

typedef struct gt_seethrough {
    uint32_t blend_count, opaque_count; /* blend_count 0: nothing to do */
    uint32_t* blend;                    /* the scene's SCN_ALPHA_BLEND triangles (reordered by each sample) */
    uint32_t* opaque;
    uint32_t* ids; /* per pixel, scratch */
    float *depth, *opaque_depth;
    uint32_t peels; /* most renders one sample needed */
} gt_seethrough;

/* Lists the scene's see-through and opaque triangles and allocates for
 * `pixels` per view. False only when memory runs out. */
bool gt_seethrough_init(gt_seethrough* g, const scn_scene* scene, size_t pixels);
void gt_seethrough_free(gt_seethrough* g);

/* One sample view (blend_count > 0; `pixels` those of the target): writes the opaque render's ids into
 * `ids`, sets gt[t] for every see-through triangle t visible, and adds to
 * *fn (*fn_rel when t is not unreliable) the pixels where such a t missing
 * from pvs_mask is seen while the opaque id there is in it or background
 * (the caller counts the opaque misses). False when a render fails. */
bool gt_seethrough_sample(gt_seethrough* g, rnd_context* ctx, rnd_target* target, const rnd_gpu_scene* gpu,
                          const rnd_camera* cam, size_t pixels, const uint8_t* pvs_mask, const uint8_t* unreliable,
                          uint32_t triangle_count, uint32_t* ids, uint8_t* gt, size_t* fn, size_t* fn_rel);

#endif
