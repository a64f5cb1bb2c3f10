#include "resolve.h"

#include <assert.h>
#include <math.h>
#include <string.h>

/* Upper bounds of the per-pixel sequences (thread-local arrays on the GPU). */
#define SEQ_MAX (2 * (TV_K_CARRY + TV_K_TRIM) + TV_K_FRONT + TV_K_BACK) // two trim depths per region entry
#define IV_MAX (TV_K_BACK + 3 < TV_K_FRONT + TV_K_CARRY ? TV_K_BACK + 3 : TV_K_FRONT + TV_K_CARRY) // + three prior backs
#define SEQ2_MAX (SEQ_MAX + IV_MAX + 2)

typedef struct seq_entry {
    float depth;
    uint32_t kind;
    uint32_t id;
    int32_t interval; /* occlusion interval a front/back belongs to, -1 none (LONE_ERODED: see walk) */
    int32_t delta;    /* +1 opens a hidden range, -1 closes it */
} seq_entry;

/* Total order: depth, kind rank, id; then, for a face and its duplicate in
 * the re-sorted sequence, the interval's opening front (delta +1) first and
 * a closing back before a lone one (interval -1 last), which is where a
 * stable sort leaves them. Entries that compare equal are identical, so
 * every sort algorithm (insertion here and in P3's per-thread pass, bitonic
 * in its cooperative pass) yields the same sequence. */
/* The interval of a lone back that a trim region meets (replace_backs). */
#define LONE_ERODED (-2)

static bool entry_less(const seq_entry* a, const seq_entry* b)
{
    if (a->depth != b->depth)
        return a->depth < b->depth;
    if (a->kind != b->kind)
        return a->kind < b->kind;
    if (a->id != b->id)
        return a->id < b->id;
    if (a->delta != b->delta)
        return a->delta > b->delta;
    return (uint32_t)a->interval < (uint32_t)b->interval;
}

static void sort_entries(seq_entry* e, uint32_t n)
{
    for (uint32_t i = 1; i < n; i++) {
        seq_entry x = e[i];
        uint32_t j = i;
        while (j > 0 && entry_less(&x, &e[j - 1])) {
            e[j] = e[j - 1];
            j--;
        }
        e[j] = x;
    }
}

static seq_entry make_entry(float depth, uint32_t kind, uint32_t id, int32_t delta)
{
    return (seq_entry){.depth = depth, .kind = kind, .id = id, .interval = -1, .delta = delta};
}

/* A candidate front, or a candidate back (the back of a triangle narrower
 * than a pixel: it may cover no pixel centre). */
static bool is_candidate(const seq_entry* e)
{
    return (e->kind == TV_ENTRY_FRONT || e->kind == TV_ENTRY_BACK) && (e->id & TV_ID_CANDIDATE) != 0;
}

/* A candidate back can be output only in the layer that drew it (in a
 * later layer the carried run's first front precedes it), so it is neither
 * carried nor the face that anchors the carried hidden range. */
static bool is_candidate_back(const seq_entry* e)
{
    return e->kind == TV_ENTRY_BACK && is_candidate(e);
}

/* A back the renderer culls from the whole viewcell (TV_ID_CULLED). */
static bool is_culled(const seq_entry* e)
{
    return e->kind == TV_ENTRY_BACK && e->id != TV_ID_PRIOR && (e->id & TV_ID_CULLED) != 0;
}

/* A back whose plane the viewcell straddles (TV_ID_STRADDLED): some eyes
 * see its front. The prior ids carry the flag bit but also TV_ID_CULLED. */
static bool is_straddled(const seq_entry* e)
{
    return e->kind == TV_ENTRY_BACK && (e->id & TV_ID_CULLED) == 0 && (e->id & TV_ID_STRADDLED) != 0;
}

/* Appends a face's triangle to the output; prior faces are already in the
 * PVS through the visibility buffer, and culled backs are never drawn. */
static void emit(uint32_t* out, uint32_t* n, uint32_t id)
{
    if (id != TV_ID_PRIOR && (id & TV_ID_CULLED) == 0)
        out[(*n)++] = id & ~(TV_ID_CANDIDATE | TV_ID_STRADDLED);
}

/* The overflow policy: every front this pixel knows of is output and the
 * pixel can no longer be sealed. */
