/* patches.h - front patches seen from a point (P3's rule for regions behind a prior front,
 * docs/pvs-edge-cases.md, "Regions behind a prior front"). */
#ifndef TRIMVR_PVS_PATCHES_H
#define TRIMVR_PVS_PATCHES_H

#include <stdbool.h>
#include <stdint.h>

/* Labels each of the n triangles (corners: 9 floats each; adjacency: 3 values each, TV_ADJ_* of pvs_shared.h) with
 * its front patch seen from `apex`: the triangles facing it (edge-on counts as facing: more joins, larger patches,
 * fewer regions skipped), joined across every manifold or rest edge whose two faces both face it, i.e. across every
 * edge that is no silhouette from apex. labels[t] is the patch's representative (one of its triangle indices), or
 * TV_PVS_PATCH_NONE for a triangle facing away, a masked one (`masked`, may be NULL: the eyes see through it) and
 * every triangle of a patch that touches a masked facing one. Returns false when out of memory (labels then all
 * TV_PVS_PATCH_NONE). */
bool pvs_front_patches(uint32_t* labels, const uint32_t* adjacency, const float* corners, const bool* masked,
                       uint32_t n, const float apex[3]);

#endif
