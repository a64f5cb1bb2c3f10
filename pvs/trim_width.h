/* trim_width.h - how far a silhouette edge is extruded inwards (paper 3.2-3.6).
 *
 * A viewpoint v in the double-cone viewcell (apex v*, base disk of radius Δ
 * at v0 = v* + z·forward, z = Δ / tan α, mirrored cone up to v* + 2z·forward)
 * sees a far-plane point p just past the silhouette point s. Projected from
 * v*, p lands inside the occluder, at most pvs_trim_width_px pixels from s
 * along the inward image-space edge normal; a trim region of that width
 * therefore lets every such ray from v* pass. The derivation is in
 * docs/trim-regions.md; the value is the exact maximum over the viewcell.
 */
#ifndef TRIMVR_PVS_TRIM_WIDTH_H
#define TRIMVR_PVS_TRIM_WIDTH_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pvs_trim_params {
    float delta;        /* viewcell radius Δ (world units), >= 0 */
    float tan_half_fov; /* tan α: half-angle of the PVS frustum (the larger axis), > 0 */
    float far_dist;     /* far plane distance from v* along forward, > 0 */
    float focal_px;     /* pixels per normalised image unit; 1 gives normalised units */
} pvs_trim_params;

/* Extrusion width in pixels for a silhouette point at `depth` (distance from
 * v* along forward) whose projection from v*, dotted with the outward unit
 * image-space edge normal (pointing away from the occluder), is
 * `sigma_outward`. Returns 0 for points at or beyond the far plane and
 * INFINITY when depth <= 2z (the point lies within the viewcell's depth
 * range, where no finite extrusion is conservative; P1 clamps to the image). */
float pvs_trim_width_px(const pvs_trim_params* params, float depth, float sigma_outward);

#ifdef __cplusplus
}
#endif

#endif
