/* Regions behind a prior front (docs/pvs-edge-cases.md, "Regions behind a prior front"): the P3 reference's
 * front-patch rule (resolve_harness.h drives one pixel) and pvs_front_patches on constructed meshes. */
#include "patches.h"
#include "resolve_harness.h"
#include "test.h"
#include "weld.h"

#include <math.h>

#define NONE_YET {INFINITY, INFINITY, INFINITY, INFINITY, INFINITY, INFINITY, INFINITY, INFINITY}

/* Labels as a view's pvs_front_patches might give them: 77 and 78 (a coplanar twin) on patch 77 or, with g_tie,
 * 78 on patch 78; the far front 14774 and 42 on patch 7000. Region 0x334 (the second solid's three-draw silhouette)
 * is named from g_region_label's patch, regions 5 and 6 from 500, region 4 from patch 77. */
static bool g_tie;
static uint32_t g_regions[0x400];

static uint32_t tri_patch(uint32_t id)
{
    return id == 77 || (id == 78 && !g_tie) ? 77 : id == 78 ? 78 : 7000;
}

static void set_patches(uint32_t region_label)
{
    for (uint32_t r = 0; r < 0x400; r++)
        g_regions[r] = TV_PVS_PATCH_NONE;
    g_regions[0x334] = region_label;
    g_regions[4] = 77;
    g_regions[5] = g_regions[6] = 500;
    harness_tri_patch = tri_patch;
    harness_region_patch = g_regions;
    harness_region_patches = 0x400;
}

static void clear_patches(void)
{
    harness_tri_patch = NULL;
    harness_region_patch = NULL;
    harness_region_patches = 0;
    g_tie = false;
}

/* Three layers of the traced pixel of oa:oa_dm5 cell 1 (docs/journal/2026-12-03-dm5rest.md, section 2): a prior
 * front at 2.4717 (77, with `twin` its coplanar twin 78) with no back of its own, then, behind it, another solid's
 * culled back (3199) and its three-draw silhouette (region 0x334, 2.4x farther), then a far front (14774) a later
 * layer closes. Returns what the last layer outputs. */
static layer_result traced_pixel(uint32_t region_label, bool twin, pvs_pixel_state* s)
{
    float centre[TV_PVS_CENTRE_STRIDE] = NONE_YET;
    set_patches(region_label);
    layer_result r = twin ? RUN_KEPT(*s, centre, F(2.4717f, 77), F(2.4717f, 78)) : RUN_KEPT(*s, centre, F(2.4717f, 77));
    TV_CHECK(r.count == 0 && s->stencil == TV_STENCIL_UNTRIMMED);
    r = RUN_KEPT(*s, centre, T(8.48134f, 0x334), BI(8.48142f, 3199 | TV_ID_CULLED), T(8.48254f, 0x334),
                 T(8.48364f, 0x334), U(8.51f, 0x334), F(14.9166f, 14774));
    CHECK_NONE(r);
    r = RUN_KEPT(*s, centre, B(15.5f));
    clear_patches();
    return r;
}

/* Region 0x334 named from another front patch (the second solid's, 4175's): not the region an eye that sees past
 * 77 needs, the interval [2.4717, 3199] is not valid and the prior front seals the pixel; also with a coplanar twin
 * of the same patch. Named from 77's own patch, from no patch (TV_PVS_PATCH_NONE), or with the twin on another patch
 * (two labels at the nearest depth: unknown), it validates the interval and 14774 is output as a terminator.
 * Without the rule every case gives the second answer. */
static void test_region_of_another_front_patch(void)
{
    pvs_pixel_state s = {0};
    layer_result r = traced_pixel(4175, false, &s);
    CHECK_NONE(r);
    TV_CHECK(s.stencil == TV_STENCIL_SEALED && s.term_depth == 2.4717f);
    pvs_pixel_state t = {0};
    CHECK_NONE(traced_pixel(4175, true, &t));
    TV_CHECK(t.stencil == TV_STENCIL_SEALED);
    pvs_pixel_state own = {0}, none = {0}, tie = {0};
    r = traced_pixel(77, false, &own);
    CHECK_OUT(r, 14774);
    r = traced_pixel(TV_PVS_PATCH_NONE, false, &none);
    CHECK_OUT(r, 14774);
    g_tie = true;
    r = traced_pixel(4175, true, &tie);
    CHECK_OUT(r, 14774);
}

/* What the rule leaves: a single draw of another patch (a rest edge named from its back-facing wall), a region of
 * the prior front's own patch and a front of this layer (not prior) each still validate; a skipped region's umbra
 * still bounds the hidden range of an interval another region validates. */
