/* image_io: PNG/EXR round trips, errors, and OpenImageIO's PSNR against the textbook formula. */
#define _DEFAULT_SOURCE /* mkdtemp */
#include "image_io.h"
#include "scene_test_dir.h"
#include "test.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char dir[256];

static void test_png_roundtrip(void)
{
    uint8_t px[3 * 3 * 4];
    for (int i = 0; i < 36; i++)
        px[i] = (uint8_t)(i * 7);
    char path[512], err[512];
    snprintf(path, sizeof path, "%s/rgba.png", dir);
    TV_CHECK(scn_image_write_png(path, px, 3, 3, 4, err, sizeof err));
    uint8_t* back = NULL;
    uint32_t w = 0, h = 0;
    TV_CHECK(scn_image_read(path, &back, &w, &h, err, sizeof err));
    TV_CHECK(w == 3 && h == 3);
    if (back)
        TV_CHECK(memcmp(back, px, sizeof px) == 0);
    scn_image_free(back);
    /* the same bytes through the memory reader */
    FILE* f = fopen(path, "rb");
    uint8_t file[4096];
    size_t n = f ? fread(file, 1, sizeof file, f) : 0;
    if (f)
        fclose(f);
    TV_CHECK(scn_image_read_memory(file, n, "embedded", &back, &w, &h, err, sizeof err));
    if (back)
        TV_CHECK(memcmp(back, px, sizeof px) == 0);
    scn_image_free(back);
}

static void test_rgb_gets_opaque_alpha(void)
{
    uint8_t px[6] = { 10, 20, 30, 40, 50, 60 };
    char path[512], err[512];
    snprintf(path, sizeof path, "%s/rgb.png", dir);
    TV_CHECK(scn_image_write_png(path, px, 2, 1, 3, err, sizeof err));
    uint8_t* back = NULL;
    uint32_t w, h;
    TV_CHECK(scn_image_read(path, &back, &w, &h, err, sizeof err));
    if (back) {
        TV_CHECK(back[0] == 10 && back[3] == 255 && back[6] == 60 && back[7] == 255);
    }
    scn_image_free(back);
}

static void test_exr(void)
{
    float depth[4] = { 0.25f, 0.5f, 1.0f, 1e6f };
    char path[512], err[512];
    snprintf(path, sizeof path, "%s/depth.exr", dir);
    TV_CHECK(scn_image_write_exr(path, depth, 2, 2, 1, err, sizeof err));
    uint8_t* back = NULL;
    uint32_t w, h;
    TV_CHECK(scn_image_read(path, &back, &w, &h, err, sizeof err)); /* readable, quantised to 8 bits */
    TV_CHECK(w == 2 && h == 2);
    if (back)
        TV_CHECK(back[0] == back[1] && back[4 * 2] == 255);
    scn_image_free(back);
}

static void test_errors(void)
{
    char path[512], err[512];
    uint8_t* px = (uint8_t*)"x";
    uint32_t w, h;
    snprintf(path, sizeof path, "%s/none.png", dir);
    TV_CHECK(!scn_image_read(path, &px, &w, &h, err, sizeof err));
    TV_CHECK(px == NULL && strstr(err, path) && !strchr(err, '\n'));
    TV_CHECK(!scn_image_read_memory("not an image", 12, "blob.png", &px, &w, &h, err, sizeof err));
    TV_CHECK(px == NULL && strstr(err, "blob.png") && !strchr(err, '\n'));
    uint8_t one[3] = { 0, 0, 0 };
    snprintf(path, sizeof path, "%s/no_such_dir/x.png", dir);
    TV_CHECK(!scn_image_write_png(path, one, 1, 1, 3, err, sizeof err));
    TV_CHECK(strstr(err, path) != NULL);
}

static void test_psnr_matches_formula(void)
{
    enum { W = 17, H = 9 };
    uint8_t a[W * H * 3], b[W * H * 3];
    double se = 0.0;
    for (int i = 0; i < W * H * 3; i++) {
        a[i] = (uint8_t)((i * 37) & 255);
        int d = (i % 5) - 2;
        int v = a[i] + d;
        b[i] = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
        se += (double)(b[i] - a[i]) * (b[i] - a[i]);
    }
    double expected = 10.0 * log10(255.0 * 255.0 / (se / (W * H * 3)));
    double psnr = 0.0;
    char err[256];
    TV_CHECK(scn_image_psnr_oiio(a, b, W, H, &psnr, err, sizeof err));
    TV_CHECK_NEAR(psnr, expected, 1e-3);
    TV_CHECK(scn_image_psnr_oiio(a, a, W, H, &psnr, err, sizeof err));
    TV_CHECK(isinf(psnr) && psnr > 0);
}

int main(void)
{
    if (!scene_test_dir_create(dir, sizeof dir, "tv_scene_img"))
        return 1;
    TV_TEST_RUN(test_png_roundtrip);
    TV_TEST_RUN(test_rgb_gets_opaque_alpha);
    TV_TEST_RUN(test_exr);
    TV_TEST_RUN(test_errors);
    TV_TEST_RUN(test_psnr_matches_formula);
    scene_test_dir_remove(dir);
    return tv_test_finish();
}
