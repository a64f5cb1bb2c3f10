// pvs_kread.glsl - P3's reads of a pixel's k-buffers through their pages
// (pvs_kbuf_read of pvs/kbuffer.c). The includer, pvs_resolve.glsl, declares
// the pixel P and its counters cnt.
#ifndef TV_PVS_KREAD_GLSL
#define TV_PVS_KREAD_GLSL

// A walk over list `list` of the pixel (TV_PVS_LISTS order) through its
// pages: its first min(count, k) slots, skipping holes (entries the pool
// had no page for; their chain may also end early). regions: FLAT's
// kregions holds its pages (kb_flat_page).
struct kb_cursor {
    uint page, slot, end;
    bool regions;
};

kb_cursor kb_open(uint list)
{
    return kb_cursor(KB_PAGED ? kheads[TV_PVS_LISTS * P + list] : kb_flat_page(P, list), 0u, min(cnt[list], view.k_lists), // the region lists: kb_open_regions
                     !KB_PAGED && list >= 2u);
}

// The cursor's next slot, a hole or not (past the end of a chain cut short,
// a hole); false at its end.
bool kb_read(inout kb_cursor c, out uvec2 e)
{
    e = uvec2(TV_PVS_HOLE, 0u);
    if (c.slot >= c.end)
        return false;
    uint at = TV_PVS_PAGE * (c.page - 1u) + c.slot % TV_PVS_PAGE;
    if (c.page != TV_PVS_NO_PAGE)
        e = c.regions ? kregions[at] : kpool[at];
    if (++c.slot % TV_PVS_PAGE == 0u && c.page != TV_PVS_NO_PAGE)
        c.page = KB_PAGED ? klinks[c.page - 1u] : c.page + 1u;
    return true;
}

bool kb_next(inout kb_cursor c, out uvec2 e)
{
    while (kb_read(c, e)) {
        if (e.x != TV_PVS_HOLE)
            return true;
    }
    return false;
}

// The pixel's region list (TV_PVS_REGION_SLOTS in pvs_shared.h): the trim
// list's first min(count, k) pairs of slots, read on into the umbra list,
// an entry with a hole in either slot skipped (its region was lost).
struct kb_regions {
    kb_cursor c;
    uint left; // slots still to read after c's list
};

kb_regions kb_open_regions()
{
    uint slots = TV_PVS_REGION_SLOTS * min(cnt.z, view.k_regions);
    kb_cursor c = kb_open(2u);
    c.end = min(slots, view.k);
    return kb_regions(c, slots - c.end);
}

// kb_read over the trim list, then on into the umbra list.
bool kb_slot(inout kb_regions r, out uvec2 e)
{
    if (r.c.slot == r.c.end && r.left > 0u) {
        r.c = kb_open(3u);
        r.c.end = r.left;
        r.left = 0u;
    }
    return kb_read(r.c, e);
}

// The next entry: a = (trim depth, region id), b = (umbra depth, second
// trim depth), depth bits 0 for none.
bool kb_next_region(inout kb_regions r, out uvec2 a, out uvec2 b)
{
    b = uvec2(0u);
    while (kb_slot(r, a) && kb_slot(r, b)) {
        if (a.x != TV_PVS_HOLE && b.x != TV_PVS_HOLE)
            return true;
    }
    return false;
}

#endif
