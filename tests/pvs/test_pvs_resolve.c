/* Trim-sequence resolve (P3 reference): paper Figure 9 (R1, R2, R3) and
 * Figure 5, soups (consecutive fronts/backs), interpenetration, carried
 * intervals, fast paths and the overflow policy. Depths are arbitrary
 * monotonic units; F/B/T/U build fronts (triangle id), backs, trims and
 * umbrae (trim-region id). */
#include <stdlib.h>
#include <string.h>

#include "resolve.h"
#include "pvs_test_scenes.h"
#include "test.h"

typedef struct item {
    uint32_t kind;
    float depth;
    uint32_t id;
} item;

#define BACK_ID 500u
#define F(d, id) {TV_ENTRY_FRONT, d, id}
#define B(d) {TV_ENTRY_BACK, d, BACK_ID} /* every back is one triangle: its id only matters when output */
#define BI(d, id) {TV_ENTRY_BACK, d, id}
#define T(d, r) {TV_ENTRY_TRIM, d, r}
#define U(d, r) {TV_ENTRY_UMBRA, d, r}

typedef struct layer_result {
    uint32_t out[PVS_RESOLVE_MAX_OUTPUT];
    uint32_t count;
    uint32_t spilled[64]; /* fronts P2 could not store */
    uint32_t spilled_count;
    uint32_t spill_out; /* how many of them pvs_spill_output adds to the PVS */
    bool overflowed;
} layer_result;

/* prior_front / prior_back: P2's nearest front / back depth at the pixel
 * centre over this and the earlier layers (0: none). */
static layer_result run_layer_prior(pvs_pixel_state* s, float prior_front, float prior_back, const item* items,
                                    uint32_t n)
{
    pvs_kbuf k;
    memset(&k, 0, sizeof k);
    k.nearest_front = prior_front;
    k.nearest_back = prior_back;
    layer_result r = {0};
    for (uint32_t i = 0; i < n; i++) {
        if (!pvs_kbuf_push(&k, items[i].kind, items[i].depth, items[i].id) && items[i].kind == TV_ENTRY_FRONT)
            r.spilled[r.spilled_count++] = items[i].id;
    }
    r.count = pvs_resolve_pixel(s, &k, r.out, &r.overflowed);
    for (uint32_t i = 0, j = 0; i < n; i++) {
        if (j < r.spilled_count && items[i].kind == TV_ENTRY_FRONT && items[i].id == r.spilled[j])
            r.spill_out += pvs_spill_output(s, items[i].id, items[i].depth), j++;
    }
    return r;
}

static layer_result run_layer(pvs_pixel_state* s, const item* items, uint32_t n)
{
    return run_layer_prior(s, 0.0f, 0.0f, items, n);
}

/* Output equals exactly the ids in `want` (order free). */
static bool same_set(const layer_result* r, const uint32_t* want, uint32_t n)
{
    if (r->count != n)
        return false;
    for (uint32_t i = 0; i < n; i++) {
        bool found = false;
        for (uint32_t j = 0; j < r->count; j++)
            found |= r->out[j] == want[i];
        if (!found)
            return false;
    }
    return true;
}

#define CHECK_OUT(r, ...)                                                       \
    do {                                                                        \
        const uint32_t want_[] = {__VA_ARGS__};                                 \
        TV_CHECK(same_set(&(r), want_, sizeof want_ / sizeof want_[0]));        \
    } while (0)
#define CHECK_NONE(r) TV_CHECK((r).count == 0)
#define RUN(s, ...)                                                             \
    run_layer(&(s), (const item[]){__VA_ARGS__}, sizeof((const item[]){__VA_ARGS__}) / sizeof(item))

#define RUN_PRIOR(s, f, b, ...)                                                 \
    run_layer_prior(&(s), f, b, (const item[]){__VA_ARGS__}, sizeof((const item[]){__VA_ARGS__}) / sizeof(item))

#define C(d, id) {TV_ENTRY_FRONT, d, (id) | TV_ID_CANDIDATE}

/* Candidate fronts (touching the pixel off its centre) are output where not
 * hidden, inside validated intervals too, but never occlude: a candidate
 * before an invalid interval does not terminate it (F3 at 5 is output, as
 * without the candidate), one inside an umbra or behind the terminator is
 * not output, and output ids carry no flag. */
