/* umbra.h - the umbra quad of one silhouette edge (paper section 4.1), the C
 * reference of what P1 emits per silhouette edge.
 *
 * The trim quad is the edge's image-space footprint extruded inwards (away
 * from the occluder's outside) by the trim width; the umbra quad is spanned
 * by the edge's two vertices and two points behind the extruded vertices,
 * as seen from v*. With the widths narrowed by the depth bound behind the
 * edge (pvs_umbra_far_depth; docs/trim-width.md) those points lie on the
 * lines of the far-plane umbra, so the umbra is the far-plane one cut to
 * the narrowed footprint. Both quads cover the same pixels, so every trim
 * fragment has its umbra fragment at the same pixel, with the same
 * trim-region id.
 */
#ifndef TRIMVR_PVS_UMBRA_H
#define TRIMVR_PVS_UMBRA_H

#include <stdbool.h>

#include "depth_bound.h"
#include "view.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pvs_umbra_quad {
    /* corner[0] = e0, corner[1] = e1, corner[2] = far point behind the
     * extruded e1, corner[3] = far point behind the extruded e0 (at the far
     * plane unless the widths were narrowed: pvs_umbra_corner_depth). */
    float corner[4][3];
    /* The extruded vertices in normalised image coordinates (the trim quad is
     * image(e0), image(e1), extruded[1], extruded[0]). */
    float extruded[2][2];
} pvs_umbra_quad;

/* Builds the quad for edge (e0, e1) whose occluder lies on the side of
 * `inside` (for a silhouette edge: the third vertex of its front-facing
 * triangle; for a border edge: the third vertex of its triangle), extruded
 * by width[0] / width[1] normalised image units at e0 / e1
 * (pvs_trim_width_px with focal_px = 1, far_dist the depth bound), the far
 * corners where the far-plane umbra's lines meet the extruded rays
 * (far_width: the widths with far_dist = view->far_dist, >= width; equal
 * widths put them at the far plane). Returns false, leaving `out`
 * untouched, when a vertex is not in front of the apex, the edge projects to
 * a point, or `inside` projects onto the edge's line. */
bool pvs_umbra_quad_make(const pvs_view* view, const float e0[3], const float e1[3], const float inside[3],
                         const float width[2], const float far_width[2], pvs_umbra_quad* out);

/* Depth at which the line from a vertex at `depth` to the far-plane point
 * far_width inwards of it meets the v* ray `width` inwards (0 <= width <=
 * far_width; normalised or pixel units alike), clamped to [depth,
 * far_dist]: a point at depth D on that line lies far_width F (D - depth) /
 * (D (F - depth)) inwards. */
float pvs_umbra_corner_depth(float depth, float width, float far_width, float far_dist);

/* The depth P1 puts in place of the far plane for edge (e0, e1), both in
 * front of the near plane of bound->view (whose far plane it returns
 * otherwise): the bound over the edge's image widened by the reach
 * (pvs_trim_reach_px at the edge's nearer depth and larger |sigma|, plus a
 * pixel), which holds every point at most at the far plane seen past the
 * edge from the viewcell (Δ `delta`, tan α `tan_alpha`). The far plane where
 * the edge comes within 2z of v* (no finite reach). */
float pvs_umbra_far_depth(const pvs_depth_bound* bound, float delta, float tan_alpha, const float e0[3],
                          const float e1[3]);

#ifdef __cplusplus
}
#endif

#endif
