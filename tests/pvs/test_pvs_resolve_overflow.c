/* Trim-sequence resolve (P3 reference) when lists overflow: every front is
 * kept, fronts behind the terminator, full umbra, trim and back lists, prior
 * faces, a carry that does not fit, and a k-buffer page pool that runs
 * out, and a deep pixel (more entries than k, fewer than the lists hold),
 * which ends umbrae and the hidden range they carried at their footprints. */
#include "resolve_harness.h"
#include "test.h"

#include <stdio.h>
#include <string.h>

static void test_overflow_keeps_every_front(void)
{
    item items[TV_K_FRONT + 12 + 4];
    uint32_t n = 0;
    items[n++] = (item)F(1.0f, 99);
    items[n++] = (item)T(1.2f, 1);
    items[n++] = (item)B(1.5f);
    items[n++] = (item)U(60.0f, 1);
    for (uint32_t i = 0; i < TV_K_FRONT + 11; i++)
        items[n++] = (item)F(2.0f + (float)i, 100 + i);
    pvs_pixel_state s = {0};
    layer_result r = run_layer(&s, items, n);
    TV_CHECK(r.overflowed);
    TV_CHECK(r.spilled_count == 12 && r.spill_out == 12 && r.count == TV_K_FRONT + 1); /* + the back */
    bool all = true;
    for (uint32_t i = 0; i < TV_K_FRONT + 11; i++) {
        bool found = false;
        for (uint32_t j = 0; j < r.count; j++)
            found |= r.out[j] == 100 + i;
        for (uint32_t j = 0; j < r.spilled_count; j++)
            found |= r.spilled[j] == 100 + i;
        all &= found;
    }
    TV_CHECK(all);
    TV_CHECK(s.stencil == TV_STENCIL_OVERFLOW);
    layer_result r2 = RUN(s, F(50.0f, 7), B(51.0f), F(52.0f, 8), B(53.0f));
    CHECK_OUT(r2, 7, 8, BACK_ID, BACK_ID); /* 7 would have terminated a normal pixel */
    TV_CHECK(r2.overflowed && s.stencil == TV_STENCIL_OVERFLOW);
}

/* A terminator in front of every lost front seals the pixel as usual: the
 * lost fronts lie behind it and stay out of the PVS. Lost candidates never
 * send a pixel to the overflow state; at an open pixel they are output. */
static void test_overflow_behind_terminator(void)
{
    item items[TV_K_FRONT + 8];
    uint32_t n = 0;
    items[n++] = (item)T(0.5f, 1);
    items[n++] = (item)F(1.0f, 1);
    items[n++] = (item)B(1.5f);
    for (uint32_t i = 0; n < TV_K_FRONT + 8; i++)
        items[n++] = (item)F(2.0f + (float)i, 100 + i);
    pvs_pixel_state s = {0};
    layer_result r = run_layer(&s, items, n);
    TV_CHECK(r.overflowed && r.spilled_count == 6 && r.spill_out == 0); /* behind the terminator */
    CHECK_OUT(r, 1);
    TV_CHECK(s.stencil == TV_STENCIL_SEALED && s.term_depth == 1.0f);
    /* a lost candidate in front of the terminator would be output */
    TV_CHECK(pvs_spill_output(&s, 7 | TV_ID_CANDIDATE, 0.8f) && !pvs_spill_output(&s, 7 | TV_ID_CANDIDATE, 1.2f));
    pvs_pixel_state untrimmed = {0};
    TV_CHECK(!pvs_spill_output(&untrimmed, 7 | TV_ID_CANDIDATE, 0.8f) && !pvs_spill_output(&untrimmed, 7, 0.8f));

    n = 0;
    items[n++] = (item)F(1.0f, 1);
    items[n++] = (item)T(1.2f, 1);
    items[n++] = (item)B(1.5f);
    items[n++] = (item)U(1000.0f, 1); /* behind every candidate */
    for (uint32_t i = 0; n < TV_K_FRONT + 8; i++)
        items[n++] = (item)C(2.0f + (float)i, 100 + i);
    pvs_pixel_state t = {0};
    r = run_layer(&t, items, n);
    /* The pixel stays open; every candidate, stored or lost, lies in the
     * umbra, the walk's spill span (1.5, 1000): none is output. */
    TV_CHECK(r.overflowed && r.spilled_count == 5 && r.spill_out == 0);
    CHECK_OUT(r, 1);
    TV_CHECK(t.stencil == TV_STENCIL_TRIMMED && t.spill_lo == 1.5f && t.spill_hi == 1000.0f);
}

