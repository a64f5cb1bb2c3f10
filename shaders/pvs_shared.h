/* pvs_shared.h - the trim-region PVS's constants, included by C (pvs/) and
 * by GLSL (pvs_common.glsl): k-buffer sizes, entry kinds and id flags of the
 * trim sequences (pvs/resolve.h is the C reference the shaders mirror), then
 * the descriptor bindings and counter slots of the GPU passes. Only #define
 * lines and comments, so the two sides cannot disagree; structs both sides
 * declare (pvs_view_gpu, pvs_push) are checked with _Static_assert in
 * pvs/gpu_internal.h. */
#ifndef TRIMVR_SHADERS_PVS_SHARED_H
#define TRIMVR_SHADERS_PVS_SHARED_H

/* Workgroup size of the 1D compute passes. */
#define TV_WG_SIZE 64

/* Trim-region PVS, per-pixel k-buffers of P2 and the trim-sequence resolve of
 * P3 (pvs/resolve.h is the C reference the shaders mirror). Capacity per
 * pixel and kind; a counter above its K marks the pixel overflowed. */
#define TV_K_FRONT 32
#define TV_K_BACK  32
#define TV_K_TRIM  32
#define TV_K_UMBRA 32
#define TV_K_CARRY 16 /* entries one pixel carries from a layer to the next */
/* A carried trim region (kind TV_ENTRY_TRIM) packs its trims and umbra into
 * as few carry entries as hold them: flags above TV_CARRY_KIND in the kind
 * word say what else an entry holds besides its trim depth; the fourth word
 * (TV_PVS_BIND_CARRY) is that depth. At most two trims an entry. */
#define TV_CARRY_KIND  0xFFu  /* the TV_ENTRY_* of a carried entry's kind word */
#define TV_CARRY_TWICE 0x100u /* its depth is two trims of the region (moved to the run's first front) */
#define TV_CARRY_TRIM2 0x200u /* the fourth word is a second trim depth */
#define TV_CARRY_UMBRA 0x400u /* the fourth word is the region's umbra depth */
/* The four lists of every pixel live in one pool of pages per tile, taken as
 * P2 fills them (docs/trim-regions.md, "k-buffer layout"): a list is a chain
 * of pages of TV_PVS_PAGE entries from its head. Heads and links hold
 * page + 1, so that 0 (TV_PVS_NO_PAGE) is the end of a chain. */
#define TV_PVS_PAGE 4u
#define TV_PVS_LISTS 4u       /* front, back, trim, umbra: the order of a pixel's counters and heads */
#define TV_PVS_NO_PAGE 0u
#define TV_PVS_HOLE 0xFFFFFFFFu /* depth bits of a slot of a taken page that holds no entry */
/* Set on a list's counter when the pool had no page for one of its entries:
 * the counter then reads as over k (overflowed), and the entry is lost as one
 * past k is. */
#define TV_PVS_COUNT_LOST 0x80000000u
/* A trim region's fragment is one entry of two slots in the pixel's region
 * list, the trim and umbra lists read as one list of 2k slots (slot s < k in
 * the trim list, else slot s - k in the umbra list): (trim depth, region id)
 * and (umbra depth, second trim depth), 0 for a depth it lacks. The trim
 * list's counter claims entries, k of them; the umbra list has no counter of
 * its own (docs/pvs-gpu-passes.md, "Passes"). */
#define TV_PVS_REGION_SLOTS 2u
/* Specialisation constant of P2's fragment shaders and P3 (pvs_common.glsl,
 * KB_PAGED): 1 for pvs_desc.kbuffer_layout PAGED, 0 for FLAT. */
#define TV_PVS_SPEC_KB_PAGED 1
/* Most workgroups of P3's cooperative pass (Vulkan's minimum of
 * maxComputeWorkGroupCount[0]); each loops over the deferred pixels. */
#define TV_PVS_MAX_COOP_GROUPS 65535u
/* The wide visibility pass dilates triangles by half a pixel (pvs_face.vert).
 * A sharp corner needs an offset of about 0.7 / sin(angle / 2) pixels to keep
 * the whole triangle covered; this bound only guards the arithmetic (it keeps
 * corners down to 0.02 degrees). */
