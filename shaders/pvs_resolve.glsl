// pvs_resolve.glsl - P3, the resolve of paper section 4.3, shared by its
// two variants: pvs_resolve.comp (one invocation per active pixel, insertion
// sort) and pvs_resolve_group.comp (one workgroup per pixel whose sequence
// is long, bitonic sort). It mirrors pvs_resolve_pixel in pvs/resolve.c
// function by function (same names, same order, same tie-breaks); the only
// differences: the runtime capacities view.k, k_exact in place of the TV_K_* bounds, kbuf.k_exact,
// that the k-buffers are read through their pages (kb_next) where the C
// reference has arrays (pvs_kbuf_read), and that region_meets reads a table
// of the regions (pvs_resolve_regions.glsl) where resolve.c scans the
// sequence: llvmpipe's loop budget (pvs_common.glsl) bounds the loops here.
// Output ids set their flag in tri_flags.
//
// The includer defines TV_RESOLVE_STORAGE (empty or `shared`), S2 and TV_RESOLVE_ENTRIES (ent[]'s layout).
#ifndef TV_PVS_RESOLVE_GLSL
#define TV_PVS_RESOLVE_GLSL

#include "pvs_common.glsl"

#define SEQ_MAX (2 * (TV_K_CARRY + TV_K_TRIM) + TV_K_FRONT + TV_K_BACK) // two trim depths per region entry
#define IV_MAX (TV_K_BACK + 3 < TV_K_FRONT + TV_K_CARRY ? TV_K_BACK + 3 : TV_K_FRONT + TV_K_CARRY) // + three prior backs
#define SEQ2_MAX (SEQ_MAX + IV_MAX + 2)

struct seq_entry {
    float depth;
    uint kind;
    uint id;
    int interval;
    int delta;
};

#include "pvs_carry.glsl"

// The pixel: state, counters.
uint P;
uvec4 cnt;
uint stencil, carry_count;
float hide_begin, hide_end, hide_end_fp; // resolve.c; while trimmed, pixstate.w packs hide_end and hide_end_fp
carry_entry carry[TV_K_CARRY];

// The trim sequence at ent[0, n), the re-sorted one at ent[S2, S2 + m):
// private to the invocation in pvs_resolve.comp, shared by the workgroup in
// pvs_resolve_group.comp (which pads both to powers of two for bitonic sort).
TV_RESOLVE_STORAGE seq_entry ent[TV_RESOLVE_ENTRIES];
uint iv_count;
uint iv_first[IV_MAX], iv_back[IV_MAX];
bool iv_valid[IV_MAX];
bool iv_show_back[IV_MAX]; // resolve.c's show_back: its back is output with its first front
float trims_lost; // nearest depth of a trim the list had no room for (+inf: none): see validate()
bool iv_hidden[IV_MAX]; // set by the walk: the run starts inside an umbra
float iv_end[IV_MAX], iv_end_fp[IV_MAX]; // resolve.c's end, end_fp
int iv_run;
uint n_out;
float term_depth; // depth of the terminator that sealed the pixel
float spill_lo, spill_hi; // resolve.c's spill span (walk), where a lost candidate is hidden
bool overflow_due; // resolve_overflow is to run in finish_pixel: see there

seq_entry make_entry(float depth, uint kind, uint id, int delta) { return seq_entry(depth, kind, id, -1, delta); }

// resolve.c's total order: entries that compare equal are identical in
// every field, so the per-thread (stable) and cooperative (unstable) sorts
// yield the same sequence.
bool entry_less(seq_entry a, seq_entry b)
{
    if (a.depth != b.depth)
        return a.depth < b.depth;
    if (a.kind != b.kind)
        return a.kind < b.kind;
    if (a.id != b.id)
        return a.id < b.id;
    if (a.delta != b.delta)
        return a.delta > b.delta;
    return uint(a.interval) < uint(b.interval);
}

// The rule of the outputs that follow, for explain mode (pvs_desc.explain):
// TV_REASON_FRONT, or TV_REASON_OVERFLOW once the overflow policy took over.
uint out_reason;

void output_id(uint id)
{
    if (id == TV_ID_PRIOR || (id & TV_ID_CULLED) != 0u)
        return;
    uint reason = out_reason != TV_REASON_FRONT       ? out_reason
                  : (id & TV_ID_CANDIDATE) != 0u      ? TV_REASON_CANDIDATE
                  : (id & TV_ID_STRADDLED) != 0u      ? TV_REASON_STRADDLED
                                                      : TV_REASON_FRONT;
    pvs_mark(id & ~(TV_ID_CANDIDATE | TV_ID_STRADDLED), reason);
    n_out++;
}

