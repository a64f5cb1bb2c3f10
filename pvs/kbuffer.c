/* kbuffer.c - P2's side of the per-pixel storage of resolve.h, as
 * pvs_kbuffer.glsl has it on the GPU (the lists in pages of a pool, read back
 * as P3 reads them): what a fragment stores, and which
 * fragments of a pixel P3 has sealed or overflowed still reach the PVS. */
#include "resolve.h"

#include <assert.h>
#include <string.h>

/* The counter always advances, as P2's atomic does, so that a value above
 * the capacity tells P3 the list overflowed; the slot is usable below it. */
static bool claim(uint32_t* counter, uint32_t capacity, uint32_t* slot)
{
    *slot = (*counter)++;
    return *slot < capacity;
}

/* pvs_follow of pvs_kbuffer.glsl: the page `link` leads to (+ 1), a fresh
 * one installed where it is missing; TV_PVS_NO_PAGE when the pool is out. */
static uint32_t follow(pvs_kpages* pages, uint32_t* link)
{
    if (*link != TV_PVS_NO_PAGE)
        return *link;
    uint32_t fresh = pages->taken++;
    if (fresh >= pages->page_count)
        return TV_PVS_NO_PAGE;
    pages->links[fresh] = TV_PVS_NO_PAGE;
    for (uint32_t i = 0; i < TV_PVS_PAGE; i++) {
        pages->slots[TV_PVS_PAGE * fresh + i][0] = TV_PVS_HOLE;
        pages->slots[TV_PVS_PAGE * fresh + i][1] = 0;
    }
    *link = fresh + 1;
    return *link;
}

/* pvs_store of pvs_kbuffer.glsl: slot `slot` of list `list` through its
 * pages; a slot the pool has no page for marks the counter. */
static bool store(pvs_kbuf* kbuf, pvs_kpages* pages, uint32_t list, uint32_t* counter, uint32_t slot, float depth,
                  uint32_t id)
{
    uint32_t page = follow(pages, &kbuf->head[list]);
    for (uint32_t i = slot / TV_PVS_PAGE; i > 0 && page != TV_PVS_NO_PAGE; i--)
        page = follow(pages, &pages->links[page - 1]);
    if (page == TV_PVS_NO_PAGE) {
        *counter |= TV_PVS_COUNT_LOST;
        return false;
    }
    uint32_t* e = pages->slots[TV_PVS_PAGE * (page - 1) + slot % TV_PVS_PAGE];
    memcpy(&e[0], &depth, sizeof depth);
    e[1] = id;
    return true;
}

static void keep_nearest(float* lost, float depth)
{
    if (*lost == 0.0f || depth < *lost)
        *lost = depth;
}

bool pvs_kbuf_push(pvs_kbuf* kbuf, pvs_kpages* pages, uint32_t kind, float depth, uint32_t id)
{
    assert(kbuf && pages);
    uint32_t s;
    switch (kind) {
    case TV_ENTRY_FRONT:
        if (!claim(&kbuf->front_count, TV_K_FRONT, &s) || !store(kbuf, pages, 0, &kbuf->front_count, s, depth, id)) {
            keep_nearest((id & TV_ID_CANDIDATE) ? &kbuf->candidate_lost : &kbuf->front_lost, depth);
            return false;
        }
        return true;
    case TV_ENTRY_BACK:
        /* Candidate backs fill at most half the list: a real back they
         * pushed out would merge two intervals (more output). They are
         * dropped without a count, so the list does not read as overflowed. */
        if ((id & TV_ID_CANDIDATE) != 0 && kbuf->back_count >= (kbuf->k_exact ? kbuf->k_exact : TV_K_BACK) / 2)
            return false;
        return claim(&kbuf->back_count, TV_K_BACK, &s) && store(kbuf, pages, 1, &kbuf->back_count, s, depth, id);
    case TV_ENTRY_TRIM:
        if (!claim(&kbuf->trim_count, TV_K_TRIM, &s) || !store(kbuf, pages, 2, &kbuf->trim_count, s, depth, id)) {
            keep_nearest(&kbuf->trim_lost, depth);
            return false;
        }
        return true;
    case TV_ENTRY_UMBRA:
        return claim(&kbuf->umbra_count, TV_K_UMBRA, &s) && store(kbuf, pages, 3, &kbuf->umbra_count, s, depth, id);
    default:
        assert(!"pvs_kbuf_push: kind must be FRONT, BACK, TRIM or UMBRA");
        return false;
    }
}

/* kb_next of pvs_resolve.glsl: the first `slots` slots of a list, holes
 * skipped. */
static uint32_t read_list(const pvs_kpages* pages, uint32_t head, uint32_t count, uint32_t capacity, float* depth,
                          uint32_t* id)
{
    uint32_t n = 0, page = head, slots = count < capacity ? count : capacity;
    for (uint32_t s = 0; s < slots && page != TV_PVS_NO_PAGE;) {
        const uint32_t* e = pages->slots[TV_PVS_PAGE * (page - 1) + s % TV_PVS_PAGE];
        if (++s % TV_PVS_PAGE == 0)
            page = pages->links[page - 1];
        if (e[0] != TV_PVS_HOLE) {
            memcpy(&depth[n], &e[0], sizeof depth[n]);
            id[n++] = e[1];
        }
    }
    return n;
}

void pvs_kbuf_read(pvs_kbuf* kbuf, const pvs_kpages* pages)
{
    assert(kbuf && pages);
    kbuf->front_held = read_list(pages, kbuf->head[0], kbuf->front_count, TV_K_FRONT, kbuf->front_depth, kbuf->front_tri);
    kbuf->back_held = read_list(pages, kbuf->head[1], kbuf->back_count, TV_K_BACK, kbuf->back_depth, kbuf->back_tri);
    kbuf->trim_held = read_list(pages, kbuf->head[2], kbuf->trim_count, TV_K_TRIM, kbuf->trim_depth, kbuf->trim_region);
    kbuf->umbra_held =
        read_list(pages, kbuf->head[3], kbuf->umbra_count, TV_K_UMBRA, kbuf->umbra_depth, kbuf->umbra_region);
}

bool pvs_kbuf_deep(const pvs_kbuf* k)
{
    uint32_t e = k->k_exact;
    bool longer = k->front_count > e || k->back_count > e || k->trim_count > e || k->umbra_count > e;
    bool fit = k->front_count <= TV_K_FRONT && k->back_count <= TV_K_BACK && k->trim_count <= TV_K_TRIM &&
               k->umbra_count <= TV_K_UMBRA;
    return e && longer && fit;
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
