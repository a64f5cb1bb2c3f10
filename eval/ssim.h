/* ssim.h - the structural similarity index (SSIM) of Wang, Bovik, Sheikh and
 * Simoncelli, "Image quality assessment: from error visibility to structural
 * similarity", IEEE TIP 13(4), 2004, as their reference ssim_index.m defines
 * it: an 11 x 11 Gaussian window (sigma 1.5, normalised to sum 1),
 * K1 = 0.01, K2 = 0.03, L = 255, no downsampling. Per window
 *
 *   SSIM = (2 mx my + C1)(2 sxy + C2) / ((mx^2 + my^2 + C1)(sx^2 + sy^2 + C2))
 *
 * with C1 = (K1 L)^2, C2 = (K2 L)^2 and the window-weighted means, variances
 * and covariance; the image's SSIM is the mean over every window that lies
 * wholly inside the image ("valid" border rule: (W - 10) x (H - 10) windows,
 * no padding). Colour images are compared on their Rec. 601 luma
 * Y = 0.299 R + 0.587 G + 0.114 B, kept unrounded in [0, 255]. Pure C, no
 * Vulkan (library tv_imgcmp). */
#ifndef TRIMVR_SSIM_H
#define TRIMVR_SSIM_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

enum { RND_SSIM_WINDOW = 11 };

/* The window's 1-D weights: exp(-k^2 / (2 * 1.5^2)) for k = -5..5 over their
 * sum; the 2-D window is their outer product. */
void rnd_ssim_weights(double w[RND_SSIM_WINDOW]);

/* Doubles of scratch rnd_ssim_rgb8 needs for a width x height image. */
size_t rnd_ssim_scratch_count(uint32_t width, uint32_t height);

/* Mean SSIM of two width x height 8-bit images, stride bytes per pixel (3
 * for RGB, 4 for RGBA; alpha is ignored), rows packed. scratch holds
 * rnd_ssim_scratch_count(width, height) doubles, caller-owned. 1 exactly for
 * identical images; NaN when the image is smaller than one window. */
double rnd_ssim_rgb8(const uint8_t* a, const uint8_t* b, uint32_t width, uint32_t height, size_t stride,
                     double* scratch);

/* The same on two single-channel images of width x height doubles on the
 * 0..255 scale (what rnd_ssim_rgb8 computes after taking luma); scratch
 * holds 5 * width doubles. */
double rnd_ssim_luma(const double* x, const double* y, uint32_t width, uint32_t height, double* scratch);

#ifdef __cplusplus
}
#endif

#endif
