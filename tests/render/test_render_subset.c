/* Subset renders: drawing every triangle except an occluded one is
 * bit-identical to the full render (colour, depth, ids), including
 * equal-depth ties; dropping a visible triangle changes exactly its pixels,
 * and those are the false-negative pixels. */
#include "mesh_shared.h"
#include "image_compare.h"
#include "render_fixture.h"
#include "test.h"

#include <stdlib.h>
#include <string.h>

#define W 96
#define H 64
#define N (W * H)

static rnd_context* ctx;
static rnd_gpu_scene* gpu;
static rnd_target* target;
static scn_scene scene;
static uint32_t hidden_tri, partial_tri, tie_first, tie_second;

typedef struct frame {
    uint8_t rgba[N * 4];
    uint32_t ids[N];
    float depth[N];
} frame;

static void draw(const uint32_t* ids, uint32_t count, frame* f)
{
    const rnd_camera cam = fx_camera();
    TV_CHECK(rnd_draw(ctx, target, gpu, &cam, ids, count, NULL));
    TV_CHECK(rnd_target_read_color(ctx, target, f->rgba) && rnd_target_read_ids(ctx, target, f->ids) &&
             rnd_target_read_depth(ctx, target, f->depth));
}

/* All triangle ids except [skip, skip + 2), in descending order so the
 * renderer's internal sort is exercised. */
static uint32_t all_but_quad(uint32_t skip, uint32_t* out)
{
    uint32_t n = 0;
    for (uint32_t t = scene.triangle_count; t-- > 0;)
        if (t < skip || t >= skip + 2)
            out[n++] = t;
    return n;
}

/* Draws the full scene into full and the scene without quad `skip` into
 * sub; returns the subset's ids (in ids) and their count. */
static uint32_t full_and_without(uint32_t skip, frame* full, frame* sub, uint32_t* ids)
{
    draw(NULL, 0, full);
    uint32_t n = all_but_quad(skip, ids);
    draw(ids, n, sub);
    return n;
}

static void build_scene(void)
{
    fx_scene_init(&scene, 6, 5);
    uint32_t red = fx_material(&scene, 1, 0, 0, SCN_ALPHA_OPAQUE, false, -1);
    uint32_t blue = fx_material(&scene, 0, 0, 1, SCN_ALPHA_OPAQUE, false, -1);
    uint32_t green = fx_material(&scene, 0, 1, 0, SCN_ALPHA_OPAQUE, false, -1);
    uint32_t white = fx_material(&scene, 1, 1, 1, SCN_ALPHA_OPAQUE, false, -1);
    uint32_t grey = fx_material(&scene, 0.3f, 0.3f, 0.3f, SCN_ALPHA_OPAQUE, false, -1);
    fx_quad_z(&scene, -1, -1, 1, 1, -5, red);                 /* occluder */
    hidden_tri = fx_quad_z(&scene, -0.5f, -0.5f, 0.5f, 0.5f, -8, blue); /* fully behind it */
    partial_tri = fx_quad_z(&scene, 0.5f, -0.5f, 2.5f, 0.5f, -6, green); /* half behind it */
    /* two coplanar quads: the lower id must win in full and subset renders */
    tie_first = fx_quad_z(&scene, -3, 1.2f, -1.5f, 2, -6, white);
    tie_second = fx_quad_z(&scene, -3, 1.2f, -1.5f, 2, -6, grey);
    fx_quad_z(&scene, -20, -20, 20, 20, -30, grey); /* backdrop */
}

static void subset_without_occluded_is_identical(void)
{
    frame* full = malloc(sizeof *full);
    frame* sub = malloc(sizeof *sub);
    uint32_t ids[16];
    full_and_without(hidden_tri, full, sub, ids);
    TV_CHECK(memcmp(full->rgba, sub->rgba, sizeof full->rgba) == 0);
    TV_CHECK(memcmp(full->ids, sub->ids, sizeof full->ids) == 0);
    TV_CHECK(memcmp(full->depth, sub->depth, sizeof full->depth) == 0);
    /* the scene is set up as intended: the hidden quad is nowhere, the tie
     * goes to the first quad, which is visible */
    size_t hidden = 0, first = 0, second = 0;
    for (int i = 0; i < N; i++) {
        hidden += full->ids[i] == hidden_tri || full->ids[i] == hidden_tri + 1;
        first += full->ids[i] == tie_first || full->ids[i] == tie_first + 1;
        second += full->ids[i] == tie_second || full->ids[i] == tie_second + 1;
    }
    TV_CHECK(hidden == 0 && first > 20 && second == 0);
    TV_CHECK(isinf(rnd_psnr_rgb8(full->rgba, sub->rgba, N, 4)));
    free(full);
    free(sub);
}

