/* carry.c - a trim region's carried entries (resolve.h, pvs_carry_add): the
 * trims and the umbra of a region that a pixel carries to the next layer,
 * packed two depths an entry (shaders/pvs_carry.glsl mirrors it). A carry of
 * one entry per trim and one per umbra filled TV_K_CARRY on Sponza, where a
 * run carries many regions (docs/journal/2026-12-03-carry.md); packed, the
 * next layer's sequence holds the same trims. */
#include "resolve.h"

bool pvs_carry_add(pvs_entry* carry, uint32_t* count, uint32_t kind, float depth, uint32_t id)
{
    bool trim = kind == TV_ENTRY_TRIM;
    for (uint32_t i = *count; (trim || kind == TV_ENTRY_UMBRA) && i-- > 0;) {
        pvs_entry* e = &carry[i];
        if ((e->kind & TV_CARRY_KIND) != TV_ENTRY_TRIM || e->id != id)
            continue;
        /* the region's last entry: a trim at its depth (a region moved to
         * the run's first front has two there), else its fourth word */
        if (trim && e->kind == TV_ENTRY_TRIM && e->depth == depth) {
            e->kind |= TV_CARRY_TWICE;
            return true;
        }
        if ((e->kind & (TV_CARRY_TRIM2 | TV_CARRY_UMBRA)) == 0 && !(trim && (e->kind & TV_CARRY_TWICE) != 0)) {
            e->kind |= trim ? TV_CARRY_TRIM2 : TV_CARRY_UMBRA;
            e->second = depth;
            return true;
        }
        break;
    }
    if (*count == TV_K_CARRY)
        return false;
    carry[(*count)++] = (pvs_entry){depth, kind, id, 0.0f};
    return true;
}

uint32_t pvs_carry_trims(const pvs_entry* e, float depth[2])
{
    if ((e->kind & TV_CARRY_KIND) != TV_ENTRY_TRIM)
        return 0;
    depth[0] = e->depth;
    depth[1] = (e->kind & TV_CARRY_TWICE) != 0 ? e->depth : e->second;
    return (e->kind & (TV_CARRY_TWICE | TV_CARRY_TRIM2)) != 0 ? 2 : 1;
}

bool pvs_carry_umbra(const pvs_entry* e, uint32_t id, float* depth)
{
    if (e->id != id || (e->kind != TV_ENTRY_UMBRA && (e->kind & TV_CARRY_UMBRA) == 0))
        return false;
    *depth = e->kind == TV_ENTRY_UMBRA ? e->depth : e->second;
    return true;
}
