#include "layers.h"

#include <assert.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clock.h"

/* Grows every array of `arrays` (all sharing the capacity *cap) to at least
 * `need` (and at least 1) elements. Capacities only grow, so a warm arena
 * does not allocate. */
static bool reserve(uint32_t* cap, uint32_t need, uint32_t** arrays[], int n)
{
    need = need ? need : 1;
    if (need <= *cap)
        return true;
    uint32_t grown_cap = need + need / 2 + 16;
    for (int i = 0; i < n; i++) {
        uint32_t* grown = realloc(*arrays[i], (size_t)grown_cap * sizeof *grown);
        if (!grown)
            return false;
        *arrays[i] = grown;
    }
    *cap = grown_cap;
    return true;
}

/* Inward frustum planes (normal, offset: inside when dot(n, p) + d >= 0). */
static void frustum_planes(const pvs_view* view, float planes[6][4])
{
    pvs_view_frame f = pvs_view_frame_make(view);
    const float* a = view->apex;
    float n[6][3];
    for (int i = 0; i < 3; i++) {
        n[0][i] = f.forward[i];
        n[1][i] = -f.forward[i];
        n[2][i] = f.right[i] + f.tan_half_x * f.forward[i];
        n[3][i] = -f.right[i] + f.tan_half_x * f.forward[i];
        n[4][i] = f.up[i] + f.tan_half_y * f.forward[i];
        n[5][i] = -f.up[i] + f.tan_half_y * f.forward[i];
    }
    for (int p = 0; p < 6; p++) {
        float apex_dot = n[p][0] * a[0] + n[p][1] * a[1] + n[p][2] * a[2];
        memcpy(planes[p], n[p], sizeof n[p]);
        planes[p][3] = -apex_dot;
    }
    planes[0][3] -= view->near_dist;
    planes[1][3] += view->far_dist;
}

static bool box_outside(const float planes[6][4], const float mn[3], const float mx[3])
{
    for (int p = 0; p < 6; p++) {
        float s = planes[p][3];
        for (int i = 0; i < 3; i++)
            s += planes[p][i] * (planes[p][i] >= 0.0f ? mx[i] : mn[i]);
        if (s < 0.0f)
            return true;
    }
    return false;
}

/* Does face f of leaf l face the apex (apex strictly beyond the face plane)? */
static bool faces_apex(const pvs_leaf* l, int f, const float apex[3])
{
    int axis = f / 2;
    return (f & 1) ? apex[axis] > l->max[axis] : apex[axis] < l->min[axis];
}

static bool alloc_arena(pvs_layers* L, const pvs_octree* tree)
{
    uint32_t** per_leaf[] = {&L->leaf_ids, &L->leaf_layer, &L->_pending, &L->_queue};
    uint32_t** per_tri[] = {&L->tri_ids};
    uint32_t** stamps[] = {&L->_tri_stamp};
    uint32_t old_stamp_cap = L->_tri_stamp_cap, t = tree->scene_triangle_count;
    if (!reserve(&L->_leaf_cap, tree->leaf_count, per_leaf, 4) ||
        !reserve(&L->_tri_cap, t, per_tri, 1) ||
        !reserve(&L->_tri_stamp_cap, t, stamps, 1))
        return false;
    if (L->_tri_stamp_cap != old_stamp_cap) {
        memset(L->_tri_stamp, 0, L->_tri_stamp_cap * sizeof(uint32_t));
        L->_stamp = 0;
    }
    return true;
}