// The back of an interval output with its first front (iv_show_back):
// straddled, or else seen through a crack.
void output_shown_back(uint id)
{
    uint rule = out_reason;
    if (rule == TV_REASON_FRONT && (id & TV_ID_STRADDLED) == 0u)
        out_reason = TV_REASON_CRACK;
    output_id(id);
    out_reason = rule;
}

// A candidate front, or a candidate back (pvs_face.frag: the back of a
// triangle narrower than a pixel).
bool is_candidate(seq_entry e)
{
    return (e.kind == TV_ENTRY_FRONT || e.kind == TV_ENTRY_BACK) && (e.id & TV_ID_CANDIDATE) != 0u;
}

// resolve.c's is_candidate_back: neither carried nor deciding the carried
// hidden range.
bool is_candidate_back(seq_entry e) { return e.kind == TV_ENTRY_BACK && is_candidate(e); }

// resolve.c's is_culled: a back the renderer culls from the whole viewcell.
bool is_culled(seq_entry e) { return e.kind == TV_ENTRY_BACK && e.id != TV_ID_PRIOR && (e.id & TV_ID_CULLED) != 0u; }

// resolve.c's is_straddled: a back some eyes see from the front.
bool is_straddled(seq_entry e)
{
    return e.kind == TV_ENTRY_BACK && (e.id & TV_ID_CULLED) == 0u && (e.id & TV_ID_STRADDLED) != 0u;
}

float kdepth(uint bits) { return uintBitsToFloat(bits); }

#include "pvs_kread.glsl"

// The overflow policy: every front this pixel knows of is output and the
// pixel can no longer be sealed.
void resolve_overflow()
{
    out_reason = TV_REASON_OVERFLOW;
    for (uint i = 0u; i < carry_count; i++)
        if (carry[i].kind == TV_ENTRY_FRONT)
            output_id(carry[i].id);
    uvec2 e;
    for (kb_cursor c = kb_open(0u); kb_next(c, e);)
        output_id(e.y);
    for (kb_cursor c = kb_open(1u); kb_next(c, e);)
        output_id(e.y);
    stencil = TV_STENCIL_OVERFLOW;
    carry_count = 0u;
    hide_begin = hide_end = spill_lo = spill_hi = 0.0;
}

// pvs_kbuf_deep: its umbrae count for nothing (resolve.c says why); a long
// region list alone does not make a pixel deep (resolve.h)
bool deep_pixel() { return any(greaterThan(cnt.xy, uvec2(view.k_exact))) && all(lessThanEqual(cnt, kb_capacity())); }

void umbra_min(float u, inout float nearest, inout float fp) { nearest = min(nearest, pvs_umbra_centre(u)); fp = min(fp, pvs_umbra_footprint(u)); }

bool umbra_depth(uint region, inout float depth, inout float footprint)
{
    const float inf = uintBitsToFloat(0x7F800000u);
    float nearest = inf, fp = inf;
    uvec2 a, b;
    for (kb_regions c = kb_open_regions(); kb_next_region(c, a, b);)
        if (a.y == region && b.x != 0u)
            umbra_min(kdepth(b.x), nearest, fp);
    for (uint i = 0u; i < carry_count; i++) {
        float u = inf;
        if (carry_umbra(carry[i], region, u))
            umbra_min(u, nearest, fp);
    }
    if (nearest == inf)
        return false;
    depth = deep_pixel() ? fp : nearest;
    footprint = fp;
    return true;
}

#include "pvs_resolve_regions.glsl"

bool stored_face(uint kind, uint depth_bits)
{
    uvec2 e;
    for (kb_cursor c = kb_open(kind == TV_ENTRY_FRONT ? 0u : 1u); kb_next(c, e);)
        if (e.x == depth_bits)
            return true;
    return false;
}

