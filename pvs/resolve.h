/* resolve.h - trim-sequence resolve of one pixel for one layer (P3), the C
 * reference the P3 compute shader mirrors line by line (paper section 4.3).
 *
 * Data layout (per pixel, as on the GPU): four k-buffers with fixed
 * capacities from shaders/pvs_shared.h, each with an atomic counter that P2
 * increments for every fragment, also past the capacity: a counter above its
 * K is how P3 knows the list overflowed. Trim and umbra fragments carry the
 * id of the silhouette edge that produced them (the trim-region id, unique
 * within one PVS computation: P1 numbers the silhouettes of all layers
 * consecutively), which is the 1:1 trim region <-> umbra correspondence.
 *
 * The pixel state persists across layers: the trim stencil, the unfinished
 * interval carried to the next layer (fronts, with the trims and umbrae that
 * may still validate it), and one hidden range [hide_begin, hide_end] (the
 * umbrae still open at the end of the layer).
 *
 * Rules (docs/trim-regions.md has examples): sort by (depth, kind, id);
 * greedy intervals [f, b] over fronts and backs, extended at the front over
 * consecutive fronts; an interval is validated by a trim region with a
 * fragment t, f <= t <= b, or fragments on both sides of [f, b]; its back is
 * replaced by the nearest umbra of the validating regions (never nearer than
 * b); +1 at validated fronts, -1 at those umbrae, prefix sum > 0 hides an
 * entry. Walking front to back, the fronts of every validated interval are
 * output unless its first front is hidden; the first front or back outside
 * a validated interval is the terminator (a visible front terminator is
 * output, and so is a visible lone back: a double-sided surface seen from
 * behind, which the renderer draws; a hidden front terminates unseen, being
 * uneroded; a hidden lone back is skipped, and a lone back that a trim
 * region meets is output without terminating) and seals the pixel; a
 * trailing run of fronts without a back is carried, not a terminator. The
 * back of an interval that a crack edge's trim (TV_REGION_CRACK) lies in,
 * or up to TV_PVS_CRACK_SLACK_M in front of, is output with its first
 * front (validated and unhidden, or the terminator): the eyes see it
 * through the crack. So is a straddled back (id | TV_ID_STRADDLED: the
 * viewcell straddles its plane, so some eyes see its front).
 *
 * Culled backs (back id | TV_ID_CULLED: the renderer culls the triangle
 * from the whole viewcell, glTF's single-sided materials) close the interval
 * their front opened and do nothing else: never output, and a lone one is
 * skipped (neither visible nor an occluder). An interval with a crack and a
 * culled back hides its inside only: through the crack the eyes see what
 * lies behind it.
 *
 * Candidate fronts (front id | TV_ID_CANDIDATE: the triangle touches the
 * pixel without covering its centre) take no part in intervals and never
 * terminate: one is output when the walk reaches it outside every hidden
 * range, or inside a validated interval whose fronts are output. Output ids
 * never carry the flag. Candidate backs (back id | TV_ID_CANDIDATE: the back
 * of a triangle narrower than a pixel, which may cover no centre at all)
 * likewise, but are output only outside every hidden range and in front of
 * every face of the sequence; they are never carried and fill at most half
 * the back list (pvs_kbuf_push).
 *
 * Overflow policy (never lose a visible front), per list:
 * - fronts: P2 keeps the nearest depth of the fronts that find the list full
 *   (front_lost; pvs_kbuf_push tells the caller, who decides with
 *   pvs_spill_output after the resolve whether to add them to the PVS).
 *   The sequence is complete in front of that depth: a terminator found
 *   there seals the pixel as usual, the lost fronts lying behind it. Otherwise a lost front could have opened an interval whose
 *   back now looks like a terminator, in this or a later layer, so the pixel
 *   becomes TV_STENCIL_OVERFLOW: all its stored and carried fronts are
 *   output, and in every later layer all fronts are output and the pixel is
 *   never sealed. The same when the carry does not fit. Lost candidates
 *   change nothing (they never occlude).
 * - trims: P2 keeps the nearest depth of the lost trims (trim_lost). An
 *   interval whose back lies at or behind it may have been validated by a
 *   lost trim, whose umbra may have been the nearest: it counts as valid and
 *   hides up to its back only. Intervals in front of it are complete and
 *   resolve as usual; the trims behind it that found room (an accident of
 *   arrival order) count for nothing. A carried run gets a trim without
 *   umbra (region TV_ID_PRIOR) at its first front, which validates it when
 *   its back arrives.
 * - backs: nothing to do. A lost back merges two intervals into one (valid
 *   when either was, hiding no further than the later back) or leaves a run
 *   open; it never creates a terminator: only more output.
 * - umbrae: nothing to do. A region whose umbra was lost hides up to the
 *   back only.
 * See docs/trim-regions.md for the rules and examples.
 *
 * Prior faces: when an untrimmed pixel becomes trimmed, its nearest face of
 * this and the earlier layers (kbuf nearest_front / nearest_back) enters the
 * sequence as a front and/or back with id TV_ID_PRIOR, which is never output;
 * its nearest culled back (nearest_culled_back) as TV_ID_PRIOR_CULLED.
 * Without it a trim arriving in a later layer than its occluder's face (a
 * triangle is drawn in its earliest layer only, and objects span layers)
 * would resolve as if that face were absent: everything behind it counted
 * as visible, or the object's back face taken for the terminator.
 */
