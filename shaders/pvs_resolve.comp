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

// The gathered sequence ent[0, n): every entry has interval -1 and delta 0
// (make_entry), so entry_less reduces to depth, kind, id and only those
// three fields need moving. llvmpipe reads and writes a private array at a
// per-invocation index one lane at a time, field by field: this sort costs
// a fraction of insertion_sort's (docs/pvs-gpu-passes.md, "Cost per phase").
void insertion_sort_gathered(uint n)
{
    for (uint i = 1u; i < n; i++) {
        float d = ent[i].depth;
        uint kind = ent[i].kind, id = ent[i].id;
        uint j = i;
        for (; j > 0u; j--) {
            float ed = ent[j - 1u].depth;
            uint ekind = ent[j - 1u].kind, eid = ent[j - 1u].id;
            if (!(d < ed || (d == ed && (kind < ekind || (kind == ekind && id < eid)))))
                break;
            ent[j].depth = ed;
            ent[j].kind = ekind;
            ent[j].id = eid;
        }
        ent[j].depth = d;
        ent[j].kind = kind;
        ent[j].id = id;
    }
}

// The compare in the loop's body, not its condition: llvmpipe then reads
// each entry it moves once, not twice (about 6 % of P3 there, 2026-12-02).
void insertion_sort(uint base, uint n)
{
    for (uint i = 1u; i < n; i++) {
        seq_entry x = ent[base + i];
        uint j = i;
        for (; j > 0u; j--) {
            seq_entry e = ent[base + j - 1u];
            if (!entry_less(x, e))
                break;
            ent[base + j] = e;
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
        insertion_sort_gathered(n);
        uint m = resolve_intervals(n);
        insertion_sort(S2, m);
        handled = resolve_end(n, m);
    }
    finish_pixel(n, handled);
    if (loop_budget_spent())
        atomicAdd(counters[TV_PVS_C_LOOP_BUDGET], 1u);
}
