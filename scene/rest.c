/* rest.c - border edges that rest on another face (see scn_join_rest_edges
 * in weld.h; the argument is in docs/trim-regions.md, "Silhouettes"), and
 * manifold edges of parts glued on a closed solid (scn_join_glued_edges;
 * docs/pvs-edge-cases.md, "Parts glued on a closed solid"). */
#include "weld.h"

#include "cell_hash.h"
#include "weld_geom.h"

#include <assert.h>
#include <cglm/cglm.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* The two faces must meet at an angle of at least about 0.6 degrees, with
 * the face on the edge's front side: flatter continuations are the
 * T-junction pass's. */
#define REST_MIN_SIN 0.01f
/* A triangle whose box spans more grid cells than this (a sky or a huge
 * floor) is tested against every edge instead of being put in the grid. */
#define REST_MAX_CELLS 4096

typedef struct rest_span {
    float t0, t1;
    uint32_t face;
    vec3 normal;
} rest_span;

typedef struct rest_grid {
    float cell;
    scn_cell* cells;
    size_t cell_count;
    uint32_t* big; /* triangles kept out of the grid */
    size_t big_count;
} rest_grid;

static int compare_span(const void* a, const void* b)
{
    float x = ((const rest_span*)a)->t0, y = ((const rest_span*)b)->t0;
    return (x > y) - (x < y);
}

/* The grid cells of a triangle's box widened by `pad`; false (nothing
 * written) when there are more than REST_MAX_CELLS. */
static bool cell_range(const float* positions, const uint32_t* indices, uint32_t tri, float cell, float pad,
                       int32_t lo[3], int32_t hi[3])
{
    size_t count = 1;
    for (int k = 0; k < 3; k++) {
        float mn = INFINITY, mx = -INFINITY;
        for (uint32_t c = 0; c < 3; c++) {
            mn = fminf(mn, scn_tri_corner(positions, indices, tri, c)[k]);
            mx = fmaxf(mx, scn_tri_corner(positions, indices, tri, c)[k]);
        }
        lo[k] = (int32_t)floorf((mn - pad) / cell);
        hi[k] = (int32_t)floorf((mx + pad) / cell);
        count *= (size_t)(hi[k] - lo[k] + 1);
        if (count > REST_MAX_CELLS)
            return false;
    }
    return true;
}

/* Puts every face that may carry an edge (solid[] set) into the cells its
 * box meets. The pad covers SCN_WELD_LINE_EPS of the longest border edge. */
static bool grid_build(rest_grid* g, const float* positions, const uint32_t* indices, size_t triangle_count,
                       const uint8_t* solid, float cell, float pad)
{
    memset(g, 0, sizeof *g);
    g->cell = cell;
    size_t total = 0;
    for (uint32_t t = 0; t < triangle_count; t++) {
        int32_t lo[3], hi[3];
        if (!solid || solid[t]) {
            if (cell_range(positions, indices, t, cell, pad, lo, hi))
                total += (size_t)(hi[0] - lo[0] + 1) * (size_t)(hi[1] - lo[1] + 1) * (size_t)(hi[2] - lo[2] + 1);
            else
                g->big_count++;
        }
    }
    g->cells = malloc(sizeof(scn_cell) * (total ? total : 1));
    g->big = malloc(sizeof(uint32_t) * (g->big_count ? g->big_count : 1));
    if (!g->cells || !g->big)
        return false;
    g->big_count = 0;
    for (uint32_t t = 0; t < triangle_count; t++) {
        int32_t lo[3], hi[3], c[3];
        if (solid && !solid[t])
            continue;
        if (!cell_range(positions, indices, t, cell, pad, lo, hi)) {
            g->big[g->big_count++] = t;
            continue;
        }
        for (c[0] = lo[0]; c[0] <= hi[0]; c[0]++)
            for (c[1] = lo[1]; c[1] <= hi[1]; c[1]++)
                for (c[2] = lo[2]; c[2] <= hi[2]; c[2]++)
                    g->cells[g->cell_count++] = (scn_cell){scn_cell_key(c), t};
    }
    qsort(g->cells, g->cell_count, sizeof *g->cells, scn_cell_compare);
    return true;
}

