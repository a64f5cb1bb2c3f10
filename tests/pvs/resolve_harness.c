#include "resolve_harness.h"

#include <assert.h>
#include <string.h>

uint32_t harness_pages = HARNESS_MAX_PAGES;
uint32_t harness_k_exact, harness_k_lists;
uint32_t (*harness_tri_patch)(uint32_t id);
const uint32_t* harness_region_patch;
uint32_t harness_region_patches;

/* centre: P2's prior faces at the pixel centre over this and the earlier layers (TV_PVS_CENTRE_*; 0: none). */
static layer_result run_layer_centre(pvs_pixel_state* s, const float centre[TV_PVS_CENTRE_STRIDE], const item* items,
                                     uint32_t n)
{
    static uint32_t slots[HARNESS_MAX_PAGES * TV_PVS_PAGE][2], links[HARNESS_MAX_PAGES];
    assert(harness_pages <= HARNESS_MAX_PAGES);
    pvs_kpages pages = {slots, links, harness_pages, 0};
    pvs_kbuf k;
    memset(&k, 0, sizeof k);
    k.k_exact = harness_k_exact;
    k.k_lists = harness_k_lists;
    k.nearest_front = centre[TV_PVS_CENTRE_FRONT];
    k.nearest_back = centre[TV_PVS_CENTRE_BACK];
    k.nearest_culled_back = centre[TV_PVS_CENTRE_CULLED];
    k.culled_behind = centre[TV_PVS_CENTRE_CULLED_BEHIND];
    memcpy(k.patch_centre, centre + TV_PVS_CENTRE_PATCH_LO, sizeof k.patch_centre);
    k.region_patch = harness_region_patch;
    k.region_patches = harness_region_patches;
    layer_result r = {0};
    for (uint32_t i = 0; i < n; i++) {
        if (!pvs_kbuf_push(&k, &pages, items[i].kind, items[i].depth, items[i].id) && items[i].kind == TV_ENTRY_FRONT)
            r.spilled[r.spilled_count++] = items[i].id;
    }
    r.pages_taken = pages.taken;
    pvs_kbuf_read(&k, &pages);
    r.count = pvs_resolve_pixel(s, &k, r.out, &r.overflowed);
    for (uint32_t i = 0, j = 0; i < n; i++) {
        if (j < r.spilled_count && items[i].kind == TV_ENTRY_FRONT && items[i].id == r.spilled[j]) {
            if (pvs_spill_output(s, items[i].id, items[i].depth))
                r.spill_ids[r.spill_out++] = items[i].id & ~TV_ID_CANDIDATE;
            j++;
        }
    }
    return r;
}

layer_result run_layer_prior(pvs_pixel_state* s, float prior_front, float prior_back, const item* items, uint32_t n)
{
    return run_layer_centre(s, (const float[TV_PVS_CENTRE_STRIDE]){prior_front, prior_back}, items, n);
}

/* P2's exact pass at the centre: the layer's fronts first (PASS_FRONTS), then its backs, candidates not at all. */
layer_result run_layer_kept(pvs_pixel_state* s, float centre[TV_PVS_CENTRE_STRIDE], const item* items, uint32_t n)
{
    for (uint32_t pass = 0; pass < 2; pass++) {
        for (uint32_t i = 0; i < n; i++) {
            if (items[i].kind == (pass ? TV_ENTRY_BACK : TV_ENTRY_FRONT) && !(items[i].id & TV_ID_CANDIDATE))
                pvs_centre_store(centre, items[i].kind, items[i].depth, items[i].id,
                                 harness_tri_patch ? harness_tri_patch(items[i].id) : TV_PVS_PATCH_NONE);
        }
    }
    return run_layer_centre(s, centre, items, n);
}

layer_result run_layer(pvs_pixel_state* s, const item* items, uint32_t n)
{
    return run_layer_prior(s, 0.0f, 0.0f, items, n);
}

/* Output equals exactly the ids in `want` (order free). */
bool same_set(const layer_result* r, const uint32_t* want, uint32_t n)
{
    if (r->count != n)
        return false;
    for (uint32_t i = 0; i < n; i++) {
        bool found = false;
        for (uint32_t j = 0; j < r->count; j++)
            found |= r->out[j] == want[i];
        if (!found)
            return false;
    }
    return true;
}