static uint32_t resolve_overflow(pvs_pixel_state* s, const pvs_kbuf* k, uint32_t* out)
{
    uint32_t n = 0;
    for (uint32_t i = 0; i < s->carry_count; i++) {
        if (s->carry[i].kind == TV_ENTRY_FRONT)
            emit(out, &n, s->carry[i].id);
    }
    for (uint32_t i = 0; i < k->front_held; i++)
        emit(out, &n, k->front_tri[i]);
    for (uint32_t i = 0; i < k->back_held; i++)
        emit(out, &n, k->back_tri[i]);
    s->stencil = TV_STENCIL_OVERFLOW;
    s->carry_count = 0;
    s->hide_begin = s->hide_end = s->spill_lo = s->spill_hi = 0.0f;
    return n;
}

static bool has_depth(float d)
{
    return d > 0.0f && d < INFINITY;
}

/* Whether this layer stored a face of `kind` at exactly `depth`: P2 wrote
 * the same value into the k-buffer and the centre depth, so a prior face
 * found here is that face and must not enter twice (a second back at a
 * validated back's depth would terminate the pixel). */
static bool stored_face(const pvs_kbuf* k, uint32_t kind, float depth)
{
    uint32_t n = kind == TV_ENTRY_FRONT ? k->front_held : k->back_held;
    for (uint32_t i = 0; i < n; i++) {
        if ((kind == TV_ENTRY_FRONT ? k->front_depth[i] : k->back_depth[i]) == depth)
            return true;
    }
    return false;
}

/* `first`: the pixel becomes trimmed in this layer, so its nearest front,
 * back and culled back join as prior faces unless this layer holds them. */
static uint32_t gather(const pvs_pixel_state* s, const pvs_kbuf* k, bool first, seq_entry* seq)
{
    uint32_t n = 0;
    if (first) {
        if (has_depth(k->nearest_front) && !stored_face(k, TV_ENTRY_FRONT, k->nearest_front))
            seq[n++] = make_entry(k->nearest_front, TV_ENTRY_FRONT, TV_ID_PRIOR, 0);
        if (has_depth(k->nearest_back) && !stored_face(k, TV_ENTRY_BACK, k->nearest_back))
            seq[n++] = make_entry(k->nearest_back, TV_ENTRY_BACK, TV_ID_PRIOR, 0);
        if (has_depth(k->nearest_culled_back) && !stored_face(k, TV_ENTRY_BACK, k->nearest_culled_back))
            seq[n++] = make_entry(k->nearest_culled_back, TV_ENTRY_BACK, TV_ID_PRIOR_CULLED, 0);
        if (has_depth(k->culled_behind) && k->culled_behind != k->nearest_culled_back &&
            !stored_face(k, TV_ENTRY_BACK, k->culled_behind))
            seq[n++] = make_entry(k->culled_behind, TV_ENTRY_BACK, TV_ID_PRIOR_CULLED, 0);
    }
    for (uint32_t i = 0; i < s->carry_count; i++) {
        float trim[2];
        uint32_t t = pvs_carry_trims(&s->carry[i], trim);
        if (s->carry[i].kind == TV_ENTRY_FRONT)
            seq[n++] = make_entry(s->carry[i].depth, TV_ENTRY_FRONT, s->carry[i].id, 0);
        for (uint32_t j = 0; j < t; j++)
            seq[n++] = make_entry(trim[j], TV_ENTRY_TRIM, s->carry[i].id, 0);
    }
    for (uint32_t i = 0; i < k->front_held; i++)
        seq[n++] = make_entry(k->front_depth[i], TV_ENTRY_FRONT, k->front_tri[i], 0);
    for (uint32_t i = 0; i < k->back_held; i++)
        seq[n++] = make_entry(k->back_depth[i], TV_ENTRY_BACK, k->back_tri[i], 0);
    for (uint32_t i = 0; i < k->trim_held; i++)
        seq[n++] = make_entry(k->trim_depth[i], TV_ENTRY_TRIM, k->trim_region[i], 0);
    sort_entries(seq, n);
    return n;
}

