/* image_io.h - image files through OpenImageIO (image_io.cpp, the only file
 * that uses it), or libpng and libjpeg in the portable build (image_io_png.c).
 *
 * Decoding gives RGBA8 whatever the source (grey, RGB, 16-bit, float): the
 * renderer samples one format. Every function returns false with a one-line
 * "<file>: <problem>" message in err on failure and never leaves partial
 * output behind.
 */
#ifndef TRIMVR_SCENE_IMAGE_IO_H
#define TRIMVR_SCENE_IMAGE_IO_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Largest image the readers accept, checked on the header before any pixel
 * memory is allocated: a few-byte file can claim 2^31 x 2^31 pixels. 16384
 * is the usual Vulkan maxImageDimension2D; 2^26 pixels (256 MiB as RGBA8)
 * bounds what one texture may cost. Every image backend applies both. */
#define SCN_IMAGE_MAX_SIDE 16384u
#define SCN_IMAGE_MAX_PIXELS (1u << 26)

/* Reads an image file into a new RGBA8 buffer (*width * *height * 4 bytes,
 * rows top to bottom; missing channels: grey -> RGB, alpha = 255). Free the
 * buffer with scn_image_free(). */
bool scn_image_read(const char* path, uint8_t** rgba8, uint32_t* width, uint32_t* height, char* err,
                    size_t err_size);

/* Same from memory (glTF embedded images). The format is detected from the
 * first bytes (PNG, JPEG, others by OpenImageIO's probing); `name` only
 * appears in error messages. */
bool scn_image_read_memory(const void* data, size_t size, const char* name, uint8_t** rgba8,
                           uint32_t* width, uint32_t* height, char* err, size_t err_size);

/* Releases a buffer returned by scn_image_read*(); NULL is ignored. */
void scn_image_free(uint8_t* rgba8);

/* Writes 8-bit pixels (channels 3 = RGB or 4 = RGBA, rows top to bottom,
 * tightly packed) as PNG. */
bool scn_image_write_png(const char* path, const uint8_t* pixels, uint32_t width, uint32_t height,
                         uint32_t channels, char* err, size_t err_size);

/* Writes float pixels (1 to 4 channels, e.g. a depth buffer) as OpenEXR. */
bool scn_image_write_exr(const char* path, const float* pixels, uint32_t width, uint32_t height,
                         uint32_t channels, char* err, size_t err_size);

/* PSNR in dB of two RGB8 images (tightly packed, same size) by
 * OpenImageIO's ImageBufAlgo::compare: 20*log10(1/rms) on values scaled to
 * [0, 1], i.e. the usual 10*log10(255^2/MSE). Identical images give +inf.
 * Exists so tests can cross-check render/'s own PSNR with an independent
 * implementation. */
bool scn_image_psnr_oiio(const uint8_t* a, const uint8_t* b, uint32_t width, uint32_t height,
                         double* psnr, char* err, size_t err_size);

#ifdef __cplusplus
}
#endif

#endif