#define TV_PVS_MAX_DILATION_PX 4096.0
/* pvs_face.frag's depth tie: two faces within this many times the depth
 * slope per pixel (|dw/dx| + |dw/dy|) of each other count as tied (it was the
 * old 3-pixel dilation limit, the dilated plane's depth error). */
#define TV_PVS_TIE_SLOPES 3.0
/* The trim quads drawn in a face's plane move this fraction of their depth
 * towards the solid (pvs_quad.vert): far above the rounding of interpolated
 * depths (about 1e-7), far below the thickness of thin walls (1 cm at 100 m
 * is 1e-4). */
#define TV_PVS_TRIM_NUDGE 1e-5
/* A culled back (TV_ID_CULLED) enters P2's lists this fraction of its depth
 * farther: a single-sided surface exported as two coincident faces of
 * opposite winding (BSP levels) rounds either way, and where the culled twin
 * sorted first it was a lone back the walk skips, leaving the front without
 * a back: a run carried through every later layer until its carry
 * overflowed (oa:czest2ctf: PVS 2 -> 28 % of the scene). Twice
 * TV_PVS_TRIM_NUDGE, so a trim in the twin's plane still lies inside. */
#define TV_PVS_CULLED_NUDGE 2e-5
/* A border edge's single trim lies in its own triangle's plane, often the face the pixel's interval starts at, and
 * ties with it only up to the rounding of two primitives' interpolated depths (oa:oasago2: 2e-6 of the depth in
 * front of the front, so the trim neither met the interval nor was carried with its run). A fragment this close in
 * front of an interval's front counts as inside (region_meets, carry_run). */
#define TV_PVS_TIE_LO (1.0 - TV_PVS_TRIM_NUDGE)
/* Raster far plane relative to the PVS far plane (pvs/gpu_compute.c), 1 %
 * further: it kept the umbra quads' far corners, which lie on the latter,
 * when the umbrae had a draw of their own; pvs_quad.frag drops the trim
 * depths beyond it, as the rasteriser clipped the trims' own draws. */
#define TV_PVS_RASTER_FAR_SCALE 1.01

/* The trim drawn at the farther plane depth is drawn only for silhouettes
 * whose front triangle v* sees within this cosine of edge-on (beyond 60
 * degrees from its normal): 0.5 kept every FN gain of drawing it always on
 * Sponza and the city, 0.3 lost 0.1 px and 0.1 lost 6 px on Sponza at 20 cm
 * (docs/trim-regions.md). */
#define TV_PVS_GRAZING_COS 0.5
/* Side in pixels of the finest cell of the far-depth bound that narrows the
 * trim widths (pvs/depth_bound.h, docs/trim-width.md). */
#define TV_PVS_DEPTH_CELL_PX 8u
/* Pixels a width narrowed by that bound keeps beyond the exact one (up to
 * the far-plane width): without it false-negative pixels rose on
 * builtin:city, sponza and oasago2, through two rules that sample a pixel
 * at its centre (the umbra where a silhouette crosses the pixel, a
 * sliver's dilated depth) and that the far-plane widths' margin had
 * covered; the conservative fixes cost more PVS than the pixel
 * (docs/trim-width.md, "The slack pixel"). */
#define TV_PVS_TRIM_SLACK_PX 1.0
/* Widest gap (scene units, metres) between two border edges that counts as
 * a crack (scn_mark_cracks): Sponza's decimated columns gape up to ~1.2 cm
 * at their corners. */
#define TV_PVS_CRACK_GAP_M 0.02f
/* A crack edge's trim lies in its own triangle's plane; the face seen
 * beside the crack may be a neighbour a few mm behind that plane (measured
 * 6 mm on a Sponza column base). An interval whose front lies up to this
 * depth (view-axis metres) behind such a trim is seen through the crack. */
#define TV_PVS_CRACK_SLACK_M 0.04f

/* Trim-region stencil values (one per pixel, initialised UNTRIMMED). */
#define TV_STENCIL_UNTRIMMED 0u
#define TV_STENCIL_TRIMMED   1u
#define TV_STENCIL_SEALED    2u
#define TV_STENCIL_OVERFLOW  3u /* lost entries: every later front is output, never sealed */

/* Trim-sequence entry kinds. The value is also the tie-break rank when two
 * entries have equal depth: an umbra end sorts first (what lies exactly on
 * it is not hidden) and a range begin last (what lies exactly on it is not
 * hidden either); fronts before trims before backs, so a trim at the depth
 * of either face lies inside the interval. */