typedef struct intervals {
    uint32_t count;
    uint32_t first[IV_MAX], back[IV_MAX]; /* sequence indices */
    bool valid[IV_MAX];
    bool hidden[IV_MAX]; /* set by the walk: the run starts inside an umbra */
    /* its back is output with its first front: a crack edge's trim
     * (TV_REGION_CRACK) lies in it or just in front, or the back is
     * straddled (validate) */
    bool show_back[IV_MAX];
    float end[IV_MAX]; /* depth where the hidden range of a valid interval ends */
    float end_fp[IV_MAX]; /* the same at its umbrae's footprints (the spill span's, walk) */
    int32_t run;       /* first front of the trailing unfinished run, -1 none */
    float trims_lost;  /* nearest depth of a trim the list had no room for (INFINITY: none) */
} intervals;

/* Greedy simple intervals [f, b] over the fronts and backs, each extended at
 * the front over the consecutive fronts preceding f. */
static void form_intervals(seq_entry* seq, uint32_t n, intervals* iv)
{
    iv->count = 0;
    iv->run = -1;
    for (uint32_t i = 0; i < n; i++) {
        if (seq[i].kind == TV_ENTRY_FRONT && !is_candidate(&seq[i]) && iv->run < 0) {
            iv->run = (int32_t)i;
        } else if (seq[i].kind == TV_ENTRY_BACK && !is_candidate(&seq[i]) && iv->run >= 0) {
            uint32_t k = iv->count++;
            iv->first[k] = (uint32_t)iv->run;
            iv->back[k] = i;
            for (uint32_t j = (uint32_t)iv->run; j <= i; j++) {
                if (seq[j].kind != TV_ENTRY_TRIM)
                    seq[j].interval = (int32_t)k;
            }
            iv->run = -1;
        }
    }
}

#include "resolve_regions.h"

/* An interval is valid when a trim region meets [f, b] (region_meets). Its hidden range
 * ends at the nearest umbra of the validating regions (the most conservative
 * choice), at b when none of them left an umbra here, never before b.
 * When trims were lost, an interval reaching back to the nearest of them
 * may have been validated by one, and the nearest umbra may have been
 * theirs: it is valid and hides up to its back only. */
static void validate(const pvs_pixel_state* s, const pvs_kbuf* k, const seq_entry* seq, uint32_t n,
                     intervals* iv)
{
    for (uint32_t v = 0; v < iv->count; v++) {
        float lo = seq[iv->first[v]].depth, hi = seq[iv->back[v]].depth;
        bool lost = hi >= iv->trims_lost;
        iv->valid[v] = lost;
        bool cracked = false, met = false;
        uint32_t prior = prior_patch(k, &seq[iv->first[v]]);
        iv->end[v] = iv->end_fp[v] = hi;
        for (uint32_t i = 0; i < n; i++) {
            if (seq[i].kind == TV_ENTRY_TRIM && seq[i].depth >= iv->trims_lost)
                continue; /* found room by arrival order (region_meets) */
            /* a crack trim lies in its edge's plane, and the face seen
             * beside the crack may be a neighbour a few mm behind it */
            bool crack = seq[i].kind == TV_ENTRY_TRIM && seq[i].id != TV_ID_PRIOR && (seq[i].id & TV_REGION_CRACK) != 0;
            if (crack && seq[i].depth >= lo - TV_PVS_CRACK_SLACK_M && seq[i].depth <= hi)
                cracked = true;
            if (lost || seq[i].kind != TV_ENTRY_TRIM || !region_meets(seq, n, i, lo, hi, iv->trims_lost))
                continue;
            float u = hi, f = hi;
            if (!pvs_umbra_depth(s, k, seq[i].id, &u, &f) || u < hi)
                u = hi;
            f = f < hi ? hi : f;
            iv->end[v] = met && iv->end[v] < u ? iv->end[v] : u; /* a skipped region's umbra still bounds it */
            iv->end_fp[v] = met && iv->end_fp[v] < f ? iv->end_fp[v] : f;
            met = true;
            iv->valid[v] = iv->valid[v] || !other_patch(k, seq, n, i, prior, iv->trims_lost);
        }
        /* Through a crack the eyes see the inside, and with the back culled
         * whatever lies behind it: the interval hides its inside only. */
        if (cracked && is_culled(&seq[iv->back[v]])) {
            iv->valid[v] = true;
            iv->end[v] = iv->end_fp[v] = hi;
        }
        /* the eyes see the back through the crack, or a straddled back's
         * front past the edge (an unseen culled back emits nothing) */
        iv->show_back[v] = cracked || is_straddled(&seq[iv->back[v]]);
    }
}

