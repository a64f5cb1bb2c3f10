// pvs_trim.glsl - the trim quad and umbra quad of one silhouette edge: the
// GLSL twin of pvs_trim_width_px (pvs/trim_width.c), pvs_umbra_far_depth,
// pvs_umbra_corner_depth and pvs_umbra_quad_make (pvs/umbra.c) and
// pvs_depth_bound_query (pvs/depth_bound.c), in normalised image units
// (focal length 1), plus what the C references leave to P1: clipping the
// edge at the near plane and clamping infinite widths.
#ifndef TV_PVS_TRIM_GLSL
#define TV_PVS_TRIM_GLSL

#include "pvs_common.glsl"

float pvs_view_depth(vec3 p) { return dot(p - view.apex.xyz, view.forward.xyz); }

vec2 pvs_image(vec3 p, float depth)
{
    vec3 d = p - view.apex.xyz;
    return vec2(dot(d, view.right.xyz), dot(d, view.up.xyz)) / depth;
}

vec3 pvs_unproject(vec2 image, float depth)
{
    return view.apex.xyz + depth * (view.forward.xyz + image.x * view.right.xyz + image.y * view.up.xyz);
}

// The C reference's cone_max (pvs/trim_width.c): (far - d) / far times the
// larger of (Δ + z s) / (d - z) and 2 z s / (d - 2z), s = -sigma_n for the
// inward width, |sigma| for the reach in any direction.
float pvs_cone_max(float depth, float s, float far)
{
    float z = view.delta / view.tan_alpha;
    float base = (view.delta + z * s) / (depth - z), tip = 2.0 * z * s / (depth - 2.0 * z);
    return max(0.0, max(base, tip)) * (far - depth) / far;
}

// Inward extrusion of a silhouette point at `depth` with outward image
// coordinate sigma, when nothing behind it lies beyond `far`; one pixel is
// added for the pixel-centre sampling of the edge itself, and the infinite
// widths near v* are clamped to the image.
float pvs_trim_width(float depth, float sigma, float far)
{
    if (depth <= 2.0 * view.delta / view.tan_alpha)
        return view.max_width;
    if (depth >= far)
        return 1.0 / view.focal_px;
    return min(pvs_cone_max(depth, -sigma, far) + 1.0 / view.focal_px, view.max_width);
}

uvec2 pvs_depth_cell(vec2 px, uvec2 cells)
{
    return uvec2(clamp(floor(px / float(TV_PVS_DEPTH_CELL_PX)), vec2(0.0), vec2(cells - 1u)));
}

// pvs_depth_bound_query (pvs/depth_bound.c) over pixel rectangle [lo, hi].
float pvs_depth_bound_query(vec2 lo, vec2 hi)
{
    uvec2 dims = (uvec2(view.width, view.height) + TV_PVS_DEPTH_CELL_PX - 1u) / TV_PVS_DEPTH_CELL_PX;
    uvec2 c0 = pvs_depth_cell(lo, dims), c1 = pvs_depth_cell(hi, dims);
    uint offset = 0u;
    while (c1.x - c0.x > 1u || c1.y - c0.y > 1u) {
        offset += dims.x * dims.y;
        dims = (dims + 1u) / 2u;
        c0 >>= 1u;
        c1 >>= 1u;
    }
    float m = 0.0;
    for (uint y = c0.y; y <= c1.y; y++) {
        for (uint x = c0.x; x <= c1.x; x++)
            m = max(m, view.depth_bound[offset + y * dims.x + x]);
    }
    return m;
}

// pvs_umbra_far_depth (pvs/umbra.c): the depth bound over the edge's image
// widened by the reach of what the viewcell sees past it up to the far
// plane, which replaces the far plane in the widths (docs/trim-width.md).
float pvs_footprint_far(vec2 i0, vec2 i1, float d0, float d1)
{
    float dmin = min(d0, d1);
    if (dmin <= 2.0 * view.delta / view.tan_alpha || dmin >= view.far_dist)
        return view.far_dist; // no finite reach, or no width to narrow
    float reach = view.focal_px * pvs_cone_max(dmin, max(length(i0), length(i1)), view.far_dist) + 1.0;
    vec2 centre = 0.5 * vec2(view.width, view.height);
    vec2 lo = centre + min(i0, i1) * view.focal_px - reach, hi = centre + max(i0, i1) * view.focal_px + reach;
    return pvs_depth_bound_query(lo, hi);
}

// pvs_umbra_corner_depth (pvs/umbra.c): where the line from a vertex at
// `depth` to the far-plane point `far_width` inwards meets the ray `width`
// inwards, so that the umbra is the far-plane one cut to the trim's footprint.
float pvs_umbra_depth(float depth, float width, float far_width)
{
    if (depth >= view.far_dist)
        return view.far_dist;
    float a = far_width * view.far_dist / (view.far_dist - depth);
    return clamp(a * depth / (a - width), depth, view.far_dist);
}

// Depth at which the v* ray through `image` meets the plane (n, p), or
// `fallback` when it meets it behind the near plane or not at all.
float pvs_plane_depth(vec2 image, vec3 n, vec3 p, float fallback)
{
    vec3 r = view.forward.xyz + image.x * view.right.xyz + image.y * view.up.xyz;
    float den = dot(n, r);
    float t = den != 0.0 ? dot(n, p - view.apex.xyz) / den : -1.0;
    return t > view.near_dist && !isinf(t) ? t : fallback;
}

