/* Welding and adjacency on meshes with known answers. */
#include "test.h"
#include "weld.h"

#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Unit cube as a soup: 12 triangles, 36 vertices, outward CCW winding. */
static const float cube_corner[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
                                         { 0, 0, 1 }, { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } };
static const uint32_t cube_tris[12][3] = { { 0, 2, 1 }, { 0, 3, 2 }, { 4, 5, 6 }, { 4, 6, 7 }, { 0, 1, 5 }, { 0, 5, 4 },
                                           { 3, 6, 2 }, { 3, 7, 6 }, { 0, 4, 7 }, { 0, 7, 3 }, { 1, 2, 6 }, { 1, 6, 5 } };

static void cube_soup(float* pos, uint32_t* idx)
{
    for (int t = 0; t < 12; t++)
        for (int c = 0; c < 3; c++) {
            memcpy(pos + 3 * (3 * t + c), cube_corner[cube_tris[t][c]], sizeof(float) * 3);
            idx[3 * t + c] = (uint32_t)(3 * t + c);
        }
}

static bool share_edge(const uint32_t* a, const uint32_t* b)
{
    int shared = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            shared += a[i] == b[j];
    return shared == 2;
}

static void test_weld_soup(void)
{
    float pos[108];
    uint32_t idx[36], remap[36];
    cube_soup(pos, idx);
    pos[3 * 3 + 0] = -0.0f; /* vertex 3 is corner (0,0,0): a -0.0 copy must still weld */
    TV_CHECK(scn_weld_positions(remap, pos, 36) == 8);
    for (int v = 0; v < 36; v++) {
        TV_CHECK(remap[v] <= (uint32_t)v);
        TV_CHECK(remap[remap[v]] == remap[v]);
        uint32_t corner = cube_tris[v / 3][v % 3];
        for (int w = 0; w < v; w++)
            if (cube_tris[w / 3][w % 3] == corner) {
                TV_CHECK(remap[v] == (uint32_t)w); /* smallest id with that position */
                break;
            }
    }
    float near[6] = { 1.0f, 2.0f, 3.0f, 1.0f, 2.0f, 3.0000002f }; /* one ulp apart: distinct */
    uint32_t r2[2];
    TV_CHECK(scn_weld_positions(r2, near, 2) == 2);
    TV_CHECK(r2[1] == 1);
}

static void test_adjacency_cube(void)
{
    float pos[108];
    uint32_t idx[36], remap[36], adj[36];
    cube_soup(pos, idx);
    scn_weld_positions(remap, pos, 36);
    scn_build_adjacency(adj, idx, 12, remap);
    for (uint32_t t = 0; t < 12; t++)
        for (int e = 0; e < 3; e++) {
            uint32_t n = adj[3 * t + e];
            TV_CHECK(n < 12 && n != t);
            if (n >= 12)
                continue;
            /* the neighbour really holds this edge's two corners, and points back */
            uint32_t a = cube_tris[t][e], b = cube_tris[t][(e + 1) % 3];
            int found = 0;
            for (int f = 0; f < 3; f++) {
                uint32_t c = cube_tris[n][f], d = cube_tris[n][(f + 1) % 3];
                if ((c == a && d == b) || (c == b && d == a)) {
                    found++;
                    TV_CHECK(adj[3 * n + f] == t);
                }
            }
            TV_CHECK(found == 1);
            TV_CHECK(share_edge(cube_tris[t], cube_tris[n]));
        }
}

static void test_adjacency_open_quad(void)
{
    /* two triangles over a quad (soup): one shared diagonal, four borders */
    float pos[18] = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0 };
    uint32_t idx[6] = { 0, 1, 2, 3, 4, 5 }, remap[6], adj[6];
    TV_CHECK(scn_weld_positions(remap, pos, 6) == 4);
    scn_build_adjacency(adj, idx, 2, remap);
    TV_CHECK(adj[0] == SCN_EDGE_BORDER && adj[1] == SCN_EDGE_BORDER && adj[2] == 1);
    TV_CHECK(adj[3] == 0 && adj[4] == SCN_EDGE_BORDER && adj[5] == SCN_EDGE_BORDER);
}

