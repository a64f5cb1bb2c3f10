/* resolve.h - trim-sequence resolve of one pixel for one layer (P3), the C
 * reference the P3 compute shader mirrors line by line (paper section 4.3).
 * The rules, with examples and the reasons for each, are in
 * docs/trim-regions.md ("k-buffer layout", "Resolve rules", "Overflow
 * policy"); the cases beyond the paper (prior faces, candidates, lone,
 * culled, straddled and cracked backs) in docs/pvs-edge-cases.md.
 *
 * Contract in short:
 * - Per pixel and layer, four k-buffers (fronts, backs, trims, umbrae) of
 *   TV_K_* entries (shaders/pvs_shared.h) whose counters run past K: a count
 *   above K means the list overflowed. The trim and umbra lists hold one list
 *   of region entries (TV_PVS_REGION_SLOTS), trims and umbrae together. P2 stores them in pages of a pool
 *   (pvs_kpages, as the GPU does); an entry the pool has no page for is lost
 *   like one past K, and its list reads as overflowed. Trims and umbrae carry their
 *   trim-region id, unique within one PVS computation, which pairs them.
 * - Depths are any value monotonic along the pixel's ray from v*.
 * - pvs_pixel_state persists across layers (zero-initialised = untrimmed):
 *   stencil, at most TV_K_CARRY carried entries, one hidden range, and once
 *   sealed the terminator's depth.
 * - pvs_resolve_pixel writes at most PVS_RESOLVE_MAX_OUTPUT triangle ids,
 *   never with a TV_ID_* flag. Where a list or the carry overflowed it errs
 *   towards output (false positives), never towards a lost triangle.
 */
#ifndef TRIMVR_PVS_RESOLVE_H
#define TRIMVR_PVS_RESOLVE_H

#include <stdbool.h>
#include <stdint.h>

#include "pvs_shared.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Most triangle ids one pvs_resolve_pixel call can output (its stored
 * candidates may come twice: from the resolve and as spill output). */
#define PVS_RESOLVE_MAX_OUTPUT (2 * TV_K_FRONT + TV_K_BACK + TV_K_CARRY)

/* The pool of k-buffer pages of P2 (shaders/pvs_kbuffer.glsl), which holds
 * every pixel's lists: a list is a chain of pages of TV_PVS_PAGE slots from
 * its head, links holding page + 1 (TV_PVS_NO_PAGE: the end). The caller owns
 * the arrays (page_count pages) and zeroes `taken` before a layer. */
typedef struct pvs_kpages {
    uint32_t (*slots)[2]; /* page_count * TV_PVS_PAGE: depth bits (TV_PVS_HOLE: no entry), id */
    uint32_t* links;      /* page_count: the next page + 1 of the list */
    uint32_t page_count;
    uint32_t taken;       /* pages asked for in this layer, past page_count too (the GPU's counter) */
} pvs_kpages;

/* The four k-buffers of one pixel for the current layer: P2's counters and
 * list heads, and the entries as pvs_kbuf_read gathers them from the pages
 * (what pvs_resolve_pixel reads). */
