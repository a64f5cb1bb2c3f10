/* layers.h - per-viewcell octree layers (P0, part 2; paper section 5.2).
 *
 * The leaves that survive culling against the PVS frustum at v* are split
 * into layers such that, along every ray from v*, the leaves the ray passes
 * through have strictly increasing layer indices: no leaf can occlude a leaf
 * of its own or of an earlier layer. Layers are then processed in order on
 * the GPU, each with one draw.
 *
 * Dependencies: leaf n depends on its face neighbours across each face of n
 * that faces v* (v* strictly beyond the face plane): a ray from v* enters n
 * through such a face, coming from the neighbour. layer(n) = 1 + max over
 * its (surviving) dependencies, 0 without any. A FIFO queue holds only leaves
 * whose dependencies are all processed (Kahn's algorithm), so every leaf is
 * visited once: O(leaves + neighbour pairs). The paper starts from one node
 * at the near plane; here every dependency-free leaf starts the traversal,
 * which covers v* inside a leaf, v* outside the octree, and leaves whose
 * dependencies were culled by the frustum (see docs/trim-regions.md).
 *
 * On an octree the dependency graph is acyclic (docs/trim-regions.md has
 * the argument); leaves given in a non-hierarchical arrangement can form a
 * cycle, which is broken by forcing the blocked leaf with the fewest
 * unprocessed dependencies into the queue (counted in cycles_broken), so no
 * leaf is ever lost.
 *
 * Merging: the order above is strict, and yields 20-50 layers on real
 * scenes, many of them thin. Consecutive layers are then merged into at most
 * `max_layers` (the per-layer triangle budget is the smallest that allows
 * it); layers without triangles always merge. Along every ray the merged
 * indices are non-decreasing instead of increasing: a merged layer is still
 * behind every earlier one and in front of every later one, which is all P3
 * needs, since it sorts each pixel's entries of one layer by depth
 * (docs/trim-regions.md, "Merging layers").
 *
 * Memory: pvs_layers is an arena owned by the caller's struct. Arrays grow on
 * demand and are reused by the next call on the same struct, so per-frame
 * generation does not allocate once warm. Release with pvs_layers_free.
 */
#ifndef TRIMVR_PVS_LAYERS_H
#define TRIMVR_PVS_LAYERS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "octree.h"
#include "view.h"

#ifdef __cplusplus
extern "C" {
#endif

#define PVS_LAYER_CULLED 0xFFFFFFFFu
#define PVS_LAYERS_DEFAULT_MAX 14u
#define PVS_LAYERS_UNMERGED UINT32_MAX /* max_layers: keep the strict order */

typedef struct pvs_layers {
    uint32_t layer_count;
    /* Leaves of layer i: leaf_ids[leaf_offsets[i] .. leaf_offsets[i+1]). */
    uint32_t* leaf_offsets; /* layer_count + 1 */
    uint32_t* leaf_ids;
    /* Triangles of layer i, each scene triangle at most once over all layers
     * (in the earliest layer of a surviving leaf referencing it):
     * tri_ids[tri_offsets[i] .. tri_offsets[i+1]). */
    uint32_t* tri_offsets; /* layer_count + 1 */
    uint32_t* tri_ids;
    uint32_t tri_count;
    uint32_t* leaf_layer; /* per octree leaf: its (merged) layer, or PVS_LAYER_CULLED */
    uint32_t layers_unmerged; /* layer count of the strict order, before merging */
    uint32_t merge_budget;    /* the triangle budget merging used (0 also when not merged) */

    uint32_t leaves_visible;
    uint32_t leaves_culled;
    uint32_t cycles_broken;
    double order_ms; /* culling and layer assignment (the paper's P0 claim) */
    double ms;       /* everything, including the per-layer triangle lists */

    /* Arena state: capacities and scratch, private. */
    uint32_t _leaf_cap, _layer_cap, _tri_cap, _tri_stamp_cap, _stamp;
    uint32_t* _pending;
    uint32_t* _queue;
    uint32_t* _tri_stamp;
} pvs_layers;

/* Culls the leaves of `tree` against `view` (conservatively: a leaf is kept
 * unless its box lies entirely outside one frustum plane), assigns layers and
 * merges them into at most `max_layers` (0: PVS_LAYERS_DEFAULT_MAX;
 * PVS_LAYERS_UNMERGED: keep the strict order). `layers` must be zeroed
 * before its first use and is overwritten. Returns false with a one-line
 * message in err only when memory runs out. */
bool pvs_layers_build(const pvs_octree* tree, const pvs_view* view, uint32_t max_layers, pvs_layers* layers,
                      char* err, size_t err_size);

/* Releases the arena and zeroes it. Safe on a zeroed struct. */
void pvs_layers_free(pvs_layers* layers);

#ifdef __cplusplus
}
#endif

#endif
