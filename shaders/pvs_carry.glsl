// pvs_carry.glsl - a trim region's carried entries, packed two depths an
// entry (pvs/carry.c, which this mirrors; TV_CARRY_* in pvs_shared.h).
// Included by pvs_resolve.glsl, whose carry_run builds the next carry in
// carry_next.
#ifndef TV_PVS_CARRY_GLSL
#define TV_PVS_CARRY_GLSL

struct carry_entry {
    float depth;
    uint kind; // TV_ENTRY_*, a trim's with TV_CARRY_* flags
    uint id;
    float second; // of TV_CARRY_TRIM2 or TV_CARRY_UMBRA, else 0
};

carry_entry carry_next[TV_K_CARRY];
uint carry_next_count;

// pvs_carry_add: a trim or umbra joins its region's last entry where that
// has room, anything else takes a new entry; false when the carry is full.
bool carry_add(uint kind, float depth, uint id)
{
    bool trim = kind == TV_ENTRY_TRIM;
    for (uint i = carry_next_count; (trim || kind == TV_ENTRY_UMBRA) && i-- > 0u;) {
        carry_entry e = carry_next[i];
        if ((e.kind & TV_CARRY_KIND) != TV_ENTRY_TRIM || e.id != id)
            continue;
        if (trim && e.kind == TV_ENTRY_TRIM && e.depth == depth) {
            carry_next[i].kind |= TV_CARRY_TWICE;
            return true;
        }
        if ((e.kind & (TV_CARRY_TRIM2 | TV_CARRY_UMBRA)) == 0u && !(trim && (e.kind & TV_CARRY_TWICE) != 0u)) {
            carry_next[i].kind |= trim ? TV_CARRY_TRIM2 : TV_CARRY_UMBRA;
            carry_next[i].second = depth;
            return true;
        }
        break;
    }
    if (carry_next_count == TV_K_CARRY)
        return false;
    carry_next[carry_next_count++] = carry_entry(depth, kind, id, 0.0);
    return true;
}

// pvs_carry_trims: the trim depths entry e holds (0 to 2).
uint carry_trims(carry_entry e, out float d0, out float d1)
{
    d0 = e.depth;
    d1 = (e.kind & TV_CARRY_TWICE) != 0u ? e.depth : e.second;
    if ((e.kind & TV_CARRY_KIND) != TV_ENTRY_TRIM)
        return 0u;
    return (e.kind & (TV_CARRY_TWICE | TV_CARRY_TRIM2)) != 0u ? 2u : 1u;
}

// pvs_carry_umbra: whether entry e holds region id's umbra, at depth.
bool carry_umbra(carry_entry e, uint id, inout float depth)
{
    if (e.id != id || (e.kind != TV_ENTRY_UMBRA && (e.kind & TV_CARRY_UMBRA) == 0u))
        return false;
    depth = e.kind == TV_ENTRY_UMBRA ? e.depth : e.second;
    return true;
}

#endif
