#version 460
// P2, scene triangles: alpha mask exactly as the mesh pass, then the front
// or back k-buffer. Both also write the visibility buffer (the pipeline's
// LESS depth test keeps the nearest id), sealed pixels included, so that P4
// sees the nearest triangle of every pixel; culled backs (TV_ID_CULLED),
// which the renderer never shows, only enter the back k-buffer.
// The exact pass also keeps the nearest depth of the front and of the back
// faces covering each pixel centre (centre_depth; P3 reads them as the
// prior faces of a pixel that becomes trimmed, TV_ID_PRIOR). The dilated
// pass (TV_PVS_KIND_WIDE, see pvs_face.vert) writes the wide visibility buffer and, at pixels whose
// centre the undilated triangle does not cover: flags the triangle when all
// of it lies in front of that nearest centre depth, or when its nearest depth
// inside the pixel ties with it (nothing covering the centre hides it, so it
// is visible from v* through part of the pixel: typically a sub-pixel
// triangle the raster missed), and inserts a front as
// a candidate front, which P3 outputs where it is not hidden but never lets
// occlude. The back of a triangle narrower than a pixel becomes a candidate
// back the same way: such a sliver may cover no pixel centre at all, so it is
// in no sequence otherwise (P3 outputs it outside every hidden range;
// pvs_resolve.glsl's walk).
// A see-through triangle (pvs_geometry.glsl) is drawn by the dilated pass
// only, as a candidate front at every pixel it touches, centre covered or
// not, and writes no depth anywhere: no visibility buffer, no centre depth,
// so it hides nothing; it is flagged where the candidate rule above finds
// it in front of the nearest centre depth, and P3 outputs it outside every
// hidden range (docs/trim-regions.md, "See-through triangles and proxies").
#extension GL_GOOGLE_include_directive : require
#include "pvs_geometry.glsl"
#include "pvs_kbuffer.glsl"
// centre_depth's 64-bit slots (TV_PVS_CENTRE_PATCH_LO, _HI; shaderBufferInt64Atomics, render/device.c). Built a
// second time with TV_PVS_NO_INT64 (shaders/CMakeLists.txt) for devices without it: no int64 capability in the
// module, the slots keep their +inf fill, and P3 sees every prior front's patch as unknown (rule off).
#ifndef TV_PVS_NO_INT64
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_CENTRE_DEPTH) coherent buffer pvs_centre64_buf {
    uint64_t centre64[];
};
#endif

layout(location = 0) in vec2 v_uv;
layout(location = 1) flat in uint v_triangle;
layout(location = 2) flat in uint v_material;
layout(location = 3) flat in vec4 v_s01;
layout(location = 4) flat in vec3 v_s2;
layout(location = 5) flat in float v_far;
layout(location = 6) flat in float v_near;
layout(location = 7) flat in uint v_id_flags;
layout(location = 8) flat in uint v_see;
layout(location = 9) flat in vec3 v_inv_w;

layout(location = 0) out uint o_triangle;

// Strictly inside by 1/64 pixel: a centre on an edge counts as not covered,
// so a fragment the exact pass's tie rule dropped is a candidate here (a
// duplicate front is harmless, a lost one is not).
bool covers_centre()
{
    vec2 s[3] = vec2[3](v_s01.xy, v_s01.zw, v_s2.xy);
    vec2 c = gl_FragCoord.xy;
    for (uint i = 0u; i < 3u; i++) {
        vec2 e = s[(i + 1u) % 3u] - s[i], d = c - s[i];
        if (v_s2.z * (e.x * d.y - e.y * d.x) <= length(e) / 64.0)
            return false;
    }
    return true;
}

// Whether the undilated triangle's height over its longest edge is under a
// pixel: it may then cover no pixel centre along its whole length.
bool narrower_than_a_pixel()
{
    vec2 a = v_s01.zw - v_s01.xy, b = v_s2.xy - v_s01.zw, c = v_s01.xy - v_s2.xy;
    return abs(a.x * c.y - a.y * c.x) < max(max(length(a), length(b)), length(c));
}