/* The part of edge (p0, p1) of triangle `tri` near which face f covers
 * the side s = d x n_f (d = p1 - p0) in f's plane: the t in [0, 1] (t = 0
 * at p0) where p0 + t d lies in f and, where it lies on an edge of f, s
 * points into f. Writes it into span; false when empty or when f does not
 * qualify. */
static bool rest_span_of(const float* positions, const uint32_t* indices, const vec4 plane_f, const vec3 n_tri,
                         const vec3 p0, const vec3 p1, uint32_t f, rest_span* span)
{
    vec3 d, s;
    float* nf = span->normal;
    if (plane_f[3] == 0.0f)
        return false; /* degenerate */
    glm_vec3_copy((float*)plane_f, nf);
    glm_vec3_sub((float*)p1, (float*)p0, d);
    float len = glm_vec3_norm(d);
    float eps = SCN_WELD_LINE_EPS * len;
    const float* q[3] = {scn_tri_corner(positions, indices, f, 0), scn_tri_corner(positions, indices, f, 1),
                         scn_tri_corner(positions, indices, f, 2)};
    vec3 r0, r1;
    glm_vec3_sub((float*)p0, (float*)q[0], r0);
    glm_vec3_sub((float*)p1, (float*)q[0], r1);
    if (fabsf(glm_vec3_dot(nf, r0)) > eps || fabsf(glm_vec3_dot(nf, r1)) > eps)
        return false; /* the edge is not in f's plane */
    glm_vec3_cross(d, nf, s);
    glm_vec3_divs(s, len, s);
    /* Only s on tri's front side (a concave crease: a wall standing on a
     * floor that runs on in front of it). Behind it (a convex edge: a slab's
     * top and the face hanging from it) f would be as sound as a manifold
     * edge, but there the pixel-centre rules lose what is seen in part of a
     * pixel past the edge (docs/trim-regions.md, "Silhouettes"). */
    if (glm_vec3_dot(s, (float*)n_tri) < REST_MIN_SIN)
        return false;
    float lo = 0.0f, hi = 1.0f;
    for (int k = 0; k < 3; k++) {
        vec3 e, m, a, b;
        glm_vec3_sub((float*)q[(k + 1) % 3], (float*)q[k], e);
        glm_vec3_cross(nf, e, m); /* points into f */
        float ml = glm_vec3_norm(m);
        if (!(ml > 0.0f))
            return false;
        glm_vec3_divs(m, ml, m);
        glm_vec3_sub((float*)p0, (float*)q[k], a);
        glm_vec3_sub((float*)p1, (float*)q[k], b);
        float g0 = glm_vec3_dot(m, a), g1 = glm_vec3_dot(m, b);
        if (fabsf(g0) <= eps && fabsf(g1) <= eps) {
            /* the edge runs along this edge of f: f must lie on side s */
            if (glm_vec3_dot(m, s) <= 0.0f)
                return false;
            continue;
        }
        /* g(t) = g0 + t (g1 - g0) >= -eps */
        if (g1 != g0) {
            float tc = (-eps - g0) / (g1 - g0);
            if (g1 > g0)
                lo = fmaxf(lo, tc);
            else
                hi = fminf(hi, tc);
        } else if (g0 < -eps) {
            return false;
        }
    }
    if (!(hi > lo))
        return false;
    span->t0 = lo, span->t1 = hi, span->face = f;
    return true;
}

/* The face whose plane's spans cover [0, 1] end to end (the plane of the
 * longest span: faces of other planes are dropped), or SCN_EDGE_BORDER.
 * Reorders the spans. */
static uint32_t covering_face(rest_span* spans, size_t m)
{
    size_t ref = 0;
    for (size_t k = 1; k < m; k++)
        if (spans[k].t1 - spans[k].t0 > spans[ref].t1 - spans[ref].t0)
            ref = k;
    rest_span r = spans[ref];
    size_t n = 0;
    for (size_t k = 0; k < m; k++)
        if (glm_vec3_dot(spans[k].normal, r.normal) >= SCN_WELD_NORMAL_COS)
            spans[n++] = spans[k];
    qsort(spans, n, sizeof *spans, compare_span);
    float reach = 0.0f;
    for (size_t k = 0; k < n && spans[k].t0 <= reach + SCN_WELD_LINE_EPS; k++)
        reach = fmaxf(reach, spans[k].t1);
    return reach >= 1.0f - SCN_WELD_LINE_EPS ? r.face : SCN_EDGE_BORDER;
}

