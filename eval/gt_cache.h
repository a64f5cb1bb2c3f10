/* gt_cache.h - a file cache for the part of a viewcell's sampled ground truth
 * that no PVS changes (docs/bench.md "Ground-truth cache").
 *
 * What pvs_evaluate derives from its GT renders without the PVS is, per
 * sample view, which triangles the view's id buffer shows and on how many
 * pixels each: the GT set, the views-per-triangle counts behind the Chao2
 * estimate and, against any PVS, every FN pixel count follow from it. The
 * colour images are not kept (about 3.7 MB a view at 1280 x 720): with a
 * cached GT, a sample view whose visible triangles are all in the PVS renders
 * identically with the PVS (same triangles, same ascending draw order, local
 * shading, one sample per pixel), so its PSNR is +inf and SSIM 1 without a
 * render, and only the views with FN pixels are drawn again for PSNR and SSIM.
 *
 * A file is keyed by everything the id renders depend on: the scene's
 * content (pvs_gt_scene_id), the renderer device, the viewcell, the sample
 * count, resolution, eye FOV, clip planes and seed, and PVS_GT_CACHE_VERSION.
 * Its name is a hash of the key; the key itself is stored and compared, and a
 * checksum covers the file, so a mismatched or damaged file is rejected.
 * Files are written to a temporary name and renamed, so processes sharing a
 * folder never read a partial file.
 */
#ifndef TRIMVR_EVAL_GT_CACHE_H
#define TRIMVR_EVAL_GT_CACHE_H

#include "ground_truth.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Bump when anything the GT's id renders depend on changes: the sampling of
 * ground_truth.c, the mesh pass's culling and rasterisation (render/,
 * shaders/mesh.*) or the scene loaders' output. Files of another version
 * are recomputed. */
#define PVS_GT_CACHE_VERSION 1

/* The PVS-independent record of one viewcell's GT. */
typedef struct pvs_gt_record {
    uint32_t views;       /* sample views */
    uint32_t* view_first; /* views + 1 offsets into ids/pixels */
    uint32_t* ids;        /* per view: the triangle ids its id buffer shows, ascending */
    uint32_t* pixels;     /* ... and on how many pixels each */
    uint32_t entry_count, entry_cap;
    double gt_ms;          /* what the id renders cost when the record was made */
    double full_render_ms; /* median full draw of one sample view, then */
} pvs_gt_record;

/* Appends one view's ascending ids and their pixel counts. False when memory runs out. */
bool pvs_gt_record_add_view(pvs_gt_record* r, const uint32_t* ids, const uint32_t* pixels, uint32_t count);
void pvs_gt_record_free(pvs_gt_record* r);

/* Writes "spec=SPEC;scene=HASH;tris=N;device=DEVICE" into out: the scene's
 * identity for pvs_eval_desc.gt_cache_scene. HASH covers what the id
 * renders read: positions, UVs, indices, materials' alpha and culling
 * rules, textures. */
void pvs_gt_scene_id(const scn_scene* scene, const char* spec, const char* device, char* out, size_t size);

/* The full key of vc's GT under resolved desc d, and its file in d's cache folder. */
void pvs_gt_cache_key(const char* scene_id, const pred_viewcell* vc, const pvs_eval_desc* d, char* key, size_t size);
void pvs_gt_cache_file(const char* dir, const char* key, char* file, size_t size);

/* Reads `file` into *out. False when it is absent (why empty) or rejected
 * (why: a one-line reason: another key, a bad checksum, truncation, ids
 * outside scene_tris). */
bool pvs_gt_cache_load(const char* file, const char* key, uint32_t scene_tris, pvs_gt_record* out, char* why,
                       size_t why_size);

/* Writes r under key to `file` atomically (a temporary file in the same
 * folder, then rename), creating the folder. False with a reason on failure. */
bool pvs_gt_cache_store(const char* file, const char* key, const pvs_gt_record* r, char* err, size_t err_size);

#endif
