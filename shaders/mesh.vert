#version 460
// Mesh pass, vertex stage: vertex pulling. No vertex buffers: draw slot
// gl_VertexIndex/3 names the triangle (directly for full draws, through the
// subset id list otherwise), so full and subset draws run identical code on
// identical data and produce bit-identical fragments.
#extension GL_GOOGLE_include_directive : require
#include "mesh_common.glsl"
#include "mesh_push.glsl"

layout(std430, set = TV_SET_DRAW, binding = TV_BIND_DRAW_IDS) readonly buffer draw_ids_buf { uint draw_ids[]; };

layout(location = 0) out vec3 v_normal;
layout(location = 1) out vec2 v_uv;
layout(location = 2) flat out uint v_triangle;
layout(location = 3) flat out uint v_material;

void main()
{
    uint slot = uint(gl_VertexIndex) / 3u;
    uint corner = uint(gl_VertexIndex) - slot * 3u;
    uint tri = pc.use_draw_ids != 0u ? draw_ids[slot] : slot;
    uint v = tv_vertex_index(tri, corner);
    gl_Position = pc.view_proj * vec4(tv_vertex_position(v), 1.0);
    // The opaque pass of a draw that blends: all three corners behind the
    // near plane clip the whole triangle, so full and subset draws keep one
    // vertex-pulling slot per triangle.
    if (pc.skip_blend != 0u && (tv_materials[tv_tri_material[tri]].flags & TV_MAT_ALPHA_BLEND) != 0u)
        gl_Position = vec4(0.0, 0.0, -1.0, 1.0);
    v_normal = tv_vertex_normal(v);
    v_uv = tv_vertex_uv(v);
    v_triangle = tri;
    v_material = tv_tri_material[tri];
}