/* Lost candidates at an open pixel: those strictly inside the walk's last
 * hidden span (an umbra, from the back of the interval it validates) are
 * hidden as the stored ones are; those in front of it, behind it or in a
 * validated interval's run are output, whether stored or lost, so the ids do
 * not depend on which found room. */
static void test_lost_candidates_in_span(void)
{
    item items[TV_K_FRONT + 8];
    uint32_t n = 0;
    items[n++] = (item)F(1.0f, 1);
    items[n++] = (item)C(1.1f, 300); /* in the validated run: eroded surface */
    items[n++] = (item)T(1.2f, 1);
    items[n++] = (item)B(1.5f);
    items[n++] = (item)U(5.0f, 1);
    items[n++] = (item)C(1.5f, 301); /* at the span's start: not inside */
    for (uint32_t i = 0; i < TV_K_FRONT / 2; i++) {
        items[n++] = (item)C(2.0f + 0.15f * (float)i, 100 + i); /* hidden */
        items[n++] = (item)C(6.0f + (float)i, 200 + i);         /* behind the umbra */
    }
    items[n++] = (item)C(5.0f, 302); /* at the umbra: not hidden */
    pvs_pixel_state s = {0};
    layer_result r = run_layer(&s, items, n);
    /* lost: 214, 115 (hidden), 215, 302 */
    TV_CHECK(r.overflowed && r.spilled_count == 4 && r.spill_out == 3 && s.stencil == TV_STENCIL_TRIMMED);
    TV_CHECK(s.spill_lo == 1.5f && s.spill_hi == 5.0f);
    /* bits: 100-115 -> 0-15, 200-215 -> 16-31, 300-302 -> 32-34, 1 -> 35 */
    uint64_t hidden = 0, shown = 0;
    for (uint32_t i = 0; i < r.count + r.spill_out; i++) {
        uint32_t id = i < r.count ? r.out[i] : r.spill_ids[i - r.count];
        if (id >= 100 && id < 100 + TV_K_FRONT / 2)
            hidden |= 1ull << (id - 100);
        else if (id == 1 || id >= 200)
            shown |= 1ull << (id == 1 ? 35 : id >= 300 ? id - 300 + 32 : id - 200 + 16);
    }
    TV_CHECK(hidden == 0);
    TV_CHECK(shown == (1ull << 36) - (1ull << 16));
}

/* The spill span ends at the umbrae's footprint (pvs_umbra_pack), not where
 * the centre's ray leaves them: a lost candidate between the two may be seen
 * past the umbra through the pixel's edge, so it is output, and the stored
 * ones there with it (ids must not depend on which found room); those in
 * front of the footprint are hidden, stored or lost. Where nothing is lost
 * the walk still hides up to the centre's umbra. */
static void test_spill_span_ends_at_footprint(void)
{
    float umbra = pvs_umbra_pack(5.0f, 3.0f), fp = pvs_umbra_footprint(umbra);
    TV_CHECK(pvs_umbra_centre(umbra) == 5.0f && fp <= 3.0f && fp > 2.98f);
    item items[4 + 2 * 18];
    uint32_t n = 0;
    items[n++] = (item)F(1.0f, 1);
    items[n++] = (item)T(1.2f, 1);
    items[n++] = (item)B(1.5f);
    items[n++] = (item)U(umbra, 1);
    for (uint32_t i = 0; i < 18; i++) {
        items[n++] = (item)C(1.6f + 0.07f * (float)i, 100 + i); /* in front of the footprint */
        items[n++] = (item)C(3.1f + 0.1f * (float)i, 200 + i);  /* behind it, in front of the centre's umbra */
    }
    pvs_pixel_state s = {0};
    layer_result r = run_layer(&s, items, 4 + 2 * 10); /* nothing lost */
    TV_CHECK(!r.overflowed && s.stencil == TV_STENCIL_TRIMMED);
    CHECK_OUT(r, 1);
    pvs_pixel_state t = {0};
    r = run_layer(&t, items, n); /* 5 candidates lost */
    TV_CHECK(r.overflowed && r.spilled_count == 5 && t.stencil == TV_STENCIL_TRIMMED);
    TV_CHECK(t.spill_lo == 1.5f && t.spill_hi == fp);
    uint64_t hidden = 0, shown = 0;
    for (uint32_t i = 0; i < r.count + r.spill_out; i++) {
        uint32_t id = i < r.count ? r.out[i] : r.spill_ids[i - r.count];
        if (id >= 100 && id < 118)
            hidden |= 1ull << (id - 100);
        else if (id >= 200 && id < 218)
            shown |= 1ull << (id - 200);
    }
    TV_CHECK(hidden == 0 && shown == (1ull << 18) - 1);
}

