/* Regions wholly behind a closed prior front (docs/pvs-edge-cases.md, "Regions behind a prior front"): the P3
 * reference's rule (resolve_harness.h drives one pixel) and its guard, pvs_convex_patches on constructed meshes. */
#include "convex.h"
#include "resolve_harness.h"
#include "test.h"
#include "weld.h"

#include <math.h>

#define NONE_YET {INFINITY, INFINITY, INFINITY, INFINITY, INFINITY}

/* Three layers of the traced pixel of oa:oa_dm5 cell 1 (docs/journal/2026-12-03-dm5rest.md, section 2): a prior
 * front at 2.4717 with no back of its own, then, behind it, another solid's culled back (3199) and its three-draw
 * silhouette (region 0x334, 2.4x farther), then a far front (14774) a later layer closes. Returns what the last layer
 * outputs; `convex`: whether P2 finds the prior front's patch closed. */
static layer_result traced_pixel(bool convex, pvs_pixel_state* s)
{
    float centre[TV_PVS_CENTRE_STRIDE] = NONE_YET;
    harness_convex_front = convex ? 77u : 0u;
    layer_result r = RUN_KEPT(*s, centre, F(2.4717f, 77));
    TV_CHECK(r.count == 0 && s->stencil == TV_STENCIL_UNTRIMMED);
    TV_CHECK(centre[TV_PVS_CENTRE_NONCONVEX] == (convex ? INFINITY : 2.4717f));
    r = RUN_KEPT(*s, centre, T(8.48134f, 0x334), BI(8.48142f, 3199 | TV_ID_CULLED), T(8.48254f, 0x334),
                 T(8.48364f, 0x334), U(8.51f, 0x334), F(14.9166f, 14774));
    CHECK_NONE(r);
    r = RUN_KEPT(*s, centre, B(15.5f));
    harness_convex_front = 0;
    return r;
}

/* Closed: 0x334 is no silhouette of the front's patch, the interval [2.4717, 3199] is not valid and the prior front
 * seals the pixel. Open (the guard refuses): 0x334 validates it, 14774 is carried and output as a terminator.
 * Without the rule both give the second answer. */
static void test_region_behind_a_closed_prior_front(void)
{
    pvs_pixel_state s = {0};
    layer_result r = traced_pixel(true, &s);
    CHECK_NONE(r);
    TV_CHECK(s.stencil == TV_STENCIL_SEALED && s.term_depth == 2.4717f);
    pvs_pixel_state open = {0};
    r = traced_pixel(false, &open);
    CHECK_OUT(r, 14774);
}

/* What the rule leaves: a single draw behind the front (a border's, in its own plane), a region within the margin,
 * a front of this layer (not prior) and a prior back's interval each still validate; a skipped region's umbra still
 * bounds the hidden range of an interval another region validates. */
static void test_closed_prior_front_keeps(void)
{
    const uint32_t cb = 900 | TV_ID_CULLED;
    float c1[TV_PVS_CENTRE_STRIDE] = NONE_YET, c2[TV_PVS_CENTRE_STRIDE] = NONE_YET, c3[TV_PVS_CENTRE_STRIDE] = NONE_YET;
    harness_convex_front = 77u;
    pvs_pixel_state a = {0}, b = {0}, c = {0}, d = {0};
    RUN_KEPT(a, c1, F(2.0f, 77));
    RUN_KEPT(a, c1, T(5.0f, 5), BI(5.2f, cb), F(10.0f, 42), B(10.5f)); /* one draw */
    TV_CHECK(a.stencil == TV_STENCIL_SEALED && a.term_depth == 10.0f);
    RUN_KEPT(b, c2, F(2.0f, 77));
    RUN_KEPT(b, c2, T(2.15f, 5), T(2.2f, 5), BI(2.3f, cb), F(10.0f, 42), B(10.5f)); /* within 1.1 f */
    TV_CHECK(b.stencil == TV_STENCIL_SEALED && b.term_depth == 10.0f);
    layer_result r = RUN_KEPT(c, c3, F(2.0f, 77), T(5.0f, 5), T(5.1f, 5), BI(5.2f, cb), F(10.0f, 42), B(10.5f));
    CHECK_OUT(r, 77, 42); /* this layer's front: not a prior one */
    float c4[TV_PVS_CENTRE_STRIDE] = NONE_YET;
    RUN_KEPT(d, c4, F(2.0f, 77));
    r = RUN_KEPT(d, c4, T(2.0f, 4), U(20.0f, 4), T(5.0f, 6), T(5.1f, 6), U(6.0f, 6), BI(5.2f, cb), F(10.0f, 42),
                 B(10.5f));
    CHECK_OUT(r, 42); /* valid by 4, hidden to 6.0 (6's umbra), not 20: 42 is seen and terminates */
    harness_convex_front = 0;
}

/* Corners: a unit quad in z = 0 facing +z (0, 1, 2, 3), a wall on its edge x = 1 rising to z = 1 facing -x (5, 4:
 * a concave corner), a side falling to z = -1 facing +x (6: a box's convex corner). */
static const float corner_pos[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 1, 1, 1, 1, 0, 1, 1, 0, -1};
#define B_ SCN_EDGE_BORDER

static uint32_t patches(const uint32_t* idx, const uint32_t* adj, uint32_t n, const bool* masked)
{
    uint32_t bits[1] = {0xFFFFFFFFu};
    TV_CHECK(pvs_convex_patches(bits, adj, idx, n, corner_pos, masked) != (size_t)-1);
    return bits[0];
}

/* The guard: a flat quad and a box corner are closed; a receding concave surface (a wall standing on the quad, welded
 * to it) opens the quad too, so a prior front on it keeps every region; so do a rest edge, a masked member and a
 * flipped flat neighbour. */
static void test_convex_patches(void)
{
    const uint32_t quad[] = {0, 1, 2, 0, 2, 3}, quad_adj[] = {B_, B_, 1, 0, B_, B_};
    TV_CHECK(patches(quad, quad_adj, 2, NULL) == 3u);
    const uint32_t box[] = {0, 1, 2, 0, 2, 3, 2, 1, 6}, box_adj[] = {B_, 2, 1, 0, B_, B_, 0, B_, B_};
    TV_CHECK(patches(box, box_adj, 3, NULL) == 7u);
    const uint32_t room[] = {0, 1, 2, 0, 2, 3, 2, 1, 5, 2, 1, 6}, room_adj[] = {B_, 2, 1, 0, B_, B_, 0, B_, B_, B_, B_, B_};
    TV_CHECK(patches(room, room_adj, 4, NULL) == 8u); /* the side, on its own (border edges), stays closed */
    const uint32_t rest_adj[] = {TV_ADJ_REST | 1u, B_, 1, 0, B_, B_};
    TV_CHECK(patches(quad, rest_adj, 2, NULL) == 0u);
    const bool masked[] = {false, true};
    TV_CHECK(patches(quad, quad_adj, 2, masked) == 0u);
    const uint32_t flipped[] = {0, 1, 2, 0, 3, 2};
    TV_CHECK(patches(flipped, quad_adj, 2, NULL) == 0u);
}

int main(void)
{
    TV_TEST_RUN(test_region_behind_a_closed_prior_front);
    TV_TEST_RUN(test_closed_prior_front_keeps);
    TV_TEST_RUN(test_convex_patches);
    return tv_test_finish();
}
