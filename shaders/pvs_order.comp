#version 460
// P1, after pvs_classify.comp: its class words and records become the FF,
// BF and silhouette lists in layer order (triangle, then edge), so that the
// same layers give the same lists, the same draw order in P2 and the same
// trim-region ids in every run, on any device (docs/pvs-gpu-passes.md,
// "Repeatability"). Two steps, chosen by the specialisation constant STEP:
//   0 (scan): one workgroup turns the per-workgroup counts into exclusive
//     offsets, writes the draw commands' vertex counts and numbers the
//     layer's regions after the tile's earlier layers' (TV_PVS_C_REGIONS);
//   1 (write): one invocation per layer triangle writes its entries at its
//     workgroup's offset plus the count of the invocations before it.
// Region ids are the running count over the tile's layers in that order, as
// the append numbered them before (a later layer's regions sort after an
// earlier layer's at equal depth, kind and id rank).
#extension GL_GOOGLE_include_directive : require
#include "pvs_common.glsl"

layout(local_size_x = TV_WG_SIZE) in;
layout(constant_id = 0) const uint STEP = 0u;

const uint EDGES = TV_PVS_CLASS_EDGE(0u) | TV_PVS_CLASS_EDGE(1u) | TV_PVS_CLASS_EDGE(2u);

shared uvec3 partial[TV_WG_SIZE];

uint group_slot(uint g) { return TV_PVS_ORDER_GROUP(view.list_capacity, g); }

uvec3 group_counts(uint g)
{
    uint s = group_slot(g);
    return uvec3(p1_order[s], p1_order[s + 1u], p1_order[s + 2u]);
}

// Each invocation scans a run of consecutive workgroups.
void scan()
{
    uint t = gl_LocalInvocationID.x, groups = (pc.layer_count + TV_WG_SIZE - 1u) / TV_WG_SIZE;
    uint per = (groups + TV_WG_SIZE - 1u) / TV_WG_SIZE, g0 = min(t * per, groups), g1 = min(g0 + per, groups);
    uint first_region = counters[TV_PVS_C_REGIONS];
    uvec3 sum = uvec3(0u);
    for (uint g = g0; g < g1; g++)
        sum += group_counts(g);
    partial[t] = sum;
    barrier();
    uvec3 off = uvec3(0u);
    for (uint j = 0u; j < t; j++)
        off += partial[j];
    for (uint g = g0; g < g1; g++) {
        uvec3 c = group_counts(g);
        uint s = group_slot(g);
        p1_order[s] = off.x;
        p1_order[s + 1u] = off.y;
        p1_order[s + 2u] = off.z;
        p1_order[s + 3u] = first_region + off.z;
        off += c;
    }
    if (t == TV_WG_SIZE - 1u) { // off: the layer's totals
        counters[TV_PVS_C_DRAW_FF] = 3u * off.x;
        counters[TV_PVS_C_DRAW_BF] = 3u * off.y;
        counters[TV_PVS_C_DRAW_TRIM] = 6u * off.z;
        counters[TV_PVS_C_DRAW_UMBRA] = 6u * off.z;
        counters[TV_PVS_C_REGIONS] = first_region + off.z;
    }
}

void write()
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
    uint s = group_slot(gl_WorkGroupID.x);
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
        sil[record * TV_PVS_SIL_VEC4].w =
            uintBitsToFloat(region | ((word & TV_PVS_CLASS_CRACK(e)) != 0u ? TV_REGION_CRACK : 0u));
        at.z++;
        region++;
    }
}

void main()
{
    if (STEP == 0u)
        scan();
    else
        write();
}
