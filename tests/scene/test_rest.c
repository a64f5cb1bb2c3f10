/* Border edges resting on another face (scn_join_rest_edges): a wall on a
 * floor, and the near misses that must stay borders; a box glued on a slab
 * closed only up to a T-junction (scn_join_glued_edges). */
#include "test.h"
#include "weld.h"

#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#define MAX_TRIS 32

typedef struct mesh {
    float pos[3 * 3 * MAX_TRIS];
    uint32_t idx[3 * MAX_TRIS], adj[3 * MAX_TRIS], remap[3 * MAX_TRIS];
    uint8_t solid[MAX_TRIS];
    size_t tris;
} mesh;

/* Quad c0 c1 c2 c3 (counter-clockwise seen from its front) as the two
 * triangles (c0 c1 c2), (c0 c2 c3), unwelded: edge 0 of the first runs c0 -> c1. */
static size_t quad(mesh* m, const float c[4][3])
{
    static const int corners[6] = {0, 1, 2, 0, 2, 3};
    size_t first = m->tris;
    for (int i = 0; i < 6; i++) {
        size_t v = 3 * m->tris + (size_t)(i % 3);
        memcpy(m->pos + 3 * v, c[corners[i]], sizeof(float) * 3);
        m->idx[v] = (uint32_t)v;
        if (i % 3 == 2) {
            m->solid[m->tris] = 1;
            m->tris++;
        }
    }
    return first;
}

/* A 2 x 1 m wall in the plane z = 0 facing -z, from y = y0 to y0 + h (h < 0:
 * hanging down from y0); returns the triangle whose edge 0 is its foot
 * (y = y0) on a standing wall. */
static size_t wall(mesh* m, float y0, float h)
{
    if (h > 0.0f) {
        const float c[4][3] = {{1, y0, 0}, {-1, y0, 0}, {-1, y0 + h, 0}, {1, y0 + h, 0}};
        return quad(m, c);
    }
    const float c[4][3] = {{-1, y0, 0}, {1, y0, 0}, {1, y0 + h, 0}, {-1, y0 + h, 0}};
    return quad(m, c);
}

/* A floor in the plane y = 0 facing +y (up = false: -y) over [x0, x1] x
 * [z0, z1]. */
static void floor_quad(mesh* m, float x0, float x1, float z0, float z1, bool up)
{
    const float c[4][3] = {{x0, 0, z1}, {x1, 0, z1}, {x1, 0, z0}, {x0, 0, z0}};
    const float r[4][3] = {{x0, 0, z0}, {x1, 0, z0}, {x1, 0, z1}, {x0, 0, z1}};
    quad(m, up ? c : r);
}

static size_t join(mesh* m)
{
    scn_weld_positions(m->remap, m->pos, 3 * m->tris);
    scn_build_adjacency(m->adj, m->idx, m->tris, m->remap);
    return scn_join_rest_edges(m->adj, m->idx, m->tris, m->pos, m->solid);
}

/* Whether the wall's foot (edge 0 of triangle t) rests on one of the
 * triangles from `face` on. */
static bool rests(const mesh* m, size_t t, size_t face)
{
    uint32_t a = m->adj[3 * t];
    return a != SCN_EDGE_BORDER && a != SCN_EDGE_NONMANIFOLD && (a & SCN_EDGE_REST) &&
           (a & ~SCN_EDGE_REST) >= face;
}

static void test_wall_on_a_floor(void)
{
    mesh m = {0};
    size_t foot = wall(&m, 0.0f, 1.0f);
    floor_quad(&m, -2, 2, -2, 2, true); /* runs on under the wall */
    TV_CHECK(join(&m) == 1);
    TV_CHECK(rests(&m, foot, 2));
    /* the wall's other borders stay: no face holds them */
    TV_CHECK(m.adj[3 * foot + 1] == SCN_EDGE_BORDER); /* a side */
    TV_CHECK(m.adj[3 * 1 + 1] == SCN_EDGE_BORDER);    /* the top */

    /* a floor ending at the foot on the wall's front side is the crease itself */
    m = (mesh){0};
    foot = wall(&m, 0.0f, 1.0f);
    floor_quad(&m, -2, 2, -2, 0, true);
    TV_CHECK(join(&m) >= 1 && rests(&m, foot, 2));

    /* two floor pieces meeting under the wall's middle */
    m = (mesh){0};
    foot = wall(&m, 0.0f, 1.0f);
    floor_quad(&m, -2, 0, -2, 2, true);
    floor_quad(&m, 0, 2, -2, 2, true);
    TV_CHECK(join(&m) >= 1 && rests(&m, foot, 2));
}

/* The foot's adjacency once a standing wall (foot at height y0) is joined
 * with a floor over [x0, x1] x [z0, z1] facing up or down (its two
 * triangles solid or not). */
static uint32_t foot_on(float y0, float x0, float x1, float z0, float z1, bool up, bool solid)
{
    mesh m = {0};
    size_t foot = wall(&m, y0, 1.0f);
    floor_quad(&m, x0, x1, z0, z1, up);
    m.solid[2] = m.solid[3] = solid;
    join(&m);
    return m.adj[3 * foot];
}

