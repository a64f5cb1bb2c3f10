/* Silhouette edges from a point: a closed cube (exactly its outline), an open
 * quad (its four border edges), a non-manifold fin, and a triangle subset.
 * Adjacency is built here by brute force in scn_build_adjacency's format. */
#include <stdbool.h>
#include <string.h>

#include "silhouette.h"
#include "test.h"
#include "weld.h"

static void brute_adjacency(uint32_t* adj, const uint32_t* idx, uint32_t tris)
{
    for (uint32_t t = 0; t < tris; t++) {
        for (uint32_t e = 0; e < 3; e++) {
            uint32_t a = idx[3 * t + e], b = idx[3 * t + (e + 1) % 3], found = 0, other = 0;
            for (uint32_t u = 0; u < tris; u++) {
                for (uint32_t k = 0; k < 3 && u != t; k++) {
                    uint32_t c = idx[3 * u + k], d = idx[3 * u + (k + 1) % 3];
                    if ((c == a && d == b) || (c == b && d == a)) {
                        found++;
                        other = u;
                    }
                }
            }
            adj[3 * t + e] = found == 0 ? SCN_EDGE_BORDER : found == 1 ? other : SCN_EDGE_NONMANIFOLD;
        }
    }
}

/* How often the undirected edge (a, b) appears in the output. */
static int count_edge(const pvs_silhouette* s, size_t n, const uint32_t* idx, uint32_t a, uint32_t b)
{
    int c = 0;
    for (size_t i = 0; i < n; i++) {
        uint32_t x = idx[3 * s[i].tri + s[i].edge], y = idx[3 * s[i].tri + (s[i].edge + 1) % 3];
        c += (x == a && y == b) || (x == b && y == a);
    }
    return c;
}

static const float cube_pos[8 * 3] = {-1, -1, -1, 1, -1, -1, -1, 1, -1, 1, 1, -1,
                                      -1, -1, 1,  1, -1, 1,  -1, 1, 1,  1, 1, 1};
/* Vertex i has x = bit 0, y = bit 1, z = bit 2; faces counter-clockwise from outside. */
static const uint32_t cube_idx[36] = {
    1, 3, 7, 1, 7, 5, /* +x */ 0, 4, 6, 0, 6, 2, /* -x */
    2, 6, 7, 2, 7, 3, /* +y */ 0, 1, 5, 0, 5, 4, /* -y */
    4, 5, 7, 4, 7, 6, /* +z */ 0, 2, 3, 0, 3, 1  /* -z */
};

static void test_cube_outline(void)
{
    uint32_t adj[36];
    brute_adjacency(adj, cube_idx, 12);
    for (int i = 0; i < 36; i++)
        TV_CHECK(adj[i] < 12); /* closed */
    pvs_silhouette out[36];
    float eye[3] = {3, 4, 5}; /* sees +x, +y, +z */
    size_t n = pvs_find_silhouettes(out, cube_pos, cube_idx, adj, NULL, 12, eye);
    TV_CHECK(n == 6);
    /* The outline: edges between a visible and a hidden face. */
    static const uint32_t outline[6][2] = {{1, 3}, {1, 5}, {2, 3}, {2, 6}, {4, 5}, {4, 6}};
    for (int i = 0; i < 6; i++)
        TV_CHECK(count_edge(out, n, cube_idx, outline[i][0], outline[i][1]) == 1);
    for (size_t i = 0; i < n; i++) { /* named from the front-facing side */
        uint32_t face = out[i].tri / 2;
        TV_CHECK(face == 0 || face == 2 || face == 4);
    }
    float inside[3] = {0.1f, 0.2f, 0.3f}; /* everything back-facing: no silhouette */
    TV_CHECK(pvs_find_silhouettes(out, cube_pos, cube_idx, adj, NULL, 12, inside) == 0);
}