/* An umbra is stored in its region's entry (TV_PVS_REGION_SLOTS), so it no
 * longer overflows a list of its own: region 0's umbra joins its trim's
 * entry, and umbrae of regions without a trim here (which the GPU does not
 * store) are dropped once the list is full, without overflowing it. */
static void test_overflow_umbra_list(void)
{
    item items[TV_K_UMBRA + 4];
    uint32_t n = 0;
    items[n++] = (item)F(1.0f, 1);
    items[n++] = (item)T(1.2f, 0);
    items[n++] = (item)B(1.5f);
    for (uint32_t i = 0; n < TV_K_UMBRA + 4; i++)
        items[n++] = (item)U(5.0f + (float)i, i);
    pvs_pixel_state s = {0};
    layer_result r = run_layer(&s, items, n);
    TV_CHECK(!r.overflowed);
    CHECK_OUT(r, 1);
    TV_CHECK(s.stencil == TV_STENCIL_TRIMMED && s.hide_begin == 1.0f && s.hide_end == 5.0f);
    layer_result r2 = RUN(s, F(4.0f, 2), T(4.2f, 9), B(4.5f), F(6.0f, 3), B(6.5f));
    CHECK_OUT(r2, 3); /* 2 (eroded) inside region 0's umbra, 3 the terminator */
    TV_CHECK(s.stencil == TV_STENCIL_SEALED);
}

/* A deep pixel (a list longer than k_exact, none past its capacity) hides up
 * to its umbrae's footprints: [2, 2.5], validated, lies inside region 1's
 * umbra (3) and is hidden at a shallow pixel; at a deep one its footprint
 * (1.8) ends in front of it, and 2 is output. F 5 terminates both. A pixel
 * whose front list overflows behind that terminator is not deep: 2 stays hidden. */
static void test_deep_pixel_umbrae_at_footprints(void)
{
    float fp = pvs_umbra_pack(3.0f, 1.8f);
    for (uint32_t k_exact = 3; k_exact >= 2; k_exact--) {
        harness_k_exact = k_exact;
        pvs_pixel_state s = {0};
        layer_result r = RUN(s, F(1.0f, 1), T(1.2f, 1), B(1.5f), U(fp, 1), F(2.0f, 2), T(2.2f, 2), B(2.5f),
                             U(4.0f, 2), F(5.0f, 3), B(6.0f));
        TV_CHECK(!r.overflowed && s.stencil == TV_STENCIL_SEALED);
        if (k_exact == 3)
            CHECK_OUT(r, 1, 3);
        else
            CHECK_OUT(r, 1, 2, 3);
    }
    item items[TV_K_FRONT + 10] = {F(1.0f, 1), T(1.2f, 1), B(1.5f), U(fp, 1), F(2.0f, 2), T(2.2f, 2), B(2.5f),
                                   U(4.0f, 2), F(5.0f, 3), B(6.0f)};
    for (uint32_t i = 10; i < TV_K_FRONT + 10; i++)
        items[i] = (item)F(7.0f + (float)i, 100 + i);
    pvs_pixel_state s = {0};
    layer_result r = run_layer(&s, items, TV_K_FRONT + 10);
    TV_CHECK(r.overflowed && s.stencil == TV_STENCIL_SEALED);
    CHECK_OUT(r, 1, 3);
    harness_k_exact = 0;
}

/* A pixel deep by its region list alone keeps its umbrae: the fronts and
 * backs of test_deep_pixel_umbrae_at_footprints's shallow pixel (k_exact 3) with
 * two regions in front of them that meet no interval, so four region
 * entries: as shallow, [2, 2.5] lies in region 1's umbra and is hidden.
 * With the front and back lists holding 3 (pvs_desc.k_regions past k_deep)
 * the region list still resolves whole, and a fourth front overflows its
 * list (at k_lists 0 it would be stored and make the pixel deep, 2 output);
 * F 5 seals in front of it (docs/journal/2026-12-03-regovf.md). */