/* Kahn's algorithm over the surviving leaves; returns the layer count. */
static uint32_t assign_layers(pvs_layers* L, const pvs_octree* tree, const float apex[3])
{
    uint32_t n = tree->leaf_count, head = 0, tail = 0, done = 0, layer_count = 0;
    uint32_t *layer = L->leaf_layer, *pending = L->_pending, *queue = L->_queue;
    for (uint32_t i = 0; i < n; i++) {
        pending[i] = 0;
        if (layer[i] == PVS_LAYER_CULLED)
            continue;
        for (int f = 0; f < 6; f++) {
            if (!faces_apex(&tree->leaves[i], f, apex))
                continue;
            for (uint32_t k = tree->nbr_offsets[6 * i + f]; k < tree->nbr_offsets[6 * i + f + 1]; k++)
                pending[i] += layer[tree->nbr_ids[k]] != PVS_LAYER_CULLED;
        }
        if (pending[i] == 0)
            queue[tail++] = i;
    }
    while (done < L->leaves_visible) {
        if (head == tail) {
            /* A cycle: release the blocked leaf closest to being ready. */
            uint32_t best = UINT32_MAX;
            for (uint32_t i = 0; i < n; i++) {
                if (layer[i] != PVS_LAYER_CULLED && pending[i] != 0 && pending[i] != UINT32_MAX &&
                    (best == UINT32_MAX || pending[i] < pending[best]))
                    best = i;
            }
            assert(best != UINT32_MAX);
            pending[best] = 0;
            queue[tail++] = best;
            L->cycles_broken++;
        }
        uint32_t cur = queue[head++];
        pending[cur] = UINT32_MAX; /* processed */
        done++;
        layer_count = layer[cur] + 1 > layer_count ? layer[cur] + 1 : layer_count;
        const pvs_leaf* cl = &tree->leaves[cur];
        for (int f = 0; f < 6; f++) {
            /* The neighbours across face f depend on cur when the apex is
             * strictly on cur's side of that plane. */
            int axis = f / 2;
            bool apex_on_our_side = (f & 1) ? apex[axis] < cl->max[axis] : apex[axis] > cl->min[axis];
            if (!apex_on_our_side)
                continue;
            for (uint32_t k = tree->nbr_offsets[6 * cur + f]; k < tree->nbr_offsets[6 * cur + f + 1]; k++) {
                uint32_t m = tree->nbr_ids[k];
                if (layer[m] == PVS_LAYER_CULLED || pending[m] == UINT32_MAX)
                    continue;
                layer[m] = layer[cur] + 1 > layer[m] ? layer[cur] + 1 : layer[m];
                /* pending 0 here: forced by a cycle break and still queued. */
                if (pending[m] != 0 && --pending[m] == 0)
                    queue[tail++] = m;
            }
        }
    }
    return layer_count;
}

/* One greedy pass over the layers: a layer joins the merged layer before it
 * while that keeps at most `budget` triangles; a layer without triangles
 * always joins. Returns the merged count. With `map` (one entry per layer)
 * it also records each layer's merged index and compacts the offsets in
 * place: a merged layer's bounds are a subset of the original ones, written
 * at an index never above the one still to be read. */
static uint32_t merge_pass(pvs_layers* L, uint32_t budget, uint32_t* map)
{
    uint32_t m = 0, start = 0, end = 0; /* the current merged layer's triangles: [start, end) */
    for (uint32_t k = 0; k < L->layer_count; k++) {
        uint32_t first = L->tri_offsets[k], last = L->tri_offsets[k + 1], leaf_end = L->leaf_offsets[k + 1];
        if (last > first && end > start && last - start > budget) {
            m++;
            start = first;
        }
        end = last;
        if (map) {
            map[k] = m;
            L->tri_offsets[m + 1] = last;
            L->leaf_offsets[m + 1] = leaf_end;
        }
    }
    return m + 1;
}

/* Merges consecutive layers into at most max_layers, choosing the smallest
 * per-layer triangle budget that allows it (greedy is optimal for a given
 * budget, and its count falls as the budget grows: binary search). */
static void merge_layers(pvs_layers* L, const pvs_octree* tree, uint32_t max_layers)
{
    if (L->layer_count == 0)
        return;
    uint32_t lo = 0, hi = L->tri_count;
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (merge_pass(L, mid, NULL) <= max_layers)
            hi = mid;
        else
            lo = mid + 1;
    }
    uint32_t* map = L->_queue; /* free after assign_layers; layers <= leaves */
    uint32_t count = merge_pass(L, lo, map);
    for (uint32_t i = 0; i < tree->leaf_count; i++) {
        if (L->leaf_layer[i] != PVS_LAYER_CULLED)
            L->leaf_layer[i] = map[L->leaf_layer[i]];
    }
    L->layer_count = count;
    L->merge_budget = lo;
}

