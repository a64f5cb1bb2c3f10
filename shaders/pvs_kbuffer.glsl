// pvs_kbuffer.glsl - P2's k-buffer insertion (pvs_kbuf_push of
// pvs/kbuffer.c): the counter always increments, so a count above k tells P3
// that the list overflowed; the entry is stored, in a page of the pool, only
// when there is room.
#ifndef TV_PVS_KBUFFER_GLSL
#define TV_PVS_KBUFFER_GLSL

#include "pvs_common.glsl"

// A tile renders the whole image with a scissor (pvs/tiles.h): the per-pixel
// buffers hold the tile, row by row.
uint pvs_pixel() { return (uint(gl_FragCoord.y) - view.tile_y) * view.tile_w + uint(gl_FragCoord.x) - view.tile_x; }

// Depth stored in every k-buffer: the distance from v* along the view axis
// (clip w), monotonic along each pixel's ray as resolve.h requires.
float pvs_depth() { return 1.0 / gl_FragCoord.w; }

bool pvs_sealed(uint p) { return pixstate[p].x == TV_STENCIL_SEALED; }

// pvs_sealed_output of resolve.h: a sealed pixel keeps its terminator's
// depth in y and the last hidden range in front of it in z, w.
bool pvs_sealed_output(uint p, float depth)
{
    uvec4 st = pixstate[p];
    float lo = uintBitsToFloat(st.z), hi = uintBitsToFloat(st.w);
    return depth < uintBitsToFloat(st.y) && !(lo < hi && lo < depth && depth < hi);
}

void pvs_mark_active(uint p)
{
    if (atomicExchange(active_flag[p], 1u) != 0u)
        return;
    uint slot = atomicAdd(counters[TV_PVS_C_ACTIVE], 1u);
    active_list[slot] = p;
    if (slot % TV_WG_SIZE == 0u)
        atomicAdd(counters[TV_PVS_C_DISPATCH], 1u); // one P3 workgroup per TV_WG_SIZE pixels
}

// The page a link leads to (head: pixel p's head of a list at `at`, else the
// page whose next link it is), taking a fresh page from the pool where the
// link is missing: the first fragment to install its page with a
// compare-and-swap wins, a loser's page stays unused, nobody waits.
// TV_PVS_NO_PAGE when the pool is exhausted. The allocator counts on past
// the pool's end, so pvs_compute sees from the count (copied after each
// layer's P2) that the pool was too small; it then grows the pool and
// computes again. Heads and links are cleared before each layer, so a fresh
// page needs no store before it is published: llvmpipe runs this branch
// under a mask for every fragment, so it is kept to two atomics. Only a
// computation that runs out leaves holes in its lists (in every other, each
// slot below min(count, k) is written), so fresh pages are cleared only
// when pvs_compute computes again with a pool that cannot grow
// (view.kb_holes).
uint pvs_follow(bool head, uint at)
{
    uint link = head ? kheads[at] : klinks[at];
    if (link != TV_PVS_NO_PAGE)
        return link;
    uint fresh = atomicAdd(kalloc[TV_PVS_A_TAKEN], 1u);
    if (fresh >= uint(klinks.length()))
        return TV_PVS_NO_PAGE;
    if (view.kb_holes != 0u) { // a computation that loses entries: the slots that stay empty must read as holes
        for (uint i = 0u; i < TV_PVS_PAGE; i++)
            kpool[TV_PVS_PAGE * fresh + i] = uvec2(TV_PVS_HOLE, 0u);
        memoryBarrierBuffer(); // before another fragment can store into the page
    }
    uint won = head ? atomicCompSwap(kheads[at], TV_PVS_NO_PAGE, fresh + 1u)
                    : atomicCompSwap(klinks[at], TV_PVS_NO_PAGE, fresh + 1u);
    return won == TV_PVS_NO_PAGE ? fresh + 1u : won;
}

