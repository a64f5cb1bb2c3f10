/* walkable.h and walk_path.h on small constructed scenes whose free space is
 * known: points stand 1.6 m above the floor with the head clear, never inside
 * a closed box or under a low ceiling, viewcells spread out and repeat, and a
 * two-storey building joined by a ramp is walked on both storeys. */
#include "clearance.h"
#include "procgen.h"
#include "walk_path.h"
#include "test.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

/* A 20 m x 20 m ground (y = 0) plus the given closed boxes. */
static bool build(scn_scene* out, const float (*boxes)[6], int nbox)
{
    scn_builder b;
    scn_builder_init(&b, out, false);
    uint32_t m = scn_gen_material(&b, "grey", -1, 0.7f, 0.7f, 0.7f, false);
    scn_gen_box(&b, (const float[3]){-10, -0.2f, -10}, (const float[3]){10, 0, 10}, SCN_FACE_POS_Y, 2.0f, m);
    for (int i = 0; i < nbox; i++)
        scn_gen_box(&b, boxes[i], boxes[i] + 3, SCN_FACE_ALL, 1.0f, m);
    char err[256];
    bool ok = scn_builder_finish(&b, "test", err, sizeof err);
    if (!ok)
        fprintf(stderr, "%s\n", err);
    return ok;
}

static tv_walkable* walkable(const scn_scene* s)
{
    char err[256];
    tv_walkable* w = tv_walkable_create(s, NULL, err, sizeof err);
    if (!w)
        fprintf(stderr, "%s\n", err);
    return w;
}

/* Points whose x-z lies inside [lo, hi] (shrunk by the clearance) with the eye between y0 and y1. */
static int points_in(const tv_walkable* w, const float lo[3], const float hi[3], float y0, float y1)
{
    int n = 0;
    for (uint32_t i = 0; i < tv_walkable_count(w); i++) {
        float e[3];
        tv_walkable_point(w, i, e, NULL);
        n += e[0] > lo[0] && e[0] < hi[0] && e[2] > lo[2] && e[2] < hi[2] && e[1] > y0 && e[1] < y1;
    }
    return n;
}

static void test_points_above_floor(void)
{
    scn_scene s;
    TV_CHECK(build(&s, NULL, 0));
    tv_walkable* w = walkable(&s);
    TV_CHECK(w && tv_walkable_count(w) > 1000); /* 400 m^2 at 0.5 m: 1600 columns less the clearance margin */
    int bad = 0;
    for (uint32_t i = 0; w && i < tv_walkable_count(w); i++) {
        float e[3];
        tv_walkable_point(w, i, e, NULL);
        bad += fabsf(e[1] - 1.6f) > 1e-4f || fabsf(e[0]) > 10.0f || fabsf(e[2]) > 10.0f ||
               tv_walkable_clearance(w, e) < 0.3f;
    }
    TV_CHECK(bad == 0);
    tv_walkable_destroy(w);
    scn_scene_free(&s);
}

static void test_none_inside_closed_box(void)
{
    /* one box floating (its inside bottom is an upward floor seen from within), one standing on the ground
     * and big enough that the region rule alone would keep its inside */
    const float boxes[2][6] = {{-3, 2, -9, 3, 6, -3}, {-9, 0, 1, 9, 4, 9}};
    scn_scene s;
    TV_CHECK(build(&s, boxes, 2));
    tv_walkable* w = walkable(&s);
    TV_CHECK(w && tv_walkable_count(w) > 500);
    for (int i = 0; w && i < 2; i++)
        TV_CHECK(points_in(w, boxes[i], boxes[i] + 3, boxes[i][1] - 0.01f, boxes[i][4] + 0.01f) == 0);
    /* under the floating box there is ground with 2 m of headroom: people stand there */
    TV_CHECK(w && points_in(w, boxes[0], boxes[0] + 3, 1.5f, 1.7f) > 20);
    tv_walkable_destroy(w);
    scn_scene_free(&s);
}