// Whether the pixel's square meets the undilated triangle (separating axes:
// the square's two, then each edge's normal): the dilated triangle covers
// more than that near its moved corners.
bool touches_pixel()
{
    vec2 s[3] = vec2[3](v_s01.xy, v_s01.zw, v_s2.xy);
    vec2 c = gl_FragCoord.xy;
    vec2 lo = min(min(s[0], s[1]), s[2]), hi = max(max(s[0], s[1]), s[2]);
    if (any(lessThan(c + 0.5, lo)) || any(greaterThan(c - 0.5, hi)))
        return false;
    for (uint i = 0u; i < 3u; i++) {
        vec2 e = s[(i + 1u) % 3u] - s[i], d = c - s[i];
        if (v_s2.z * (e.x * d.y - e.y * d.x) + 0.5 * (abs(e.x) + abs(e.y)) < 0.0)
            return false;
    }
    return true;
}

// The largest 1/w of edge a-b (1/w ia, ib) at a, if a lies in the square
// [lo, hi], and where the edge crosses the square's sides. Written without
// run-time indexed arrays or loops: llvmpipe keeps those in memory.
float edge_inv(vec2 a, vec2 b, float ia, float ib, vec2 lo, vec2 hi)
{
    float inv = all(greaterThanEqual(a, lo)) && all(lessThanEqual(a, hi)) ? ia : 0.0;
    vec2 d = b - a;
    if (d.x != 0.0) { // the sides x = lo.x, x = hi.x
        vec2 t = (vec2(lo.x, hi.x) - a.x) / d.x, o = a.y + t * d.y;
        if (t.x >= 0.0 && t.x <= 1.0 && o.x >= lo.y && o.x <= hi.y)
            inv = max(inv, mix(ia, ib, t.x));
        if (t.y >= 0.0 && t.y <= 1.0 && o.y >= lo.y && o.y <= hi.y)
            inv = max(inv, mix(ia, ib, t.y));
    }
    if (d.y != 0.0) { // the sides y = lo.y, y = hi.y
        vec2 t = (vec2(lo.y, hi.y) - a.y) / d.y, o = a.x + t * d.x;
        if (t.x >= 0.0 && t.x <= 1.0 && o.x >= lo.x && o.x <= hi.x)
            inv = max(inv, mix(ia, ib, t.x));
        if (t.y >= 0.0 && t.y <= 1.0 && o.y >= lo.x && o.y <= hi.x)
            inv = max(inv, mix(ia, ib, t.y));
    }
    return inv;
}

// 1/w at square corner q if the triangle (s0, s1, s2) holds it, else 0.
float corner_inv(vec2 s0, vec2 s1, vec2 s2, vec2 q, float e)
{
    vec2 d0 = s1 - s0, d1 = s2 - s1, d2 = s0 - s2;
    bool in_tri = v_s2.z * cross2(d0, q - s0) >= -e * length(d0) && v_s2.z * cross2(d1, q - s1) >= -e * length(d1) &&
                  v_s2.z * cross2(d2, q - s2) >= -e * length(d2);
    return in_tri ? dot(bary(vec2[3](s0, s1, s2), q), v_inv_w) : 0.0;
}

// The depth a candidate enters at: the nearest depth of the undilated
// triangle's part inside the pixel's square, never nearer than `bound`
// (max(nearest corner, centre depth - half the slope), the nearest the plane
// has anywhere in the square). 1/w is affine in screen space, so over that
// convex part it is largest at one of its corners: a triangle corner in the
// square, a square corner in the triangle, or where an edge crosses a side.
// Nearer only adds output (a candidate never occludes), so the part is
// taken with a slack of 1/256 pixel; if it is found empty, or the triangle
// was not dilated (a see-through one with a corner behind v*), `bound` stands.
float candidate_depth(float bound)
{
    if (v_s2.z == 0.0)
        return bound;
    vec2 s0 = v_s01.xy, s1 = v_s01.zw, s2 = v_s2.xy;
    const float e = 1.0 / 256.0;
    vec2 lo = gl_FragCoord.xy - 0.5 - e, hi = gl_FragCoord.xy + 0.5 + e;
    float inv = max(max(edge_inv(s0, s1, v_inv_w.x, v_inv_w.y, lo, hi), edge_inv(s1, s2, v_inv_w.y, v_inv_w.z, lo, hi)),
                    edge_inv(s2, s0, v_inv_w.z, v_inv_w.x, lo, hi));
    inv = max(inv, max(max(corner_inv(s0, s1, s2, lo, e), corner_inv(s0, s1, s2, vec2(hi.x, lo.y), e)),
                       max(corner_inv(s0, s1, s2, vec2(lo.x, hi.y), e), corner_inv(s0, s1, s2, hi, e))));
    return inv > 0.0 ? max(bound, 1.0 / inv) : bound;
}

