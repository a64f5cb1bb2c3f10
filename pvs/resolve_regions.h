/* resolve_regions.h - resolve.c's tests of the trim regions of a pixel's sequence, as
 * shaders/pvs_resolve_regions.glsl has them: whether a region meets an interval or a lone back, whether a
 * region has a fragment in front of a run, and the front-patch rule (prior_patch, other_patch). Included by resolve.c
 * alone, after its sequence types; static functions. */
#ifndef TRIMVR_PVS_RESOLVE_REGIONS_H
#define TRIMVR_PVS_RESOLVE_REGIONS_H

/* Whether trim seq[i]'s region meets the depth range [lo, hi] at this pixel. P2 puts a trim quad's fragments at up
 * to three depths: the midpoint of its solid's two planes, at the nearer and (grazing fronts only) at the farther
 * one, those two moved TV_PVS_TRIM_NUDGE towards the other. The solid lies between the planes, so the region meets
 * a range its fragments overlap or straddle (a thin solid's interval can fall between two draws), and a range that
 * starts on its farther plane: a face in that plane (found on oa:oa_dm5; docs/trim-regions.md, "Umbra quad and trim
 * quad") lies behind every draw. With two draws that plane is twice the midpoint less the nearer. When trims were
 * lost, only fragments in front of the nearest lost one count (all of those found room): which ones behind it did
 * depends on arrival order, and the PVS must not. */
static bool region_meets(const seq_entry* seq, uint32_t n, uint32_t i, float lo, float hi, float trims_lost)
{
    float mn = INFINITY, mx = -INFINITY;
    uint32_t count = 0;
    for (uint32_t j = 0; j < n; j++) {
        if (seq[j].kind == TV_ENTRY_TRIM && seq[j].id == seq[i].id && seq[j].depth < trims_lost) {
            mn = fminf(mn, seq[j].depth);
            mx = fmaxf(mx, seq[j].depth);
            count++;
        }
    }
    if (count == 0)
        return false;
    if (mn <= hi && mx >= lo * (float)TV_PVS_TIE_LO)
        return true;
    float far = count == 2 ? 2.0f * mx - mn : mx;
    return count > 1 && fabsf(lo - far) <= 4.0f * TV_PVS_TRIM_NUDGE * far;
}

/* The front patch (pvs/patches.h) of an interval's first front when it is the prior front (TV_ID_PRIOR) and P2's patch
 * slots (TV_PVS_CENTRE_PATCH_LO, _HI) name one patch at exactly its depth; else TV_PVS_PATCH_NONE. The eyes see past
 * it only across a silhouette or border of that patch, whose region covers the pixel (docs/pvs-edge-cases.md,
 * "Regions behind a prior front"). */
static uint32_t prior_patch(const pvs_kbuf* k, const seq_entry* first)
{
    uint32_t f, lo = k->patch_centre[0], hi = k->patch_centre[2];
    memcpy(&f, &first->depth, sizeof f); /* a carried one: unknown once a nearer front joined the slots */
    bool known = first->id == TV_ID_PRIOR && k->patch_centre[1] == f && k->patch_centre[3] == f && lo == ~hi;
    return known ? lo : TV_PVS_PATCH_NONE;
}

/* Whether trim seq[i]'s region has a nearer-plane draw (two or three draws in front of trims_lost) and is named
 * from a known front patch other than `prior`: never the region an eye that sees past the prior front needs. */
static bool other_patch(const pvs_kbuf* k, const seq_entry* seq, uint32_t n, uint32_t i, uint32_t prior,
                        float trims_lost)
{
    uint32_t count = 0, id = seq[i].id, r = id & ~TV_REGION_CRACK;
    for (uint32_t j = 0; j < n; j++)
        count += seq[j].kind == TV_ENTRY_TRIM && seq[j].id == id && seq[j].depth < trims_lost;
    uint32_t l = k->region_patch && r < k->region_patches ? k->region_patch[r] : TV_PVS_PATCH_NONE;
    return count > 1 && prior != TV_PVS_PATCH_NONE && id != TV_ID_PRIOR && l != TV_PVS_PATCH_NONE && l != prior;
}

/* Whether trim region `id` has a fragment among seq[0, n). */
static bool region_in(const seq_entry* seq, uint32_t n, uint32_t id)
{
    for (uint32_t j = 0; j < n; j++) {
        if (seq[j].kind == TV_ENTRY_TRIM && seq[j].id == id)
            return true;
    }
    return false;
}

/* Whether a trim region meets lone back seq[b] (region_meets with the
 * range [b, b]), or a lost trim may: its surface is eroded at this pixel,
 * as a validated interval's is. Giving it a hidden range up to the nearest
 * umbra of those regions, as an interval gets, changed no PVS by more than
 * 0.3 % (2026-11-24), so it has none. */
static bool lone_eroded(const seq_entry* seq, uint32_t n, uint32_t b, float trims_lost)
{
    float d = seq[b].depth;
    if (d >= trims_lost)
        return true;
    for (uint32_t i = 0; i < n; i++) {
        if (seq[i].kind == TV_ENTRY_TRIM && seq[i].depth < trims_lost && region_meets(seq, n, i, d, d, trims_lost))
            return true;
    }
    return false;
}

#endif
