/* test_mover.c - keyframe interpolation, posing, swept bounds, the
 * built-in movers and glTF animations, with answers known in closed form. */
#define _DEFAULT_SOURCE /* mkdtemp */
#include "mover.h"
#include "procedural.h"
#include "procgen.h"
#include "scene.h"
#include "scene_test_dir.h"
#include "test.h"

#include <float.h>
#include <math.h>

/* A scene of one unit cube mover [-0.5, 0.5]^3 (no bottom face: 10 triangles)
 * after a static ground quad; the caller's tracks (copied) drive it. */
typedef struct track_spec {
    int which;
    scn_interp interp;
    uint32_t count;
    const float* times;
    const float* values;
} track_spec;

static bool make_scene(scn_scene* s, const track_spec* tracks, int track_count)
{
    scn_builder b;
    scn_builder_init(&b, s, false);
    uint32_t mat = scn_gen_material(&b, "m", -1, 1, 1, 1, false);
    float o[3] = {-5, 0, -5}, u[3] = {0, 0, 10}, v[3] = {10, 0, 0};
    scn_gen_quad(&b, o, u, v, 1, 1, mat);
    scn_builder_mover_begin(&b);
    float lo[3] = {-0.5f, -0.5f, -0.5f}, hi[3] = {0.5f, 0.5f, 0.5f};
    scn_gen_box(&b, lo, hi, SCN_FACE_NO_BOTTOM, 0.0f, mat);
    scn_mover* m = scn_builder_mover_end(&b, "cube");
    for (int i = 0; m && i < track_count; i++) {
        const track_spec* t = &tracks[i];
        int w = t->which == SCN_TRACK_ROTATION ? 4 : 3;
        scn_track* tr = &m->track[t->which];
        tr->times = malloc(t->count * sizeof(float));
        tr->values = malloc(t->count * w * sizeof(float));
        memcpy(tr->times, t->times, t->count * sizeof(float));
        memcpy(tr->values, t->values, t->count * w * sizeof(float));
        tr->count = t->count;
        tr->interp = t->interp;
    }
    char err[256];
    bool ok = scn_builder_finish(&b, "test", err, sizeof err);
    if (!ok)
        printf("  %s\n", err);
    return ok;
}

/* World box of the mover's vertices as posed now. */
static void posed_box(const scn_scene* s, float mn[3], float mx[3])
{
    const scn_mover* m = &s->movers[0];
    for (int k = 0; k < 3; k++)
        mn[k] = FLT_MAX, mx[k] = -FLT_MAX;
    for (uint32_t v = 0; v < m->vertex_count; v++)
        for (int k = 0; k < 3; k++) {
            float p = s->positions[3 * (m->first_vertex + v) + k];
            mn[k] = fminf(mn[k], p), mx[k] = fmaxf(mx[k], p);
        }
}

static void test_layout(void)
{
    static const float t[2] = {0, 2}, v[6] = {0, 0, 0, 4, 0, 0};
    track_spec tr = {SCN_TRACK_TRANSLATION, SCN_INTERP_LINEAR, 2, t, v};
    scn_scene s;
    TV_CHECK(make_scene(&s, &tr, 1));
    TV_CHECK(s.mover_count == 1 && s.triangle_count == 12 && s.dynamic_triangle_count == 10);
    TV_CHECK(s.movers[0].first_triangle == 2 && s.movers[0].triangle_count == 10);
    TV_CHECK(s.movers[0].period_s == 2.0f);
    /* scene bounds hold the whole loop: x up to 4.5 */
    TV_CHECK_NEAR(s.bounds_max[0], 5.0f, 1e-6);
    TV_CHECK_NEAR(s.bounds_max[1], 0.5f, 1e-6);
    scn_scene_free(&s);
}

