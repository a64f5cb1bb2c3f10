/* kbuffer.c - P2's side of the per-pixel storage of resolve.h, as
 * pvs_kbuffer.glsl has it on the GPU (the lists in pages of a pool, read back
 * as P3 reads them): what a fragment stores, and which
 * fragments of a pixel P3 has sealed or overflowed still reach the PVS. */
#include "resolve.h"

#include <assert.h>
#include <math.h>
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
 * pages; false where the pool has no page for it. */
static bool store_bits(pvs_kbuf* kbuf, pvs_kpages* pages, uint32_t list, uint32_t slot, uint32_t e0, uint32_t e1)
{
    uint32_t page = follow(pages, &kbuf->head[list]);
    for (uint32_t i = slot / TV_PVS_PAGE; i > 0 && page != TV_PVS_NO_PAGE; i--)
        page = follow(pages, &pages->links[page - 1]);
    if (page == TV_PVS_NO_PAGE)
        return false;
    uint32_t* e = pages->slots[TV_PVS_PAGE * (page - 1) + slot % TV_PVS_PAGE];
    e[0] = e0;
    e[1] = e1;
    return true;
}

static uint32_t bits(float depth)
{
    uint32_t b;
    memcpy(&b, &depth, sizeof b);
    return b;
}

static float bits_depth(uint32_t b)
{
    float d;
    memcpy(&d, &b, sizeof d);
    return d;
}

/* A slot the pool has no page for marks the counter. */
static bool store(pvs_kbuf* kbuf, pvs_kpages* pages, uint32_t list, uint32_t* counter, uint32_t slot, float depth,
                  uint32_t id)
{
    if (store_bits(kbuf, pages, list, slot, bits(depth), id))
        return true;
    *counter |= TV_PVS_COUNT_LOST;
    return false;
}

/* Entry r's two slots in the region list (TV_PVS_REGION_SLOTS): slot s of
 * the trim list below K, else slot s - K of the umbra list. */
static bool store_entry(pvs_kbuf* kbuf, pvs_kpages* pages, uint32_t r, const uint32_t e[4])
{
    for (uint32_t i = 0; i < TV_PVS_REGION_SLOTS; i++) {
        uint32_t s = TV_PVS_REGION_SLOTS * r + i;
        if (!store_bits(kbuf, pages, s < TV_K_TRIM ? 2 : 3, s < TV_K_TRIM ? s : s - TV_K_TRIM, e[2 * i], e[2 * i + 1]))
            return false;
    }
    return true;
}

static void keep_nearest(float* lost, float depth)
{
    if (*lost == 0.0f || depth < *lost)
        *lost = depth;
}

/* Claims entry r and stores it; where it finds no room, a claimed entry
 * marks the counter. */
static bool push_entry(pvs_kbuf* kbuf, pvs_kpages* pages, const uint32_t e[4])
{
    uint32_t r;
    if (claim(&kbuf->trim_count, TV_K_TRIM, &r) && store_entry(kbuf, pages, r, e)) {
        memcpy(kbuf->entry_bits[r], e, sizeof kbuf->entry_bits[r]);
        return true;
    }
    if (r < TV_K_TRIM)
        kbuf->trim_count |= TV_PVS_COUNT_LOST;
    return false;
}

bool pvs_kbuf_push_region(pvs_kbuf* kbuf, pvs_kpages* pages, float trim, float second, float umbra, uint32_t id)
{
    assert(kbuf && pages);
    if (trim == 0.0f && second == 0.0f)
        return false;
    const uint32_t e[4] = {bits(trim), id, bits(umbra), bits(second)};
    if (push_entry(kbuf, pages, e))
        return true;
    keep_nearest(&kbuf->trim_lost, trim == 0.0f ? second : second == 0.0f ? trim : fminf(trim, second));
    return false;
}

/* A trim or umbra pushed alone (pvs_kbuf_push_region says how). */
static bool push_joined(pvs_kbuf* kbuf, pvs_kpages* pages, uint32_t kind, float depth, uint32_t id)
{
    uint32_t stored = kbuf->trim_count < TV_K_TRIM ? kbuf->trim_count : TV_K_TRIM;
    for (uint32_t r = 0; r < stored; r++) {
        uint32_t* e = kbuf->entry_bits[r];
        uint32_t free_slot = kind == TV_ENTRY_UMBRA ? 2 : e[0] == 0 ? 0 : 3;
        if ((e[0] | e[2] | e[3]) != 0 && e[1] == id && e[free_slot] == 0) {
            e[free_slot] = bits(depth);
            return store_entry(kbuf, pages, r, e);
        }
    }
    if (kind == TV_ENTRY_TRIM)
        return pvs_kbuf_push_region(kbuf, pages, depth, 0.0f, 0.0f, id);
    const uint32_t u[4] = {0, id, bits(depth), 0};
    return kbuf->trim_count < TV_K_TRIM && push_entry(kbuf, pages, u); /* a full list drops it uncounted */
}

