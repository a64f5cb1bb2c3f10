/* image_io_png.c - image_io.h through libpng and libjpeg: the portable build
 * (TRIMVR_PORTABLE), which leaves OpenImageIO and its ~250 libraries out.
 * Reads PNG (any bit depth, palette, grey, tRNS) and baseline/progressive
 * JPEG (grey, RGB); writes PNG. OpenEXR output and the OpenImageIO PSNR
 * cross-check are not in this build and say so. Values are scaled, never
 * gamma-converted (16-bit samples keep their top byte), as the OpenImageIO
 * path does. */
#include "image_io.h"

#include <stdio.h> /* before jpeglib.h, which uses FILE */
#include <jpeglib.h>
#include <png.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

static bool fail(char* err, size_t err_size, const char* file, const char* problem)
{
    snprintf(err, err_size, "%s: %s", file, problem);
    return false;
}

static bool size_ok(uint32_t w, uint32_t h, const char* file, char* err, size_t err_size)
{
    if (w == 0 || h == 0)
        return fail(err, err_size, file, "unsupported image dimensions");
    if (w > SCN_IMAGE_MAX_SIDE || h > SCN_IMAGE_MAX_SIDE || (uint64_t)w * h > SCN_IMAGE_MAX_PIXELS) {
        char msg[160];
        snprintf(msg, sizeof msg, "image of %ux%u pixels is over the limit (%u a side, %u pixels)", w, h,
                 SCN_IMAGE_MAX_SIDE, SCN_IMAGE_MAX_PIXELS);
        return fail(err, err_size, file, msg);
    }
    return true;
}

/* libpng reports through these instead of its own stderr lines. */
typedef struct png_ctx {
    jmp_buf jump;
    char message[200];
    const uint8_t* data;
    size_t size, at;
} png_ctx;

static void png_error_fn(png_structp png, png_const_charp msg)
{
    png_ctx* c = png_get_error_ptr(png);
    snprintf(c->message, sizeof c->message, "libpng: %s", msg);
    longjmp(c->jump, 1);
}

static void png_warning_fn(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg; /* warnings (unknown chunks, bad CRCs in ancillary data) do not stop the decode */
}

static void png_read_fn(png_structp png, png_bytep out, size_t n)
{
    png_ctx* c = png_get_io_ptr(png);
    if (n > c->size - c->at)
        png_error(png, "file truncated");
    memcpy(out, c->data + c->at, n);
    c->at += n;
}

static bool read_png(const uint8_t* data, size_t size, const char* name, uint8_t** rgba8, uint32_t* width,
                     uint32_t* height, char* err, size_t err_size)
{
    /* the size from IHDR (always the first chunk) before libpng reads on */
    if (size >= 24 && memcmp(data + 12, "IHDR", 4) == 0 &&
        !size_ok(png_get_uint_32(data + 16), png_get_uint_32(data + 20), name, err, err_size))
        return false;
    png_ctx c = {.data = data, .size = size};
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &c, png_error_fn, png_warning_fn);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    uint8_t* volatile out = NULL;
    png_bytep* volatile rows = NULL;
    volatile bool ok = false;
    if (!info) {
        snprintf(c.message, sizeof c.message, "out of memory for the PNG decoder");
    } else if (setjmp(c.jump) == 0) {
        png_set_read_fn(png, &c, png_read_fn);
        png_read_info(png, info);
        uint32_t w = png_get_image_width(png, info), h = png_get_image_height(png, info);
        png_set_expand(png); /* palette -> RGB, grey < 8 bits -> 8, tRNS -> alpha */
        png_set_strip_16(png);
        png_set_gray_to_rgb(png);
        png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
        png_set_interlace_handling(png);
        png_read_update_info(png, info);
        out = malloc((size_t)w * h * 4);
        rows = malloc(h * sizeof *rows);
        if (!out || !rows)
            png_error(png, "out of memory for the decoded image");
        for (uint32_t y = 0; y < h; y++)
            rows[y] = out + (size_t)y * w * 4;
        png_read_image(png, rows);
        *width = w;
        *height = h;
        ok = true;
    }
    png_destroy_read_struct(&png, &info, NULL);
    free(rows);
    if (!ok) {
        free(out);
        return fail(err, err_size, name, c.message);
    }
    *rgba8 = out;
    return true;
}

typedef struct jpeg_ctx {
    struct jpeg_error_mgr mgr;
    jmp_buf jump;
    char message[JMSG_LENGTH_MAX + 32];
} jpeg_ctx;

static void jpeg_error_fn(j_common_ptr cinfo)
{
    jpeg_ctx* c = (jpeg_ctx*)cinfo->err;
    char msg[JMSG_LENGTH_MAX];
    c->mgr.format_message(cinfo, msg);
    snprintf(c->message, sizeof c->message, "cannot decode JPEG: %s", msg);
    longjmp(c->jump, 1);
}

static void jpeg_quiet(j_common_ptr cinfo, int level)
{
    (void)cinfo;
    (void)level; /* corrupt-data warnings: the decoder fills in and goes on */
}