static void test_linear_step_loop(void)
{
    static const float t[3] = {0, 1, 2}, v[9] = {0, 0, 0, 2, 0, 0, 2, 4, 0};
    track_spec lin = {SCN_TRACK_TRANSLATION, SCN_INTERP_LINEAR, 3, t, v};
    scn_scene s;
    TV_CHECK(make_scene(&s, &lin, 1));
    float mn[3], mx[3];
    scn_scene_pose(&s, 0.25);
    posed_box(&s, mn, mx);
    TV_CHECK_NEAR(mn[0], 0.5f - 0.5f, 1e-6);
    scn_scene_pose(&s, 1.5);
    posed_box(&s, mn, mx);
    TV_CHECK_NEAR(mn[0], 1.5f, 1e-6);
    TV_CHECK_NEAR(mn[1], 1.5f, 1e-6);
    scn_scene_pose(&s, 2.25 + 2.0); /* loops: as at 0.25 */
    posed_box(&s, mn, mx);
    TV_CHECK_NEAR(mn[0], 0.0f, 1e-6);
    TV_CHECK_NEAR(mn[1], -0.5f, 1e-6);
    scn_scene_free(&s);

    track_spec step = {SCN_TRACK_TRANSLATION, SCN_INTERP_STEP, 3, t, v};
    TV_CHECK(make_scene(&s, &step, 1));
    scn_scene_pose(&s, 0.99);
    posed_box(&s, mn, mx);
    TV_CHECK_NEAR(mn[0], -0.5f, 1e-6);
    scn_scene_pose(&s, 1.0);
    posed_box(&s, mn, mx);
    TV_CHECK_NEAR(mn[0], 1.5f, 1e-6);
    TV_CHECK_NEAR(mn[1], -0.5f, 1e-6);
    scn_scene_free(&s);
}

static void test_rotation_scale_normals(void)
{
    float h = sinf(0.25f * 3.14159265f), c = cosf(0.25f * 3.14159265f);
    static const float t[2] = {0, 1};
    float q[8] = {0, 0, 0, 1, 0, h, 0, c}; /* 0 -> 90 degrees about +y */
    float sc[6] = {1, 1, 1, 3, 1, 1};
    track_spec tr[2] = {{SCN_TRACK_ROTATION, SCN_INTERP_LINEAR, 2, t, q},
                        {SCN_TRACK_SCALE, SCN_INTERP_LINEAR, 2, t, sc}};
    scn_scene s;
    TV_CHECK(make_scene(&s, tr, 2));
    scn_scene_pose(&s, 0.5); /* 45 degrees, scale x 2 */
    const scn_mover* m = &s.movers[0];
    int checked = 0;
    for (uint32_t v = 0; v < m->vertex_count; v++) {
        const float* r = m->rest + 6 * v;
        const float* p = s.positions + 3 * (m->first_vertex + v);
        const float* n = s.normals + 3 * (m->first_vertex + v);
        float a = 0.25f * 3.14159265f, x = 2.0f * r[0], z = r[2];
        TV_CHECK_NEAR(p[0], cosf(a) * x + sinf(a) * z, 1e-5);
        TV_CHECK_NEAR(p[2], -sinf(a) * x + cosf(a) * z, 1e-5);
        TV_CHECK_NEAR(p[1], r[1], 1e-6);
        if (r[3] > 0.5f) { /* a +x face: its normal turns with the body, unit length */
            TV_CHECK_NEAR(n[0], cosf(a), 1e-5);
            TV_CHECK_NEAR(n[2], -sinf(a), 1e-5);
            checked++;
        }
    }
    TV_CHECK(checked > 0);
    scn_scene_free(&s);
}

/* Every sampled pose lies in the bounds; with `exact`, the bounds are the
 * sampled hull itself (to the 2001 samples' spacing: the test paths move
 * under 4 m/s). */
static void check_bounds(scn_scene* s, double t0, double t1, bool exact, float max_slack)
{
    float bmin[3], bmax[3], smin[3] = {FLT_MAX, FLT_MAX, FLT_MAX}, smax[3] = {-FLT_MAX, -FLT_MAX, -FLT_MAX};
    scn_mover_bounds(s, 0, t0, t1, bmin, bmax);
    bool inside = true;
    for (int i = 0; i <= 2000; i++) {
        scn_scene_pose(s, t0 + (t1 - t0) * i / 2000.0);
        float mn[3], mx[3];
        posed_box(s, mn, mx);
        for (int k = 0; k < 3; k++) {
            inside = inside && mn[k] >= bmin[k] - 1e-5f && mx[k] <= bmax[k] + 1e-5f;
            smin[k] = fminf(smin[k], mn[k]), smax[k] = fmaxf(smax[k], mx[k]);
        }
    }
    TV_CHECK(inside);
    for (int k = 0; k < 3; k++) {
        float slack = fmaxf(smin[k] - bmin[k], bmax[k] - smax[k]);
        TV_CHECK(slack <= (exact ? 2e-3f : max_slack));
    }
}