/* One 64-bit slot of centre[] (two uints, low first, as the GPU's little-endian uint64): atomicMin. */
static void centre_min64(float* slot, uint64_t v)
{
    uint32_t w[2];
    memcpy(w, slot, sizeof w);
    if (v < ((uint64_t)w[1] << 32 | w[0])) {
        w[0] = (uint32_t)v;
        w[1] = (uint32_t)(v >> 32);
        memcpy(slot, w, sizeof w);
    }
}

void pvs_centre_store(float centre[TV_PVS_CENTRE_STRIDE], uint32_t kind, float depth, uint32_t id, uint32_t label)
{
    if (kind == TV_ENTRY_FRONT) {
        uint64_t d = (uint64_t)bits(depth) << 32;
        centre_min64(centre + TV_PVS_CENTRE_PATCH_LO, d | label);
        centre_min64(centre + TV_PVS_CENTRE_PATCH_HI, d | (uint32_t)~label);
    }
    assert(kind == TV_ENTRY_FRONT || kind == TV_ENTRY_BACK);
    bool culled = kind == TV_ENTRY_BACK && (id & TV_ID_CULLED) != 0;
    uint32_t slot = kind == TV_ENTRY_FRONT ? TV_PVS_CENTRE_FRONT : culled ? TV_PVS_CENTRE_CULLED : TV_PVS_CENTRE_BACK;
    centre[slot] = fminf(centre[slot], depth);
    if (culled && TV_PVS_PRIOR_CULLED_BEHIND(centre[TV_PVS_CENTRE_FRONT], depth))
        centre[TV_PVS_CENTRE_CULLED_BEHIND] = fminf(centre[TV_PVS_CENTRE_CULLED_BEHIND], depth);
}