static void test_deep_by_regions_keeps_umbrae(void)
{
    harness_k_exact = 3;
    for (uint32_t lists = 0; lists <= 3; lists += 3) {
        harness_k_lists = lists;
        pvs_pixel_state s = {0};
        layer_result r = RUN(s, T(0.5f, 7), T(0.6f, 8), F(1.0f, 1), T(1.2f, 1), B(1.5f), U(3.0f, 1), F(2.0f, 2),
                             T(2.2f, 2), B(2.5f), U(4.0f, 2), F(5.0f, 3), B(6.0f));
        TV_CHECK(!r.overflowed && s.stencil == TV_STENCIL_SEALED);
        CHECK_OUT(r, 1, 3);
    }
    pvs_pixel_state s = {0};
    layer_result r = RUN(s, T(0.5f, 7), T(0.6f, 8), F(1.0f, 1), T(1.2f, 1), B(1.5f), U(3.0f, 1), F(2.0f, 2),
                         T(2.2f, 2), B(2.5f), U(4.0f, 2), F(5.0f, 3), B(6.0f), F(7.0f, 4));
    TV_CHECK(r.overflowed && s.stencil == TV_STENCIL_SEALED);
    CHECK_OUT(r, 1, 3);
    harness_k_exact = harness_k_lists = 0;
}

/* Sponza's deep pixel (382, 256) (docs/journal/2026-12-03-deepfix.md): a
 * shallow layer validates [1, 1.5] with region 1's umbra at 10 (its footprint
 * 4.14) and carries the hidden range [1, 10]; a later layer's faces at 4-5
 * lie in it. At a shallow pixel they stay hidden (F 20 seals unseen). Where
 * the front list is longer than k (k_deep off would output every front) that
 * range ends at its footprint, as umbrae do: C 4.2 and the terminator F 20
 * are output, C 4.0 and 4.1 stay hidden (dropping the range, as before
 * 2026-12-03-ovf2, output them too). A pixel deep by its trims alone keeps it. */
static void test_deep_pixel_carried_range_at_footprint(void)
{
    harness_k_exact = 3;
    for (uint32_t c = 0; c < 3; c++) { /* shallow, 4 fronts, 4 trims */
        pvs_pixel_state s = {0};
        layer_result r = RUN(s, F(1.0f, 1), T(1.2f, 1), B(1.5f), U(pvs_umbra_pack(10.0f, 4.15f), 1));
        CHECK_OUT(r, 1);
        TV_CHECK(s.stencil == TV_STENCIL_TRIMMED && s.hide_begin == 1.0f && s.hide_end == 10.0f);
        TV_CHECK(s.hide_end_fp > 4.1f && s.hide_end_fp < 4.15f);
        item later[] = {C(4.0f, 10), C(4.1f, 11), C(4.2f, 12), F(5.0f, 20), B(5.5f),
                        T(6.0f, 7),  T(6.1f, 8),  T(6.2f, 9),  T(6.3f, 10)};
        r = c == 1 ? run_layer(&s, later, 5) : run_layer(&s, later + 1, c == 0 ? 4 : 8);
        TV_CHECK(!r.overflowed && s.stencil == TV_STENCIL_SEALED && s.term_depth == 5.0f);
        if (c == 1)
            CHECK_OUT(r, 12, 20);
        else
            CHECK_NONE(r);
    }
    harness_k_exact = 0;
}

/* Lost trims: every interval reaching back to the nearest lost trim counts
 * as validated, hiding up to its back. Alone, F1 would terminate; with trims
 * lost at 0.5 F1, F2, F3 are output and the pixel stays open; a carried run
 * gets a stand-in trim that validates it in the next layer. Trims lost
 * behind an interval cannot have validated it (the sequence is complete in
 * front of them). */