bool pvs_layers_build(const pvs_octree* tree, const pvs_view* view, uint32_t max_layers, pvs_layers* layers,
                      char* err, size_t err_size)
{
    assert(tree && view && layers && tree->leaf_count > 0);
    double start = tv_now_ms();
    pvs_layers* L = layers;
    if (!alloc_arena(L, tree)) {
        snprintf(err, err_size, "pvs layers: out of memory for %u leaves", tree->leaf_count);
        return false;
    }
    float planes[6][4];
    frustum_planes(view, planes);
    L->leaves_visible = L->leaves_culled = L->cycles_broken = 0;
    for (uint32_t i = 0; i < tree->leaf_count; i++) {
        bool out = box_outside(planes, tree->leaves[i].min, tree->leaves[i].max);
        L->leaf_layer[i] = out ? PVS_LAYER_CULLED : 0;
        L->leaves_visible += !out;
    }
    L->leaves_culled = tree->leaf_count - L->leaves_visible;
    uint32_t count = assign_layers(L, tree, view->apex);
    L->order_ms = tv_now_ms() - start;
    uint32_t** per_layer[] = {&L->leaf_offsets, &L->tri_offsets};
    if (!reserve(&L->_layer_cap, count + 1, per_layer, 2)) {
        snprintf(err, err_size, "pvs layers: out of memory for %u layers", count);
        return false;
    }
    L->layer_count = count;

    /* Counting sort of the surviving leaves by layer (stable in leaf id). */
    memset(L->leaf_offsets, 0, (count + 1) * sizeof(uint32_t));
    for (uint32_t i = 0; i < tree->leaf_count; i++) {
        if (L->leaf_layer[i] != PVS_LAYER_CULLED)
            L->leaf_offsets[L->leaf_layer[i] + 1]++;
    }
    for (uint32_t k = 0; k < count; k++)
        L->leaf_offsets[k + 1] += L->leaf_offsets[k];
    uint32_t* fill = L->_pending; /* free again after assign_layers */
    memcpy(fill, L->leaf_offsets, count * sizeof(uint32_t));
    for (uint32_t i = 0; i < tree->leaf_count; i++) {
        if (L->leaf_layer[i] != PVS_LAYER_CULLED)
            L->leaf_ids[fill[L->leaf_layer[i]]++] = i;
    }

    /* Walking the layers in order, a triangle's first sighting is its
     * earliest layer; the stamp avoids clearing a per-triangle array. */
    if (++L->_stamp == 0) {
        memset(L->_tri_stamp, 0, L->_tri_stamp_cap * sizeof(uint32_t));
        L->_stamp = 1;
    }
    uint32_t n_tris = 0;
    L->tri_offsets[0] = 0;
    for (uint32_t k = 0; k < count; k++) {
        for (uint32_t j = L->leaf_offsets[k]; j < L->leaf_offsets[k + 1]; j++) {
            uint32_t leaf = L->leaf_ids[j];
            for (uint32_t r = tree->tri_offsets[leaf]; r < tree->tri_offsets[leaf + 1]; r++) {
                uint32_t t = tree->tri_ids[r];
                if (L->_tri_stamp[t] != L->_stamp) {
                    L->_tri_stamp[t] = L->_stamp;
                    L->tri_ids[n_tris++] = t;
                }
            }
        }
        L->tri_offsets[k + 1] = n_tris;
    }
    L->tri_count = n_tris;
    L->layers_unmerged = count;
    L->merge_budget = 0;
    if (max_layers != PVS_LAYERS_UNMERGED)
        merge_layers(L, tree, max_layers ? max_layers : PVS_LAYERS_DEFAULT_MAX);
    L->ms = tv_now_ms() - start;
    return true;
}

void pvs_layers_free(pvs_layers* layers)
{
    free(layers->leaf_offsets);
    free(layers->leaf_ids);
    free(layers->tri_offsets);
    free(layers->tri_ids);
    free(layers->leaf_layer);
    free(layers->_pending);
    free(layers->_queue);
    free(layers->_tri_stamp);
    memset(layers, 0, sizeof *layers);
}