// The spill draws after P3 (exact and dilated; P3 requests them, see
// request_spill) at pixels whose front list overflowed in this layer. They
// draw only the triangles that lost a fragment somewhere in P2 (the spill
// list) but cannot tell which of their fragments, so they output what P3 may
// not have: each such front at an overflowed pixel that lost one, and the
// candidates within P3's bound. An untrimmed pixel needs nothing (its
// visibility buffer holds its nearest face; P3 ignores its fronts).
void spill(uint p, float w, float slope)
{
    if (pixcount[p].x <= view.k_lists || pixstate[p].x == TV_STENCIL_UNTRIMMED)
        return;
    if ((pc.kind & TV_PVS_KIND_WIDE) == 0u) {
        if (pixstate[p].x == TV_STENCIL_OVERFLOW && lost[TV_PVS_LOST_STRIDE * p + TV_PVS_LOST_FRONT] != 0x7F800000u)
            pvs_mark(v_triangle, TV_REASON_OVERFLOW);
        return;
    }
    if (v_see == 0u && (v_s2.z == 0.0 || covers_centre()))
        return; // not a candidate: the exact spill draw's
    float depth = candidate_depth(max(v_near, w - 0.5 * slope)); // as P2 pushed it
    float span_lo = uintBitsToFloat(lost[TV_PVS_LOST_STRIDE * p + TV_PVS_LOST_SPAN_LO]);
    float span_hi = uintBitsToFloat(lost[TV_PVS_LOST_STRIDE * p + TV_PVS_LOST_SPAN_HI]);
    if (depth < uintBitsToFloat(lost[TV_PVS_LOST_STRIDE * p + TV_PVS_LOST_CANDIDATE]) && // P3's bound
        !pvs_spill_hidden(span_lo, span_hi, depth)) // and its spill span
        pvs_mark(v_triangle, TV_REASON_OVERFLOW);
}

