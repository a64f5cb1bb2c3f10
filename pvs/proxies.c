#include "proxies.h"

#include <assert.h>
#include <stdlib.h>
#include <string.h>

static bool grow(uint32_t** array, uint32_t* cap, uint32_t need)
{
    if (need <= *cap)
        return true;
    uint32_t n = need + need / 2;
    uint32_t* a = realloc(*array, sizeof(uint32_t) * n);
    if (!a)
        return false;
    *array = a;
    *cap = n;
    return true;
}

static bool boxes_touch(const float* lo, const float* hi, const float* box)
{
    for (int i = 0; i < 3; i++) {
        if (box[4 + i] < lo[i] || box[i] > hi[i])
            return false;
    }
    return true;
}

static bool meets_sphere(const float* box, const float c[3], float r)
{
    float d2 = 0.0f;
    for (int i = 0; i < 3; i++) {
        float d = c[i] < box[i] ? box[i] - c[i] : c[i] > box[4 + i] ? c[i] - box[4 + i] : 0.0f;
        d2 += d * d;
    }
    return d2 <= r * r;
}

static bool inside_root(const pvs_octree* tree, const float* box)
{
    for (int i = 0; i < 3; i++) {
        if (box[i] < tree->root_min[i] || box[4 + i] > tree->root_min[i] + tree->root_size)
            return false;
    }
    return true;
}

const pvs_octree* pvs_proxies_sort(pvs_proxy_sort* sort, const pvs_octree* tree, const float* boxes, uint32_t count,
                                   uint32_t first_face, const float centre[3], float radius, bool* always)
{
    assert(sort && tree && (boxes || count == 0) && (always || count == 0));
    sort->always_count = 0;
    uint32_t drawn = 0;
    for (uint32_t p = 0; p < count; p++) {
        const float* b = boxes + PVS_PROXY_FLOATS * p;
        always[p] = meets_sphere(b, centre, radius) || !inside_root(tree, b);
        sort->always_count += always[p];
        drawn += !always[p];
    }
    if (drawn == 0)
        return tree;
    /* Counts first (O(leaves x proxies): a few hundred thousand box tests
     * for 40 proxies on the shared scenes), then the static references and
     * the faces per leaf. */
    if (!grow(&sort->_offsets, &sort->_leaf_cap, tree->leaf_count + 1))
        return NULL;
    uint32_t refs = 0;
    for (uint32_t l = 0; l < tree->leaf_count; l++) {
        const pvs_leaf* leaf = &tree->leaves[l];
        sort->_offsets[l] = refs;
        refs += tree->tri_offsets[l + 1] - tree->tri_offsets[l];
        for (uint32_t p = 0; p < count; p++)
            refs += !always[p] && boxes_touch(leaf->min, leaf->max, boxes + PVS_PROXY_FLOATS * p) ? 12u : 0u;
    }
    sort->_offsets[tree->leaf_count] = refs;
    if (!grow(&sort->_ids, &sort->_ref_cap, refs ? refs : 1))
        return NULL;
    for (uint32_t l = 0; l < tree->leaf_count; l++) {
        const pvs_leaf* leaf = &tree->leaves[l];
        uint32_t n = tree->tri_offsets[l + 1] - tree->tri_offsets[l], at = sort->_offsets[l] + n;
        memcpy(sort->_ids + sort->_offsets[l], tree->tri_ids + tree->tri_offsets[l], sizeof(uint32_t) * n);
        for (uint32_t p = 0; p < count; p++) {
            if (always[p] || !boxes_touch(leaf->min, leaf->max, boxes + PVS_PROXY_FLOATS * p))
                continue;
            for (uint32_t f = 0; f < 12; f++)
                sort->_ids[at++] = first_face + 12 * p + f;
        }
    }
    sort->tree = *tree;
    sort->tree.tri_offsets = sort->_offsets;
    sort->tree.tri_ids = sort->_ids;
    sort->tree.scene_triangle_count = first_face + 12 * count;
    return &sort->tree;
}

void pvs_proxy_sort_free(pvs_proxy_sort* sort)
{
    free(sort->_offsets);
    free(sort->_ids);
    memset(sort, 0, sizeof *sort);
}
