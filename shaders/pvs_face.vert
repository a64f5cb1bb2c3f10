#version 460
// P2, scene triangles: vertex pulling from the FF or BF list P1 wrote (the
// draw's vertexCount is 3 x the list length, set by P1's scan in pvs_classify.comp).
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
#include "pvs_geometry.glsl"

layout(location = 0) out vec2 v_uv;
layout(location = 1) flat out uint v_triangle;
layout(location = 2) flat out uint v_material;
layout(location = 3) flat out vec4 v_s01; // undilated screen corners 0 and 1
layout(location = 4) flat out vec3 v_s2;  // corner 2, orientation (0: not dilated)
layout(location = 5) flat out float v_far; // farthest corner's depth (clip w)
layout(location = 6) flat out float v_near; // nearest corner's depth (clip w)
layout(location = 7) flat out uint v_id_flags; // TV_ID_CULLED / TV_ID_STRADDLED from P1's list
layout(location = 8) flat out uint v_see;      // 1: see-through (pvs_seethrough), looked up once per triangle, not per fragment
layout(location = 9) flat out vec3 v_inv_w; // 1 / clip w of the corners (dilated pass; 0: not dilated)

// Two enlargements, each containing every pixel the triangle touches (its
// Minkowski sum with the pixel square); the first is drawn unless the
// second has under a quarter of its area:
// - each corner moves until both of its edges have moved out by the pixel's
//   half extent along their normals (fine for fat triangles; a sharp corner
//   moves 0.7 / sin(angle / 2) pixels, so a sliver grows by the square of
//   that). An earlier clamp of that offset to 3 pixels left slivers whose
//   corners are almost collinear without a single fragment;
// - the smallest triangle around the triangle's bounding rectangle along its
//   longest edge, grown by the pixel's extent (twice that rectangle's area:
//   about 3 pixels per pixel of a sliver's length). Its corners take the
//   depth and uv of the triangle's plane there (1/w, z/w and uv/w are affine
//   in screen space), the depth clamped to the triangle's own range; it is
//   used only where that plane lies in front of v* at all three. Drawn for
//   every triangle smaller than the first, it cost the interior's running
//   replay a few false-negative pixels (depths across a wide triangle whose
//   corners were clamped are not the plane's); the quarter keeps it to the
//   slivers, where it saves most fragments.
// The fragment shader discards what either covers beyond the pixels the
// triangle touches (touches_pixel), so coverage is exact.

vec2 screen(vec4 clip) { return (clip.xy / clip.w * 0.5 + 0.5) * vec2(view.width, view.height); }

// Corner i moved out by the pixel's half extent along both of its edges.
vec2 moved_corner(vec2 s[3], float orient, uint i)
{
    vec2 prev = s[i] - s[(i + 2u) % 3u], next = s[(i + 1u) % 3u] - s[i];
    vec2 np = normalize(orient * vec2(prev.y, -prev.x)), nn = normalize(orient * vec2(next.y, -next.x));
    float hp = 0.5 * (abs(np.x) + abs(np.y)), hn = 0.5 * (abs(nn.x) + abs(nn.y));
    float det = np.x * nn.y - np.y * nn.x;
    vec2 d = abs(det) > 1e-4 ? vec2(hp * nn.y - hn * np.y, np.x * hn - nn.x * hp) / det : np * hp;
    if (length(d) > TV_PVS_MAX_DILATION_PX)
        d = normalize(d) * TV_PVS_MAX_DILATION_PX;
    return s[i] + d;
}

// The triangle around the grown bounding rectangle; returns its area.
float rectangle_triangle(vec2 s[3], out vec2 t[3])
{
    uint e = 0u;
    for (uint i = 1u; i < 3u; i++)
        if (length(s[(i + 1u) % 3u] - s[i]) > length(s[(e + 1u) % 3u] - s[e]))
            e = i;
    vec2 a = s[e], u = normalize(s[(e + 1u) % 3u] - a), n = vec2(-u.y, u.x);
    float len = length(s[(e + 1u) % 3u] - a), h = dot(s[(e + 2u) % 3u] - a, n);
    if (h < 0.0) {
        n = -n;
        h = -h;
    }
    // the opposite corner projects inside the longest edge: the rectangle
    // [0, len] x [0, h] holds the triangle; grow it by the square's support
    float mu = 0.5 * (abs(u.x) + abs(u.y)), mn = 0.5 * (abs(n.x) + abs(n.y));
    float w = len + 2.0 * mu, ht = h + 2.0 * mn;
    vec2 base = a - mn * n;
    t[0] = base + (-mu - 0.5 * w) * u;
    t[1] = base + (len + mu + 0.5 * w) * u;
    t[2] = base + 0.5 * len * u + 2.0 * ht * n;
    return 2.0 * w * ht;
}

