/* umbra.h - the umbra quad of one silhouette edge (paper section 4.1), the C
 * reference of what P1 emits per silhouette edge.
 *
 * The trim quad is the edge's image-space footprint extruded inwards (away
 * from the occluder's outside) by the trim width; the umbra quad is spanned
 * by the edge's two vertices and the far-plane points behind the two
 * extruded vertices, as seen from v*. Both quads therefore cover the same
 * pixels, so every trim fragment has its umbra fragment at the same pixel,
 * with the same trim-region id.
 */
#ifndef TRIMVR_PVS_UMBRA_H
#define TRIMVR_PVS_UMBRA_H

#include <stdbool.h>

#include "view.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pvs_umbra_quad {
    /* corner[0] = e0, corner[1] = e1, corner[2] = far point behind the
     * extruded e1, corner[3] = far point behind the extruded e0. */
    float corner[4][3];
    /* The extruded vertices in normalised image coordinates (the trim quad is
     * image(e0), image(e1), extruded[1], extruded[0]). */
    float extruded[2][2];
} pvs_umbra_quad;

/* Builds the quad for edge (e0, e1) whose occluder lies on the side of
 * `inside` (for a silhouette edge: the third vertex of its front-facing
 * triangle; for a border edge: the third vertex of its triangle), extruded
 * by width0 / width1 normalised image units at e0 / e1 (pvs_trim_width_px
 * with focal_px = 1). Returns false, leaving `out` untouched, when a vertex is
 * not in front of the apex, the edge projects to a point, or `inside`
 * projects onto the edge's line. */
bool pvs_umbra_quad_make(const pvs_view* view, const float e0[3], const float e1[3],
                         const float inside[3], float width0, float width1, pvs_umbra_quad* out);

#ifdef __cplusplus
}
#endif

#endif