/* T-junctions: quad A = [0,2]x[0,1] meets quads B1 = [2,3]x[0,0.5] and
 * B2 = [2,3]x[0.5,1] in the plane z = 0 (all facing +z, a soup). A's right
 * edge and the left edges of B1 and B2 are borders; each is covered end to
 * end by the others, so all three are joined. Variants: B2 missing (A's edge
 * half covered: only B1's is joined), the Bs tilted out of the plane, facing
 * -z, or lying over A instead of beside it: nothing is joined. */
typedef struct tj_mesh {
    float pos[3 * 18];
    uint32_t idx[18], adj[18];
    uint32_t tris;
} tj_mesh;

static void tj_quad(tj_mesh* m, float x0, float y0, float x1, float y1, float z_tilt, bool flip)
{
    const float c[4][3] = {{x0, y0, 0}, {x1, y0, (x1 - x0) * z_tilt}, {x1, y1, (x1 - x0) * z_tilt}, {x0, y1, 0}};
    const int order[2][6] = {{0, 1, 2, 0, 2, 3}, {0, 2, 1, 0, 3, 2}};
    for (int i = 0; i < 6; i++) {
        uint32_t v = 3 * m->tris + (uint32_t)i;
        memcpy(m->pos + 3 * v, c[order[flip][i]], sizeof(float) * 3);
        m->idx[v] = v;
    }
    m->tris += 2;
}

static size_t tj_join(tj_mesh* m)
{
    uint32_t remap[18];
    scn_weld_positions(remap, m->pos, 3 * m->tris);
    scn_build_adjacency(m->adj, m->idx, m->tris, remap);
    return scn_join_tjunctions(m->adj, m->idx, m->tris, m->pos);
}

static void test_join_tjunctions(void)
{
    tj_mesh m = {0};
    tj_quad(&m, 0, 0, 2, 1, 0, false);
    tj_quad(&m, 2, 0, 3, 0.5f, 0, false);
    tj_quad(&m, 2, 0.5f, 3, 1, 0, false);
    TV_CHECK(tj_join(&m) == 3);
    TV_CHECK(m.adj[1] == 3 || m.adj[1] == 5); /* A's right edge: now the second triangle of B1 or B2 */

    tj_mesh half = {0};
    tj_quad(&half, 0, 0, 2, 1, 0, false);
    tj_quad(&half, 2, 0, 3, 0.5f, 0, false);
    TV_CHECK(tj_join(&half) == 1 && half.adj[1] == SCN_EDGE_BORDER);

    tj_mesh tilted = {0};
    tj_quad(&tilted, 0, 0, 2, 1, 0, false);
    tj_quad(&tilted, 2, 0, 3, 0.5f, 0.2f, false);
    tj_quad(&tilted, 2, 0.5f, 3, 1, 0.2f, false);
    TV_CHECK(tj_join(&tilted) == 0);

    tj_mesh flipped = {0};
    tj_quad(&flipped, 0, 0, 2, 1, 0, false);
    tj_quad(&flipped, 2, 0, 3, 0.5f, 0, true);
    tj_quad(&flipped, 2, 0.5f, 3, 1, 0, true);
    TV_CHECK(tj_join(&flipped) == 0);

    tj_mesh over = {0};
    tj_quad(&over, 0, 0, 2, 1, 0, false);
    tj_quad(&over, 1, 0, 2, 0.5f, 0, false);
    tj_quad(&over, 1, 0.5f, 2, 1, 0, false);
    TV_CHECK(tj_join(&over) == 0);
}

