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

static uint32_t crc32(const uint8_t* p, size_t n)
{
    uint32_t c = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++)
            c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
    }
    return ~c;
}

static void put_be32(uint8_t* p, uint32_t v)
{
    p[0] = (uint8_t)(v >> 24), p[1] = (uint8_t)(v >> 16), p[2] = (uint8_t)(v >> 8), p[3] = (uint8_t)v;
}

/* A valid PNG signature and IHDR claiming side x side RGBA8, a 2-byte IDAT
 * and IEND: 59 bytes that decoded in full would need side^2 * 4 bytes. */
static size_t claim_png(uint8_t* out, uint32_t side)
{
    static const uint8_t sig[8] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n' };
    memcpy(out, sig, 8);
    put_be32(out + 8, 13);
    memcpy(out + 12, "IHDR", 4);
    put_be32(out + 16, side);
    put_be32(out + 20, side);
    memcpy(out + 24, "\x08\x06\x00\x00\x00", 5);
    put_be32(out + 29, crc32(out + 12, 17));
    put_be32(out + 33, 2);
    memcpy(out + 37, "IDAT\x78\x9c", 6);
    put_be32(out + 43, crc32(out + 37, 6));
    put_be32(out + 47, 0);
    memcpy(out + 51, "IEND", 4);
    put_be32(out + 55, crc32(out + 51, 4));
    return 59;
}

/* 16384^2 pixels from 59 bytes: refused from the header, before the 1 GiB
 * the pixels would take. */
static void test_absurd_size_refused(void)
{
    uint8_t png[64];
    size_t n = claim_png(png, 16384);
    char err[512];
    uint8_t* px = NULL;
    uint32_t w, h;
    TV_CHECK(!scn_image_read_memory(png, n, "huge.png", &px, &w, &h, err, sizeof err));
    TV_CHECK(px == NULL && strstr(err, "huge.png: image claims 16384x16384 pixels") && strstr(err, "the limit is"));
    printf("     %s\n", err);
}

/* A truncated PNG: trimvr's one-line error and nothing else on stderr
 * (libpng printed its own "libpng error: ..." line first). */
static void test_truncated_png_one_line(void)
{
    enum { S = 64 };
    static uint8_t px[S * S * 3];
    uint32_t x = 2463534242u;
    for (size_t i = 0; i < sizeof px; i++) { /* xorshift noise: the file stays large */
        x ^= x << 13, x ^= x >> 17, x ^= x << 5;
        px[i] = (uint8_t)x;
    }
    char path[512], err[512], log[512];
    snprintf(path, sizeof path, "%s/cut.png", dir);
    TV_CHECK(scn_image_write_png(path, px, S, S, 3, err, sizeof err));
    TV_CHECK(truncate(path, 6000) == 0); /* of about 12 kB */
    snprintf(log, sizeof log, "%s/stderr.txt", dir);
    fflush(stderr);
    int saved = dup(2);
    FILE* capture = fopen(log, "w+");
    TV_CHECK(capture != NULL);
    if (!capture)
        return;
    dup2(fileno(capture), 2);
    uint8_t* back = NULL;
    uint32_t w, h;
    bool ok = scn_image_read(path, &back, &w, &h, err, sizeof err);
    fflush(stderr);
    dup2(saved, 2);
    close(saved);
    fseek(capture, 0, SEEK_END);
    long printed = ftell(capture);
    fclose(capture);
    TV_CHECK(!ok && back == NULL && strstr(err, path) && !strchr(err, '\n'));
    TV_CHECK(printed == 0);
    printf("     %s (%ld bytes on stderr)\n", err, printed);
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
    TV_TEST_RUN(test_absurd_size_refused);
    TV_TEST_RUN(test_truncated_png_one_line);
    TV_TEST_RUN(test_psnr_matches_formula);
    scene_test_dir_remove(dir);
    return tv_test_finish();
}