void main()
{
    // Dilated pass: how far the dilated plane's depth may stray from the
    // exact one at this pixel (derivatives need uniform control flow, so
    // before any discard; pc.kind is uniform).
    float w = pvs_depth(), slope = 0.0;
    if ((pc.kind & TV_PVS_KIND_WIDE) != 0u)
        slope = abs(dFdx(w)) + abs(dFdy(w));
    if ((pc.kind & TV_PVS_KIND_WIDE) != 0u && v_s2.z != 0.0 && !touches_pixel())
        discard;
    bool see = v_see != 0u;
    if (see && (pc.kind & TV_PVS_KIND_WIDE) == 0u)
        discard;
    // the colour (a texture fetch) only for a masked material: llvmpipe
    // evaluates a call's arguments for every fragment
    if (!see && (tv_materials[v_material].flags & TV_MAT_ALPHA_MASK) != 0u &&
        tv_alpha_masked(v_material, tv_material_color(v_material, v_uv).a))
        discard;
    uint p = pvs_pixel();
    if ((v_id_flags & TV_ID_CULLED) != 0u) {
        // A back the renderer culls from the whole viewcell: it only closes
        // the interval its front opened (pvs_resolve.glsl), so the exact pass
        // stores it and keeps it apart as a prior face, and nothing else sees
        // it: no visibility-buffer id (the discard keeps those stores), no
        // candidate (the dilated pass does not draw it, pvs_face.vert).
        w *= 1.0 + TV_PVS_CULLED_NUDGE; // behind a coincident front twin
        uint c = TV_PVS_CENTRE_STRIDE * p;
        atomicMin(centre_depth[c + TV_PVS_CENTRE_CULLED], floatBitsToUint(w));
        if (TV_PVS_PRIOR_CULLED_BEHIND(uintBitsToFloat(centre_depth[c + TV_PVS_CENTRE_FRONT]), w))
            atomicMin(centre_depth[c + TV_PVS_CENTRE_CULLED_BEHIND], floatBitsToUint(w));
        if (!pvs_sealed(p))
            pvs_push(p, TV_PVS_KIND_BACK, w, v_triangle | v_id_flags);
        discard;
    }
    o_triangle = v_triangle;
    if ((pc.kind & TV_PVS_KIND_SPILL) != 0u) {
        spill(p, w, slope);
        if (see)
            discard;
        return;
    }
    uint kind = pc.kind & ~TV_PVS_KIND_WIDE, id = v_triangle | v_id_flags;
    if (kind == pc.kind) {
        atomicMin(centre_depth[TV_PVS_CENTRE_STRIDE * p + (kind == TV_PVS_KIND_BACK ? TV_PVS_CENTRE_BACK : TV_PVS_CENTRE_FRONT)],
                  floatBitsToUint(w));
#ifndef TV_PVS_NO_INT64
        if (kind == TV_PVS_KIND_FRONT) { // the front patches at the nearest depth, exactly under ties and races
            uint64_t d = uint64_t(floatBitsToUint(w)) << 32, l = uint64_t(patch_label[v_triangle]);
            uint c = (TV_PVS_CENTRE_STRIDE * p) / 2u;
            atomicMin(centre64[c + TV_PVS_CENTRE_PATCH_LO / 2u], d | l);
            atomicMin(centre64[c + TV_PVS_CENTRE_PATCH_HI / 2u], d | (l ^ 0xFFFFFFFFul));
        }
#endif
    } else { // the dilated pass, after the exact one
        uint c = TV_PVS_CENTRE_STRIDE * p;
        float nearest = uintBitsToFloat(min(centre_depth[c + TV_PVS_CENTRE_FRONT], centre_depth[c + TV_PVS_CENTRE_BACK]));
        // Not dilated (a corner behind v*, or edge-on): rasterised exactly,
        // so every fragment covers its centre and only the tie rule applies.
        // Skipping it lost a floor crossing the near plane that z-fights
        // with its coincident reverse-wound twin.
        if (!see && (v_s2.z == 0.0 || covers_centre())) {
            // Tied in depth with the nearest face at this centre (coplanar
            // faces): the depth test kept one, but an eye's raster may show
            // either (z-fighting), so both are visible from v*.
            if (w <= nearest + slope * TV_PVS_TIE_SLOPES)
                pvs_mark(v_triangle, TV_REASON_TIE);
            return;
        }
        // Visible from v* through part of the pixel: in front of everything
        // covering the centre, or nowhere in the pixel behind the face
        // covering the centre by more than the tie rule's depth error (a
        // sub-pixel triangle of the same finely tessellated surface, or of a
        // surface just behind it: an eye's pixel centre may land on it).
        float inside = max(v_near, w - 0.5 * slope); // its nearest depth in the pixel
        if (v_far < nearest || inside <= nearest + slope * TV_PVS_TIE_SLOPES)
            pvs_mark(v_triangle, TV_REASON_PARTIAL);
        if (kind == TV_PVS_KIND_BACK && !narrower_than_a_pixel())
            return; // a wider back covers pixel centres, where it is in the sequence
        // A candidate stands for the part of the triangle inside the pixel,
        // which may be nearer than its plane at the centre: it enters the
        // sequence at the nearest depth it can have there, so that a face
        // covering the centre does not hide it by comparing centre depths
        // (it never occludes, so nearer only means more output). spill()
        // repeats this.
        w = candidate_depth(inside);
        id |= TV_ID_CANDIDATE;
    }
    if (pvs_sealed(p)) { // a face of a later layer in front of the terminator (pvs_sealed_output)
        if (pvs_sealed_output(p, w))
            pvs_mark(v_triangle, TV_REASON_SEALED);
    } else if (!pvs_push(p, kind, w, id) && kind == TV_PVS_KIND_FRONT) {
        // overflow policy: left to the spill draws after P3, which draw
        // only the triangles listed here (once per layer: the stamp)
        atomicAdd(counters[TV_PVS_C_OVERFLOW_FRONTS], 1u);
        if (atomicExchange(spill_list[TV_PVS_SPILL_STAMP(v_triangle)], pc.layer + 1u) != pc.layer + 1u)
            spill_list[TV_PVS_SPILL_ENTRY(atomicAdd(spill_list[0], 1u))] = id & ~TV_ID_CANDIDATE; // as FF lists it
    }
    if (see)
        discard; // no depth, no visibility-buffer id (the stores above stay)
}