static void test_none_under_low_ceiling(void)
{
    /* a slab 1.7 m up: no room for a 1.6 m eye plus 0.3 m; its top is a roof, not walkable */
    const float slab[1][6] = {{-5, 1.7f, -5, 5, 1.8f, 5}};
    scn_scene s;
    TV_CHECK(build(&s, slab, 1));
    tv_walkable* w = walkable(&s);
    TV_CHECK(w && tv_walkable_count(w) > 500);
    TV_CHECK(w && points_in(w, slab[0], slab[0] + 3, -1.0f, 100.0f) == 0);
    tv_walkable_destroy(w);
    scn_scene_free(&s);
}

static void test_viewcells_spread_and_repeat(void)
{
    scn_scene s;
    TV_CHECK(build(&s, NULL, 0));
    tv_walkable* w = walkable(&s);
    float pos[15], dir[15], pos2[15], dir2[15];
    int n = w ? tv_walkable_viewcells(w, UINT32_MAX, 5, pos, dir, NULL) : 0;
    TV_CHECK(n == 5);
    /* the first is the point nearest the centroid, then the four corners */
    TV_CHECK(n == 5 && fabsf(pos[0]) < 0.5f && fabsf(pos[2]) < 0.5f);
    float closest = INFINITY;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            closest = fminf(closest, hypotf(pos[3 * i] - pos[3 * j], pos[3 * i + 2] - pos[3 * j + 2]));
    TV_CHECK(closest > 12.0f);
    for (int i = 0; i < n; i++)
        TV_CHECK_NEAR(dir[3 * i] * dir[3 * i] + dir[3 * i + 2] * dir[3 * i + 2], 1.0, 1e-5);
    TV_CHECK(w && tv_walkable_viewcells(w, UINT32_MAX, 5, pos2, dir2, NULL) == 5);
    TV_CHECK(memcmp(pos, pos2, sizeof pos) == 0 && memcmp(dir, dir2, sizeof dir) == 0);
    tv_walkable_destroy(w);
    scn_scene_free(&s);
}

/* Ground 20 x 12 m, an upper floor (y = 3) over z < 0, a roof at 6 m, outer
 * walls, and a 12 m ramp along x at 0 < z < 2 from the ground to the upper floor. */
static bool two_storeys(scn_scene* out)
{
    scn_builder b;
    scn_builder_init(&b, out, false);
    uint32_t m = scn_gen_material(&b, "grey", -1, 0.7f, 0.7f, 0.7f, false);
    const float boxes[][6] = {{-10, -0.2f, -6, 10, 0, 6},    {-10, 2.8f, -6, 10, 3, 0},     {-10, 6, -6, 10, 6.2f, 6},
                              {-10.2f, 0, -6, -10, 6, 6},    {10, 0, -6, 10.2f, 6, 6},      {-10, 0, -6.2f, 10, 6, -6},
                              {-10, 0, 6, 10, 6, 6.2f}};
    for (size_t i = 0; i < sizeof boxes / sizeof boxes[0]; i++)
        scn_gen_box(&b, boxes[i], boxes[i] + 3, SCN_FACE_ALL, 1.0f, m);
    scn_gen_quad(&b, (const float[3]){-8, 0, 2}, (const float[3]){12, 3, 0}, (const float[3]){0, 0, -2}, 12, 2, m);
    char err[256];
    return scn_builder_finish(&b, "two storeys", err, sizeof err);
}