// Stores entry e in slot `slot` (< k) of list `list` at pixel p, through the
// list's pages (pvs_kbuf_push in pvs/kbuffer.c; FLAT: slot j of a list's k
// consecutive slots, its pages). False when the PAGED pool had no
// page for it: the list's counter then reads as overflowed
// (TV_PVS_COUNT_LOST) and the caller treats the entry as one past k.
bool pvs_store(uint p, uint list, uint slot, uvec2 e)
{
    if (!KB_PAGED) { // cannot run out
        uint at = TV_PVS_PAGE * (kb_flat_page(p, list) - 1u) + slot;
        if (list < 2u)
            kpool[at] = e;
        else
            kregions[at] = e;
        return true;
    }
    uint page = pvs_follow(true, TV_PVS_LISTS * p + list);
    for (uint i = slot / TV_PVS_PAGE; i > 0u && page != TV_PVS_NO_PAGE; i--)
        page = pvs_follow(false, page - 1u);
    if (page == TV_PVS_NO_PAGE) {
        atomicOr(pixcount[p][list], TV_PVS_COUNT_LOST);
        return false;
    }
    kpool[TV_PVS_PAGE * (page - 1u) + slot % TV_PVS_PAGE] = e;
    return true;
}

// Returns false when the list was full or the pool had no page left (the
// caller handles a lost front; the lost depths make both conservative).
// Only pixels P3 has work for become active: a still untrimmed pixel
// without trim fragments resolves to nothing (pvs_resolve_pixel's early
// return), so faces activate it only once it is trimmed (trims where they
// can change it: pvs_region_activates); the counters of every pixel are
// cleared before each layer instead.
bool pvs_push(uint p, uint kind, float depth, uint id)
{
    if (pixstate[p].x != TV_STENCIL_UNTRIMMED)
        pvs_mark_active(p);
    uint d = floatBitsToUint(depth);
    uvec2 e = uvec2(d, id);
    if (kind == TV_PVS_KIND_FRONT) {
        uint slot = atomicAdd(pixcount[p].x, 1u);
        if (slot >= view.k_lists || !pvs_store(p, 0u, slot, e)) {
            atomicMin(lost[TV_PVS_LOST_STRIDE * p + ((id & TV_ID_CANDIDATE) != 0u ? TV_PVS_LOST_CANDIDATE : TV_PVS_LOST_FRONT)], d);
            return false;
        }
    } else if (kind == TV_PVS_KIND_BACK) {
        if ((id & TV_ID_CANDIDATE) != 0u && pixcount[p].y >= view.k_exact / 2u)
            return false; // pvs_kbuf_push: half the list stays for real backs
        uint slot = atomicAdd(pixcount[p].y, 1u);
        return slot < view.k_lists && pvs_store(p, 1u, slot, e);
    }
    return true;
}

// Slot s of the pixel's region list (TV_PVS_REGION_SLOTS in pvs_shared.h).
bool pvs_store_region(uint p, uint s, uvec2 e)
{
    return s < view.k ? pvs_store(p, 2u, s, e) : pvs_store(p, 3u, s - view.k, e);
}

// One trim region's fragment (pvs_kbuf_push_region of pvs/kbuffer.c): two
// trim depths and the umbra's (0: none) in one entry, so that a list of k
// entries holds k regions where three trim entries each held k / 3. An
// entry without a trim depth is not stored: its umbra pairs with no trim.
// Where it finds no room, its nearer trim depth is the lost trim's.
bool pvs_push_region(uint p, float trim, float second, float umbra, uint id)
{
    if (trim == 0.0 && second == 0.0)
        return false;
    if (pvs_region_activates(pixstate[p]))
        pvs_mark_active(p);
    uint r = atomicAdd(pixcount[p].z, 1u);
    uvec2 a = uvec2(floatBitsToUint(trim), id), b = uvec2(floatBitsToUint(umbra), floatBitsToUint(second));
    if (r < view.k_regions && pvs_store_region(p, TV_PVS_REGION_SLOTS * r, a) &&
        pvs_store_region(p, TV_PVS_REGION_SLOTS * r + 1u, b))
        return true;
    if (r < view.k_regions) // the umbra list's chain too: the counter of the entries reads as lost
        atomicOr(pixcount[p].z, TV_PVS_COUNT_LOST);
    float nearest = trim == 0.0 ? second : second == 0.0 ? trim : min(trim, second);
    atomicMin(lost[TV_PVS_LOST_STRIDE * p + TV_PVS_LOST_TRIM], floatBitsToUint(nearest));
    return false;
}

#endif