static void test_bounds(void)
{
    static const float t[4] = {0, 1, 3, 4}, v[12] = {0, 0, 0, 3, 0, 0, 3, 0, 5, 0, 0, 0};
    track_spec lin = {SCN_TRACK_TRANSLATION, SCN_INTERP_LINEAR, 4, t, v};
    scn_scene s;
    TV_CHECK(make_scene(&s, &lin, 1));
    check_bounds(&s, 0.2, 0.7, true, 0);
    check_bounds(&s, 0.5, 2.0, true, 0);  /* across a key */
    check_bounds(&s, 3.5, 4.6, true, 0);  /* across the loop */
    check_bounds(&s, 1.0, 9.0, true, 0);  /* longer than a loop */
    scn_scene_free(&s);

    float h = sinf(0.5f * 3.0f), c = cosf(0.5f * 3.0f); /* 0 -> 3 rad about a tilted axis */
    float ax[3] = {0.3f, 0.9f, 0.316f}, len = sqrtf(0.09f + 0.81f + 0.099856f);
    float q[8] = {0, 0, 0, 1, h * ax[0] / len, h * ax[1] / len, h * ax[2] / len, c};
    static const float rt[2] = {0, 2}, tv[6] = {0, 0, 0, 2, 1, 0}, sc[6] = {1, 1, 1, 0.5f, 2, 1};
    track_spec rot[3] = {{SCN_TRACK_ROTATION, SCN_INTERP_LINEAR, 2, rt, q},
                         {SCN_TRACK_TRANSLATION, SCN_INTERP_LINEAR, 2, rt, tv},
                         {SCN_TRACK_SCALE, SCN_INTERP_LINEAR, 2, rt, sc}};
    TV_CHECK(make_scene(&s, rot, 3));
    /* slack: per 5-degree sub-step (57 ms here) the translation's and the
     * rotating corner's boxes are added, about their motion in it (6 cm) */
    check_bounds(&s, 0.1, 0.9, false, 0.08f);
    check_bounds(&s, 1.5, 2.7, false, 0.08f);
    scn_scene_free(&s);

    track_spec step = {SCN_TRACK_ROTATION, SCN_INTERP_STEP, 2, rt, q};
    TV_CHECK(make_scene(&s, &step, 1));
    check_bounds(&s, 0.0, 1.0, true, 0); /* the first key's pose only */
    check_bounds(&s, 1.5, 2.5, false, 1.0f);
    scn_scene_free(&s);
}

static void test_bad_tracks(void)
{
    static const float t[2] = {1, 1}, v[6] = {0};
    track_spec tr = {SCN_TRACK_TRANSLATION, SCN_INTERP_LINEAR, 2, t, v};
    scn_scene s;
    TV_CHECK(!make_scene(&s, &tr, 1)); /* times not increasing */
    TV_CHECK(s.triangle_count == 0 && s.movers == NULL);
    static const float t2[2] = {0, 1}, q[8] = {0};
    track_spec zero = {SCN_TRACK_ROTATION, SCN_INTERP_LINEAR, 2, t2, q};
    TV_CHECK(!make_scene(&s, &zero, 1));
}

/* Static arrays equal over the first `n` triangles and their vertices. */
static bool same_static(const scn_scene* a, const scn_scene* b, uint32_t tris)
{
    uint32_t verts = 0;
    for (uint32_t i = 0; i < 3 * tris; i++)
        verts = a->indices[i] + 1 > verts ? a->indices[i] + 1 : verts;
    return a->triangle_count >= tris && b->triangle_count >= tris &&
           memcmp(a->indices, b->indices, 3 * tris * sizeof(uint32_t)) == 0 &&
           memcmp(a->positions, b->positions, 3 * verts * sizeof(float)) == 0 &&
           memcmp(a->tri_material, b->tri_material, tris * sizeof(uint32_t)) == 0;
}

