/* sheets.c - non-manifold edges that are two flat sheets each continuing
 * across the edge (see scn_pair_sheets in weld.h). */
#include "weld.h"

#include "weld_geom.h"

#include <stdlib.h>

typedef struct sheet_edge {
    uint32_t lo, hi; /* welded ends, lo < hi */
    uint32_t tri, corner;
} sheet_edge;

static int cmp_edge(const void* a, const void* b)
{
    const sheet_edge *x = a, *y = b;
    if (x->lo != y->lo)
        return x->lo < y->lo ? -1 : 1;
    if (x->hi != y->hi)
        return x->hi < y->hi ? -1 : 1;
    return x->tri < y->tri ? -1 : x->tri > y->tri;
}

/* Whether the two triangles face the same way in one plane: they share the
 * edge, so equal normals put them in the same plane. */
static bool same_facing(const float* positions, const uint32_t* indices, uint32_t a, uint32_t b)
{
    vec3 na, nb;
    return scn_tri_unit_normal(positions, indices, a, na) && scn_tri_unit_normal(positions, indices, b, nb) &&
           glm_vec3_dot(na, nb) > SCN_WELD_NORMAL_COS;
}

/* One edge's four half-edges e[0..4): pairs each triangle that walks the
 * edge lo -> hi with a same-facing one that walks it hi -> lo (the other side
 * of the edge in their common plane). */
static bool pair_four(uint32_t* adjacency, const uint32_t* indices, const uint32_t* remap, const float* positions,
                      const sheet_edge* e)
{
    const sheet_edge *ab[2], *ba[2];
    int nab = 0, nba = 0;
    for (int i = 0; i < 4; i++) {
        bool forward = remap[indices[3 * (size_t)e[i].tri + e[i].corner]] == e[i].lo;
        if (forward && nab < 2)
            ab[nab++] = &e[i];
        else if (!forward && nba < 2)
            ba[nba++] = &e[i];
    }
    if (nab != 2 || nba != 2)
        return false;
    for (int swap = 0; swap < 2; swap++) {
        const sheet_edge *a0 = ab[0], *a1 = ab[1], *b0 = ba[swap], *b1 = ba[1 - swap];
        if (same_facing(positions, indices, a0->tri, b0->tri) && same_facing(positions, indices, a1->tri, b1->tri)) {
            adjacency[3 * (size_t)a0->tri + a0->corner] = b0->tri;
            adjacency[3 * (size_t)b0->tri + b0->corner] = a0->tri;
            adjacency[3 * (size_t)a1->tri + a1->corner] = b1->tri;
            adjacency[3 * (size_t)b1->tri + b1->corner] = a1->tri;
            return true;
        }
    }
    return false;
}

size_t scn_pair_sheets(uint32_t* adjacency, const uint32_t* indices, size_t triangle_count, const uint32_t* remap,
                       const float* positions)
{
    size_t n = 0, paired = 0;
    for (size_t i = 0; i < 3 * triangle_count; i++)
        n += adjacency[i] == SCN_EDGE_NONMANIFOLD;
    sheet_edge* e = malloc((n ? n : 1) * sizeof *e);
    if (!e)
        return 0;
    n = 0;
    for (size_t t = 0; t < triangle_count; t++) {
        for (uint32_t c = 0; c < 3; c++) {
            if (adjacency[3 * t + c] != SCN_EDGE_NONMANIFOLD)
                continue;
            uint32_t a = remap[indices[3 * t + c]], b = remap[indices[3 * t + (c + 1) % 3]];
            e[n++] = (sheet_edge){.lo = a < b ? a : b, .hi = a < b ? b : a, .tri = (uint32_t)t, .corner = c};
        }
    }
    qsort(e, n, sizeof *e, cmp_edge);
    for (size_t i = 0, j; i < n; i = j) {
        for (j = i + 1; j < n && e[j].lo == e[i].lo && e[j].hi == e[i].hi;)
            j++;
        if (j - i == 4 && pair_four(adjacency, indices, remap, positions, e + i))
            paired++;
    }
    free(e);
    return paired;
}
