/* Octree layers (P0 part 2): every frustum-visible leaf in exactly one layer,
 * front-to-back order along random rays from v* (strict, or non-decreasing
 * once merged), earliest-layer triangle assignment, merging as a coarsening
 * of the strict order within its budget, cycle breaking on a non-octree
 * pinwheel, and timing. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layers.h"
#include "pvs_test_scenes.h"
#include "test.h"

static pvs_view random_view(const pvs_octree* t, uint32_t* rng, bool outside)
{
    pvs_view v = {.up = {0, 1, 0}, .near_dist = 0.05f, .far_dist = 40.0f};
    for (int a = 0; a < 3; a++) {
        float r = pvs_test_rand(rng);
        v.apex[a] = t->root_min[a] + t->root_size * (outside ? 3.0f * r - 1.0f : r);
        v.forward[a] = pvs_test_rand(rng) - 0.5f;
    }
    if (fabsf(v.forward[1]) > 0.9f * sqrtf(v.forward[0] * v.forward[0] + v.forward[1] * v.forward[1] +
                                           v.forward[2] * v.forward[2]))
        v.forward[0] += 1.0f;
    v.fov_y_deg = 40.0f + 80.0f * pvs_test_rand(rng);
    v.aspect = 0.8f + pvs_test_rand(rng);
    return v;
}

/* Leaf containing world point p, or UINT32_MAX outside the root. */
static uint32_t locate(const pvs_octree* t, const float p[3])
{
    uint32_t cell[3], n = 1u << t->max_depth;
    for (int a = 0; a < 3; a++) {
        float c = (p[a] - t->root_min[a]) / t->root_size * (float)n;
        if (!(c >= 0.0f && c < (float)n))
            return UINT32_MAX;
        cell[a] = (uint32_t)c;
    }
    return pvs_octree_locate(t, cell[0], cell[1], cell[2]);
}

/* `merged`: layers may repeat along a ray (non-decreasing) instead of
 * strictly increasing. */
static void check_layers(const pvs_octree* t, const pvs_view* v, const pvs_layers* L, bool merged, uint32_t* rng)
{
    /* Each surviving leaf listed exactly once, in the layer it is assigned. */
    uint32_t* seen = calloc(t->leaf_count, sizeof *seen);
    uint32_t listed = 0, wrong_layer = 0;
    for (uint32_t k = 0; k < L->layer_count; k++) {
        TV_CHECK(L->leaf_offsets[k + 1] > L->leaf_offsets[k]); /* no empty layer */
        for (uint32_t j = L->leaf_offsets[k]; j < L->leaf_offsets[k + 1]; j++) {
            seen[L->leaf_ids[j]]++;
            wrong_layer += L->leaf_layer[L->leaf_ids[j]] != k;
            listed++;
        }
    }
    uint32_t twice = 0, unlisted = 0;
    for (uint32_t i = 0; i < t->leaf_count; i++) {
        twice += seen[i] > 1;
        unlisted += L->leaf_layer[i] != PVS_LAYER_CULLED && seen[i] != 1;
    }
    TV_CHECK(listed == L->leaves_visible && L->leaves_visible + L->leaves_culled == t->leaf_count);
    TV_CHECK(twice == 0 && unlisted == 0 && wrong_layer == 0);
    TV_CHECK(L->cycles_broken == 0);

    /* Random rays from v* inside the frustum: the leaves passed have
     * strictly increasing layers (non-decreasing when merged), and none of
     * them was culled. */
    pvs_view_frame f = pvs_view_frame_make(v);
    float step = t->root_size / (float)(1u << t->max_depth) * 0.25f;
    uint32_t order_violations = 0, culled_on_ray = 0;
    for (int r = 0; r < 150; r++) {
        float x = (2.0f * pvs_test_rand(rng) - 1.0f) * f.tan_half_x;
        float y = (2.0f * pvs_test_rand(rng) - 1.0f) * f.tan_half_y;
        float dir[3];
        for (int a = 0; a < 3; a++)
            dir[a] = f.forward[a] + x * f.right[a] + y * f.up[a];
        uint32_t prev = UINT32_MAX;
        for (float depth = v->near_dist; depth <= v->far_dist; depth += step) {
            float p[3] = {v->apex[0] + depth * dir[0], v->apex[1] + depth * dir[1], v->apex[2] + depth * dir[2]};
            uint32_t leaf = locate(t, p);
            if (leaf == UINT32_MAX || leaf == prev)
                continue;
            if (L->leaf_layer[leaf] == PVS_LAYER_CULLED) {
                culled_on_ray++;
                continue;
            }
            if (prev != UINT32_MAX && (merged ? L->leaf_layer[leaf] < L->leaf_layer[prev]
                                              : L->leaf_layer[leaf] <= L->leaf_layer[prev]))
                order_violations++;
            prev = leaf;
        }
    }
    TV_CHECK(order_violations == 0);
    TV_CHECK(culled_on_ray == 0);

    /* Each triangle of a surviving leaf once, in its earliest such layer. */
    uint32_t* expect = malloc(t->scene_triangle_count * sizeof *expect);
    uint32_t* got = malloc(t->scene_triangle_count * sizeof *got);
    for (uint32_t i = 0; i < t->scene_triangle_count; i++)
        expect[i] = got[i] = UINT32_MAX;
    for (uint32_t i = 0; i < t->leaf_count; i++) {
        for (uint32_t r = t->tri_offsets[i]; r < t->tri_offsets[i + 1]; r++) {
            uint32_t tri = t->tri_ids[r];
            if (L->leaf_layer[i] != PVS_LAYER_CULLED && L->leaf_layer[i] < expect[tri])
                expect[tri] = L->leaf_layer[i];
        }
    }
    uint32_t dup = 0, mismatched = 0;
    for (uint32_t k = 0; k < L->layer_count; k++) {
        for (uint32_t j = L->tri_offsets[k]; j < L->tri_offsets[k + 1]; j++) {
            dup += got[L->tri_ids[j]] != UINT32_MAX;
            got[L->tri_ids[j]] = k;
        }
    }
    for (uint32_t i = 0; i < t->scene_triangle_count; i++)
        mismatched += got[i] != expect[i];
    TV_CHECK(dup == 0 && mismatched == 0);
    TV_CHECK(L->tri_count == L->tri_offsets[L->layer_count]);
    free(expect);
    free(got);
    free(seen);
}