// Depths of a trim corner: the trim fragments must lie in [f, b] of the
// intervals they validate, and near the edge the solid lies between the
// planes of its front triangle (nf, pf) and back neighbour (nb, pb). x: the
// midpoint of the two ray/plane depths (inside a thick or curved solid); y
// and z: the nearer and the farther of the two (a face's plane where that
// face goes on past the trim's corner: a thin wall's front, where the
// midpoint lies behind the back face, or a slab's back face where its side
// is the front triangle seen almost edge-on and both the midpoint and the
// side's plane lie in front of the slab); y = z = 0 when there is no back
// neighbour. A border or non-manifold edge has only its own triangle's
// plane: the trim then ties with the front, and ties sort fronts first
// (docs/trim-regions.md, "Umbra quad and trim quad").
vec3 pvs_trim_depth(vec2 image, float edge_depth, vec3 nf, vec3 pf, bool has_back, vec3 nb, vec3 pb)
{
    float f = pvs_plane_depth(image, nf, pf, edge_depth);
    if (!has_back)
        return vec3(f, 0.0, 0.0);
    float b = pvs_plane_depth(image, nb, pb, edge_depth);
    return vec3(0.5 * (f + b), min(f, b), max(f, b));
}

// Writes e0, e1 (clipped to the near plane), the trim corners behind the
// extruded e1 and e0 (at the midpoint depth; `near` and `far` hold their
// nearer and farther plane depths, pvs_trim_depth; far is 0, no draw,
// unless the front triangle is seen grazing), and the umbra's far corners
// behind them. `inside` is
// the third vertex of the occluder-side triangle (its plane: nf through e0);
// nb, pb the back neighbour's plane when has_back. Returns false when the
// edge lies behind the near plane, projects to a point, or its occluder
// side cannot be told (the triangle is seen edge-on).
bool pvs_trim_quad(vec3 e0, vec3 e1, vec3 inside, bool has_back, vec3 nb, vec3 pb, out vec3 c[6], out vec2 near, out vec2 far)
{
    vec3 nf = cross(e1 - e0, inside - e0), pf = e0;
    float nearc = view.near_dist;
    float d0 = pvs_view_depth(e0), d1 = pvs_view_depth(e1);
    if (d0 <= nearc && d1 <= nearc)
        return false;
    if (d0 <= nearc) {
        e0 += (nearc - d0) / (d1 - d0) * (e1 - e0);
        d0 = nearc;
    } else if (d1 <= nearc) {
        e1 += (nearc - d1) / (d0 - d1) * (e0 - e1);
        d1 = nearc;
    }
    // Any point of the triangle between the edge and `inside` projects to
    // the occluder side: pull `inside` in front of the near plane if needed.
    vec3 mid = 0.5 * (e0 + e1);
    float dm = pvs_view_depth(mid), dq = pvs_view_depth(inside);
    if (dq <= nearc)
        inside = mid + (0.5 * (dm - nearc) / (dm - dq)) * (inside - mid);
    vec2 i0 = pvs_image(e0, d0), i1 = pvs_image(e1, d1);
    vec2 iq = pvs_image(inside, pvs_view_depth(inside));
    vec2 t = i1 - i0;
    float len = length(t);
    if (len == 0.0)
        return false;
    vec2 n = vec2(-t.y, t.x) / len;
    float side = dot(n, iq - i0);
    if (side == 0.0)
        return false;
    if (side > 0.0)
        n = -n; // n points away from the occluder
    float behind = pvs_footprint_far(i0, i1, d0, d1);
    vec2 wf = vec2(pvs_trim_width(d0, dot(i0, n), view.far_dist), pvs_trim_width(d1, dot(i1, n), view.far_dist));
    // A narrowed width keeps TV_PVS_TRIM_SLACK_PX more, never beyond the far-plane one.
    vec2 w = min(wf, vec2(pvs_trim_width(d0, dot(i0, n), behind), pvs_trim_width(d1, dot(i1, n), behind)) +
                         TV_PVS_TRIM_SLACK_PX / view.focal_px);
    vec2 x0 = i0 - w.x * n, x1 = i1 - w.y * n;
    c[0] = e0;
    c[1] = e1;
    vec3 t1 = pvs_trim_depth(x1, d1, nf, pf, has_back, nb, pb), t0 = pvs_trim_depth(x0, d0, nf, pf, has_back, nb, pb);
    c[2] = pvs_unproject(x1, t1.x);
    c[3] = pvs_unproject(x0, t0.x);
    near = vec2(t1.y, t0.y);
    // The farther plane only where v* sees the front triangle at a grazing
    // angle (the slab's side), so that its plane misleads: elsewhere that
    // draw cost the OpenArena levels 10-37 % more PVS for no FN gain.
    vec3 view_ray = normalize(0.5 * (e0 + e1) - view.apex.xyz);
    bool grazing = abs(dot(normalize(nf), view_ray)) < TV_PVS_GRAZING_COS;
    far = grazing ? vec2(t1.z, t0.z) : vec2(0.0);
    c[4] = pvs_unproject(x1, pvs_umbra_depth(d1, w.y, wf.y));
    c[5] = pvs_unproject(x0, pvs_umbra_depth(d0, w.x, wf.x));
    return true;
}

#endif