typedef struct pvs_kbuf {
    /* May exceed K; TV_PVS_COUNT_LOST: pages ran out. The region entries
     * (trim_count) fill the trim list's pages, then the umbra list's. */
    uint32_t front_count, back_count, trim_count;
    /* pvs_desc.k (0: TV_K_*): a pixel with a longer list is deep, its umbrae count for nothing. */
    uint32_t k_exact;
    /* Entries the front and back lists hold (pvs_desc.k_deep; 0: TV_K_FRONT, TV_K_BACK); the
     * region list holds TV_K_TRIM (pvs_desc.k_regions), so it may hold more (pvs_kbuf_capacity). */
    uint32_t k_lists;
    uint32_t head[TV_PVS_LISTS]; /* first page + 1 of each list in the pool (0: empty) */
    /* Entries in the arrays below: min(count, K), fewer when the pool lost some. */
    uint32_t front_held, back_held, trim_held, umbra_held;
    float front_depth[TV_K_FRONT];
    uint32_t front_tri[TV_K_FRONT];
    float back_depth[TV_K_BACK];
    uint32_t back_tri[TV_K_BACK];
    /* Trims and umbrae come in region entries (TV_PVS_REGION_SLOTS): up to
     * two trim depths and an umbra each, trim_count of them. */
    float trim_depth[2 * TV_K_TRIM];
    uint32_t trim_region[2 * TV_K_TRIM];
    float umbra_depth[TV_K_UMBRA];
    uint32_t umbra_region[TV_K_UMBRA];
    /* The region entries as stored (trim, region id, umbra, second trim
     * bits; a region id of 0 with no depth: none), which pvs_kbuf_push's
     * trims and umbrae join. */
    uint32_t entry_bits[TV_K_TRIM][4];
    /* Nearest depth of the front / back faces covering the pixel centre over
     * this and every earlier layer (P2's exact pass; 0 or INFINITY: none).
     * Read only when the pixel becomes trimmed (TV_ID_PRIOR). */
    float nearest_front, nearest_back;
    /* The same for culled backs (TV_ID_CULLED), kept apart: they enter as
     * TV_ID_PRIOR_CULLED, which closes an interval and does nothing else. */
    float nearest_culled_back;
    /* The nearest culled back behind the nearest front of its layer (TV_PVS_CENTRE_CULLED_BEHIND), which may close a
     * prior front whose own back the nearest culled back, a lone one in front of it, is not. */
    float culled_behind;
    /* P2's front-patch slots at the centre (TV_PVS_CENTRE_PATCH_LO, _HI as uints: least label, its depth bits, the
     * greatest's complement, its depth bits; pvs_centre_store), and the regions' labels (P1; NULL: none known). */
    uint32_t patch_centre[4];
    const uint32_t* region_patch;
    uint32_t region_patches;
    /* Nearest depth of a front (not a candidate) that found the front list
     * full (0: none); pvs_kbuf_push keeps it, as P2's atomicMin does. */
    float front_lost;
    /* The same for a candidate front: pvs_resolve_pixel then outputs the
     * stored candidates that pvs_spill_output would output if lost. */
    float candidate_lost;
    /* Nearest depth of a trim that found the trim list full (0: none). */
    float trim_lost;
} pvs_kbuf;

/* One carried entry (pvs_pixel_state). id: triangle id for fronts, trim-region
 * id for trims and umbrae; a region's trims and umbra share entries (pvs_carry_add). */
typedef struct pvs_entry {
    float depth;
    uint32_t kind; /* TV_ENTRY_*, a trim's with TV_CARRY_* flags */
    uint32_t id;
    float second;  /* the second depth of TV_CARRY_TRIM2 or TV_CARRY_UMBRA, else 0 */
} pvs_entry;

typedef struct pvs_pixel_state {
    uint32_t stencil; /* TV_STENCIL_*; zero-initialised = untrimmed */
    uint32_t carry_count;
    pvs_entry carry[TV_K_CARRY]; /* kinds FRONT, TRIM, UMBRA; fronts in depth order (trims need not be) */
    /* A hidden range when hide_begin < hide_end: carried to the next layer
     * while trimmed; once sealed, the last one in front of the terminator. */
    float hide_begin, hide_end;
    /* While trimmed, where the hidden range's umbrae's footprints stop covering it (walk); carry_range rounds it and
     * hide_end as pvs_umbra_pack does, so that the GPU keeps both in one word. */
    float hide_end_fp;
    float term_depth; /* the terminator's depth once sealed */
    /* The spill span of the latest resolve: the walk's last hidden span (from the back of the interval whose
     * umbra opened it to where none is open, or to the terminator that sealed the pixel in it), cut where the
     * umbrae's footprints stop covering it (walk); empty after a carried range's start, in overflow state and in
     * any layer that did not walk. A candidate strictly inside it is hidden, lost or stored (pvs_spill_hidden). */
    float spill_lo, spill_hi;
} pvs_pixel_state;

/* P2's insertion of one fragment of `kind` (TV_ENTRY_FRONT, BACK, TRIM or
 * UMBRA) into the pixel's k-buffer: increments the counter and, when there
 * is room, stores the entry in the list's pages, taking a page from `pages`
 * where the chain ends before the slot. Returns false when the list was full
 * or the pool had no page left (the counter then gets TV_PVS_COUNT_LOST);
 * for a front the caller must then keep `id` and ask pvs_spill_output after
 * the resolve. Asserts a valid kind. */
bool pvs_kbuf_push(pvs_kbuf* kbuf, pvs_kpages* pages, uint32_t kind, float depth, uint32_t id);

