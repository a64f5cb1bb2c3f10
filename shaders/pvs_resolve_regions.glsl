// pvs_resolve_regions.glsl - pvs/resolve_regions.h: region_meets over a table of the trim sequence's
// regions, region_in, and the front-patch rule (prior_patch, other_patch); included by pvs_resolve.glsl after
// umbra_depth.
// resolve.c scans the whole sequence for a region's fragments at every call,
// and validate and lone_eroded call it per fragment (with umbra_depth's scan
// of the umbrae inside): cubic in the sequence, which spent llvmpipe's loop
// budget (pvs_common.glsl) on long sequences. regions_build gathers once,
// per region, what region_meets and umbra_depth read (every fragment of a
// region gives both the same answer), so the tests below cost no loop.
#ifndef TV_PVS_RESOLVE_REGIONS_GLSL
#define TV_PVS_RESOLVE_REGIONS_GLSL

#define RG_MAX (TV_K_TRIM + TV_K_CARRY) // the list's trims and the carried ones

uint rg_n;
uint rg_id[RG_MAX], rg_count[RG_MAX]; // fragments in front of trims_lost
float rg_mn[RG_MAX], rg_mx[RG_MAX];
float rg_umbra[RG_MAX], rg_umbra_fp[RG_MAX]; // umbra_depth's answers, +inf: none

uint rg_find(uint id)
{
    uint r = 0u;
    while (r < rg_n && rg_id[r] != id)
        r++;
    return r;
}

// The regions of the trims of ent[0, n) in front of trims_lost (set first).
void regions_build(uint n)
{
    const float inf = uintBitsToFloat(0x7F800000u);
    rg_n = 0u;
    for (uint i = 0u; i < n; i++) {
        if (ent[i].kind != TV_ENTRY_TRIM || !(ent[i].depth < trims_lost))
            continue;
        uint r = rg_find(ent[i].id);
        if (r == rg_n) {
            rg_id[r] = ent[i].id;
            rg_count[r] = 0u;
            rg_mn[r] = inf;
            rg_mx[r] = -inf;
            rg_n++;
        }
        rg_mn[r] = min(rg_mn[r], ent[i].depth);
        rg_mx[r] = max(rg_mx[r], ent[i].depth);
        rg_count[r]++;
    }
    // umbra_depth's answers for all regions in one walk of the list and the
    // carry: a walk per region was quadratic in the list, the dearest part of
    // P3 at pixels whose region list is long (docs/journal/2026-12-03-ovf30.md)
    for (uint r = 0u; r < rg_n; r++)
        rg_umbra[r] = rg_umbra_fp[r] = inf;
    uvec2 a, b;
    for (kb_regions c = kb_open_regions(); kb_next_region(c, a, b);) {
        uint r = b.x != 0u ? rg_find(a.y) : rg_n;
        if (r < rg_n)
            umbra_min(kdepth(b.x), rg_umbra[r], rg_umbra_fp[r]);
    }
    for (uint i = 0u; i < carry_count; i++) {
        uint r = rg_find(carry[i].id);
        float u = inf;
        if (r < rg_n && carry_umbra(carry[i], carry[i].id, u))
            umbra_min(u, rg_umbra[r], rg_umbra_fp[r]);
    }
    for (uint r = 0u; deep_pixel() && r < rg_n; r++)
        rg_umbra[r] = rg_umbra_fp[r]; // umbra_depth
}

// resolve.c's region_meets for region r of the table: its fragments overlap
// or straddle [lo, hi], or lo lies on its farther plane.
bool region_meets(uint r, float lo, float hi)
{
    if (rg_mn[r] <= hi && rg_mx[r] >= lo * TV_PVS_TIE_LO)
        return true;
    float far = rg_count[r] == 2u ? 2.0 * rg_mx[r] - rg_mn[r] : rg_mx[r];
    return rg_count[r] > 1u && abs(lo - far) <= 4.0 * TV_PVS_TRIM_NUDGE * far;
}

bool region_in(uint n, uint id)
{
    for (uint j = 0u; j < n; j++)
        if (ent[j].kind == TV_ENTRY_TRIM && ent[j].id == id)
            return true;
    return false;
}

// resolve_regions.h's prior_patch: the front patch of an interval starting at the prior front, TV_PVS_PATCH_NONE
// where unknown (two labels at its depth, or P2's patch slots not at its depth)
uint prior_patch(uint first)
{
    uint c = TV_PVS_CENTRE_STRIDE * P, f = floatBitsToUint(ent[first].depth); // its own: see resolve_regions.h
    uint lo = centre_depth[c + TV_PVS_CENTRE_PATCH_LO], hi = centre_depth[c + TV_PVS_CENTRE_PATCH_HI];
    bool known = ent[first].id == TV_ID_PRIOR && centre_depth[c + TV_PVS_CENTRE_PATCH_LO + 1u] == f &&
                 centre_depth[c + TV_PVS_CENTRE_PATCH_HI + 1u] == f && lo == ~hi;
    return known ? lo : TV_PVS_PATCH_NONE;
}

// resolve_regions.h's other_patch: region id named from a known front patch other than `prior`
bool other_patch(uint id, uint prior)
{
    uint r = id & ~TV_REGION_CRACK, l = r < 3u * patch_drawn() ? patch_label[patch_drawn() + r] : TV_PVS_PATCH_NONE;
    return prior != TV_PVS_PATCH_NONE && id != TV_ID_PRIOR && l != TV_PVS_PATCH_NONE && l != prior;
}

#endif
