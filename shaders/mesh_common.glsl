// mesh_common.glsl - the scene's descriptor set and the material functions
// every pass that rasterises scene triangles shares (mesh pass, PVS passes),
// so alpha masking and vertex pulling cannot differ between them.
#ifndef TV_MESH_COMMON_GLSL
#define TV_MESH_COMMON_GLSL

#include "mesh_shared.h"

struct tv_material_gpu {
    vec4 base_color;    // linear RGBA factor
    uint texture;       // layer of tv_textures when TV_MAT_TEXTURED is set
    uint flags;         // TV_MAT_*
    float alpha_cutoff;
    uint pad;
};

layout(std430, set = TV_SET_SCENE, binding = TV_BIND_POSITIONS) readonly buffer tv_positions_buf { float tv_positions[]; };
layout(std430, set = TV_SET_SCENE, binding = TV_BIND_ATTRIBS) readonly buffer tv_attribs_buf { float tv_attribs[]; };
layout(std430, set = TV_SET_SCENE, binding = TV_BIND_INDICES) readonly buffer tv_indices_buf { uint tv_indices[]; };
layout(std430, set = TV_SET_SCENE, binding = TV_BIND_TRI_MAT) readonly buffer tv_tri_mat_buf { uint tv_tri_material[]; };
layout(std430, set = TV_SET_SCENE, binding = TV_BIND_MATERIALS) readonly buffer tv_materials_buf { tv_material_gpu tv_materials[]; };
layout(set = TV_SET_SCENE, binding = TV_BIND_TEXTURES) uniform sampler2DArray tv_textures;

// Floats per vertex in tv_attribs: normal.xyz, uv.xy.
#define TV_ATTRIB_STRIDE 5

uint tv_vertex_index(uint tri, uint corner) { return tv_indices[tri * 3u + corner]; }

vec3 tv_vertex_position(uint v) { return vec3(tv_positions[3u * v], tv_positions[3u * v + 1u], tv_positions[3u * v + 2u]); }

vec3 tv_vertex_normal(uint v)
{
    uint a = TV_ATTRIB_STRIDE * v;
    return vec3(tv_attribs[a], tv_attribs[a + 1u], tv_attribs[a + 2u]);
}

vec2 tv_vertex_uv(uint v)
{
    uint a = TV_ATTRIB_STRIDE * v + 3u;
    return vec2(tv_attribs[a], tv_attribs[a + 1u]);
}

// Base colour (linear RGBA) of material m at uv. Textures have one mip level
// and are sampled at LOD 0 so every pass, fragment or compute, sees the same
// texel and therefore the same alpha-mask decision. The layer index may vary
// per triangle: it is a coordinate, not a descriptor index.
vec4 tv_material_color(uint m, vec2 uv)
{
    tv_material_gpu mat = tv_materials[m];
    vec4 c = mat.base_color;
    if ((mat.flags & TV_MAT_TEXTURED) != 0u)
        c *= textureLod(tv_textures, vec3(uv, float(mat.texture)), 0.0);
    return c;
}

// True when an alpha-masked material's fragment must be discarded.
bool tv_alpha_masked(uint m, float alpha)
{
    tv_material_gpu mat = tv_materials[m];
    return (mat.flags & TV_MAT_ALPHA_MASK) != 0u && alpha < mat.alpha_cutoff;
}

#endif
