/* The far-depth bound (pvs/depth_bound.h): its levels, known answers, and
 * the contract checked on random triangles (sub-pixel ones, ones crossing
 * the near plane or behind v*): over any rectangle holding a point's image,
 * the bound is at least the point's depth. */
#include <math.h>

#include "depth_bound.h"
#include "proxies.h"
#include "pvs_shared.h"
#include "pvs_test_scenes.h"
#include "test.h"

static pvs_view test_view(void)
{
    return (pvs_view){.apex = {0, 0, 0}, .forward = {0, 0, -1}, .up = {0, 1, 0}, .fov_y_deg = 90.0f,
                      .aspect = 16.0f / 9.0f, .near_dist = 0.1f, .far_dist = 60.0f};
}

/* World point at normalised image (x, y) and depth (forward -z). */
static void at(float x, float y, float depth, float p[3])
{
    p[0] = x * depth;
    p[1] = y * depth;
    p[2] = -depth;
}

static void test_levels(void)
{
    pvs_depth_bound b;
    TV_CHECK(pvs_depth_bound_init(&b, 320, 180));
    /* 40x23, 20x12, 10x6, 5x3, 3x2, 2x1, 1x1 */
    TV_CHECK(b.levels == 7 && b.level_width[0] == 40 && b.level_height[0] == 23);
    TV_CHECK(b.level_width[4] == 3 && b.level_height[4] == 2 && b.level_width[6] == 1 && b.level_height[6] == 1);
    TV_CHECK(b.cell_count == 920 + 240 + 60 + 15 + 6 + 2 + 1);
    TV_CHECK(pvs_depth_bound_cell_count(320, 180) == b.cell_count);
    TV_CHECK(b.level_offset[2] == 1160);
    pvs_depth_bound_free(&b);
    TV_CHECK(b.cells == NULL);
}

static void test_known_answers(void)
{
    pvs_depth_bound b;
    TV_CHECK(pvs_depth_bound_init(&b, 320, 180));
    pvs_view v = test_view();
    pvs_depth_bound_begin(&b, &v);
    pvs_depth_bound_finish(&b);
    TV_CHECK(pvs_depth_bound_query(&b, 0, 0, 320, 180) == 0.0f); /* nothing added */

    /* A triangle at depths 3-4 in the right half of the image. */
    pvs_depth_bound_begin(&b, &v);
    float tri[3][3];
    at(0.5f, -0.2f, 3.0f, tri[0]);
    at(0.9f, -0.2f, 4.0f, tri[1]);
    at(0.7f, 0.3f, 3.5f, tri[2]);
    pvs_depth_bound_add(&b, (const float(*)[3])tri, 3);
    pvs_depth_bound_finish(&b);
    float px[2];
    pvs_depth_bound_pixel(&b, (const float[2]){0.7f, 0.0f}, px);
    TV_CHECK(px[0] > 160.0f && px[1] > 90.0f - 1.0f && px[1] < 90.0f + 1.0f);
    /* The plane's depth over the cell there (about 3.5 m at its centre),
     * not the farthest corner's; over the whole image the farthest corner. */
    float here = pvs_depth_bound_query(&b, px[0], px[1], px[0], px[1]);
    TV_CHECK(here > 3.45f && here < 3.6f);
    TV_CHECK_NEAR(pvs_depth_bound_query(&b, 0, 0, 320, 180), 4.0, 4.0 * 2e-4);
    TV_CHECK(pvs_depth_bound_query(&b, 0, 0, 100, 180) == 0.0f); /* the left part holds nothing */

    /* Beyond the far plane: clamped to it. A box across the near plane
     * counts with the part in front of it. */
    pvs_depth_bound_begin(&b, &v);
    float far_tri[3][3];
    at(-0.5f, 0.0f, 50.0f, far_tri[0]);
    at(-0.4f, 0.0f, 90.0f, far_tri[1]);
    at(-0.45f, 0.1f, 70.0f, far_tri[2]);
    pvs_depth_bound_add(&b, (const float(*)[3])far_tri, 3);
    float box[8 * PVS_PROXY_FLOATS] = {0};
    const float lo[3] = {0.3f, -0.1f, -2.0f}, hi[3] = {0.5f, 0.1f, 1.0f}; /* from depth -1 to 2 */
    for (int a = 0; a < 3; a++) {
        box[a] = lo[a];
        box[4 + a] = hi[a];
    }
    const uint32_t faces[2] = {100 + 12 * 0 + 5, 100 + 12 * 0 + 11}; /* two faces of proxy 0 above 100 ids */
    pvs_depth_bound_add_ids(&b, faces, 2, far_tri[0], 100, box);
    pvs_depth_bound_finish(&b);
    pvs_depth_bound_pixel(&b, (const float[2]){-0.45f, 0.03f}, px);
    TV_CHECK(pvs_depth_bound_query(&b, px[0], px[1], px[0], px[1]) == v.far_dist);
    /* the box's part in front of the near plane spans the image from x = 0.15 (its far face) outwards */
    pvs_depth_bound_pixel(&b, (const float[2]){0.2f, 0.0f}, px);
    TV_CHECK_NEAR(pvs_depth_bound_query(&b, px[0], px[1], px[0], px[1]), 2.0, 2.0 * 2e-4);
    pvs_depth_bound_pixel(&b, (const float[2]){1.7f, 0.0f}, px); /* near the right border: the near-plane cut */
    TV_CHECK_NEAR(pvs_depth_bound_query(&b, px[0], px[1], px[0], px[1]), 2.0, 2.0 * 2e-4);
    pvs_depth_bound_free(&b);
}