static void test_adjacency_fin(void)
{
    /* three triangles on the edge (0,0,0)-(0,1,0): non-manifold; the rest border */
    float pos[] = { 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, -1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1 };
    uint32_t idx[9] = { 0, 1, 2, 3, 4, 5, 6, 7, 8 }, remap[9], adj[9];
    TV_CHECK(scn_weld_positions(remap, pos, 9) == 5);
    scn_build_adjacency(adj, idx, 3, remap);
    TV_CHECK(adj[0] == SCN_EDGE_NONMANIFOLD && adj[3] == SCN_EDGE_NONMANIFOLD && adj[6] == SCN_EDGE_NONMANIFOLD);
    for (int t = 0; t < 3; t++)
        TV_CHECK(adj[3 * t + 1] == SCN_EDGE_BORDER && adj[3 * t + 2] == SCN_EDGE_BORDER);
}

/* A quad and its coincident twin of opposite winding (a soup): the four
 * triangles share the diagonal (0,0,0)-(1,1,0), which scn_pair_sheets pairs
 * front with front and twin with twin; with the last twin tilted out of the
 * plane no same-facing pairing exists and the edge stays non-manifold. */
static void test_pair_sheets(void)
{
    for (int tilt = 0; tilt < 2; tilt++) {
        float pos[] = { 0, 0, 0, 1, 0, 0, 1, 1, 0,  0, 0, 0, 1, 1, 0, 0, 1, 0,  /* faces +z */
                        0, 0, 0, 0, 1, 0, 1, 1, 0,  0, 0, 0, 1, 1, 0, 1, 0, 0 }; /* faces -z */
        pos[35] = tilt ? 0.5f : 0.0f;
        uint32_t idx[12], remap[12], adj[12];
        for (uint32_t i = 0; i < 12; i++)
            idx[i] = i;
        scn_weld_positions(remap, pos, 12);
        scn_build_adjacency(adj, idx, 4, remap);
        TV_CHECK(adj[2] == SCN_EDGE_NONMANIFOLD && adj[3] == SCN_EDGE_NONMANIFOLD);
        TV_CHECK(scn_pair_sheets(adj, idx, 4, remap, pos) == (size_t)!tilt);
        if (tilt) {
            TV_CHECK(adj[2] == SCN_EDGE_NONMANIFOLD && adj[3] == SCN_EDGE_NONMANIFOLD);
            TV_CHECK(adj[8] == SCN_EDGE_NONMANIFOLD && adj[9] == SCN_EDGE_NONMANIFOLD);
        } else {
            TV_CHECK(adj[2] == 1 && adj[3] == 0 && adj[8] == 3 && adj[9] == 2);
        }
        TV_CHECK(adj[0] == (tilt ? SCN_EDGE_BORDER : 3)); /* the edge (0,0,0)-(1,0,0): a quad and its twin */
    }
}

static void test_adjacency_mixed_winding_and_degenerate(void)
{
    /* triangle 1 walks the shared edge in the same direction as triangle 0
     * (inconsistent winding): still paired. Triangle 2 has two welded corners. */
    float pos[] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -1, 0, 5, 5, 5, 5, 5, 5, 6, 5, 5 };
    uint32_t idx[9] = { 0, 1, 2, 3, 4, 5, 6, 7, 8 }, remap[9], adj[9];
    scn_weld_positions(remap, pos, 9);
    scn_build_adjacency(adj, idx, 3, remap);
    TV_CHECK(adj[0] == 1 && adj[3] == 0);
    TV_CHECK(adj[6] == SCN_EDGE_BORDER && adj[7] == SCN_EDGE_BORDER && adj[8] == SCN_EDGE_BORDER);
}