/* The sequence with validated backs replaced by their umbrae (END entries)
 * plus the carried hidden range, re-sorted. */
static uint32_t replace_backs(const pvs_pixel_state* s, const seq_entry* seq, uint32_t n,
                              const intervals* iv, seq_entry* seq2)
{
    uint32_t m = 0;
    for (uint32_t i = 0; i < n; i++) {
        int32_t v = seq[i].interval;
        bool valid = v >= 0 && iv->valid[v];
        if (valid && seq[i].kind == TV_ENTRY_BACK && !is_candidate(&seq[i]))
            continue; /* a candidate back stays: the walk decides (straddled ones may be output) */
        seq2[m] = seq[i];
        seq2[m].delta = valid && iv->first[v] == i ? 1 : 0;
        if (v < 0 && seq[i].kind == TV_ENTRY_BACK && !is_candidate(&seq[i]) && lone_eroded(seq, n, i, iv->trims_lost))
            seq2[m].interval = LONE_ERODED;
        m++;
    }
    for (uint32_t v = 0; v < iv->count; v++) {
        if (iv->valid[v]) {
            seq2[m] = make_entry(iv->end[v], TV_ENTRY_END, v, -1);
            seq2[m++].interval = (int32_t)v;
        }
    }
    if (s->hide_begin < s->hide_end) {
        seq2[m++] = make_entry(s->hide_begin, TV_ENTRY_BEGIN, 0, 1);
        seq2[m++] = make_entry(s->hide_end, TV_ENTRY_END, UINT32_MAX, -1);
    }
    sort_entries(seq2, m);
    return m;
}

/* Front-to-back walk with the running prefix sum; returns true when a
 * terminator sealed the pixel and sets *term to its depth and s's hidden
 * range to the last one before it (from the back of the interval that
 * opened it, or the carried range's start, to where the prefix returns to
 * 0), which pvs_sealed_output reads; and s's spill span (resolve.h): the
 * footprints' `reach` joins an interval's from its back (a carried range's
 * from its start: hide_end_fp) where that lies within it. */