static void test_near_misses(void)
{
    /* the floor only behind the wall (it ends at the foot on the wall's
     * front side, where the viewer stands): a fin, seen past from in front */
    TV_CHECK(foot_on(0.0f, -2, 2, 0, 2, true, true) == SCN_EDGE_BORDER);
    /* the floor stops 1 cm short of the foot */
    TV_CHECK(foot_on(0.0f, -2, 2, -2, -0.01f, true, true) == SCN_EDGE_BORDER);
    /* the floor covers only part of the foot */
    TV_CHECK(foot_on(0.0f, -2, 0.5f, -2, 2, true, true) == SCN_EDGE_BORDER);
    /* the wall hovers 1 cm above the floor */
    TV_CHECK(foot_on(0.01f, -2, 2, -2, 2, true, true) == SCN_EDGE_BORDER);
    /* the floor faces down: the wall stands behind it */
    TV_CHECK(foot_on(0.0f, -2, 2, -2, 0, false, true) == SCN_EDGE_BORDER);
    /* an alpha-masked (or see-through) floor has holes */
    TV_CHECK(foot_on(0.0f, -2, 2, -2, 2, true, false) == SCN_EDGE_BORDER);
    /* the same opaque floor: the one difference */
    TV_CHECK(foot_on(0.0f, -2, 2, -2, 2, true, true) != SCN_EDGE_BORDER);
}

/* A wall hanging below the floor plane: with the floor only on its front
 * side the two do not close (rays from above pass the floor's edge behind
 * the wall); with the floor running on behind it, they bound a solid (a
 * slab's top and the face hanging from it: a convex edge), which is left a
 * border all the same (weld.h: the pixel-centre rules lose what is seen in
 * part of a pixel past such an edge). */
static void test_wall_below_the_floor(void)
{
    mesh m = {0};
    size_t top = wall(&m, 0.0f, -1.0f);
    floor_quad(&m, -2, 2, -2, 0, true);
    join(&m);
    TV_CHECK(m.adj[3 * top] == SCN_EDGE_BORDER);

    m = (mesh){0};
    top = wall(&m, 0.0f, -1.0f);
    floor_quad(&m, -2, 2, 0, 2, true);
    TV_CHECK(join(&m) == 0 && m.adj[3 * top] == SCN_EDGE_BORDER);
}

/* The floor tilted 20 degrees about the foot's line still holds the foot;
 * tilted 1 degree about the z axis it leaves the foot's ends 1.7 cm off
 * its plane. */
static void test_tilted_floor(void)
{
    const float c = cosf(0.349f), s = sinf(0.349f);
    mesh m = {0};
    size_t foot = wall(&m, 0.0f, 1.0f);
    const float about_x[4][3] = {{-2, 2 * s, 2 * c}, {2, 2 * s, 2 * c}, {2, -2 * s, -2 * c}, {-2, -2 * s, -2 * c}};
    quad(&m, about_x);
    TV_CHECK(join(&m) >= 1 && rests(&m, foot, 2));

    const float t = tanf(0.01745f);
    m = (mesh){0};
    foot = wall(&m, 0.0f, 1.0f);
    const float about_z[4][3] = {{-2, -2 * t, 2}, {2, 2 * t, 2}, {2, 2 * t, -2}, {-2, -2 * t, -2}};
    quad(&m, about_z);
    join(&m);
    TV_CHECK(m.adj[3 * foot] == SCN_EDGE_BORDER);
}


/* Box [lo, hi], each face a quad counter-clockwise from outside; the top
 * (y = hi) split at x = split when lo[0] < split < hi[0] (its two halves
 * meet the sides z = lo, hi at a T-junction: the sides' top edges are not
 * split); without its bottom when !bottom. */
static void box(mesh* m, const float lo[3], const float hi[3], float split, bool bottom)
{
    const float x0 = lo[0], y0 = lo[1], z0 = lo[2], x1 = hi[0], y1 = hi[1], z1 = hi[2];
    const float f[5][4][3] = {
        {{x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1}}, /* bottom, -y */
        {{x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}}, /* +z */
        {{x1, y0, z0}, {x0, y0, z0}, {x0, y1, z0}, {x1, y1, z0}}, /* -z */
        {{x1, y0, z1}, {x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}}, /* +x */
        {{x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}, {x0, y1, z0}}, /* -x */
    };
    for (int i = bottom ? 0 : 1; i < 5; i++)
        quad(m, f[i]);
    float cuts[3] = {x0, split, x1};
    int n = x0 < split && split < x1 ? 2 : 1;
    if (n == 1)
        cuts[1] = x1;
    for (int i = 0; i < n; i++) {
        const float top[4][3] = {{cuts[i], y1, z1}, {cuts[i + 1], y1, z1}, {cuts[i + 1], y1, z0}, {cuts[i], y1, z0}};
        quad(m, top);
    }
}

/* A box glued on a slab's top: the box's bottom edges are glued (no
 * silhouettes) when the slab is closed, also when its top is split at a
 * T-junction (closed up to it: scn_cover_borders), not when a face is
 * missing. */
static void test_box_glued_on_a_split_slab(void)
{
    const float slab_lo[3] = {-2, -1, -2}, slab_hi[3] = {2, 0, 2}, lo[3] = {0.5f, 0, -0.5f}, hi[3] = {1.5f, 1, 0.5f};
    size_t glued[3];
    for (int v = 0; v < 3; v++) {
        mesh m = {0};
        box(&m, slab_lo, slab_hi, v == 0 ? 9.0f : 0.0f, v < 2); /* v = 2: split, no bottom (open) */
        box(&m, lo, hi, 9.0f, true);
        join(&m);
        glued[v] = scn_join_glued_edges(m.adj, m.idx, m.tris, m.pos, m.solid);
    }
    TV_CHECK(glued[0] == 4); /* the four edges of the box's bottom */
    TV_CHECK(glued[1] == 4);
    TV_CHECK(glued[2] == 0);
}

int main(void)
{
    TV_TEST_RUN(test_wall_on_a_floor);
    TV_TEST_RUN(test_near_misses);
    TV_TEST_RUN(test_wall_below_the_floor);
    TV_TEST_RUN(test_tilted_floor);
    TV_TEST_RUN(test_box_glued_on_a_split_slab);
    return tv_test_finish();
}
