/* The mesh pass on the built-in scenes: visibility known from the scene
 * contract (builtin:unit), subset equality on a real scene, our PSNR against
 * OpenImageIO's, and golden images.
 *
 * Golden images live in tests/render/golden/<scene>.png (320x180 RGB, camera
 * fixed below) and <scene>-ids.png (the triangle id of each pixel as its four
 * RGBA bytes, least significant first). The id buffer must match exactly:
 * rasterisation (coverage, depth test, top-left rule) leaves no room for
 * rounding. The colour must reach GOLDEN_MIN_PSNR, which absorbs texture
 * filtering and blending differences between llvmpipe versions but not a
 * changed scene, camera or shading. Regenerate both after an intended change
 * with   TRIMVR_UPDATE_GOLDEN=1 ctest -R render_scenes
 * On a mismatch the render is written to <build>/tests/render/<scene>.actual.png
 * (and -ids.actual.png). */
#include "mesh_shared.h"
#include "image_compare.h"
#include "image_io.h"
#include "procedural.h"
#include "render_fixture.h"
#include "test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 320
#define H 180
#define N (W * H)
/* An RMS error of one 8-bit level is 20 log10(255) = 48.1 dB: room for
 * rounding in filtering and blending (llvmpipe's vector width follows the
 * CPU), none for a visible change. Measured: inf (bit-identical) in repeated
 * runs on Debian 12's llvmpipe 15.0.6 (docs/quality.md). */
#define GOLDEN_MIN_PSNR 48.0

static rnd_context* ctx;
static rnd_target* target;

typedef struct loaded {
    scn_scene scene;
    rnd_gpu_scene* gpu;
} loaded;