static bool walk(pvs_pixel_state* s, const seq_entry* seq, const seq_entry* seq2, uint32_t m, intervals* iv,
                 uint32_t* out, uint32_t* n_out, float* term)
{
    int32_t prefix = 0;
    float open = 0.0f, reach = 0.0f, span_lo = 0.0f, span_hi = 0.0f;
    for (uint32_t i = 0; i < m; i++) {
        const seq_entry* e = &seq2[i];
        bool is_face = e->kind == TV_ENTRY_FRONT || e->kind == TV_ENTRY_BACK;
        if (e->delta > 0 && e->kind == TV_ENTRY_FRONT) {
            iv->hidden[e->interval] = prefix > 0; /* its run starts inside an umbra */
            if (prefix == 0 && iv->show_back[e->interval])
                emit(out, n_out, seq[iv->back[e->interval]].id);
        }
        if (e->delta > 0) {
            float b = e->kind == TV_ENTRY_BEGIN ? e->depth : seq[iv->back[e->interval]].depth;
            float f = e->kind == TV_ENTRY_BEGIN ? s->hide_end_fp : iv->end_fp[e->interval];
            if (prefix == 0)
                open = reach = b;
            if (b <= reach && reach < f)
                reach = f;
        }
        prefix += e->delta;
        if (prefix == 0 && e->delta < 0) {
            span_lo = s->spill_lo = open;
            span_hi = e->depth;
            s->spill_hi = fminf(e->depth, reach);
        }
        if (is_candidate(e)) {
            /* It only touches the pixel: visible unless hidden, never an
             * occluder (neither a run nor a terminator). Inside a validated
             * interval a candidate front is part of the eroded surface eyes
             * see past its edge, and so is a straddled candidate back (some
             * eyes see its front: the side of a thin solid seen edge-on); any
             * other back there is the inside of a closed surface. Faces the
             * walk passed do not hide it: they are the ones it sees past
             * (docs/pvs-edge-cases.md, "Candidates": counting them made the
             * output depend on which layer held them). */
            bool in_valid = e->interval >= 0 && iv->valid[e->interval] && !iv->hidden[e->interval];
            if (prefix == 0 || (in_valid && (e->kind == TV_ENTRY_FRONT || is_straddled(e))))
                emit(out, n_out, e->id);
            continue;
        }
        if (e->kind == TV_ENTRY_FRONT && e->interval >= 0 && iv->valid[e->interval]) {
            /* Every front of a validated interval's run is visible from the
             * viewcell unless the run starts inside an earlier umbra. */
            if (!iv->hidden[e->interval])
                emit(out, n_out, e->id);
            continue;
        }
        if (!is_face)
            continue; /* trims and range markers */
        if (e->interval < 0 && is_culled(e))
            continue; /* a lone culled back: the eyes see through it, nothing else */
        if (prefix > 0) {
            /* Hidden by an umbra. The front of an unvalidated interval is
             * still an uneroded surface at this pixel: it hides everything
             * behind it from the whole viewcell, as a terminator outside
             * the range does, and seals the pixel unseen (the range kept
             * is the one it lies in). A lone back does not: its front may
             * have joined a validated run. */
            if (e->kind == TV_ENTRY_BACK || e->interval < 0)
                continue;
            *term = e->depth;
            s->hide_begin = s->spill_lo = open;
            s->hide_end = e->depth;
            s->spill_hi = fminf(e->depth, reach);
            return true;
        }
        if (e->kind == TV_ENTRY_FRONT && e->interval < 0)
            return false; /* the unfinished trailing run: carried, not a terminator */
        if (e->interval == LONE_ERODED) {
            /* A lone back that a trim region meets: a single-sided surface
             * eyes see past at this pixel, as they see past the front of a
             * validated interval. Visible, not a terminator. */
            emit(out, n_out, e->id);
            continue;
        }
        /* A lone back (no front before it: a double-sided surface seen from
         * behind, or a single-sided one whose plane the viewcell straddles)
         * is visible; the back of a run whose front lies in an umbra is
         * hidden by that front. */
        if (e->kind == TV_ENTRY_FRONT || e->interval < 0)
            emit(out, n_out, e->id);
        if (e->kind == TV_ENTRY_FRONT && e->interval >= 0 && iv->show_back[e->interval])
            emit(out, n_out, seq[iv->back[e->interval]].id);
        *term = e->depth;
        s->hide_begin = span_lo;
        s->hide_end = span_hi;
        return true;
    }
    return false;
}

/* The carried hidden range: the union of the ranges (this layer's validated
 * intervals and the range carried in) that contain the depth where the
 * carried part of the sequence starts. They all contain that depth, so their
 * union is one range. Ranges ending before it are dropped (conservative: the
 * next layer then hides less). */
static void carry_range(pvs_pixel_state* s, const seq_entry* seq, uint32_t n, const intervals* iv)
{
    float tail = -INFINITY;
    if (iv->run >= 0) {
        tail = seq[iv->run].depth;
    } else {
        for (uint32_t i = 0; i < n; i++) {
            if ((seq[i].kind == TV_ENTRY_FRONT || seq[i].kind == TV_ENTRY_BACK) && !is_candidate_back(&seq[i]))
                tail = seq[i].depth;
        }
        if (tail == -INFINITY)
            return; /* nothing but trims this layer: keep the range as it is */
    }
    float lo = INFINITY, hi = -INFINITY;
    bool carried = s->hide_begin < s->hide_end && s->hide_begin <= tail && tail < s->hide_end;
    if (carried) {
        lo = s->hide_begin;
        hi = s->hide_end;
    }
    for (uint32_t v = 0; v < iv->count; v++) {
        float b = seq[iv->first[v]].depth;
        if (iv->valid[v] && b <= tail && tail < iv->end[v]) {
            lo = b < lo ? b : lo;
            hi = iv->end[v] > hi ? iv->end[v] : hi;
        }
    }
    /* The footprints' end, from lo over the ranges that join within it (one pass: may stop short) */
    float reach = carried && s->hide_begin <= lo ? fmaxf(lo, s->hide_end_fp) : lo;
    for (uint32_t v = 0; v < iv->count; v++) {
        float b = seq[iv->first[v]].depth;
        if (iv->valid[v] && b <= tail && tail < iv->end[v] && b <= reach)
            reach = fmaxf(reach, iv->end_fp[v]);
    }
    float end = lo < hi ? pvs_umbra_pack(hi, fminf(reach, hi)) : 0.0f;
    s->hide_begin = lo < hi ? lo : 0.0f;
    s->hide_end = pvs_umbra_centre(end);
    s->hide_end_fp = pvs_umbra_footprint(end);
}

