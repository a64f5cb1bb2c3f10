/* Proxy boxes sorted into the octree (pvs/proxies.h): every face of a drawn
 * proxy in every leaf its box touches and in no other, the static lists
 * unchanged, the outright proxies (near the viewcell, outside the root) in
 * no leaf, and through pvs_layers_build each face once, in the earliest
 * layer of a touched leaf. */
#include <stdlib.h>
#include <string.h>

#include "layers.h"
#include "proxies.h"
#include "pvs_test_scenes.h"
#include "test.h"

static bool touches(const pvs_leaf* l, const float* b)
{
    for (int a = 0; a < 3; a++)
        if (b[4 + a] < l->min[a] || b[a] > l->max[a])
            return false;
    return true;
}

static uint32_t count_in_leaf(const pvs_octree* t, uint32_t leaf, uint32_t lo, uint32_t hi)
{
    uint32_t n = 0;
    for (uint32_t r = t->tri_offsets[leaf]; r < t->tri_offsets[leaf + 1]; r++)
        n += t->tri_ids[r] >= lo && t->tri_ids[r] < hi;
    return n;
}

static void test_sort_and_layers(void)
{
    scn_scene s;
    pvs_test_box_grid(&s, 6, 6, 2); /* boxes over x, z in [0, 11] */
    pvs_octree tree;
    char err[256];
    TV_CHECK(pvs_octree_build(&(pvs_octree_desc){.max_triangles_per_leaf = 16}, &s, &tree, err, sizeof err));
    const uint32_t first = s.triangle_count;
    float boxes[4 * PVS_PROXY_FLOATS] = {
        2.5f, 0.0f, 2.5f, 0, 4.5f, 0.8f, 3.0f, 0,   /* between boxes: drawn */
        8.0f, 0.2f, 8.0f, 0, 8.2f, 0.4f, 8.2f, 0,   /* small: drawn */
        -0.5f, 0.0f, -0.5f, 0, 0.5f, 1.0f, 0.5f, 0, /* around the viewcell's centre below */
        5.0f, 0.0f, 5.0f, 0, 50.0f, 1.0f, 6.0f, 0,  /* out of the root */
    };
    const float centre[3] = {0.0f, 0.5f, 0.0f};
    bool always[4];
    pvs_proxy_sort sort = {0};
    TV_CHECK(pvs_proxies_sort(&sort, &tree, boxes, 2, first, centre, 0.2f, always) == &sort.tree);
    const pvs_octree* t = pvs_proxies_sort(&sort, &tree, boxes, 4, first, centre, 0.2f, always);
    TV_CHECK(t == &sort.tree && t->scene_triangle_count == first + 48);
    TV_CHECK(!always[0] && !always[1] && always[2] && always[3] && sort.always_count == 2);
    uint32_t wrong = 0, touched[2] = {0, 0};
    for (uint32_t l = 0; l < t->leaf_count; l++) {
        wrong += count_in_leaf(t, l, 0, first) != tree.tri_offsets[l + 1] - tree.tri_offsets[l];
        for (uint32_t p = 0; p < 4; p++) {
            bool in = p < 2 && touches(&t->leaves[l], boxes + PVS_PROXY_FLOATS * p);
            wrong += count_in_leaf(t, l, first + 12 * p, first + 12 * p + 12) != (in ? 12u : 0u);
            touched[p < 2 ? p : 0] += in;
        }
    }
    TV_CHECK(wrong == 0 && touched[0] > 1 && touched[1] >= 1);

    /* layers: each face once, in the earliest layer of the leaves it is in */
    pvs_view v = {.apex = {-3.0f, 0.5f, -3.0f}, .forward = {1.0f, 0.0f, 1.0f}, .up = {0, 1, 0},
                  .fov_y_deg = 90.0f, .aspect = 1.0f, .near_dist = 0.05f, .far_dist = 100.0f};
    pvs_layers L = {0};
    TV_CHECK(pvs_layers_build(t, &v, 0, &L, err, sizeof err)); /* merged, as pvs_compute does */
    uint32_t faces = 0, misplaced = 0;
    for (uint32_t k = 0; k < L.layer_count; k++) {
        for (uint32_t i = L.tri_offsets[k]; i < L.tri_offsets[k + 1]; i++) {
            uint32_t id = L.tri_ids[i];
            if (id < first)
                continue;
            faces++;
            uint32_t earliest = UINT32_MAX;
            for (uint32_t l = 0; l < t->leaf_count; l++)
                if (L.leaf_layer[l] < earliest && count_in_leaf(t, l, id, id + 1))
                    earliest = L.leaf_layer[l];
            misplaced += earliest != k;
        }
    }
    TV_CHECK(faces == 24 && misplaced == 0);
    pvs_layers_free(&L);
    pvs_proxy_sort_free(&sort);
    pvs_octree_free(&tree);
    pvs_test_scene_free(&s);
}

int main(void)
{
    TV_TEST_RUN(test_sort_and_layers);
    return tv_test_finish();
}
