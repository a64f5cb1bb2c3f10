/* weld.h - position welding and triangle adjacency (meshoptimizer-style).
 *
 * The PVS finds silhouette edges by comparing the facing of the two triangles
 * on each edge. Scenes arrive as polygon soups (every primitive has its own
 * vertices, OpenArena has T-junctions and fins), so edges are matched on
 * welded positions, never on raw vertex ids. Output buffers are caller-owned.
 */
#ifndef TRIMVR_SCENE_WELD_H
#define TRIMVR_SCENE_WELD_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* adjacency[] value for an edge only one triangle uses (or a degenerate edge
 * whose two ends weld together). */
#define SCN_EDGE_BORDER 0xFFFFFFFFu
/* adjacency[] value for an edge shared by three or more triangles. */
#define SCN_EDGE_NONMANIFOLD 0xFFFFFFFEu
/* Flag on an adjacency[] value below SCN_EDGE_NONMANIFOLD: the edge is a
 * border resting on the face whose id is in the other bits
 * (scn_join_rest_edges). Triangle ids stay below it. */
#define SCN_EDGE_REST 0x80000000u

/* Exact welding: remap[v] = the smallest vertex id whose position is bitwise
 * equal to v's (after folding -0.0 into +0.0, so a mirrored coordinate still
 * welds). No epsilon: two positions that differ in one ulp are distinct, as
 * they are for the rasteriser. `remap` holds vertex_count entries;
 * `positions` holds 3 floats per vertex. Returns the number of unique
 * positions. Expected O(n) (one hash table of ~2n slots, allocated inside;
 * returns 0 and leaves remap[v] = v if that allocation fails). */
size_t scn_weld_positions(uint32_t* remap, const float* positions, size_t vertex_count);

/* For triangle t and edge e (corner e -> corner (e+1)%3), writes into
 * adjacency[3t+e]:
 *   - the other triangle's id when exactly two triangles share the welded
 *     edge, whatever their winding. With inconsistent winding (the neighbour
 *     walks the edge in the same direction) the pair is still reported: a
 *     consumer that classifies facing per triangle then sees the edge as a
 *     silhouette wherever the two disagree, which is conservative;
 *   - SCN_EDGE_BORDER when no other triangle has the edge, or when both ends
 *     of the edge weld to one position (degenerate edge);
 *   - SCN_EDGE_NONMANIFOLD when three or more triangles share it.
 * `adjacency` and `indices` hold 3*triangle_count entries; `remap` comes from
 * scn_weld_positions over the same vertex array. Expected O(n); on allocation
 * failure every edge is written as SCN_EDGE_BORDER (always-silhouette, so the
 * consumer stays conservative) and an error is logged. */
void scn_build_adjacency(uint32_t* adjacency, const uint32_t* indices, size_t triangle_count,
                         const uint32_t* remap);

/* Map-compiled levels export some single-sided surfaces as two coincident
 * faces of opposite winding, so a quad's diagonal is shared by four
 * triangles and scn_build_adjacency writes SCN_EDGE_NONMANIFOLD there: a
 * silhouette from everywhere, whose trim region erodes the surface along
 * its diagonal (an OpenArena fog sheet spanning a whole level let everything
 * above it into the PVS there). For each edge exactly four triangles share,
 * two walking it each way, that pair into two same-facing pairs (unit
 * normals within SCN_WELD_NORMAL_COS, so each pair lies in one plane, one
 * triangle on each side of the edge), writes each triangle's partner into
 * adjacency[]: each pair is a flat sheet that continues across the edge and
 * faces one way from every point, so a ray crossing the plane near the edge
 * meets a face of that sheet of the same facing on either side, and the
 * edge is never a silhouette (scn_join_tjunctions' argument, per sheet).
 * Any other non-manifold edge stays one. Run it on scn_build_adjacency's
 * output with the same `indices` and `remap`. Returns the number of edges
 * paired; 0 (nothing changed) if it cannot allocate. */
size_t scn_pair_sheets(uint32_t* adjacency, const uint32_t* indices, size_t triangle_count, const uint32_t* remap,
                       const float* positions);

/* Map-compiled levels (OpenArena) split faces at T-junctions: a long edge of
 * one triangle meets several shorter edges of its neighbours, so no edge is
 * shared and every one of them is a border, hence a silhouette and a trim
 * region, although the surface goes on. For each SCN_EDGE_BORDER edge that
 * border edges of other triangles cover end to end, where those triangles
 * lie in its triangle's plane with the same facing and on the other side of
 * the edge, writes one of them into adjacency[] (a flat continuation: the
 * two face the same way from every point, so the edge is never a
 * silhouette). Edges it cannot prove covered stay borders (conservative).
 * `positions` are the scene's, indices as for scn_build_adjacency. Returns
 * the number of edges joined; 0 (nothing changed) if it cannot allocate. */