#define TV_ENTRY_END   0u /* end of a hidden range: umbra of a validated interval */
#define TV_ENTRY_FRONT 1u
#define TV_ENTRY_TRIM  2u
#define TV_ENTRY_BACK  3u
#define TV_ENTRY_BEGIN 4u /* start of a hidden range carried from an earlier layer */
#define TV_ENTRY_UMBRA 5u /* an umbra fragment as rasterised (looked up by region) */

/* The id bits of trim-sequence entries, in one table. They overlap: the
 * flags of triangle ids and of region ids share bits, and the two prior
 * values are whole ids with flag bits set. Triangle ids stay below
 * 0x20000000 (pvs_create refuses larger scenes), region ids below
 * TV_REGION_CRACK.
 *
 *   bits        name                on                 test
 *   0x80000000  TV_ID_CANDIDATE     front, back ids    id & bit
 *   0x40000000  TV_ID_CULLED        back ids           id & bit, id != TV_ID_PRIOR
 *   0x40000000  TV_REGION_CRACK     trim region ids    id & bit, id != TV_ID_PRIOR
 *   0x20000000  TV_ID_STRADDLED     back ids           id & bit, !(id & TV_ID_CULLED)
 *   0x7FFFFFFF  TV_ID_PRIOR         front, back, trim  id == value (has CULLED/CRACK
 *                                                      and STRADDLED set)
 *   0x7FFFFFFE  TV_ID_PRIOR_CULLED  back               id == value; a culled back
 *                                                      (CULLED set, so is_culled
 *                                                      holds), never straddled
 *
 * CULLED and CRACK share a bit because they flag different id spaces (a
 * back's triangle id, a trim's region id). Output (pvs/resolve.c's
 * emit, pvs_resolve.glsl's output_id) skips TV_ID_PRIOR and every id with
 * the CULLED bit, and clears CANDIDATE and STRADDLED. */

/* Flag on a front's triangle id: a candidate front, i.e. a triangle that
 * touches the pixel without covering its centre (P2's dilated pass). It is
 * output when not hidden but never occludes: it neither starts an interval
 * nor terminates the pixel. On a back's id (a candidate back: the back of a
 * triangle narrower than a pixel) the same, but output only in front of
 * every face at the centre. Triangle ids stay below it. */
#define TV_ID_CANDIDATE 0x80000000u

/* Id of the "prior" face entries: the nearest faces (from v*) covering a
 * pixel's centre up to the layer in which the pixel becomes trimmed. Until
 * then the visibility buffer alone resolved the pixel, so P3 had kept none of
 * its faces; they enter the trim sequence as faces with this id and are never
 * output (the visibility buffer already holds them). Triangle ids stay below
 * it. */
#define TV_ID_PRIOR 0x7FFFFFFFu
/* Flag on a back's triangle id: a straddled back, whose plane the viewcell
 * straddles (P1), so that some eyes see its front while v* sees its back (a
 * side face seen edge-on past an occluder's edge). Where it closes an
 * interval, it is output with that interval's first front when the walk
 * reaches it unhidden, as the back of a cracked interval is. Triangle ids
 * stay below it; the prior ids, which have it, are recognised by
 * TV_ID_CULLED. */
#define TV_ID_STRADDLED 0x20000000u

/* Explain mode (pvs_desc.explain): each triangle's flag holds the OR of the
 * rules that output it (docs/evaluation.md, "Explaining false positives"). */
#define TV_REASON_VIS 0x001u       /* P4: nearest face at a pixel centre (visibility buffer) */
#define TV_REASON_VIS_WIDE 0x002u  /* P4: the dilated visibility buffer */
#define TV_REASON_OPEN_RUN 0x004u  /* P4: a run still carried after the last layer */
#define TV_REASON_TIE 0x008u       /* P2: depth tie with the nearest face at a centre */
#define TV_REASON_PARTIAL 0x010u   /* P2: in front through part of a pixel (sub-pixel) */
#define TV_REASON_SEALED 0x020u    /* P2: in front of a sealed pixel's terminator */
#define TV_REASON_FRONT 0x040u     /* P3: a front of a validated interval, a terminator, a lone face */
#define TV_REASON_CANDIDATE 0x080u /* P3: a candidate front or back (touches the pixel) */
#define TV_REASON_STRADDLED 0x100u /* P3: a straddled back */
#define TV_REASON_CRACK 0x200u     /* P3: the back of an interval seen through a crack */
#define TV_REASON_OVERFLOW 0x400u  /* P3's overflow policy, a full carry, the spill draws */
#define TV_REASON_COUNT 11