bool pvs_kbuf_push(pvs_kbuf* kbuf, pvs_kpages* pages, uint32_t kind, float depth, uint32_t id)
{
    assert(kbuf && pages);
    uint32_t s;
    switch (kind) {
    case TV_ENTRY_FRONT:
        if (!claim(&kbuf->front_count, pvs_kbuf_capacity(kbuf, TV_K_FRONT), &s) ||
            !store(kbuf, pages, 0, &kbuf->front_count, s, depth, id)) {
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
        return claim(&kbuf->back_count, pvs_kbuf_capacity(kbuf, TV_K_BACK), &s) &&
               store(kbuf, pages, 1, &kbuf->back_count, s, depth, id);
    case TV_ENTRY_TRIM:
    case TV_ENTRY_UMBRA:
        return push_joined(kbuf, pages, kind, depth, id);
    default:
        assert(!"pvs_kbuf_push: kind must be FRONT, BACK, TRIM or UMBRA");
        return false;
    }
}

/* kb_read of pvs_kread.glsl: the first `slots` slots of a list, holes
 * included (past a chain cut short, holes). */
static void read_slots(const pvs_kpages* pages, uint32_t head, uint32_t slots, uint32_t (*out)[2])
{
    uint32_t page = head;
    for (uint32_t s = 0; s < slots; s++) {
        out[s][0] = TV_PVS_HOLE;
        out[s][1] = 0;
        if (page == TV_PVS_NO_PAGE)
            continue;
        memcpy(out[s], pages->slots[TV_PVS_PAGE * (page - 1) + s % TV_PVS_PAGE], sizeof out[s]);
        if ((s + 1) % TV_PVS_PAGE == 0)
            page = pages->links[page - 1];
    }
}

/* kb_next of pvs_kread.glsl: the first min(count, capacity) slots of a
 * list, holes skipped. */
static uint32_t read_list(const pvs_kpages* pages, uint32_t head, uint32_t count, uint32_t capacity, float* depth,
                          uint32_t* id)
{
    uint32_t raw[TV_K_FRONT > TV_K_BACK ? TV_K_FRONT : TV_K_BACK][2], n = 0, slots = count < capacity ? count : capacity;
    read_slots(pages, head, slots, raw);
    for (uint32_t s = 0; s < slots; s++) {
        if (raw[s][0] != TV_PVS_HOLE) {
            depth[n] = bits_depth(raw[s][0]);
            id[n++] = raw[s][1];
        }
    }
    return n;
}

void pvs_kbuf_read(pvs_kbuf* kbuf, const pvs_kpages* pages)
{
    assert(kbuf && pages);
    kbuf->front_held = read_list(pages, kbuf->head[0], kbuf->front_count, pvs_kbuf_capacity(kbuf, TV_K_FRONT),
                                 kbuf->front_depth, kbuf->front_tri);
    kbuf->back_held = read_list(pages, kbuf->head[1], kbuf->back_count, pvs_kbuf_capacity(kbuf, TV_K_BACK),
                                kbuf->back_depth, kbuf->back_tri);
    kbuf->trim_held = kbuf->umbra_held = 0;
    uint32_t slots = TV_PVS_REGION_SLOTS * (kbuf->trim_count < TV_K_TRIM ? kbuf->trim_count : TV_K_TRIM);
    uint32_t raw[2 * TV_K_TRIM][2];
    read_slots(pages, kbuf->head[2], slots < TV_K_TRIM ? slots : TV_K_TRIM, raw);
    if (slots > TV_K_TRIM)
        read_slots(pages, kbuf->head[3], slots - TV_K_TRIM, raw + TV_K_TRIM);
    for (uint32_t s = 0; s < slots; s += TV_PVS_REGION_SLOTS) {
        const uint32_t* a = raw[s];
        const uint32_t* b = raw[s + 1];
        if (a[0] == TV_PVS_HOLE || b[0] == TV_PVS_HOLE)
            continue; /* its region was lost */
        uint32_t region = a[1];
        const float trims[2] = {bits_depth(a[0]), bits_depth(b[1])};
        for (uint32_t i = 0; i < 2; i++) {
            if (trims[i] != 0.0f) {
                kbuf->trim_depth[kbuf->trim_held] = trims[i];
                kbuf->trim_region[kbuf->trim_held++] = region;
            }
        }
        if (b[0] != 0) {
            kbuf->umbra_depth[kbuf->umbra_held] = bits_depth(b[0]);
            kbuf->umbra_region[kbuf->umbra_held++] = region;
        }
    }
}

bool pvs_kbuf_deep(const pvs_kbuf* k)
{
    uint32_t e = k->k_exact;
    bool longer = k->front_count > e || k->back_count > e; /* a long region list alone: resolve.h */
    bool fit = k->front_count <= pvs_kbuf_capacity(k, TV_K_FRONT) && k->back_count <= pvs_kbuf_capacity(k, TV_K_BACK) &&
               k->trim_count <= TV_K_TRIM;
    return e && longer && fit;
}

bool pvs_sealed_output(const pvs_pixel_state* state, float depth)
{
    assert(state && state->stencil == TV_STENCIL_SEALED);
    bool hidden = state->hide_begin < state->hide_end && state->hide_begin < depth && depth < state->hide_end;
    return depth < state->term_depth && !hidden;
}

bool pvs_spill_hidden(const pvs_pixel_state* state, float depth)
{
    return state->spill_lo < depth && depth < state->spill_hi;
}

bool pvs_spill_output(const pvs_pixel_state* state, uint32_t id, float depth)
{
    assert(state);
    if (state->stencil == TV_STENCIL_OVERFLOW)
        return true;
    if ((id & TV_ID_CANDIDATE) == 0 || pvs_spill_hidden(state, depth))
        return false;
    return state->stencil == TV_STENCIL_TRIMMED ||
           (state->stencil == TV_STENCIL_SEALED && depth < state->term_depth);
}

/* The low byte of the bits is the footprint's code: 0 the centre depth itself, else q + 1 for q / 256 of it. The
 * centre keeps 16 significant bits, so centre * q is exact and the GPU decodes the same float. */
#define UMBRA_CODE 0xFFu

float pvs_umbra_centre(float packed)
{
    return bits_depth(bits(packed) & ~UMBRA_CODE);
}

float pvs_umbra_footprint(float packed)
{
    uint32_t code = bits(packed) & UMBRA_CODE;
    float centre = pvs_umbra_centre(packed);
    return code == 0 ? centre : centre * (float)(code - 1) * (1.0f / 256.0f);
}

float pvs_umbra_pack(float centre, float footprint)
{
    if (!(centre > 0.0f && centre < INFINITY))
        return centre; /* none (0) or not a depth */
    uint32_t b = bits(centre) & ~UMBRA_CODE;
    float c = bits_depth(b);
    if (footprint >= c)
        return c;
    /* the largest q <= 254 with c * q / 256 <= footprint; the estimate is off by one at most (rounding of the
     * division, which the GPU may round otherwise), the steps compare exact products */
    float q = fminf(fmaxf(floorf(footprint / c * 256.0f), 0.0f), 254.0f);
    if (q > 0.0f && c * q * (1.0f / 256.0f) > footprint)
        q -= 1.0f;
    if (q < 254.0f && c * (q + 1.0f) * (1.0f / 256.0f) <= footprint)
        q += 1.0f;
    return bits_depth(b | ((uint32_t)q + 1u));
}

bool pvs_umbra_depth(const pvs_pixel_state* s, const pvs_kbuf* k, uint32_t region, float* depth, float* footprint)
{
    float nearest = INFINITY, fp = INFINITY, u;
    for (uint32_t i = 0; i < k->umbra_held + s->carry_count; i++) {
        if (i < k->umbra_held) { /* this layer's, then the carried ones */
            if (k->umbra_region[i] != region)
                continue;
            u = k->umbra_depth[i];
        } else if (!pvs_carry_umbra(&s->carry[i - k->umbra_held], region, &u)) {
            continue;
        }
        nearest = fminf(nearest, pvs_umbra_centre(u));
        fp = fminf(fp, pvs_umbra_footprint(u));
    }
    if (nearest == INFINITY)
        return false;
    *depth = pvs_kbuf_deep(k) ? fp : nearest;
    *footprint = fp;
    return true;
}