/* Carries the trailing unfinished run: its fronts, the trims behind its
 * first front (they may validate it once its back arrives) and those trims'
 * umbrae, packed (pvs_carry_add); when trims were lost, also a trim without
 * umbra (region TV_ID_PRIOR) at its first front, standing in for them.
 * Returns false when that does not fit in TV_K_CARRY. */
static bool carry_run(pvs_pixel_state* s, const pvs_kbuf* k, const seq_entry* seq, uint32_t n,
                      const intervals* iv)
{
    pvs_entry next[TV_K_CARRY];
    uint32_t c = 0;
    uint32_t run = iv->run < 0 ? n : (uint32_t)iv->run, from = run;
    /* trims in the first front's plane that rounded in front of it (TV_PVS_TIE_LO): carried, moved to it */
    while (iv->run >= 0 && from > 0 && seq[from - 1].kind == TV_ENTRY_TRIM &&
           seq[from - 1].depth >= seq[run].depth * (float)TV_PVS_TIE_LO)
        from--;
    for (uint32_t i = from; i < n; i++) {
        /* trims behind the nearest lost one: the stand-in below covers them */
        if (is_candidate_back(&seq[i]) || (seq[i].kind == TV_ENTRY_TRIM && seq[i].depth >= iv->trims_lost))
            continue;
        /* A region with fragments in front of the run's first front too
         * meets any interval the run will form (region_meets): carried at
         * that front, as those fragments are not. */
        bool moved = seq[i].kind == TV_ENTRY_TRIM && region_in(seq, run, seq[i].id);
        if (!pvs_carry_add(next, &c, seq[i].kind, moved ? seq[run].depth : seq[i].depth, seq[i].id))
            return false;
    }
    /* The stand-in for lost trims, at the run's first front: a lost trim,
     * or a lost fragment of a region with one in front of the run, may
     * validate the run once its back arrives. */
    if (iv->run >= 0 && iv->trims_lost < INFINITY && !pvs_carry_add(next, &c, TV_ENTRY_TRIM, seq[run].depth, TV_ID_PRIOR))
        return false;
    uint32_t run_entries = c;
    for (uint32_t i = 0; i < run_entries; i++) {
        float u, f;
        bool first = (next[i].kind & TV_CARRY_KIND) == TV_ENTRY_TRIM; /* the region's first entry */
        for (uint32_t j = 0; first && j < i; j++)
            first = next[j].id != next[i].id || (next[j].kind & TV_CARRY_KIND) != TV_ENTRY_TRIM;
        if (first && pvs_umbra_depth(s, k, next[i].id, &u, &f) &&
            !pvs_carry_add(next, &c, TV_ENTRY_UMBRA, pvs_umbra_pack(u, f), next[i].id))
            return false;
    }
    for (uint32_t i = 0; i < c; i++)
        s->carry[i] = next[i];
    s->carry_count = c;
    return true;
}

/* A sealed pixel stores nothing more (P2 drops its fragments); a front or
 * back of a later layer that pvs_sealed_output admits is output at once. */
static uint32_t resolve_sealed(const pvs_pixel_state* s, const pvs_kbuf* kbuf, uint32_t* out)
{
    uint32_t n_out = 0;
    for (uint32_t i = 0; i < kbuf->front_held; i++)
        if (pvs_sealed_output(s, kbuf->front_depth[i]))
            emit(out, &n_out, kbuf->front_tri[i]);
    for (uint32_t i = 0; i < kbuf->back_held; i++)
        if (pvs_sealed_output(s, kbuf->back_depth[i]))
            emit(out, &n_out, kbuf->back_tri[i]);
    return n_out;
}