uint gather(bool first)
{
    uint n = 0u;
    if (first) {
        const uint inf = 0x7F800000u;
        uint c = TV_PVS_CENTRE_STRIDE * P;
        uint f = centre_depth[c + TV_PVS_CENTRE_FRONT], b = centre_depth[c + TV_PVS_CENTRE_BACK];
        uint cb = centre_depth[c + TV_PVS_CENTRE_CULLED], cbb = centre_depth[c + TV_PVS_CENTRE_CULLED_BEHIND];
        if (f < inf && !stored_face(TV_ENTRY_FRONT, f))
            ent[n++] = make_entry(kdepth(f), TV_ENTRY_FRONT, TV_ID_PRIOR, 0);
        if (b < inf && !stored_face(TV_ENTRY_BACK, b))
            ent[n++] = make_entry(kdepth(b), TV_ENTRY_BACK, TV_ID_PRIOR, 0);
        if (cb < inf && !stored_face(TV_ENTRY_BACK, cb))
            ent[n++] = make_entry(kdepth(cb), TV_ENTRY_BACK, TV_ID_PRIOR_CULLED, 0);
        if (cbb < inf && cbb != cb && !stored_face(TV_ENTRY_BACK, cbb))
            ent[n++] = make_entry(kdepth(cbb), TV_ENTRY_BACK, TV_ID_PRIOR_CULLED, 0);
    }
    for (uint i = 0u; i < carry_count; i++) {
        float t0, t1;
        uint t = carry_trims(carry[i], t0, t1);
        if (carry[i].kind == TV_ENTRY_FRONT)
            ent[n++] = make_entry(carry[i].depth, TV_ENTRY_FRONT, carry[i].id, 0);
        if (t > 0u)
            ent[n++] = make_entry(t0, TV_ENTRY_TRIM, carry[i].id, 0);
        if (t > 1u)
            ent[n++] = make_entry(t1, TV_ENTRY_TRIM, carry[i].id, 0);
    }
    uvec2 e, b;
    for (uint l = 0u; l < 2u; l++)
        for (kb_cursor c = kb_open(l); kb_next(c, e);)
            ent[n++] = make_entry(kdepth(e.x), l == 0u ? TV_ENTRY_FRONT : TV_ENTRY_BACK, e.y, 0);
    for (kb_regions c = kb_open_regions(); kb_next_region(c, e, b);) {
        if (e.x != 0u) // pvs_kbuf_read: an entry's trim depths, each a trim of its region
            ent[n++] = make_entry(kdepth(e.x), TV_ENTRY_TRIM, e.y, 0);
        if (b.y != 0u)
            ent[n++] = make_entry(kdepth(b.y), TV_ENTRY_TRIM, e.y, 0);
    }
    return n;
}

void form_intervals(uint n)
{
    iv_count = 0u;
    iv_run = -1;
    for (uint i = 0u; i < n; i++) {
        if (ent[i].kind == TV_ENTRY_FRONT && !is_candidate(ent[i]) && iv_run < 0) {
            iv_run = int(i);
        } else if (ent[i].kind == TV_ENTRY_BACK && !is_candidate(ent[i]) && iv_run >= 0) {
            uint k = iv_count++;
            iv_first[k] = uint(iv_run);
            iv_back[k] = i;
            for (uint j = uint(iv_run); j <= i; j++)
                if (ent[j].kind != TV_ENTRY_TRIM)
                    ent[j].interval = int(k);
            iv_run = -1;
        }
    }
}

void validate(uint n)
{
    for (uint v = 0u; v < iv_count; v++) {
        float lo = ent[iv_first[v]].depth, hi = ent[iv_back[v]].depth;
        bool lost_here = hi >= trims_lost; // a lost trim may validate it, and its umbra be the nearest
        iv_valid[v] = lost_here;
        bool cracked = false;
        iv_end[v] = iv_end_fp[v] = hi;
        for (uint i = 0u; i < n; i++) { // trims behind trims_lost found room by arrival order (resolve.c)
            bool crack = ent[i].kind == TV_ENTRY_TRIM && ent[i].depth < trims_lost && ent[i].id != TV_ID_PRIOR &&
                         (ent[i].id & TV_REGION_CRACK) != 0u;
            if (crack && ent[i].depth >= lo - TV_PVS_CRACK_SLACK_M && ent[i].depth <= hi)
                cracked = true;
        }
        uint prior = prior_patch(iv_first[v]);
        bool met = false; // resolve.c
        for (uint r = 0u; !lost_here && r < rg_n; r++) { // resolve.c's fragments, a region at a time
            if (!region_meets(r, lo, hi))
                continue;
            float u = rg_umbra[r] < hi || isinf(rg_umbra[r]) ? hi : rg_umbra[r];
            float f = isinf(rg_umbra[r]) ? hi : max(rg_umbra_fp[r], hi);
            iv_end[v] = met && iv_end[v] < u ? iv_end[v] : u;
            iv_end_fp[v] = met && iv_end_fp[v] < f ? iv_end_fp[v] : f;
            met = true;
            iv_valid[v] = iv_valid[v] || !(rg_count[r] > 1u && other_patch(rg_id[r], prior));
        }
        if (cracked && is_culled(ent[iv_back[v]])) { // resolve.c: seen through
            iv_valid[v] = true;
            iv_end[v] = iv_end_fp[v] = hi;
        }
        iv_show_back[v] = cracked || is_straddled(ent[iv_back[v]]);
    }
}

