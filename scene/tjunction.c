/* tjunction.c - border edges that a flat surface continues past a T-junction
 * (see scn_join_tjunctions in weld.h). */
#include "weld.h"

#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

/* Tolerances, relative to the edge length: a T-junction vertex computed by
 * a map compiler lies on the long edge up to rounding. */
#define TJ_LINE_EPS 1e-4f
#define TJ_NORMAL_COS 0.99999f

typedef struct tj_edge {
    uint32_t tri, corner;
    float p0[3], p1[3];
    uint64_t key; /* quantised line: direction and closest point to the origin */
} tj_edge;

static void sub3(const float* a, const float* b, float* o)
{
    o[0] = a[0] - b[0], o[1] = a[1] - b[1], o[2] = a[2] - b[2];
}

static float dot3(const float* a, const float* b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const float* a, const float* b, float* o)
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

static const float* corner_pos(const float* positions, const uint32_t* indices, uint32_t tri, uint32_t c)
{
    return positions + 3 * (size_t)indices[3 * tri + c];
}

/* Unit normal of a triangle; false when degenerate. */
static bool tri_normal(const float* positions, const uint32_t* indices, uint32_t tri, float n[3])
{
    float e1[3], e2[3];
    sub3(corner_pos(positions, indices, tri, 1), corner_pos(positions, indices, tri, 0), e1);
    sub3(corner_pos(positions, indices, tri, 2), corner_pos(positions, indices, tri, 0), e2);
    cross3(e1, e2, n);
    float len = sqrtf(dot3(n, n));
    if (!(len > 0.0f))
        return false;
    n[0] /= len, n[1] /= len, n[2] /= len;
    return true;
}

/* Lines are bucketed by direction (sign-canonical, 1/64 steps) and by the
 * point nearest the origin (5 cm steps). Two collinear edges whose keys fall
 * on either side of a step boundary are not joined: only conservative. */
static uint64_t line_key(const float* p0, const float* p1)
{
    float d[3];
    sub3(p1, p0, d);
    float len = sqrtf(dot3(d, d));
    d[0] /= len, d[1] /= len, d[2] /= len;
    int big = fabsf(d[0]) >= fabsf(d[1]) && fabsf(d[0]) >= fabsf(d[2]) ? 0 : fabsf(d[1]) >= fabsf(d[2]) ? 1 : 2;
    if (d[big] < 0.0f)
        d[0] = -d[0], d[1] = -d[1], d[2] = -d[2];
    float t = dot3(p0, d), o[3] = {p0[0] - t * d[0], p0[1] - t * d[1], p0[2] - t * d[2]};
    uint64_t h = 1469598103934665603ull;
    for (int i = 0; i < 3; i++) {
        int32_t q[2] = {(int32_t)lrintf(d[i] * 64.0f), (int32_t)lrintf(o[i] * 20.0f)};
        for (int j = 0; j < 2; j++)
            h = (h ^ (uint32_t)q[j]) * 1099511628211ull;
    }
    return h;
}

static int compare_key(const void* a, const void* b)
{
    uint64_t x = ((const tj_edge*)a)->key, y = ((const tj_edge*)b)->key;
    return x < y ? -1 : x > y;
}

typedef struct tj_span {
    float t0, t1;
} tj_span;

static int compare_span(const void* a, const void* b)
{
    float x = ((const tj_span*)a)->t0, y = ((const tj_span*)b)->t0;
    return x < y ? -1 : x > y;
}

/* Whether edge b (of another triangle) continues edge a's surface: on a's
 * line, its triangle in a's plane with the same facing, on the other side
 * of the line. Writes b's extent along a (t = 0 at a.p0, 1 at a.p1). */