static uint32_t resolve_layer(pvs_pixel_state* state, const pvs_kbuf* kbuf, uint32_t* out, bool* overflowed)
{
    *overflowed = false;
    state->spill_lo = state->spill_hi = 0.0f; /* the walk's, in this layer only */
    if (state->stencil == TV_STENCIL_SEALED)
        return resolve_sealed(state, kbuf, out);
    if (state->stencil == TV_STENCIL_UNTRIMMED && kbuf->trim_count == 0)
        return 0;
    *overflowed = state->stencil == TV_STENCIL_OVERFLOW || kbuf->front_count > pvs_kbuf_capacity(kbuf, TV_K_FRONT) ||
                  kbuf->back_count > pvs_kbuf_capacity(kbuf, TV_K_BACK) || kbuf->trim_count > TV_K_TRIM;
    if (state->stencil == TV_STENCIL_OVERFLOW)
        return resolve_overflow(state, kbuf, out);
    bool first = state->stencil == TV_STENCIL_UNTRIMMED;
    assert(!first || state->carry_count == 0); /* room for the prior faces */
    state->stencil = TV_STENCIL_TRIMMED;
    /* Where k_deep off would take the overflow policy (a front list longer than k), the carried hidden range ends
     * at its footprints, as the umbrae that ended it (pvs_umbra_depth; journal/2026-12-03-deepfix; dropping it
     * grew the PVS, -ovf2) */
    if (pvs_kbuf_deep(kbuf) && kbuf->front_count > kbuf->k_exact) {
        state->hide_end = state->hide_end_fp;
        if (!(state->hide_begin < state->hide_end))
            state->hide_begin = state->hide_end = 0.0f;
    }
    seq_entry seq[SEQ_MAX], seq2[SEQ2_MAX];
    intervals iv;
    uint32_t n = gather(state, kbuf, first, seq);
    form_intervals(seq, n, &iv);
    iv.trims_lost = kbuf->trim_count > TV_K_TRIM ? (has_depth(kbuf->trim_lost) ? kbuf->trim_lost : 0.0f) : INFINITY;
    validate(state, kbuf, seq, n, &iv);
    uint32_t m = replace_backs(state, seq, n, &iv, seq2);
    uint32_t n_out = 0;
    float term = INFINITY, lost = has_depth(kbuf->front_lost) ? kbuf->front_lost : INFINITY;
    bool sealed = walk(state, seq, seq2, m, &iv, out, &n_out, &term);
    if (lost < INFINITY && !(sealed && term < lost))
        return resolve_overflow(state, kbuf, out); /* outputs what the walk did, and more */
    if (sealed) {
        state->term_depth = term;
        state->stencil = TV_STENCIL_SEALED;
        state->carry_count = 0;
        return n_out;
    }
    carry_range(state, seq, n, &iv);
    if (!carry_run(state, kbuf, seq, n, &iv)) {
        /* The run's fronts have not been output yet: the policy outputs them. */
        *overflowed = true;
        for (uint32_t i = (uint32_t)iv.run; i < n; i++) {
            if (seq[i].kind == TV_ENTRY_FRONT)
                emit(out, &n_out, seq[i].id);
        }
        state->stencil = TV_STENCIL_OVERFLOW;
        state->carry_count = 0;
        state->hide_begin = state->hide_end = state->spill_lo = state->spill_hi = 0.0f;
    }
    return n_out;
}

/* The stored candidates: the GPU's request_spill (resolve.h says why). */
uint32_t pvs_resolve_pixel(pvs_pixel_state* state, const pvs_kbuf* kbuf, uint32_t* out, bool* overflowed)
{
    assert(state && kbuf && out && overflowed);
    uint32_t n = resolve_layer(state, kbuf, out, overflowed);
    float bound = state->stencil == TV_STENCIL_SEALED ? state->term_depth : INFINITY;
    if (kbuf->front_count <= pvs_kbuf_capacity(kbuf, TV_K_FRONT) || state->stencil == TV_STENCIL_UNTRIMMED ||
        !has_depth(kbuf->candidate_lost) || kbuf->candidate_lost >= bound)
        return n;
    for (uint32_t i = 0; i < kbuf->front_held; i++) {
        if ((kbuf->front_tri[i] & TV_ID_CANDIDATE) != 0 && kbuf->front_depth[i] < bound &&
            !pvs_spill_hidden(state, kbuf->front_depth[i]))
            emit(out, &n, kbuf->front_tri[i]);
    }
    return n;
}
