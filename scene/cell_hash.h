/* cell_hash.h - hashed grid cells for the scene passes that look up nearby
 * edges or faces (cracks.c, rest.c): a sorted array of (cell key, item). */
#ifndef TRIMVR_SCENE_CELL_HASH_H
#define TRIMVR_SCENE_CELL_HASH_H

#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

typedef struct scn_cell {
    uint64_t key;
    uint32_t item;
} scn_cell;

/* FNV-1a over the three cell coordinates. */
static inline uint64_t scn_cell_key(const int32_t c[3])
{
    uint64_t h = 1469598103934665603ull;
    for (int i = 0; i < 3; i++)
        h = (h ^ (uint32_t)c[i]) * 1099511628211ull;
    return h;
}

static inline int scn_cell_compare(const void* a, const void* b)
{
    uint64_t x = ((const scn_cell*)a)->key, y = ((const scn_cell*)b)->key;
    return (x > y) - (x < y);
}

/* The first entry of cell c in cells[0..n) sorted by key, or NULL; the
 * cell's entries follow it while their key is the same. */
static inline const scn_cell* scn_cell_first(const scn_cell* cells, size_t n, const int32_t c[3])
{
    scn_cell probe = {scn_cell_key(c), 0};
    const scn_cell* hit = bsearch(&probe, cells, n, sizeof *cells, scn_cell_compare);
    while (hit && hit > cells && hit[-1].key == probe.key)
        hit--;
    return hit;
}

#endif