void main()
{
    uint slot = uint(gl_VertexIndex) / 3u;
    uint corner = uint(gl_VertexIndex) - slot * 3u;
    uint listed = (pc.kind & TV_PVS_KIND_SPILL) != 0u ? spill_list[TV_PVS_SPILL_ENTRY(slot)]
                  : (pc.kind & ~TV_PVS_KIND_WIDE) == TV_PVS_KIND_FRONT ? ff_list[slot] : bf_list[slot];
    uint tri = listed & ~(TV_ID_CULLED | TV_ID_STRADDLED);
    v_triangle = tri;
    v_id_flags = listed & ~tri;
    if ((pc.kind & TV_PVS_KIND_WIDE) != 0u && (listed & TV_ID_CULLED) != 0u) {
        // a culled back has nothing to do in the dilated pass (pvs_face.frag
        // discards all of it): a degenerate triangle, no fragments
        gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
        v_uv = vec2(0.0);
        v_material = 0u;
        v_s01 = vec4(0.0);
        v_s2 = vec3(0.0);
        v_far = v_near = 0.0;
        v_inv_w = vec3(0.0);
        v_see = 0u;
        return;
    }
    vec4 c[3];
    for (uint i = 0u; i < 3u; i++)
        c[i] = view.view_proj * vec4(pvs_corner(tri, i), 1.0);
    vec4 pos = c[corner];
    v_far = max(max(c[0].w, c[1].w), c[2].w);
    v_near = min(min(c[0].w, c[1].w), c[2].w);
    v_s01 = vec4(0.0);
    v_s2 = vec3(0.0);
    v_inv_w = vec3(0.0);
    v_uv = pvs_corner_uv(tri, corner);
    if ((pc.kind & TV_PVS_KIND_WIDE) != 0u && c[0].w > 0.0 && c[1].w > 0.0 && c[2].w > 0.0) {
        vec2 s[3] = vec2[3](screen(c[0]), screen(c[1]), screen(c[2]));
        vec2 a = s[1] - s[0], b = s[2] - s[0];
        float orient = sign(a.x * b.y - a.y * b.x);
        if (orient != 0.0) {
            v_s01 = vec4(s[0], s[1]);
            v_s2 = vec3(s[2], orient);
            vec2 m[3] = vec2[3](moved_corner(s, orient, 0u), moved_corner(s, orient, 1u), moved_corner(s, orient, 2u));
            vec2 t[3];
            float rect = rectangle_triangle(s, t);
            vec3 inv_w = 1.0 / vec3(c[0].w, c[1].w, c[2].w);
            v_inv_w = inv_w;
            bool ahead = dot(bary(s, t[0]), inv_w) > 0.0 && dot(bary(s, t[1]), inv_w) > 0.0 &&
                         dot(bary(s, t[2]), inv_w) > 0.0;
            if (ahead && rect < 0.125 * abs(cross2(m[1] - m[0], m[2] - m[0]))) {
                // the plane's depth and uv at the corner, the depth kept
                // within the triangle's own range like the moved corners'
                // (a grazing plane extrapolated past the triangle comes
                // close to v*, where it would hide what it does not)
                vec3 b = bary(s, t[corner]) * inv_w;
                float w = 1.0 / (b.x + b.y + b.z);
                v_uv = w * (b.x * pvs_corner_uv(tri, 0u) + b.y * pvs_corner_uv(tri, 1u) +
                            b.z * pvs_corner_uv(tri, 2u));
                vec3 z = vec3(c[0].z, c[1].z, c[2].z) * inv_w;
                float ndc_z = clamp(w * dot(b, vec3(c[0].z, c[1].z, c[2].z)), min(min(z.x, z.y), z.z),
                                    max(max(z.x, z.y), z.z));
                w = clamp(w, v_near, v_far);
                pos = vec4((t[corner] / vec2(view.width, view.height) * 2.0 - 1.0) * w, ndc_z * w, w);
            } else {
                pos.xy += (m[corner] - s[corner]) * 2.0 / vec2(view.width, view.height) * pos.w;
            }
        }
    }
    gl_Position = pos;
    v_see = pvs_seethrough(tri) ? 1u : 0u;
    v_material = pvs_material(tri);
}
