#version 460
// P4: every id of the visibility buffer (the nearest front of each pixel
// from v*, trimmed pixels included: it is visible from v*, a point of the
// viewcell) and of the wide (dilated) visibility buffer joins the trimmed
// primitives already flagged by P2/P3.
#extension GL_GOOGLE_include_directive : require
#include "pvs_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = TV_PVS_SET, binding = TV_PVS_BIND_VIS_IDS, r32ui) uniform readonly uimage2D vis_ids;
layout(set = TV_PVS_SET, binding = TV_PVS_BIND_VIS_WIDE, r32ui) uniform readonly uimage2D vis_wide;

void main()
{
    uvec2 xy = gl_GlobalInvocationID.xy;
    if (xy.x >= view.width || xy.y >= view.height)
        return;
    uint id = imageLoad(vis_ids, ivec2(xy)).x;
    if (id != TV_NO_TRIANGLE)
        tri_flags[id] = 1u;
    id = imageLoad(vis_wide, ivec2(xy)).x;
    if (id != TV_NO_TRIANGLE)
        tri_flags[id] = 1u;
}