/* The merged layers `M` coarsen the strict ones `S` of the same view: the
 * same triangle sequence, each merged layer a run of consecutive strict
 * ones, at most max_layers of them, each within the budget unless it is a
 * single strict layer, and each as long as the budget allows (the next
 * non-empty strict layer would not have fit). */
static void check_merge(const pvs_octree* t, const pvs_layers* S, const pvs_layers* M, uint32_t max_layers)
{
    TV_CHECK(M->layers_unmerged == S->layer_count && S->layers_unmerged == S->layer_count);
    TV_CHECK(M->tri_count == S->tri_count);
    TV_CHECK(memcmp(M->tri_ids, S->tri_ids, S->tri_count * sizeof(uint32_t)) == 0);
    TV_CHECK(M->layer_count <= max_layers && M->layer_count <= S->layer_count);
    uint32_t not_a_run = 0, over_budget = 0, strict_of_prev = 0;
    for (uint32_t i = 0; i < t->leaf_count; i++) {
        if (S->leaf_layer[i] == PVS_LAYER_CULLED) {
            not_a_run += M->leaf_layer[i] != PVS_LAYER_CULLED;
            continue;
        }
        for (uint32_t j = 0; j < t->leaf_count; j++) {
            if (S->leaf_layer[j] != PVS_LAYER_CULLED && S->leaf_layer[i] < S->leaf_layer[j])
                not_a_run += M->leaf_layer[i] > M->leaf_layer[j];
            if (S->leaf_layer[j] == S->leaf_layer[i])
                not_a_run += M->leaf_layer[i] != M->leaf_layer[j];
        }
    }
    for (uint32_t k = 0; k < M->layer_count; k++) {
        uint32_t n = M->tri_offsets[k + 1] - M->tri_offsets[k], strict = 0;
        for (uint32_t s = 0; s < S->layer_count; s++)
            strict += S->tri_offsets[s] >= M->tri_offsets[k] && S->tri_offsets[s + 1] <= M->tri_offsets[k + 1] &&
                      S->tri_offsets[s + 1] > S->tri_offsets[s];
        over_budget += n > M->merge_budget && strict > 1;
        /* the next layer's first non-empty strict layer would not have fit */
        if (k + 1 < M->layer_count) {
            uint32_t s = 0;
            while (S->tri_offsets[s] < M->tri_offsets[k + 1] || S->tri_offsets[s + 1] == S->tri_offsets[s])
                s++;
            strict_of_prev += S->tri_offsets[s + 1] - M->tri_offsets[k] <= M->merge_budget && n > 0;
        }
    }
    TV_CHECK(not_a_run == 0 && over_budget == 0 && strict_of_prev == 0);
}

static void test_random_octrees_and_views(void)
{
    uint32_t rng = 12345;
    pvs_layers L = {0}; /* reused across octrees: exercises the arena growth */
    pvs_layers M = {0};
    char err[256];
    uint32_t merged_some = 0;
    for (uint32_t seed = 1; seed <= 6; seed++) {
        scn_scene s;
        pvs_test_soup(&s, 1500 * seed, 10.0f, 0.3f, seed);
        pvs_octree t;
        pvs_octree_desc d = {.max_triangles_per_leaf = 6 + 4 * seed, .max_depth = 4 + seed % 4};
        TV_CHECK(pvs_octree_build(&d, &s, &t, err, sizeof err));
        for (int i = 0; i < 12; i++) {
            pvs_view v = random_view(&t, &rng, i % 3 == 2);
            TV_CHECK(pvs_layers_build(&t, &v, PVS_LAYERS_UNMERGED, &L, err, sizeof err));
            check_layers(&t, &v, &L, false, &rng);
            uint32_t max_layers = 1 + (uint32_t)i % 6;
            TV_CHECK(pvs_layers_build(&t, &v, max_layers, &M, err, sizeof err));
            check_layers(&t, &v, &M, true, &rng);
            check_merge(&t, &L, &M, max_layers);
            merged_some += M.layer_count < L.layer_count;
        }
        pvs_octree_free(&t);
        pvs_test_scene_free(&s);
    }
    TV_CHECK(merged_some > 0);
    pvs_layers_free(&M);
    pvs_layers_free(&L);
    pvs_layers_free(&L); /* safe on a zeroed struct */
}

