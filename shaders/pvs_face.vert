#version 460
// P2, scene triangles: vertex pulling from the FF or BF list P1 wrote (the
// draw's vertexCount is 3 x the list length, set by P1 through atomics).
// With TV_PVS_KIND_WIDE the triangle is dilated by half a pixel in screen
// space (conservative rasterisation by hand: lavapipe has no
// VK_EXT_conservative_rasterization) into the second, "wide" visibility
// buffer, so that P4 also sees the nearest of the triangles that touch a
// pixel without covering its centre: an eye in the viewcell samples other
// directions than v*'s pixel centres. The undilated screen triangle goes to
// the fragment shader, which inserts the fronts of such pixels as candidate
// fronts (TV_ID_CANDIDATE).
#extension GL_GOOGLE_include_directive : require
#define PVS_RW readonly
#include "mesh_common.glsl"
#include "pvs_common.glsl"

layout(location = 0) out vec2 v_uv;
layout(location = 1) flat out uint v_triangle;
layout(location = 2) flat out uint v_material;
layout(location = 3) flat out vec4 v_s01; // undilated screen corners 0 and 1
layout(location = 4) flat out vec3 v_s2;  // corner 2, orientation (0: not dilated)
layout(location = 5) flat out float v_far; // farthest corner's depth (clip w)
layout(location = 6) flat out float v_near; // nearest corner's depth (clip w)

// Every corner moves so far that both of its edges move out by the pixel's
// half extent: a needle's sharp corner moves tens or hundreds of pixels. An
// earlier clamp to 3 pixels let thin slivers lose their whole dilation (and
// all their fragments): the edges meeting at a clamped corner barely move.
// The fragment shader discards what the enlarged triangle covers beyond the
// pixels the triangle touches (touches_pixel), so coverage is exact.

vec2 screen(vec4 clip) { return (clip.xy / clip.w * 0.5 + 0.5) * vec2(view.width, view.height); }

void main()
{
    uint slot = uint(gl_VertexIndex) / 3u;
    uint corner = uint(gl_VertexIndex) - slot * 3u;
    uint tri = (pc.kind & ~(TV_PVS_KIND_WIDE | TV_PVS_KIND_SPILL)) == TV_PVS_KIND_FRONT ? ff_list[slot] : bf_list[slot];
    vec4 c[3];
    for (uint i = 0u; i < 3u; i++)
        c[i] = view.view_proj * vec4(tv_vertex_position(tv_vertex_index(tri, i)), 1.0);
    vec4 pos = c[corner];
    v_far = max(max(c[0].w, c[1].w), c[2].w);
    v_near = min(min(c[0].w, c[1].w), c[2].w);
    v_s01 = vec4(0.0);
    v_s2 = vec3(0.0);
    if ((pc.kind & TV_PVS_KIND_WIDE) != 0u && c[0].w > 0.0 && c[1].w > 0.0 && c[2].w > 0.0) {
        vec2 s[3] = vec2[3](screen(c[0]), screen(c[1]), screen(c[2]));
        vec2 a = s[1] - s[0], b = s[2] - s[0];
        float orient = sign(a.x * b.y - a.y * b.x);
        if (orient != 0.0) {
            v_s01 = vec4(s[0], s[1]);
            v_s2 = vec3(s[2], orient);
            // outward normals of the two edges meeting at this corner
            vec2 prev = s[corner] - s[(corner + 2u) % 3u], next = s[(corner + 1u) % 3u] - s[corner];
            vec2 np = normalize(orient * vec2(prev.y, -prev.x)), nn = normalize(orient * vec2(next.y, -next.x));
            // move each edge out by the pixel's half extent along its normal
            float hp = 0.5 * (abs(np.x) + abs(np.y)), hn = 0.5 * (abs(nn.x) + abs(nn.y));
            float det = np.x * nn.y - np.y * nn.x;
            vec2 d = abs(det) > 1e-4 ? vec2(hp * nn.y - hn * np.y, np.x * hn - nn.x * hp) / det : np * hp;
            if (length(d) > TV_PVS_MAX_DILATION_PX)
                d = normalize(d) * TV_PVS_MAX_DILATION_PX;
            pos.xy += d * 2.0 / vec2(view.width, view.height) * pos.w;
        }
    }
    gl_Position = pos;
    uint v = tv_vertex_index(tri, corner);
    v_uv = tv_vertex_uv(v);
    v_triangle = tri;
    v_material = tv_tri_material[tri];
}
