#version 460
// P3, second pass: one workgroup per pixel that pvs_resolve.comp deferred
// (a trim sequence of at least COOP_SORT_MIN entries), the parallel half of
// the paper's hybrid sort (section 4.3). The workgroup bitonic-sorts the
// sequence and the re-sorted sequence in shared memory; invocation 0 runs
// the serial steps between the sorts (the same functions as the first
// pass). At most TV_PVS_MAX_COOP_GROUPS groups are dispatched; each loops
// over the deferred pixels with that stride.
#extension GL_GOOGLE_include_directive : require

// Powers of two that hold SEQ_MAX and SEQ2_MAX.
#define SEQ_PAD 256u
#define SEQ2_PAD 256u
#define TV_RESOLVE_STORAGE shared
#define S2 SEQ_PAD
#define TV_RESOLVE_ENTRIES (SEQ_PAD + SEQ2_PAD)
#include "pvs_resolve.glsl"

// A compile error (array size <= 0) when a pad is too small.
int seq_pad_fits[int(SEQ_PAD) - SEQ_MAX + 1];
int seq2_pad_fits[int(SEQ2_PAD) - SEQ2_MAX + 1];

// One subgroup per pixel (pvs/gpu_pipelines.c sets the width), so that the
// barriers cost little.
layout(local_size_x_id = 0) in;

shared uint s_n, s_m;

// Sorts ent[base, base + n) ascending by entry_less; the whole workgroup
// calls it (uniform n). Padding entries sort last and are never read.
void bitonic_sort(uint base, uint n)
{
    uint size = 1u;
    while (size < n)
        size <<= 1;
    const float inf = uintBitsToFloat(0x7F800000u);
    for (uint t = n + gl_LocalInvocationIndex; t < size; t += gl_WorkGroupSize.x)
        ent[base + t] = seq_entry(inf, 0xFFFFFFFFu, 0xFFFFFFFFu, -1, -1);
    barrier();
    for (uint k = 2u; k <= size; k <<= 1) {
        for (uint j = k >> 1; j > 0u; j >>= 1) {
            for (uint t = gl_LocalInvocationIndex; t < size / 2u; t += gl_WorkGroupSize.x) {
                uint lo = (t / j) * 2u * j + t % j, hi = lo + j;
                bool ascending = (lo & k) == 0u;
                if (entry_less(ent[base + hi], ent[base + lo]) == ascending) {
                    seq_entry x = ent[base + lo];
                    ent[base + lo] = ent[base + hi];
                    ent[base + hi] = x;
                }
            }
            barrier();
        }
    }
}

void main()
{
    bool lead = gl_LocalInvocationIndex == 0u;
    uint count = counters[TV_PVS_C_COOP];
    for (uint c = gl_WorkGroupID.x; c < count; c += gl_NumWorkGroups.x) {
        if (lead) {
            load_pixel(coop_list[c]);
            bool first;
            resolve_begin(first); // RESOLVE_SEQUENCE: the first pass deferred it
            s_n = gather(first);
        }
        barrier();
        bitonic_sort(0u, s_n);
        if (lead)
            s_m = resolve_intervals(s_n);
        barrier();
        bitonic_sort(S2, s_m);
        if (lead) {
            finish_pixel(s_n, resolve_end(s_n, s_m));
            if (loop_budget_spent()) // also the later pixels of this group: the budget is the group's
                atomicAdd(counters[TV_PVS_C_LOOP_BUDGET], 1u);
        }
        barrier();
    }
}
