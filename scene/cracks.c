/* cracks.c - border edges that run along another triangle's border edge
 * across a narrow gap (see scn_mark_cracks in weld.h). */
#include "weld.h"

#include "cell_hash.h"

#include <assert.h>
#include <cglm/cglm.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Two edges count as running alongside when their directions are within
 * about 8 degrees. */
#define CRACK_PARALLEL_COS 0.99f
/* Edges closer than this fraction of max_gap along their whole overlap are
 * coincident, not cracked: a T-junction between perpendicular faces (the
 * city's window recesses) leaves no opening. */
#define CRACK_MIN_GAP 0.05f

typedef struct crack_edge {
    vec3 p0, p1;
    uint32_t tri, corner;
} crack_edge;

/* Points along an edge no farther apart than half a cell, so that every
 * cell the segment passes through holds one of them. */
static uint32_t sample_count(crack_edge* e, float cell)
{
    float len = glm_vec3_distance(e->p0, e->p1);
    return 1u + (uint32_t)ceilf(len / (0.5f * cell));
}

static void sample_cell(crack_edge* e, uint32_t i, uint32_t n, float cell, int32_t c[3])
{
    vec3 p;
    glm_vec3_lerp(e->p0, e->p1, n > 1 ? (float)i / (float)(n - 1) : 0.0f, p);
    for (int k = 0; k < 3; k++)
        c[k] = (int32_t)floorf(p[k] / cell);
}

static float point_segment_distance(vec3 p, vec3 a, vec3 b)
{
    vec3 ab, ap, q;
    glm_vec3_sub(b, a, ab);
    glm_vec3_sub(p, a, ap);
    float len2 = glm_vec3_norm2(ab);
    float t = len2 > 0.0f ? glm_clamp(glm_vec3_dot(ap, ab) / len2, 0.0f, 1.0f) : 0.0f;
    glm_vec3_scale(ab, t, q);
    glm_vec3_add(a, q, q);
    return glm_vec3_distance(p, q);
}

/* Whether f runs along e within max_gap: nearly parallel, overlapping along
 * e's direction, and both ends of the overlap within max_gap of f. */
static bool alongside(crack_edge* e, crack_edge* f, float max_gap)
{
    vec3 d, df;
    glm_vec3_sub(e->p1, e->p0, d);
    glm_vec3_sub(f->p1, f->p0, df);
    float len = glm_vec3_norm(d), lenf = glm_vec3_norm(df);
    if (!(len > 0.0f) || !(lenf > 0.0f) || fabsf(glm_vec3_dot(d, df)) < CRACK_PARALLEL_COS * len * lenf)
        return false;
    glm_vec3_divs(d, len, d);
    vec3 r0, r1;
    glm_vec3_sub(f->p0, e->p0, r0);
    glm_vec3_sub(f->p1, e->p0, r1);
    float a = glm_vec3_dot(r0, d), b = glm_vec3_dot(r1, d);
    float lo = fmaxf(0.0f, fminf(a, b)), hi = fminf(len, fmaxf(a, b));
    if (!(hi > lo))
        return false;
    vec3 q0, q1;
    glm_vec3_scale(d, lo, q0);
    glm_vec3_add(e->p0, q0, q0);
    glm_vec3_scale(d, hi, q1);
    glm_vec3_add(e->p0, q1, q1);
    float g0 = point_segment_distance(q0, f->p0, f->p1), g1 = point_segment_distance(q1, f->p0, f->p1);
    return g0 <= max_gap && g1 <= max_gap && fmaxf(g0, g1) > CRACK_MIN_GAP * max_gap;
}

/* Whether a border edge of another triangle runs along edges[i]: the edges
 * in the cells around its samples, each tested once (tested[] holds the
 * last edge each was tested against). */