typedef struct rest_scratch {
    vec4* normals;    /* per triangle: unit normal, w = 1 (all 0 when degenerate) */
    uint32_t* tested; /* per triangle: the last edge it was tested against, +1 */
    rest_span* spans; /* the spans on the edge's front side */
    size_t m, cap;
} rest_scratch;

/* Allocates w's per-triangle stamps and unit normals (w = 0 where
 * degenerate) and its first spans; a failed allocation leaves a NULL. */
static void scratch_init(rest_scratch* w, const float* positions, const uint32_t* indices, size_t triangle_count)
{
    w->tested = calloc(triangle_count, sizeof(uint32_t));
    w->normals = calloc(triangle_count, sizeof(vec4));
    for (uint32_t t = 0; w->normals && t < triangle_count; t++)
        if (scn_tri_unit_normal(positions, indices, t, w->normals[t]))
            w->normals[t][3] = 1.0f;
    w->spans = malloc(sizeof(rest_span) * w->cap);
}

static bool consider(rest_scratch* w, const float* positions, const uint32_t* indices, uint32_t tri,
                     const vec3 n_tri, const vec3 p0, const vec3 p1, uint32_t f, uint32_t stamp)
{
    if (f == tri || w->tested[f] == stamp)
        return true;
    w->tested[f] = stamp;
    rest_span span;
    if (!rest_span_of(positions, indices, w->normals[f], n_tri, p0, p1, f, &span))
        return true;
    if (w->m == w->cap) {
        rest_span* s = realloc(w->spans, sizeof(rest_span) * 2 * w->cap);
        if (!s)
            return false;
        w->spans = s;
        w->cap *= 2;
    }
    w->spans[w->m++] = span;
    return true;
}

/* Considers the faces in grid cell q for edge (p0, p1) of tri. */
static bool scan_cell(rest_scratch* w, const rest_grid* g, const float* positions, const uint32_t* indices,
                      uint32_t tri, const vec3 n_tri, const vec3 p0, const vec3 p1, const int32_t q[3],
                      uint32_t stamp)
{
    const scn_cell* hit = scn_cell_first(g->cells, g->cell_count, q);
    bool ok = true;
    for (uint64_t key = hit ? hit->key : 0; ok && hit && hit < g->cells + g->cell_count && hit->key == key; hit++)
        ok = consider(w, positions, indices, tri, n_tri, p0, p1, hit->item, stamp);
    return ok;
}

/* Collects into w->spans the faces near edge (p0, p1) of tri: the big faces,
 * then the grid cells along the edge, sampled half a cell apart so that the
 * stretch between two samples lies in the box of their cells. */
static bool scan_edge(rest_scratch* w, const rest_grid* g, const float* positions, const uint32_t* indices,
                      uint32_t tri, const vec3 n_tri, const vec3 p0, const vec3 p1, uint32_t stamp)
{
    bool ok = true;
    w->m = 0;
    for (size_t b = 0; ok && b < g->big_count; b++)
        ok = consider(w, positions, indices, tri, n_tri, p0, p1, g->big[b], stamp);
    uint32_t samples = 2u + (uint32_t)(glm_vec3_distance((float*)p0, (float*)p1) / (0.5f * g->cell));
    int32_t prev[3];
    for (uint32_t j = 0; ok && j < samples; j++) {
        vec3 p;
        glm_vec3_lerp((float*)p0, (float*)p1, (float)j / (float)(samples - 1), p);
        int32_t cur[3], lo[3], hi[3], q[3];
        for (int k = 0; k < 3; k++) {
            cur[k] = (int32_t)floorf(p[k] / g->cell);
            lo[k] = j ? (cur[k] < prev[k] ? cur[k] : prev[k]) : cur[k];
            hi[k] = j ? (cur[k] > prev[k] ? cur[k] : prev[k]) : cur[k];
            prev[k] = cur[k];
        }
        for (q[0] = lo[0]; q[0] <= hi[0]; q[0]++)
            for (q[1] = lo[1]; q[1] <= hi[1]; q[1]++)
                for (q[2] = lo[2]; ok && q[2] <= hi[2]; q[2]++)
                    ok = scan_cell(w, g, positions, indices, tri, n_tri, p0, p1, q, stamp);
    }
    return ok;
}