static void test_candidate_fronts(void)
{
    pvs_pixel_state s = {0};
    layer_result r = RUN(s, C(0.5f, 7), F(1.0f, 1), C(1.3f, 8), T(1.2f, 1), B(1.5f), U(3.0f, 1), C(2.0f, 9),
                         F(5.0f, 3), B(6.0f), C(7.0f, 10));
    CHECK_OUT(r, 7, 1, 8, 3);
    TV_CHECK(s.stencil == TV_STENCIL_SEALED);
    pvs_pixel_state alone = {0};
    r = RUN(alone, T(0.5f, 1), C(1.0f, 4), F(2.0f, 5), B(3.0f));
    CHECK_OUT(r, 4, 5); /* without the flag, [C, F, B] would be one invalid interval and F lost */
    TV_CHECK(alone.stencil == TV_STENCIL_SEALED);
}

#define CB(d, id) {TV_ENTRY_BACK, d, (id) | TV_ID_CANDIDATE}

/* Candidate backs (the back of a triangle narrower than a pixel, touching
 * it off its centre) are output only in front of every face at the centre
 * and outside every hidden range: CB 7 is, CB 8 behind the validated
 * interval is not, where a candidate front (9) is. Neither closes an
 * interval: [F 5, B 3] stays one interval, validated by the trim at 2, so
 * F 5 does not become a terminator. */
static void test_candidate_backs(void)
{
    pvs_pixel_state s = {0};
    layer_result r = RUN(s, CB(0.5f, 7), F(1.0f, 1), T(1.2f, 1), B(1.5f), U(3.0f, 1), CB(4.0f, 8), C(4.0f, 9),
                         F(5.0f, 3), B(6.0f));
    CHECK_OUT(r, 7, 1, 9, 3);
    TV_CHECK(s.stencil == TV_STENCIL_SEALED);
    pvs_pixel_state open = {0};
    r = RUN(open, F(1.0f, 5), CB(1.5f, 6), T(2.0f, 1), B(3.0f));
    CHECK_OUT(r, 5);
    TV_CHECK(open.stencil == TV_STENCIL_TRIMMED);
    /* they take at most half the back list, so real backs keep the rest */
    pvs_kbuf k = {0};
    uint32_t stored = 0;
    for (uint32_t i = 0; i < TV_K_BACK; i++)
        stored += pvs_kbuf_push(&k, TV_ENTRY_BACK, 1.0f + (float)i, i | TV_ID_CANDIDATE);
    TV_CHECK(stored == TV_K_BACK / 2 && k.back_count == TV_K_BACK / 2);
    for (uint32_t i = 0; i < TV_K_BACK / 2; i++)
        TV_CHECK(pvs_kbuf_push(&k, TV_ENTRY_BACK, 50.0f + (float)i, 100 + i));
    TV_CHECK(!pvs_kbuf_push(&k, TV_ENTRY_BACK, 99.0f, 200));
}

/* R1: f1 t1 b1 validated (u1 at 3) -> f1 out; f2 lies inside u1, but its
 * interval [f2, b2] has no trim: an uneroded surface, it seals the pixel
 * unseen (the paper lets b2, behind u1, terminate: the same output, but
 * a later face between f2 and b2 would count as visible); f3 never
 * reached. A later layer's faces (a triangle is drawn in the layer of its
 * earliest octree leaf, so a nearer one can come after the terminator)
 * are output in front of the terminator, unless inside the hidden range
 * kept at sealing (from b1 to f2). With f2's interval validated (its own
 * trim), b2 is the terminator as in the paper. */
static void test_figure9_r1(void)
{
    pvs_pixel_state s = {0};
    layer_result r = RUN(s, F(1.0f, 1), T(1.2f, 1), B(1.5f), U(3.0f, 1), F(2.0f, 2), B(4.0f), F(5.0f, 3), B(6.0f));
    CHECK_OUT(r, 1);
    TV_CHECK(s.stencil == TV_STENCIL_SEALED && s.term_depth == 2.0f);
    TV_CHECK(s.hide_begin == 1.5f && s.hide_end == 2.0f);
    layer_result later = RUN(s, F(0.5f, 9), F(1.8f, 10), F(3.5f, 11), F(5.0f, 12), T(0.55f, 5));
    CHECK_OUT(later, 9);
    TV_CHECK(s.stencil == TV_STENCIL_SEALED && s.term_depth == 2.0f);
    pvs_pixel_state v = {0};
    r = RUN(v, F(1.0f, 1), T(1.2f, 1), B(1.5f), U(3.0f, 1), F(2.0f, 2), T(2.5f, 2), BI(4.0f, 7), F(5.0f, 3), B(6.0f));
    CHECK_OUT(r, 1, 3);
    TV_CHECK(v.stencil == TV_STENCIL_SEALED && v.term_depth == 5.0f); /* f2's range ends at b2: f3 seals */
    TV_CHECK(v.hide_begin == 1.5f && v.hide_end == 4.0f);
}