static void test_open_quad_borders(void)
{
    const float pos[12] = {0, 0, 0, 1, 0, 0, 1, 0, 1, 0, 0, 1};
    const uint32_t idx[6] = {0, 2, 1, 0, 3, 2}; /* facing +y */
    uint32_t adj[6];
    brute_adjacency(adj, idx, 2);
    pvs_silhouette out[6];
    float above[3] = {0.5f, 2, 0.5f}, below[3] = {0.3f, -2, 0.6f};
    for (int side = 0; side < 2; side++) {
        size_t n = pvs_find_silhouettes(out, pos, idx, adj, NULL, 2, side ? below : above);
        TV_CHECK(n == 4);
        TV_CHECK(count_edge(out, n, idx, 0, 1) == 1 && count_edge(out, n, idx, 1, 2) == 1);
        TV_CHECK(count_edge(out, n, idx, 2, 3) == 1 && count_edge(out, n, idx, 3, 0) == 1);
        TV_CHECK(count_edge(out, n, idx, 0, 2) == 0); /* the shared diagonal */
    }
}

static void test_nonmanifold_fin(void)
{
    /* Three triangles on the edge (0, 1): a floor, its continuation and a fin. */
    const float pos[15] = {0, 0, 0, 1, 0, 0, 0.5f, 0, -1, 0.5f, 0, 1, 0.5f, 1, 0};
    const uint32_t idx[9] = {0, 1, 2, 1, 0, 3, 0, 1, 4};
    uint32_t adj[9];
    brute_adjacency(adj, idx, 3);
    TV_CHECK(adj[0] == SCN_EDGE_NONMANIFOLD && adj[3] == SCN_EDGE_NONMANIFOLD && adj[6] == SCN_EDGE_NONMANIFOLD);
    pvs_silhouette out[9];
    float eye[3] = {0.5f, 3, 0.2f};
    size_t n = pvs_find_silhouettes(out, pos, idx, adj, NULL, 3, eye);
    TV_CHECK(n == 9); /* the fin edge once per triangle, plus six border edges */
    TV_CHECK(count_edge(out, n, idx, 0, 1) == 3);
    /* Only a subset scanned: only its edges. */
    const uint32_t subset[1] = {2};
    n = pvs_find_silhouettes(out, pos, idx, adj, subset, 1, eye);
    TV_CHECK(n == 3);
    for (size_t i = 0; i < n; i++)
        TV_CHECK(out[i].tri == 2);
    TV_CHECK(pvs_silhouettes_bound(3) == 9);
}

/* A wall triangle standing on a floor triangle that runs under it, its
 * foot marked as resting on the floor (scn_join_rest_edges): a silhouette
 * only where the two do not both face the point or both face away, and
 * then named from the wall, also when the wall faces away (the floor has
 * no edge there to name it by). */
static void test_rest_edge(void)
{
    /* wall: foot (1,0,0) -> (-1,0,0), apex above, facing -z; floor: y = 0, facing +y */
    const float pos[18] = {1, 0, 0, -1, 0, 0, 0, 1, 0, -2, 0, 2, 2, 0, 2, 0, 0, -3};
    const uint32_t idx[6] = {0, 1, 2, 3, 4, 5};
    uint32_t adj[6] = {SCN_EDGE_REST | 1u, SCN_EDGE_BORDER, SCN_EDGE_BORDER,
                       SCN_EDGE_BORDER, SCN_EDGE_BORDER, SCN_EDGE_BORDER};
    const uint32_t wall[1] = {0};
    pvs_silhouette out[3];
    /* in front of both; behind the wall above the floor; in front of the
     * wall below the floor; behind both; on the floor's plane */
    const float points[5][3] = {{0.3f, 2, -3}, {0.3f, 2, 3}, {0.3f, -2, -3}, {0.3f, -2, 3}, {0.3f, 0, -3}};
    const bool foot[5] = {false, true, true, false, true};
    for (int i = 0; i < 5; i++) {
        size_t n = pvs_find_silhouettes(out, pos, idx, adj, wall, 1, points[i]);
        TV_CHECK(n == 2u + foot[i]); /* the wall's two sides always */
        TV_CHECK(count_edge(out, n, idx, 0, 1) == (foot[i] ? 1 : 0));
        for (size_t k = 0; k < n; k++)
            TV_CHECK(out[k].tri == 0);
    }
}

int main(void)
{
    TV_TEST_RUN(test_cube_outline);
    TV_TEST_RUN(test_open_quad_borders);
    TV_TEST_RUN(test_nonmanifold_fin);
    TV_TEST_RUN(test_rest_edge);
    return tv_test_finish();
}
