/* convex.h - which triangles lie on a convex patch of surface closed by its
 * borders: the guard of P3's rule for regions wholly behind a prior front
 * (docs/pvs-edge-cases.md, "Regions behind a prior front"). Vulkan-free, run
 * once per scene in pvs_create; the GPU gets the bits as TV_PVS_BIND_CONVEX. */
#ifndef TRIMVR_PVS_CONVEX_H
#define TRIMVR_PVS_CONVEX_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* For each triangle t, sets bit t % 32 of bits[t / 32] (ceil(count / 32)
 * words, cleared first) when t's convex patch is closed: the triangles
 * joined to t through manifold edges that are convex or flat (each face's
 * corners on or behind the other's plane, rounding aside, winding
 * consistent) form a set with no other link: no concave manifold edge, no
 * rest edge (TV_ADJ_REST), no masked member (`masked[t]`: its texture's
 * holes are edges no silhouette marks). Borders, cracks and non-manifold
 * edges (values from TV_ADJ_CRACK up) end a patch without opening it: they
 * are silhouettes from everywhere. From any point, the part of such a patch
 * that faces the point and is reachable from t across edges that are not
 * silhouettes is convex, so each of its silhouettes' trim draws lies at or
 * in front of t's plane along any ray that meets t. `adjacency` is the GPU's
 * (3 values per triangle: corner e -> e + 1), `positions` xyz per vertex.
 * Returns the number of triangles set, or (size_t)-1 out of memory (no bit
 * set then: conservative). */
size_t pvs_convex_patches(uint32_t* bits, const uint32_t* adjacency, const uint32_t* indices, uint32_t count,
                          const float* positions, const bool* masked);

static inline bool pvs_convex_bit(const uint32_t* bits, uint32_t t)
{
    return (bits[t / 32] >> (t % 32)) & 1u;
}

#endif
