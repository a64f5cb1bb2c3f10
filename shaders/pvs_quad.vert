#version 460
// P2, trim-region and umbra quads: six vertices per silhouette record of P1
// (trim: e0 e1 t1 t0, umbra: e0 e1 u1 u0, as two triangles each).
#extension GL_GOOGLE_include_directive : require
#define PVS_RW readonly
#include "pvs_common.glsl"

layout(location = 0) flat out uint v_region;

const uint quad_corner[6] = uint[6](0u, 1u, 2u, 0u, 2u, 3u);

void main()
{
    uint slot = uint(gl_VertexIndex) / 6u;
    uint corner = quad_corner[uint(gl_VertexIndex) - slot * 6u];
    uint base = slot * TV_PVS_SIL_VEC4;
    // corners 2, 3 are record entries 2, 3 (trim) or 4, 5 (umbra)
    uint entry = corner < 2u ? corner : corner + (pc.kind == TV_PVS_KIND_UMBRA ? 2u : 0u);
    gl_Position = view.view_proj * vec4(sil[base + entry].xyz, 1.0);
    v_region = floatBitsToUint(sil[base].w);
}
