#version 460
// Mesh pass, fragment stage: glTF back-face culling, base colour x texture,
// alpha mask, one directional light plus hemispheric ambient, triangle id
// output. BLEND materials output their alpha for the blend pipeline.
#extension GL_GOOGLE_include_directive : require
#include "mesh_common.glsl"

layout(location = 0) in vec3 v_normal;
layout(location = 1) in vec2 v_uv;
layout(location = 2) flat in uint v_triangle;
layout(location = 3) flat in uint v_material;

layout(location = 0) out vec4 o_color; // linear; the SRGB attachment encodes it
layout(location = 1) out uint o_triangle;

void main()
{
    // glTF: back faces of single-sided materials are culled. A discard, not
    // the pipeline's cull mode, since one draw mixes materials.
    bool double_sided = (tv_materials[v_material].flags & TV_MAT_DOUBLE_SIDED) != 0u;
    if (!gl_FrontFacing && !double_sided)
        discard;
    vec4 base = tv_material_color(v_material, v_uv);
    if (tv_alpha_masked(v_material, base.a))
        discard;
    vec3 n = normalize(v_normal);
    if (!gl_FrontFacing)
        n = -n; // a double-sided back is lit as a front
    vec3 ambient = mix(vec3(TV_GROUND_COLOR), vec3(TV_SKY_COLOR), n.y * 0.5 + 0.5);
    vec3 sun = vec3(TV_SUN_COLOR) * max(dot(n, vec3(TV_SUN_DIR)), 0.0);
    bool blend = (tv_materials[v_material].flags & TV_MAT_ALPHA_BLEND) != 0u;
    o_color = vec4(base.rgb * (ambient + sun), blend ? base.a : 1.0);
    o_triangle = v_triangle;
}