/* A pillar with a crack in its front surface: the interval validated by
 * the crack edge's region outputs its back (seen through the crack) with
 * its front; the same interval validated by an ordinary silhouette's region
 * does not, and neither does a cracked interval that starts inside an
 * earlier umbra. A crack trim up to TV_PVS_CRACK_SLACK_M in front of the
 * front (in its own face's plane, the visible face a neighbour behind it)
 * validates nothing, but the terminating front's back is output; one
 * farther in front does not count. */
static void test_cracked_interval(void)
{
    const uint32_t crack = 7u | TV_REGION_CRACK;
    pvs_pixel_state s = {0};
    layer_result r = RUN(s, F(1.0f, 1), T(1.0f, crack), BI(1.5f, 2), U(3.0f, crack), F(4.0f, 3), B(5.0f));
    CHECK_OUT(r, 1, 2, 3);
    pvs_pixel_state plain = {0};
    r = RUN(plain, F(1.0f, 1), T(1.0f, 7), BI(1.5f, 2), U(3.0f, 7), F(4.0f, 3), B(5.0f));
    CHECK_OUT(r, 1, 3);
    pvs_pixel_state inside = {0};
    r = RUN(inside, F(0.5f, 4), T(0.6f, 8), BI(0.7f, 5), U(6.0f, 8), F(1.0f, 1), T(1.0f, crack), BI(1.5f, 2),
            U(3.0f, crack), F(7.0f, 3), B(8.0f));
    CHECK_OUT(r, 4, 3);
    pvs_pixel_state slack = {0};
    r = RUN(slack, T(1.0f - 0.5f * TV_PVS_CRACK_SLACK_M, crack), F(1.0f, 1), BI(1.5f, 2), F(4.0f, 3), B(5.0f));
    CHECK_OUT(r, 1, 2);
    TV_CHECK(slack.stencil == TV_STENCIL_SEALED && slack.term_depth == 1.0f);
    pvs_pixel_state far = {0};
    r = RUN(far, T(1.0f - 2.0f * TV_PVS_CRACK_SLACK_M, crack), F(1.0f, 1), BI(1.5f, 2), F(4.0f, 3), B(5.0f));
    CHECK_OUT(r, 1);
}

/* A trim region drawn at two depths that straddle a thin solid's interval
 * (P1 draws a trim quad at its solid's near plane, midpoint and far plane)
 * validates it: the solid lies between those depths. A single trim
 * outside the interval does not. Carried: the region's fragment in front of
 * the run's first front is not carried, so the one behind it moves to that
 * front. An interval starting on the region's farther plane is met. */
static void test_trim_region_straddles_interval(void)
{
    pvs_pixel_state s = {0};
    layer_result r = RUN(s, T(0.9f, 5), F(1.0f, 1), B(1.2f), T(1.5f, 5), U(3.0f, 5), F(4.0f, 3), B(4.5f));
    CHECK_OUT(r, 1, 3);
    TV_CHECK(s.stencil == TV_STENCIL_SEALED && s.term_depth == 4.0f);
    pvs_pixel_state one = {0};
    r = RUN(one, T(0.9f, 5), F(1.0f, 1), B(1.2f), T(1.5f, 6), U(3.0f, 5), F(4.0f, 3), B(4.5f));
    CHECK_OUT(r, 1);
    TV_CHECK(one.stencil == TV_STENCIL_SEALED && one.term_depth == 1.0f);
    pvs_pixel_state c = {0};
    r = RUN(c, T(0.9f, 5), F(1.0f, 1), T(1.5f, 5), U(3.0f, 5));
    CHECK_NONE(r);
    TV_CHECK(c.stencil == TV_STENCIL_TRIMMED && c.carry_count == 3);
    TV_CHECK(c.carry[1].kind == TV_ENTRY_TRIM && c.carry[1].id == 5 && c.carry[1].depth == 1.0f);
    r = RUN(c, B(1.2f), F(4.0f, 3), B(4.5f));
    CHECK_OUT(r, 1, 3);
    /* Two draws (nearer plane 1.0, midpoint 1.05): the undrawn farther
     * plane is at 1.1, and an interval whose front lies on it (a face in
     * that plane) is met; one starting 1 % behind it, or a single draw, is
     * not. */
    pvs_pixel_state far = {0};
    r = RUN(far, T(1.0f, 5), T(1.05f, 5), F(1.1f, 1), B(1.5f), U(3.0f, 5), F(4.0f, 3), B(4.5f));
    CHECK_OUT(r, 1, 3);
    pvs_pixel_state beyond = {0};
    r = RUN(beyond, T(1.0f, 5), T(1.05f, 5), F(1.111f, 1), B(1.5f), U(3.0f, 5), F(4.0f, 3), B(4.5f));
    CHECK_OUT(r, 1);
    pvs_pixel_state single = {0};
    r = RUN(single, T(1.0999f, 5), F(1.1f, 1), B(1.5f), U(3.0f, 5), F(4.0f, 3), B(4.5f));
    CHECK_OUT(r, 1);
}