static void test_overflow_trim_list(void)
{
    item items[TV_K_TRIM + 8];
    uint32_t n = 0;
    for (uint32_t i = 0; i <= TV_K_TRIM; i++)
        items[n++] = (item)T(0.5f, i);
    const item rest[] = {F(1.0f, 1), B(1.5f), F(2.0f, 2), B(2.5f), F(3.0f, 3), B(3.5f), F(4.0f, 4)};
    for (uint32_t i = 0; i < sizeof rest / sizeof rest[0]; i++)
        items[n++] = rest[i];
    pvs_pixel_state s = {0};
    layer_result r = run_layer(&s, items, n);
    TV_CHECK(r.overflowed);
    CHECK_OUT(r, 1, 2, 3);
    TV_CHECK(s.stencil == TV_STENCIL_TRIMMED && s.carry_count == 2);
    TV_CHECK(s.carry[1].kind == TV_ENTRY_TRIM && s.carry[1].id == TV_ID_PRIOR && s.carry[1].depth == 4.0f);
    layer_result r2 = RUN(s, B(4.5f), F(5.0f, 5), B(5.5f), F(6.0f, 6));
    CHECK_OUT(r2, 4, 5); /* [4, 4.5] validated by the stand-in, 5 terminates */
    TV_CHECK(!r2.overflowed && s.stencil == TV_STENCIL_SEALED);

    n = 0;
    for (uint32_t i = 0; i <= TV_K_TRIM; i++)
        items[n++] = (item)T(5.0f, i);
    items[n++] = (item)F(1.0f, 1);
    items[n++] = (item)B(1.5f);
    items[n++] = (item)F(2.0f, 2);
    pvs_pixel_state near = {0};
    r = run_layer(&near, items, n);
    CHECK_OUT(r, 1); /* [1, 1.5] lies in front of every lost trim: F1 terminates */
    TV_CHECK(r.overflowed && near.stencil == TV_STENCIL_SEALED && near.term_depth == 1.0f);
    /* Which trims behind the nearest lost one found room depends on arrival
     * order, so they count for nothing: region 7's fragment at 9 (stored)
     * does not make it straddle [1, 1.5]. The carried F3 gets the stand-in
     * at its own depth, and the stored trims behind the lost one are not
     * carried. */
    n = 0;
    items[n++] = (item)T(0.5f, 7);
    items[n++] = (item)T(9.0f, 7); /* in region 7's entry */
    for (uint32_t i = 1; i < TV_K_TRIM; i++)
        items[n++] = (item)T(0.2f, 100 + i);
    items[n++] = (item)T(5.0f, 99); /* lost */
    items[n++] = (item)F(1.0f, 1);
    items[n++] = (item)B(1.5f);
    items[n++] = (item)F(3.0f, 3);
    pvs_pixel_state run = {0};
    r = run_layer(&run, items, n);
    CHECK_OUT(r, 1);
    TV_CHECK(r.overflowed && run.stencil == TV_STENCIL_SEALED && run.term_depth == 1.0f);
    n -= 3;
    items[n++] = (item)F(3.0f, 3);
    pvs_pixel_state open = {0};
    r = run_layer(&open, items, n);
    CHECK_NONE(r);
    TV_CHECK(open.stencil == TV_STENCIL_TRIMMED && open.carry_count == 2);
    TV_CHECK(open.carry[1].kind == TV_ENTRY_TRIM && open.carry[1].id == TV_ID_PRIOR && open.carry[1].depth == 3.0f);
}

/* A trim region's fragment is one entry: two trim depths and its umbra
 * (TV_PVS_REGION_SLOTS; a third depth, the farther plane, in a second).
 * Eleven regions of three trim depths each (33 trims, 22 entries; more than
 * the K = 32 trim entries of one trim per entry, which held ten such
 * regions, five at k = 16) no longer overflow: region 10's farther
 * trim is not lost, so [F1, B1.5], which its nearer trim meets, hides up to
 * its umbra at 3, F2 terminates there and F3 is not output. With one trim
 * per entry the 2.2 trim was lost: [F4, B4.5] reached back to it, counted as
 * validated, and F3 was output with the pixel left open. */
static void test_regions_in_one_entry(void)
{
    item items[11 * 4 + 6];
    uint32_t n = 0;
    for (uint32_t i = 0; i < 10; i++) { /* in front of every face: they meet nothing */
        items[n++] = (item)T(0.3f, i);
        items[n++] = (item)T(0.2f, i);
        items[n++] = (item)T(0.35f, i);
        items[n++] = (item)U(0.4f, i);
    }
    const item rest[] = {T(2.0f, 10), T(1.00001f, 10), T(2.2f, 10), U(3.0f, 10), F(1.0f, 1), B(1.5f),
                         F(2.5f, 2),  B(2.8f),         F(4.0f, 3),  B(4.5f)};
    for (uint32_t i = 0; i < sizeof rest / sizeof rest[0]; i++)
        items[n++] = rest[i];
    pvs_pixel_state s = {0};
    layer_result r = run_layer(&s, items, n);
    TV_CHECK(!r.overflowed);
    CHECK_OUT(r, 1);
    TV_CHECK(s.stencil == TV_STENCIL_SEALED && s.term_depth == 2.5f);
}

/* A lost back merges two intervals: [F1, B1.5] (valid, umbra 1.8) and
 * [F2, B3.5] (not valid) become one valid interval hiding to 3.5. The
 * output is the same (F2 is the terminator in the full sequence); only the
 * far fillers decide where it seals. */