/* P2's exact pass at a pixel centre (centre_depth, TV_PVS_CENTRE_*): joins a front, back or culled back (id with
 * TV_ID_CULLED) covering the centre to the nearest of its kind over the earlier faces; INFINITY: none. The caller
 * stores a layer's fronts before its backs, as P2 draws them, so that a culled back finds its layer's nearest front
 * (TV_PVS_PRIOR_CULLED_BEHIND). A front's front-patch `label` (pvs/patches.h) joins the 64-bit slots
 * TV_PVS_CENTRE_PATCH_LO, _HI (their uints' bits in the floats), as P2's atomicMin does. */
void pvs_centre_store(float centre[TV_PVS_CENTRE_STRIDE], uint32_t kind, float depth, uint32_t id, uint32_t label);

/* P2's push of one trim region's fragment (pvs_push_region of
 * pvs_kbuffer.glsl): one entry of two trim depths and the umbra's depth (0:
 * none), nothing where both trim depths are 0. Where it finds no
 * room, the nearer trim depth is kept as the lost trim's. A trim or umbra
 * pushed by pvs_kbuf_push joins the first stored entry of its region that
 * has room for it, else starts one (the tests build sequences fragment by
 * fragment; an umbra alone is an entry without trim depth, dropped
 * uncounted where the list is full: the GPU stores no umbra without trims). */
bool pvs_kbuf_push_region(pvs_kbuf* kbuf, pvs_kpages* pages, float trim, float second, float umbra, uint32_t id);

/* A region's umbra as P2 stores it (the entry's umbra slot, carried umbrae): the depth where the pixel centre's
 * ray leaves the umbra, which the walk hides up to, rounded down to 16 significant bits, and in the low byte of its
 * bits its footprint (P2: its nearest depth over the square of two pixels' side around the pixel's centre) as a
 * fraction of it, rounded down, where the spill span ends (pvs_spill_hidden; docs/journal/2026-12-03-fpumbra.md).
 * A depth whose low byte is 0 has its centre depth as footprint; 0 and +inf (none) pack as themselves. */
float pvs_umbra_pack(float centre, float footprint);
float pvs_umbra_centre(float packed);
float pvs_umbra_footprint(float packed);

/* A deep pixel: k_exact set, a front or back list longer than it, none past
 * its capacity (docs/trim-regions.md, "Overflow policy"). Its umbrae end at
 * their footprints (pvs_umbra_depth), as where the centre ray leaves them some
 * of its many faces lie nearer the edge; a region list longer than k_exact alone
 * does not make a pixel deep: its faces are as few as a shallow pixel's,
 * and it keeps its umbrae (docs/journal/2026-12-03-regovf.md). */
bool pvs_kbuf_deep(const pvs_kbuf* kbuf);

/* Entries the front or back list holds: k_lists where set, else `max` (TV_K_FRONT, TV_K_BACK). */
static inline uint32_t pvs_kbuf_capacity(const pvs_kbuf* kbuf, uint32_t max)
{
    return kbuf->k_lists && kbuf->k_lists < max ? kbuf->k_lists : max;
}

/* Gathers the pixel's entries from the pages into kbuf's arrays, as P3 reads
 * them: the first min(count, K) slots of each list, skipping holes. */
void pvs_kbuf_read(pvs_kbuf* kbuf, const pvs_kpages* pages);

/* Whether a trim region's fragment makes its pixel active in P2 (pvs_region_activates of
 * pvs_common.glsl; sealed pixels store nothing). A trimmed pixel that carries nothing, or one in
 * overflow state, resolves with trims alone to no output and its state as it was (no interval,
 * nothing to carry; test_trims_alone_change_nothing), so P2 leaves it inactive unless a face of
 * the layer activates it: 4-10 % of P3's resolves at 30 cm (docs/journal/2026-12-03-speed2.md). */
static inline bool pvs_region_activates(const pvs_pixel_state* s)
{
    return s->stencil == TV_STENCIL_UNTRIMMED || (s->stencil == TV_STENCIL_TRIMMED && s->carry_count != 0);
}