/* R2: two validated intervals, the second inside the first's umbra; f3
 * (inside u2, unfinished) carried; in layer i+1 b3 terminates. */
static void test_figure9_r2(void)
{
    pvs_pixel_state s = {0};
    layer_result r = RUN(s, F(1.0f, 1), T(1.2f, 1), B(1.5f), U(3.0f, 1), F(2.0f, 2), T(2.2f, 2), B(2.5f),
                         U(4.0f, 2), F(3.5f, 3));
    CHECK_OUT(r, 1);
    TV_CHECK(s.stencil == TV_STENCIL_TRIMMED);
    TV_CHECK(s.carry_count == 1 && s.carry[0].kind == TV_ENTRY_FRONT && s.carry[0].id == 3);
    TV_CHECK(s.hide_begin == 2.0f && s.hide_end == 4.0f); /* u2 still open at f3 */
    layer_result r2 = RUN(s, B(5.0f), F(6.0f, 4), B(7.0f));
    CHECK_NONE(r2);
    TV_CHECK(s.stencil == TV_STENCIL_SEALED);
}

/* R3: like R2 but f3 lies behind u2: carried, validated in layer i+1 by t3,
 * output there; f4 lies inside u3 with an unvalidated interval: it seals
 * the pixel unseen, and f5 behind it is hidden (the paper ignores f4 and
 * lets f5 terminate). With f4 validated (t4), f5 terminates and is output. */
static void test_figure9_r3(void)
{
    pvs_pixel_state s = {0};
    layer_result r = RUN(s, F(1.0f, 1), T(1.2f, 1), B(1.5f), U(3.0f, 1), F(2.0f, 2), T(2.2f, 2), B(2.5f),
                         U(4.0f, 2), F(4.5f, 3));
    CHECK_OUT(r, 1);
    TV_CHECK(s.carry_count == 1 && s.hide_begin >= s.hide_end);
    pvs_pixel_state s2 = s;
    layer_result r2 = RUN(s, T(5.0f, 3), B(5.5f), U(8.0f, 3), F(7.0f, 4), B(7.5f), F(9.0f, 5), B(10.0f));
    CHECK_OUT(r2, 3);
    TV_CHECK(s.stencil == TV_STENCIL_SEALED && s.term_depth == 7.0f);
    r2 = RUN(s2, T(5.0f, 3), B(5.5f), U(8.0f, 3), F(7.0f, 4), T(7.2f, 4), B(7.5f), F(9.0f, 5), B(10.0f));
    CHECK_OUT(r2, 3, 5);
    TV_CHECK(s2.stencil == TV_STENCIL_SEALED && s2.term_depth == 9.0f);
}

/* Figure 5 left: the occludee's trim region lies inside the occluder's
 * umbra: the occludee (and what its umbra covers) is not output; the first
 * untrimmed object behind the outer umbra terminates. An untrimmed object
 * inside the umbra (f3) hides what lies behind it unseen. */
