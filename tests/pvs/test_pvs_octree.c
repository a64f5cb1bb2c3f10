/* Octree (P0 part 1): triangle/box overlap, coverage, cap, 2-level balance,
 * neighbour lists (complete and symmetric), errors, build time. */
#include <stdlib.h>
#include <string.h>

#include "octree.h"
#include "pvs_test_scenes.h"
#include "test.h"
#include "tri_box.h"

static void test_tri_box_known_cases(void)
{
    float mn[3] = {0, 0, 0}, mx[3] = {1, 1, 1};
    float a[3] = {3, 3, 3}, b[3] = {4, 3, 3}, c[3] = {3, 4, 3};
    TV_CHECK(!pvs_tri_box_overlap(a, b, c, mn, mx)); /* far away */
    /* A big triangle slicing through the box with every vertex outside. */
    float s0[3] = {-5, 0.5f, -5}, s1[3] = {5, 0.5f, -5}, s2[3] = {0, 0.5f, 10};
    TV_CHECK(pvs_tri_box_overlap(s0, s1, s2, mn, mx));
    /* Bounding boxes overlap, the triangle passes the corner (x+y+z = 3.2). */
    float d0[3] = {3.2f, 0, 0}, d1[3] = {0, 3.2f, 0}, d2[3] = {0, 0, 3.2f};
    TV_CHECK(!pvs_tri_box_overlap(d0, d1, d2, mn, mx));
    float e0[3] = {2.9f, 0, 0}, e1[3] = {0, 2.9f, 0}, e2[3] = {0, 0, 2.9f};
    TV_CHECK(pvs_tri_box_overlap(e0, e1, e2, mn, mx));
    /* Touching the face x = 1 counts. */
    float t0[3] = {1, 0.2f, 0.2f}, t1[3] = {2, 0.2f, 0.8f}, t2[3] = {2, 0.8f, 0.2f};
    TV_CHECK(pvs_tri_box_overlap(t0, t1, t2, mn, mx));
    /* A degenerate triangle (segment) crossing the box diagonally, and one missing it. */
    float g0[3] = {-1, -1, -1}, g1[3] = {2, 2, 2};
    TV_CHECK(pvs_tri_box_overlap(g0, g1, g1, mn, mx));
    float h0[3] = {-1, 3.5f, 0.5f}, h1[3] = {3.5f, -1, 0.5f}; /* x + y = 2.5 */
    TV_CHECK(!pvs_tri_box_overlap(h0, h1, h1, mn, mx));
}

static bool leaf_has(const pvs_octree* t, uint32_t leaf, uint32_t tri)
{
    for (uint32_t r = t->tri_offsets[leaf]; r < t->tri_offsets[leaf + 1]; r++) {
        if (t->tri_ids[r] == tri)
            return true;
    }
    return false;
}

static bool nbr_has(const pvs_octree* t, uint32_t leaf, int face, uint32_t other)
{
    for (uint32_t k = t->nbr_offsets[6 * leaf + face]; k < t->nbr_offsets[6 * leaf + face + 1]; k++) {
        if (t->nbr_ids[k] == other)
            return true;
    }
    return false;
}

/* Do leaves i and j touch across face f of i with a positive shared area? */
static bool touches(const pvs_octree* t, uint32_t i, uint32_t j, int f)
{
    const pvs_leaf *a = &t->leaves[i], *b = &t->leaves[j];
    uint32_t sa = 1u << (t->max_depth - a->level), sb = 1u << (t->max_depth - b->level);
    int axis = f / 2;
    if (f & 1 ? a->cell[axis] + sa != b->cell[axis] : b->cell[axis] + sb != a->cell[axis])
        return false;
    for (int k = 0; k < 3; k++) {
        if (k == axis)
            continue;
        if (a->cell[k] >= b->cell[k] + sb || b->cell[k] >= a->cell[k] + sa)
            return false;
    }
    return true;
}

static void check_octree(const scn_scene* s, const pvs_octree* t)
{
    /* Leaves tile the root cube exactly. */
    uint64_t volume = 0, root = 1ull << t->max_depth;
    for (uint32_t i = 0; i < t->leaf_count; i++) {
        uint64_t side = 1ull << (t->max_depth - t->leaves[i].level);
        volume += side * side * side;
    }
    TV_CHECK(volume == root * root * root);
    /* Cap respected unless at maximum depth; every referenced triangle overlaps its leaf. */
    uint32_t bad_cap = 0, bad_overlap = 0;
    for (uint32_t i = 0; i < t->leaf_count; i++) {
        uint32_t n = t->tri_offsets[i + 1] - t->tri_offsets[i];
        bad_cap += n > t->max_triangles_per_leaf && t->leaves[i].level < t->max_depth;
        for (uint32_t r = t->tri_offsets[i]; r < t->tri_offsets[i + 1]; r++) {
            const uint32_t* idx = s->indices + 3u * t->tri_ids[r];
            bad_overlap += !pvs_tri_box_overlap(s->positions + 3u * idx[0], s->positions + 3u * idx[1],
                                                s->positions + 3u * idx[2], t->leaves[i].min,
                                                t->leaves[i].max);
        }
    }
    TV_CHECK(bad_cap == 0);
    TV_CHECK(bad_overlap == 0);
    /* Independent coverage check: random points on each triangle lie in a
     * leaf that references the triangle. */
    uint32_t rng = 7, missing = 0;
    float unit = t->root_size / (float)(1u << t->max_depth);
    for (uint32_t tri = 0; tri < s->triangle_count; tri++) {
        const uint32_t* idx = s->indices + 3u * tri;
        for (int k = 0; k < 8; k++) {
            float u = pvs_test_rand(&rng), v = pvs_test_rand(&rng);
            if (u + v > 1.0f)
                u = 1.0f - u, v = 1.0f - v;
            uint32_t cell[3];
            for (int a = 0; a < 3; a++) {
                float p = s->positions[3u * idx[0] + a] * (1 - u - v) + s->positions[3u * idx[1] + a] * u +
                          s->positions[3u * idx[2] + a] * v;
                cell[a] = (uint32_t)((p - t->root_min[a]) / unit);
            }
            missing += !leaf_has(t, pvs_octree_locate(t, cell[0], cell[1], cell[2]), tri);
        }
    }
    TV_CHECK(missing == 0);
    /* Neighbours: complete, exact, symmetric, balanced. */
    uint32_t wrong = 0, asym = 0, unbalanced = 0, incomplete = 0;
    for (uint32_t i = 0; i < t->leaf_count; i++) {
        for (int f = 0; f < 6; f++) {
            for (uint32_t k = t->nbr_offsets[6 * i + f]; k < t->nbr_offsets[6 * i + f + 1]; k++) {
                uint32_t j = t->nbr_ids[k];
                wrong += !touches(t, i, j, f);
                asym += !nbr_has(t, j, f ^ 1, i);
                int dl = (int)t->leaves[i].level - (int)t->leaves[j].level;
                unbalanced += dl > 2 || dl < -2;
            }
        }
        for (uint32_t j = 0; j < t->leaf_count; j++) {
            for (int f = 0; f < 6; f++)
                incomplete += touches(t, i, j, f) && !nbr_has(t, i, f, j);
        }
    }
    TV_CHECK(wrong == 0);
    TV_CHECK(asym == 0);
    TV_CHECK(unbalanced == 0);
    TV_CHECK(incomplete == 0);
}

