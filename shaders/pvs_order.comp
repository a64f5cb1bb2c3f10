#version 460
// P1, after pvs_classify.comp: one invocation per layer triangle writes its
// class word's entries into the FF, BF and silhouette lists at its
// workgroup's offset (the classify pass's scan) plus the entries of the
// invocations before it, so the lists follow the layer list (triangle, then
// edge) and the same layers give the same lists, the same draw order in P2
// and the same trim-region ids in every run, on any device
// (docs/pvs-gpu-passes.md, "Repeatability").
#extension GL_GOOGLE_include_directive : require
#include "pvs_common.glsl"

layout(local_size_x = TV_WG_SIZE) in;

const uint EDGES = TV_PVS_CLASS_EDGE(0u) | TV_PVS_CLASS_EDGE(1u) | TV_PVS_CLASS_EDGE(2u);

shared uvec3 partial[TV_WG_SIZE];

void main()
{
    uint i = gl_GlobalInvocationID.x, t = gl_LocalInvocationID.x;
    uint word = i < pc.layer_count ? p1_order[TV_PVS_ORDER_CLASS(view.list_capacity, i)] : 0u;
    partial[t] = uvec3((word & TV_PVS_CLASS_FF) != 0u ? 1u : 0u, (word & TV_PVS_CLASS_BF) != 0u ? 1u : 0u,
                       bitCount(word & EDGES));
    barrier();
    if (i >= pc.layer_count)
        return;
    uvec3 at = uvec3(0u);
    for (uint j = 0u; j < t; j++)
        at += partial[j];
    uint s = TV_PVS_ORDER_GROUP(view.list_capacity, gl_WorkGroupID.x);
    at += uvec3(p1_order[s], p1_order[s + 1u], p1_order[s + 2u]);
    uint region = p1_order[s + 3u] + at.z - p1_order[s + 2u];
    uint tri = layer_tris[pc.layer_offset + i];
    if ((word & TV_PVS_CLASS_FF) != 0u)
        ff_list[at.x] = tri;
    if ((word & TV_PVS_CLASS_BF) != 0u)
        bf_list[at.y] = tri | ((word & TV_PVS_CLASS_CULLED) != 0u ? TV_ID_CULLED : 0u) |
                        ((word & TV_PVS_CLASS_STRADDLED) != 0u ? TV_ID_STRADDLED : 0u);
    for (uint e = 0u; e < 3u; e++) {
        if ((word & TV_PVS_CLASS_EDGE(e)) == 0u)
            continue;
        uint record = 3u * i + e;
        p1_order[TV_PVS_ORDER_SIL(at.z)] = record;
        if (region < 3u * patch_drawn()) // P3's rule for regions behind a prior front: the patch it is named from
            patch_label[patch_drawn() + region] = patch_label[tri];
        sil[record * TV_PVS_SIL_VEC4].w =
            uintBitsToFloat(region | ((word & TV_PVS_CLASS_CRACK(e)) != 0u ? TV_REGION_CRACK : 0u));
        at.z++;
        region++;
    }
}
