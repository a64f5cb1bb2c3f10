/* silhouette.h - silhouette edges as seen from a point (CPU reference of the
 * edge classification in P1).
 *
 * An edge is a silhouette when its two triangles face opposite ways with
 * respect to the point, or when it is a border or non-manifold edge (always:
 * a polygon soup's open edges are where an occluder ends). Adjacency comes
 * from scn_build_adjacency (scene/weld.h): adjacency[3t+e] is the triangle
 * across edge e (corner e -> corner (e+1)%3) of t, SCN_EDGE_BORDER or
 * SCN_EDGE_NONMANIFOLD, or SCN_EDGE_REST | f for a border resting on face f
 * (scn_join_rest_edges): a silhouette unless t and f both face the point or
 * both face away from it, named from t (its third corner on the occluder
 * side) as a border is.
 */
#ifndef TRIMVR_PVS_SILHOUETTE_H
#define TRIMVR_PVS_SILHOUETTE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* One silhouette edge, named from the triangle on its occluder side: the
 * front-facing one of a facing-changing pair, or the triangle owning a
 * border / non-manifold edge (each of a non-manifold edge's triangles reports
 * it, since each is an occluder ending there). The edge runs from corner
 * `edge` to corner (edge+1)%3 of `tri`; the third corner is on the occluder
 * side. */
typedef struct pvs_silhouette {
    uint32_t tri;
    uint32_t edge;
} pvs_silhouette;

/* Worst-case output size for `triangle_count` triangles scanned. */
size_t pvs_silhouettes_bound(size_t triangle_count);

/* Scans triangles tri_ids[0..count) (all triangles 0..count when tri_ids is
 * NULL) and writes their silhouette edges as seen from `point` into `out`
 * (room for pvs_silhouettes_bound(count)); returns how many. A triangle is
 * front-facing when `point` lies strictly on the side its counter-clockwise
 * normal points to; a degenerate triangle faces neither way, so its edges to
 * front-facing neighbours are silhouettes (conservative). */
size_t pvs_find_silhouettes(pvs_silhouette* out, const float* positions, const uint32_t* indices,
                            const uint32_t* adjacency, const uint32_t* tri_ids, size_t count,
                            const float point[3]);

#ifdef __cplusplus
}
#endif

#endif
