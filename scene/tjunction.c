/* tjunction.c - border edges that a flat surface continues past a T-junction
 * (see scn_join_tjunctions in weld.h). */
#include "weld.h"

#include "weld_geom.h"

#include <cglm/cglm.h>
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

typedef struct tj_edge {
    uint32_t tri, corner;
    vec3 p0, p1;
    uint64_t key; /* quantised line: direction and closest point to the origin */
} tj_edge;

/* Lines are bucketed by direction (sign-canonical, 1/64 steps) and by the
 * point nearest the origin (5 cm steps). Two collinear edges whose keys fall
 * on either side of a step boundary are not joined: only conservative. */
static uint64_t line_key(vec3 p0, vec3 p1)
{
    vec3 d, o;
    glm_vec3_sub(p1, p0, d);
    glm_vec3_normalize(d);
    int big = fabsf(d[0]) >= fabsf(d[1]) && fabsf(d[0]) >= fabsf(d[2]) ? 0 : fabsf(d[1]) >= fabsf(d[2]) ? 1 : 2;
    if (d[big] < 0.0f)
        glm_vec3_negate(d);
    glm_vec3_scale(d, -glm_vec3_dot(p0, d), o);
    glm_vec3_add(p0, o, o);
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
static bool continues(const float* positions, const uint32_t* indices, tj_edge* a, vec3 na, tj_edge* b,
                      tj_span* span)
{
    vec3 d;
    glm_vec3_sub(a->p1, a->p0, d);
    float len = glm_vec3_norm(d);
    float eps = SCN_WELD_LINE_EPS * len;
    float* bp[2] = {b->p0, b->p1};
    float t[2];
    for (int i = 0; i < 2; i++) {
        vec3 r, c;
        glm_vec3_sub(bp[i], a->p0, r);
        glm_vec3_cross(d, r, c);
        if (glm_vec3_norm(c) / len > eps) /* distance from a's line */
            return false;
        t[i] = glm_vec3_dot(r, d) / (len * len);
    }
    vec3 nb;
    if (!scn_tri_unit_normal(positions, indices, b->tri, nb) || glm_vec3_dot(na, nb) < SCN_WELD_NORMAL_COS)
        return false;
    /* the third corners lie on opposite sides of the line, within the plane */
    vec3 side, ra, rb;
    glm_vec3_cross(na, d, side);
    glm_vec3_copy((float*)scn_tri_corner(positions, indices, a->tri, (a->corner + 2) % 3), ra);
    glm_vec3_copy((float*)scn_tri_corner(positions, indices, b->tri, (b->corner + 2) % 3), rb);
    glm_vec3_sub(ra, a->p0, ra);
    glm_vec3_sub(rb, a->p0, rb);
    if (fabsf(glm_vec3_dot(na, rb)) > eps || glm_vec3_dot(side, ra) * glm_vec3_dot(side, rb) >= 0.0f)
        return false;
    span->t0 = fminf(t[0], t[1]);
    span->t1 = fmaxf(t[0], t[1]);
    return span->t1 > span->t0;
}

/* An edge whose closure the glued-edge pass may read past: a border, or a
 * border resting on a face (SCN_EDGE_REST | F, F a triangle). Cracks and
 * non-manifold edges are not. */
static bool open_edge(uint32_t a, size_t triangle_count)
{
    return a == SCN_EDGE_BORDER || (a >= SCN_EDGE_REST && (a & ~SCN_EDGE_REST) < triangle_count);
}

/* The edges of positive length that border a triangle (`open`: also rest
 * edges and non-manifold ones) into `edges`, sorted by line; their count. */
static size_t line_edges(tj_edge* edges, const uint32_t* adjacency, const uint32_t* indices, size_t triangle_count,
                         const float* positions, bool open)
{
    size_t n = 0;
    for (uint32_t t = 0; t < triangle_count; t++) {
        for (uint32_t c = 0; c < 3; c++) {
            uint32_t v = adjacency[3 * (size_t)t + c];
            if (open ? !open_edge(v, triangle_count) && v != SCN_EDGE_NONMANIFOLD : v != SCN_EDGE_BORDER)
                continue;
            tj_edge* e = &edges[n];
            glm_vec3_copy((float*)scn_tri_corner(positions, indices, t, c), e->p0);
            glm_vec3_copy((float*)scn_tri_corner(positions, indices, t, (c + 1) % 3), e->p1);
            if (!(glm_vec3_distance2(e->p0, e->p1) > 0.0f))
                continue;
            e->tri = t, e->corner = c, e->key = line_key(e->p0, e->p1);
            n++;
        }
    }
    qsort(edges, n, sizeof *edges, compare_key);
    return n;
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
    size_t n = line_edges(edges, adjacency, indices, triangle_count, positions, false);
    size_t joined = 0;
    for (size_t lo = 0, hi; lo < n; lo = hi) {
        for (hi = lo + 1; hi < n && edges[hi].key == edges[lo].key; hi++)
            ;
        for (size_t i = lo; i < hi; i++) {
            vec3 na;
            if (!scn_tri_unit_normal(positions, indices, edges[i].tri, na))
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
            const float eps = SCN_WELD_LINE_EPS;
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


size_t scn_cover_borders(uint32_t* cover, const uint32_t* adjacency, const uint32_t* indices, size_t triangle_count,
                         const float* positions)
{
    for (size_t i = 0; i < 3 * triangle_count; i++)
        cover[i] = SCN_EDGE_BORDER;
    size_t border = 0;
    for (size_t i = 0; i < 3 * triangle_count; i++)
        border += open_edge(adjacency[i], triangle_count) || adjacency[i] == SCN_EDGE_NONMANIFOLD;
    tj_edge* edges = malloc(sizeof(tj_edge) * (border ? border : 1));
    tj_span* spans = malloc(sizeof(tj_span) * (border ? border : 1));
    if (!edges || !spans) {
        free(edges);
        free(spans);
        return 0; /* nothing covered: every border stays an opening */
    }
    size_t n = line_edges(edges, adjacency, indices, triangle_count, positions, true);
    size_t covered = 0;
    for (size_t lo = 0, hi; lo < n; lo = hi) {
        for (hi = lo + 1; hi < n && edges[hi].key == edges[lo].key; hi++)
            ;
        for (size_t i = lo; i < hi; i++) {
            tj_edge* a = &edges[i];
            if (adjacency[3 * (size_t)a->tri + a->corner] == SCN_EDGE_NONMANIFOLD)
                continue; /* covers others, never an opening itself */
            vec3 d;
            glm_vec3_sub(a->p1, a->p0, d);
            float len = glm_vec3_norm(d), eps = SCN_WELD_LINE_EPS * len;
            size_t m = 0;
            uint32_t partner = SCN_EDGE_BORDER;
            for (size_t j = lo; j < hi; j++) {
                tj_edge* b = &edges[j];
                vec3 db;
                glm_vec3_sub(b->p1, b->p0, db);
                if (b->tri == a->tri || glm_vec3_dot(d, db) >= 0.0f) /* walked the other way: consistent winding */
                    continue;
                float* bp[2] = {b->p0, b->p1};
                float t[2];
                bool on = true;
                for (int k = 0; k < 2 && on; k++) {
                    vec3 r, x;
                    glm_vec3_sub(bp[k], a->p0, r);
                    glm_vec3_cross(d, r, x);
                    on = glm_vec3_norm(x) / len <= eps; /* on a's line */
                    t[k] = glm_vec3_dot(r, d) / (len * len);
                }
                if (!on || !(fmaxf(t[0], t[1]) > fminf(t[0], t[1])))
                    continue;
                spans[m].t0 = fminf(t[0], t[1]), spans[m].t1 = fmaxf(t[0], t[1]);
                partner = b->tri;
                m++;
            }
            if (m == 0)
                continue;
            qsort(spans, m, sizeof *spans, compare_span);
            float reach = 0.0f;
            for (size_t k = 0; k < m && spans[k].t0 <= reach + SCN_WELD_LINE_EPS; k++)
                reach = fmaxf(reach, spans[k].t1);
            if (reach >= 1.0f - SCN_WELD_LINE_EPS) {
                cover[3 * (size_t)a->tri + a->corner] = partner;
                covered++;
            }
        }
    }
    free(edges);
    free(spans);
    return covered;
}
