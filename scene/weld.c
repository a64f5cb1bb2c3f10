/* weld.c - hash-based position welding and edge adjacency. */
#include "weld.h"

#include "log.h"

#include <assert.h>
#include <stdlib.h>
#include <string.h>

static uint32_t _scn_hash32(uint32_t h)
{
    /* murmur3 finaliser: float bit patterns cluster, so mix them well. */
    h ^= h >> 16;
    h *= 0x85ebca6bu;
    h ^= h >> 13;
    h *= 0xc2b2ae35u;
    h ^= h >> 16;
    return h;
}

static size_t _scn_table_size(size_t count)
{
    size_t size = 16;
    while (size < count * 2)
        size *= 2;
    return size;
}

static void _scn_position_key(const float* p, uint32_t key[3])
{
    for (int i = 0; i < 3; i++) {
        float f = p[i] == 0.0f ? 0.0f : p[i]; /* -0.0 == 0.0 folds the sign */
        memcpy(&key[i], &f, sizeof f);
    }
}

size_t scn_weld_positions(uint32_t* remap, const float* positions, size_t vertex_count)
{
    assert(remap && (positions || vertex_count == 0));
    assert(vertex_count < SCN_EDGE_NONMANIFOLD);
    for (size_t v = 0; v < vertex_count; v++)
        remap[v] = (uint32_t)v;
    if (vertex_count == 0)
        return 0;
    size_t size = _scn_table_size(vertex_count);
    uint32_t* table = malloc(size * sizeof *table);
    if (!table) {
        tv_log(TV_LOG_ERROR, "scn_weld_positions: out of memory for %zu vertices", vertex_count);
        return 0;
    }
    memset(table, 0xFF, size * sizeof *table);
    size_t unique = 0;
    for (size_t v = 0; v < vertex_count; v++) {
        uint32_t key[3];
        _scn_position_key(positions + 3 * v, key);
        size_t slot = _scn_hash32(key[0] ^ _scn_hash32(key[1] ^ _scn_hash32(key[2]))) & (size - 1);
        for (;;) {
            uint32_t other = table[slot];
            if (other == UINT32_MAX) {
                table[slot] = (uint32_t)v;
                unique++;
                break;
            }
            uint32_t okey[3];
            _scn_position_key(positions + 3 * (size_t)other, okey);
            if (memcmp(key, okey, sizeof key) == 0) {
                remap[v] = other; /* first inserted == smallest id */
                break;
            }
            slot = (slot + 1) & (size - 1);
        }
    }
    free(table);
    return unique;
}

typedef struct _scn_edge_slot {
    uint32_t lo, hi;     /* welded vertex ids, lo < hi; lo == UINT32_MAX: empty */
    uint32_t tri[2];     /* first two triangles seen on the edge */
    uint32_t count;
} _scn_edge_slot;

static _scn_edge_slot* _scn_edge_find(_scn_edge_slot* table, size_t size, uint32_t lo, uint32_t hi)
{
    size_t slot = _scn_hash32(lo ^ _scn_hash32(hi)) & (size - 1);
    while (table[slot].lo != UINT32_MAX && (table[slot].lo != lo || table[slot].hi != hi))
        slot = (slot + 1) & (size - 1);
    return &table[slot];
}

void scn_build_adjacency(uint32_t* adjacency, const uint32_t* indices, size_t triangle_count,
                         const uint32_t* remap)
{
    assert(adjacency && remap && (indices || triangle_count == 0));
    assert(triangle_count < SCN_EDGE_NONMANIFOLD);
    size_t half_edges = triangle_count * 3;
    for (size_t i = 0; i < half_edges; i++)
        adjacency[i] = SCN_EDGE_BORDER;
    if (triangle_count == 0)
        return;
    size_t size = _scn_table_size(half_edges);
    _scn_edge_slot* table = malloc(size * sizeof *table);
    if (!table) {
        tv_log(TV_LOG_ERROR, "scn_build_adjacency: out of memory for %zu triangles", triangle_count);
        return;
    }
    for (size_t i = 0; i < size; i++)
        table[i].lo = UINT32_MAX;
    for (int pass = 0; pass < 2; pass++) {
        for (size_t t = 0; t < triangle_count; t++) {
            for (int e = 0; e < 3; e++) {
                uint32_t a = remap[indices[3 * t + e]], b = remap[indices[3 * t + (e + 1) % 3]];
                if (a == b)
                    continue;
                uint32_t lo = a < b ? a : b, hi = a < b ? b : a;
                _scn_edge_slot* s = _scn_edge_find(table, size, lo, hi);
                if (pass == 0) {
                    if (s->lo == UINT32_MAX) {
                        s->lo = lo;
                        s->hi = hi;
                        s->count = 0;
                    }
                    if (s->count < 2)
                        s->tri[s->count] = (uint32_t)t;
                    s->count++;
                } else if (s->count >= 3) {
                    adjacency[3 * t + e] = SCN_EDGE_NONMANIFOLD;
                } else if (s->count == 2 && s->tri[0] != s->tri[1]) {
                    /* A triangle meeting itself is degenerate (two corners
                     * weld together): its edge stays a border. */
                    adjacency[3 * t + e] = s->tri[0] == t ? s->tri[1] : s->tri[0];
                }
            }
        }
    }
    free(table);
}
