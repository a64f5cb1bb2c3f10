#define _DEFAULT_SOURCE /* mkdtemp */
/* image_io_png.c (the portable build's image I/O): PNG round trips, PNG
 * colour types expanded to RGBA8 as the OpenImageIO path does (grey,
 * 16-bit, palette with tRNS), JPEG decoding, oversized headers refused
 * before decoding, and the OpenImageIO-only functions refusing with a
 * message. Encoders here are libpng's and libjpeg's own. */
#include "image_io.h"
#include "scene_test_dir.h"
#include "test.h"

#include <stdio.h> /* before jpeglib.h, which uses FILE */
#include <jpeglib.h>
#include <png.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

static char dir[256];

static void test_png_roundtrip(void)
{
    uint8_t px[5 * 3 * 4];
    for (int i = 0; i < (int)sizeof px; i++)
        px[i] = (uint8_t)(i * 13 + 1);
    char path[512], err[512];
    for (uint32_t channels = 3; channels <= 4; channels++) {
        snprintf(path, sizeof path, "%s/round%u.png", dir, channels);
        TV_CHECK(scn_image_write_png(path, px, 5, 3, channels, err, sizeof err));
        uint8_t* back = NULL;
        uint32_t w = 0, h = 0;
        TV_CHECK(scn_image_read(path, &back, &w, &h, err, sizeof err));
        TV_CHECK(w == 5 && h == 3);
        int wrong = 0;
        for (int p = 0; back && p < 15; p++)
            for (int c = 0; c < 4; c++)
                wrong += back[4 * p + c] != (c < (int)channels ? px[channels * p + c] : 255);
        TV_CHECK(back && wrong == 0);
        scn_image_free(back);
    }
}

/* One row of `w` pixels in a PNG of the given colour type and depth, into a file. */
static void write_png(const char* path, int type, int depth, const uint8_t* row, uint32_t w, const png_color* palette,
                      int npal, const uint8_t* trns, int ntrns)
{
    FILE* f = fopen(path, "wb");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, f);
    png_set_IHDR(png, info, w, 1, depth, type, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (palette)
        png_set_PLTE(png, info, palette, npal);
    if (trns)
        png_set_tRNS(png, info, trns, ntrns, NULL);
    png_write_info(png, info);
    png_write_row(png, row);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    fclose(f);
}

static void test_png_colour_types(void)
{
    char path[512], err[512];
    uint8_t* px = NULL;
    uint32_t w, h;
    /* 16-bit grey: the top byte, copied to R, G and B, opaque */
    const uint8_t grey16[4] = {0x12, 0x34, 0xfe, 0xdc};
    snprintf(path, sizeof path, "%s/grey16.png", dir);
    write_png(path, PNG_COLOR_TYPE_GRAY, 16, grey16, 2, NULL, 0, NULL, 0);
    TV_CHECK(scn_image_read(path, &px, &w, &h, err, sizeof err) && w == 2 && h == 1);
    TV_CHECK(px && memcmp(px, (const uint8_t[8]){0x12, 0x12, 0x12, 255, 0xfe, 0xfe, 0xfe, 255}, 8) == 0);
    scn_image_free(px);
    /* palette with a transparent entry */
    const png_color pal[2] = {{10, 20, 30}, {200, 100, 50}};
    const uint8_t idx[3] = {1, 0, 1}, trns[1] = {0};
    snprintf(path, sizeof path, "%s/palette.png", dir);
    write_png(path, PNG_COLOR_TYPE_PALETTE, 8, idx, 3, pal, 2, trns, 1);
    TV_CHECK(scn_image_read(path, &px, &w, &h, err, sizeof err) && w == 3);
    TV_CHECK(px && memcmp(px, (const uint8_t[12]){200, 100, 50, 255, 10, 20, 30, 0, 200, 100, 50, 255}, 12) == 0);
    scn_image_free(px);
}

/* An 8x8 JPEG of one colour (components 1: grey, 3: RGB) into buf; returns its size. */
static size_t write_jpeg(uint8_t** buf, int components, const uint8_t colour[3])
{
    struct jpeg_compress_struct c;
    struct jpeg_error_mgr e;
    c.err = jpeg_std_error(&e);
    jpeg_create_compress(&c);
    unsigned long size = 0;
    jpeg_mem_dest(&c, buf, &size);
    c.image_width = c.image_height = 8;
    c.input_components = components;
    c.in_color_space = components == 3 ? JCS_RGB : JCS_GRAYSCALE;
    jpeg_set_defaults(&c);
    jpeg_set_quality(&c, 95, TRUE);
    jpeg_start_compress(&c, TRUE);
    uint8_t row[8 * 3];
    for (int x = 0; x < 8; x++)
        memcpy(row + components * x, colour, (size_t)components);
    while (c.next_scanline < 8) {
        JSAMPROW r = row;
        jpeg_write_scanlines(&c, &r, 1);
    }
    jpeg_finish_compress(&c);
    jpeg_destroy_compress(&c);
    return size;
}