static void test_soup_octrees(void)
{
    for (uint32_t seed = 1; seed <= 4; seed++) {
        scn_scene s;
        pvs_test_soup(&s, 3000, 10.0f, 0.3f, seed);
        /* A dense cluster of tiny triangles just below the x = 5 split in a
         * sparse region: deep leaves next to a shallow one, to be balanced. */
        uint32_t rng = seed;
        for (uint32_t i = 0; i < 300 * 9; i++) {
            float centre = i % 3 == 0 ? 4.99f : 6.0f + 0.1f * (float)seed;
            s.positions[i] = centre + 0.02f * (pvs_test_rand(&rng) - 0.5f);
        }
        pvs_octree t;
        char err[256] = "";
        pvs_octree_desc d = {.max_triangles_per_leaf = 8 + 8 * seed, .max_depth = 5 + seed % 3};
        TV_CHECK(pvs_octree_build(&d, &s, &t, err, sizeof err));
        TV_CHECK(t.leaf_count > 64);
        TV_CHECK(t.balance_splits > 0); /* the clustered soup needs balancing */
        check_octree(&s, &t);
        pvs_octree_free(&t);
        pvs_test_scene_free(&s);
    }
}

static void test_box_grid_octree(void)
{
    scn_scene s;
    pvs_test_box_grid(&s, 4, 3, 3);
    pvs_octree t;
    char err[256];
    TV_CHECK(pvs_octree_build(&(pvs_octree_desc){.max_triangles_per_leaf = 20}, &s, &t, err, sizeof err));
    check_octree(&s, &t);
    pvs_octree_free(&t);
    pvs_test_scene_free(&s);
}

static void test_errors_and_empty(void)
{
    scn_scene s;
    pvs_test_soup(&s, 10, 1.0f, 0.1f, 3);
    pvs_octree t;
    char err[256] = "";
    TV_CHECK(!pvs_octree_build(&(pvs_octree_desc){.max_depth = 17}, &s, &t, err, sizeof err));
    TV_CHECK(strstr(err, "test:soup") && strstr(err, "max_depth"));
    TV_CHECK(t.leaf_count == 0 && t.leaves == NULL);
    s.indices[7] = 99;
    err[0] = 0;
    TV_CHECK(!pvs_octree_build(NULL, &s, &t, err, sizeof err));
    TV_CHECK(strstr(err, "test:soup") && strstr(err, "triangle 2"));
    s.triangle_count = 0;
    TV_CHECK(pvs_octree_build(NULL, &s, &t, err, sizeof err));
    TV_CHECK(t.leaf_count == 1 && t.tri_offsets[1] == 0);
    pvs_octree_free(&t);
    pvs_octree_free(&t); /* safe on a zeroed octree */
    pvs_test_scene_free(&s);
}

static void test_build_time_200k(void)
{
    scn_scene s;
    pvs_test_box_grid(&s, 13, 13, 10); /* 202,800 triangles */
    pvs_octree t;
    char err[256];
    pvs_octree_desc descs[2] = {{0}, {.max_triangles_per_leaf = 64}};
    for (int i = 0; i < 2; i++) {
        TV_CHECK(pvs_octree_build(&descs[i], &s, &t, err, sizeof err));
        printf("octree: %u triangles, cap %u, depth %u: %u leaves, %u refs, %u balance splits, %.1f ms\n",
               s.triangle_count, t.max_triangles_per_leaf, t.max_depth, t.leaf_count,
               t.tri_offsets[t.leaf_count], t.balance_splits, t.build_ms);
        pvs_octree_free(&t);
    }
    pvs_test_scene_free(&s);
}

int main(void)
{
    TV_TEST_RUN(test_tri_box_known_cases);
    TV_TEST_RUN(test_soup_octrees);
    TV_TEST_RUN(test_box_grid_octree);
    TV_TEST_RUN(test_errors_and_empty);
    TV_TEST_RUN(test_build_time_200k);
    return tv_test_finish();
}