static void test_overflow_back_list(void)
{
    item items[TV_K_BACK + 8];
    uint32_t n = 0;
    items[n++] = (item)F(1.0f, 1);
    items[n++] = (item)T(1.2f, 1);
    items[n++] = (item)U(1.8f, 1);
    items[n++] = (item)F(2.0f, 2);
    for (uint32_t i = 0; i + 1 < TV_K_BACK; i++)
        items[n++] = (item)B(100.0f + (float)i);
    items[n++] = (item)B(3.5f);
    items[n++] = (item)B(1.5f); /* no room: lost */
    pvs_pixel_state s = {0};
    layer_result r = run_layer(&s, items, n);
    TV_CHECK(r.overflowed);
    CHECK_OUT(r, 1, 2, BACK_ID); /* the first filler is a lone back: the terminator */
    TV_CHECK(s.stencil == TV_STENCIL_SEALED);
}

/* Prior faces: the pixel's nearest faces from earlier layers (P2's centre
 * depths) enter the sequence when it becomes trimmed, never output. Here an
 * occluder whose front (at 1) was drawn in an earlier layer gets its back,
 * trim and umbra only now (an object spanning layers): it hides the small
 * eroded object 2 and lets F3 through, where without it the occluder's back
 * would have been taken for the terminator and F3 lost. */
static void test_prior_faces(void)
{
    pvs_pixel_state s = {0};
    layer_result r = RUN_PRIOR(s, 1.0f, 2.0f, T(1.5f, 1), B(2.0f), U(3.0f, 1), F(2.5f, 2), T(2.6f, 2), B(2.7f),
                               U(2.8f, 2), F(4.0f, 3), B(4.5f));
    CHECK_OUT(r, 3);
    TV_CHECK(s.stencil == TV_STENCIL_SEALED);
    pvs_pixel_state t = {0};
    r = RUN(t, T(1.5f, 1), B(2.0f), U(3.0f, 1), F(2.5f, 2), T(2.6f, 2), B(2.7f), U(2.8f, 2), F(4.0f, 3), B(4.5f));
    CHECK_OUT(r, BACK_ID); /* what the resolve did without prior faces */
    /* an untrimmed solid in front of a newly trimmed one seals at once */
    pvs_pixel_state u = {0};
    r = RUN_PRIOR(u, 1.0f, 1.5f, F(5.0f, 5), T(5.2f, 2), B(5.5f), U(9.0f, 2), F(10.0f, 6));
    CHECK_NONE(r);
    TV_CHECK(u.stencil == TV_STENCIL_SEALED);
    /* a single-sided surface seen from behind (a back alone) too */
    pvs_pixel_state v = {0};
    r = RUN_PRIOR(v, 0.0f, 1.0f, F(5.0f, 5), T(5.2f, 2), B(5.5f));
    CHECK_NONE(r);
    TV_CHECK(v.stencil == TV_STENCIL_SEALED);
    /* a prior face that this layer stored is not added twice: a second back
     * at the validated [1, 1.5]'s depth would have terminated the pixel */
    pvs_pixel_state x = {0};
    r = RUN_PRIOR(x, 1.0f, 1.5f, F(1.0f, 1), T(1.2f, 1), B(1.5f), F(2.0f, 2), T(2.2f, 2), B(2.5f), U(4.0f, 2),
                  F(5.0f, 3));
    CHECK_OUT(r, 1, 2);
    TV_CHECK(x.stencil == TV_STENCIL_TRIMMED && x.carry_count == 1);
    /* prior faces only join when the pixel becomes trimmed */
    pvs_pixel_state w = {0};
    RUN(w, F(0.5f, 1), T(0.6f, 3), B(0.7f), U(0.8f, 3), F(0.9f, 9));
    r = RUN_PRIOR(w, 0.0f, 0.85f, F(5.0f, 5), B(5.5f));
    CHECK_OUT(r, 9); /* the carried 9 terminates; a prior back at 0.85 would have hidden it */
}

/* A trailing run longer than the carry: its fronts are output at once. */
static void test_carry_overflow(void)
{
    item items[TV_K_CARRY + 3];
    uint32_t n = 0;
    items[n++] = (item)T(0.5f, 1);
    for (uint32_t i = 0; i < TV_K_CARRY + 2; i++)
        items[n++] = (item)F(1.0f + (float)i, 200 + i);
    pvs_pixel_state s = {0};
    layer_result r = run_layer(&s, items, n);
    TV_CHECK(r.overflowed && r.count == TV_K_CARRY + 2);
    TV_CHECK(s.stencil == TV_STENCIL_OVERFLOW && s.carry_count == 0);
}

/* A run carrying 22 trims of eleven regions and their umbrae (44 entries
 * unpacked; Sponza's full carries were such runs): ten regions with a trim
 * in front of the run's first front and two behind it, both moved to that
 * front (an entry each, with the umbra), and one wholly behind it (its two
 * trims in one entry, its umbra in another). They fit TV_K_CARRY, and the
 * next layer resolves as if nothing had been carried: [1, 1.5] validated,
 * hidden up to the nearest umbra 3 (region 30's), so 2 at 4 terminates. */