static void test_two_storeys(void)
{
    scn_scene s;
    TV_CHECK(two_storeys(&s));
    tv_walkable* w = walkable(&s);
    TV_CHECK(w != NULL);
    if (!w)
        return;
    /* both storeys are walkable and the ramp joins them into one region */
    int ground = 0, upper = 0;
    uint32_t largest = tv_walkable_largest_region(w), lower_pt = 0, upper_pt = 0;
    for (uint32_t i = 0; i < tv_walkable_count(w); i++) {
        float e[3];
        uint32_t r;
        tv_walkable_point(w, i, e, &r);
        TV_CHECK(r == largest);
        if (fabsf(e[1] - 1.6f) < 1e-3f)
            ground++, lower_pt = i;
        if (fabsf(e[1] - 4.6f) < 1e-3f)
            upper++, upper_pt = i;
    }
    TV_CHECK(ground > 300 && upper > 200);
    uint32_t route[4096];
    TV_CHECK(tv_walkable_route(w, lower_pt, upper_pt, route, 4096) > 10);
    /* a run visits both storeys and keeps the head out of the geometry */
    pred_path p = {0};
    char err[256];
    TV_CHECK(tv_walkable_path(w, "two storeys", TV_AUTO_RUN, 1, &p, err, sizeof err));
    tv_clearance* cl = tv_clearance_create(&s, &(tv_clearance_desc){.radius_m = 1.0f}, err, sizeof err);
    float lowest = INFINITY, highest = -INFINITY, closest = INFINITY;
    for (size_t i = 0; cl && i < p.count; i++) {
        float e[3] = {(float)p.poses[i].p[0], (float)p.poses[i].p[1], (float)p.poses[i].p[2]};
        lowest = fminf(lowest, e[1]);
        highest = fmaxf(highest, e[1]);
        closest = fminf(closest, tv_clearance_query(cl, e, NULL));
    }
    TV_CHECK(lowest < 1.7f && lowest > 1.5f && highest > 4.5f && highest < 4.7f);
    TV_CHECK(closest >= 0.2f);
    TV_CHECK(pred_path_duration(&p) > 20.0);
    /* a seated look-around stays within centimetres of one spot */
    pred_path q = {0};
    TV_CHECK(tv_walkable_path(w, "two storeys", TV_AUTO_LOOKAROUND, 1, &q, err, sizeof err));
    for (size_t i = 1; i < q.count; i++)
        TV_CHECK(fabs(q.poses[i].p[0] - q.poses[0].p[0]) < 0.05 && fabs(q.poses[i].p[2] - q.poses[0].p[2]) < 0.05);
    pred_path_free(&p);
    pred_path_free(&q);
    tv_clearance_destroy(cl);
    tv_walkable_destroy(w);
    scn_scene_free(&s);
}

/* builtin:house: the walkable rule finds both storeys inside the house and
 * joins them over the stairs into the yard's region. */
static void test_house_storeys(void)
{
    scn_scene s;
    char err[512];
    TV_CHECK(scn_load("builtin:house", &s, err, sizeof err));
    tv_walkable* w = walkable(&s);
    TV_CHECK(w != NULL);
    if (!w)
        return;
    const float lo[3] = { -5.7f, 0, -4.2f }, hi[3] = { 5.7f, 0, 4.2f };
    int ground = points_in(w, lo, hi, 1.5f, 1.7f), upper = points_in(w, lo, hi, 4.5f, 4.7f);
    printf("     builtin:house: %u walkable points, %d on the ground floor, %d upstairs\n", tv_walkable_count(w),
           ground, upper);
    TV_CHECK(ground > 50 && upper > 50);
    uint32_t largest = tv_walkable_largest_region(w), found = 0;
    for (uint32_t i = 0; i < tv_walkable_count(w); i++) {
        float e[3];
        uint32_t r;
        tv_walkable_point(w, i, e, &r);
        found |= (r == largest) << (e[1] > 4.5f && e[1] < 4.7f);
    }
    TV_CHECK(found == 3); /* the largest region reaches upstairs */
    tv_walkable_destroy(w);
    scn_scene_free(&s);
}

int main(void)
{
    TV_TEST_RUN(test_points_above_floor);
    TV_TEST_RUN(test_none_inside_closed_box);
    TV_TEST_RUN(test_none_under_low_ceiling);
    TV_TEST_RUN(test_viewcells_spread_and_repeat);
    TV_TEST_RUN(test_two_storeys);
    TV_TEST_RUN(test_house_storeys);
    return tv_test_finish();
}