size_t scn_join_rest_edges(uint32_t* adjacency, const uint32_t* indices, size_t triangle_count,
                           const float* positions, const uint8_t* solid)
{
    assert(adjacency && indices && positions && triangle_count < SCN_EDGE_REST);
    /* cell size: the mean border edge, so that an edge meets a few cells */
    double total_len = 0.0, max_len = 0.0;
    size_t border = 0;
    for (size_t i = 0; i < 3 * triangle_count; i++) {
        if (adjacency[i] != SCN_EDGE_BORDER)
            continue;
        size_t t = i / 3, c = i % 3;
        double l = glm_vec3_distance((float*)scn_tri_corner(positions, indices, (uint32_t)t, (uint32_t)c),
                                     (float*)scn_tri_corner(positions, indices, (uint32_t)t, (uint32_t)((c + 1) % 3)));
        total_len += l, max_len = fmax(max_len, l), border++;
    }
    if (border == 0 || !(total_len > 0.0))
        return 0;
    rest_grid g;
    rest_scratch w = {.cap = 16};
    scratch_init(&w, positions, indices, triangle_count);
    float cell = (float)fmax(total_len / (double)border, 1e-3);
    /* a point of an edge lies within about 1.5 SCN_WELD_LINE_EPS of its length from
     * a face that covers it: pad the faces' boxes by twice that */
    bool ok = grid_build(&g, positions, indices, triangle_count, solid, cell, (float)(2.0 * SCN_WELD_LINE_EPS * max_len)) &&
              w.tested && w.normals && w.spans;
    size_t joined = 0;
    uint32_t stamp = 0;
    for (uint32_t t = 0; ok && t < triangle_count; t++) {
        if (w.normals[t][3] == 0.0f)
            continue;
        float* n_tri = w.normals[t];
        for (uint32_t c = 0; ok && c < 3; c++) {
            if (adjacency[3 * (size_t)t + c] != SCN_EDGE_BORDER)
                continue;
            vec3 p0, p1;
            memcpy(p0, scn_tri_corner(positions, indices, t, c), sizeof p0);
            memcpy(p1, scn_tri_corner(positions, indices, t, (c + 1) % 3), sizeof p1);
            float len = glm_vec3_distance(p0, p1);
            if (!(len > 0.0f))
                continue;
            ok = scan_edge(&w, &g, positions, indices, t, n_tri, p0, p1, ++stamp);
            /* the faces (facing one way) must cover the edge */
            uint32_t f = ok && w.m > 0 ? covering_face(w.spans, w.m) : SCN_EDGE_BORDER;
            if (f != SCN_EDGE_BORDER) {
                adjacency[3 * (size_t)t + c] = SCN_EDGE_REST | f;
                joined++;
            }
        }
    }
    free(g.cells);
    free(g.big);
    free(w.tested);
    free(w.normals);
    free(w.spans);
    return joined; /* those joined before a failed allocation are sound */
}

/* Per triangle, whether its connected component (triangles joined by
 * adjacency entries that name a triangle, or by `cover`: borders closed up
 * to a T-junction, scn_cover_borders) has no other edge: a closed surface.
 * Union-find with path halving. NULL when out of memory. */
