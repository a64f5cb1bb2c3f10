/* Built-in scenes: determinism, the size knob and the layout contracts of procedural.h. */
#include "procedural.h"
#include "scene.h"
#include "test.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static bool load(const char* spec, scn_scene* s)
{
    char err[512];
    bool ok = scn_load(spec, s, err, sizeof err);
    if (!ok)
        fprintf(stderr, "%s\n", err);
    return ok;
}

static bool same_scene(const scn_scene* a, const scn_scene* b)
{
    return a->vertex_count == b->vertex_count && a->triangle_count == b->triangle_count &&
           memcmp(a->positions, b->positions, 12 * (size_t)a->vertex_count) == 0 &&
           memcmp(a->normals, b->normals, 12 * (size_t)a->vertex_count) == 0 &&
           memcmp(a->uvs, b->uvs, 8 * (size_t)a->vertex_count) == 0 &&
           memcmp(a->indices, b->indices, 12 * (size_t)a->triangle_count) == 0 &&
           memcmp(a->tri_material, b->tri_material, 4 * (size_t)a->triangle_count) == 0;
}

static void test_determinism(void)
{
    const char* specs[][3] = { { "builtin:city?seed=3&tris=50000", "builtin:city?tris=50000&seed=3", "builtin:city?seed=4&tris=50000" },
                               { "builtin:interior?seed=1", "builtin:interior", "builtin:interior?seed=2" },
                               { "builtin:house?seed=1", "builtin:house", "builtin:house?seed=3" } };
    for (int k = 0; k < 3; k++) {
        scn_scene a, b, c;
        TV_CHECK(load(specs[k][0], &a) && load(specs[k][1], &b) && load(specs[k][2], &c));
        TV_CHECK(same_scene(&a, &b));
        TV_CHECK(!same_scene(&a, &c));
        scn_scene_free(&a), scn_scene_free(&b), scn_scene_free(&c);
    }
}

static void test_bad_specs(void)
{
    const char* bad[] = { "builtin:town", "builtin:city?tris=5", "builtin:city?seed=-1", "builtin:city?seed",
                          "builtin:city?color=3", "builtin:unit?seed=2", "builtin:interior?tris=100000", "builtin:house?tris=30000",
                          "builtin:city?seed=1&seed=2", "builtin:city?tris=20000&seed=1&tris=30000" };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        scn_scene s;
        char err[512];
        TV_CHECK(!scn_load(bad[i], &s, err, sizeof err));
        TV_CHECK(strstr(err, bad[i]) != NULL && s.triangle_count == 0);
    }
    TV_CHECK(strstr(scn_builtin_help(), "builtin:city") != NULL);
}

/* Every triangle's bounding box must miss the open street prisms: 0 < y <= 6
 * within 4 m of x = i*P or z = j*P. Stricter than the contract (a box, not
 * the triangle), so passing proves it. */
static uint32_t street_violations(const scn_scene* s)
{
    const float P = SCN_CITY_BLOCK_PITCH, half = SCN_CITY_STREET_CLEAR_HALF_WIDTH;
    uint32_t bad = 0;
    for (uint32_t t = 0; t < s->triangle_count; t++) {
        float lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
        for (int c = 0; c < 3; c++)
            for (int k = 0; k < 3; k++) {
                float p = s->positions[3 * (size_t)s->indices[3 * t + c] + k];
                lo[k] = fminf(lo[k], p), hi[k] = fmaxf(hi[k], p);
            }
        if (hi[1] <= 1e-4f || lo[1] > SCN_CITY_STREET_CLEAR_HEIGHT)
            continue;
        for (int axis = 0; axis < 3; axis += 2) {
            float line = roundf((lo[axis] + hi[axis]) * 0.5f / P) * P;
            for (int i = -1; i <= 1; i++) {
                float c = line + i * P;
                if (hi[axis] > c - half && lo[axis] < c + half)
                    bad++;
            }
        }
    }
    return bad;
}

static void test_city_size_and_streets(void)
{
    struct { const char* spec; double target, tol; } cases[] = {
        { "builtin:city?tris=50000", 50000, 0.2 },
        { "builtin:city", 150000, 0.2 },
        { "builtin:city?seed=7&tris=2000000", 2000000, 0.2 },
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        scn_scene s;
        TV_CHECK(load(cases[i].spec, &s));
        printf("     %s: %u triangles, %u vertices\n", cases[i].spec, s.triangle_count, s.vertex_count);
        TV_CHECK(fabs(s.triangle_count - cases[i].target) <= cases[i].tol * cases[i].target);
        if (cases[i].target >= 2000000)
            TV_CHECK(s.triangle_count >= 2000000);
        TV_CHECK(street_violations(&s) == 0);
        TV_CHECK(s.bounds_min[1] == 0.0f);
        TV_CHECK(s.bounds_min[0] <= -2 * SCN_CITY_BLOCK_PITCH && s.bounds_max[2] >= 2 * SCN_CITY_BLOCK_PITCH);
        TV_CHECK(s.texture_count >= 5 && s.material_count >= 5);
        scn_scene_free(&s);
    }
}

