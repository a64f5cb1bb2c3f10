// pvs_geometry.glsl - the triangles P1 and P2 draw: the scene's, pulled from
// the scene set, and the proxies' (pvs_compute_dynamic), 12 per proxy box,
// whose ids follow the scene's: view.triangle_count + 12 proxy + face. Both
// a proxy face and a triangle of an SCN_ALPHA_BLEND material are
// see-through: never an occluder, output wherever it may be visible
// (docs/trim-regions.md, "See-through triangles and proxies").
#ifndef TV_PVS_GEOMETRY_GLSL
#define TV_PVS_GEOMETRY_GLSL

#include "mesh_common.glsl"
#include "pvs_common.glsl"

layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_PROXIES) readonly buffer pvs_proxy_buf { vec4 proxy_box[]; };

bool pvs_is_proxy(uint tri) { return tri >= view.triangle_count; }

// Box corners as bits (1: +x, 2: +y, 4: +z), three per face triangle, 3 bits
// per corner, 9 corners per word: the table (0 4 6, 0 6 2, 1 3 7, 1 7 5,
// 0 1 5, 0 5 4, 2 6 7, 2 7 3, 0 2 3, 0 3 1, 4 5 7, 4 7 6) packed into
// constants, because a constant array indexed at run time costs every
// invocation of P1 and P2 an array copy on llvmpipe, proxy or not. The
// winding does not matter: a see-through face has no back.
uint pvs_box_corner_bits(uint k)
{
    uint word = k < 9u ? 0x76561a0u : k < 18u ? 0x4a29179u : k < 27u ? 0x341f5f2u : 0x6f3d858u;
    return (word >> (3u * (k % 9u))) & 7u;
}

vec3 pvs_corner(uint tri, uint c)
{
    if (!pvs_is_proxy(tri))
        return tv_vertex_position(tv_vertex_index(tri, c));
    uint v = tri - view.triangle_count, p = v / 12u;
    uint bits = pvs_box_corner_bits(3u * (v - 12u * p) + c);
    return mix(proxy_box[2u * p].xyz, proxy_box[2u * p + 1u].xyz,
               vec3(float(bits & 1u), float((bits >> 1u) & 1u), float((bits >> 2u) & 1u)));
}

vec2 pvs_corner_uv(uint tri, uint c) { return pvs_is_proxy(tri) ? vec2(0.0) : tv_vertex_uv(tv_vertex_index(tri, c)); }

// A proxy's faces take material 0; pvs_face.frag never reads it for them.
uint pvs_material(uint tri) { return pvs_is_proxy(tri) ? 0u : tv_tri_material[tri]; }

bool pvs_seethrough(uint tri)
{
    return pvs_is_proxy(tri) || (tv_materials[tv_tri_material[tri]].flags & TV_MAT_ALPHA_BLEND) != 0u;
}

float cross2(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }

// Barycentric weights of screen point p (affine: any p, inside or not).
vec3 bary(vec2 s[3], vec2 p)
{
    float area = cross2(s[1] - s[0], s[2] - s[0]);
    float b1 = cross2(p - s[0], s[2] - s[0]) / area, b2 = cross2(s[1] - s[0], p - s[0]) / area;
    return vec3(1.0 - b1 - b2, b1, b2);
}

#endif