static bool read_jpeg(const uint8_t* data, size_t size, const char* name, uint8_t** rgba8, uint32_t* width,
                      uint32_t* height, char* err, size_t err_size)
{
    struct jpeg_decompress_struct cinfo;
    jpeg_ctx c;
    cinfo.err = jpeg_std_error(&c.mgr);
    c.mgr.error_exit = jpeg_error_fn;
    c.mgr.emit_message = jpeg_quiet;
    uint8_t* volatile out = NULL;
    uint8_t* volatile row = NULL;
    volatile bool ok = false, too_big = false;
    if (setjmp(c.jump) == 0) {
        jpeg_create_decompress(&cinfo);
        jpeg_mem_src(&cinfo, data, (unsigned long)size);
        jpeg_read_header(&cinfo, TRUE);
        too_big = !size_ok(cinfo.image_width, cinfo.image_height, name, err, err_size);
        if (!too_big) {
            cinfo.out_color_space = JCS_RGB; /* grey and YCbCr both convert; CMYK fails with a message */
            jpeg_start_decompress(&cinfo);
            uint32_t w = cinfo.output_width, h = cinfo.output_height;
            out = malloc((size_t)w * h * 4);
            row = malloc((size_t)w * 3);
            if (!out || !row) {
                snprintf(c.message, sizeof c.message, "out of memory for the decoded image");
                longjmp(c.jump, 1);
            }
            while (cinfo.output_scanline < h) {
                uint8_t* dst = out + (size_t)cinfo.output_scanline * w * 4;
                JSAMPROW rp = row;
                jpeg_read_scanlines(&cinfo, &rp, 1);
                for (uint32_t x = 0; x < w; x++) {
                    memcpy(dst + 4 * x, row + 3 * x, 3);
                    dst[4 * x + 3] = 255;
                }
            }
            jpeg_finish_decompress(&cinfo);
            *width = w;
            *height = h;
            ok = true;
        }
    }
    jpeg_destroy_decompress(&cinfo);
    free(row);
    if (!ok) {
        free(out);
        return too_big ? false : fail(err, err_size, name, c.message);
    }
    *rgba8 = out;
    return true;
}

bool scn_image_read_memory(const void* data, size_t size, const char* name, uint8_t** rgba8, uint32_t* width,
                           uint32_t* height, char* err, size_t err_size)
{
    *rgba8 = NULL;
    const uint8_t* b = data;
    if (size >= 8 && png_sig_cmp(b, 0, 8) == 0)
        return read_png(b, size, name, rgba8, width, height, err, err_size);
    if (size >= 3 && b[0] == 0xff && b[1] == 0xd8 && b[2] == 0xff)
        return read_jpeg(b, size, name, rgba8, width, height, err, err_size);
    return fail(err, err_size, name, "not a PNG or JPEG image (this portable build reads only those)");
}

bool scn_image_read(const char* path, uint8_t** rgba8, uint32_t* width, uint32_t* height, char* err,
                    size_t err_size)
{
    *rgba8 = NULL;
    FILE* f = fopen(path, "rb");
    if (!f)
        return fail(err, err_size, path, "image file not found");
    long size = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    uint8_t* data = size > 0 && fseek(f, 0, SEEK_SET) == 0 ? malloc((size_t)size) : NULL;
    bool ok = data && fread(data, 1, (size_t)size, f) == (size_t)size;
    fclose(f);
    ok = ok ? scn_image_read_memory(data, (size_t)size, path, rgba8, width, height, err, err_size)
            : fail(err, err_size, path, size == 0 ? "empty file" : "cannot read the file");
    free(data);
    return ok;
}

void scn_image_free(uint8_t* rgba8)
{
    free(rgba8);
}

bool scn_image_write_png(const char* path, const uint8_t* pixels, uint32_t width, uint32_t height,
                         uint32_t channels, char* err, size_t err_size)
{
    if ((channels != 3 && channels != 4) || width == 0 || height == 0)
        return fail(err, err_size, path, "PNG output needs 3 or 4 channels and a non-empty image");
    FILE* f = fopen(path, "wb");
    if (!f)
        return fail(err, err_size, path, "cannot create the file");
    png_ctx c = {0};
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &c, png_error_fn, png_warning_fn);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    volatile bool ok = false;
    if (!info) {
        snprintf(c.message, sizeof c.message, "out of memory for the PNG encoder");
    } else if (setjmp(c.jump) == 0) {
        png_init_io(png, f);
        png_set_IHDR(png, info, width, height, 8, channels == 4 ? PNG_COLOR_TYPE_RGBA : PNG_COLOR_TYPE_RGB,
                     PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        png_write_info(png, info);
        for (uint32_t y = 0; y < height; y++)
            png_write_row(png, pixels + (size_t)y * width * channels);
        png_write_end(png, NULL);
        ok = true;
    }
    png_destroy_write_struct(&png, &info);
    ok = fclose(f) == 0 && ok;
    if (!ok) {
        remove(path);
        return fail(err, err_size, path, c.message[0] ? c.message : "cannot write the file");
    }
    return true;
}

bool scn_image_write_exr(const char* path, const float* pixels, uint32_t width, uint32_t height,
                         uint32_t channels, char* err, size_t err_size)
{
    (void)pixels, (void)width, (void)height, (void)channels;
    return fail(err, err_size, path, "OpenEXR output is not in this build (TRIMVR_PORTABLE: PNG and JPEG only)");
}

bool scn_image_psnr_oiio(const uint8_t* a, const uint8_t* b, uint32_t width, uint32_t height, double* psnr,
                         char* err, size_t err_size)
{
    (void)a, (void)b, (void)width, (void)height, (void)psnr;
    return fail(err, err_size, "scn_image_psnr_oiio", "OpenImageIO is not in this build (TRIMVR_PORTABLE)");
}