/* Segment-triangle intersection (Moller-Trumbore), both sides, interior of the segment. */
static bool segment_hits(const scn_scene* s, uint32_t t, const float a[3], const float b[3])
{
    const float* p0 = s->positions + 3 * (size_t)s->indices[3 * t];
    const float* p1 = s->positions + 3 * (size_t)s->indices[3 * t + 1];
    const float* p2 = s->positions + 3 * (size_t)s->indices[3 * t + 2];
    double d[3], e1[3], e2[3], h[3], q[3], o[3];
    for (int k = 0; k < 3; k++)
        d[k] = b[k] - a[k], e1[k] = p1[k] - p0[k], e2[k] = p2[k] - p0[k], o[k] = a[k] - p0[k];
    h[0] = d[1] * e2[2] - d[2] * e2[1], h[1] = d[2] * e2[0] - d[0] * e2[2], h[2] = d[0] * e2[1] - d[1] * e2[0];
    double det = e1[0] * h[0] + e1[1] * h[1] + e1[2] * h[2];
    if (fabs(det) < 1e-12)
        return false;
    double u = (o[0] * h[0] + o[1] * h[1] + o[2] * h[2]) / det;
    q[0] = o[1] * e1[2] - o[2] * e1[1], q[1] = o[2] * e1[0] - o[0] * e1[2], q[2] = o[0] * e1[1] - o[1] * e1[0];
    double v = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
    double tt = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
    return u >= 0 && v >= 0 && u + v <= 1 && tt > 1e-6 && tt < 1 - 1e-6;
}

static uint32_t hits(const scn_scene* s, const float a[3], const float b[3], uint32_t* first)
{
    uint32_t n = 0;
    for (uint32_t t = 0; t < s->triangle_count; t++)
        if (segment_hits(s, t, a, b)) {
            if (first && n == 0)
                *first = t;
            n++;
        }
    return n;
}

static void test_interior_contract(void)
{
    scn_scene s;
    TV_CHECK(load("builtin:interior?seed=5", &s));
    printf("     builtin:interior: %u triangles\n", s.triangle_count);
    const float rooms[4] = { -18, -6, 6, 18 };
    uint32_t blocked = 0, control = 0;
    for (int r = 0; r < 4; r++)
        for (int side = -1; side <= 1; side += 2)
            for (float y = 1.0f; y <= 2.0f; y += 0.5f)
                for (float dx = -0.5f; dx <= 0.5f; dx += 0.5f) {
                    float door[3] = { rooms[r] + dx, y, side * 1.5f }, centre[3] = { rooms[r], y, side * 6.5f };
                    blocked += hits(&s, door, centre, NULL);
                    /* control: beside the doorway the corridor wall blocks */
                    float beside[3] = { rooms[r] + 2.0f + dx, y, 0.0f }, into[3] = { rooms[r] + 2.0f + dx, y, side * 3.0f };
                    control += hits(&s, beside, into, NULL) > 0;
                }
    TV_CHECK(blocked == 0);
    TV_CHECK(control == 4 * 2 * 3 * 3);
    float west[3] = { -23.5f, 1.5f, 0.0f }, east[3] = { 23.5f, 1.5f, 0.0f };
    TV_CHECK(hits(&s, west, east, NULL) == 0);
    TV_CHECK_NEAR(s.bounds_min[0], -24.2, 1e-5);
    TV_CHECK_NEAR(s.bounds_max[2], 10.7, 1e-5);
    TV_CHECK_NEAR(s.bounds_max[1], 3.0, 1e-5);
    TV_CHECK(s.bounds_min[1] == 0.0f);
    scn_scene_free(&s);
}

/* builtin:house: a few tens of thousands of triangles, none degenerate,
 * the bundled walk's lanes clear at eye height (procedural.h) and blocked
 * beside them, the two floors and the roof where the contract puts them. */