static void test_carry_packs_regions(void)
{
    item items[1 + 10 * 4 + 3];
    uint32_t n = 0;
    items[n++] = (item)F(1.0f, 1);
    for (uint32_t r = 10; r < 20; r++) {
        item region[4] = {T(0.9f, r), T(1.1f, r), T(1.2f, r), U(5.0f + (float)r, r)};
        memcpy(items + n, region, sizeof region);
        n += 4;
    }
    items[n++] = (item)T(1.3f, 30);
    items[n++] = (item)T(1.4f, 30);
    items[n++] = (item)U(3.0f, 30);
    pvs_pixel_state s = {0};
    layer_result r = run_layer(&s, items, n);
    CHECK_NONE(r);
    TV_CHECK(!r.overflowed && s.stencil == TV_STENCIL_TRIMMED && s.carry_count == 13);
    TV_CHECK(s.carry[1].kind == (TV_ENTRY_TRIM | TV_CARRY_TWICE | TV_CARRY_UMBRA) && s.carry[1].depth == 1.0f);
    r = RUN(s, B(1.5f), F(4.0f, 2), B(4.5f), F(20.0f, 3), B(21.0f));
    CHECK_OUT(r, 1, 2);
    TV_CHECK(!r.overflowed && s.stencil == TV_STENCIL_SEALED && s.term_depth == 4.0f);
}

/* The carry as pvs_carry_add packs it and the same entries unpacked (one a
 * trim, one an umbra: what P3 carried before 2026-12-03) resolve alike:
 * random runs of fronts, trims and umbrae of three regions, then a random
 * layer of backs and fronts. */
static void test_carry_packing_lossless(void)
{
    uint32_t seed = 7u, compared = 0, packed = 0;
    for (uint32_t trial = 0; trial < 4000; trial++) {
        item a[24], b[6];
        uint32_t na = 0, nb = 0;
        a[na++] = (item)F(1.0f, 1);
        for (uint32_t i = 0; i < 6 + trial % 17; i++) {
            seed = seed * 1664525u + 1013904223u;
            uint32_t kind = (seed >> 8) % 4, region = 10 + (seed >> 12) % 3;
            float d = 0.5f + 0.25f * (float)((seed >> 16) % 6);
            a[na++] = kind == 0 ? (item)F(d, 2 + i) : kind == 3 ? (item)U(d + 2.0f, region) : (item)T(d, region);
        }
        for (uint32_t i = 0; i < 6; i++) {
            seed = seed * 1664525u + 1013904223u;
            float d = 0.5f + 0.4f * (float)((seed >> 16) % 8);
            b[nb++] = (seed >> 8) % 2 ? (item)B(d) : (item)F(d, 30 + i);
        }
        pvs_pixel_state s = {0};
        layer_result r = run_layer(&s, a, na);
        pvs_pixel_state plain = s;
        plain.carry_count = 0;
        bool fits = true;
        for (uint32_t i = 0; i < s.carry_count; i++) {
            const pvs_entry* e = &s.carry[i];
            float trim[2], u;
            uint32_t t = pvs_carry_trims(e, trim);
            packed += t == 2 || (e->kind & TV_CARRY_UMBRA) != 0;
            for (uint32_t j = 0; j < (t ? t : 1) && fits; j++) {
                fits = plain.carry_count < TV_K_CARRY;
                if (fits)
                    plain.carry[plain.carry_count++] = t ? (pvs_entry){trim[j], TV_ENTRY_TRIM, e->id, 0.0f} : *e;
            }
            if (fits && (e->kind & TV_CARRY_UMBRA) != 0 && pvs_carry_umbra(e, e->id, &u)) {
                fits = plain.carry_count < TV_K_CARRY;
                if (fits)
                    plain.carry[plain.carry_count++] = (pvs_entry){u, TV_ENTRY_UMBRA, e->id, 0.0f};
            }
        }
        if (r.overflowed || s.stencil != TV_STENCIL_TRIMMED || !fits)
            continue;
        layer_result r1 = run_layer(&s, b, nb), r2 = run_layer(&plain, b, nb);
        bool same = r1.count == r2.count && memcmp(r1.out, r2.out, r1.count * sizeof r1.out[0]) == 0 &&
                    s.stencil == plain.stencil && s.carry_count == plain.carry_count &&
                    memcmp(s.carry, plain.carry, s.carry_count * sizeof s.carry[0]) == 0 &&
                    s.hide_begin == plain.hide_begin && s.hide_end == plain.hide_end;
        if (!same)
            printf("  trial %u: packed and unpacked carries resolve differently\n", trial);
        TV_CHECK(same);
        compared++;
    }
    printf("  %u pixels compared, %u packed entries\n", compared, packed);
    TV_CHECK(compared > 1000 && packed > 1000);
}

