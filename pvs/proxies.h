/* proxies.h - moving objects in one PVS request (pvs_compute_dynamic): the
 * paper's lazy sorting (section 5) of each proxy's box into the octree
 * leaves it touches, so that pvs_layers_build draws its 12 see-through faces
 * in the earliest layer of those leaves (docs/trim-regions.md, "See-through
 * triangles and proxies").
 *
 * A proxy is not drawn but output outright ("always") when its box meets
 * the viewcell's bounding sphere (an eye may be inside it, or its faces may
 * cross the near plane) or reaches outside the octree's root cube (leaves
 * cover the root only, so part of the box would be in no layer).
 *
 * Memory: pvs_proxy_sort is an arena like pvs_layers: arrays grow on demand
 * and are reused; release with pvs_proxy_sort_free.
 */
#ifndef TRIMVR_PVS_PROXIES_H
#define TRIMVR_PVS_PROXIES_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "octree.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Floats per proxy box: min xyz, unused, max xyz, unused (the GPU's vec4 pair). */
#define PVS_PROXY_FLOATS 8u

typedef struct pvs_proxy_sort {
    /* The static octree's leaves, each with the faces of the proxies whose
     * box touches it appended: face ids first_face + 12 p + 0..11. Only its
     * tri_offsets, tri_ids and scene_triangle_count differ from the static
     * tree's (the rest is shared, not owned). */
    pvs_octree tree;
    uint32_t always_count; /* proxies marked in `always` */

    uint32_t _leaf_cap, _ref_cap;
    uint32_t* _offsets;
    uint32_t* _ids;
} pvs_proxy_sort;

/* Sorts `count` boxes (PVS_PROXY_FLOATS floats each, min <= max) into the
 * leaves of `tree`; always[p] is set for the proxies output without drawing
 * (see above), which join no leaf. Returns the tree to build the layers
 * from: `tree` itself when no proxy is drawn, else &sort->tree. NULL only
 * when memory runs out. */
const pvs_octree* pvs_proxies_sort(pvs_proxy_sort* sort, const pvs_octree* tree, const float* boxes, uint32_t count,
                                   uint32_t first_face, const float centre[3], float radius, bool* always);

/* Releases the arena and zeroes it. Safe on a zeroed struct. */
void pvs_proxy_sort_free(pvs_proxy_sort* sort);

#ifdef __cplusplus
}
#endif

#endif
