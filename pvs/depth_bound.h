/* depth_bound.h - an upper bound of the depth of the scene behind every part
 * of the PVS image, for narrower trim regions (docs/trim-width.md).
 *
 * The image seen from v* is cut into square cells of TV_PVS_DEPTH_CELL_PX
 * pixels; a cell holds the largest depth (from v*, along forward, clamped to
 * the far plane) of any convex piece of geometry added whose image bounding
 * box, widened by one pixel, touches the cell, and 0 where nothing does.
 * Coarser levels hold the maximum of their 2x2 children, so a rectangle is
 * bounded with at most four reads at the level where it spans two cells.
 *
 * Contract: for every point p of an added piece with depth in [near, far],
 * pvs_depth_bound_query over any rectangle holding p's image returns at
 * least depth(p). Built per PVS computation from the triangles and proxy
 * boxes the layers draw; bounding boxes rather than rasterisation, so no
 * sub-pixel triangle is missed. P1 reads the same cells (pvs_trim.glsl).
 *
 * Memory: one float array for all levels, sized by pvs_depth_bound_init.
 */
#ifndef TRIMVR_PVS_DEPTH_BOUND_H
#define TRIMVR_PVS_DEPTH_BOUND_H

#include <stdbool.h>
#include <stdint.h>

#include "view.h"

#ifdef __cplusplus
extern "C" {
#endif

#define PVS_DEPTH_BOUND_MAX_LEVELS 16

typedef struct pvs_depth_bound {
    uint32_t width, height; /* image pixels */
    uint32_t levels;        /* level 0 is the finest; the last is 1x1 */
    uint32_t level_width[PVS_DEPTH_BOUND_MAX_LEVELS], level_height[PVS_DEPTH_BOUND_MAX_LEVELS];
    uint32_t level_offset[PVS_DEPTH_BOUND_MAX_LEVELS]; /* first cell of each level in `cells` */
    uint32_t cell_count;                               /* all levels */
    float* cells;

    /* the frame of the view being built (pvs_depth_bound_begin) */
    pvs_view view;
    pvs_view_frame frame;
    float focal_px;
} pvs_depth_bound;

/* Cells of all levels for a width x height image (what the GPU copy holds). */
uint32_t pvs_depth_bound_cell_count(uint32_t width, uint32_t height);

/* Allocates the cells for a width x height image (both > 0). False when
 * memory runs out; `b` is then zeroed. */
bool pvs_depth_bound_init(pvs_depth_bound* b, uint32_t width, uint32_t height);

/* Releases the cells and zeroes `b`. Safe on a zeroed struct. */
void pvs_depth_bound_free(pvs_depth_bound* b);

/* Starts a bound for `view` (its fov and aspect span the image): every cell 0. */
void pvs_depth_bound_begin(pvs_depth_bound* b, const pvs_view* view);

/* Adds the convex hull of `count` points (a triangle, a box's corners): the
 * part in front of the near plane, its image bounding box widened by one
 * pixel, its largest depth clamped to the far plane. Nothing when it lies
 * wholly behind the near plane. */
void pvs_depth_bound_add(pvs_depth_bound* b, const float (*points)[3], uint32_t count);

/* Adds what the PVS draws: triangles `ids` below `first_proxy_face` (their
 * corners at corners + 9 id) and, for each face id above it, the box of its
 * proxy (faces first_proxy_face + 12 p + 0..11, box at boxes +
 * PVS_PROXY_FLOATS p, pvs/proxies.h). */
void pvs_depth_bound_add_ids(pvs_depth_bound* b, const uint32_t* ids, uint32_t count, const float* corners,
                             uint32_t first_proxy_face, const float* boxes);

/* Builds the coarser levels; call after the last add. */
void pvs_depth_bound_finish(pvs_depth_bound* b);

/* Upper bound of the depth of what was added over the pixel rectangle
 * [x0, x1] x [y0, y1] (continuous pixel coordinates, x right, y up from
 * the image's lower-left corner; clamped to the image). 0: nothing there. */
float pvs_depth_bound_query(const pvs_depth_bound* b, float x0, float y0, float x1, float y1);

/* Pixel coordinates of normalised image point `image` (view.h), as _query
 * takes them. */
void pvs_depth_bound_pixel(const pvs_depth_bound* b, const float image[2], float px[2]);

#ifdef __cplusplus
}
#endif

#endif