static void test_adjacency_grid_scale(void)
{
    /* 512x512 indexed grid (524288 triangles): interior edges pair, outer ones border */
    const uint32_t n = 512, nv = (n + 1) * (n + 1), nt = 2 * n * n;
    float* pos = malloc(sizeof(float) * 3 * nv);
    uint32_t* idx = malloc(sizeof(uint32_t) * 3 * nt);
    uint32_t* remap = malloc(sizeof(uint32_t) * nv);
    uint32_t* adj = malloc(sizeof(uint32_t) * 3 * nt);
    for (uint32_t j = 0; j <= n; j++)
        for (uint32_t i = 0; i <= n; i++) {
            float* p = pos + 3 * (j * (n + 1) + i);
            p[0] = (float)i, p[1] = 0.0f, p[2] = (float)j;
        }
    for (uint32_t j = 0; j < n; j++)
        for (uint32_t i = 0; i < n; i++) {
            uint32_t a = j * (n + 1) + i, *t = idx + 6 * (j * n + i);
            t[0] = a, t[1] = a + n + 1, t[2] = a + 1, t[3] = a + 1, t[4] = a + n + 1, t[5] = a + n + 2;
        }
    TV_CHECK(scn_weld_positions(remap, pos, nv) == nv);
    scn_build_adjacency(adj, idx, nt, remap);
    uint32_t borders = 0, bad = 0;
    for (uint32_t h = 0; h < 3 * nt; h++) {
        if (adj[h] == SCN_EDGE_BORDER)
            borders++;
        else if (adj[h] >= nt || !share_edge(idx + 3 * (h / 3), idx + 3 * adj[h]))
            bad++;
    }
    TV_CHECK(borders == 4 * n);
    TV_CHECK(bad == 0);
    free(pos), free(idx), free(remap), free(adj);
}

/* Cracks: quad A [0,1]^2 and quad B beside it in the same plane, its left
 * edge parallel to A's right edge across a gap. 1 cm (under the 2 cm
 * bound): both edges marked, nothing else; 3 cm: none; coincident edges
 * that do not weld (B half as tall, no T-junction join run): none, they
 * leave no opening; B beside A's edge but past its end: none. */
static size_t crack_count(tj_mesh* m, uint8_t crack[18])
{
    uint32_t remap[18];
    scn_weld_positions(remap, m->pos, 3 * m->tris);
    scn_build_adjacency(m->adj, m->idx, m->tris, remap);
    return scn_mark_cracks(crack, m->adj, m->idx, m->tris, m->pos, 0.02f);
}

static void test_mark_cracks(void)
{
    uint8_t crack[18];
    tj_mesh m = {0};
    tj_quad(&m, 0, 0, 1, 1, 0, false);
    tj_quad(&m, 1.01f, 0, 2, 1, 0, false);
    TV_CHECK(crack_count(&m, crack) == 2);
    TV_CHECK(crack[1] == 1 && crack[3 * 3 + 2] == 1); /* A's right edge (x = 1), B's left (x = 1.01) */
    tj_mesh wide = {0};
    tj_quad(&wide, 0, 0, 1, 1, 0, false);
    tj_quad(&wide, 1.03f, 0, 2, 1, 0, false);
    TV_CHECK(crack_count(&wide, crack) == 0);
    tj_mesh touching = {0};
    tj_quad(&touching, 0, 0, 1, 1, 0, false);
    tj_quad(&touching, 1, 0, 2, 0.5f, 0, false);
    TV_CHECK(crack_count(&touching, crack) == 0);
    tj_mesh apart = {0};
    tj_quad(&apart, 0, 0, 1, 1, 0, false);
    tj_quad(&apart, 1.01f, 1.5f, 2, 2.5f, 0, false);
    TV_CHECK(crack_count(&apart, crack) == 0);
}

int main(void)
{
    TV_TEST_RUN(test_weld_soup);
    TV_TEST_RUN(test_adjacency_cube);
    TV_TEST_RUN(test_adjacency_open_quad);
    TV_TEST_RUN(test_adjacency_fin);
    TV_TEST_RUN(test_pair_sheets);
    TV_TEST_RUN(test_adjacency_mixed_winding_and_degenerate);
    TV_TEST_RUN(test_adjacency_grid_scale);
    TV_TEST_RUN(test_join_tjunctions);
    TV_TEST_RUN(test_mark_cracks);
    return tv_test_finish();
}
