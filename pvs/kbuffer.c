/* kbuffer.c - P2's side of the per-pixel storage of resolve.h, as
 * pvs_kbuffer.glsl has it on the GPU: what a fragment stores, and which
 * fragments of a pixel P3 has sealed or overflowed still reach the PVS. */
#include "resolve.h"

#include <assert.h>

/* The counter always advances, as P2's atomic does, so that a value above
 * the capacity tells P3 the list overflowed; the slot is usable below it. */
static bool claim(uint32_t* counter, uint32_t capacity, uint32_t* slot)
{
    *slot = (*counter)++;
    return *slot < capacity;
}

bool pvs_kbuf_push(pvs_kbuf* kbuf, uint32_t kind, float depth, uint32_t id)
{
    uint32_t s;
    switch (kind) {
    case TV_ENTRY_FRONT:
        if (!claim(&kbuf->front_count, TV_K_FRONT, &s)) {
            float* lost = (id & TV_ID_CANDIDATE) ? &kbuf->candidate_lost : &kbuf->front_lost;
            if (*lost == 0.0f || depth < *lost)
                *lost = depth;
            return false;
        }
        kbuf->front_depth[s] = depth;
        kbuf->front_tri[s] = id;
        return true;
    case TV_ENTRY_BACK:
        /* Candidate backs fill at most half the list: a real back they
         * pushed out would merge two intervals (more output). They are
         * dropped without a count, so the list does not read as overflowed. */
        if ((id & TV_ID_CANDIDATE) != 0 && kbuf->back_count >= TV_K_BACK / 2)
            return false;
        if (!claim(&kbuf->back_count, TV_K_BACK, &s))
            return false;
        kbuf->back_depth[s] = depth;
        kbuf->back_tri[s] = id;
        return true;
    case TV_ENTRY_TRIM:
        if (!claim(&kbuf->trim_count, TV_K_TRIM, &s)) {
            if (kbuf->trim_lost == 0.0f || depth < kbuf->trim_lost)
                kbuf->trim_lost = depth;
            return false;
        }
        kbuf->trim_depth[s] = depth;
        kbuf->trim_region[s] = id;
        return true;
    case TV_ENTRY_UMBRA:
        if (!claim(&kbuf->umbra_count, TV_K_UMBRA, &s))
            return false;
        kbuf->umbra_depth[s] = depth;
        kbuf->umbra_region[s] = id;
        return true;
    default:
        assert(!"pvs_kbuf_push: kind must be FRONT, BACK, TRIM or UMBRA");
        return false;
    }
}

bool pvs_sealed_output(const pvs_pixel_state* state, float depth)
{
    assert(state && state->stencil == TV_STENCIL_SEALED);
    bool hidden = state->hide_begin < state->hide_end && state->hide_begin < depth && depth < state->hide_end;
    return depth < state->term_depth && !hidden;
}

bool pvs_spill_output(const pvs_pixel_state* state, uint32_t id, float depth)
{
    assert(state);
    if (state->stencil == TV_STENCIL_OVERFLOW)
        return true;
    if ((id & TV_ID_CANDIDATE) == 0)
        return false;
    return state->stencil == TV_STENCIL_TRIMMED ||
           (state->stencil == TV_STENCIL_SEALED && depth < state->term_depth);
}