/* The prior culled back (TV_ID_CULLED): it closes a prior front's interval
 * and is otherwise skipped like every culled back. */
#define TV_ID_PRIOR_CULLED 0x7FFFFFFEu

/* Flag on a back's triangle id: a culled back, the back of a triangle whose
 * material is single-sided (glTF doubleSided false) and whose plane has the
 * whole viewcell behind it (P1, pvs_classify.comp). The renderer culls it
 * from every eye of the viewcell, so it is never visible and hides nothing:
 * it only closes the interval its front opened. It is never output, never
 * terminates a pixel and is not a prior face. Triangle ids stay below it
 * (it shares its bit with TV_REGION_CRACK, which flags region ids). */
#define TV_ID_CULLED 0x40000000u

/* Flag on a trim-region id: the region of a crack edge (scn_mark_cracks),
 * a border edge along which another triangle's border edge runs across a
 * narrow gap. An interval whose front lies at or up to
 * TV_PVS_CRACK_SLACK_M behind such a region's trim has a hole at its front
 * surface, through which the eyes of the viewcell see its back face: P3
 * outputs that back (pvs_resolve_pixel). Region ids stay below it;
 * TV_ID_PRIOR, which has this bit, is never a crack region. */
#define TV_REGION_CRACK 0x40000000u

/* Adjacency value the GPU copy gives a crack edge (P1): a border edge, like
 * SCN_EDGE_BORDER and SCN_EDGE_NONMANIFOLD above it. */
#define TV_ADJ_CRACK 0xFFFFFFFDu
/* Flag on an adjacency value below TV_ADJ_CRACK (SCN_EDGE_REST): a border
 * resting on the face whose id is in the other bits; a silhouette unless
 * the two face v* alike, and then treated as a border (P1). */
#define TV_ADJ_REST 0x80000000u


// Set 0 is the scene set (TV_SET_SCENE); the PVS passes bind theirs as set 1.
#define TV_PVS_SET 1