#define LONE_ERODED (-2) // resolve.c

bool lone_eroded(uint b)
{
    float d = ent[b].depth;
    if (d >= trims_lost)
        return true;
    for (uint r = 0u; r < rg_n; r++)
        if (region_meets(r, d, d))
            return true;
    return false;
}

uint replace_backs(uint n)
{
    uint m = 0u;
    for (uint i = 0u; i < n; i++) {
        int v = ent[i].interval;
        bool valid = v >= 0 && iv_valid[v];
        if (valid && ent[i].kind == TV_ENTRY_BACK && !is_candidate(ent[i]))
            continue; // resolve.c: a candidate back stays, the walk decides
        ent[S2 + m] = ent[i];
        ent[S2 + m].delta = valid && iv_first[v] == i ? 1 : 0;
        if (v < 0 && ent[i].kind == TV_ENTRY_BACK && !is_candidate(ent[i]) && lone_eroded(i))
            ent[S2 + m].interval = LONE_ERODED;
        m++;
    }
    for (uint v = 0u; v < iv_count; v++) {
        if (iv_valid[v]) {
            ent[S2 + m] = make_entry(iv_end[v], TV_ENTRY_END, v, -1);
            ent[S2 + m++].interval = int(v);
        }
    }
    if (hide_begin < hide_end) {
        ent[S2 + m++] = make_entry(hide_begin, TV_ENTRY_BEGIN, 0u, 1);
        ent[S2 + m++] = make_entry(hide_end, TV_ENTRY_END, 0xFFFFFFFFu, -1);
    }
    return m;
}

bool walk(uint m)
{
    int prefix = 0;
    float open = 0.0, reach = 0.0, span_lo = 0.0, span_hi = 0.0;
    for (uint i = 0u; i < m; i++) {
        seq_entry e = ent[S2 + i];
        bool is_face = e.kind == TV_ENTRY_FRONT || e.kind == TV_ENTRY_BACK;
        if (e.delta > 0 && e.kind == TV_ENTRY_FRONT) {
            iv_hidden[e.interval] = prefix > 0;
            if (prefix == 0 && iv_show_back[e.interval])
                output_shown_back(ent[iv_back[e.interval]].id);
        }
        if (e.delta > 0) { // resolve.c: the spill span's reach
            float b = e.kind == TV_ENTRY_BEGIN ? e.depth : ent[iv_back[e.interval]].depth;
            float f = e.kind == TV_ENTRY_BEGIN ? hide_end_fp : iv_end_fp[e.interval];
            if (prefix == 0)
                open = reach = b;
            if (b <= reach && reach < f)
                reach = f;
        }
        prefix += e.delta;
        if (prefix == 0 && e.delta < 0) {
            span_lo = spill_lo = open;
            span_hi = e.depth;
            spill_hi = min(e.depth, reach);
        }
        bool in_valid = e.interval >= 0 && iv_valid[e.interval];
        if (is_candidate(e)) { // touches the pixel only: output unless hidden, never an occluder
            // inside a validated interval: fronts and straddled backs (resolve.c)
            if (prefix == 0 || (in_valid && !iv_hidden[e.interval] && (e.kind == TV_ENTRY_FRONT || is_straddled(e))))
                output_id(e.id);
            continue;
        }
        if (e.kind == TV_ENTRY_FRONT && in_valid) {
            if (!iv_hidden[e.interval])
                output_id(e.id);
            continue;
        }
        if (!is_face || (e.interval < 0 && is_culled(e)))
            continue; // resolve.c: a lone culled back is neither seen nor an occluder
        if (prefix > 0) { // hidden; an unvalidated interval's front still seals (resolve.c)
            if (e.kind == TV_ENTRY_BACK || e.interval < 0)
                continue;
            term_depth = e.depth;
            hide_begin = spill_lo = open;
            hide_end = e.depth;
            spill_hi = min(e.depth, reach);
            return true;
        }
        if (e.kind == TV_ENTRY_FRONT && e.interval < 0)
            return false;
        if (e.interval == LONE_ERODED) { // resolve.c: visible, not a terminator
            output_id(e.id);
            continue;
        }
        // A lone back (no front before it: a double-sided surface seen from
        // behind, or a single-sided one whose plane the viewcell straddles)
        // is visible; the back of a run whose front lies in an umbra is
        // hidden by that front.
        if (e.kind == TV_ENTRY_FRONT || e.interval < 0)
            output_id(e.id);
        if (e.kind == TV_ENTRY_FRONT && e.interval >= 0 && iv_show_back[e.interval])
            output_shown_back(ent[iv_back[e.interval]].id);
        term_depth = e.depth;
        hide_begin = span_lo;
        hide_end = span_hi;
        return true;
    }
    return false;
}