/* Resolves one active pixel after P2 rasterised a layer (depth: any value
 * monotonic in the distance along the pixel's ray from v*). Writes the
 * triangle ids this pixel adds to the trimmed-primitive list into `out`
 * (room for PVS_RESOLVE_MAX_OUTPUT) and returns their count; updates
 * `state`. A sealed pixel outputs the fronts and backs that
 * pvs_sealed_output admits (the GPU does this in P2: it stores nothing at
 * a sealed pixel); an untrimmed pixel without trim fragments outputs
 * nothing (its nearest front is the visibility
 * buffer's), otherwise the pixel becomes trimmed and is resolved. Sets
 * *overflowed when a list of the pixel overflowed, its carry did not fit or
 * it was already in overflow state (the statistics count these pixels).
 * When its front list lost a candidate (kbuf->candidate_lost), it also
 * outputs every stored candidate that pvs_spill_output would output were it
 * lost: the GPU's spill draws draw only the fronts that lost a fragment, so
 * a stored candidate of a triangle that lost nothing, which a draw of every
 * front would output there too, is output by P3 (request_spill); the ids
 * then do not depend on which triangles lost what, nor on the tiling. */
uint32_t pvs_resolve_pixel(pvs_pixel_state* state, const pvs_kbuf* kbuf, uint32_t* out,
                           bool* overflowed);

/* After pvs_resolve_pixel of the layer: whether a front (id with or without
 * TV_ID_CANDIDATE, at the depth it was pushed with) that found the front
 * list full must be added to the PVS. At an overflowed pixel every one; at
 * a pixel left open, every candidate (a lost front would have overflowed
 * it); at a pixel sealed in this layer, the candidates in front of its
 * terminator (lost fronts lie behind it), at either none inside the spill
 * span (pvs_spill_hidden); at an untrimmed pixel none: its visibility buffer
 * holds its nearest face, and P3 ignores its fronts. The GPU's spill draws
 * after P3 decide the same way. */
bool pvs_spill_output(const pvs_pixel_state* state, uint32_t id, float depth);

/* Whether a candidate at `depth` lies strictly inside state's spill span: the walk hid it there (no validated
 * interval's run starts inside the span) and, the span ending at the umbrae's footprints, no eye sees it through
 * any point of the pixel, so a lost one is not output either (docs/trim-regions.md, "Overflow policy", 1). */
bool pvs_spill_hidden(const pvs_pixel_state* state, float depth);

/* Whether a front or back face at `depth` reaching a sealed pixel in a later
 * layer is output: when it lies in front of the terminator and outside the
 * hidden range kept at sealing. Layers are peeled front to back by octree
 * leaf, but a triangle is drawn in the layer of its earliest leaf only, so a
 * large one may terminate a pixel before the layer holding a nearer face
 * there (found on Sponza: a back face sealed pixels 24 cm behind a ledge
 * drawn four layers later, which eyes in the viewcell see). Asserts that
 * the pixel is sealed. */
bool pvs_sealed_output(const pvs_pixel_state* state, float depth);

/* Adds an entry of `kind` to carry[0, *count): a trim of region `id` or its
 * umbra (TV_ENTRY_UMBRA) goes into the region's last entry where that has
 * room (two trims, or trims and the umbra), anything else into a new entry.
 * False when the TV_K_CARRY entries are full. */
bool pvs_carry_add(pvs_entry* carry, uint32_t* count, uint32_t kind, float depth, uint32_t id);

/* The trim depths a carried entry holds (0 to 2) into depth[]. */
uint32_t pvs_carry_trims(const pvs_entry* e, float depth[2]);

/* Whether carried entry e holds region `id`'s umbra, and its depth. */
bool pvs_carry_umbra(const pvs_entry* e, uint32_t id, float* depth);

/* Depth of the umbra of trim region `region` at this pixel (nearest if it
 * was rasterised more than once), from this layer or carried (resolve.c's
 * validate and carry_run), and the nearest of its footprints. At a deep
 * pixel the footprint is its depth too: an umbra ends where the pixel's
 * centre ray leaves it, and where many faces lie behind an occluder, some
 * are seen nearer its edge (trim-regions.md); none ends nearer than its
 * footprint, two pixels' width around the centre (dropping them grew
 * czest2ctf's PVS 7 %: docs/journal/2026-12-03-ovf30.md). */
bool pvs_umbra_depth(const pvs_pixel_state* s, const pvs_kbuf* k, uint32_t region, float* depth, float* footprint);

#ifdef __cplusplus
}
#endif

#endif
