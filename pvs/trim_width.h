/* trim_width.h - how far a silhouette edge is extruded inwards (paper 3.2-3.6).
 *
 * A viewpoint v in the double-cone viewcell (apex v*, base disk of radius Δ
 * at v0 = v* + z·forward, z = Δ / tan α, mirrored cone up to v* + 2z·forward)
 * sees a far-plane point p just past the silhouette point s. Projected from
 * v*, p lands inside the occluder, at most pvs_trim_width_px pixels from s
 * along the inward image-space edge normal; a trim region of that width
 * therefore lets every such ray from v* pass. The derivation is in
 * docs/trim-width.md; the value is the exact maximum over the viewcell. With
 * far_dist set to a bound of the depth of what lies behind the edge (P1 uses
 * pvs/depth_bound.h), it is the maximum over every point that exists.
 */
#ifndef TRIMVR_PVS_TRIM_WIDTH_H
#define TRIMVR_PVS_TRIM_WIDTH_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pvs_trim_params {
    float delta;        /* viewcell radius Δ (world units), >= 0 */
    float tan_half_fov; /* tan α: half-angle of the PVS frustum (the larger axis), > 0 */
    /* Depth (from v*, along forward) of the farthest point that can lie
     * behind the silhouette: the far plane, or a bound of the scene's depth
     * over the edge's footprint (pvs/depth_bound.h), > 0. */
    float far_dist;
    float focal_px; /* pixels per normalised image unit; 1 gives normalised units */
} pvs_trim_params;

/* Extrusion width in pixels for a silhouette point at `depth` (distance from
 * v* along forward) whose projection from v*, dotted with the outward unit
 * image-space edge normal (pointing away from the occluder), is
 * `sigma_outward`. INFINITY when depth <= 2z (the point lies within the
 * viewcell's depth range, where no finite extrusion is conservative; P1
 * clamps to the image), else 0 for points at or beyond far_dist. */
float pvs_trim_width_px(const pvs_trim_params* params, float depth, float sigma_outward);

/* How far, in pixels and in any direction, a point at depth <= far_dist seen
 * past the silhouette point from the viewcell can land from the point's
 * image (`sigma_length`: the length of its normalised image coordinates):
 * the width's bound with the inward component replaced by the length. P1
 * bounds the scene's depth over the edge's image widened by this reach.
 * INFINITY and 0 as pvs_trim_width_px. */
float pvs_trim_reach_px(const pvs_trim_params* params, float depth, float sigma_length);

#ifdef __cplusplus
}
#endif

#endif