void carry_range(uint n)
{
    float tail = uintBitsToFloat(0xFF800000u); // -inf
    if (iv_run >= 0) {
        tail = ent[iv_run].depth;
    } else {
        bool any = false;
        for (uint i = 0u; i < n; i++) {
            if ((ent[i].kind == TV_ENTRY_FRONT || ent[i].kind == TV_ENTRY_BACK) && !is_candidate_back(ent[i])) {
                tail = ent[i].depth;
                any = true;
            }
        }
        if (!any)
            return;
    }
    float lo = uintBitsToFloat(0x7F800000u), hi = uintBitsToFloat(0xFF800000u);
    bool carried = hide_begin < hide_end && hide_begin <= tail && tail < hide_end;
    if (carried) {
        lo = hide_begin;
        hi = hide_end;
    }
    for (uint v = 0u; v < iv_count; v++) {
        float b = ent[iv_first[v]].depth;
        if (iv_valid[v] && b <= tail && tail < iv_end[v]) {
            lo = min(b, lo);
            hi = max(iv_end[v], hi);
        }
    }
    float reach = carried && hide_begin <= lo ? max(lo, hide_end_fp) : lo; // resolve.c: the footprints' end
    for (uint v = 0u; v < iv_count; v++) {
        float b = ent[iv_first[v]].depth;
        if (iv_valid[v] && b <= tail && tail < iv_end[v] && b <= reach)
            reach = max(reach, iv_end_fp[v]);
    }
    float end = lo < hi ? pvs_umbra_pack(hi, min(reach, hi)) : 0.0;
    hide_begin = lo < hi ? lo : 0.0;
    hide_end = pvs_umbra_centre(end);
    hide_end_fp = pvs_umbra_footprint(end);
}

bool carry_run(uint n)
{
    carry_next_count = 0u;
    uint run = iv_run < 0 ? n : uint(iv_run), from = run;
    while (iv_run >= 0 && from > 0u && ent[from - 1u].kind == TV_ENTRY_TRIM && ent[from - 1u].depth >= ent[run].depth * TV_PVS_TIE_LO)
        from--; // resolve.c: in the first front's plane
    for (uint i = from; i < n; i++) {
        if (is_candidate_back(ent[i]) || (ent[i].kind == TV_ENTRY_TRIM && ent[i].depth >= trims_lost))
            continue;
        // resolve.c: its fragments in front of the run are not carried
        bool moved = ent[i].kind == TV_ENTRY_TRIM && region_in(run, ent[i].id);
        if (!carry_add(ent[i].kind, moved ? ent[run].depth : ent[i].depth, ent[i].id))
            return false;
    }
    if (iv_run >= 0 && trims_lost < kdepth(0x7F800000u) && !carry_add(TV_ENTRY_TRIM, ent[run].depth, TV_ID_PRIOR))
        return false; // resolve.c's stand-in for lost trims
    uint run_entries = carry_next_count;
    for (uint i = 0u; i < run_entries; i++) {
        float u = 0.0, f = 0.0;
        bool first = (carry_next[i].kind & TV_CARRY_KIND) == TV_ENTRY_TRIM; // the region's first entry
        for (uint j = 0u; first && j < i; j++)
            first = carry_next[j].id != carry_next[i].id || (carry_next[j].kind & TV_CARRY_KIND) != TV_ENTRY_TRIM;
        if (first && umbra_depth(carry_next[i].id, u, f) && !carry_add(TV_ENTRY_UMBRA, pvs_umbra_pack(u, f), carry_next[i].id))
            return false;
    }
    for (uint i = 0u; i < carry_next_count; i++)
        carry[i] = carry_next[i];
    carry_count = carry_next_count;
    return true;
}