static void test_figure5_umbra_inside_umbra(void)
{
    pvs_pixel_state s = {0};
    layer_result r = RUN(s, F(1.0f, 1), T(1.1f, 1), B(1.5f), U(10.0f, 1), F(3.0f, 2), T(3.2f, 2), B(3.5f),
                         U(6.0f, 2), F(11.0f, 4), B(12.0f));
    CHECK_OUT(r, 1, 4);
    TV_CHECK(s.stencil == TV_STENCIL_SEALED && s.term_depth == 11.0f);
    pvs_pixel_state t = {0};
    r = RUN(t, F(1.0f, 1), T(1.1f, 1), B(1.5f), U(10.0f, 1), F(3.0f, 2), T(3.2f, 2), B(3.5f), U(6.0f, 2),
            F(8.0f, 3), B(9.0f), F(11.0f, 4), B(12.0f));
    CHECK_OUT(r, 1);
    TV_CHECK(t.stencil == TV_STENCIL_SEALED && t.term_depth == 8.0f);
}

/* Figure 5 middle: the occludee's trim region is outside the umbra: both
 * fronts are visible, and the ray goes on past the second umbra. */
static void test_figure5_disjoint_umbrae(void)
{
    pvs_pixel_state s = {0};
    layer_result r = RUN(s, F(1.0f, 1), T(1.1f, 1), B(1.5f), U(4.0f, 1), F(5.0f, 2), T(5.2f, 2), B(5.5f),
                         U(8.0f, 2), F(7.0f, 3), T(7.2f, 3), B(7.5f));
    CHECK_OUT(r, 1, 2);
    TV_CHECK(s.stencil == TV_STENCIL_TRIMMED);
}

/* Soups: consecutive fronts extend the interval (every front of the run is
 * output); extra backs inside the umbra are ignored, one behind it ends the ray. */
static void test_soup_consecutive_faces(void)
{
    pvs_pixel_state s = {0};
    layer_result r = RUN(s, F(1.0f, 1), F(1.1f, 2), T(1.2f, 7), B(1.5f), B(1.6f), U(3.0f, 7), F(4.0f, 3), B(5.0f));
    CHECK_OUT(r, 1, 2, 3);
    TV_CHECK(s.stencil == TV_STENCIL_SEALED);
    pvs_pixel_state s2 = {0};
    layer_result r2 = RUN(s2, F(1.0f, 1), T(1.2f, 7), B(1.5f), U(1.55f, 7), B(1.6f), F(4.0f, 3), B(5.0f));
    CHECK_OUT(r2, 1, BACK_ID); /* b at 1.6 lies behind the umbra: a lone back, the terminator (output) */
    TV_CHECK(s2.stencil == TV_STENCIL_SEALED);
    /* The trim only validates its own interval: f2's interval has none. */
    pvs_pixel_state s3 = {0};
    layer_result r3 = RUN(s3, T(0.5f, 7), U(0.9f, 7), F(1.0f, 1), B(1.5f));
    CHECK_OUT(r3, 1);
    TV_CHECK(s3.stencil == TV_STENCIL_SEALED);
}

/* Interpenetrating objects A [1, 3] and B [2, 4]: with A trimmed both fronts
 * are candidates and B's back is inside A's umbra; without a trim A wins. */
static void test_interpenetrating(void)
{
    pvs_pixel_state s = {0};
    layer_result r = RUN(s, F(1.0f, 10), F(2.0f, 11), T(1.5f, 1), B(3.0f), B(4.0f), U(5.0f, 1), F(6.0f, 12), B(7.0f));
    CHECK_OUT(r, 10, 11, 12);
    TV_CHECK(s.stencil == TV_STENCIL_SEALED);
    pvs_pixel_state s2 = {.stencil = TV_STENCIL_TRIMMED};
    layer_result r2 = RUN(s2, F(1.0f, 10), F(2.0f, 11), B(3.0f), B(4.0f), F(6.0f, 12), B(7.0f));
    CHECK_OUT(r2, 10);
    TV_CHECK(s2.stencil == TV_STENCIL_SEALED);
}

/* The trim and umbra of an unfinished interval arrive before its back:
 * carried together, validated in the next layer. */
static void test_carry_trim_and_umbra(void)
{
    pvs_pixel_state s = {0};
    layer_result r = RUN(s, F(1.0f, 1), T(1.2f, 4), U(6.0f, 4));
    CHECK_NONE(r);
    TV_CHECK(s.carry_count == 3);
    layer_result r2 = RUN(s, B(1.5f), F(3.0f, 2), T(3.2f, 5), B(3.5f), F(7.0f, 3), B(8.0f));
    CHECK_OUT(r2, 1, 3); /* f2 lies in the carried umbra, f3 terminates */
    TV_CHECK(s.stencil == TV_STENCIL_SEALED);
}