static bool has_partner(crack_edge* edges, uint32_t i, const scn_cell* cells, size_t m, uint32_t* tested,
                        float cell, float max_gap)
{
    crack_edge* e = &edges[i];
    uint32_t s = sample_count(e, cell);
    int32_t prev[3] = {INT32_MIN, INT32_MIN, INT32_MIN};
    for (uint32_t j = 0; j < s; j++) {
        int32_t c[3];
        sample_cell(e, j, s, cell, c);
        if (c[0] == prev[0] && c[1] == prev[1] && c[2] == prev[2])
            continue;
        memcpy(prev, c, sizeof prev);
        for (int k = 0; k < 27; k++) {
            int32_t q[3] = {c[0] + k % 3 - 1, c[1] + k / 3 % 3 - 1, c[2] + k / 9 - 1};
            const scn_cell* hit = scn_cell_first(cells, m, q);
            for (uint64_t key = hit ? hit->key : 0; hit && hit < cells + m && hit->key == key; hit++) {
                if (tested[hit->item] == i)
                    continue;
                tested[hit->item] = i;
                if (edges[hit->item].tri != e->tri && alongside(e, &edges[hit->item], max_gap))
                    return true;
            }
        }
    }
    return false;
}

size_t scn_mark_cracks(uint8_t* crack, const uint32_t* adjacency, const uint32_t* indices, size_t triangle_count,
                       const float* positions, float max_gap)
{
    assert(crack && adjacency && indices && positions && max_gap > 0.0f);
    memset(crack, 0, 3 * triangle_count);
    size_t border = 0;
    for (size_t i = 0; i < 3 * triangle_count; i++)
        border += adjacency[i] == SCN_EDGE_BORDER;
    crack_edge* edges = malloc(sizeof(crack_edge) * (border ? border : 1));
    if (!edges)
        return 0;
    /* samples half a cell apart: an edge within max_gap of one lies in that
     * sample's cell or one of its 26 neighbours while cell >= 4/3 max_gap.
     * Larger cells mean fewer samples and lookups but more candidates each;
     * 32 gaps was the fastest of 4-32 on builtin:city and Sponza (0.2 s). */
    const float cell = 32.0f * max_gap;
    size_t n = 0, samples = 0;
    for (uint32_t t = 0; t < triangle_count; t++) {
        for (uint32_t c = 0; c < 3; c++) {
            if (adjacency[3 * t + c] != SCN_EDGE_BORDER)
                continue;
            crack_edge* e = &edges[n];
            memcpy(e->p0, positions + 3 * (size_t)indices[3 * t + c], sizeof(vec3));
            memcpy(e->p1, positions + 3 * (size_t)indices[3 * t + (c + 1) % 3], sizeof(vec3));
            e->tri = t, e->corner = c;
            samples += sample_count(e, cell);
            n++;
        }
    }
    scn_cell* cells = malloc(sizeof(scn_cell) * (samples ? samples : 1));
    if (!cells) {
        free(edges);
        return 0;
    }
    size_t m = 0;
    for (uint32_t i = 0; i < n; i++) {
        uint32_t s = sample_count(&edges[i], cell);
        for (uint32_t j = 0; j < s; j++) {
            int32_t c[3];
            sample_cell(&edges[i], j, s, cell, c);
            cells[m++] = (scn_cell){scn_cell_key(c), i};
        }
    }
    qsort(cells, m, sizeof *cells, scn_cell_compare);
    uint32_t* tested = malloc(sizeof(uint32_t) * (n ? n : 1)); /* the last edge each was tested against */
    if (!tested) {
        free(cells);
        free(edges);
        return 0;
    }
    memset(tested, 0xFF, sizeof(uint32_t) * n);
    size_t marked = 0;
    for (uint32_t i = 0; i < n; i++) {
        if (has_partner(edges, i, cells, m, tested, cell, max_gap)) {
            crack[3 * edges[i].tri + edges[i].corner] = 1;
            marked++;
        }
    }
    free(tested);
    free(cells);
    free(edges);
    return marked;
}