static bool continues(const float* positions, const uint32_t* indices, const tj_edge* a, const float na[3],
                      const tj_edge* b, tj_span* span)
{
    float d[3], len;
    sub3(a->p1, a->p0, d);
    len = sqrtf(dot3(d, d));
    float eps = TJ_LINE_EPS * len;
    const float* bp[2] = {b->p0, b->p1};
    float t[2];
    for (int i = 0; i < 2; i++) {
        float r[3], c[3];
        sub3(bp[i], a->p0, r);
        cross3(d, r, c);
        if (sqrtf(dot3(c, c)) / len > eps) /* distance from a's line */
            return false;
        t[i] = dot3(r, d) / (len * len);
    }
    float nb[3];
    if (!tri_normal(positions, indices, b->tri, nb) || dot3(na, nb) < TJ_NORMAL_COS)
        return false;
    /* the third corners lie on opposite sides of the line, within the plane */
    float side[3], ra[3], rb[3];
    cross3(na, d, side);
    sub3(corner_pos(positions, indices, a->tri, (a->corner + 2) % 3), a->p0, ra);
    sub3(corner_pos(positions, indices, b->tri, (b->corner + 2) % 3), a->p0, rb);
    if (fabsf(dot3(na, rb)) > eps || dot3(side, ra) * dot3(side, rb) >= 0.0f)
        return false;
    span->t0 = fminf(t[0], t[1]);
    span->t1 = fmaxf(t[0], t[1]);
    return span->t1 > span->t0;
}

size_t scn_join_tjunctions(uint32_t* adjacency, const uint32_t* indices, size_t triangle_count,
                           const float* positions)
{
    size_t border = 0;
    for (size_t i = 0; i < 3 * triangle_count; i++)
        border += adjacency[i] == SCN_EDGE_BORDER;
    tj_edge* edges = malloc(sizeof(tj_edge) * (border ? border : 1));
    tj_span* spans = malloc(sizeof(tj_span) * (border ? border : 1));
    if (!edges || !spans) {
        free(edges);
        free(spans);
        return 0; /* every border stays a silhouette: conservative */
    }
    size_t n = 0;
    for (uint32_t t = 0; t < triangle_count; t++) {
        for (uint32_t c = 0; c < 3; c++) {
            if (adjacency[3 * t + c] != SCN_EDGE_BORDER)
                continue;
            tj_edge* e = &edges[n];
            memcpy(e->p0, corner_pos(positions, indices, t, c), sizeof e->p0);
            memcpy(e->p1, corner_pos(positions, indices, t, (c + 1) % 3), sizeof e->p1);
            float d[3];
            sub3(e->p1, e->p0, d);
            if (!(dot3(d, d) > 0.0f))
                continue;
            e->tri = t, e->corner = c, e->key = line_key(e->p0, e->p1);
            n++;
        }
    }
    qsort(edges, n, sizeof *edges, compare_key);
    size_t joined = 0;
    for (size_t lo = 0, hi; lo < n; lo = hi) {
        for (hi = lo + 1; hi < n && edges[hi].key == edges[lo].key; hi++)
            ;
        for (size_t i = lo; i < hi; i++) {
            float na[3];
            if (!tri_normal(positions, indices, edges[i].tri, na))
                continue;
            size_t m = 0;
            uint32_t partner = SCN_EDGE_BORDER;
            for (size_t j = lo; j < hi; j++) {
                if (edges[j].tri != edges[i].tri &&
                    continues(positions, indices, &edges[i], na, &edges[j], &spans[m])) {
                    partner = edges[j].tri;
                    m++;
                }
            }
            if (m == 0)
                continue;
            /* covered from t = 0 to 1 by the union of the spans */
            qsort(spans, m, sizeof *spans, compare_span);
            float reach = 0.0f;
            const float eps = TJ_LINE_EPS;
            for (size_t k = 0; k < m && spans[k].t0 <= reach + eps; k++)
                reach = fmaxf(reach, spans[k].t1);
            if (reach >= 1.0f - eps) {
                adjacency[3 * edges[i].tri + edges[i].corner] = partner;
                joined++;
            }
        }
    }
    free(edges);
    free(spans);
    return joined;
}
