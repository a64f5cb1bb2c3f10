/* image_compare.h - pure C image metrics (no Vulkan): PSNR, differing
 * pixels, false-negative pixels from id buffers. Library tv_imgcmp, usable
 * in the headless sanitizer build. */
#ifndef TRIMVR_IMAGE_COMPARE_H
#define TRIMVR_IMAGE_COMPARE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* PSNR in dB over the R, G and B channels of two 8-bit images of
 * pixel_count pixels, each pixel stride bytes apart (3 for RGB, 4 for RGBA;
 * alpha is ignored): 10 log10(255^2 / MSE). Identical images return
 * INFINITY (callers print it as "inf"). pixel_count > 0. */
double rnd_psnr_rgb8(const uint8_t* a, const uint8_t* b, size_t pixel_count, size_t stride);

/* Pixels whose R, G or B differ by more than tolerance (0: any difference). */
size_t rnd_count_diff_pixels(const uint8_t* a, const uint8_t* b, size_t pixel_count, size_t stride,
                             uint8_t tolerance);

/* False-negative pixels: pixels of a full render whose triangle id is not in
 * the set. tri_in_set is a byte mask of triangle_count entries (non-zero =
 * in the set); pixels holding TV_NO_TRIANGLE (0xFFFFFFFF) are never false
 * negatives. Every other id must be < triangle_count. */
size_t rnd_count_fn_pixels(const uint32_t* full_ids, size_t pixel_count, const uint8_t* tri_in_set,
                           size_t triangle_count);

/* The same, counting only pixels whose id is at least first_id (the moving
 * triangles of a scene: first_id = triangle_count - dynamic_triangle_count). */
size_t rnd_count_fn_pixels_from(const uint32_t* full_ids, size_t pixel_count, const uint8_t* tri_in_set,
                                size_t triangle_count, uint32_t first_id);

/* The paper's Figure 1 colours, per pixel of a full render (rgba, 4 bytes
 * per pixel) and its id buffer, into out (out_stride 3 or 4 bytes per
 * pixel; out == rgba with stride 4 recolours in place): triangles in
 * `visible` keep their shading, those only in `pvs` (false positives) turn
 * blue, the rest grey; background pixels keep their colour. visible and pvs
 * are byte masks of triangle_count entries. */
void rnd_colour_figure1(const uint8_t* rgba, const uint32_t* ids, size_t pixel_count, const uint8_t* visible,
                        const uint8_t* pvs, size_t triangle_count, uint8_t* out, size_t out_stride);

/* False-negative pixels (as rnd_count_fn_pixels counts them) turned red,
 * blended so the surface stays recognisable; every other pixel keeps its
 * colour. Same buffers and in-place rule as rnd_colour_figure1. */
void rnd_colour_false_negatives(const uint8_t* rgba, const uint32_t* ids, size_t pixel_count, const uint8_t* pvs,
                                size_t triangle_count, uint8_t* out, size_t out_stride);

#ifdef __cplusplus
}
#endif

#endif
