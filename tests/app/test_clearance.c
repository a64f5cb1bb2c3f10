/* clearance.h: point-triangle distances with known answers, the grid against
 * brute force on builtin:interior (default and deliberately coarse grids),
 * and the interior's documented corridor dimensions. */
#include "clearance.h"
#include "test.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

static void test_point_triangle(void)
{
    const float a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0};
    TV_CHECK_NEAR(tv_point_triangle_distance((const float[3]){0.2f, 0.2f, 0.5f}, a, b, c), 0.5, 1e-6); /* face */
    TV_CHECK_NEAR(tv_point_triangle_distance((const float[3]){0.2f, 0.2f, -0.5f}, a, b, c), 0.5, 1e-6);
    TV_CHECK_NEAR(tv_point_triangle_distance((const float[3]){2, 0, 0}, a, b, c), 1.0, 1e-6);      /* vertex b */
    TV_CHECK_NEAR(tv_point_triangle_distance((const float[3]){-1, -1, 0}, a, b, c), sqrt(2.0), 1e-6); /* a */
    TV_CHECK_NEAR(tv_point_triangle_distance((const float[3]){0, 3, 4}, a, b, c), sqrt(16.0 + 4.0), 1e-6); /* c */
    TV_CHECK_NEAR(tv_point_triangle_distance((const float[3]){0.5f, -1, 0}, a, b, c), 1.0, 1e-6);  /* edge ab */
    TV_CHECK_NEAR(tv_point_triangle_distance((const float[3]){-2, 0.5f, 1}, a, b, c), sqrt(5.0), 1e-6); /* ac */
    TV_CHECK_NEAR(tv_point_triangle_distance((const float[3]){1, 1, 0}, a, b, c), sqrt(0.5), 1e-6); /* edge bc */
    TV_CHECK_NEAR(tv_point_triangle_distance((const float[3]){0.25f, 0.25f, 0}, a, b, c), 0.0, 1e-6);
    /* a degenerate triangle (two equal vertices) is its segment */
    TV_CHECK_NEAR(tv_point_triangle_distance((const float[3]){0.5f, 2, 0}, a, b, b), 2.0, 1e-6);
}

static uint32_t g_rng = 12345u;
static float frand(float lo, float hi)
{
    g_rng = g_rng * 1664525u + 1013904223u;
    return lo + (hi - lo) * (float)(g_rng >> 8) / (float)(1u << 24);
}

static float brute(const scn_scene* s, const float p[3])
{
    float best = INFINITY;
    for (uint32_t t = 0; t < s->triangle_count; t++) {
        const float* v[3];
        for (int k = 0; k < 3; k++)
            v[k] = s->positions + 3 * (size_t)s->indices[3 * (size_t)t + (size_t)k];
        best = fminf(best, tv_point_triangle_distance(p, v[0], v[1], v[2]));
    }
    return best;
}

static void check_against_brute(const scn_scene* s, const tv_clearance_desc* desc)
{
    char err[256];
    tv_clearance* c = tv_clearance_create(s, desc, err, sizeof err);
    TV_CHECK(c != NULL);
    if (!c)
        return;
    float r = tv_clearance_radius(c);
    TV_CHECK_NEAR(r, desc->radius_m, 0.0);
    int within = 0, mismatches = 0;
    for (int i = 0; i < 400; i++) {
        /* the corridor and the rooms at head heights, plus points outside the bounds */
        float p[3] = {frand(-26, 26), frand(-0.5f, 3.5f), frand(-12, 12)};
        uint32_t tri;
        float got = tv_clearance_query(c, p, &tri), want = fminf(brute(s, p), r);
        within += tri != UINT32_MAX;
        if (fabsf(got - want) > 1e-5f)
            mismatches++;
        if (tri != UINT32_MAX) {
            const float* v[3];
            for (int k = 0; k < 3; k++)
                v[k] = s->positions + 3 * (size_t)s->indices[3 * (size_t)tri + (size_t)k];
            TV_CHECK_NEAR(tv_point_triangle_distance(p, v[0], v[1], v[2]), got, 1e-6);
        } else {
            TV_CHECK(got == r);
        }
    }
    TV_CHECK(mismatches == 0);
    TV_CHECK(within > 50 && within < 400); /* both cases were exercised */
    uint32_t tri = 0;
    TV_CHECK(tv_clearance_query(c, (const float[3]){500, 1, 500}, &tri) == r && tri == UINT32_MAX);
    tv_clearance_destroy(c);
}

static void test_grid_matches_brute_force(void)
{
    scn_scene s;
    char err[256];
    TV_CHECK(scn_load("builtin:interior", &s, err, sizeof err));
    check_against_brute(&s, &(tv_clearance_desc){.radius_m = 1.0f});
    check_against_brute(&s, &(tv_clearance_desc){.radius_m = 0.3f});
    /* 64 cells: each far larger than the radius, the same answers */
    check_against_brute(&s, &(tv_clearance_desc){.radius_m = 1.0f, .max_cells = 64});

    /* docs/scenes.md: corridor walls at z = +-1.5, ceiling at y = 3, no room near x = 0 */
    tv_clearance* c = tv_clearance_create(&s, &(tv_clearance_desc){.radius_m = 2.0f}, err, sizeof err);
    TV_CHECK(c != NULL);
    if (c) {
        TV_CHECK_NEAR(tv_clearance_query(c, (const float[3]){0, 1.7f, 0}, NULL), 1.3, 1e-5);
        TV_CHECK_NEAR(tv_clearance_query(c, (const float[3]){0, 1.0f, 1.2f}, NULL), 0.3, 1e-5);
        tv_clearance_destroy(c);
    }
    scn_scene_free(&s);
}

static void test_empty_scene(void)
{
    scn_scene s = {.name = "empty"};
    char err[256] = "";
    TV_CHECK(tv_clearance_create(&s, NULL, err, sizeof err) == NULL);
    TV_CHECK(err[0] != '\0');
}

int main(void)
{
    TV_TEST_RUN(test_point_triangle);
    TV_TEST_RUN(test_grid_matches_brute_force);
    TV_TEST_RUN(test_empty_scene);
    return tv_test_finish();
}
