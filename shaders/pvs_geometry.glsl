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

// Box corners as bits (1: +x, 2: +y, 4: +z), three per face triangle; the
// winding does not matter, a see-through face has no back.
const uint pvs_box_corners[36] = uint[36](0u, 4u, 6u, 0u, 6u, 2u, 1u, 3u, 7u, 1u, 7u, 5u, 0u, 1u, 5u, 0u, 5u, 4u,
                                          2u, 6u, 7u, 2u, 7u, 3u, 0u, 2u, 3u, 0u, 3u, 1u, 4u, 5u, 7u, 4u, 7u, 6u);

vec3 pvs_corner(uint tri, uint c)
{
    if (!pvs_is_proxy(tri))
        return tv_vertex_position(tv_vertex_index(tri, c));
    uint v = tri - view.triangle_count, p = v / 12u;
    uint bits = pvs_box_corners[3u * (v - 12u * p) + c];
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

#endif