// pvs_resolve_pixel in stages, so that the cooperative variant can sort
// between them. resolve_begin: RESOLVE_NONE (nothing to resolve),
// RESOLVE_OVERFLOW (the overflow policy is due; finish_pixel runs it) or
// RESOLVE_SEQUENCE (gather, sort ent[0, n), resolve_intervals, sort
// ent[S2, S2 + m), resolve_end).
#define RESOLVE_NONE 0u
#define RESOLVE_OVERFLOW 1u
#define RESOLVE_SEQUENCE 2u

uint resolve_begin(out bool first)
{
    first = stencil == TV_STENCIL_UNTRIMMED;
    if (stencil == TV_STENCIL_SEALED)
        return RESOLVE_NONE;
    if (stencil == TV_STENCIL_UNTRIMMED && cnt.z == 0u)
        return RESOLVE_NONE;
    overflow_due = stencil == TV_STENCIL_OVERFLOW;
    if (overflow_due)
        return RESOLVE_OVERFLOW;
    stencil = TV_STENCIL_TRIMMED;
    if (deep_pixel() && cnt.x > view.k_exact) { // resolve.c: the carried range ends at its footprints
        hide_end = hide_begin < hide_end_fp ? hide_end_fp : 0.0;
        hide_begin = hide_end > 0.0 ? hide_begin : 0.0;
    }
    return RESOLVE_SEQUENCE;
}

uint resolve_intervals(uint n)
{
    form_intervals(n);
    trims_lost = cnt.z > view.k_regions ? kdepth(lost[TV_PVS_LOST_STRIDE * P + TV_PVS_LOST_TRIM]) : kdepth(0x7F800000u);
    regions_build(n);
    validate(n);
    return replace_backs(n);
}

// Returns true when the overflow policy handles the pixel (see finish_pixel).
bool resolve_end(uint n, uint m)
{
    float front_lost = kdepth(lost[TV_PVS_LOST_STRIDE * P + TV_PVS_LOST_FRONT]);
    bool sealed = walk(m);
    if (front_lost < kdepth(0x7F800000u) && !(sealed && term_depth < front_lost)) {
        overflow_due = true; // outputs what the walk did, and more
        return true;
    }
    if (sealed) {
        stencil = TV_STENCIL_SEALED;
        carry_count = 0u;
        return false;
    }
    carry_range(n);
    if (!carry_run(n)) {
        out_reason = TV_REASON_OVERFLOW; // the carry is full
        for (uint i = uint(iv_run); i < n; i++)
            if (ent[i].kind == TV_ENTRY_FRONT)
                output_id(ent[i].id);
        stencil = TV_STENCIL_OVERFLOW;
        carry_count = 0u;
        hide_begin = hide_end = spill_lo = spill_hi = 0.0;
        return true;
    }
    return false;
}

// Fragments P2 had no room for (pvs_spill_output of resolve.h): the exact spill draw outputs every front of an
// overflowed pixel that lost a front; the dilated one the candidates nearer than the bound left in
// lost[TV_PVS_LOST_STRIDE * P + TV_PVS_LOST_CANDIDATE]: all of them at an overflowed or open pixel, those in front of
// the terminator at a pixel sealed now, none otherwise, none inside the spill span (pvs_spill_hidden). Both draw only
// the spill list (the fronts that lost a fragment somewhere in the layer), so the stored candidates the dilated draw
// would also find here (those of triangles that lost nothing) are output now: the ids are those of a draw of every
// front, per pixel and so under any tiling. The stored fronts of an overflowed pixel, resolve_overflow has output.
void request_spill()
{
    const float inf = uintBitsToFloat(0x7F800000u);
    if (stencil == TV_STENCIL_OVERFLOW && lost[TV_PVS_LOST_STRIDE * P + TV_PVS_LOST_FRONT] != 0x7F800000u)
        counters[TV_PVS_C_DRAW_SPILL] = 3u * spill_list[0];
    float bound = stencil == TV_STENCIL_SEALED ? term_depth : inf;
    bool candidates = stencil != TV_STENCIL_UNTRIMMED && kdepth(lost[TV_PVS_LOST_STRIDE * P + TV_PVS_LOST_CANDIDATE]) < bound;
    lost[TV_PVS_LOST_STRIDE * P + TV_PVS_LOST_CANDIDATE] = candidates ? floatBitsToUint(bound) : 0u;
    if (!candidates)
        return;
    lost[TV_PVS_LOST_STRIDE * P + TV_PVS_LOST_SPAN_LO] = floatBitsToUint(spill_lo);
    lost[TV_PVS_LOST_STRIDE * P + TV_PVS_LOST_SPAN_HI] = floatBitsToUint(spill_hi);
    counters[TV_PVS_C_DRAW_SPILL_WIDE] = 3u * spill_list[0];
    out_reason = TV_REASON_OVERFLOW; // what the dilated spill draw would have output
    uvec2 e;
    for (kb_cursor c = kb_open(0u); kb_next(c, e);) {
        if ((e.y & TV_ID_CANDIDATE) != 0u && kdepth(e.x) < bound && !pvs_spill_hidden(spill_lo, spill_hi, kdepth(e.x)))
            output_id(e.y);
    }
    out_reason = TV_REASON_FRONT;
}

