#version 460
// P1: one invocation per triangle of the layer. Classifies the triangle as
// front- or back-facing from v* (plane test, as pvs/silhouette.c), for the FF
// or BF draw list (a back the renderer culls from the whole viewcell flagged
// TV_ID_CULLED) unless its clip-space outcodes put it outside one frustum
// plane, and emits a silhouette record (trim quad + umbra quad) for every
// silhouette edge it owns: border and non-manifold edges always, an edge to
// an opposite-facing neighbour when this triangle is the front-facing one. A
// see-through triangle (a proxy's face, an SCN_ALPHA_BLEND one) goes to the
// FF list whichever way it faces and has no silhouette: it never occludes
// (pvs_face.frag). Nothing is appended here: the triangle's class word and
// its records (in its own slots 3 i + e) wait for pvs_order.comp, which
// lists them in layer order, so that the draws' primitive order and the
// trim-region ids are the same in every run (an append with atomics follows
// the threads' timing, and with it which fronts fill a k-buffer and how
// P3's sort ties break). Each workgroup's entries are counted; the last
// invocation to finish turns the counts into offsets (scan).
#extension GL_GOOGLE_include_directive : require
#include "pvs_geometry.glsl"
#include "pvs_trim.glsl"

layout(local_size_x = TV_WG_SIZE) in;

vec3 corner_position(uint tri, uint c) { return pvs_corner(tri, c); }

// > 0: v* in front of the triangle's plane, < 0 behind, 0 on it or degenerate.
float facing(uint tri)
{
    vec3 a = corner_position(tri, 0u), b = corner_position(tri, 1u), c = corner_position(tri, 2u);
    return dot(cross(b - a, c - a), view.apex.xyz - a);
}

bool front_facing(uint tri) { return facing(tri) > 0.0; }

// How far the double cone reaches in front of the plane of the triangle with
// corners p (positive: some eye of the viewcell sees its front), in metres:
// the cone's support along the normal, the base disc of radius delta through
// v0 and the apexes v0 -+ z forward (z = delta / tan alpha).
float front_reach(vec3 p[3])
{
    vec3 n = normalize(cross(p[1] - p[0], p[2] - p[0])), f = view.forward.xyz;
    float z = view.delta / view.tan_alpha, nf = dot(n, f);
    vec3 v0 = view.apex.xyz + z * f;
    return dot(n, v0 - p[0]) + max(z * abs(nf), view.delta * length(n - nf * f));
}

uint outcode(vec4 clip)
{
    uint code = 0u;
    code |= clip.x < -clip.w ? 1u : 0u;
    code |= clip.x > clip.w ? 2u : 0u;
    code |= clip.y < -clip.w ? 4u : 0u;
    code |= clip.y > clip.w ? 8u : 0u;
    code |= clip.z < 0.0 ? 16u : 0u;
    code |= clip.z > clip.w ? 32u : 0u;
    return code;
}

// other: the triangle across the edge, or >= TV_ADJ_CRACK (a border, crack
// or non-manifold edge), or a rest edge (TV_ADJ_REST), drawn as a border. Writes record `slot` (its region id is
// pvs_order.comp's); false when the edge has no trim quad.
bool emit_silhouette(uint slot, vec3 e0, vec3 e1, vec3 inside, uint other)
{
    bool has_back = other < TV_ADJ_REST;
    vec3 nb = vec3(0.0), pb = vec3(0.0);
    if (has_back) {
        pb = corner_position(other, 0u);
        nb = cross(corner_position(other, 1u) - pb, corner_position(other, 2u) - pb);
    }
    vec3 c[6];
    vec2 near, far;
    if (!pvs_trim_quad(e0, e1, inside, has_back, nb, pb, c, near, far))
        return false;
    uint base = slot * TV_PVS_SIL_VEC4;
    sil[base] = vec4(c[0], 0.0);
    for (uint i = 1u; i < TV_PVS_SIL_VEC4; i++)
        sil[base + i] = vec4(c[i], i == 2u ? near.x : i == 3u ? near.y : i == 4u ? far.x : far.y);
    return true;
}