#define TV_PVS_BIND_VIEW       0  // pvs_view_gpu: matrices and frustum of v*
#define TV_PVS_BIND_ADJ        1  // uint[3] per triangle: neighbour across each edge
#define TV_PVS_BIND_LAYER_TRIS 2  // the triangle ids of every layer, back to back
#define TV_PVS_BIND_FF         3  // P1 -> P2: front-facing triangle ids of the layer
#define TV_PVS_BIND_BF         4  // P1 -> P2: back-facing triangle ids of the layer
#define TV_PVS_BIND_SIL        5  // P1 -> P2: TV_PVS_SIL_VEC4 vec4 per silhouette record, slot 3 i + e (layer triangle i, edge e)
#define TV_PVS_BIND_COUNTERS   6  // indirect commands and counters (TV_PVS_C_*)
#define TV_PVS_BIND_KPOOL      7  // k-buffer pages: TV_PVS_PAGE uvec2 (depth bits, triangle or region id) each
#define TV_PVS_BIND_KHEADS     8  // uint x TV_PVS_LISTS per pixel: first page + 1 of each list (0: empty), reset every layer
#define TV_PVS_BIND_KLINKS     9  // uint per page: the next page + 1 of its list (0: none), reset every layer
#define TV_PVS_BIND_KALLOC     10 // uint: pages taken in this layer (the pool's next free page, reset every layer), then per tile and layer a copy of it after P2
#define TV_PVS_A_TAKEN  0u
#define TV_PVS_A_LAYERS 1u // slot of tile 0's layer 0 in TV_PVS_BIND_KALLOC
#define TV_PVS_BIND_PIXCOUNT   11 // uvec4 per pixel: front, back and region-entry counters; the fourth only marks lost umbra-list pages
#define TV_PVS_BIND_PIXSTATE   12 // uvec4 per pixel: stencil, carry count (sealed: terminator depth bits), hide begin/end bits
#define TV_PVS_BIND_CARRY      13 // uvec4 (depth bits, kind | TV_CARRY_* flags, id, second depth bits) x TV_K_CARRY per pixel
#define TV_PVS_BIND_ACTIVE     14 // uint per pixel: active pixel stencil
#define TV_PVS_BIND_ACTIVE_LIST 15 // pixel indices activated in this layer
#define TV_PVS_BIND_TRI_FLAGS  16 // uint per triangle: 1 = in the PVS
#define TV_PVS_BIND_VIS_IDS    17 // r32ui storage image: the visibility buffer's ids
#define TV_PVS_BIND_LAYER_STATS 18 // TV_PVS_LAYER_STATS_STRIDE uvec4 per layer: (0, then P3's active pixels, sequence sum, overflows), P1's (vertex counts of the FF, BF and trim draws, 0)
#define TV_PVS_LAYER_STATS_STRIDE 2
#define TV_PVS_BIND_VIS_WIDE   19 // r32ui storage image: ids of the dilated pass
#define TV_PVS_BIND_CENTRE_DEPTH 20 // TV_PVS_CENTRE_STRIDE uints per pixel: nearest depth bits of the faces covering its centre
#define TV_PVS_CENTRE_FRONT   0u // slots of a pixel's TV_PVS_BIND_CENTRE_DEPTH entry (P2's exact pass, atomicMin)
#define TV_PVS_CENTRE_BACK    1u
#define TV_PVS_CENTRE_CULLED  2u // culled backs (TV_ID_CULLED): they close intervals only
// The nearest culled back behind the nearest front at the centre over its layer and the earlier ones (P2 draws a
// layer's backs after its fronts, a barrier between), which may close that front: the nearest overall is often a
// lone one in front of every front, and alone it left a front's own back out (merged solids: docs/pvs-edge-cases.md,
// "Prior faces"). Depths as floats, in C and GLSL.
#define TV_PVS_CENTRE_CULLED_BEHIND 3u
#define TV_PVS_PRIOR_CULLED_BEHIND(front, culled) ((culled) > (front))
// Two 64-bit slots (uints 4-5, 6-7; P2's exact pass, atomicMin of depth bits << 32 | label): the least front-patch
// label (TV_PVS_BIND_PATCH) and the complement of the greatest among the fronts at the nearest depth at the centre.
// P3 knows the prior front's patch when both depths are TV_PVS_CENTRE_FRONT's and the labels agree (prior_patch).
#define TV_PVS_CENTRE_PATCH_LO 4u
#define TV_PVS_CENTRE_PATCH_HI 6u
#define TV_PVS_CENTRE_STRIDE  8u
#define TV_PVS_BIND_LOST       21 // TV_PVS_LOST_STRIDE uints per pixel, depth bits: the nearest lost front, lost candidate (P3 replaces it by the candidate spill bound), lost trim
#define TV_PVS_LOST_FRONT     0u // slots of a pixel's TV_PVS_BIND_LOST entry: what the layer's k-buffer had no room for (P2, atomicMin)
#define TV_PVS_LOST_CANDIDATE 1u
#define TV_PVS_LOST_TRIM      2u
#define TV_PVS_LOST_SPAN_LO   TV_PVS_LOST_TRIM // after P3 read it: the spill span (pvs_spill_hidden), for the dilated spill draw
#define TV_PVS_LOST_SPAN_HI   3u
#define TV_PVS_LOST_STRIDE    4u
#define TV_PVS_BIND_COOP_LIST  22 // P3: pixels whose sequence the cooperative pass sorts (pvs_resolve_group.comp)
#define TV_PVS_BIND_PROXIES    23 // vec4 min, vec4 max per proxy of the request (pvs_compute_dynamic); P1, P2 pull their box faces
#define TV_PVS_BIND_SPILL      24 // uint: the spill list's length, then interleaved: its entries (the layer's fronts that lost a fragment in P2, drawn by the spill draws) and a layer stamp per drawn id
#define TV_PVS_SPILL_ENTRY(i)  (1u + 2u * (i)) // slot of the list's entry i in TV_PVS_BIND_SPILL
#define TV_PVS_SPILL_STAMP(t)  (2u + 2u * (t)) // slot of drawn id t's stamp: 1 + the last layer that listed it (0 after each tile's reset)
#define TV_PVS_BIND_ORDER      25 // P1's lists in layer order (pvs_order.comp), uints; cap = view.list_capacity:
#define TV_PVS_ORDER_SIL(i)        (i)                       // the layer's silhouette list: record slot of entry i (P2's quads)
#define TV_PVS_ORDER_CLASS(cap, i) (3u * (cap) + (i))       // layer triangle i's TV_PVS_CLASS_* bits
#define TV_PVS_ORDER_GROUP(cap, g) (4u * (cap) + 4u * (g))  // P1 workgroup g: FF, BF, record counts (cleared per layer), then offsets and first region id
#define TV_PVS_BIND_KREGIONS   26 // FLAT: the region list's pages (trim and umbra lists); KPOOL holds the fronts' and backs'
#define TV_PVS_BIND_PATCH      27 // drawn front-patch labels (pvs/patches.h, per view), then 3 x drawn region ids' (P1)
#define TV_PVS_PATCH_NONE 0xFFFFFFFFu // no label: a triangle not facing v*, masked or touching a masked one, a proxy
#define TV_PVS_BINDINGS        28