void load_pixel(uint pixel)
{
    P = pixel;
    cnt = pixcount[P];
    uvec4 st = pixstate[P];
    if (st.x != TV_STENCIL_SEALED && !pvs_region_activates(st) && cnt.x == 0u && cnt.y == 0u)
        atomicAdd(counters[TV_PVS_C_IDLE], 1u); // P2 activated it for trims alone
    stencil = st.x;
    carry_count = stencil == TV_STENCIL_SEALED ? 0u : st.y;
    hide_begin = uintBitsToFloat(st.z);
    hide_end = stencil == TV_STENCIL_TRIMMED ? pvs_umbra_centre(uintBitsToFloat(st.w)) : uintBitsToFloat(st.w);
    hide_end_fp = pvs_umbra_footprint(uintBitsToFloat(st.w));
    for (uint c = 0u; c < carry_count; c++) {
        uvec4 e = carry_buf[P * TV_K_CARRY + c];
        carry[c] = carry_entry(uintBitsToFloat(e.x), e.y, e.z, uintBitsToFloat(e.w));
    }
    n_out = 0u;
    out_reason = TV_REASON_FRONT;
    term_depth = stencil == TV_STENCIL_SEALED ? uintBitsToFloat(st.y) : 0.0;
    spill_lo = spill_hi = 0.0; // set by the walk only
    overflow_due = false;
}

// Runs the overflow policy if due, writes the pixel's state back, requests
// spill draws, adds the layer's statistics and clears the active flag.
void finish_pixel(uint seq_len, bool handled)
{
    if (overflow_due) // one inlined copy (llvmpipe), not one per stage that finds it due
        resolve_overflow();
    bool overflowed = handled || any(greaterThan(cnt, kb_capacity()));
    if (cnt.x > view.k_lists)
        request_spill();
    pixstate[P] = uvec4(stencil, stencil == TV_STENCIL_SEALED ? floatBitsToUint(term_depth) : carry_count,
                        floatBitsToUint(hide_begin),
                        floatBitsToUint(stencil == TV_STENCIL_TRIMMED ? pvs_umbra_pack(hide_end, hide_end_fp) : hide_end));
    for (uint c = 0u; c < carry_count; c++)
        carry_buf[P * TV_K_CARRY + c] = uvec4(floatBitsToUint(carry[c].depth), carry[c].kind, carry[c].id,
                                              floatBitsToUint(carry[c].second));
    if (!KB_PAGED) { // the bytes read: FLAT's kbuffer_bytes_used (PAGED counts the pages taken)
        uvec4 stored = min(cnt, kb_capacity());
        atomicAdd(layer_stats[TV_PVS_LAYER_STATS_STRIDE * pc.layer].x, 8u * (stored.x + stored.y + TV_PVS_REGION_SLOTS * stored.z));
    }
    atomicAdd(layer_stats[TV_PVS_LAYER_STATS_STRIDE * pc.layer].y, 1u);
    atomicAdd(layer_stats[TV_PVS_LAYER_STATS_STRIDE * pc.layer].z, seq_len);
    if (overflowed)
        atomicAdd(layer_stats[TV_PVS_LAYER_STATS_STRIDE * pc.layer].w, 1u);
    active_flag[P] = 0u;
}

#endif