static uint8_t* closed_components(const uint32_t* adjacency, const uint32_t* cover, size_t triangle_count)
{
    uint32_t* root = malloc(sizeof(uint32_t) * (triangle_count ? triangle_count : 1));
    uint8_t* closed = malloc(triangle_count ? triangle_count : 1);
    if (!root || !closed) {
        free(root);
        free(closed);
        return NULL;
    }
    for (uint32_t t = 0; t < triangle_count; t++)
        root[t] = t, closed[t] = 1;
    for (size_t i = 0; i < 3 * triangle_count; i++) {
        uint32_t a = (uint32_t)(i / 3), b = adjacency[i] < SCN_EDGE_REST ? adjacency[i] : cover[i];
        if (b >= SCN_EDGE_REST)
            continue;
        while (root[a] != a)
            a = root[a] = root[root[a]];
        while (root[b] != b)
            b = root[b] = root[root[b]];
        if (a != b)
            root[a < b ? b : a] = a < b ? a : b;
    }
    for (size_t i = 0; i < 3 * triangle_count; i++) {
        uint32_t a = (uint32_t)(i / 3);
        while (root[a] != a)
            a = root[a];
        if (adjacency[i] >= SCN_EDGE_REST && adjacency[i] != SCN_EDGE_NONMANIFOLD && cover[i] == SCN_EDGE_BORDER)
            closed[a] = 0; /* a border: an opening (an edge three or more faces share has no side open) */
    }
    for (uint32_t t = 0; t < triangle_count; t++) {
        uint32_t a = t;
        while (root[a] != a)
            a = root[a];
        closed[t] = closed[a];
    }
    free(root);
    return closed;
}

/* A key of the plane (n, d = n . p) quantised to 1e-3, the normal and the
 * distance shifted by `dd` steps: a plane near another may round to a
 * neighbouring key, which only skips an edge (it stays a silhouette). */
static uint64_t plane_key(const float* n, float d, int dd)
{
    uint64_t h = 1469598103934665603ull;
    int32_t q[4] = {(int32_t)lrintf(n[0] * 1000.0f), (int32_t)lrintf(n[1] * 1000.0f), (int32_t)lrintf(n[2] * 1000.0f),
                    (int32_t)lrintf(d * 1000.0f) + dd};
    for (int i = 0; i < 4; i++)
        h = (h ^ (uint32_t)q[i]) * 1099511628211ull;
    return h;
}

static int compare_u64(const void* a, const void* b)
{
    uint64_t x = *(const uint64_t*)a, y = *(const uint64_t*)b;
    return (x > y) - (x < y);
}

/* Corner of tri k whose position is bitwise p's, or 3. */
static uint32_t corner_at(const float* positions, const uint32_t* indices, uint32_t tri, const float* p)
{
    for (uint32_t c = 0; c < 3; c++)
        if (memcmp(scn_tri_corner(positions, indices, tri, c), p, 3 * sizeof(float)) == 0)
            return c;
    return 3;
}