// Class word of a layer triangle (TV_PVS_ORDER_CLASS): which of P1's lists
// it enters, a back's flags, and which of its edges emitted a silhouette
// record (in the fixed record slot 3 i + e) and which of those is a crack.
#define TV_PVS_CLASS_FF        1u
#define TV_PVS_CLASS_BF        2u
#define TV_PVS_CLASS_CULLED    4u
#define TV_PVS_CLASS_STRADDLED 8u
#define TV_PVS_CLASS_EDGE(e)   (16u << (e))
#define TV_PVS_CLASS_CRACK(e)  (128u << (e))

// vec4s per silhouette record: e0 (w = region id bits), e1, trim corner
// behind e1, trim corner behind e0 (w: their nearer plane depths), umbra
// far corner behind e1, behind e0 (w: the trim corners' farther plane
// depths; pvs_trim_depth).
#define TV_PVS_SIL_VEC4 6

// Slots of the counters buffer (uints). Three VkDrawIndirectCommand (FF, BF,
// trim and umbra quads; vertexCount set by P1's scan, pvs_classify.comp;
// slots 12-15 are free), one
// VkDispatchIndirectCommand for P3, the active count, the two spill draws
// (after P3, exact and dilated, of the fronts in TV_PVS_BIND_SPILL; P3 sets
// their vertexCount from its length when a pixel needs them), the VkDispatchIndirectCommand of P3's
// cooperative pass (groups = min(deferred pixels, TV_PVS_MAX_COOP_GROUPS))
// and the deferred pixel count, then counters that live for a whole
// pvs_compute.
#define TV_PVS_C_DRAW_FF    0
#define TV_PVS_C_DRAW_BF    4
#define TV_PVS_C_DRAW_TRIM  8
#define TV_PVS_C_DISPATCH   16
#define TV_PVS_C_ACTIVE     19 // active pixels of the current layer
#define TV_PVS_C_DRAW_SPILL 20
#define TV_PVS_C_DRAW_SPILL_WIDE 24
#define TV_PVS_C_DISPATCH_COOP 28
#define TV_PVS_C_COOP       31 // pixels deferred to the cooperative pass in this layer
#define TV_PVS_C_PER_LAYER  32 // slots [0, 32) are reset before every layer
#define TV_PVS_C_REGIONS    32 // trim regions numbered so far (in this tile)
#define TV_PVS_C_OVERFLOW_FRONTS 33
#define TV_PVS_C_COOP_TOTAL 34 // pixel resolves sorted cooperatively
#define TV_PVS_C_P1_DONE    35 // P1 invocations of the layer done: the last one scans the counts and resets it (pvs_classify.comp)
#define TV_PVS_C_LOOP_BUDGET 36 // P3 pixel resolves whose invocation ran out of llvmpipe's loop budget (pvs_common.glsl)
#define TV_PVS_C_IDLE       37 // P3 resolves of a pixel with trims only where they do nothing (pvs_region_activates): 0
#define TV_PVS_C_COUNT      38

// Fragment kinds of P2 (push constant `kind`), = TV_ENTRY_* above.
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
