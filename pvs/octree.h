/* octree.h - the viewcell-independent octree of the trim-region PVS (P0, part 1).
 *
 * Built once per scene and cached (paper section 5.1). The root is a cube
 * around the scene; a node is split while it references more triangles than
 * the cap and is shallower than the maximum depth. A triangle is referenced
 * by every leaf it overlaps (exact triangle/box test), so the leaves of one
 * layer may share triangles; pvs_layers_build assigns each triangle to its
 * earliest layer. After the split the tree is balanced: face-neighbouring
 * leaves differ by at most two levels, so a leaf face has at most 16
 * neighbours (violating leaves are split until none remain).
 *
 * Leaves are stored flat. Positions are integers in units of the finest cell
 * (the root side is 1 << max_depth units): the face-neighbour relation and
 * the faces' world coordinates are then exact, which the layer ordering
 * relies on (two neighbours see their shared face at the same float).
 */
#ifndef TRIMVR_PVS_OCTREE_H
#define TRIMVR_PVS_OCTREE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "scene.h"

#ifdef __cplusplus
extern "C" {
#endif

#define PVS_OCTREE_DEFAULT_CAP 1024u
#define PVS_OCTREE_DEFAULT_DEPTH 8u
#define PVS_OCTREE_MAX_DEPTH 16u
#define PVS_OCTREE_LEAF_BIT 0x80000000u

/* Leaf faces: axis = face / 2, the positive side when face is odd. */
typedef enum pvs_face {
    PVS_FACE_NEG_X = 0,
    PVS_FACE_POS_X = 1,
    PVS_FACE_NEG_Y = 2,
    PVS_FACE_POS_Y = 3,
    PVS_FACE_NEG_Z = 4,
    PVS_FACE_POS_Z = 5
} pvs_face;

typedef struct pvs_octree_desc {
    uint32_t max_triangles_per_leaf; /* 0: PVS_OCTREE_DEFAULT_CAP */
    uint32_t max_depth;              /* 0: PVS_OCTREE_DEFAULT_DEPTH; at most PVS_OCTREE_MAX_DEPTH */
} pvs_octree_desc;

typedef struct pvs_leaf {
    float min[3], max[3]; /* world-space box, computed from cell[] and level */
    uint32_t cell[3];     /* min corner in finest-cell units */
    uint32_t level;       /* 0 = root; side = 1 << (max_depth - level) units */
} pvs_leaf;

typedef struct pvs_octree {
    float root_min[3];
    float root_size;   /* side of the root cube, world units */
    uint32_t max_depth;
    uint32_t max_triangles_per_leaf;
    uint32_t scene_triangle_count;

    uint32_t leaf_count;
    pvs_leaf* leaves;
    /* Triangles of leaf i: tri_ids[tri_offsets[i] .. tri_offsets[i+1]). */
    uint32_t* tri_offsets; /* leaf_count + 1 */
    uint32_t* tri_ids;
    /* Leaves touching face f of leaf i (sharing a positive area):
     * nbr_ids[nbr_offsets[6i+f] .. nbr_offsets[6i+f+1]). Symmetric. */
    uint32_t* nbr_offsets; /* 6 * leaf_count + 1 */
    uint32_t* nbr_ids;
    /* Node tree for point location: node 0 is the root; nodes[i] is the index
     * of the first of 8 contiguous children (bit 0 = +x, bit 1 = +y,
     * bit 2 = +z), or PVS_OCTREE_LEAF_BIT | leaf index. */
    uint32_t node_count;
    uint32_t* nodes;

    double build_ms;
    uint32_t balance_splits; /* leaves split only to satisfy the 2-level rule */
} pvs_octree;

/* Builds the octree over all triangles of `scene` into `out` (zeroed first).
 * desc may be NULL (all defaults). A scene without triangles gives a single
 * empty leaf. Returns false with a one-line message in err (naming the scene)
 * when the desc is invalid or memory runs out; `out` is then empty. */
bool pvs_octree_build(const pvs_octree_desc* desc, const scn_scene* scene, pvs_octree* out,
                      char* err, size_t err_size);

/* Releases the arrays and zeroes the octree. Safe on a zeroed octree. */
void pvs_octree_free(pvs_octree* tree);

/* Index of the leaf containing finest-cell point (x, y, z), each < 1 << max_depth. */
uint32_t pvs_octree_locate(const pvs_octree* tree, uint32_t x, uint32_t y, uint32_t z);

#ifdef __cplusplus
}
#endif

#endif