/* Five boxes in a pinwheel around a hole (extruded in z) are not an octree:
 * seen from the hole, each blade waits for the next one. */
static void test_pinwheel_cycle_is_broken(void)
{
    static const float boxes[5][4] = {{1, 1, 2, 2}, {0, 0, 2, 1}, {2, 0, 3, 2}, {1, 2, 3, 3}, {0, 1, 1, 3}};
    pvs_leaf leaves[5];
    uint32_t tri_offsets[6] = {0}, nbr_offsets[31], nbr_ids[64], n = 0;
    for (int i = 0; i < 5; i++) {
        leaves[i] = (pvs_leaf){.min = {boxes[i][0], boxes[i][1], 0}, .max = {boxes[i][2], boxes[i][3], 1}};
    }
    nbr_offsets[0] = 0;
    for (int i = 0; i < 5; i++) {
        for (int f = 0; f < 6; f++) {
            int a = f / 2;
            for (int j = 0; j < 5 && a < 2; j++) {
                int o = 1 - a;
                bool plane = (f & 1) ? leaves[i].max[a] == leaves[j].min[a] : leaves[i].min[a] == leaves[j].max[a];
                bool overlap = leaves[i].min[o] < leaves[j].max[o] && leaves[j].min[o] < leaves[i].max[o];
                if (i != j && plane && overlap)
                    nbr_ids[n++] = (uint32_t)j;
            }
            nbr_offsets[6 * i + f + 1] = n;
        }
    }
    pvs_octree t = {.leaf_count = 5, .leaves = leaves, .tri_offsets = tri_offsets,
                    .nbr_offsets = nbr_offsets, .nbr_ids = nbr_ids};
    pvs_view v = {.apex = {1.5f, 1.5f, -0.5f}, .forward = {0, 0, 1}, .up = {0, 1, 0},
                  .fov_y_deg = 170.0f, .near_dist = 0.1f, .far_dist = 10.0f};
    pvs_layers L = {0};
    char err[256];
    TV_CHECK(pvs_layers_build(&t, &v, PVS_LAYERS_UNMERGED, &L, err, sizeof err));
    TV_CHECK(L.leaves_visible == 5);
    TV_CHECK(L.cycles_broken >= 1);
    TV_CHECK(L.leaf_layer[0] == 0);
    for (int i = 0; i < 5; i++)
        TV_CHECK(L.leaf_layer[i] != PVS_LAYER_CULLED && L.leaf_layer[i] < 5);
    TV_CHECK(L.leaf_offsets[L.layer_count] == 5);
    pvs_layers_free(&L);
}

static int cmp_double(const void* a, const void* b)
{
    double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

static void test_timing_200k(void)
{
    scn_scene s;
    pvs_test_box_grid(&s, 13, 13, 10);
    char err[256];
    uint32_t caps[2] = {1024, 64};
    for (int c = 0; c < 2; c++) {
        pvs_octree t;
        TV_CHECK(pvs_octree_build(&(pvs_octree_desc){.max_triangles_per_leaf = caps[c]}, &s, &t, err, sizeof err));
        pvs_layers L = {0};
        double ms[64], order[64];
        uint32_t rng = 99, layers = 0, visible = 0;
        for (int i = 0; i < 64; i++) {
            pvs_view v = random_view(&t, &rng, false);
            v.apex[1] = 0.5f + pvs_test_rand(&rng); /* standing among the boxes */
            v.forward[1] = 0.1f * v.forward[1];
            TV_CHECK(pvs_layers_build(&t, &v, 0, &L, err, sizeof err));
            ms[i] = L.ms;
            order[i] = L.order_ms;
            layers += L.layers_unmerged;
            visible += L.leaves_visible;
        }
        qsort(ms, 64, sizeof ms[0], cmp_double);
        qsort(order, 64, sizeof order[0], cmp_double);
        printf("layers: %u leaves (cap %u), mean %u visible, mean %u layers before merging: order median %.3f ms, "
               "with triangle lists median %.3f ms, max %.3f ms\n",
               t.leaf_count, caps[c], visible / 64, layers / 64, order[32], ms[32], ms[63]);
        pvs_layers_free(&L);
        pvs_octree_free(&t);
    }
    pvs_test_scene_free(&s);
}

int main(void)
{
    TV_TEST_RUN(test_random_octrees_and_views);
    TV_TEST_RUN(test_pinwheel_cycle_is_broken);
    TV_TEST_RUN(test_timing_200k);
    return tv_test_finish();
}