static void test_builtin_movers(void)
{
    char err[256];
    scn_scene plain, zero, moving;
    TV_CHECK(scn_load("builtin:city", &plain, err, sizeof err));
    TV_CHECK(scn_load("builtin:city?movers=0", &zero, err, sizeof err));
    TV_CHECK(scn_load("builtin:city?movers=12", &moving, err, sizeof err));
    TV_CHECK(zero.triangle_count == plain.triangle_count && zero.vertex_count == plain.vertex_count &&
             zero.material_count == plain.material_count && zero.mover_count == 0 &&
             zero.dynamic_triangle_count == 0 && same_static(&zero, &plain, plain.triangle_count));
    TV_CHECK(moving.mover_count == 12 && moving.dynamic_triangle_count == 120 &&
             moving.triangle_count == plain.triangle_count + 120 && same_static(&moving, &plain, plain.triangle_count));
    /* every mover keeps to a street's clear space over its whole loop */
    for (uint32_t i = 0; i < moving.mover_count; i++) {
        float mn[3], mx[3];
        scn_mover_bounds(&moving, i, 0.0, moving.movers[i].period_s, mn, mx);
        TV_CHECK(moving.movers[i].period_s > 0.0f && mn[1] >= 0.0f && mx[1] <= SCN_CITY_STREET_CLEAR_HEIGHT);
        bool clear = false;
        for (int axis = 0; axis < 2; axis++) { /* the box within 4 m of one centreline */
            int k = axis ? 2 : 0;
            float line = SCN_CITY_BLOCK_PITCH * roundf(0.5f * (mn[k] + mx[k]) / SCN_CITY_BLOCK_PITCH);
            clear = clear || (mn[k] >= line - SCN_CITY_STREET_CLEAR_HALF_WIDTH &&
                              mx[k] <= line + SCN_CITY_STREET_CLEAR_HALF_WIDTH);
        }
        TV_CHECK(clear);
    }
    scn_scene_free(&plain);
    scn_scene_free(&zero);
    scn_scene_free(&moving);

    scn_scene room;
    TV_CHECK(scn_load("builtin:interior?movers=9", &room, err, sizeof err));
    TV_CHECK(room.mover_count == 9);
    float mn[3], mx[3];
    scn_mover_bounds(&room, 0, 0.0, room.movers[0].period_s, mn, mx); /* door of room x = -18, +z */
    TV_CHECK(mn[0] >= -18.0f - 1.0f && mx[0] <= -18.0f + 1.0f && mn[2] >= 1.5f && mx[2] <= 6.5f);
    scn_scene_pose(&room, room.movers[0].track[SCN_TRACK_ROTATION].times[1]); /* fully open: along +z */
    float pmn[3], pmx[3];
    posed_box(&room, pmn, pmx);
    TV_CHECK(pmx[2] - pmn[2] > 1.1f && pmx[0] - pmn[0] < 0.1f);
    scn_scene_free(&room);

    const char* bad[] = {"builtin:city?movers=-1", "builtin:city?movers=10001", "builtin:city?movers=1&movers=2",
                         "builtin:unit?movers=1", "builtin:city?movers=x"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        scn_scene s;
        TV_CHECK(!scn_load(bad[i], &s, err, sizeof err) && strstr(err, "builtin:") != NULL);
    }
}

static char dir[256];

/* A glTF of one triangle (0,0,0) (1,0,0) (0,1,0) on five nodes: "static"
 * (a morph-weights channel only: stays static), "slide" (translation LINEAR
 * 0 -> (2,0,0) -> (2,2,0) at t = 0, 1, 2), "spin" under "arm" (0,5,0):
 * scale 2, rotation STEP identity -> 90 deg about z -> identity, and "cubic"
 * (CUBICSPLINE translation, values (0,0,0) (0,0,3) (0,0,6)). `times` are the
 * three key times. */
static void write_animated(char* path, size_t size, const char* name, const float times[3])
{
    float bin[60] = {0, 0, 0, 1, 0, 0, 0, 1, 0}; /* 240 bytes */
    memcpy(bin + 9, times, 3 * sizeof(float));
    const float slide[9] = {0, 0, 0, 2, 0, 0, 2, 2, 0};
    float h = sqrtf(0.5f);
    const float spin[12] = {0, 0, 0, 1, 0, 0, h, h, 0, 0, 0, 1};
    memcpy(bin + 12, slide, sizeof slide);
    memcpy(bin + 21, spin, sizeof spin);
    for (int k = 0; k < 3; k++) /* in-tangent, value, out-tangent per key */
        bin[33 + 9 * k + 3 + 2] = 3.0f * k, bin[33 + 9 * k] = 7.0f, bin[33 + 9 * k + 6] = -7.0f;
    char bin_path[300];
    snprintf(bin_path, sizeof bin_path, "%s/%s.bin", dir, name);
    FILE* f = fopen(bin_path, "wb");
    TV_CHECK(f && fwrite(bin, sizeof bin, 1, f) == 1);
    if (f)
        fclose(f);
    snprintf(path, size, "%s/%s.gltf", dir, name);
    f = fopen(path, "w");
    TV_CHECK(f != NULL);
    if (!f)
        return;
    fprintf(f,
            "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0,1,2,4]}],"
            "\"nodes\":[{\"name\":\"static\",\"mesh\":0,\"translation\":[10,0,0]},"
            "{\"name\":\"slide\",\"mesh\":0,\"translation\":[0,0,-5]},"
            "{\"name\":\"arm\",\"translation\":[0,5,0],\"children\":[3]},"
            "{\"name\":\"spin\",\"mesh\":0,\"scale\":[2,2,2]},{\"name\":\"cubic\",\"mesh\":0}],"
            "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],"
            "\"buffers\":[{\"uri\":\"%s.bin\",\"byteLength\":240}],"
            "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":36},"
            "{\"buffer\":0,\"byteOffset\":36,\"byteLength\":12},{\"buffer\":0,\"byteOffset\":48,\"byteLength\":36},"
            "{\"buffer\":0,\"byteOffset\":84,\"byteLength\":48},{\"buffer\":0,\"byteOffset\":132,\"byteLength\":108}],"
            "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\","
            "\"min\":[0,0,0],\"max\":[1,1,0]},"
            "{\"bufferView\":1,\"componentType\":5126,\"count\":3,\"type\":\"SCALAR\",\"min\":[0],\"max\":[2]},"
            "{\"bufferView\":2,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
            "{\"bufferView\":3,\"componentType\":5126,\"count\":3,\"type\":\"VEC4\"},"
            "{\"bufferView\":4,\"componentType\":5126,\"count\":9,\"type\":\"VEC3\"}],"
            "\"animations\":[{\"channels\":[{\"sampler\":0,\"target\":{\"node\":1,\"path\":\"translation\"}},"
            "{\"sampler\":2,\"target\":{\"node\":4,\"path\":\"translation\"}},"
            "{\"sampler\":3,\"target\":{\"node\":0,\"path\":\"weights\"}}],"
            "\"samplers\":[{\"input\":1,\"output\":2},{\"input\":1,\"output\":3,\"interpolation\":\"STEP\"},"
            "{\"input\":1,\"output\":4,\"interpolation\":\"CUBICSPLINE\"},{\"input\":1,\"output\":1}]},"
            "{\"channels\":[{\"sampler\":0,\"target\":{\"node\":3,\"path\":\"rotation\"}}],"
            "\"samplers\":[{\"input\":1,\"output\":3,\"interpolation\":\"STEP\"}]}]}",
            name);
    fclose(f);
}