/* A single-sided surface seen from behind past an occluder's edge: its back
 * face is the terminator and is output (the renderer draws back faces);
 * the back of a box whose front lies in the umbra is not; an eroded lone
 * back is output without terminating. */
static void test_lone_back_output(void)
{
    pvs_pixel_state s = {0};
    layer_result r = RUN(s, F(1.0f, 1), T(1.2f, 7), B(1.5f), U(3.0f, 7), BI(4.0f, 42));
    CHECK_OUT(r, 1, 42);
    TV_CHECK(s.stencil == TV_STENCIL_SEALED);
    pvs_pixel_state t = {0};
    r = RUN(t, F(1.0f, 1), T(1.2f, 7), B(1.5f), U(3.0f, 7), F(2.5f, 2), BI(4.0f, 43));
    CHECK_OUT(r, 1);
    TV_CHECK(t.stencil == TV_STENCIL_SEALED);
    /* A lone back that a trim region meets (here it lies on the farther
     * plane of a region drawn at its nearer plane 0.8 and midpoint 0.9):
     * eroded, eyes see past it. Output, and not the terminator. */
    pvs_pixel_state e = {0};
    r = RUN(e, T(0.8f, 5), T(0.9f, 5), BI(1.0f, 44), F(3.0f, 3), B(3.5f));
    CHECK_OUT(r, 44, 3);
    TV_CHECK(e.stencil == TV_STENCIL_SEALED && e.term_depth == 3.0f);
}

/* Without any trim fragment an untrimmed pixel is the visibility buffer's;
 * a trimmed pixel with a lone back face is sealed, the back output (a
 * single-sided surface seen from behind). */
static void test_fast_paths(void)
{
    pvs_pixel_state s = {0};
    layer_result r = RUN(s, F(1.0f, 1), B(2.0f), F(3.0f, 2));
    CHECK_NONE(r);
    TV_CHECK(s.stencil == TV_STENCIL_UNTRIMMED);
    pvs_pixel_state t = {.stencil = TV_STENCIL_TRIMMED};
    layer_result r2 = RUN(t, B(2.0f), F(3.0f, 2), B(4.0f));
    CHECK_OUT(r2, BACK_ID);
    TV_CHECK(t.stencil == TV_STENCIL_SEALED);
}

/* Front overflow: every front is either spilled by P2 or output by P3, and
 * the pixel stays open (later layers output all their fronts) unless a
 * terminator lies in front of the nearest lost front. Here the interval
 * [1, 1.5] hides everything up to its umbra at 60, beyond the lost ones. */
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
    items[n++] = (item)U(60.0f, 1);
    for (uint32_t i = 0; n < TV_K_FRONT + 8; i++)
        items[n++] = (item)C(2.0f + (float)i, 100 + i);
    pvs_pixel_state t = {0};
    r = run_layer(&t, items, n);
    TV_CHECK(r.overflowed && r.spilled_count == 5 && r.spill_out == 5); /* the pixel stays open */
    CHECK_OUT(r, 1); /* the stored candidates lie in the umbra */
    TV_CHECK(t.stencil == TV_STENCIL_TRIMMED);
}

/* A lost umbra only shortens a hidden range to its back: the pixel is
 * resolved as usual (not the all-fronts policy), and reported. */
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
    TV_CHECK(r.overflowed);
    CHECK_OUT(r, 1);
    TV_CHECK(s.stencil == TV_STENCIL_TRIMMED && s.hide_begin == 1.0f && s.hide_end == 5.0f);
    layer_result r2 = RUN(s, F(4.0f, 2), T(4.2f, 9), B(4.5f), F(6.0f, 3), B(6.5f));
    CHECK_OUT(r2, 3); /* 2 (eroded) inside region 0's umbra, 3 the terminator */
    TV_CHECK(s.stencil == TV_STENCIL_SEALED);
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
    items[n++] = (item)T(9.0f, 7);
    for (uint32_t i = 2; i < TV_K_TRIM; i++)
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

static int cmp_u32(const void* a, const void* b)
{
    uint32_t x = *(const uint32_t*)a, y = *(const uint32_t*)b;
    return (x > y) - (x < y);
}