static void test_prior_front_keeps(void)
{
    const uint32_t cb = 900 | TV_ID_CULLED;
    float c1[TV_PVS_CENTRE_STRIDE] = NONE_YET, c2[TV_PVS_CENTRE_STRIDE] = NONE_YET, c3[TV_PVS_CENTRE_STRIDE] = NONE_YET;
    set_patches(4175);
    pvs_pixel_state a = {0}, b = {0}, c = {0}, d = {0};
    RUN_KEPT(a, c1, F(2.0f, 77));
    RUN_KEPT(a, c1, T(5.0f, 5), BI(5.2f, cb), F(10.0f, 42), B(10.5f)); /* one draw */
    TV_CHECK(a.stencil == TV_STENCIL_SEALED && a.term_depth == 10.0f);
    RUN_KEPT(b, c2, F(2.0f, 77));
    RUN_KEPT(b, c2, T(5.0f, 4), T(5.1f, 4), BI(5.2f, cb), F(10.0f, 42), B(10.5f)); /* the prior front's patch */
    TV_CHECK(b.stencil == TV_STENCIL_SEALED && b.term_depth == 10.0f);
    layer_result r = RUN_KEPT(c, c3, F(2.0f, 77), T(5.0f, 5), T(5.1f, 5), BI(5.2f, cb), F(10.0f, 42), B(10.5f));
    CHECK_OUT(r, 77, 42); /* this layer's front: not a prior one */
    float c4[TV_PVS_CENTRE_STRIDE] = NONE_YET;
    set_patches(4175);
    RUN_KEPT(d, c4, F(2.0f, 77));
    r = RUN_KEPT(d, c4, T(2.0f, 4), U(20.0f, 4), T(5.0f, 6), T(5.1f, 6), U(6.0f, 6), BI(5.2f, cb), F(10.0f, 42),
                 B(10.5f));
    CHECK_OUT(r, 42); /* valid by 4, hidden to 6.0 (6's umbra), not 20: 42 is seen and terminates */
    clear_patches();
}

/* Corners: a unit quad in z = 0 facing +z (0, 1, 2, 3), a wall on its edge x = 1 rising to z = 1 facing -x (5, 4:
 * a concave corner), a side falling to z = -1 facing +x (6: a box's convex corner). */
static const float corner_pos[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 1, 1, 1, 1, 0, 1, 1, 0, -1};
#define B_ SCN_EDGE_BORDER

static void labels(const uint32_t* idx, const uint32_t* adj, uint32_t n, const bool* masked, const float apex[3],
                   uint32_t* out)
{
    float corners[9 * 4];
    for (uint32_t t = 0; t < 9 * n; t++)
        corners[t] = corner_pos[3 * idx[t / 3] + t % 3];
    TV_CHECK(pvs_front_patches(out, adj, corners, masked, n, apex));
}

/* Seen from above and left of the wall, the quad and the wall (joined across the concave corner, which is no
 * silhouette) are one patch, also across a rest edge; the side faces away (no label), and seen from below the side
 * alone is labelled. A masked member has no label, nor has the patch it touches. */
static void test_front_patches(void)
{
    const float above[3] = {0.5f, 0.5f, 0.5f}, below[3] = {2.0f, 0.5f, -0.5f};
    const uint32_t room[] = {0, 1, 2, 0, 2, 3, 2, 1, 5, 2, 1, 6};
    const uint32_t room_adj[] = {2, 1, B_, B_, B_, 0, 0, B_, B_, B_, B_, B_};
    uint32_t l[4];
    labels(room, room_adj, 3, NULL, above, l);
    TV_CHECK(l[0] != TV_PVS_PATCH_NONE && l[0] == l[1] && l[1] == l[2]);
    const uint32_t rest_adj[] = {TV_ADJ_REST | 2u, 1, B_, B_, B_, 0, TV_ADJ_REST | 0u, B_, B_, B_, B_, B_};
    labels(room, rest_adj, 3, NULL, above, l);
    TV_CHECK(l[0] == l[1] && l[1] == l[2]);
    const uint32_t box_adj[] = {3, 1, B_, B_, B_, 0, B_, B_, B_, 0, B_, B_};
    labels(room, box_adj, 4, NULL, above, l);
    TV_CHECK(l[3] == TV_PVS_PATCH_NONE && l[0] == l[1] && l[2] == 2u);
    labels(room, box_adj, 4, NULL, below, l);
    TV_CHECK(l[3] == 3u && l[0] == TV_PVS_PATCH_NONE);
    const bool masked[] = {false, false, true};
    labels(room, room_adj, 3, masked, above, l);
    TV_CHECK(l[0] == TV_PVS_PATCH_NONE && l[1] == TV_PVS_PATCH_NONE && l[2] == TV_PVS_PATCH_NONE);
}

int main(void)
{
    TV_TEST_RUN(test_region_of_another_front_patch);
    TV_TEST_RUN(test_prior_front_keeps);
    TV_TEST_RUN(test_front_patches);
    return tv_test_finish();
}
