// pvs_layout.glsl - descriptor bindings and counter slots of the trim-region
// PVS passes (pvs/gpu_*.c and shaders/pvs_*). Only #define lines: the C side
// includes this file too, so the two can never disagree.
#ifndef TV_PVS_LAYOUT_GLSL
#define TV_PVS_LAYOUT_GLSL

// Set 0 is the scene set (TV_SET_SCENE); the PVS passes bind theirs as set 1.
#define TV_PVS_SET 1

#define TV_PVS_BIND_VIEW       0  // pvs_view_gpu: matrices and frustum of v*
#define TV_PVS_BIND_ADJ        1  // uint[3] per triangle: neighbour across each edge
#define TV_PVS_BIND_LAYER_TRIS 2  // the triangle ids of every layer, back to back
#define TV_PVS_BIND_FF         3  // P1 -> P2: front-facing triangle ids of the layer
#define TV_PVS_BIND_BF         4  // P1 -> P2: back-facing triangle ids of the layer
#define TV_PVS_BIND_SIL        5  // P1 -> P2: TV_PVS_SIL_VEC4 vec4 per silhouette edge
#define TV_PVS_BIND_COUNTERS   6  // indirect commands and counters (TV_PVS_C_*)
#define TV_PVS_BIND_KFRONT     7  // k-buffer: uvec2 (depth bits, triangle) per slot
#define TV_PVS_BIND_KBACK      8  // k-buffer: depth bits per slot
#define TV_PVS_BIND_KTRIM      9  // k-buffer: uvec2 (depth bits, region) per slot
#define TV_PVS_BIND_KUMBRA     10 // k-buffer: uvec2 (depth bits, region) per slot
#define TV_PVS_BIND_PIXCOUNT   11 // uvec4 per pixel: front, back, trim, umbra counters
#define TV_PVS_BIND_PIXSTATE   12 // uvec4 per pixel: stencil, carry count (sealed: terminator depth bits), hide begin/end bits
#define TV_PVS_BIND_CARRY      13 // uvec4 (depth bits, kind, id, 0) x TV_K_CARRY per pixel
#define TV_PVS_BIND_ACTIVE     14 // uint per pixel: active pixel stencil
#define TV_PVS_BIND_ACTIVE_LIST 15 // pixel indices activated in this layer
#define TV_PVS_BIND_TRI_FLAGS  16 // uint per triangle: 1 = in the PVS
#define TV_PVS_BIND_VIS_IDS    17 // r32ui storage image: the visibility buffer's ids
#define TV_PVS_BIND_LAYER_STATS 18 // TV_PVS_LAYER_STATS_STRIDE uvec4 per layer: P3's (bytes stored, active pixels, sequence sum, overflows), P1's (vertex counts of the FF, BF and trim draws, 0)
#define TV_PVS_LAYER_STATS_STRIDE 2
#define TV_PVS_BIND_VIS_WIDE   19 // r32ui storage image: ids of the dilated pass
#define TV_PVS_BIND_CENTRE_DEPTH 20 // TV_PVS_CENTRE_STRIDE uints per pixel: nearest depth bits of the faces covering its centre
#define TV_PVS_CENTRE_FRONT   0u // slots of a pixel's TV_PVS_BIND_CENTRE_DEPTH entry (P2's exact pass, atomicMin)
#define TV_PVS_CENTRE_BACK    1u
#define TV_PVS_CENTRE_CULLED  2u // culled backs (TV_ID_CULLED): they close intervals only
#define TV_PVS_CENTRE_STRIDE  3u
#define TV_PVS_BIND_LOST       21 // TV_PVS_LOST_STRIDE uints per pixel, depth bits: the nearest lost front, lost candidate (P3 replaces it by the candidate spill bound), lost trim
#define TV_PVS_LOST_FRONT     0u // slots of a pixel's TV_PVS_BIND_LOST entry: what the layer's k-buffer had no room for (P2, atomicMin)
#define TV_PVS_LOST_CANDIDATE 1u
#define TV_PVS_LOST_TRIM      2u
#define TV_PVS_LOST_STRIDE    3u
#define TV_PVS_BIND_COOP_LIST  22 // P3: pixels whose sequence the cooperative pass sorts (pvs_resolve_group.comp)
#define TV_PVS_BINDINGS        23

// vec4s per silhouette record: e0 (w = region id bits), e1, trim corner
// behind e1, trim corner behind e0 (w: their nearer plane depths), umbra
// far corner behind e1, behind e0 (w: the trim corners' farther plane
// depths; pvs_trim_depth).
#define TV_PVS_SIL_VEC4 6

// Slots of the counters buffer (uints). Four VkDrawIndirectCommand (FF, BF,
// trim, umbra; vertexCount is bumped by P1 per primitive), one
// VkDispatchIndirectCommand for P3, the active count, the two spill draws
// (the FF draw again after P3, exact and dilated; P3 copies FF's vertexCount
// into them when a pixel needs them), the VkDispatchIndirectCommand of P3's
// cooperative pass (groups = min(deferred pixels, TV_PVS_MAX_COOP_GROUPS))
// and the deferred pixel count, then counters that live for a whole
// pvs_compute.
#define TV_PVS_C_DRAW_FF    0
#define TV_PVS_C_DRAW_BF    4
#define TV_PVS_C_DRAW_TRIM  8
#define TV_PVS_C_DRAW_UMBRA 12
#define TV_PVS_C_DISPATCH   16
#define TV_PVS_C_ACTIVE     19 // active pixels of the current layer
#define TV_PVS_C_DRAW_SPILL 20
#define TV_PVS_C_DRAW_SPILL_WIDE 24
#define TV_PVS_C_DISPATCH_COOP 28
#define TV_PVS_C_COOP       31 // pixels deferred to the cooperative pass in this layer
#define TV_PVS_C_PER_LAYER  32 // slots [0, 32) are reset before every layer
#define TV_PVS_C_REGIONS    32 // trim regions numbered so far
#define TV_PVS_C_OVERFLOW_FRONTS 33
#define TV_PVS_C_COOP_TOTAL 34 // pixel resolves sorted cooperatively
#define TV_PVS_C_COUNT      36

// Fragment kinds of P2 (push constant `kind`), = TV_ENTRY_* of config.h.
#define TV_PVS_KIND_FRONT 1u
#define TV_PVS_KIND_TRIM  2u
#define TV_PVS_KIND_BACK  3u
#define TV_PVS_KIND_UMBRA 5u
// Flag on FRONT/BACK: the dilated pass (wide visibility buffer; fronts that
// miss the pixel centre become candidate fronts).
#define TV_PVS_KIND_WIDE 256u
// Flag on FRONT (and WIDE): the spill draws after P3 (pvs_face.frag): output
// the fronts and candidates P2 had no room for where P3 did not hide them.
#define TV_PVS_KIND_SPILL 512u

#endif
