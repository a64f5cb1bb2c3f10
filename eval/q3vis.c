/* q3vis.c - cluster look-ups on a parsed .pvs.json and the triangle set of
 * a cluster PVS (the reader is q3vis_parse.c). */
#include "q3vis.h"

#include <assert.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

bool pvs_q3vis_sees(const pvs_q3vis* vis, uint32_t from, uint32_t to)
{
    assert(vis && from < vis->n_clusters && to < vis->n_clusters);
    return (vis->visdata[(size_t)from * vis->bytes_per_cluster + to / 8] >> (to % 8)) & 1u;
}

/* A leaf that can hold a viewpoint: in a cluster and with a non-empty box. */
static bool _usable(const pvs_q3vis_leaf* l)
{
    return l->cluster >= 0 && l->min[0] < l->max[0] && l->min[1] < l->max[1] && l->min[2] < l->max[2];
}

uint32_t pvs_q3vis_clusters_near(const pvs_q3vis* vis, const float centre[3], float radius, uint8_t* cluster_mask)
{
    assert(vis && centre && cluster_mask && radius >= 0.0f);
    memset(cluster_mask, 0, vis->n_clusters);
    uint32_t marked = 0;
    for (uint32_t i = 0; i < vis->leaf_count; i++) {
        const pvs_q3vis_leaf* l = &vis->leaves[i];
        if (!_usable(l))
            continue;
        float d2 = 0.0f; /* squared distance from the centre to the grown box */
        for (int k = 0; k < 3; k++) {
            float lo = l->min[k] - PVS_Q3VIS_EPS_M, hi = l->max[k] + PVS_Q3VIS_EPS_M;
            float d = centre[k] < lo ? lo - centre[k] : centre[k] > hi ? centre[k] - hi : 0.0f;
            d2 += d * d;
        }
        if (d2 <= radius * radius && !cluster_mask[l->cluster]) {
            cluster_mask[l->cluster] = 1;
            marked++;
        }
    }
    return marked;
}

/* A uniform grid over the usable leaves, so that mapping a scene costs
 * O(triangles * leaves per cell) instead of O(triangles * leaves). */
typedef struct _grid {
    float min[3], cell[3];
    uint32_t n[3];
    uint32_t* offsets; /* cells + 1 */
    uint32_t* leaves;
} _grid;

#define GRID_CELLS_PER_AXIS 48u

static uint32_t _cell_of(const _grid* g, int axis, float x)
{
    float c = (x - g->min[axis]) / g->cell[axis];
    if (!(c > 0.0f))
        return 0;
    return c >= (float)(g->n[axis] - 1) ? g->n[axis] - 1 : (uint32_t)c;
}

/* Cell range [lo, hi] per axis covering the box [bmin, bmax]. */
static void _cell_range(const _grid* g, const float bmin[3], const float bmax[3], uint32_t lo[3], uint32_t hi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = _cell_of(g, k, bmin[k]);
        hi[k] = _cell_of(g, k, bmax[k]);
    }
}

/* Counts (cursor NULL) or stores `leaf` in every cell of the range. */
static void _grid_insert(_grid* g, const uint32_t lo[3], const uint32_t hi[3], uint32_t leaf, uint32_t* cursor)
{
    for (uint32_t z = lo[2]; z <= hi[2]; z++)
        for (uint32_t y = lo[1]; y <= hi[1]; y++)
            for (uint32_t x = lo[0]; x <= hi[0]; x++) {
                uint32_t c = (z * g->n[1] + y) * g->n[0] + x;
                if (cursor)
                    g->leaves[cursor[c]++] = leaf;
                else
                    g->offsets[c + 1]++;
            }
}

static void _grown_box(const pvs_q3vis_leaf* l, float bmin[3], float bmax[3])
{
    for (int k = 0; k < 3; k++) {
        bmin[k] = l->min[k] - PVS_Q3VIS_EPS_M;
        bmax[k] = l->max[k] + PVS_Q3VIS_EPS_M;
    }
}

static bool _grid_build(const pvs_q3vis* vis, _grid* g)
{
    memset(g, 0, sizeof *g);
    float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
    for (uint32_t i = 0; i < vis->leaf_count; i++) {
        if (!_usable(&vis->leaves[i]))
            continue;
        for (int k = 0; k < 3; k++) {
            lo[k] = vis->leaves[i].min[k] < lo[k] ? vis->leaves[i].min[k] : lo[k];
            hi[k] = vis->leaves[i].max[k] > hi[k] ? vis->leaves[i].max[k] : hi[k];
        }
    }
    uint32_t cells = 1;
    for (int k = 0; k < 3; k++) {
        g->n[k] = lo[k] < hi[k] ? GRID_CELLS_PER_AXIS : 1;
        g->min[k] = lo[k];
        g->cell[k] = lo[k] < hi[k] ? (hi[k] - lo[k]) / (float)g->n[k] : 1.0f;
        cells *= g->n[k];
    }
    g->offsets = calloc(cells + 1, sizeof(uint32_t));
    if (!g->offsets)
        return false;
    uint32_t clo[3], chi[3];
    float bmin[3], bmax[3];
    for (int pass = 0; pass < 2; pass++) {
        uint32_t* cursor = NULL;
        if (pass == 1) {
            for (uint32_t c = 0; c < cells; c++)
                g->offsets[c + 1] += g->offsets[c];
            g->leaves = malloc(((size_t)g->offsets[cells] + 1) * sizeof(uint32_t));
            cursor = malloc((size_t)cells * sizeof(uint32_t));
            if (!g->leaves || !cursor) {
                free(cursor);
                return false;
            }
            memcpy(cursor, g->offsets, (size_t)cells * sizeof(uint32_t));
        }
        for (uint32_t i = 0; i < vis->leaf_count; i++) {
            if (!_usable(&vis->leaves[i]))
                continue;
            _grown_box(&vis->leaves[i], bmin, bmax);
            _cell_range(g, bmin, bmax, clo, chi);
            _grid_insert(g, clo, chi, i, cursor);
        }
        free(cursor);
    }
    return true;
}