/* Position of corner c of the triangle of mover `name`. */
static const float* corner(const scn_scene* s, const char* name, int c)
{
    for (uint32_t i = 0; i < s->mover_count; i++)
        if (strcmp(s->movers[i].name, name) == 0)
            return s->positions + 3 * s->indices[3 * s->movers[i].first_triangle + c];
    return NULL;
}

static bool near3(const float* p, float x, float y, float z)
{
    return p && fabsf(p[0] - x) < 1e-5f && fabsf(p[1] - y) < 1e-5f && fabsf(p[2] - z) < 1e-5f;
}

static void test_gltf_animation(void)
{
    char path[300], err[512];
    const float times[3] = {0, 1, 2};
    write_animated(path, sizeof path, "animated", times);
    scn_scene s;
    TV_CHECK(scn_load(path, &s, err, sizeof err));
    if (s.triangle_count == 0) {
        printf("  %s\n", err);
        return;
    }
    TV_CHECK(s.mover_count == 3 && s.triangle_count == 4 && s.dynamic_triangle_count == 3);
    /* the static triangle first, at (10, 0, 0) */
    TV_CHECK(near3(s.positions + 3 * s.indices[0], 10, 0, 0));
    scn_scene_pose(&s, 0.5);
    TV_CHECK(near3(corner(&s, "slide", 0), 1, 0, 0)); /* the channel replaces the node's translation */
    TV_CHECK(near3(corner(&s, "spin", 1), 2, 5, 0));  /* STEP: still the first key */
    TV_CHECK(near3(corner(&s, "cubic", 0), 0, 0, 1.5f));
    scn_scene_pose(&s, 1.5);
    TV_CHECK(near3(corner(&s, "slide", 0), 2, 1, 0));
    TV_CHECK(near3(corner(&s, "spin", 1), 0, 7, 0)); /* (2,0,0) turned 90 deg about z, under the arm */
    scn_scene_pose(&s, 2.5); /* loops with the last key time, 2 s */
    TV_CHECK(near3(corner(&s, "slide", 0), 1, 0, 0));
    scn_scene_free(&s);

    const float bad[3] = {0, 1, 1};
    write_animated(path, sizeof path, "bad_times", bad);
    TV_CHECK(!scn_load(path, &s, err, sizeof err) && strstr(err, "bad_times.gltf: ") && strstr(err, "increasing"));
}

int main(void)
{
    if (!scene_test_dir_create(dir, sizeof dir, "tv_scene_mover"))
        return 1;
    TV_TEST_RUN(test_gltf_animation);
    TV_TEST_RUN(test_layout);
    TV_TEST_RUN(test_linear_step_loop);
    TV_TEST_RUN(test_rotation_scale_normals);
    TV_TEST_RUN(test_bounds);
    TV_TEST_RUN(test_bad_tracks);
    TV_TEST_RUN(test_builtin_movers);
    scene_test_dir_remove(dir);
    return tv_test_finish();
}