/* The ids two layers output, the spill draws' included, as a bit set over
 * ids below 64 (BACK_ID as bit 63). */
static uint64_t two_layers(const item* a, uint32_t na, const item* b, uint32_t nb, uint32_t pages, bool* lost)
{
    pvs_pixel_state s = {0};
    uint64_t ids = 0;
    *lost = false;
    for (int l = 0; l < 2; l++) {
        harness_pages = l == 0 ? pages : HARNESS_MAX_PAGES;
        layer_result r = l == 0 ? run_layer(&s, a, na) : run_layer(&s, b, nb);
        for (uint32_t i = 0; i < r.count; i++)
            ids |= 1ull << (r.out[i] == BACK_ID ? 63 : r.out[i]);
        for (uint32_t i = 0; i < r.spill_out; i++)
            ids |= 1ull << r.spill_ids[i];
        /* a layer that ran out of pages must read as overflowed */
        TV_CHECK(r.pages_taken <= harness_pages || r.overflowed);
        *lost |= r.pages_taken > harness_pages;
    }
    harness_pages = HARNESS_MAX_PAGES;
    return ids;
}

/* Every pool size from none to enough: what the pool cannot hold is lost
 * as an entry past k is, so the output only grows (never a lost triangle),
 * and with room for every page it is the output of a pool that never ran
 * out. Two boxes behind a wall seen past its edge, candidates, more trims
 * and fronts than one page holds, then a second layer behind them. */
static void test_pool_exhaustion(void)
{
    const item a[] = {F(1.0f, 1), C(1.1f, 2), T(1.2f, 1), T(1.3f, 2), B(1.5f), U(9.0f, 1), U(4.0f, 2),
                      F(2.0f, 3), T(2.1f, 3), B(2.5f), U(8.0f, 3), F(3.0f, 4), C(3.2f, 5), B(3.5f),
                      F(5.0f, 6), T(5.5f, 4), B(6.0f), U(7.0f, 4), F(6.5f, 7), B(7.5f), C(12.0f, 8)};
    const item b[] = {F(4.0f, 9), B(4.5f), F(10.0f, 10), B(11.0f), C(0.5f, 11)};
    const uint32_t na = sizeof a / sizeof a[0], nb = sizeof b / sizeof b[0];
    bool lost;
    uint64_t full = two_layers(a, na, b, nb, HARNESS_MAX_PAGES, &lost);
    TV_CHECK(!lost && full != 0);
    uint32_t lossy = 0;
    for (uint32_t pages = 0; pages <= 12; pages++) {
        uint64_t got = two_layers(a, na, b, nb, pages, &lost);
        if ((full & ~got) != 0)
            printf("  pool of %u pages: ids 0x%llx missing\n", pages, (unsigned long long)(full & ~got));
        TV_CHECK((full & ~got) == 0);
        TV_CHECK(lost || got == full);
        lossy += lost;
    }
    TV_CHECK(lossy >= 4 && lossy < 13); /* the pixel needs at least 4 pages (one per list), at most 12 */
}

int main(void)
{
    TV_TEST_RUN(test_overflow_keeps_every_front);
    TV_TEST_RUN(test_overflow_behind_terminator);
    TV_TEST_RUN(test_lost_candidates_in_span);
    TV_TEST_RUN(test_spill_span_ends_at_footprint);
    TV_TEST_RUN(test_overflow_umbra_list);
    TV_TEST_RUN(test_deep_pixel_umbrae_at_footprints);
    TV_TEST_RUN(test_deep_pixel_carried_range_at_footprint);
    TV_TEST_RUN(test_deep_by_regions_keeps_umbrae);
    TV_TEST_RUN(test_overflow_trim_list);
    TV_TEST_RUN(test_regions_in_one_entry);
    TV_TEST_RUN(test_overflow_back_list);
    TV_TEST_RUN(test_prior_faces);
    TV_TEST_RUN(test_carry_overflow);
    TV_TEST_RUN(test_carry_packs_regions);
    TV_TEST_RUN(test_carry_packing_lossless);
    TV_TEST_RUN(test_pool_exhaustion);
    return tv_test_finish();
}