static bool load(const char* spec, loaded* out)
{
    char err[512];
    if (!scn_load(spec, &out->scene, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return false;
    }
    out->gpu = rnd_scene_create(ctx, &out->scene, err, sizeof err);
    if (!out->gpu)
        fprintf(stderr, "%s\n", err);
    return out->gpu != NULL;
}

static void unload(loaded* l)
{
    rnd_scene_destroy(ctx, l->gpu);
    scn_scene_free(&l->scene);
}

/* builtin:unit's contract viewpoint: (0, 1.5, 0) looking down -Z */
static rnd_camera unit_camera(void)
{
    return (rnd_camera){.position = {0, 1.5f, 0}, .orientation = {0, 0, 0, 1}, .fov_y_deg = 60, .near_m = 0.05f,
                        .far_m = 100};
}

/* builtin:interior: in the corridor near its west end, looking along +X */
static rnd_camera interior_camera(void)
{
    const float s = sqrtf(0.5f);
    return (rnd_camera){.position = {-21, 1.6f, 0.4f}, .orientation = {0, -s, 0, s}, .fov_y_deg = 70,
                        .near_m = 0.05f, .far_m = 100};
}

static size_t pixels_of(const uint32_t* ids, uint32_t first, uint32_t count)
{
    size_t n = 0;
    for (int i = 0; i < N; i++)
        n += ids[i] >= first && ids[i] < first + count;
    return n;
}

/* Every triangle id except those in [skip_first, skip_first + skip_count). */
static uint32_t* ids_without(uint32_t triangle_count, uint32_t skip_first, uint32_t skip_count, uint32_t* n)
{
    uint32_t* ids = malloc(triangle_count * sizeof *ids);
    *n = 0;
    for (uint32_t t = 0; t < triangle_count; t++)
        if (t < skip_first || t >= skip_first + skip_count)
            ids[(*n)++] = t;
    return ids;
}

static void unit_visibility_and_subsets(void)
{
    loaded l;
    if (!load("builtin:unit", &l)) {
        TV_CHECK(!"builtin:unit loads");
        return;
    }
    uint32_t b_first, b_count, c_first, c_count, wall_first, wall_count;
    TV_CHECK(scn_unit_object("box_b", &b_first, &b_count) && scn_unit_object("box_c", &c_first, &c_count) &&
             scn_unit_object("wall", &wall_first, &wall_count));
    const rnd_camera cam = unit_camera();
    uint32_t* full_ids = malloc(N * sizeof *full_ids);
    uint32_t* sub_ids = malloc(N * sizeof *sub_ids);
    uint8_t* full_rgba = malloc(N * 4);
    uint8_t* sub_rgba = malloc(N * 4);
    TV_CHECK(rnd_draw(ctx, target, l.gpu, &cam, NULL, 0, NULL) && rnd_target_read_ids(ctx, target, full_ids) &&
             rnd_target_read_color(ctx, target, full_rgba));
    TV_CHECK(pixels_of(full_ids, b_first, b_count) == 0);
    TV_CHECK(pixels_of(full_ids, c_first, c_count) > 100);
    TV_CHECK(pixels_of(full_ids, wall_first, wall_count) > 1000);

    /* without the hidden box: bit-identical */
    uint32_t n;
    uint32_t* ids = ids_without(l.scene.triangle_count, b_first, b_count, &n);
    TV_CHECK(rnd_draw(ctx, target, l.gpu, &cam, ids, n, NULL) && rnd_target_read_ids(ctx, target, sub_ids) &&
             rnd_target_read_color(ctx, target, sub_rgba));
    TV_CHECK(memcmp(full_ids, sub_ids, N * sizeof *sub_ids) == 0 && memcmp(full_rgba, sub_rgba, N * 4) == 0);
    free(ids);

    /* without the visible box: exactly its pixels are false negatives, and
     * our PSNR agrees with OpenImageIO's */
    ids = ids_without(l.scene.triangle_count, c_first, c_count, &n);
    TV_CHECK(rnd_draw(ctx, target, l.gpu, &cam, ids, n, NULL) && rnd_target_read_ids(ctx, target, sub_ids) &&
             rnd_target_read_color(ctx, target, sub_rgba));
    uint8_t* in_set = calloc(l.scene.triangle_count, 1);
    for (uint32_t i = 0; i < n; i++)
        in_set[ids[i]] = 1;
    size_t c_pixels = pixels_of(full_ids, c_first, c_count);
    TV_CHECK(rnd_count_fn_pixels(full_ids, N, in_set, l.scene.triangle_count) == c_pixels);
    size_t differing = 0;
    for (int i = 0; i < N; i++)
        differing += full_ids[i] != sub_ids[i];
    TV_CHECK(differing == c_pixels);
    uint8_t* a = malloc(N * 3);
    uint8_t* b = malloc(N * 3);
    for (int i = 0; i < N; i++)
        for (int c = 0; c < 3; c++) {
            a[3 * i + c] = full_rgba[4 * i + c];
            b[3 * i + c] = sub_rgba[4 * i + c];
        }
    double ours = rnd_psnr_rgb8(full_rgba, sub_rgba, N, 4), oiio = 0;
    char err[256];
    bool compared = scn_image_psnr_oiio(a, b, W, H, &oiio, err, sizeof err);
    if (!compared)
        fprintf(stderr, "%s\n", err);
    TV_CHECK(compared);
    TV_CHECK(isfinite(ours) && ours > 10);
    TV_CHECK_NEAR(ours, oiio, 1e-4);
    TV_CHECK(scn_image_psnr_oiio(a, a, W, H, &oiio, err, sizeof err) && isinf(oiio));
    TV_CHECK(isinf(rnd_psnr_rgb8(a, a, N, 3)));
    free(a);
    free(b);
    free(in_set);
    free(ids);
    free(full_ids);
    free(sub_ids);
    free(full_rgba);
    free(sub_rgba);
    unload(&l);
}

/* Renders spec from cam and compares with (or, with TRIMVR_UPDATE_GOLDEN=1,
 * rewrites) tests/render/golden/<name>.png. */
static void golden(const char* spec, const char* name, rnd_camera cam)
{
    const char* source = getenv("TRIMVR_SOURCE_DIR");
    if (!source) {
        TV_CHECK(!"TRIMVR_SOURCE_DIR is set (ctest sets it)");
        return;
    }
    loaded l;
    if (!load(spec, &l)) {
        TV_CHECK(!"scene loads");
        return;
    }
    uint8_t* rgba = malloc(N * 4);
    uint8_t* rgb = malloc(N * 3);
    uint8_t* id_bytes = malloc(N * 4);
    uint32_t* ids = malloc(N * sizeof *ids);
    TV_CHECK(rnd_draw(ctx, target, l.gpu, &cam, NULL, 0, NULL) && rnd_target_read_color(ctx, target, rgba) &&
             rnd_target_read_ids(ctx, target, ids));
    for (int i = 0; i < N; i++) {
        memcpy(rgb + 3 * i, rgba + 4 * i, 3);
        for (int b = 0; b < 4; b++)
            id_bytes[4 * i + b] = (uint8_t)(ids[i] >> (8 * b));
    }
    char path[1024], id_path[1024], err[1024];
    snprintf(path, sizeof path, "%s/tests/render/golden/%s.png", source, name);
    snprintf(id_path, sizeof id_path, "%s/tests/render/golden/%s-ids.png", source, name);
    const char* update = getenv("TRIMVR_UPDATE_GOLDEN");
    if (update && strcmp(update, "1") == 0) {
        TV_CHECK(scn_image_write_png(path, rgb, W, H, 3, err, sizeof err));
        TV_CHECK(scn_image_write_png(id_path, id_bytes, W, H, 4, err, sizeof err));
        printf("wrote %s and %s\n", path, id_path);
    } else {
        uint8_t* expected_ids = NULL;
        uint32_t iw = 0, ih = 0;
        bool read_ids = scn_image_read(id_path, &expected_ids, &iw, &ih, err, sizeof err);
        if (!read_ids)
            fprintf(stderr, "%s\n", err);
        TV_CHECK(read_ids && iw == W && ih == H);
        int differ = 0;
        for (int i = 0; read_ids && iw == W && ih == H && i < N; i++)
            differ += memcmp(id_bytes + 4 * i, expected_ids + 4 * i, 4) != 0;
        printf("%s: %d of %d pixels with another triangle id than the golden\n", name, differ, N);
        TV_CHECK(read_ids && differ == 0);
        if (differ) {
            snprintf(id_path, sizeof id_path, "%s-ids.actual.png", name);
            scn_image_write_png(id_path, id_bytes, W, H, 4, err, sizeof err);
        }
        scn_image_free(expected_ids);
        uint8_t* expected = NULL;
        uint32_t w = 0, h = 0;
        bool read = scn_image_read(path, &expected, &w, &h, err, sizeof err);
        if (!read)
            fprintf(stderr, "%s\n", err);
        TV_CHECK(read && w == W && h == H);
        double psnr = read && w == W && h == H ? rnd_psnr_rgb8(rgba, expected, N, 4) : 0.0;
        printf("%s: PSNR vs golden %.2f dB\n", name, psnr);
        TV_CHECK(psnr >= GOLDEN_MIN_PSNR);
        if (psnr < GOLDEN_MIN_PSNR) {
            snprintf(path, sizeof path, "%s.actual.png", name);
            scn_image_write_png(path, rgb, W, H, 3, err, sizeof err);
        }
        scn_image_free(expected);
    }
    free(rgba);
    free(rgb);
    free(id_bytes);
    free(ids);
    unload(&l);
}

static void golden_unit(void) { golden("builtin:unit", "unit", unit_camera()); }
static void golden_interior(void) { golden("builtin:interior", "interior", interior_camera()); }

int main(void)
{
    char err[256];
    ctx = fx_context();
    target = rnd_target_create(ctx, W, H, err, sizeof err);
    if (!target) {
        fprintf(stderr, "set-up: %s\n", err);
        return 1;
    }
    TV_TEST_RUN(unit_visibility_and_subsets);
    TV_TEST_RUN(golden_unit);
    TV_TEST_RUN(golden_interior);
    rnd_target_destroy(ctx, target);
    TV_CHECK(rnd_validation_message_count(ctx) == 0);
    rnd_destroy(ctx);
    return tv_test_finish();
}