/* Random triangles of every size (down to a thousandth of a pixel), some
 * crossing the near plane or behind v*, each alone in the bound (so that no
 * other covers for it): each point sampled on it with a depth in [near,
 * far] must be bounded over its own pixel and over random rectangles
 * holding it. */
static void test_bound_holds_every_point(void)
{
    pvs_depth_bound b;
    TV_CHECK(pvs_depth_bound_init(&b, 320, 180));
    pvs_view v = test_view();
    uint32_t rng = 99;
    int checked = 0, failed = 0;
    for (int t = 0; t < 3000; t++) {
        float tri[3][3];
        float cx = 3.6f * pvs_test_rand(&rng) - 1.8f, cy = 2.2f * pvs_test_rand(&rng) - 1.1f;
        float depth = 0.05f + 70.0f * pvs_test_rand(&rng) * pvs_test_rand(&rng);
        int kind = t % 4; /* 0: sub-pixel, 1: a few pixels, 2: large, 3: across the near plane / behind v* */
        float size = kind == 0 ? 1e-5f : kind == 1 ? 0.02f : 0.6f;
        for (int c = 0; c < 3; c++) {
            if (kind == 3) { /* metres around a point 0.5 m ahead: most cross the near plane */
                at(cx, cy, 0.5f, tri[c]);
                for (int a = 0; a < 3; a++)
                    tri[c][a] += 2.0f * pvs_test_rand(&rng) - 1.0f;
                continue;
            }
            float d = depth * (1.0f + 0.2f * size * pvs_test_rand(&rng));
            at(cx + size * (pvs_test_rand(&rng) - 0.5f), cy + size * (pvs_test_rand(&rng) - 0.5f), d, tri[c]);
        }
        pvs_depth_bound_begin(&b, &v);
        pvs_depth_bound_add(&b, (const float(*)[3])tri, 3);
        pvs_depth_bound_finish(&b);
        for (int s = 0; s < 12; s++) {
            float u = pvs_test_rand(&rng), w = pvs_test_rand(&rng);
            if (s < 3) { /* the corners too */
                u = s == 1;
                w = s == 2;
            } else if (u + w > 1.0f) {
                u = 1.0f - u;
                w = 1.0f - w;
            }
            float p[3], depth_p, img[2], px[2];
            for (int a = 0; a < 3; a++)
                p[a] = tri[0][a] + u * (tri[1][a] - tri[0][a]) + w * (tri[2][a] - tri[0][a]);
            depth_p = -p[2];
            if (depth_p < v.near_dist || depth_p > v.far_dist)
                continue;
            img[0] = p[0] / depth_p;
            img[1] = p[1] / depth_p;
            pvs_depth_bound_pixel(&b, img, px);
            float grow[4];
            for (int g = 0; g < 4; g++)
                grow[g] = 40.0f * pvs_test_rand(&rng) * pvs_test_rand(&rng);
            float own = pvs_depth_bound_query(&b, px[0], px[1], px[0], px[1]);
            float around = pvs_depth_bound_query(&b, px[0] - grow[0], px[1] - grow[1], px[0] + grow[2], px[1] + grow[3]);
            failed += own < depth_p || around < own;
            checked++;
        }
    }
    printf("  %d points on 3000 triangles, %d unbounded\n", checked, failed);
    TV_CHECK(failed == 0 && checked > 20000);
    pvs_depth_bound_free(&b);
}

int main(void)
{
    TV_TEST_RUN(test_levels);
    TV_TEST_RUN(test_known_answers);
    TV_TEST_RUN(test_bound_holds_every_point);
    return tv_test_finish();
}