size_t scn_join_glued_edges(uint32_t* adjacency, const uint32_t* indices, size_t triangle_count,
                            const float* positions, const uint8_t* solid)
{
    assert(adjacency && indices && positions && triangle_count < SCN_EDGE_REST);
    double total_len = 0.0, max_len = 0.0;
    for (size_t i = 0; i < 3 * triangle_count; i++) {
        size_t t = i / 3, c = i % 3;
        double l = glm_vec3_distance((float*)scn_tri_corner(positions, indices, (uint32_t)t, (uint32_t)c),
                                     (float*)scn_tri_corner(positions, indices, (uint32_t)t, (uint32_t)((c + 1) % 3)));
        total_len += l, max_len = fmax(max_len, l);
    }
    if (triangle_count == 0 || !(total_len > 0.0))
        return 0;
    uint32_t* cover = malloc(sizeof(uint32_t) * 3 * triangle_count);
    if (!cover)
        return 0;
    scn_cover_borders(cover, adjacency, indices, triangle_count, positions);
    uint8_t* closed = closed_components(adjacency, cover, triangle_count);
    free(cover);
    if (!closed)
        return 0;
    for (size_t t = 0; t < triangle_count; t++) /* the faces glued on: opaque, static, of a closed surface */
        closed[t] = closed[t] && (!solid || solid[t]);
    rest_grid g = {0};
    rest_scratch w = {.cap = 16};
    scratch_init(&w, positions, indices, triangle_count);
    float cell = (float)fmax(total_len / (double)(3 * triangle_count), 1e-3);
    bool ok = w.tested && w.normals && w.spans &&
              grid_build(&g, positions, indices, triangle_count, closed, cell, (float)(2.0 * SCN_WELD_LINE_EPS * max_len));
    /* the planes of the faces that may be glued on, to skip the edges of
     * every triangle no such face lies against (most of a scene) */
    uint64_t* keys = ok ? malloc(sizeof(uint64_t) * (triangle_count ? triangle_count : 1)) : NULL;
    size_t nkeys = 0;
    for (uint32_t t = 0; keys && t < triangle_count; t++)
        if (closed[t] && w.normals[t][3] != 0.0f)
            keys[nkeys++] = plane_key(w.normals[t], glm_vec3_dot(w.normals[t], (float*)scn_tri_corner(positions, indices, t, 0)), 0);
    if (keys)
        qsort(keys, nkeys, sizeof *keys, compare_u64);
    ok = ok && keys;
    size_t joined = 0;
    uint32_t stamp = 0;
    for (uint32_t t = 0; ok && t < triangle_count; t++) {
        float* n_t = w.normals[t];
        bool against = false;
        if (n_t[3] != 0.0f) {
            vec3 m;
            glm_vec3_negate_to(n_t, m);
            float d = glm_vec3_dot(m, (float*)scn_tri_corner(positions, indices, t, 0));
            for (int dd = -1; dd <= 1 && !against; dd++) {
                uint64_t key = plane_key(m, d, dd);
                against = bsearch(&key, keys, nkeys, sizeof *keys, compare_u64) != NULL;
            }
        }
        for (uint32_t c = 0; ok && against && c < 3; c++) {
            uint32_t k = adjacency[3 * (size_t)t + c];
            if (k >= SCN_EDGE_REST || k == t || w.normals[k][3] == 0.0f)
                continue;
            /* a consistently wound manifold edge, convex (t behind k's plane) */
            const float *p0 = scn_tri_corner(positions, indices, t, c), *p1 = scn_tri_corner(positions, indices, t, (c + 1) % 3);
            uint32_t k0 = corner_at(positions, indices, k, p1), k1 = corner_at(positions, indices, k, p0);
            if (k0 == 3 || k1 != (k0 + 1) % 3 || adjacency[3 * (size_t)k + k0] != t)
                continue;
            vec3 d, s, r;
            float* n_k = w.normals[k];
            glm_vec3_sub((float*)scn_tri_corner(positions, indices, t, (c + 2) % 3), (float*)p0, r);
            if (!(glm_vec3_dot(r, n_k) < -SCN_WELD_LINE_EPS * glm_vec3_norm(r)))
                continue;
            /* the faces t lies on face -n_t: s = d x (-n_t) must point to k's front side */
            glm_vec3_sub((float*)p1, (float*)p0, d);
            glm_vec3_cross(d, n_t, s);
            glm_vec3_negate(s);
            bool fwd = glm_vec3_dot(s, n_k) > 0.0f;
            vec3 q0, q1;
            memcpy(q0, fwd ? p0 : p1, sizeof q0);
            memcpy(q1, fwd ? p1 : p0, sizeof q1);
            ok = scan_edge(&w, &g, positions, indices, t, n_k, q0, q1, ++stamp);
            size_t m = 0; /* only faces t lies on: coplanar with t, facing the other way */
            for (size_t i = 0; i < w.m; i++)
                if (w.spans[i].face != k && glm_vec3_dot(w.spans[i].normal, n_t) <= -SCN_WELD_NORMAL_COS)
                    w.spans[m++] = w.spans[i];
            if (ok && m > 0 && covering_face(w.spans, m) != SCN_EDGE_BORDER) {
                adjacency[3 * (size_t)t + c] = t; /* faces as t from every point: never a silhouette */
                adjacency[3 * (size_t)k + k0] = k;
                joined++;
            }
        }
    }
    free(keys);
    free(g.cells);
    free(g.big);
    free(w.tested);
    free(w.normals);
    free(w.spans);
    free(closed);
    return joined;
}