size_t scn_join_tjunctions(uint32_t* adjacency, const uint32_t* indices, size_t triangle_count,
                           const float* positions);

/* Map-compiled levels stand walls on floor faces that run on under them,
 * so a wall's foot is a border although nothing can be seen past it from
 * in front of both. For each SCN_EDGE_BORDER edge E of a triangle T (corner
 * c -> c+1, direction d) that faces F cover end to end, where each F holds E
 * in its plane, covers a neighbourhood of E on the side d x n_F of E in that
 * plane (n_F: F's unit normal) that lies on T's front side (n_T . (d x n_F)
 * > 0), the F are coplanar and face one way, and T meets their plane at
 * more than ~0.6 degrees, writes SCN_EDGE_REST | F. T and F then bound
 * space near E as the two triangles of a consistently wound manifold edge
 * do (a wall standing on a floor: a concave crease), so E is a silhouette
 * exactly when T and F do not both face the point or both face away from
 * it (a convex edge, a face hanging from a slab that runs on behind it,
 * would be as sound but stays a border: docs/trim-regions.md); as there is no edge of F at E, such a silhouette is named
 * from T, as a border (pvs_find_silhouettes). The argument, the tolerances
 * (those of scn_join_tjunctions) and what it leaves alone:
 * docs/trim-regions.md, "Silhouettes". `solid` (NULL: all) marks the
 * triangles that may be an F: opaque and static ones, as a face with holes
 * or one that moves does not close the crease. Run it after
 * scn_mark_cracks, which then still sees these edges as borders; `indices`
 * as for scn_build_adjacency, fewer than SCN_EDGE_REST triangles. Returns
 * the number of edges joined (those before a failed allocation). */
size_t scn_join_rest_edges(uint32_t* adjacency, const uint32_t* indices, size_t triangle_count,
                           const float* positions, const uint8_t* solid);

/* Parts glued on a closed solid (CAD/BIM exports: a wall standing on a
 * slab, a slab against a wall, a book on a shelf): for each consistently
 * wound, convex manifold edge E of triangles t and k where faces F of closed
 * opaque static surfaces (`solid`, NULL: all) cover E end to end, each
 * coplanar with t and facing the other way, covering a neighbourhood of E on
 * k's front side, writes t into t's entry and k into k's (each faces as
 * itself: E is never a silhouette). E is then a silhouette neither by the
 * manifold rule (t, k) nor by the rest rule (k, F) (t faces one way exactly
 * when F faces the other), and each alone is sound (docs/trim-regions.md,
 * "Silhouettes"). Run it after scn_join_rest_edges. Returns the number of
 * edges joined. */
size_t scn_join_glued_edges(uint32_t* adjacency, const uint32_t* indices, size_t triangle_count,
                            const float* positions, const uint8_t* solid);
/* Closure up to T-junctions, for scn_join_glued_edges: a box whose top is
 * split where its side is not has border edges along that crease (the
 * side's long edge meets the top's short ones), yet no gap. For each border
 * edge (SCN_EDGE_BORDER, or SCN_EDGE_REST | F) that border edges of other
 * triangles, walked the other way, cover end to end on its line (any
 * plane), writes one of those triangles into cover[] (3*triangle_count
 * entries), else SCN_EDGE_BORDER. Tolerances as scn_join_tjunctions'.
 * Returns the number covered; 0 with nothing covered if it cannot allocate. */
size_t scn_cover_borders(uint32_t* cover, const uint32_t* adjacency, const uint32_t* indices, size_t triangle_count,
                         const float* positions);
/* Cracks: a mesh simplified or exported per part leaves narrow gaps between
 * faces that should meet (Sponza's decimated columns: 1 cm at their
 * corners), through which a renderer shows what lies inside. Sets
 * crack[3t+e] = 1 for each SCN_EDGE_BORDER edge along which a border edge of
 * another triangle runs within max_gap (directions within ~8 degrees, both
 * ends of their overlap within max_gap of the other edge), 0 for every
 * other edge. `crack` holds 3*triangle_count bytes; the rest as for
 * scn_join_tjunctions (run that first: a joined edge is no border). Returns
 * the number marked; 0 with nothing marked if it cannot allocate. Expected
 * O(L / max_gap) over the border edges' total length L. */
size_t scn_mark_cracks(uint8_t* crack, const uint32_t* adjacency, const uint32_t* indices, size_t triangle_count,
                       const float* positions, float max_gap);

#ifdef __cplusplus
}
#endif

#endif
