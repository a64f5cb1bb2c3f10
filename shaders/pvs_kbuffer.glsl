// pvs_kbuffer.glsl - P2's k-buffer insertion (pvs_kbuf_push of
// pvs/resolve.c): the counter always increments, so a count above k tells P3
// that the list overflowed; the entry is stored only when there is room.
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

// Returns false when the list was full (the caller handles a lost front).
// Only pixels P3 has work for become active: a still untrimmed pixel
// without trim fragments resolves to nothing (pvs_resolve_pixel's early
// return), so faces and umbrae activate it only once it is trimmed; the
// counters of every pixel are cleared before each layer instead.
bool pvs_push(uint p, uint kind, float depth, uint id)
{
    if (kind == TV_PVS_KIND_TRIM || pixstate[p].x != TV_STENCIL_UNTRIMMED)
        pvs_mark_active(p);
    uint slot;
    uint d = floatBitsToUint(depth);
    if (kind == TV_PVS_KIND_FRONT) {
        slot = atomicAdd(pixcount[p].x, 1u);
        if (slot >= view.k) {
            atomicMin(lost[TV_PVS_LOST_STRIDE * p + ((id & TV_ID_CANDIDATE) != 0u ? TV_PVS_LOST_CANDIDATE : TV_PVS_LOST_FRONT)], d);
            return false;
        }
        kfront[p * view.k + slot] = uvec2(d, id);
    } else if (kind == TV_PVS_KIND_BACK) {
        if ((id & TV_ID_CANDIDATE) != 0u && pixcount[p].y >= view.k / 2u)
            return false; // pvs_kbuf_push: half the list stays for real backs
        slot = atomicAdd(pixcount[p].y, 1u);
        if (slot >= view.k)
            return false;
        kback[p * view.k + slot] = uvec2(d, id);
    } else if (kind == TV_PVS_KIND_TRIM) {
        slot = atomicAdd(pixcount[p].z, 1u);
        if (slot >= view.k) {
            atomicMin(lost[TV_PVS_LOST_STRIDE * p + TV_PVS_LOST_TRIM], d);
            return false;
        }
        ktrim[p * view.k + slot] = uvec2(d, id);
    } else {
        slot = atomicAdd(pixcount[p].w, 1u);
        if (slot >= view.k)
            return false;
        kumbra[p * view.k + slot] = uvec2(d, id);
    }
    return true;
}

#endif
