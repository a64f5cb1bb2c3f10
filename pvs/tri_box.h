/* tri_box.h - exact triangle / axis-aligned box overlap (separating axis test).
 *
 * The octree references a triangle from every leaf it overlaps; testing the
 * triangle itself rather than its bounding box keeps long diagonal triangles
 * out of leaves they only pass near, which keeps per-leaf lists (and so the
 * per-layer k-buffer depth complexity) small.
 */
#ifndef TRIMVR_PVS_TRI_BOX_H
#define TRIMVR_PVS_TRI_BOX_H

#include <stdbool.h>

#ifdef __cplusplus
extern "C" {
#endif

/* True when triangle (a, b, c) and the closed box [box_min, box_max] share
 * at least one point. Touching counts as overlap, so a triangle lying in a
 * node boundary plane belongs to both nodes (conservative). Degenerate
 * triangles (segments, points) are handled. */
bool pvs_tri_box_overlap(const float a[3], const float b[3], const float c[3],
                         const float box_min[3], const float box_max[3]);

#ifdef __cplusplus
}
#endif

#endif
