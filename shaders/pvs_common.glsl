// pvs_common.glsl - the descriptor set, view block and push constants every
// trim-region PVS pass shares (pvs/gpu_internal.h mirrors the layouts).
#ifndef TV_PVS_COMMON_GLSL
#define TV_PVS_COMMON_GLSL

#include "mesh_shared.h"
#include "pvs_shared.h"

// Vertex shaders define PVS_RW as readonly before including this file: the
// device enables fragment but not vertex-stage stores.
#ifndef PVS_RW
#define PVS_RW
#define TV_PVS_WRITES
#endif

layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_VIEW) readonly buffer pvs_view_buf {
    mat4 view_proj;
    vec4 apex, forward, right, up;
    float tan_half_x, tan_half_y, tan_alpha, far_dist;
    float near_dist, delta, focal_px, max_width;
    uint width, height, k, triangle_count; // width, height: the whole image
    uint tile_x, tile_y, tile_w, tile_h;    // the tile being computed (pvs/tiles.h): per-pixel buffers index it
    uint explain, kb_holes, list_capacity, k_exact; // explain: tri_flags collect TV_REASON_* bits (pvs_desc.explain); kb_holes: pvs_kbuffer.glsl; list_capacity: TV_PVS_BIND_ORDER's cap; k: slots stored per list, k_exact: pvs_desc.k (a longer list: a deep pixel)
    uint k_lists, k_regions, view_pad0, view_pad1; // entries the front and back lists hold (k_deep), the region list (k_regions)
    float depth_bound[];                    // pvs/depth_bound.h's cells, all levels (pvs_trim.glsl)
} view;

// pvs_desc.kbuffer_layout: the only difference between the layouts is how
// page j of a pixel's list is found. PAGED: through the list's head and the
// pages' links (pvs_kbuffer.glsl, pvs_follow). FLAT: page j of list l of
// pixel p is kb_flat_page(p, l) + j, every list holding k slots; no
// allocation, no heads or links. The front and back lists' pages are in
// kpool, the region list's (trim and umbra lists) in kregions: each buffer
// then takes half of the four lists, so that k = 32 fits one tile of
// 512x512 under lavapipe's maxStorageBufferRange (docs/journal/2026-12-03-ovf30.md).
layout(constant_id = TV_PVS_SPEC_KB_PAGED) const bool KB_PAGED = true;

// Page + 1 (as heads and links hold pages) of the first page of list `list`
// of pixel p in the FLAT layout, in kpool (lists 0, 1) or kregions (2, 3):
// each list in a region of its own, pixel by pixel, as the four buffers
// before the pool had it (a pixel's four lists side by side made P2 some
// 10 % slower on llvmpipe).
uint kb_flat_page(uint p, uint list)
{
    return ((list & 1u) * view.tile_w * view.tile_h + p) * ((view.k + TV_PVS_PAGE - 1u) / TV_PVS_PAGE) + 1u;
}

// Entries each list holds before it overflows: front, back, region list, and
// the umbra list's slot count (its lost-page mark only).
uvec4 kb_capacity() { return uvec4(view.k_lists, view.k_lists, view.k_regions, view.k); }

layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_ADJ) readonly buffer pvs_adj_buf { uint adjacency[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_LAYER_TRIS) readonly buffer pvs_layer_buf { uint layer_tris[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_FF) PVS_RW buffer pvs_ff_buf { uint ff_list[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_BF) PVS_RW buffer pvs_bf_buf { uint bf_list[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_SIL) PVS_RW buffer pvs_sil_buf { vec4 sil[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_COUNTERS) PVS_RW coherent buffer pvs_counter_buf { uint counters[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_KPOOL) PVS_RW buffer pvs_kpool_buf { uvec2 kpool[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_KREGIONS) PVS_RW buffer pvs_kregions_buf { uvec2 kregions[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_KHEADS) PVS_RW coherent buffer pvs_kheads_buf { uint kheads[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_KLINKS) PVS_RW coherent buffer pvs_klinks_buf { uint klinks[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_KALLOC) PVS_RW coherent buffer pvs_kalloc_buf { uint kalloc[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_PIXCOUNT) PVS_RW coherent buffer pvs_pixcount_buf { uvec4 pixcount[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_PIXSTATE) PVS_RW buffer pvs_pixstate_buf { uvec4 pixstate[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_CARRY) PVS_RW buffer pvs_carry_buf { uvec4 carry_buf[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_ACTIVE) PVS_RW coherent buffer pvs_active_buf { uint active_flag[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_ACTIVE_LIST) PVS_RW buffer pvs_active_list_buf { uint active_list[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_TRI_FLAGS) PVS_RW buffer pvs_flags_buf { uint tri_flags[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_LAYER_STATS) PVS_RW buffer pvs_layer_stats_buf { uvec4 layer_stats[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_CENTRE_DEPTH) PVS_RW coherent buffer pvs_centre_buf { uint centre_depth[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_LOST) PVS_RW coherent buffer pvs_lost_buf { uint lost[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_COOP_LIST) PVS_RW buffer pvs_coop_list_buf { uint coop_list[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_SPILL) PVS_RW coherent buffer pvs_spill_buf { uint spill_list[]; };
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_ORDER) PVS_RW coherent buffer pvs_order_buf { uint p1_order[]; };
// Front-patch labels (pvs/patches.h): triangles' from the CPU per view, then regions' from P1 (pvs_order.comp)
layout(std430, set = TV_PVS_SET, binding = TV_PVS_BIND_PATCH) PVS_RW buffer pvs_patch_buf { uint patch_label[]; };
uint patch_drawn() { return uint(patch_label.length()) / 4u; } // drawn labels, then 3 drawn region labels

layout(push_constant) uniform pvs_push_block {
    uint layer_offset;
    uint layer_count;
    uint layer;
    uint kind;
} pc;

// llvmpipe (lavapipe) counts the back-edges of every loop an invocation of
// a shader runs (one SIMD group: 8 lanes at 256 bits) against one budget of
// 65535 (LP_MAX_TGSI_LOOP_ITERATIONS) and, once it is spent, ends every loop
// after the iteration it is in, silently, and its lanes' results are wrong:
// P3's validate, cubic in the sequence until regions_build, spent it at long
// sequences (docs/journal/2026-12-03-k64.md). This loop of view.k + 1 >= 2
// iterations runs one when the budget is spent; other devices have none.
bool loop_budget_spent()
{
    uint trips = 0u;
    for (uint j = 0u; j <= view.k; j++)
        trips++;
    return trips != view.k + 1u;
}

// pvs_umbra_pack, pvs_umbra_centre, pvs_umbra_footprint (pvs/kbuffer.c): a
// region's umbra depth with its footprint's fraction in the low byte.
float pvs_umbra_centre(float packed) { return uintBitsToFloat(floatBitsToUint(packed) & ~0xFFu); }

float pvs_umbra_footprint(float packed)
{
    uint code = floatBitsToUint(packed) & 0xFFu;
    float centre = pvs_umbra_centre(packed);
    return code == 0u ? centre : centre * float(code - 1u) * (1.0 / 256.0);
}

float pvs_umbra_pack(float centre, float footprint)
{
    if (!(centre > 0.0) || isinf(centre))
        return centre;
    uint b = floatBitsToUint(centre) & ~0xFFu;
    float c = uintBitsToFloat(b);
    if (footprint >= c)
        return c;
    float q = clamp(floor(footprint / c * 256.0), 0.0, 254.0);
    if (q > 0.0 && c * q * (1.0 / 256.0) > footprint)
        q -= 1.0;
    if (q < 254.0 && c * (q + 1.0) * (1.0 / 256.0) <= footprint)
        q += 1.0;
    return uintBitsToFloat(b | (uint(q) + 1u));
}

// Whether a region fragment makes its pixel active (P2; pvs_region_activates
// of resolve.h): a trimmed pixel that carries nothing, or one in overflow
// state, resolves to nothing from trims alone (no interval, no carry, its
// state written back as it was), so its region entries are read only where
// a face of the layer activates it (pvs_push). P3 counts the resolves it
// would have wasted (TV_PVS_C_IDLE, pvs_stats.idle_resolves: 0).
bool pvs_region_activates(uvec4 st)
{
    return st.x == TV_STENCIL_UNTRIMMED || (st.x == TV_STENCIL_TRIMMED && st.y != 0u);
}

// pvs_spill_hidden (pvs/resolve.h): a candidate strictly inside the spill span [lo, hi] is hidden, lost or stored.
bool pvs_spill_hidden(float lo, float hi, float depth) { return lo < depth && depth < hi; }

#ifdef TV_PVS_WRITES
// Puts triangle `id` in the PVS. In explain mode (pvs_desc.explain) its flag
// collects the TV_REASON_* bit of every rule that output it; otherwise a plain
// store, so the normal path pays one uniform branch.
void pvs_mark(uint id, uint reason)
{
    if (view.explain != 0u)
        atomicOr(tri_flags[id], reason);
    else
        tri_flags[id] = 1u;
}
#endif

#endif