static void test_jpeg(void)
{
    const uint8_t colour[3] = {200, 60, 30};
    char err[512];
    for (int components = 1; components <= 3; components += 2) {
        uint8_t* jpg = NULL;
        size_t n = write_jpeg(&jpg, components, colour);
        uint8_t* px = NULL;
        uint32_t w = 0, h = 0;
        TV_CHECK(scn_image_read_memory(jpg, n, "flat.jpg", &px, &w, &h, err, sizeof err));
        TV_CHECK(w == 8 && h == 8);
        int far = 0;
        for (int p = 0; px && p < 64; p++)
            for (int c = 0; c < 3; c++)
                far += abs(px[4 * p + c] - colour[components == 3 ? c : 0]) > 3;
        TV_CHECK(px && far == 0 && px[3] == 255 && px[4 * 63 + 3] == 255);
        scn_image_free(px);
        free(jpg);
    }
}

static void put32(uint8_t* p, uint32_t v)
{
    p[0] = (uint8_t)(v >> 24), p[1] = (uint8_t)(v >> 16), p[2] = (uint8_t)(v >> 8), p[3] = (uint8_t)v;
}

static void test_oversized_headers(void)
{
    char err[512];
    uint8_t* px = (uint8_t*)"x";
    uint32_t w, h;
    /* PNG: signature and a valid IHDR claiming 20000 x 16 (over the side limit), nothing after */
    uint8_t png[8 + 25] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    put32(png + 8, 13);
    memcpy(png + 12, "IHDR", 4);
    put32(png + 16, 20000);
    put32(png + 20, 16);
    png[24] = 8, png[25] = 6; /* 8-bit RGBA */
    put32(png + 29, (uint32_t)crc32(0, png + 12, 17));
    TV_CHECK(!scn_image_read_memory(png, sizeof png, "huge.png", &px, &w, &h, err, sizeof err));
    TV_CHECK(px == NULL && strstr(err, "huge.png: image of 20000x16 pixels is over the limit"));
    /* JPEG: SOI, a baseline frame of 9000 x 9000 (each side fine, 81M pixels over the limit), SOS */
    const uint8_t jpg[] = {0xff, 0xd8, 0xff, 0xc0, 0, 11, 8, 0x23, 0x28, 0x23, 0x28, 1, 1, 0x11, 0,
                           0xff, 0xda, 0, 8, 1, 1, 0, 0, 63, 0};
    TV_CHECK(!scn_image_read_memory(jpg, sizeof jpg, "huge.jpg", &px, &w, &h, err, sizeof err));
    TV_CHECK(px == NULL && strstr(err, "huge.jpg: image of 9000x9000 pixels is over the limit"));
    /* a truncated PNG: one line naming it */
    TV_CHECK(!scn_image_read_memory(png, 20, "cut.png", &px, &w, &h, err, sizeof err));
    TV_CHECK(px == NULL && strstr(err, "cut.png: libpng: ") && !strchr(err, '\n'));
}

static void test_oiio_only_refused(void)
{
    char err[512];
    const float depth[1] = {1.0f};
    TV_CHECK(!scn_image_write_exr("d.exr", depth, 1, 1, 1, err, sizeof err) && strstr(err, "not in this build"));
    double psnr;
    const uint8_t a[3] = {0};
    TV_CHECK(!scn_image_psnr_oiio(a, a, 1, 1, &psnr, err, sizeof err) && strstr(err, "not in this build"));
}

int main(void)
{
    if (!scene_test_dir_create(dir, sizeof dir, "tv_scene_png"))
        return 1;
    TV_TEST_RUN(test_png_roundtrip);
    TV_TEST_RUN(test_png_colour_types);
    TV_TEST_RUN(test_jpeg);
    TV_TEST_RUN(test_oversized_headers);
    TV_TEST_RUN(test_oiio_only_refused);
    scene_test_dir_remove(dir);
    return tv_test_finish();
}