// Layer triangle i's class word (TV_PVS_CLASS_*), its records written.
uint classify(uint i)
{
    uint tri = layer_tris[pc.layer_offset + i];
    vec3 p[3] = vec3[3](corner_position(tri, 0u), corner_position(tri, 1u), corner_position(tri, 2u));
    uint codes = outcode(view.view_proj * vec4(p[0], 1.0)) & outcode(view.view_proj * vec4(p[1], 1.0)) &
                 outcode(view.view_proj * vec4(p[2], 1.0));
    if (pvs_seethrough(tri))
        return codes == 0u ? TV_PVS_CLASS_FF : 0u;
    float side = facing(tri);
    bool front = side > 0.0;
    uint word = 0u;
    if (codes == 0u) {
        // A single-sided back wholly behind the viewcell (short of its plane
        // by more than rounding) the renderer culls from every eye; a back
        // whose plane the viewcell straddles shows its front to some eyes.
        float reach = front ? 0.0 : front_reach(p);
        bool culled = !front && reach < -1e-4 &&
                      (tv_materials[tv_tri_material[tri]].flags & TV_MAT_DOUBLE_SIDED) == 0u;
        word = front ? TV_PVS_CLASS_FF
                     : TV_PVS_CLASS_BF | (culled ? TV_PVS_CLASS_CULLED : 0u) | (reach > 0.0 ? TV_PVS_CLASS_STRADDLED : 0u);
    }
    // Silhouettes of triangles outside the frustum are still emitted (unless
    // behind the near or beyond the far plane): their trim quads extend
    // inwards and may reach into the image.
    if ((codes & 48u) != 0u)
        return word;
    for (uint e = 0u; e < 3u; e++) {
        uint other = adjacency[3u * tri + e];
        bool silhouette;
        if (other >= TV_ADJ_CRACK) {
            silhouette = true;
        } else if (other >= TV_ADJ_REST) {
            // no edge of the face rested on names it: this triangle does, both ways
            float f = facing(other & ~TV_ADJ_REST);
            silhouette = !((side > 0.0 && f > 0.0) || (side < 0.0 && f < 0.0));
        } else {
            silhouette = front && !front_facing(other);
        }
        if (silhouette && emit_silhouette(3u * i + e, p[e], p[(e + 1u) % 3u], p[(e + 2u) % 3u], other))
            word |= TV_PVS_CLASS_EDGE(e) | (other == TV_ADJ_CRACK ? TV_PVS_CLASS_CRACK(e) : 0u);
    }
    return word;
}

uint group_slot(uint g) { return TV_PVS_ORDER_GROUP(view.list_capacity, g); }

// By the invocation that finishes last, whichever: every workgroup's counts
// become exclusive offsets and the layer's first region id (region ids: the
// running count over the tile's layers in layer order, as the append
// numbered them before, so a later layer's regions still sort after an
// earlier layer's at equal depth and kind); the totals become the draws'
// vertex counts. Serially: a layer has a few thousand workgroups at most.
void scan()
{
    uint first_region = counters[TV_PVS_C_REGIONS];
    uvec3 off = uvec3(0u);
    for (uint g = 0u; g < gl_NumWorkGroups.x; g++) {
        uint s = group_slot(g);
        uvec3 c = uvec3(p1_order[s], p1_order[s + 1u], p1_order[s + 2u]);
        p1_order[s] = off.x;
        p1_order[s + 1u] = off.y;
        p1_order[s + 2u] = off.z;
        p1_order[s + 3u] = first_region + off.z;
        off += c;
    }
    counters[TV_PVS_C_DRAW_FF] = 3u * off.x;
    counters[TV_PVS_C_DRAW_BF] = 3u * off.y;
    counters[TV_PVS_C_DRAW_TRIM] = 6u * off.z;
    counters[TV_PVS_C_REGIONS] = first_region + off.z;
    counters[TV_PVS_C_P1_DONE] = 0u; // for the next layer
}

// No barrier and no shared memory, as before the ordering (a version that
// counted in shared memory behind a barrier was no faster on llvmpipe,
// docs/journal/2026-12-02-repeatable.md). The group counts are atomic sums
// (cleared before each layer), so their order is free.
void main()
{
    uint i = gl_GlobalInvocationID.x;
    if (i >= pc.layer_count)
        return;
    uint word = classify(i), s = group_slot(gl_WorkGroupID.x);
    p1_order[TV_PVS_ORDER_CLASS(view.list_capacity, i)] = word;
    if ((word & TV_PVS_CLASS_FF) != 0u)
        atomicAdd(p1_order[s], 1u);
    if ((word & TV_PVS_CLASS_BF) != 0u)
        atomicAdd(p1_order[s + 1u], 1u);
    uint records = bitCount(word & (TV_PVS_CLASS_EDGE(0u) | TV_PVS_CLASS_EDGE(1u) | TV_PVS_CLASS_EDGE(2u)));
    if (records != 0u)
        atomicAdd(p1_order[s + 2u], records);
    memoryBarrierBuffer(); // the counts before this invocation counts as done
    if (atomicAdd(counters[TV_PVS_C_P1_DONE], 1u) == pc.layer_count - 1u) {
        memoryBarrierBuffer(); // every invocation's counts, seen through its atomicAdd
        scan();
    }
}