static void subset_missing_visible_triangle_differs_in_its_pixels(void)
{
    frame* full = malloc(sizeof *full);
    frame* sub = malloc(sizeof *sub);
    uint32_t ids[16];
    uint32_t n = full_and_without(partial_tri, full, sub, ids);
    uint8_t in_set[16] = {0};
    for (uint32_t i = 0; i < n; i++)
        in_set[ids[i]] = 1;
    size_t own = 0, changed_elsewhere = 0, unchanged_own = 0;
    for (int i = 0; i < N; i++) {
        bool mine = full->ids[i] == partial_tri || full->ids[i] == partial_tri + 1;
        bool differs = memcmp(full->rgba + 4 * i, sub->rgba + 4 * i, 4) != 0 || full->ids[i] != sub->ids[i];
        own += mine;
        changed_elsewhere += !mine && differs;
        unchanged_own += mine && full->ids[i] == sub->ids[i];
    }
    TV_CHECK(own > 50);
    TV_CHECK(changed_elsewhere == 0 && unchanged_own == 0);
    TV_CHECK(rnd_count_fn_pixels(full->ids, N, in_set, scene.triangle_count) == own);
    /* green quad over a grey backdrop: every one of its pixels changes colour */
    TV_CHECK(rnd_count_diff_pixels(full->rgba, sub->rgba, N, 4, 0) == own);
    TV_CHECK(rnd_psnr_rgb8(full->rgba, sub->rgba, N, 4) < 40.0);
    free(full);
    free(sub);
}

static void subset_buffer_grows_and_empty_subset_clears(void)
{
    /* more ids than the initial buffer holds (duplicates are allowed) */
    uint32_t count = 10000;
    uint32_t* ids = malloc(count * sizeof *ids);
    for (uint32_t i = 0; i < count; i++)
        ids[i] = i % scene.triangle_count;
    frame* full = malloc(sizeof *full);
    frame* sub = malloc(sizeof *sub);
    draw(NULL, 0, full);
    draw(ids, count, sub);
    TV_CHECK(memcmp(full->ids, sub->ids, sizeof full->ids) == 0);
    TV_CHECK(memcmp(full->rgba, sub->rgba, sizeof full->rgba) == 0);
    draw(ids, 0, sub);
    size_t empty = 0;
    for (int i = 0; i < N; i++)
        empty += sub->ids[i] == TV_NO_TRIANGLE;
    TV_CHECK(empty == N);
    free(ids);
    free(full);
    free(sub);
}

/* Growing the id buffer twice on a context without the validation layer:
 * lavapipe can hand the new buffer the freed one's handle value, and the
 * layer's unique handle wrapping once hid a draw set left pointing at the
 * freed buffer. The first, smaller draw fills the buffer with one hidden
 * triangle, so a stale binding would show in the second draw. */
static void subset_buffer_regrows_without_validation(void)
{
    char err[256];
    rnd_context* plain = rnd_create(&(rnd_desc){.validation = -1}, err, sizeof err);
    rnd_gpu_scene* g = plain ? rnd_scene_create(plain, &scene, err, sizeof err) : NULL;
    rnd_target* t = g ? rnd_target_create(plain, W, H, err, sizeof err) : NULL;
    TV_CHECK(t != NULL);
    uint32_t count = 40000;
    uint32_t* ids = malloc(count * sizeof *ids);
    frame* full = malloc(sizeof *full);
    frame* sub = malloc(sizeof *sub);
    const rnd_camera cam = fx_camera();
    for (uint32_t i = 0; i < count; i++)
        ids[i] = hidden_tri;
    bool ok = t && rnd_draw(plain, t, g, &cam, NULL, 0, NULL) && rnd_target_read_color(plain, t, full->rgba) &&
              rnd_draw(plain, t, g, &cam, ids, 6000, NULL);
    for (uint32_t i = 0; i < count; i++)
        ids[i] = i % scene.triangle_count;
    ok = ok && rnd_draw(plain, t, g, &cam, ids, count, NULL) && rnd_target_read_color(plain, t, sub->rgba);
    TV_CHECK(ok);
    TV_CHECK(ok && memcmp(full->rgba, sub->rgba, sizeof full->rgba) == 0);
    if (t)
        rnd_target_destroy(plain, t);
    if (g)
        rnd_scene_destroy(plain, g);
    if (plain)
        rnd_destroy(plain);
    free(ids);
    free(full);
    free(sub);
}

static void bad_id_is_rejected(void)
{
    const rnd_camera cam = fx_camera();
    const uint32_t ids[3] = {0, 1, scene.triangle_count};
    uint32_t out[N];
    TV_CHECK(!rnd_draw(ctx, target, gpu, &cam, ids, 3, NULL));
    /* nothing was drawn, so there is nothing to read back */
    TV_CHECK(!rnd_target_read_ids(ctx, target, out));
}

int main(void)
{
    char err[256];
    ctx = fx_context();
    build_scene();
    gpu = rnd_scene_create(ctx, &scene, err, sizeof err);
    target = rnd_target_create(ctx, W, H, err, sizeof err);
    if (!gpu || !target) {
        fprintf(stderr, "set-up: %s\n", err);
        return 1;
    }
    TV_TEST_RUN(subset_without_occluded_is_identical);
    TV_TEST_RUN(subset_missing_visible_triangle_differs_in_its_pixels);
    TV_TEST_RUN(subset_buffer_grows_and_empty_subset_clears);
    TV_TEST_RUN(subset_buffer_regrows_without_validation);
    TV_TEST_RUN(bad_id_is_rejected);
    rnd_target_destroy(ctx, target);
    rnd_scene_destroy(ctx, gpu);
    scn_scene_free(&scene);
    TV_CHECK(rnd_validation_message_count(ctx) == 0);
    rnd_destroy(ctx);
    return tv_test_finish();
}