static void _grid_free(_grid* g)
{
    free(g->offsets);
    free(g->leaves);
}

static bool _boxes_meet(const float amin[3], const float amax[3], const float bmin[3], const float bmax[3])
{
    for (int k = 0; k < 3; k++)
        if (amax[k] < bmin[k] || bmax[k] < amin[k])
            return false;
    return true;
}

/* Appends the clusters of triangle t (each once: `stamp` remembers the last
 * triangle that listed a cluster) to map->clusters. */
static bool _map_triangle(const pvs_q3vis* vis, const _grid* g, const scn_scene* scene, uint32_t t, uint32_t* stamp,
                          uint32_t* cap, pvs_q3vis_tri_map* map)
{
    float tmin[3], tmax[3];
    for (int k = 0; k < 3; k++)
        tmin[k] = tmax[k] = scene->positions[3 * scene->indices[3 * t] + k];
    for (int v = 1; v < 3; v++)
        for (int k = 0; k < 3; k++) {
            float x = scene->positions[3 * scene->indices[3 * t + v] + k];
            tmin[k] = x < tmin[k] ? x : tmin[k];
            tmax[k] = x > tmax[k] ? x : tmax[k];
        }
    uint32_t lo[3], hi[3], n = map->offsets[t];
    _cell_range(g, tmin, tmax, lo, hi);
    for (uint32_t z = lo[2]; z <= hi[2]; z++)
        for (uint32_t y = lo[1]; y <= hi[1]; y++)
            for (uint32_t x = lo[0]; x <= hi[0]; x++) {
                uint32_t c = (z * g->n[1] + y) * g->n[0] + x;
                for (uint32_t j = g->offsets[c]; j < g->offsets[c + 1]; j++) {
                    const pvs_q3vis_leaf* l = &vis->leaves[g->leaves[j]];
                    float bmin[3], bmax[3];
                    _grown_box(l, bmin, bmax);
                    if (stamp[l->cluster] == t + 1 || !_boxes_meet(tmin, tmax, bmin, bmax))
                        continue;
                    stamp[l->cluster] = t + 1;
                    if (n == *cap) {
                        uint32_t grown_cap = *cap * 2;
                        uint32_t* grown = grown_cap > *cap ? realloc(map->clusters, grown_cap * sizeof *grown) : NULL;
                        if (!grown)
                            return false;
                        map->clusters = grown;
                        *cap = grown_cap;
                    }
                    map->clusters[n++] = (uint32_t)l->cluster;
                }
            }
    map->offsets[t + 1] = n;
    map->unclustered += n == map->offsets[t];
    return true;
}

bool pvs_q3vis_map_triangles(const pvs_q3vis* vis, const scn_scene* scene, pvs_q3vis_tri_map* map, char* err,
                             size_t err_size)
{
    assert(vis && scene && map && vis->n_clusters > 0);
    memset(map, 0, sizeof *map);
    _grid g;
    uint32_t cap = 1024;
    uint32_t* stamp = calloc(vis->n_clusters, sizeof(uint32_t));
    map->triangle_count = scene->triangle_count;
    map->offsets = calloc((size_t)scene->triangle_count + 1, sizeof(uint32_t));
    map->clusters = malloc(cap * sizeof(uint32_t));
    bool ok = _grid_build(vis, &g) && stamp && map->offsets && map->clusters;
    for (uint32_t t = 0; ok && t < scene->triangle_count; t++)
        ok = _map_triangle(vis, &g, scene, t, stamp, &cap, map);
    _grid_free(&g);
    free(stamp);
    if (!ok) {
        pvs_q3vis_tri_map_free(map);
        snprintf(err, err_size, "q3vis: out of memory mapping %u triangles to clusters", scene->triangle_count);
    }
    return ok;
}

void pvs_q3vis_tri_map_free(pvs_q3vis_tri_map* map)
{
    free(map->offsets);
    free(map->clusters);
    memset(map, 0, sizeof *map);
}

uint32_t pvs_q3vis_triangles(const pvs_q3vis* vis, const pvs_q3vis_tri_map* map, const uint8_t* sources,
                             uint8_t* scratch, uint32_t* ids)
{
    assert(vis && map && sources && scratch && ids);
    uint8_t* visible = scratch;
    memset(visible, 0, vis->n_clusters);
    for (uint32_t from = 0; from < vis->n_clusters; from++) {
        if (!sources[from])
            continue;
        for (uint32_t to = 0; to < vis->n_clusters; to++)
            visible[to] |= (uint8_t)pvs_q3vis_sees(vis, from, to);
    }
    uint32_t count = 0;
    for (uint32_t t = 0; t < map->triangle_count; t++) {
        for (uint32_t j = map->offsets[t]; j < map->offsets[t + 1]; j++)
            if (visible[map->clusters[j]]) {
                ids[count++] = t;
                break;
            }
    }
    return count;
}