static item random_item(uint32_t* rng, uint32_t i)
{
    float depth = 1.0f + 20.0f * pvs_test_rand(rng);
    uint32_t region = (uint32_t)(4.0f * pvs_test_rand(rng));
    switch ((uint32_t)(6.0f * pvs_test_rand(rng))) {
    case 0:
    case 1: return (item)F(depth, 1000 + i);
    case 2:
    case 3: return (item)B(depth);
    case 4: return (item)T(depth, region);
    default: return (item)U(depth, region);
    }
}

/* P2 fills the k-buffers in whatever order the rasteriser's atomics give:
 * the resolve must not depend on it. Also, in a trimmed pixel without carried
 * state whose nearest face is a front followed by some back, that front is
 * output (it starts either a validated interval or the terminator). */
static void test_random_sequences_order_free(void)
{
    uint32_t rng = 777, checked_nearest = 0;
    for (int round = 0; round < 400; round++) {
        pvs_pixel_state a = {.stencil = TV_STENCIL_TRIMMED}, b = a;
        for (int layer = 0; layer < 3; layer++) {
            item items[24], shuffled[24];
            uint32_t n = 4 + (uint32_t)(20.0f * pvs_test_rand(&rng));
            for (uint32_t i = 0; i < n; i++)
                items[i] = shuffled[i] = random_item(&rng, 100 * (uint32_t)layer + i);
            for (uint32_t i = n - 1; i > 0; i--) {
                uint32_t j = (uint32_t)((float)(i + 1) * pvs_test_rand(&rng));
                item t = shuffled[i];
                shuffled[i] = shuffled[j];
                shuffled[j] = t;
            }
            bool fresh = a.stencil == TV_STENCIL_TRIMMED && a.carry_count == 0 && a.hide_begin >= a.hide_end;
            layer_result ra = run_layer(&a, items, n), rb = run_layer(&b, shuffled, n);
            qsort(ra.out, ra.count, sizeof ra.out[0], cmp_u32);
            qsort(rb.out, rb.count, sizeof rb.out[0], cmp_u32);
            TV_CHECK(ra.count == rb.count && memcmp(ra.out, rb.out, ra.count * sizeof ra.out[0]) == 0);
            TV_CHECK(a.stencil == b.stencil && a.carry_count == b.carry_count);
            TV_CHECK(a.hide_begin == b.hide_begin && a.hide_end == b.hide_end);
            const item* nearest = NULL;
            bool back_after = false;
            for (uint32_t i = 0; i < n; i++) {
                if (items[i].kind == TV_ENTRY_FRONT && (!nearest || items[i].depth < nearest->depth))
                    nearest = &items[i];
            }
            bool back_before = false;
            for (uint32_t i = 0; i < n && nearest; i++) {
                back_after |= items[i].kind == TV_ENTRY_BACK && items[i].depth >= nearest->depth;
                back_before |= items[i].kind == TV_ENTRY_BACK && items[i].depth < nearest->depth;
            }
            if (fresh && nearest && back_after && !back_before) {
                checked_nearest++;
                TV_CHECK(bsearch(&nearest->id, ra.out, ra.count, sizeof ra.out[0], cmp_u32) != NULL);
            }
        }
    }
    TV_CHECK(checked_nearest > 100);
}

int main(void)
{
    TV_TEST_RUN(test_candidate_fronts);
    TV_TEST_RUN(test_candidate_backs);
    TV_TEST_RUN(test_figure9_r1);
    TV_TEST_RUN(test_trim_region_straddles_interval);
    TV_TEST_RUN(test_figure9_r2);
    TV_TEST_RUN(test_cracked_interval);
    TV_TEST_RUN(test_figure9_r3);
    TV_TEST_RUN(test_figure5_umbra_inside_umbra);
    TV_TEST_RUN(test_figure5_disjoint_umbrae);
    TV_TEST_RUN(test_soup_consecutive_faces);
    TV_TEST_RUN(test_interpenetrating);
    TV_TEST_RUN(test_carry_trim_and_umbra);
    TV_TEST_RUN(test_fast_paths);
    TV_TEST_RUN(test_lone_back_output);
    TV_TEST_RUN(test_overflow_keeps_every_front);
    TV_TEST_RUN(test_overflow_behind_terminator);
    TV_TEST_RUN(test_overflow_umbra_list);
    TV_TEST_RUN(test_overflow_trim_list);
    TV_TEST_RUN(test_overflow_back_list);
    TV_TEST_RUN(test_prior_faces);
    TV_TEST_RUN(test_carry_overflow);
    TV_TEST_RUN(test_random_sequences_order_free);
    return tv_test_finish();
}
