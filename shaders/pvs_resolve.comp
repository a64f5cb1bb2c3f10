#version 460
// P3, first pass: one invocation per active pixel (the list P2 built). A
// trim sequence shorter than COOP_SORT_MIN entries is sorted and resolved
// here (insertion sort); a longer one is left untouched and its pixel
// appended to coop_list for pvs_resolve_group.comp, the paper's hybrid sort
// (section 4.3). The pixel's active flag is reset for the next layer (the
// counters are cleared by a fill before each layer).
#extension GL_GOOGLE_include_directive : require

#define TV_RESOLVE_STORAGE
#define S2 SEQ_MAX
#define TV_RESOLVE_ENTRIES (SEQ_MAX + SEQ2_MAX)
#include "pvs_resolve.glsl"

layout(local_size_x = TV_WG_SIZE) in;

// Sequences of at least this many entries go to the cooperative pass
// (pvs_desc.coop_sort_min; the paper's N = 8).
layout(constant_id = 0) const uint COOP_SORT_MIN = 8u;

void insertion_sort(uint base, uint n)
{
    for (uint i = 1u; i < n; i++) {
        seq_entry x = ent[base + i];
        uint j = i;
        while (j > 0u && entry_less(x, ent[base + j - 1u])) {
            ent[base + j] = ent[base + j - 1u];
            j--;
        }
        ent[base + j] = x;
    }
}

void defer_pixel()
{
    uint slot = atomicAdd(counters[TV_PVS_C_COOP], 1u);
    coop_list[slot] = P;
    atomicMax(counters[TV_PVS_C_DISPATCH_COOP], min(slot + 1u, TV_PVS_MAX_COOP_GROUPS));
    atomicAdd(counters[TV_PVS_C_COOP_TOTAL], 1u);
}

void main()
{
    uint i = gl_GlobalInvocationID.x;
    if (i >= counters[TV_PVS_C_ACTIVE])
        return;
    load_pixel(active_list[i]);
    bool first;
    uint step = resolve_begin(first), n = 0u;
    bool handled = step == RESOLVE_OVERFLOW;
    if (step == RESOLVE_SEQUENCE) {
        n = gather(first);
        if (n >= COOP_SORT_MIN) {
            defer_pixel(); // nothing of the pixel was written yet
            return;
        }
        insertion_sort(0u, n);
        uint m = resolve_intervals(n);
        insertion_sort(S2, m);
        handled = resolve_end(n, m);
    }
    finish_pixel(n, handled);
}
