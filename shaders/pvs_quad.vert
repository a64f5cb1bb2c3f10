#version 460
// P2, trim-region and umbra quads: six vertices per entry of P1's silhouette
// list, each naming a record (e0 e1 t1 t0, as two triangles). One quad feeds
// both lists: the trim quad and the umbra quad (e0 e1 u1 u0) have the same
// footprint (the umbra's far corners lie on the v* rays through the trim's
// extruded ones), so the trim quad is rasterised once and every other depth
// comes with it. The trim quad is the one rasterised because its depth at
// the midpoint of the silhouette's two planes (record entries 2, 3) ties
// with a face's where the edge has no back neighbour, and only the
// rasteriser's own gl_FragCoord.w rounds that tie as the faces' depths do
// (a noperspective 1 / w for it moved 1 % of the city's PVS). The other two
// trim depths: the nearer of the two planes and the farther (kept in the
// record's w; 0: none, an edge without a back neighbour, or, for the
// farther, whose front triangle is not seen grazing), so that a thin
// occluder's front face, or a slab's back face behind a side seen edge-on,
// holds a trim too (pvs_trim_depth). Those two are moved TV_PVS_TRIM_NUDGE
// of their depth towards the other plane, all four corners: a trim in a
// face's plane would tie with the face only up to rounding, and on the
// wrong side of it validates nothing.
#extension GL_GOOGLE_include_directive : require
#define PVS_RW readonly
#include "pvs_common.glsl"

layout(location = 0) flat out uint v_region;
// w of the trim corner over w of the corner at the nearer and farther trim
// depth and of the umbra corner, interpolated perspective-correct: at a
// pixel, the trim's depth over it is that other depth (1 / w is affine in
// the image). A noperspective 1 / w per depth, the same in exact arithmetic,
// moved 2 ids of 7,021 on the city at 10 cm in the old draw order, this none.
// 0 where the record has no such trim: its depth reads as infinite, beyond
// the far plane, where pvs_quad.frag outputs nothing.
layout(location = 1) out vec3 v_w_over;

float w_of(vec3 p) { return (view.view_proj * vec4(p, 1.0)).w; }

// p moved along its v* ray from `depth` to `plane` times `scale`
vec3 along_ray(vec3 p, float depth, float plane, float scale)
{
    return view.apex.xyz + (p - view.apex.xyz) * (plane * scale / depth);
}

void main()
{
    uint slot = uint(gl_VertexIndex) / 6u;
    // corners 0 1 2 0 2 3, a nibble each: a constant array indexed at run
    // time costs every invocation an array copy on llvmpipe (pvs_geometry.glsl)
    uint corner = (0x320210u >> (4u * (uint(gl_VertexIndex) - slot * 6u))) & 15u;
    uint base = p1_order[TV_PVS_ORDER_SIL(slot)] * TV_PVS_SIL_VEC4; // the record, in P1's order (pvs_order.comp)
    vec4 trim = sil[base + corner];
    vec4 umbra = corner < 2u ? trim : sil[base + corner + 2u]; // corners 2, 3: entries 4, 5
    float depth = dot(trim.xyz - view.apex.xyz, view.forward.xyz);
    float near = corner < 2u ? depth : trim.w, far = corner < 2u ? depth : umbra.w;
    bool has_near = sil[base + 2u].w != 0.0, has_far = sil[base + 4u].w != 0.0;
    gl_Position = view.view_proj * vec4(trim.xyz, 1.0);
    float w = gl_Position.w;
    v_w_over = vec3(has_near ? w / w_of(along_ray(trim.xyz, depth, near, 1.0 + TV_PVS_TRIM_NUDGE)) : 0.0,
                    has_far ? w / w_of(along_ray(trim.xyz, depth, far, 1.0 - TV_PVS_TRIM_NUDGE)) : 0.0,
                    w / w_of(umbra.xyz));
    // No depth clipping (no depth test either): the trim depths may lie
    // beyond the far plane, the umbra's never does, and pvs_quad.frag
    // clips each trim depth as the rasteriser clipped the trim's own draws.
    gl_Position.z = 0.5 * gl_Position.w;
    v_region = floatBitsToUint(sil[base].w);
}