#ifndef TRIMVR_PVS_RESOLVE_H
#define TRIMVR_PVS_RESOLVE_H

#include <stdbool.h>
#include <stdint.h>

#include "pvs_shared.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Most triangle ids one pvs_resolve_pixel call can output. */
#define PVS_RESOLVE_MAX_OUTPUT (TV_K_FRONT + TV_K_BACK + TV_K_CARRY)

/* The four k-buffers of one pixel for the current layer. */
typedef struct pvs_kbuf {
    uint32_t front_count, back_count, trim_count, umbra_count; /* may exceed K */
    float front_depth[TV_K_FRONT];
    uint32_t front_tri[TV_K_FRONT];
    float back_depth[TV_K_BACK];
    uint32_t back_tri[TV_K_BACK];
    float trim_depth[TV_K_TRIM];
    uint32_t trim_region[TV_K_TRIM];
    float umbra_depth[TV_K_UMBRA];
    uint32_t umbra_region[TV_K_UMBRA];
    /* Nearest depth of the front / back faces covering the pixel centre over
     * this and every earlier layer (P2's exact pass; 0 or INFINITY: none).
     * Read only when the pixel becomes trimmed (TV_ID_PRIOR). */
    float nearest_front, nearest_back;
    /* The same for culled backs (TV_ID_CULLED), kept apart: they enter as
     * TV_ID_PRIOR_CULLED, which closes an interval and does nothing else. */
    float nearest_culled_back;
    /* Nearest depth of a front (not a candidate) that found the front list
     * full (0: none); pvs_kbuf_push keeps it, as P2's atomicMin does. */
    float front_lost;
    /* Nearest depth of a trim that found the trim list full (0: none). */
    float trim_lost;
} pvs_kbuf;

/* One trim-sequence entry. id: triangle id for fronts and backs, trim-region
 * id for trims and umbrae. */
typedef struct pvs_entry {
    float depth;
    uint32_t kind; /* TV_ENTRY_* */
    uint32_t id;
} pvs_entry;

typedef struct pvs_pixel_state {
    uint32_t stencil; /* TV_STENCIL_*; zero-initialised = untrimmed */
    uint32_t carry_count;
    pvs_entry carry[TV_K_CARRY]; /* kinds FRONT, TRIM, UMBRA; fronts in depth order (trims need not be) */
    /* A hidden range when hide_begin < hide_end: carried to the next layer
     * while trimmed; once sealed, the last one in front of the terminator. */
    float hide_begin, hide_end;
    float term_depth; /* the terminator's depth once sealed */
} pvs_pixel_state;

/* P2's insertion of one fragment of `kind` (TV_ENTRY_FRONT, BACK, TRIM or
 * UMBRA) into the pixel's k-buffer: increments the counter, stores the entry
 * when there is room. Returns false when the list was full; for a front the
 * caller must then keep `id` and ask pvs_spill_output after the resolve.
 * Asserts a valid kind. */
bool pvs_kbuf_push(pvs_kbuf* kbuf, uint32_t kind, float depth, uint32_t id);

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
 * it was already in overflow state (the statistics count these pixels). */
uint32_t pvs_resolve_pixel(pvs_pixel_state* state, const pvs_kbuf* kbuf, uint32_t* out,
                           bool* overflowed);

/* After pvs_resolve_pixel of the layer: whether a front (id with or without
 * TV_ID_CANDIDATE, at the depth it was pushed with) that found the front
 * list full must be added to the PVS. At an overflowed pixel every one; at
 * a pixel left open, every candidate (a lost front would have overflowed
 * it); at a pixel sealed in this layer, the candidates in front of its
 * terminator (lost fronts lie behind it); at an untrimmed pixel none: its
 * visibility buffer holds its nearest face, and P3 ignores its fronts. The
 * GPU's spill draws after P3 decide the same way. */
bool pvs_spill_output(const pvs_pixel_state* state, uint32_t id, float depth);

/* Whether a front or back face at `depth` reaching a sealed pixel in a later
 * layer is output: when it lies in front of the terminator and outside the
 * hidden range kept at sealing. Layers are peeled front to back by octree
 * leaf, but a triangle is drawn in the layer of its earliest leaf only, so a
 * large one may terminate a pixel before the layer holding a nearer face
 * there (found on Sponza: a back face sealed pixels 24 cm behind a ledge
 * drawn four layers later, which eyes in the viewcell see). Asserts that
 * the pixel is sealed. */
bool pvs_sealed_output(const pvs_pixel_state* state, float depth);

#ifdef __cplusplus
}
#endif

#endif