static void test_house_contract(void)
{
    scn_scene s;
    TV_CHECK(load("builtin:house?seed=7", &s));
    printf("     builtin:house: %u triangles, %u materials\n", s.triangle_count, s.material_count);
    TV_CHECK(s.triangle_count >= 20000 && s.triangle_count <= 60000);
    uint32_t degenerate = 0;
    for (uint32_t t = 0; t < s.triangle_count; t++) {
        const float* p[3];
        for (int c = 0; c < 3; c++)
            p[c] = s.positions + 3 * (size_t)s.indices[3 * t + c];
        float e1[3], e2[3];
        for (int k = 0; k < 3; k++)
            e1[k] = p[1][k] - p[0][k], e2[k] = p[2][k] - p[0][k];
        float cx = e1[1] * e2[2] - e1[2] * e2[1], cy = e1[2] * e2[0] - e1[0] * e2[2], cz = e1[0] * e2[1] - e1[1] * e2[0];
        degenerate += 0.5f * sqrtf(cx * cx + cy * cy + cz * cz) < 1e-6f;
    }
    TV_CHECK(degenerate == 0);
    /* the walk's lanes, at knee, eye and head height (1.7 m eye, 0.3 m clearance) */
    const float lanes[][4] = { { -0.75f, 8.5f, -0.75f, -2.25f }, { -0.75f, -2.25f, -3.25f, -2.25f },
                               { -3.25f, -2.25f, -3.25f, 2.25f }, { -3.25f, 2.25f, -0.75f, 2.25f },
                               { -0.75f, 2.25f, -0.75f, -3.25f }, { -0.75f, -3.25f, 3.25f, -3.25f } };
    uint32_t blocked = 0;
    for (int l = 0; l < 6; l++)
        for (float y = 0.5f; y <= 2.0f; y += 0.75f)
            for (float off = -0.3f; off <= 0.3f; off += 0.3f) {
                bool along_z = lanes[l][0] == lanes[l][2];
                float a[3] = { lanes[l][0] + (along_z ? off : 0), y, lanes[l][1] + (along_z ? 0 : off) };
                float b[3] = { lanes[l][2] + (along_z ? off : 0), y, lanes[l][3] + (along_z ? 0 : off) };
                blocked += hits(&s, a, b, NULL);
            }
    TV_CHECK(blocked == 0);
    /* control: half a metre beside the lanes through doors, the walls block */
    float beside_a[3] = { -0.75f, 1.7f, -2.9f }, beside_b[3] = { -3.25f, 1.7f, -2.9f };
    TV_CHECK(hits(&s, beside_a, beside_b, NULL) > 0);
    /* vertical line at the hall: ground slab, upper slab (two faces each) and roof */
    float below[3] = { -0.6f, -1.0f, -3.1f }, above[3] = { -0.6f, 7.0f, -3.1f };
    TV_CHECK(hits(&s, below, above, NULL) >= 6);
    TV_CHECK_NEAR(s.bounds_min[0], -12.0, 1e-5);
    TV_CHECK_NEAR(s.bounds_max[1], 6.25, 1e-5);
    TV_CHECK_NEAR(s.bounds_min[1], -0.15, 1e-5);
    scn_scene_free(&s);
}

static void test_unit_scene(void)
{
    scn_scene s;
    TV_CHECK(load("builtin:unit", &s));
    TV_CHECK(s.triangle_count == 32);
    struct { const char* name; float lo[3], hi[3]; } objs[] = {
        { "ground", { -10, 0, -15 }, { 10, 0, 5 } },
        { "wall", { -2, 0, -5.1f }, { 2, 3, -5 } },
        { "box_b", { -0.5f, 0, -8 }, { 0.5f, 1, -7 } },
        { "box_c", { 4, 0, -6 }, { 5, 1, -5 } },
    };
    uint32_t covered = 0;
    uint32_t range[4][2];
    for (int i = 0; i < 4; i++) {
        uint32_t first, count;
        TV_CHECK(scn_unit_object(objs[i].name, &first, &count));
        range[i][0] = first, range[i][1] = count;
        covered += count;
        float lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
        for (uint32_t t = first; t < first + count && t < s.triangle_count; t++)
            for (int c = 0; c < 3; c++)
                for (int k = 0; k < 3; k++) {
                    float p = s.positions[3 * (size_t)s.indices[3 * t + c] + k];
                    lo[k] = fminf(lo[k], p), hi[k] = fmaxf(hi[k], p);
                }
        for (int k = 0; k < 3; k++) {
            TV_CHECK_NEAR(lo[k], objs[i].lo[k], 1e-6);
            TV_CHECK_NEAR(hi[k], objs[i].hi[k], 1e-6);
        }
    }
    TV_CHECK(covered == s.triangle_count);
    TV_CHECK(!scn_unit_object("box_d", &range[0][0], &range[0][1]));
    /* from the test eye, B is behind W and C is in the open */
    float eye[3] = { 0, 1.5f, 0 }, b_centre[3] = { 0, 0.5f, -7.5f }, c_centre[3] = { 4.5f, 0.5f, -5.5f };
    uint32_t first_hit = UINT32_MAX;
    TV_CHECK(hits(&s, eye, b_centre, &first_hit) >= 2);
    TV_CHECK(first_hit >= range[1][0] && first_hit < range[1][0] + range[1][1]);
    TV_CHECK(hits(&s, eye, c_centre, &first_hit) == 1);
    TV_CHECK(first_hit >= range[3][0] && first_hit < range[3][0] + range[3][1]);
    scn_scene_free(&s);
}

int main(void)
{
    TV_TEST_RUN(test_determinism);
    TV_TEST_RUN(test_bad_specs);
    TV_TEST_RUN(test_city_size_and_streets);
    TV_TEST_RUN(test_interior_contract);
    TV_TEST_RUN(test_house_contract);
    TV_TEST_RUN(test_unit_scene);
    return tv_test_finish();
}
