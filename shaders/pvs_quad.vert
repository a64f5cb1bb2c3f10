#version 460
// P2, trim-region and umbra quads: six vertices per entry of P1's silhouette
// list, each naming a record (trim: e0 e1 t1 t0, umbra: e0 e1 u1 u0, as two
// triangles each). Trim quads are drawn three times: instance 0 with t1, t0 at the midpoint depth
// of the silhouette's two planes, instance 1 at the nearer of them and
// instance 2 at the farther (kept in the record's w; 0 draws nothing: an
// edge without a back neighbour, or, for instance 2, whose front triangle
// is not seen grazing), so that a thin occluder's front
// face, or a slab's back face behind a side seen edge-on, holds a trim too
// (pvs_trim_depth). Those two are moved TV_PVS_TRIM_NUDGE of their depth
// towards the other plane, all four corners: a trim in a face's plane
// would tie with the face only up to rounding, and on the wrong side of it
// validates nothing.
#extension GL_GOOGLE_include_directive : require
#define PVS_RW readonly
#include "pvs_common.glsl"

layout(location = 0) flat out uint v_region;

void main()
{
    uint slot = uint(gl_VertexIndex) / 6u;
    // corners 0 1 2 0 2 3, a nibble each: a constant array indexed at run
    // time costs every invocation an array copy on llvmpipe (pvs_geometry.glsl)
    uint corner = (0x320210u >> (4u * (uint(gl_VertexIndex) - slot * 6u))) & 15u;
    uint base = p1_order[TV_PVS_ORDER_SIL(slot)] * TV_PVS_SIL_VEC4; // the record, in P1's order (pvs_order.comp)
    // corners 2, 3 are record entries 2, 3 (trim) or 4, 5 (umbra)
    uint entry = corner < 2u ? corner : corner + (pc.kind == TV_PVS_KIND_UMBRA ? 2u : 0u);
    vec3 p = sil[base + entry].xyz;
    if (pc.kind == TV_PVS_KIND_TRIM && gl_InstanceIndex > 0) {
        if (sil[base + (gl_InstanceIndex == 2 ? 4u : 2u)].w == 0.0) {
            gl_Position = vec4(0.0, 0.0, 0.0, 1.0); // degenerate: no fragments
            v_region = 0u;
            return;
        }
        float depth = dot(p - view.apex.xyz, view.forward.xyz);
        float plane = entry < 2u ? depth : sil[base + entry + (gl_InstanceIndex == 2 ? 2u : 0u)].w;
        float nudge = gl_InstanceIndex == 1 ? 1.0 + TV_PVS_TRIM_NUDGE : 1.0 - TV_PVS_TRIM_NUDGE;
        p = view.apex.xyz + (p - view.apex.xyz) * (plane * nudge / depth); // along the v* ray through the corner
    }
    gl_Position = view.view_proj * vec4(p, 1.0);
    v_region = floatBitsToUint(sil[base].w);
}
